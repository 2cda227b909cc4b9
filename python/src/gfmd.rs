//! GFMD from Python: one brute-force run ([`asperity::gfmd::run`]) of a scene on a generated
//! reduced grid (the preset's `[gfmd]` grid or N×N keeping L/λ_r and λ_s/Δa) or on a given
//! map, with the theory on the same map's discrete spectrum beside it; the keys of
//! `asperity gfmd --format json`, and the map itself (`heights`, m, rows along y). The
//! relaxation runs on a worker thread without the GIL and stops within one step on Ctrl-C
//! ([`crate::work`]).

use crate::errors;
use crate::record::Record;
use crate::scene::SceneCore;
use crate::surface::{map_of, on_map};
use crate::work::{self, Info};
use asperity::gfmd::{self, GfmdOptions, GfmdSetup, Method, Progress, Stage};
use asperity::report::gfmd::GfmdSpec;
use numpy::PyReadonlyArray2;
use pyo3::prelude::*;

/// GFMD's knobs as the Python side checked them: (grid, seed, tolerance, max_iterations,
/// bins, method, rescale).
#[derive(FromPyObject)]
pub struct Knobs(Option<i64>, u64, f64, Option<usize>, Option<usize>, String, bool);

/// The map GFMD runs on: (heights in m, rows along y; the x side in m), or none (generated).
pub type GivenMap<'py> = (Option<PyReadonlyArray2<'py, f64>>, Option<f64>);

/// The run's setup and solver options from the arguments of `gfmd` and `gfmd_cycle`, every one
/// checked before any work.
pub fn setup<'py>(
    py: Python<'py>,
    scene: &SceneCore,
    (heights, size_m): GivenMap<'py>,
    Knobs(grid, seed, tolerance, max_iterations, bins, method, rescale): Knobs,
) -> PyResult<(GfmdSetup, GfmdOptions)> {
    let surface = match (&heights, size_m) {
        (Some(h), Some(l)) => Some(map_of(py, h, l)?),
        (Some(_), None) => {
            return Err(errors::input(
                py,
                "size",
                "None",
                "the map's x side in metres with heights",
            ))
        }
        (None, Some(_)) => return Err(errors::input(py, "heights", "None", "a map when size is given")),
        (None, None) => scene.map.as_deref().cloned(),
    };
    let method = errors::guard(py, || method.parse::<Method>())?;
    let spec = GfmdSpec {
        grid,
        seed,
        tolerance,
        max_iterations,
        bins,
        method,
        rescale,
        ..GfmdSpec::default()
    };
    // without the GIL: the map is generated (or checked) and transformed here
    errors::detached(py, || spec.setup(&scene.preset, &scene.scene, surface))
}

/// The progress report of a relaxation step or of the theory beside it (`total`: the step
/// limit).
pub fn info(p: Progress, total: usize) -> Info {
    Info {
        stage: if p.stage == Stage::Theory { "theory" } else { "relax" },
        done: p.iteration,
        total,
        residual: p.residual,
        contact_fraction: p.contact_fraction,
    }
}

/// `gfmd(scene, map, knobs, progress)`: see the module docs.
#[pyfunction]
#[pyo3(name = "gfmd")]
pub fn run_gfmd<'py>(
    py: Python<'py>,
    scene: &SceneCore,
    map: GivenMap<'py>,
    knobs: Knobs,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Record> {
    let (setup, opts) = setup(py, scene, map, knobs)?;
    let total = opts.max_iterations;
    let mut r = work::run(py, progress.as_ref(), move |ctx| {
        let mut report = |p: Progress| ctx.report(info(p, total));
        gfmd::run(&setup, &opts, &mut report, &ctx.cancel)
    })?;
    let map = r.surface.take();
    on_map(py, &r, map)
}
