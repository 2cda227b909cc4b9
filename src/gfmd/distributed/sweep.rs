//! [`crate::gfmd::sweep::run_sweep`] over ranks: the same loads, warm starts, rows and
//! theory sweep, bit for bit. The load loop, the rows, the measurements and the energy are the
//! serial code ([`crate::gfmd::sweep`], [`crate::gfmd::measure::measure_slab`]) on this rank's
//! rows; what is the slabs' own is the relaxation ([`super::fire`]).

use super::comm::Comm;
use super::fire::{relax_slab_from, SlabProblem};
use super::run::{prepare_slab, PreparedSlab};
use crate::error::Result;
use crate::gfmd::measure::measure_slab;
use crate::gfmd::relax::Relaxation;
use crate::gfmd::sweep::{beside_theory, energy_slab, walk_loads, GfmdSweep, GfmdSweepRow, LoadMap, Walker};
use crate::gfmd::{GfmdOptions, GfmdSetup, Progress, Solution};
use crate::input::scene::Scene;
use crate::theory::sweep::SweepSpec;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// [`GfmdSweepRow::measured`] from this rank's rows of a contact relaxed at p* = `p` (every
/// rank gets the row).
pub fn row_slab(
    comm: &dyn Comm,
    p: f64,
    prep: &PreparedSlab,
    problem: &SlabProblem<'_>,
    sol: &Solution,
    opts: &GfmdOptions,
) -> GfmdSweepRow {
    let nodes = prep.slab.nodes();
    let m = measure_slab(
        comm,
        sol,
        opts,
        nodes,
        problem.modulus,
        prep.rms_gradient,
        prep.rms_height,
    );
    let load = (problem.pressure, problem.gamma, problem.range);
    GfmdSweepRow::of(p, &m, energy_slab(comm, &problem.slab.heights, nodes, load, sol), sol)
}

impl LoadMap for PreparedSlab {
    fn relax_at(
        &self,
        comm: &dyn Comm,
        p: f64,
        start: Option<&[f64]>,
        opts: &GfmdOptions,
        progress: &mut dyn FnMut(Progress),
        cancel: &AtomicBool,
    ) -> Result<(Option<GfmdSweepRow>, Relaxation)> {
        let problem = self.problem(p);
        let out = relax_slab_from(comm, &problem, opts, start, progress, cancel)?;
        let row = match &out {
            Relaxation::Equilibrium(sol) => Some(row_slab(comm, p, self, &problem, sol, opts)),
            Relaxation::ContactLost { .. } => None,
        };
        Ok((row, out))
    }

    fn scene_and_gradient(&self) -> (&Scene, f64) {
        (&self.scene, self.rms_gradient)
    }
}

/// [`crate::gfmd::sweep::run_loads`] on this rank: the prepared slab, the rows, the steps.
///
/// # Errors
/// As [`crate::gfmd::sweep::run_loads`].
pub fn run_loads_slab(
    comm: &dyn Comm,
    setup: &GfmdSetup,
    spec: &SweepSpec,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<(PreparedSlab, Vec<GfmdSweepRow>, usize)> {
    spec.validate()?;
    opts.validate()?;
    let mut walker = Walker::new(comm, prepare_slab(comm, setup)?, opts);
    let rows = walk_loads(&mut walker, &spec.pressures(), progress, cancel)?;
    Ok((walker.prep, rows, walker.iterations))
}

/// [`crate::gfmd::sweep::run_sweep`] on this rank of `comm` (every rank calls it); the
/// theory's sweep runs on rank 0 only (None elsewhere).
///
/// # Errors
/// As [`crate::gfmd::sweep::run_sweep`].
pub fn run_sweep_slab(
    comm: &dyn Comm,
    setup: &GfmdSetup,
    spec: &SweepSpec,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<GfmdSweep> {
    let t0 = Instant::now();
    let (prep, rows, iterations) = run_loads_slab(comm, setup, spec, opts, progress, cancel)?;
    let map = (
        prep.slab.nx,
        setup.surface.is_none().then_some(setup.seed),
        prep.reduction.clone(),
    );
    let theory = (comm.rank() == 0).then(|| Ok(prep.theory_scene(spec.from)));
    beside_theory(rows, theory, spec, map, (iterations, t0), progress, cancel)
}
