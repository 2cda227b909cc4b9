//! The theory from Python: `evaluate` ([`asperity::report::point()`], the object of
//! `asperity run --format json`), the load sweep ([`asperity::theory::sweep`], the rows of
//! `asperity sweep --format json`) and the knob sweeps over t·q_r or γ_s
//! ([`asperity::theory::knob`], `asperity sweep --over thickness|gamma`), each computed on a
//! worker thread without the GIL ([`crate::work`]).
//!
//! A sweep's values are the caller's: evenly spaced ones (log-spaced loads and thicknesses,
//! linear γ_s, as `np.geomspace`/`np.linspace` give them) run as one library sweep, exactly as
//! the CLI's `--from --to --points`; any other ascending list runs as one single-value sweep
//! per value. A value that does not converge leaves NaN (None in `to_dict()`) in its row with
//! the reason in `reasons`; invalid input fails the call before any work.
//!
//! A load sweep with `cycle` (`asperity sweep --cycle`) adds the theory's path along the load
//! cycle under `cycle` ([`asperity::theory::cycle::path_through_tension`]: up on the loading
//! branch, back down on the unloading branch and on into tension to the theory's pull-off);
//! `cycle(scene, from_, to, points)` is that path over the CLI's loads (`--from --to
//! --points`, log-spaced).

use crate::errors;
use crate::scene::SceneCore;
use crate::value;
use crate::work::{self, Info};
use asperity::error::{Error, Field, Result};
use asperity::input::scene::{Scene, PRESSURE_RANGE};
use asperity::theory::adhesion::AdhesionAccuracy;
use asperity::theory::closed_form::eq18_area;
use asperity::theory::cycle::{path_through_tension, TheoryCycle};
use asperity::theory::engine::Options;
use asperity::theory::hysteresis::{self, EdgeKind, KnobEdge};
use asperity::theory::knob::{self, Knob, KnobPoint, KnobSpec};
use asperity::theory::persson::Accuracy;
use asperity::theory::sweep::{self, SweepRow, SweepSpec};
use pyo3::prelude::*;
use serde::Serialize;

/// The engine's options of `evaluate` (the accuracy flags of `asperity run`).
#[pyfunction]
#[pyo3(signature = (sigma_points = 201, sigma_max = None, rtol = None, adhesion_steps = None, adhesion_points = None, adhesion_tol = None))]
pub fn options_check(
    py: Python<'_>,
    sigma_points: usize,
    sigma_max: Option<f64>,
    rtol: Option<f64>,
    adhesion_steps: Option<f64>,
    adhesion_points: Option<f64>,
    adhesion_tol: Option<f64>,
) -> PyResult<()> {
    let o = options(
        sigma_points,
        sigma_max,
        rtol,
        adhesion_steps,
        adhesion_points,
        adhesion_tol,
    );
    errors::guard(py, || o.validate())
}

fn options(
    sigma_points: usize,
    sigma_max: Option<f64>,
    rtol: Option<f64>,
    adhesion_steps: Option<f64>,
    adhesion_points: Option<f64>,
    adhesion_tol: Option<f64>,
) -> Options {
    let a = AdhesionAccuracy::default();
    Options {
        accuracy: Accuracy {
            rtol: rtol.unwrap_or(Accuracy::default().rtol),
            ..Accuracy::default()
        },
        sigma_points,
        sigma_max,
        adhesion: AdhesionAccuracy {
            steps_per_ln_q: adhesion_steps.unwrap_or(a.steps_per_ln_q),
            points_per_width: adhesion_points.unwrap_or(a.points_per_width),
            tol: adhesion_tol.unwrap_or(a.tol),
            ..a
        },
        ..Options::default()
    }
}

/// `evaluate(scene, ...)`: the report of one scene at its load, as a dict with the keys of
/// `asperity run --format json` (the preset's name under `preset`).
#[pyfunction]
#[pyo3(signature = (scene, sigma_points = 201, sigma_max = None, rtol = None, adhesion_steps = None, adhesion_points = None, adhesion_tol = None, progress = None))]
#[allow(clippy::too_many_arguments)]
pub fn evaluate<'py>(
    py: Python<'py>,
    scene: &SceneCore,
    sigma_points: usize,
    sigma_max: Option<f64>,
    rtol: Option<f64>,
    adhesion_steps: Option<f64>,
    adhesion_points: Option<f64>,
    adhesion_tol: Option<f64>,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let opts = options(
        sigma_points,
        sigma_max,
        rtol,
        adhesion_steps,
        adhesion_points,
        adhesion_tol,
    );
    let s = scene.scene.clone();
    let report = work::run(py, progress.as_ref(), move |_| asperity::report::point(&s, &opts))?;
    value::ser_with_preset(py, &scene.preset.name, &report)
}

/// One row of a sweep (the CLI's `sweep` row: the engine's row, a_r/p*, [S-18], t·q_r, γ_s).
#[derive(Debug, Clone, Serialize)]
struct Row {
    #[serde(flatten)]
    row: SweepRow,
    a_r_over_p: f64,
    a_r_eq18: Option<f64>,
    thickness_qr: Option<f64>,
    gamma: f64,
    trust_inside: bool,
    trust_a_r_log_error: f64,
    /// Why the row has no numbers, on one line (the CLI's `reason`); None for a complete row.
    reason: Option<String>,
}

impl Row {
    /// The row with `reason`.
    fn with_reason(self, reason: Option<String>) -> Row {
        Row { reason, ..self }
    }

    /// The row of `row` for `scene` at the row's load, with the trust read-out
    /// ([`asperity::fit::trust`]), as the CLI's.
    fn new(row: SweepRow, scene: &asperity::input::scene::Scene) -> Row {
        let (thickness_qr, gamma) = (scene.thickness_qr(), scene.surface_energy_j_m2());
        let eq18 = (gamma == 0.0 && thickness_qr.is_infinite()).then(|| eq18_area(row.p));
        let at = scene.clone().with_pressure(row.p).unwrap_or_else(|_| scene.clone());
        let trust = asperity::fit::trust::assess(&at);
        Row {
            row,
            a_r_over_p: row.a_r / row.p,
            a_r_eq18: eq18,
            thickness_qr: thickness_qr.is_finite().then_some(thickness_qr),
            gamma,
            trust_inside: trust.inside,
            trust_a_r_log_error: trust.a_r_log_error,
            reason: None,
        }
    }
}

/// The object of `asperity sweep --format json`, with one reason per row (None: converged).
#[derive(Debug, Serialize)]
struct SweepOut {
    preset: String,
    over: &'static str,
    scene: asperity::input::scene::SceneSummary,
    rows: Vec<Row>,
    evaluations: usize,
    full_contact_pressure: f64,
    monotone: bool,
    failed_loads: Vec<f64>,
    failed_values: Vec<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    note: Option<String>,
    jump_in_pressure: Option<f64>,
    pull_off_pressure: Option<f64>,
    window_edges: Vec<KnobEdge>,
    /// With `cycle`: the theory's path along the load cycle (the CLI's `sweep --cycle`).
    #[serde(skip_serializing_if = "Option::is_none")]
    cycle: Option<TheoryCycle>,
    #[serde(skip)]
    reasons: Vec<Option<String>>,
}

impl SweepOut {
    fn into_py<'py>(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let d = value::ser(py, &self)?;
        d.set_item("reasons", self.reasons)?;
        Ok(d)
    }
}

/// Whether `values` (ascending) are `spec`'s to 1e-9 relative.
fn same_values(values: &[f64], spec: &[f64]) -> bool {
    values.len() == spec.len()
        && values
            .iter()
            .zip(spec)
            .all(|(a, b)| a == b || (a - b).abs() <= 1e-9 * a.abs().max(b.abs()))
}

/// Checks that `values` is a non-empty ascending list.
fn check_ascending(values: &[f64], field: &str) -> Result<()> {
    if values.is_empty() {
        return Err(Error::invalid_text(
            Field::Other(field.into()),
            "[] (empty)",
            "one or more values",
        ));
    }
    if let Some(w) = values.windows(2).find(|w| w[1] <= w[0] || w[1].is_nan()) {
        return Err(Error::invalid(
            Field::Other(field.into()),
            w[1],
            format!("strictly ascending values (after {})", asperity::error::fmt_value(w[0])),
        ));
    }
    Ok(())
}

/// The library sweeps that give `pressures` (module docs): one sweep where they are evenly
/// log-spaced, else one single-load sweep per value. With `cycle` the loads must be one sweep's
/// (the path follows the sweep's branches).
fn pressure_specs(pressures: &[f64], cycle: bool) -> Result<Vec<SweepSpec>> {
    check_ascending(pressures, "pressures")?;
    for &p in pressures {
        asperity::error::check_in(Field::Pressure, p, PRESSURE_RANGE.0, PRESSURE_RANGE.1)?;
    }
    let n = pressures.len();
    let spec = SweepSpec {
        from: pressures[0],
        to: pressures[n - 1],
        points: n,
    };
    let even = spec.pressures();
    if same_values(pressures, &even) {
        return Ok(vec![spec]);
    }
    if cycle {
        let (k, &v) = pressures
            .iter()
            .enumerate()
            .find(|(k, p)| !same_values(&[**p], &[even[*k]]))
            .expect("a value off the log-spaced loads");
        return Err(Error::invalid(
            Field::Other("pressures".into()),
            v,
            format!(
                "log-spaced loads with cycle=True (np.geomspace(first, last, n)): {} at position {k}",
                asperity::error::fmt_value(even[k])
            ),
        ));
    }
    Ok(pressures
        .iter()
        .map(|&p| SweepSpec {
            from: p,
            to: p,
            points: 1,
        })
        .collect())
}

/// The load sweep of `core`'s scene over the loads of `specs` (`n` in all; module docs), with
/// the theory's path along the cycle when `cycle` (`specs` then one sweep).
fn pressure_sweep(
    core: &SceneCore,
    specs: &[SweepSpec],
    opts: &Options,
    ctx: &work::Ctx,
    cycle: bool,
) -> Result<SweepOut> {
    let n: usize = specs.iter().map(|s| s.points).sum();
    let scene = core.scene.clone().with_pressure(specs[0].from)?;
    let single = specs.len() == 1;
    let mut out = SweepOut {
        preset: core.preset.name.clone(),
        over: "pressure",
        scene: scene.summary(),
        rows: Vec::new(),
        evaluations: 0,
        full_contact_pressure: f64::NAN,
        monotone: true,
        failed_loads: Vec::new(),
        failed_values: Vec::new(),
        note: None,
        jump_in_pressure: None,
        pull_off_pressure: None,
        window_edges: Vec::new(),
        cycle: None,
        reasons: Vec::new(),
    };
    let mut notes = Vec::new();
    for (k, sp) in specs.iter().enumerate() {
        ctx.report(Info {
            stage: "sweep",
            done: if single { 0 } else { k },
            total: n,
            residual: f64::NAN,
            contact_fraction: f64::NAN,
        });
        let sw = sweep::sweep(&scene, sp, opts, Some(&*ctx.cancel))?;
        if cycle && single {
            out.cycle = Some(path_through_tension(&sw, &scene, &opts.adhesion, Some(&*ctx.cancel))?);
        }
        for (r, why) in sw.rows.iter().zip(&sw.reasons) {
            // the row's own reason (the solver's error at that load)
            let reason = (!r.converged).then(|| {
                why.clone()
                    .or_else(|| sw.note.clone())
                    .unwrap_or_else(|| "did not converge".into())
            });
            out.rows.push(Row::new(*r, &scene).with_reason(why.clone()));
            out.reasons.push(reason);
        }
        out.evaluations += sw.evaluations;
        if k == 0 {
            out.full_contact_pressure = sw.full_contact_pressure;
        }
        out.failed_loads.extend(&sw.failed_loads);
        notes.extend(sw.note.clone());
        if single {
            out.monotone = sw.monotone;
            out.jump_in_pressure = sw.jump_in_pressure;
            out.pull_off_pressure = sw.pull_off_pressure;
            out.window_edges = [
                (sw.pull_off_pressure, EdgeKind::PullOff),
                (sw.jump_in_pressure, EdgeKind::JumpIn),
            ]
            .into_iter()
            .filter_map(|(v, kind)| v.map(|value| KnobEdge { value, kind }))
            .collect();
        }
    }
    if !single {
        let ok: Vec<&Row> = out.rows.iter().filter(|r| r.row.converged).collect();
        out.monotone = ok.windows(2).all(|w| {
            w[1].row.a_r >= w[0].row.a_r
                && w[1].row.mean_gap_rel.partial_cmp(&w[0].row.mean_gap_rel) != Some(std::cmp::Ordering::Greater)
        });
    }
    out.failed_values = out.failed_loads.clone();
    out.note = (!notes.is_empty()).then(|| notes.join("; "));
    Ok(out)
}

/// The row of one value of a knob sweep (as `asperity sweep --over`), with the reason it lacks
/// numbers (the solve's error, or why the mean gap is unavailable).
fn knob_row(pt: &KnobPoint, pressure: f64, unit: f64) -> (Row, Option<String>) {
    let reason = match (&pt.result, &pt.gap) {
        (Err(e), _) => Some(e.to_string()),
        (Ok(_), Err(e)) => Some(format!("mean gap unavailable: {e}")),
        (Ok(_), Ok(_)) => None,
    };
    let r = pt.row(pressure, unit);
    let reason = reason.map(|r| asperity::theory::sweep::one_line(&r));
    (Row::new(r, &pt.scene).with_reason(reason.clone()), reason)
}

/// The knob sweep of `scene` over `values` of `knob` at the scene's p* (module docs).
fn knob_sweep(core: &SceneCore, kn: Knob, values: &[f64], opts: &Options, ctx: &work::Ctx) -> Result<SweepOut> {
    let field = match kn {
        Knob::Thickness => "thickness_qr",
        Knob::Gamma => "surface_energy_j_m2",
    };
    check_ascending(values, field)?;
    let scene: &Scene = &core.scene;
    let n = values.len();
    let spec = KnobSpec {
        knob: kn,
        from: values[0],
        to: values[n - 1],
        points: n,
    };
    // every value valid before any work (the error names the scene's field)
    if let Some(&v) = values.iter().find(|v| kn == Knob::Thickness && !v.is_finite()) {
        return Err(Error::invalid(
            Field::Thickness,
            v,
            "a finite t*q_r in a sweep (the half-space: evaluate the scene with thickness_qr = inf)",
        ));
    }
    for &v in values {
        let ok = match kn {
            Knob::Thickness => scene.clone().with_thickness_qr(v).map(|_| ()),
            Knob::Gamma => scene.clone().with_surface_energy_j_m2(v).map(|_| ()),
        };
        ok?;
    }
    let specs: Vec<KnobSpec> = if spec.validate().is_ok() && same_values(values, &spec.values()) {
        vec![spec]
    } else {
        values
            .iter()
            .map(|&v| KnobSpec {
                knob: kn,
                from: v,
                to: v,
                points: 1,
            })
            .collect()
    };
    let mut points: Vec<KnobPoint> = Vec::with_capacity(n);
    for sp in &specs {
        ctx.report(Info {
            stage: "sweep",
            done: points.len(),
            total: n,
            residual: f64::NAN,
            contact_fraction: f64::NAN,
        });
        points.extend(knob::knob_sweep(scene, sp, opts, true, Some(&*ctx.cancel))?);
    }
    let window_edges = hysteresis::knob_edges(scene, kn, &points, &opts.adhesion, Some(&*ctx.cancel))?;
    let unit = asperity::theory::energy::energy_unit(scene);
    let first = kn.apply(scene, values[0]);
    let mut notes = Vec::new();
    let mut failed = Vec::new();
    let mut reasons = Vec::new();
    let rows: Vec<Row> = points
        .iter()
        .map(|pt| {
            let (row, reason) = knob_row(pt, scene.pressure(), unit);
            if pt.result.is_err() {
                failed.push(pt.value);
            }
            if let Some(why) = &reason {
                notes.push(format!("value {:e}: {why}", pt.value));
            }
            reasons.push(reason);
            row
        })
        .collect();
    let note = (!notes.is_empty()).then(|| {
        format!(
            "{} of {} values did not converge or lack the gap; their cells are empty (null): {}",
            notes.len(),
            points.len(),
            notes.join("; ")
        )
    });
    Ok(SweepOut {
        preset: core.preset.name.clone(),
        over: match kn {
            Knob::Thickness => "thickness",
            Knob::Gamma => "gamma",
        },
        scene: first.summary(),
        rows,
        evaluations: points.len(),
        full_contact_pressure: asperity::theory::gap::full_contact_pressure(&first),
        monotone: true,
        failed_loads: failed.iter().map(|_| scene.pressure()).collect(),
        failed_values: failed,
        note,
        jump_in_pressure: None,
        pull_off_pressure: None,
        window_edges,
        cycle: None,
        reasons,
    })
}

/// `sweep(scene, values, over, progress, cycle)`: a sweep over p* (`over="pressure"`), t·q_r
/// (`"thickness"`) or γ_s in J/m² (`"gamma"`), as a dict with the keys of
/// `asperity sweep --format json` and `reasons`; a load sweep with `cycle` adds the theory's
/// path along the cycle (module docs).
#[pyfunction]
#[pyo3(name = "sweep", signature = (scene, values, over = "pressure", progress = None, cycle = false))]
pub fn run_sweep<'py>(
    py: Python<'py>,
    scene: &SceneCore,
    values: Vec<f64>,
    over: &str,
    progress: Option<Bound<'py, PyAny>>,
    cycle: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let opts = Options::default();
    let core = scene.clone();
    if cycle && !matches!(over, "pressure") {
        return Err(errors::input(
            py,
            "cycle",
            "True",
            "only with over=\"pressure\" (a load cycle runs over p*)",
        ));
    }
    let out = match over {
        "pressure" => {
            let specs = errors::guard(py, || pressure_specs(&values, cycle))?;
            work::run(py, progress.as_ref(), move |ctx| {
                pressure_sweep(&core, &specs, &opts, ctx, cycle)
            })?
        }
        "thickness" | "thickness_qr" => work::run(py, progress.as_ref(), move |ctx| {
            knob_sweep(&core, Knob::Thickness, &values, &opts, ctx)
        })?,
        "gamma" | "surface_energy_j_m2" => work::run(py, progress.as_ref(), move |ctx| {
            knob_sweep(&core, Knob::Gamma, &values, &opts, ctx)
        })?,
        other => return Err(errors::input(py, "over", other, "pressure, thickness or gamma")),
    };
    out.into_py(py)
}

/// `cycle(scene, from_, to, points)`: the theory's path along the load cycle over the loads of
/// `asperity sweep --from --to --points` (log-spaced), as the dict under `cycle` of
/// `asperity sweep --cycle --format json` (module docs).
#[pyfunction]
#[pyo3(name = "cycle", signature = (scene, from_, to, points = 64, progress = None))]
pub fn run_cycle<'py>(
    py: Python<'py>,
    scene: &SceneCore,
    from_: f64,
    to: f64,
    points: usize,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let spec = SweepSpec {
        from: from_,
        to,
        points,
    };
    errors::guard(py, || spec.validate())?;
    let opts = Options::default();
    let core = scene.clone();
    let out = work::run(py, progress.as_ref(), move |ctx| {
        pressure_sweep(&core, &[spec], &opts, ctx, true)
    })?;
    value::ser(py, &out.cycle)
}
