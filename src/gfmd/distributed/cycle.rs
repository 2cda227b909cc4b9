//! [`crate::gfmd::cycle::run_cycle`] over ranks: loading, unloading and tension to pull-off on
//! one map, every rank holding its slab of the relaxed gap between loads.
//!
//! The path (loads, turning point, tensile steps p* = 0, −p*₁, −2p*₁, …, the bisections of
//! the pull-off bracket, the jump-in) is the serial code ([`crate::gfmd::cycle`]'s `walk`)
//! driven by the walker of [`crate::gfmd::sweep`] on this rank's slab: each load relaxes with FIRE on slabs
//! ([`super::fire::relax_slab_from`], warm-started from the rank's rows of the last state
//! held) and is measured by ordered reductions ([`super::sweep::row_slab`]). Every rank sees
//! the same rows bit for bit, so every rank takes the same branch at every test of the path
//! (contact lost, bracket wide enough), and rank 0's cycle equals the serial
//! `Method::Fire` cycle bit for bit (with adhesion FIRE is the serial method whatever the
//! choice). The theory's sweep on the map runs on rank 0 only.

use super::comm::Comm;
use super::run::prepare_slab;
use crate::error::Result;
use crate::gfmd::cycle::{theory_sweep, walk, CycleSpec, GfmdCycle};
use crate::gfmd::sweep::Walker;
use crate::gfmd::{GfmdOptions, GfmdSetup, Progress};
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// [`crate::gfmd::cycle::run_cycle`] on this rank of `comm` (every rank calls it with the same
/// arguments): rank 0 returns the serial cycle; the other ranks return it without the theory
/// (`theory` None, which only rank 0 evaluates).
///
/// # Errors
/// As [`crate::gfmd::cycle::run_cycle`]; every rank returns the same error.
pub fn run_cycle_slab(
    comm: &dyn Comm,
    setup: &GfmdSetup,
    spec: &CycleSpec,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<GfmdCycle> {
    spec.validate()?;
    opts.validate()?;
    let t0 = Instant::now();
    let mut walker = Walker::new(comm, prepare_slab(comm, setup)?, opts);
    let path = walk(&mut walker, spec, progress, cancel)?;
    let rising = spec.rising();
    let theory = if comm.rank() == 0 {
        theory_sweep(Ok(walker.prep.theory_scene(rising.from)), &rising, cancel)?
    } else {
        (None, None, None)
    };
    let map = (
        walker.prep.slab.nx,
        setup.surface.is_none().then_some(setup.seed),
        walker.prep.reduction.clone(),
    );
    Ok(path.into_cycle(theory, map, walker.iterations, t0))
}
