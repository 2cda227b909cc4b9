//! GFMD over ranks: the map by slabs ([`prepare_slab`]), then the serial code on this rank's
//! rows: the run of [`crate::gfmd::run()`], the load walk of [`crate::gfmd::sweep`] and
//! [`crate::gfmd::cycle`], FIRE of [`crate::gfmd::fire::relax_from`] with the slab FFT, the
//! measurements and the map's moments by ordered reductions, the theory on rank 0
//! ([`run_on_ranks`]).

use super::comm::{share, Comm};
use super::fire::SlabProblem;
use super::map::{self, Slab};
use super::slab_fft::SlabFft;
use crate::error::Result;
use crate::gfmd::cycle::{cycle_on, CycleSpec, GfmdCycle};
use crate::gfmd::reduction::{check_map_moments, reduce, Reduction};
use crate::gfmd::result::{check_ranks, given_map, problem_on, run_on, scene_on_spectrum};
use crate::gfmd::sweep::{beside_theory, walk_on, GfmdSweep, LoadMap};
use crate::gfmd::{GfmdOptions, GfmdResult, GfmdSetup, Progress};
use crate::input::scene::Scene;
use crate::surface::spectrum::{Discrete, Spectrum};
use crate::theory::sweep::SweepSpec;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// A map ready to solve on this rank: [`crate::gfmd::Prepared`] with the rank's rows only.
#[derive(Debug, Clone)]
pub struct PreparedSlab {
    /// The scene GFMD runs (reduced for a generated map).
    pub scene: Scene,
    /// This rank's rows of the map.
    pub slab: Slab,
    /// q_r of the map.
    pub q_r: f64,
    /// ḡ of the whole map.
    pub rms_gradient: f64,
    /// h_rms of the whole map (m).
    pub rms_height: f64,
    /// The map's discrete spectrum (every rank).
    pub spectrum: Discrete,
    /// The full and reduced invariants (None for a loaded map).
    pub reduction: Option<Reduction>,
}

impl LoadMap for PreparedSlab {
    type Map = Slab;

    fn problem(&self, p: f64) -> SlabProblem<'_> {
        problem_on(&self.slab, &self.scene, (self.q_r, self.rms_gradient), p)
    }

    fn scene_and_moments(&self) -> (&Scene, f64, f64) {
        (&self.scene, self.rms_gradient, self.rms_height)
    }

    fn theory_scene(&self, p: f64) -> Result<Scene> {
        Ok(scene_on_spectrum(&self.scene, &self.spectrum, p))
    }

    fn grid_and_reduction(&self) -> (usize, Option<Reduction>) {
        (self.slab.nx, self.reduction.clone())
    }
}

/// [`crate::gfmd::prepare`] on this rank: a generated map by slabs; a given map (which every
/// rank was handed whole, e.g. read from a file) cut to the rank's rows.
///
/// # Errors
/// As [`crate::gfmd::prepare`]; [`crate::Error::Invalid`] naming the grid when it has fewer rows
/// than ranks.
pub fn prepare_slab(comm: &dyn Comm, setup: &GfmdSetup) -> Result<PreparedSlab> {
    let scene = &setup.scene;
    let size = comm.size();
    match &setup.surface {
        Some(s) => {
            let q_r = given_map(s, setup, size)?;
            let (y0, y1) = share(s.ny, size, comm.rank());
            Ok(PreparedSlab {
                scene: scene.clone(),
                slab: Slab::of_map(s, y0, y1),
                q_r,
                rms_gradient: s.rms_gradient(),
                rms_height: s.rms_height(),
                spectrum: s.discrete_spectrum(q_r)?,
                reduction: None,
            })
        }
        None => {
            let (red, mut reduction) = reduce(scene, &setup.grid, setup.rescale)?;
            let spec = match &red.spectrum {
                Spectrum::SelfAffine(sa) => *sa,
                _ => unreachable!("reduce gives a self-affine spectrum"),
            };
            check_ranks(setup.grid.n(), size)?;
            let slab = map::generate(comm, &spec, setup.grid.n(), setup.seed)?;
            let spectrum = map::discrete_spectrum(comm, &slab, spec.q_r())?;
            let mut fft = SlabFft::new(slab.nx, slab.ny, comm.rank(), size);
            let rms_gradient = map::rms_gradient(comm, &mut fft, &slab);
            let rms_height = map::rms_height(comm, &slab);
            check_map_moments(&mut reduction, &red, rms_height, rms_gradient, spectrum.clone());
            Ok(PreparedSlab {
                scene: red,
                slab,
                q_r: spec.q_r(),
                rms_gradient,
                rms_height,
                spectrum,
                reduction: Some(reduction),
            })
        }
    }
}

/// What a run over ranks does: one run ([`crate::gfmd::run()`]), a load sweep
/// ([`crate::gfmd::sweep::run_sweep`]) or a load path ([`crate::gfmd::cycle::run_cycle`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Job {
    /// One run at the scene's load.
    Run,
    /// A load sweep, warm-started from load to load.
    Sweep(SweepSpec),
    /// A load path: loading, unloading, tension to pull-off.
    Cycle(CycleSpec),
}

/// What a [`Job`] returns: the serial run's result, as rank 0 has it.
#[derive(Debug, Clone)]
pub enum Outcome {
    /// Of [`Job::Run`].
    Run(Box<GfmdResult>),
    /// Of [`Job::Sweep`].
    Sweep(Box<GfmdSweep>),
    /// Of [`Job::Cycle`].
    Cycle(Box<GfmdCycle>),
}

/// `job` on the map of `setup` on this rank of `comm`: every rank calls it with the same
/// arguments. Rank 0 returns the serial result (the map field `surface` is None: no rank holds
/// the map); the other ranks return it without the theory (None, which only rank 0
/// evaluates). `progress` gets the row index (0 for one run) with each report.
///
/// # Errors
/// As the serial run, sweep or cycle; every rank returns the same error.
pub fn run_on_ranks(
    comm: &dyn Comm,
    setup: &GfmdSetup,
    job: Job,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<Outcome> {
    match job {
        Job::Run => {}
        Job::Sweep(spec) => spec.validate()?,
        Job::Cycle(spec) => spec.validate()?,
    }
    opts.validate()?;
    let t0 = Instant::now();
    let prep = prepare_slab(comm, setup)?;
    Ok(match job {
        Job::Run => {
            let r = run_on(comm, &prep, setup, opts, &mut |p| progress(0, p), cancel, t0)?;
            Outcome::Run(Box::new(r))
        }
        Job::Sweep(spec) => {
            let (prep, rows, its) = walk_on(comm, prep, &spec.pressures(), opts, progress, cancel)?;
            let sw = beside_theory(comm, (&prep, setup), (rows, its, t0), &spec, progress, cancel)?;
            Outcome::Sweep(Box::new(sw))
        }
        Job::Cycle(spec) => {
            let (_, c) = cycle_on(comm, (prep, setup), &spec, opts, progress, cancel, t0)?;
            Outcome::Cycle(Box::new(c))
        }
    })
}
