//! Computing a figure's data: the theory curves (the engine, each point as `run` computes
//! it), the closed forms (eq. (18) \[S-18, S-19\] and the small- and large-stress asymptotes
//! of Pr(σ*)), the values \[S\] states, and when asked the brute-force GFMD points (one run
//! per x value, or one Pr(σ*) histogram per curve scene), each run's progress passed to the
//! caller as a [`RunProgress`].

pub use super::curves::x_values;
use super::curves::{branch_series, point, refine_axes, sample_at, sweep_curve, x_name, y_of};
use super::refine::{self, Refined, Sample};
use super::spec::{ClosedFormKind, FigureSpec, Overrides, XAxis, YAxis};
use super::{DataPoint, DataSeries, FigureData, RunProgress, SeriesKind, Style};
use crate::error::{Error, Result};
use crate::gfmd::{self, GfmdOptions, GfmdResult, GfmdSetup, GridSpec};
use crate::input::model::{Model, ModelKind};
use crate::input::preset::Preset;
use crate::input::scene::Scene;
use crate::surface::heightmap::Surface;
use crate::surface::spectrum::Spectrum;
use crate::theory::closed_form;
use crate::theory::engine::{self, Evaluation, Options};
use rayon::prelude::*;
use std::sync::atomic::AtomicBool;

pub use super::spec::curve_scene;

/// A measured surface a figure is drawn for instead of its preset's self-affine spectrum
/// (a height map or a PSD table): every theory curve uses `spectrum`; GFMD runs on
/// `map`, which a PSD table does not have.
#[derive(Debug, Clone)]
pub struct Measured {
    /// The tabulated C(q) of the map or of the PSD file.
    pub spectrum: Spectrum,
    /// The height map (None for a PSD table).
    pub map: Option<Surface>,
}

impl Measured {
    /// The name the figure gives the surface: the file the table came from.
    pub fn name(&self) -> String {
        match &self.spectrum {
            Spectrum::Tabulated(t) => t.source.clone(),
            other => other.kind().to_string(),
        }
    }
}

/// The scene on the measured surface's spectrum (unchanged without one).
fn on_surface(scene: Scene, on: Option<&Measured>) -> Result<Scene> {
    match on {
        Some(m) => scene.with_spectrum(m.spectrum.clone()),
        None => Ok(scene),
    }
}

/// Brute-force runs: grid side and seed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GfmdChoice {
    /// Grid side N (None: the preset's `[gfmd]` grid).
    pub grid: Option<usize>,
    /// Seed of the random phases.
    pub seed: u64,
}

fn x_label(x: XAxis) -> &'static str {
    match x {
        XAxis::Pressure => "p* = p/(E*ḡ)",
        XAxis::Thickness => "t·q_r (slab thickness × roll-off wavenumber)",
        XAxis::Gamma => "γ_s (J/m²)",
        XAxis::Stress => "σ* = σ/(E*ḡ)",
    }
}

fn y_label(y: YAxis) -> &'static str {
    match y {
        YAxis::AR => "a_r (relative contact area)",
        YAxis::AROverP => "a_r/p*",
        YAxis::MeanContactStress => "σ̄_c* (mean contact stress / E*ḡ)",
        YAxis::ContactStressVariance => "⟨δσ_c²⟩* (variance / (E*ḡ)²)",
        YAxis::MeanGapRel => "ū/h_rms (mean gap)",
        YAxis::Pr => "Pr(σ*) (per unit σ*, ∫ = a_r)",
    }
}

/// Pr(σ*) of one curve: the engine's sample on [0 or −σ_a*, `to`] with `points` values.
fn stress_curve(spec: &FigureSpec, scene: &Scene) -> Result<(Vec<DataPoint>, Evaluation)> {
    let opts = Options {
        sigma_points: spec.points,
        sigma_max: Some(spec.to),
        ..Options::default()
    };
    let e = engine::evaluate(scene, &opts)?;
    let pts = e
        .stats
        .pr
        .points()
        .into_iter()
        .map(|(x, y)| point(x, Some(y), None))
        .collect();
    Ok((pts, e))
}

/// Computes the figure's data (theory, closed forms, \[S\] values; GFMD when `gfmd` is given,
/// without progress reports).
pub fn compute(spec: &FigureSpec, gfmd: Option<GfmdChoice>) -> Result<FigureData> {
    compute_on(spec, gfmd, None, &mut |_| {})
}

/// Computes the figure's data on a measured surface when `on` is given: the theory curves and
/// closed forms of its spectrum, GFMD on its map; the values \[S\] states are of the paper's
/// surfaces and are left out (with a note). The GFMD runs report to `progress`.
pub fn compute_on(
    spec: &FigureSpec,
    gfmd: Option<GfmdChoice>,
    on: Option<&Measured>,
    progress: &mut dyn FnMut(RunProgress),
) -> Result<FigureData> {
    let preset = Preset::resolve(&spec.preset)?;
    if gfmd.is_some() && on.is_some_and(|m| m.map.is_none()) {
        return Err(Error::field(
            "gfmd",
            "on a PSD table",
            "GFMD on a height map only (a measured surface, not its spectrum)",
        ));
    }
    let mut data = FigureData {
        id: spec.id.clone(),
        title: match on {
            Some(m) => format!("{} — on {}", spec.title, m.name()),
            None => spec.title.clone(),
        },
        spectrum_source: on.map(Measured::name),
        preset: preset.name.clone(),
        x_label: x_label(spec.x).to_string(),
        y_label: y_label(spec.y).to_string(),
        x_log: spec.x_log,
        y_log: spec.y_log,
        y_decades: spec.y_decades,
        series: Vec::new(),
        notes: Vec::new(),
    };
    let scenes: Vec<Scene> = spec
        .curve
        .iter()
        .map(|c| {
            let s = on_surface(curve_scene(&preset, &spec.overrides(), &c.overrides())?, on)?;
            match &c.variant {
                Some(v) => s.clone().with_model(Model::of_kind(v.parse()?, &s.model())?),
                None => Ok(s),
            }
        })
        .collect::<Result<_>>()?;
    let kinds = curve_kinds(&scenes);
    let mut widths: Vec<(u8, f64, f64)> = Vec::new(); // (model, p*, Δ*) for the asymptotes
    if spec.x == XAxis::Stress {
        for ((c, scene), &kind) in spec.curve.iter().zip(&scenes).zip(&kinds) {
            let points = match stress_curve(spec, scene) {
                Ok((pts, e)) => {
                    data.notes.push(format!(
                        "{}: a_r = {:.4}, σ̄_c* = {:.4}, ⟨δσ_c²⟩* = {:.4}, Δ* = {:.4}",
                        c.label, e.stats.a_r, e.stats.mean_contact_stress, e.stats.contact_stress_variance, e.width
                    ));
                    if let Some(n) = scene.model().number() {
                        widths.push((n, scene.pressure(), e.width));
                    }
                    pts
                }
                Err(e @ Error::NotConverged { .. }) => {
                    data.notes.push(format!("{}: {e}", c.label));
                    Vec::new()
                }
                Err(e) => return Err(e),
            };
            data.series.push(DataSeries {
                name: c.label.clone(),
                style: Style::Line,
                points,
                kind,
            });
        }
    } else {
        // every curve on the file's x values, then each refined where it bends on the axes
        // they share
        let base: Vec<Vec<Sample>> = spec
            .curve
            .iter()
            .zip(&scenes)
            .map(|(_, scene)| sweep_curve(spec, scene))
            .collect::<Result<_>>()?;
        let axes = refine_axes(spec, &base);
        let x_name = x_name(spec.x);
        let refined: Vec<Refined> = scenes
            .par_iter()
            .zip(base)
            .map(|(scene, first)| refine::refine_from(first, &axes, &|x| sample_at(spec, scene, x)))
            .collect();
        for ((c, &kind), refined) in spec.curve.iter().zip(&kinds).zip(refined) {
            for s in refined.samples.iter().filter(|s| s.y.is_none()) {
                data.notes.push(format!(
                    "{} at x = {:e}: no value ({})",
                    c.label,
                    s.x,
                    s.note.as_deref().unwrap_or("unavailable")
                ));
            }
            let series = branch_series(&c.label, kind, &refined, &axes, x_name, &mut data.notes);
            data.series.extend(series);
        }
    }
    closed_form_series(spec, &widths, &mut data);
    paper_series(spec, on, &mut data);
    if let Some(choice) = gfmd {
        let runs = Runs {
            spec,
            preset: &preset,
            scenes: &scenes,
            choice,
            on,
        };
        gfmd_series(runs, &mut data, progress)?;
    }
    Ok(data)
}

/// The closed forms of the figure (eq. (18), the small- and large-stress asymptotes of Pr
/// with the Δ* of their model's curve in `widths`: (model, p*, Δ*)).
fn closed_form_series(spec: &FigureSpec, widths: &[(u8, f64, f64)], data: &mut FigureData) {
    for cf in &spec.closed_form {
        let points: Vec<DataPoint> = match cf.kind {
            ClosedFormKind::Eq18 => x_values(spec)
                .into_iter()
                .map(|p| {
                    let a = closed_form::eq18_area(p);
                    point(p, Some(if spec.y == YAxis::AROverP { a / p } else { a }), None)
                })
                .collect(),
            ClosedFormKind::PrSmallStress | ClosedFormKind::PrLargeStress => {
                let m = cf.model.expect("validated");
                let Some(&(_, p, d)) = widths.iter().find(|w| w.0 == m) else {
                    data.notes
                        .push(format!("{}: no curve of model {m} to take Δ* from", cf.label));
                    continue;
                };
                // log-spaced σ* over the figure's range
                let n = 200;
                let lo = spec.to * 1e-4;
                (0..n)
                    .map(|i| lo * (spec.to / lo).powf(i as f64 / (n - 1) as f64))
                    .map(|s| {
                        let y = if cf.kind == ClosedFormKind::PrSmallStress {
                            closed_form::pr_small_stress(s, p, d)
                        } else {
                            closed_form::pr_large_stress(s, p, d)
                        };
                        point(s, Some(y), None)
                    })
                    .collect()
            }
        };
        data.series.push(DataSeries {
            name: cf.label.clone(),
            style: Style::Dashed,
            points,
            kind: SeriesKind::ClosedForm {
                second: cf.kind == ClosedFormKind::PrLargeStress,
            },
        });
    }
}

/// The values \[S\] states, one series per source (left out on a measured surface `on`, with
/// a note).
fn paper_series(spec: &FigureSpec, on: Option<&Measured>, data: &mut FigureData) {
    let mut labels: Vec<&str> = Vec::new();
    if let (Some(m), false) = (on, spec.paper.is_empty()) {
        data.notes.push(format!(
            "the values [S] states are of the paper's surfaces: not drawn on {}",
            m.name()
        ));
    }
    for pp in spec.paper.iter().filter(|_| on.is_none()) {
        if !labels.contains(&pp.label.as_str()) {
            labels.push(&pp.label);
        }
    }
    for (nth, l) in labels.into_iter().enumerate() {
        // the model of the values where one of them names it
        let of = spec.paper.iter().filter(|p| p.label == l);
        let model = of
            .clone()
            .find_map(|p| p.model)
            .and_then(|m| Model::named(m).ok())
            .map(|m| m.kind);
        data.series.push(DataSeries {
            name: l.to_string(),
            style: Style::Points,
            points: of.map(|p| point(p.x, Some(p.y), None)).collect(),
            kind: SeriesKind::Paper { model, nth },
        });
    }
}

/// What each curve is: its model's curve, numbered as a repeat where a curve of the same
/// model came before (Fig. 8: one model at several thicknesses), so a front end can tell the
/// curves apart.
fn curve_kinds(scenes: &[Scene]) -> Vec<SeriesKind> {
    let models: Vec<ModelKind> = scenes.iter().map(|s| s.model().kind).collect();
    let mut extra = 0;
    models
        .iter()
        .enumerate()
        .map(|(i, &model)| {
            let repeat = models[..i].contains(&model).then(|| {
                extra += 1;
                extra - 1
            });
            SeriesKind::Theory { model, repeat }
        })
        .collect()
}

/// The options of every GFMD run of a figure.
pub fn gfmd_options() -> GfmdOptions {
    GfmdOptions {
        tolerance: 1e-8,
        ..GfmdOptions::default()
    }
}

/// One GFMD run of `scene` on the chosen grid, or on `map` where one is given: run `run` of
/// `runs` (the figure's GFMD points), reporting to `progress`.
pub fn gfmd_run(
    preset: &Preset,
    scene: &Scene,
    (choice, map): (GfmdChoice, Option<&Surface>),
    (run, runs): (usize, usize),
    progress: &mut dyn FnMut(RunProgress),
) -> Result<GfmdResult> {
    let grid = GridSpec::of_preset(preset, choice.grid.map(|n| n as i64))?;
    let setup = GfmdSetup {
        scene: scene.clone(),
        grid,
        seed: choice.seed,
        surface: map.cloned(),
        // the reduced grid keeps the full system's gamma_glo and Tabor parameter
        rescale: true,
    };
    let pressure = scene.pressure();
    gfmd::run(
        &setup,
        &gfmd_options(),
        &mut |solver| {
            progress(RunProgress {
                run,
                runs,
                pressure,
                solver,
            })
        },
        &AtomicBool::new(false),
    )
}

/// What a figure's GFMD runs are of: the figure, its preset, the curves' scenes, the grid and
/// seed, and the measured surface where there is one.
#[derive(Clone, Copy)]
struct Runs<'a> {
    spec: &'a FigureSpec,
    preset: &'a Preset,
    scenes: &'a [Scene],
    choice: GfmdChoice,
    on: Option<&'a Measured>,
}

/// A stress-axis figure's GFMD: Pr(σ*) of one run per distinct scene of the curves.
fn gfmd_pr_series(runs: Runs, data: &mut FigureData, progress: &mut dyn FnMut(RunProgress)) {
    let Runs {
        spec,
        preset,
        scenes,
        choice,
        on,
    } = runs;
    let map = on.and_then(|m| m.map.as_ref());
    let mut done: Vec<(f64, f64, f64)> = Vec::new();
    for (c, s) in spec.curve.iter().zip(scenes) {
        let key = (s.pressure(), s.thickness_qr(), s.surface_energy_j_m2());
        if !spec.gfmd || done.contains(&key) {
            continue;
        }
        done.push(key);
        let name = if spec.curve.iter().all(|c| c.thickness_qr.is_none()) {
            "GFMD".to_string()
        } else {
            format!("GFMD, {}", c.label)
        };
        match gfmd_run(preset, s, (choice, map), (done.len() - 1, scenes.len()), progress) {
            Ok(r) => {
                let map_words = match on {
                    Some(m) => format!("on {}", m.name()),
                    None => format!("{}, seed {}", map_description(&r), choice.seed),
                };
                data.notes.push(format!(
                    "{name}: {}² grid, {map_words}: a_r = {:.4}, σ̄_c* = {:.4}, ⟨δσ_c²⟩* = {:.4}{}",
                    r.grid,
                    r.stats.a_r,
                    r.stats.mean_contact_stress,
                    r.stats.contact_stress_variance,
                    r.theory.as_ref().map_or(String::new(), |t| format!(
                        "; theory on the same map ({}): a_r = {:.4}",
                        t.model, t.stats.a_r
                    ))
                ));
                data.series.push(DataSeries {
                    name: format!("{name} ({}²)", r.grid),
                    style: Style::Points,
                    kind: SeriesKind::Gfmd,
                    points: r
                        .stats
                        .pr
                        .points()
                        .into_iter()
                        .map(|(x, y)| point(x, Some(y), None))
                        .collect(),
                });
            }
            Err(e) => data.notes.push(format!("{name}: {e}")),
        }
    }
}

/// A sweep figure's GFMD: one run at each x of `gfmd_at` (the theory on the same map beside
/// it); a stress figure's: [`gfmd_pr_series`].
fn gfmd_series(runs: Runs, data: &mut FigureData, progress: &mut dyn FnMut(RunProgress)) -> Result<()> {
    let Runs {
        spec,
        preset,
        choice,
        on,
        ..
    } = runs;
    // GFMD does not depend on the model: the figure's scene without the curves' models
    let base = on_surface(curve_scene(preset, &spec.overrides(), &Overrides::default())?, on)?;
    let map = on.and_then(|m| m.map.as_ref());
    if spec.x == XAxis::Stress {
        gfmd_pr_series(runs, data, progress);
        return Ok(());
    }
    let mut points = Vec::new();
    let mut on_map: Vec<DataPoint> = Vec::new();
    let mut grid = 0;
    let mut map_note = String::new();
    for (k, &x) in spec.gfmd_at.iter().enumerate() {
        let s = match spec.x {
            XAxis::Pressure => base.clone().with_pressure(x),
            XAxis::Thickness => base.clone().with_thickness_qr(x),
            XAxis::Gamma => base.clone().with_surface_energy_j_m2(x),
            XAxis::Stress => Ok(base.clone()),
        };
        let run = s.and_then(|s| {
            Ok((
                gfmd_run(preset, &s, (choice, map), (k, spec.gfmd_at.len()), progress)?,
                s,
            ))
        });
        match run {
            Ok((r, s)) => {
                grid = r.grid;
                map_note = map_description(&r);
                let st = &r.stats;
                let gap = Some(r.mean_gap_rel);
                let y = y_of(
                    spec.y,
                    s.pressure(),
                    st.a_r,
                    st.mean_contact_stress,
                    st.contact_stress_variance,
                    gap,
                );
                points.push(point(x, y, None));
                // the theory on the same map (its discrete, reduced spectrum): the like-for-like
                // comparison (no mean gap on the map)
                let th = r.theory.as_ref().and_then(|t| {
                    let st = &t.stats;
                    y_of(
                        spec.y,
                        s.pressure(),
                        st.a_r,
                        st.mean_contact_stress,
                        st.contact_stress_variance,
                        None,
                    )
                });
                on_map.push(point(x, th, r.theory_error.clone()));
            }
            Err(e) => {
                data.notes.push(format!("GFMD at x = {x:e}: {e}"));
                points.push(point(x, None, Some(e.to_string())));
                on_map.push(point(x, None, Some(e.to_string())));
            }
        }
    }
    if grid > 0 {
        data.notes.push(match on {
            Some(m) => format!(
                "GFMD: on {} ({grid}² grid); the theory curves are of its tabulated spectrum, the \
                 \"theory on the GFMD map\" points of the map's own discrete one",
                m.name()
            ),
            None => format!(
                "GFMD: {grid}² grid, {map_note} (the preset's reduced grid unless another grid was asked for), seed {}; the theory \
                 curves are of the full spectrum, the \"theory on the GFMD map\" points of the map's own",
                choice.seed
            ),
        });
    }
    data.series.push(DataSeries {
        name: if grid > 0 {
            format!("GFMD ({grid}²)")
        } else {
            "GFMD".into()
        },
        style: Style::Points,
        points,
        kind: SeriesKind::Gfmd,
    });
    if spec.y != YAxis::MeanGapRel {
        data.series.push(DataSeries {
            name: format!("theory on the GFMD map ({})", base.model().label()),
            style: Style::Points,
            points: on_map,
            kind: SeriesKind::GfmdTheory,
        });
    }
    Ok(())
}

/// The map's reduced geometry in words (L/λ_r, λ_r/λ_s, λ_s/Δa).
fn map_description(r: &GfmdResult) -> String {
    match &r.grid_spec {
        Some(g) => format!(
            "L/λ_r = {}, λ_r/λ_s = {}, λ_s/Δa = {}",
            g.system_size_ratio, g.bandwidth, g.points_per_short_wavelength
        ),
        None => "a given map".into(),
    }
}
