//! The theory from Python: `evaluate` ([`asperity::report::point()`], the object of
//! `asperity run --format json`) and the sweeps over p*, t·q_r or γ_s
//! ([`asperity::report::sweep`], the object of `asperity sweep --format json`), each computed
//! on a worker thread without the GIL ([`crate::work`]).
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
use crate::record::Record;
use crate::report::Report;
use crate::scene::SceneCore;
use crate::value;
use crate::work::{self, Info};
use asperity::error::{Allowed, Error, Result};
use asperity::input::overrides::AccuracyKnobs;
use asperity::report::sweep::{self, Over, SweepReport};
use asperity::theory::engine::Options;
use asperity::theory::sweep::SweepSpec;
use pyo3::prelude::*;
use std::sync::Arc;

/// `evaluate(scene, ...)`: the [`Report`] of one scene at its load (`to_dict()`: the keys of
/// `asperity run --format json`, the preset's name under `preset`).
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
) -> PyResult<Report> {
    let mut opts = AccuracyKnobs {
        sigma_points: Some(sigma_points),
        sigma_max,
        rtol,
        adhesion_steps,
        adhesion_points,
        adhesion_tol,
    }
    .options();
    // a scene exported on the unloading branch (`[load] branch = "unloading"`) reports it, as
    // `asperity run --preset` does
    opts.adhesion.follow_unloading = scene.preset.follows_unloading();
    let s = scene.scene.clone();
    let report = work::run(py, progress.as_ref(), move |_| asperity::report::point(&s, &opts))?;
    Report::new(py, &scene.preset.name, &report)
}

/// The report as a [`Record`] with `reasons`: each row's reason, and for a load row that did
/// not converge without one of its own the sweep's note (None: converged).
fn into_py(py: Python<'_>, report: &SweepReport) -> PyResult<Record> {
    let reasons: Vec<Option<String>> = report
        .rows
        .iter()
        .map(|r| match report.over {
            Over::Pressure => (!r.row.converged).then(|| {
                r.reason
                    .clone()
                    .or_else(|| report.note.clone())
                    .unwrap_or_else(|| "did not converge".into())
            }),
            _ => r.reason.clone(),
        })
        .collect();
    let mut data = value::json(report)?;
    data["reasons"] = value::json(&reasons)?;
    Record::new(py, Arc::new(data))
}

/// A load cycle's loads in Python's words: `cycle=True` and the `np.geomspace` that gives them.
fn python_words(e: Error) -> Error {
    match e {
        Error::Invalid {
            field,
            value,
            allowed: Allowed::Text(t),
        } => Error::Invalid {
            field,
            value,
            allowed: Allowed::Text(t.replace(
                sweep::CYCLE_LOADS_WORDS,
                "with cycle=True (np.geomspace(first, last, n))",
            )),
        },
        e => e,
    }
}

/// Progress of a sweep as the callback's `sweep` stage.
fn sweep_progress(ctx: &work::Ctx) -> impl FnMut(usize, usize) + '_ {
    |done, total| {
        ctx.report(Info {
            stage: "sweep",
            done,
            total,
            residual: f64::NAN,
            contact_fraction: f64::NAN,
        })
    }
}

/// The load sweep ([`sweep::pressure`]) of `core` over `specs` on the worker.
fn pressure_sweep(
    core: &SceneCore,
    specs: &[SweepSpec],
    opts: &Options,
    ctx: &work::Ctx,
    cycle: bool,
) -> Result<SweepReport> {
    let mut report = sweep_progress(ctx);
    let ctl = sweep::Control {
        cancel: Some(&*ctx.cancel),
        progress: &mut report,
    };
    sweep::pressure(&core.scene, &core.preset.name, specs, opts, cycle, ctl)
}

/// `sweep(scene, values, over, progress, cycle)`: a sweep over p* (`over="pressure"`), t·q_r
/// (`"thickness"`) or γ_s in J/m² (`"gamma"`), as a [`Record`] with the keys of
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
) -> PyResult<Record> {
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
    let Ok(over) = over.parse::<Over>() else {
        return Err(errors::input(py, "over", over, "pressure, thickness or gamma"));
    };
    let out = match over.knob() {
        None => {
            let specs = errors::guard(py, || sweep::pressure_specs(&values, cycle).map_err(python_words))?;
            work::run(py, progress.as_ref(), move |ctx| {
                pressure_sweep(&core, &specs, &opts, ctx, cycle)
            })?
        }
        Some(knob) => {
            let specs = errors::guard(py, || sweep::knob_specs(&core.scene, knob, &values))?;
            work::run(py, progress.as_ref(), move |ctx| {
                let mut report = sweep_progress(ctx);
                let ctl = sweep::Control {
                    cancel: Some(&*ctx.cancel),
                    progress: &mut report,
                };
                sweep::knob(&core.scene, &core.preset.name, knob, &specs, &opts, ctl)
            })?
        }
    };
    into_py(py, &out)
}

/// `cycle(scene, from_, to, points)`: the theory's path along the load cycle over the loads of
/// `asperity sweep --from --to --points` (log-spaced), as a [`Record`] of the object under `cycle` of
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
) -> PyResult<Record> {
    let spec = SweepSpec {
        from: from_,
        to,
        points,
    };
    errors::guard(py, || spec.validate())?;
    let opts = Options::default();
    let core = scene.clone();
    let out = work::run(py, progress.as_ref(), move |ctx| {
        let mut report = sweep_progress(ctx);
        let ctl = sweep::Control {
            cancel: Some(&*ctx.cancel),
            progress: &mut report,
        };
        asperity::report::cycle::cycle(&core.scene, &core.preset.name, &spec, &opts, ctl)
    })?;
    Record::of(py, &out)
}

/// The pull-off read-out of `scene` (`asperity run --pull-off`'s `pull_off`): the theory's
/// pull-off in tension, the DMT routes', GFMD's nearest and how far each was measured from
/// GFMD, as a record.
#[pyfunction]
#[pyo3(name = "pull_off", signature = (scene, progress = None))]
pub fn run_pull_off<'py>(py: Python<'py>, scene: &SceneCore, progress: Option<Bound<'py, PyAny>>) -> PyResult<Record> {
    let core = scene.clone();
    let acc = Options::default().adhesion;
    let out = work::run(py, progress.as_ref(), move |ctx| {
        asperity::report::pull_off::pull_off(&core.scene, &acc, Some(&*ctx.cancel))
    })?;
    Record::of(py, &out)
}
