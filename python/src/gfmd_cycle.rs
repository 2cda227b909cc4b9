//! GFMD's load cycle from Python ([`asperity::gfmd::cycle::run_cycle`], the object of
//! `asperity gfmd --cycle --from A --to B --points N --format json`): on one map, loading from
//! p* = A up to B (log-spaced, warm-started), unloading back down to A and on into tension
//! (p* = 0, −A, −2A, …, then bisection) until the contact is lost, the pull-off with its
//! bracket, the jump-in, the theory's sweep on the same map (`theory`) and its path along the
//! same cycle to its own pull-off (`theory_cycle`). The map is generated or given as for
//! `gfmd` ([`crate::gfmd::setup`]); every argument is checked before any work, and the walk
//! runs on a worker thread that stops within one relaxation step on Ctrl-C
//! ([`crate::work`]).
//!
//! With `cycle = false` it is the one-way sweep of `asperity gfmd --from A --to B`: loading
//! ([`asperity::gfmd::sweep::run_sweep`]) when B ≥ A, unloading (the cycle's walk without the
//! way up) when B < A.

use crate::errors;
use crate::gfmd::{info, setup, GivenMap, Knobs};
use crate::record::Record;
use crate::scene::SceneCore;
use crate::surface::on_map;
use crate::work;
use asperity::gfmd::cycle::{run_cycle, CycleSpec};
use asperity::gfmd::sweep::run_sweep;
use asperity::gfmd::Progress;
use asperity::theory::sweep::SweepSpec;
use pyo3::prelude::*;

/// `gfmd_cycle(scene, from_, to, points, map, knobs, progress, cycle)`: see the
/// module docs.
#[pyfunction]
#[pyo3(name = "gfmd_cycle")]
#[allow(clippy::too_many_arguments)]
pub fn run_gfmd_cycle<'py>(
    py: Python<'py>,
    scene: &SceneCore,
    from_: f64,
    to: f64,
    points: usize,
    map: GivenMap<'py>,
    knobs: Knobs,
    progress: Option<Bound<'py, PyAny>>,
    cycle: bool,
) -> PyResult<Record> {
    let spec = CycleSpec {
        from: from_,
        to,
        points,
        cycle,
    };
    errors::guard(py, || spec.validate())?;
    let (setup, opts) = setup(py, scene, map, knobs)?;
    let total = opts.max_iterations;
    if !cycle && to >= from_ {
        let rising = SweepSpec {
            from: from_,
            to,
            points,
        };
        let mut sw = work::run(py, progress.as_ref(), move |ctx| {
            let mut report = |_: usize, p: Progress| ctx.report(info(p, total));
            run_sweep(&setup, &rising, &opts, &mut report, &ctx.cancel)
        })?;
        let map = sw.surface.take();
        return on_map(py, &sw, map);
    }
    let mut c = work::run(py, progress.as_ref(), move |ctx| {
        let mut report = |_: usize, p: Progress| ctx.report(info(p, total));
        run_cycle(&setup, &spec, &opts, &mut report, &ctx.cancel)
    })?;
    let map = c.surface.take();
    on_map(py, &c, map)
}
