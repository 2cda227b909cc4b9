//! FIRE on slabs: the relaxation of [`crate::gfmd::relax`] (the same code as the serial
//! run's) on this rank's rows, with the elastic force through the slab FFT
//! ([`super::slab_fft`]) and the force sums folded in the serial order
//! ([`super::comm::chain_fold`]), so that the sums, every position and the step count equal
//! the serial run's bit for bit for any number of ranks. What is the slabs' own here is the
//! set-up: the kernel on the rank's columns, the start on its rows.
//!
//! Polonsky–Keer ([`crate::gfmd::pk`]) is not distributed: a hard-wall run relaxes with FIRE
//! alone (the serial `Method::Fire`).

use super::comm::{all_max, all_min, Comm};
use super::map::Slab;
use super::slab_fft::SlabFft;
use crate::error::{Error, Result};
use crate::gfmd::relax::{adhesion_units, fire, start_positions, stiffness_at, Convolver, Relaxation, Start};
use crate::gfmd::{GfmdOptions, Progress, Solution};
use std::sync::atomic::AtomicBool;

/// One contact problem on a slab (physical units, as [`crate::gfmd::Problem`]).
#[derive(Debug, Clone, Copy)]
pub struct SlabProblem<'a> {
    /// This rank's rows of the substrate.
    pub slab: &'a Slab,
    /// Contact modulus E* (Pa).
    pub modulus: f64,
    /// Slab thickness t (m); `f64::INFINITY` = semi-infinite.
    pub thickness: f64,
    /// Nominal pressure p₀ (Pa).
    pub pressure: f64,
    /// Surface energy γ (J/m²).
    pub gamma: f64,
    /// Range ρ (m).
    pub range: f64,
}

/// [`crate::gfmd::solve_from`] with FIRE on this rank's slab: `start_gap` (m) is this rank's
/// rows of the start; the returned [`Solution`] holds this rank's rows. Every rank must call
/// it with the same problem and options.
///
/// # Errors
/// As [`crate::gfmd::solve_from`]; [`Error::Unsupported`] for `Method::PolonskyKeer` on a hard
/// wall (not distributed).
pub fn solve_slab(
    comm: &dyn Comm,
    problem: &SlabProblem<'_>,
    opts: &GfmdOptions,
    start_gap: Option<&[f64]>,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<Solution> {
    relax_slab_from(comm, problem, opts, start_gap, progress, cancel)?.equilibrium()
}

/// [`solve_slab`], telling a loss of contact under tension apart from an equilibrium, as
/// [`crate::gfmd::fire::relax_from`] does (the load cycle over ranks steps into tension with
/// it).
///
/// # Errors
/// As [`solve_slab`].
pub fn relax_slab_from(
    comm: &dyn Comm,
    problem: &SlabProblem<'_>,
    opts: &GfmdOptions,
    start_gap: Option<&[f64]>,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<Relaxation> {
    crate::work::start();
    crate::gfmd::problem::check_loads(
        problem.modulus,
        problem.thickness,
        problem.pressure,
        problem.gamma,
        problem.range,
    )?;
    let (lo, hi) = problem
        .slab
        .heights
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| (a.min(h), b.max(h)));
    if all_min(comm, lo) == all_max(comm, hi) {
        return Err(Error::invalid_text(
            crate::error::Field::HeightMap,
            "a flat map",
            "a height map with some roughness",
        ));
    }
    opts.validate()?;
    if problem.gamma == 0.0 && opts.method == crate::gfmd::Method::PolonskyKeer {
        return Err(Error::Unsupported(
            "Polonsky-Keer is not distributed over ranks: use FIRE (or Auto, which is FIRE on ranks)".into(),
        ));
    }
    let s = problem.slab;
    let (nx, ny, da) = (s.nx, s.ny, s.spacing);
    let n = nx * ny;
    let e = problem.modulus;
    let fft = SlabFft::new(nx, ny, comm.rank(), comm.size());
    let (c0, c1) = fft.my_cols();
    let mut kernel = vec![0.0; (c1 - c0) * ny];
    let mut phi_max: f64 = 0.0;
    for kx in c0..c1 {
        for ky in 0..ny {
            let p = stiffness_at(kx, ky, (nx, ny, da), problem.thickness);
            kernel[(kx - c0) * ny + ky] = p * (1.0 / n as f64);
            phi_max = phi_max.max(p);
        }
    }
    let phi_max = all_max(comm, phi_max);
    let h: Vec<f64> = s.heights.iter().map(|x| x / da).collect();
    let (adh_stress, inv_range) = adhesion_units(problem.gamma, problem.range, e, da);
    let w0 = start_positions(comm, &h, start_gap, da)?;
    let start = Start {
        nodes: n,
        offset: s.offset(),
        h,
        w: w0,
        loads: (problem.pressure / e, adh_stress, inv_range),
        omega_sq: phi_max + adh_stress * inv_range,
        steps: 0,
        units: (da, e),
    };
    fire(comm, Convolver::Slab(fft, kernel), start, opts, progress, cancel)
}
