//! The engine jobs of the explorer: the current point (at full and at chart accuracy, with the
//! adhesionless comparison), the load and thickness sweeps of the charts, and the GFMD run of
//! `g` on its own thread. Each turns the engine's results into the plain data of [`crate::tui::base::data`].

use crate::tui::base::data::{self, PointData, ScalesData, SweepData, ThicknessData};
use crate::tui::base::gfmd_view::GfmdView;
use crate::tui::base::protocol::*;
use asperity::error::{Error, Result};
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::surface::heightmap::Surface;
use asperity::theory::engine::{self, Options};
use asperity::theory::knob::{knob_sweep, Knob, KnobPoint, KnobSpec};
use asperity::theory::sweep::{self, SweepSpec};
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// Precision (relative, in p*) of the preview's window edges: the largest the engine allows,
/// about its load step (a jump drawn within a braille dot or two of the full sweep's, which
/// refines it to `Options::chart`'s 3 %). Refining to 3 % took a third of the preview.
pub const PREVIEW_EDGE_REL: f64 = asperity::theory::engine::EDGE_REL_RANGE.1;

fn point_options() -> Options {
    Options {
        sigma_points: SIGMA_POINTS,
        ..Options::default()
    }
}

/// The quick first answer of an adhesive point ([`PointData::preview`]): chart accuracy
/// ([`Options::chart`]: half the resolution in both directions, no error estimate) with the
/// search for every branch, so the panel lists the branches at once.
fn preview_options() -> Options {
    let mut o = Options::chart();
    o.sigma_points = SIGMA_POINTS;
    o.adhesion.explore_branches = true;
    o
}

/// The adhesive point at chart accuracy (see `preview_options`), with the adhesionless
/// comparison when `compare`.
pub fn evaluate_preview(scene: &Scene, cancel: &AtomicBool, compare: bool) -> Result<PointData> {
    let ev = engine::evaluate_warm(scene, &preview_options(), None, Some(cancel))?;
    let mut pd = PointData::at(&ev, scene.pressure());
    pd.error_estimate = f64::NAN;
    pd.preview = true;
    add_unloading(&mut pd, scene, &ev, &preview_options(), false, cancel)?;
    if let Some(u) = pd.unloading.as_mut() {
        u.error_estimate = f64::NAN;
        u.preview = true;
    }
    if compare {
        add_comparison(&mut pd, scene);
    }
    Ok(pd)
}

fn add_comparison(pd: &mut PointData, scene: &Scene) {
    let mut s0 = scene.clone();
    s0 = s0.without_adhesion();
    // the comparison curve is optional: an error only hides it
    if let Ok(ev0) = engine::evaluate(&s0, &point_options()) {
        pd.adhesionless = Some(data::pr_points(&ev0));
    }
}

/// Inside a hysteresis window (two stable branches at the load): the same load on the
/// unloading branch, evaluated whole from `ev`'s roots ([`PointData::unloading`]), and with
/// `gap` its ū/h_rms and bracket. The branch is optional: where it cannot be had the panel
/// shows what the loading evaluation knows of it (only [`Error::Cancelled`] is returned).
fn add_unloading(
    pd: &mut PointData,
    scene: &Scene,
    ev: &engine::Evaluation,
    opts: &Options,
    gap: bool,
    cancel: &AtomicBool,
) -> Result<()> {
    if ev.branches.iter().filter(|b| b.stable).count() < 2 {
        return Ok(());
    }
    let mut o = *opts;
    o.adhesion.follow_unloading = true;
    // the roots are known: re-bracket them from `ev` instead of scanning again
    o.adhesion.explore_branches = false;
    let twin = match engine::evaluate_warm(scene, &o, Some(ev), Some(cancel)) {
        Ok(t) => t,
        Err(Error::Cancelled) => return Err(Error::Cancelled),
        Err(_) => {
            o.adhesion_error_estimate = false;
            match engine::evaluate_warm(scene, &o, Some(ev), Some(cancel)) {
                Ok(mut t) => {
                    t.error_estimate = f64::NAN;
                    t
                }
                Err(Error::Cancelled) => return Err(Error::Cancelled),
                Err(_) => return Ok(()),
            }
        }
    };
    if twin.branch != asperity::theory::adhesion::Branch::Unloading {
        return Ok(());
    }
    let mut u = PointData::at(&twin, scene.pressure());
    if gap {
        u.gap = match asperity::theory::gap::mean_gap_of_cancellable(scene, ev, &Options::chart(), Some(cancel)) {
            Ok(g) => g.unloading.map(|b| data::BranchGapView {
                relative: b.relative,
                lower: b.lower,
                upper: b.upper,
            }),
            Err(Error::Cancelled) => return Err(Error::Cancelled),
            Err(_) => None,
        };
    }
    pd.unloading = Some(Box::new(u));
    Ok(())
}

pub fn evaluate_point(scene: &Scene, cancel: &AtomicBool, compare: bool) -> Result<PointData> {
    let mut pd = match engine::evaluate_warm(scene, &point_options(), None, Some(cancel)) {
        Ok(ev) => {
            let mut pd = PointData::at(&ev, scene.pressure());
            add_unloading(&mut pd, scene, &ev, &point_options(), true, cancel)?;
            pd
        }
        Err(e @ Error::NotConverged { .. }) if scene.surface_energy_j_m2() > 0.0 => {
            // the self-consistency may have converged while its error check did not (the edge
            // of a jump into contact): show it, without an error bar, and say why
            let opts = Options {
                adhesion_error_estimate: false,
                ..point_options()
            };
            match engine::evaluate_warm(scene, &opts, None, Some(cancel)) {
                Ok(ev) => {
                    let mut pd = PointData::at(&ev, scene.pressure());
                    add_unloading(&mut pd, scene, &ev, &opts, true, cancel)?;
                    pd.error_estimate = f64::NAN;
                    pd.branch.push_str(", no error bar");
                    pd.warning = Some(e.to_string());
                    pd
                }
                Err(Error::Cancelled) => return Err(Error::Cancelled),
                _ => return Err(e),
            }
        }
        Err(e) => return Err(e),
    };
    if compare && scene.surface_energy_j_m2() > 0.0 {
        add_comparison(&mut pd, scene);
    }
    Ok(pd)
}

/// ū/h_rms of the loading branch at the scene's p*, at chart accuracy, where no load sweep was
/// asked for (a screen showing no load chart): one evaluation and the adhesionless gap table
/// from p* up to full contact ([`asperity::theory::gap::mean_gap_of_cancellable`]). It is the
/// value a one-load [`sweep::sweep`] gives, for a tenth of the CPU: the sweep also solves the
/// adhesive theory at every node of its grid up to full contact, which the gap does not use.
pub fn point_gap(scene: &Scene, cancel: &AtomicBool) -> Result<f64> {
    let opts = Options::chart();
    let ev = engine::evaluate_warm(scene, &opts, None, Some(cancel))?;
    Ok(asperity::theory::gap::mean_gap_of_cancellable(scene, &ev, &opts, Some(cancel))?.relative)
}

/// The load curves of the charts at chart accuracy: the loading branch with ū and σ̄_c*, and
/// with adhesion the unloading branch and the jump-in and pull-off loads ([`sweep::sweep`]).
pub fn load_sweep(scene: &Scene, spec: &SweepSpec, cancel: &AtomicBool) -> Result<SweepData> {
    Ok(SweepData::from_sweep(&sweep::sweep(
        scene,
        spec,
        &Options::chart(),
        Some(cancel),
    )?))
}

/// The quick first load curves of `scene` over `range` ([`PREVIEW_POINTS`]).
pub fn preview_sweep(scene: &Scene, range: (f64, f64), cancel: &AtomicBool) -> Result<SweepData> {
    let spec = SweepSpec {
        from: range.0,
        to: range.1,
        points: PREVIEW_POINTS,
    };
    let opts = Options {
        sweep_step_ln: PREVIEW_STEP_LN,
        edge_rel: PREVIEW_EDGE_REL,
        ..Options::chart()
    };
    let mut sd = SweepData::from_sweep(&sweep::sweep(scene, &spec, &opts, Some(cancel))?);
    sd.preview = true;
    Ok(sd)
}

/// The chart's thicknesses: [`THICKNESS_POINTS`] log-spaced t·q_r over [`THICKNESS_RANGE`].
pub fn thickness_spec() -> KnobSpec {
    KnobSpec {
        knob: Knob::Thickness,
        from: THICKNESS_RANGE.0,
        to: THICKNESS_RANGE.1,
        points: THICKNESS_POINTS,
    }
}

/// a_r at the chart's thicknesses ([`thickness_spec`]) by the library's knob sweep
/// ([`knob_sweep`] at chart accuracy: each thickness its own scene, its model resolved for it)
/// and at t = ∞; a thickness where the solver fails is a gap (NaN), not an error. With
/// adhesion also the adhesionless curve, and the hysteresis windows in t·q_r at this p*: every
/// branch is found at each thickness (a_r of the loading branch, and of the unloading one
/// where two are stable), a jump between two neighbours is searched for a thickness inside a
/// window (the library's probe, [`asperity::theory::hysteresis::window_probes`], as
/// `asperity sweep --over thickness` does; added to the curve), and each window's edges are
/// found by bisection ([`asperity::theory::hysteresis::knob_edges_to`]) to
/// [`WINDOW_EDGE_REL`]. A window is resolved, not bridged: [`WINDOW_POINTS`] thicknesses
/// between its edges are evaluated at the engine's full accuracy (both branches) and added to
/// the curve.
pub fn thickness_sweep(scene: &Scene, cancel: &AtomicBool) -> Result<ThicknessData> {
    use asperity::theory::hysteresis::{knob_edges_to, merge_probes, window_probes, EdgeKind};
    let gamma = scene.surface_energy_j_m2();
    let mut opts = Options {
        sigma_points: 2,
        ..Options::chart()
    };
    // every branch at each thickness: the windows' two stable ones
    opts.adhesion.explore_branches = gamma > 0.0;
    let mut points = knob_sweep(scene, &thickness_spec(), &opts, false, Some(cancel))?;
    if gamma > 0.0 {
        // a thickness inside each window between two neighbours, added to the curve
        let probes = window_probes(scene, Knob::Thickness, &points, &opts, false, Some(cancel))?;
        points = merge_probes(points, probes).0;
    }
    let (mut jump_in, mut pull_off) = (Vec::new(), Vec::new());
    if gamma > 0.0 && points.len() > 1 {
        for e in knob_edges_to(
            scene,
            Knob::Thickness,
            &points,
            &opts.adhesion,
            WINDOW_EDGE_REL,
            Some(cancel),
        )? {
            match e.kind {
                EdgeKind::JumpIn => jump_in.push(e.value),
                EdgeKind::PullOff => pull_off.push(e.value),
            }
        }
        let windows: Vec<(f64, f64)> = jump_in
            .iter()
            .zip(&pull_off)
            .map(|(&j, &p)| (j.min(p), j.max(p)))
            .collect();
        if !windows.is_empty() {
            // the grid's and the probe's thicknesses inside a window are evaluated again
            let inside = |t: f64| windows.iter().any(|&(lo, hi)| t > lo && t < hi);
            let again: Vec<f64> = points.iter().map(|p| p.value).filter(|&t| inside(t)).collect();
            points.retain(|p| !inside(p.value));
            points.extend(window_interior(scene, &windows, again, cancel)?);
            points.sort_by(|a, b| a.value.total_cmp(&b.value));
        }
    }
    let a_r: Vec<f64> = points.iter().map(a_r_of).collect();
    if a_r.iter().all(|a| !a.is_finite()) {
        return Err(Error::NotConverged {
            solver: asperity::error::Solver::ThicknessSweep,
            reason: "no thickness converged".into(),
        });
    }
    let unloading: Vec<f64> = points
        .iter()
        .map(|p| p.result.as_ref().ok().and_then(|e| e.unloading_a_r).unwrap_or(f64::NAN))
        .collect();
    // the half-space lies outside a knob sweep's (finite) values
    let half_space = Knob::Thickness.apply(scene, f64::INFINITY);
    let a_r_inf = match engine::evaluate_warm(&half_space, &opts, None, Some(cancel)) {
        Err(Error::Cancelled) => return Err(Error::Cancelled),
        r => r.map_or(f64::NAN, |e| e.stats.a_r),
    };
    let t: Vec<f64> = points.iter().map(|p| p.value).collect();
    let adhesionless = if gamma > 0.0 {
        Some(adhesionless_at(scene, &t, &opts, cancel)?)
    } else {
        None
    };
    Ok(ThicknessData {
        a_r_unloading: if unloading.iter().any(|u| u.is_finite()) {
            unloading
        } else {
            Vec::new()
        },
        t,
        a_r,
        a_r_inf,
        adhesionless,
        jump_in,
        pull_off,
    })
}

/// Relative precision in t·q_r of the thickness chart's window edges: a window can be 3 %
/// wide (system II, model 3, γ_s = 0.1256 J/m², p* = 1e-4: t·q_r 0.0989–0.1018), so its
/// edges are bisected to 0.1 % (a chart's 3 % would not place them inside it).
pub const WINDOW_EDGE_REL: f64 = 1e-3;

/// Thicknesses evaluated inside each window of the thickness chart, between its edges.
pub const WINDOW_POINTS: usize = 5;

/// `values` and [`WINDOW_POINTS`] thicknesses inside each window (lo, hi) (log-spaced,
/// strictly between its edges), each evaluated at the engine's full accuracy with its
/// branches, so the curve inside a window is the engine's (at the chart's accuracy, two σ
/// points, a_r at t·q_r = 0.1 inside the window of [`WINDOW_EDGE_REL`]'s scene is 0.2 % off).
fn window_interior(
    scene: &Scene,
    windows: &[(f64, f64)],
    mut values: Vec<f64>,
    cancel: &AtomicBool,
) -> Result<Vec<KnobPoint>> {
    use rayon::prelude::*;
    let mut full = Options::default();
    full.adhesion.explore_branches = true;
    for &(lo, hi) in windows {
        for k in 0..WINDOW_POINTS {
            let f = (k as f64 + 1.0) / (WINDOW_POINTS as f64 + 1.0);
            values.push(lo * (hi / lo).powf(f));
        }
    }
    let found: Vec<Option<KnobPoint>> = values
        .into_par_iter()
        .map(|t| one_thickness(scene, t, &full, cancel))
        .collect::<Result<_>>()?;
    Ok(found.into_iter().flatten().collect())
}

/// a_r of a knob sweep's point (NaN where its solve failed).
fn a_r_of(p: &KnobPoint) -> f64 {
    p.result.as_ref().map_or(f64::NAN, |e| e.stats.a_r)
}

/// The knob sweep of `scene` at the single thickness `t` (its one point).
fn one_thickness(scene: &Scene, t: f64, opts: &Options, cancel: &AtomicBool) -> Result<Option<KnobPoint>> {
    let spec = KnobSpec {
        knob: Knob::Thickness,
        from: t,
        to: t,
        points: 1,
    };
    Ok(knob_sweep(scene, &spec, opts, false, Some(cancel))?.pop())
}

/// The adhesionless a_r of `scene` at the thicknesses `t`: the chart's grid in one knob
/// sweep, a thickness added inside a window on its own.
fn adhesionless_at(scene: &Scene, t: &[f64], opts: &Options, cancel: &AtomicBool) -> Result<Vec<f64>> {
    let dry = scene.without_adhesion();
    let grid = knob_sweep(&dry, &thickness_spec(), opts, false, Some(cancel))?;
    t.iter()
        .map(|&v| match grid.iter().find(|p| p.value == v) {
            Some(p) => Ok(a_r_of(p)),
            None => one_thickness(&dry, v, opts, cancel).map(|p| p.as_ref().map_or(f64::NAN, a_r_of)),
        })
        .collect()
}

/// ū/h_rms at p* from the chart sweep's rows ([`sweep::interpolate_in_ln_p`]), when p* lies
/// inside the swept range: it saves a separate gap computation (a sweep from p* to full
/// contact) on every step of p*.
pub fn interpolate_gap(sd: &SweepData, p: f64) -> Option<f64> {
    sweep::interpolate_in_ln_p(&sd.p, &sd.gap_rel, p)
}

/// The scale view of `scene`: [`SCALE_FRAMES`] snapshots of Pr(σ*, q) read off the engine's
/// march at chart accuracy ([`Options::chart`]), sampled on [`SIGMA_POINTS`] σ*.
pub fn scale_view(scene: &Scene, cancel: &AtomicBool) -> Result<ScalesData> {
    use asperity::theory::adhesion::scales::{snapshots, Sampling};
    let acc = Options::chart().adhesion;
    let s = snapshots(
        scene,
        &acc,
        None,
        SCALE_FRAMES,
        Sampling::Points(SIGMA_POINTS),
        Some(cancel),
    )?;
    Ok(ScalesData::from_scales(&s))
}

/// Loads of the GFMD sweep drawn on the a_r and ū charts (p*/3 … 3p*).
pub const GFMD_SWEEP_POINTS: usize = 5;

/// Bins of the GFMD Pr(σ*) histogram drawn in the explorer.
pub const GFMD_CHART_BINS: usize = 80;

/// Least time between two progress reports of the GFMD job within a phase (a new phase is
/// reported at once).
pub const GFMD_REPORT_EVERY: std::time::Duration = std::time::Duration::from_millis(100);

/// The loads of the GFMD sweep at p*: [`GFMD_SWEEP_POINTS`] log-spaced from p*/3 to 3p*
/// (within the allowed loads).
pub fn gfmd_sweep_spec(p: f64) -> SweepSpec {
    SweepSpec {
        from: (p / 3.0).max(1e-6),
        to: (3.0 * p).min(1.0).max(p / 3.0 * 1.01),
        points: GFMD_SWEEP_POINTS,
    }
}

/// The GFMD job of `g` ([`crate::tui::base::progress::plan`]): the relaxation at p* from first touch and
/// the theory on the map's spectrum ([`asperity::gfmd::run`]), then the same map over the
/// loads of [`gfmd_sweep_spec`], each warm-started from the one below, and the theory's
/// sweep on the map ([`asperity::gfmd::sweep::run_sweep`]). `report` gets the progress: at
/// once when a phase begins, then at most every [`GFMD_REPORT_EVERY`]. `cancel` ends it with
/// [`Error::Cancelled`] within one solver step or one march of the theory's adhesive solver.
/// A sweep that fails otherwise leaves the run at p* with the reason
/// ([`GfmdView::sweep_error`]).
pub fn gfmd_job(
    setup: &asperity::gfmd::GfmdSetup,
    cancel: &AtomicBool,
    report: &mut dyn FnMut(crate::tui::base::progress::GfmdProgress),
) -> Result<GfmdView> {
    use asperity::gfmd::{Progress, Stage};
    // a chart-sized histogram: ~10⁴ contact nodes on 512² give ~100 per bin
    let opts = asperity::gfmd::GfmdOptions {
        pr_bins: GFMD_CHART_BINS,
        ..asperity::gfmd::GfmdOptions::default()
    };
    let spec = gfmd_sweep_spec(setup.scene.pressure());
    let plan = crate::tui::base::progress::plan(setup.scene.pressure(), &spec.pressures());
    let mut clock = crate::tui::effects::clock::Timeline::new(plan, grid_side(setup));
    let mut last: Option<std::time::Instant> = None;
    let mut on = |index: usize, p: &Progress| {
        let new_phase = clock.enter(index);
        if new_phase || last.is_none_or(|t| t.elapsed() >= GFMD_REPORT_EVERY) {
            last = Some(std::time::Instant::now());
            report(clock.report(p.iteration, p.residual));
        }
    };
    on(
        0,
        &Progress {
            stage: Stage::Relax,
            iteration: 0,
            residual: f64::NAN,
            contact_fraction: 0.0,
        },
    );
    let r = asperity::gfmd::run(
        setup,
        &opts,
        &mut |p| on(if p.stage == Stage::Theory { 1 } else { 0 }, &p),
        cancel,
    )?;
    let view = GfmdView::from_result(&r);
    // the theory's sweep is reported with the index one past the last load
    match asperity::gfmd::sweep::run_sweep(setup, &spec, &opts, &mut |k, p| on(2 + k, &p), cancel) {
        Ok(sw) => Ok(view.with_sweep(&sw)),
        Err(Error::Cancelled) => Err(Error::Cancelled),
        Err(e) => Ok(GfmdView {
            sweep_error: Some(e.to_string()),
            ..view
        }),
    }
}

/// Runs [`gfmd_job`] on its own thread (the theory worker stays responsive), sending the
/// progress and, at the end, the result and the job's wall time.
pub fn spawn_gfmd(
    id: u64,
    setup: asperity::gfmd::GfmdSetup,
    cancel: Arc<AtomicBool>,
    send: impl Fn(Reply) + Send + 'static,
) -> std::io::Result<std::thread::JoinHandle<()>> {
    std::thread::Builder::new().name("asperity-gfmd".into()).spawn(move || {
        let t0 = std::time::Instant::now();
        // a fault (a panic) ends the job with its message, so the panel does not wait on it
        let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            gfmd_job(&setup, &cancel, &mut |progress| {
                send(Reply::GfmdProgress { id, progress })
            })
        }))
        .unwrap_or_else(|payload| {
            Err(asperity::error::Error::io(
                "run GFMD",
                format!("internal fault: {}", panic_text(payload.as_ref())),
            ))
        });
        send(Reply::GfmdDone {
            id,
            result,
            elapsed_s: t0.elapsed().as_secs_f64(),
        });
    })
}

/// The message of a panic's payload (a `&str` or a `String`; else a placeholder), on one
/// line and at most 200 characters.
pub fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    let text = payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic without a message".into());
    let line = text.split_whitespace().collect::<Vec<_>>().join(" ");
    match line.char_indices().nth(200) {
        Some((i, _)) => format!("{}…", &line[..i]),
        None => line,
    }
}

/// The GFMD setup of `g`: the scene on the preset's reduced grid (a 512² default), or on the
/// measured `map` where one is given.
pub fn gfmd_setup(preset: &Preset, scene: &Scene, map: Option<&Surface>) -> asperity::gfmd::GfmdSetup {
    // the preset's grid (or the default): without a grid asked for, nothing to refuse
    let grid = asperity::gfmd::GridSpec::of_preset(preset, None).unwrap_or(asperity::gfmd::GridSpec::DEFAULT);
    asperity::gfmd::GfmdSetup {
        scene: scene.clone(),
        grid,
        seed: 1,
        surface: map.cloned(),
        rescale: true,
    }
}

/// The side N of the N×N grid GFMD runs on: the map's where one is given, else the grid's.
pub fn grid_side(setup: &asperity::gfmd::GfmdSetup) -> usize {
    setup.surface.as_ref().map_or(setup.grid.n(), |s| s.nx)
}

#[cfg(test)]
#[path = "engine_tests.rs"]
mod tests;
