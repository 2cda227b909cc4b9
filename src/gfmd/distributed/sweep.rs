//! [`crate::gfmd::sweep::run_sweep`] over ranks: the same loads, warm starts, rows and
//! theory sweep, bit for bit; the energy U = ½⟨(w − w̄)(σ − p₀)⟩ + ⟨v(g)⟩ by ordered sums.

use super::comm::{chain_sum, Comm};
use super::fire::{solve_slab, SlabProblem};
use super::measure::measure_slab;
use super::run::{prepare_slab, PreparedSlab};
use crate::error::{Error, Result};
use crate::gfmd::sweep::{GfmdSweep, GfmdSweepRow};
use crate::gfmd::{GfmdOptions, GfmdSetup, Progress, Solution, Stage};
use crate::theory::engine::Options;
use crate::theory::sweep::{self, SweepSpec};
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// [`crate::gfmd::sweep::energy`] from this rank's rows (J/m²; every rank gets it).
pub fn energy_slab(comm: &dyn Comm, problem: &SlabProblem<'_>, sol: &Solution) -> f64 {
    let h = &problem.slab.heights;
    let n = problem.slab.nodes() as f64;
    let w: Vec<f64> = sol.gap.iter().zip(h).map(|(g, h)| g + h).collect();
    let wbar = chain_sum(comm, w.iter().copied()) / n;
    let el =
        0.5 * chain_sum(
            comm,
            w.iter()
                .zip(&sol.stress)
                .map(|(w, s)| (w - wbar) * (s - problem.pressure)),
        ) / n;
    let inter = if problem.gamma > 0.0 {
        -problem.gamma * chain_sum(comm, sol.gap.iter().map(|g| (-g / problem.range).exp())) / n
    } else {
        0.0
    };
    el + inter
}

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
    let m = measure_slab(
        comm,
        sol,
        opts,
        prep.slab.nodes(),
        problem.modulus,
        prep.rms_gradient,
        prep.rms_height,
    );
    GfmdSweepRow {
        p,
        a_r: m.stats.a_r,
        mean_gap_rel: m.mean_gap_rel,
        mean_gap: m.mean_gap,
        mean_contact_stress: m.stats.mean_contact_stress,
        elastic_energy: energy_slab(comm, problem, sol),
        converged: true,
        contact_stress_variance: m.stats.contact_stress_variance,
        iterations: sol.iterations,
        residual: sol.residual,
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
    let prep = prepare_slab(comm, setup)?;
    let mut rows = Vec::new();
    let mut start: Option<Vec<f64>> = None;
    let mut iterations = 0;
    for (k, &p) in spec.pressures().iter().enumerate() {
        let problem = prep.problem(p);
        let sol = solve_slab(
            comm,
            &problem,
            opts,
            start.as_deref(),
            &mut |pr| progress(k, pr),
            cancel,
        )?;
        iterations += sol.iterations;
        rows.push(row_slab(comm, p, &prep, &problem, &sol, opts));
        start = Some(sol.gap);
    }
    Ok((prep, rows, iterations))
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
    if let Some(last) = rows.last() {
        progress(
            rows.len(),
            Progress {
                stage: Stage::Theory,
                iteration: last.iterations,
                residual: last.residual,
                contact_fraction: last.a_r,
            },
        );
    }
    let (theory, theory_error) = if comm.rank() == 0 {
        match sweep::sweep(&prep.theory_scene(spec.from), spec, &Options::default(), Some(cancel)) {
            Err(Error::Cancelled) => return Err(Error::Cancelled),
            Ok(s) => (Some(s), None),
            Err(e) => (None, Some(e.to_string())),
        }
    } else {
        (None, None)
    };
    Ok(GfmdSweep {
        rows,
        grid: prep.slab.nx,
        seed: setup.surface.is_none().then_some(setup.seed),
        reduction: prep.reduction.clone(),
        theory,
        theory_error,
        iterations,
        elapsed_s: t0.elapsed().as_secs_f64(),
        surface: None,
    })
}
