//! GFMD load sweeps: one map, loads p*₁ < p*₂ < … (log-spaced, [`SweepSpec`]), each load
//! warm-started from the relaxed gap of the previous one (quasi-static loading), with the same
//! columns as the theory's [`crate::theory::sweep`] and the theory's sweep on the same map's
//! discrete spectrum (including its mean gap [S-12]) beside it.
//!
//! Without adhesion the minimum at each load is unique, so a sweep gives the single runs'
//! answers to the solver tolerance (tested). On a half-space Polonsky–Keer relaxes each load
//! from the uniform pressure ([`super::solve_from`]: a warm pressure start could stall for
//! tens of thousands of iterations on a contact that no longer changed), so every load costs
//! what a single run costs, 20–160 iterations, and is the single run's answer bit for bit
//! (tested); FIRE (slabs, `Method::Fire`) starts from the previous gap. With adhesion the warm start
//! follows the loading branch from the previous load, which may differ from a cold start
//! (first touch at the final load): contact hysteresis, not an error.
//!
//! Per load: a_r, σ̄_c*, ⟨δσ_c²⟩*, ū, ū/h_rms ([`super::measure()`]) and the energy per nominal
//! area U = ½Σ_q φ(q)|w̃(q)|² + ⟨v(g)⟩ (J/m²), the elastic energy plus the interaction energy,
//! as the theory's U = Σ u_ela − a_rγ_s [S-11] counts it. The elastic part is
//! ½⟨(w − w̄)(σ − p₀)⟩ over the nodes (Parseval; σ − p₀ = φ⋆w).

use super::{measure, prepare, solve_from, GfmdOptions, GfmdSetup, Prepared, Problem, Progress, Solution, Stage};
use crate::error::{Error, Result};
use crate::surface::heightmap::Surface;
use crate::theory::engine::Options;
use crate::theory::sweep::{self, Sweep, SweepSpec};
use serde::Serialize;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// One load of a GFMD sweep (the first seven keys are the theory sweep's columns).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GfmdSweepRow {
    /// p*.
    pub p: f64,
    /// a_r.
    pub a_r: f64,
    /// ū/h_rms.
    pub mean_gap_rel: f64,
    /// ū (m).
    pub mean_gap: f64,
    /// σ̄_c*.
    pub mean_contact_stress: f64,
    /// U (J/m²): elastic plus interaction energy per nominal area.
    pub elastic_energy: f64,
    /// Whether the solver met its tolerance (always true in a returned sweep).
    pub converged: bool,
    /// ⟨δσ_c²⟩*.
    pub contact_stress_variance: f64,
    /// Solver steps at this load (warm-started).
    pub iterations: usize,
    /// Final relative force residual.
    pub residual: f64,
}

/// A GFMD sweep and the theory's on the same map.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GfmdSweep {
    /// One row per load, increasing p*.
    pub rows: Vec<GfmdSweepRow>,
    /// Grid side N.
    pub grid: usize,
    /// Seed (null for a loaded map).
    pub seed: Option<u64>,
    /// The reduced system's invariants (null for a loaded map).
    pub reduction: Option<super::reduction::Reduction>,
    /// The theory's sweep on the map's discrete spectrum (null if it failed).
    pub theory: Option<Sweep>,
    /// Why `theory` is null.
    pub theory_error: Option<String>,
    /// Total solver steps.
    pub iterations: usize,
    /// Wall time (s).
    pub elapsed_s: f64,
    /// The map the sweep ran on (not serialised; null over MPI ranks, where no rank holds it
    /// whole).
    #[serde(skip)]
    pub surface: Option<Surface>,
}

impl GfmdSweepRow {
    /// The row of a contact relaxed at p* = `p` (measured with [`measure()`], the energy with
    /// [`energy`]).
    pub fn measured(p: f64, problem: &Problem<'_>, sol: &Solution, opts: &GfmdOptions) -> GfmdSweepRow {
        let m = measure(problem, sol, opts);
        GfmdSweepRow {
            p,
            a_r: m.stats.a_r,
            mean_gap_rel: m.mean_gap_rel,
            mean_gap: m.mean_gap,
            mean_contact_stress: m.stats.mean_contact_stress,
            elastic_energy: energy(problem, sol),
            converged: true,
            contact_stress_variance: m.stats.contact_stress_variance,
            iterations: sol.iterations,
            residual: sol.residual,
        }
    }
}

/// U = ½⟨(w − w̄)(σ − p₀)⟩ + ⟨v(g)⟩ of a relaxed contact (J/m², see the module docs).
pub fn energy(problem: &Problem<'_>, sol: &Solution) -> f64 {
    let h = &problem.surface.heights;
    let n = h.len() as f64;
    let w: Vec<f64> = sol.gap.iter().zip(h).map(|(g, h)| g + h).collect();
    let wbar = w.iter().sum::<f64>() / n;
    let el = 0.5
        * w.iter()
            .zip(&sol.stress)
            .map(|(w, s)| (w - wbar) * (s - problem.pressure))
            .sum::<f64>()
        / n;
    let inter = if problem.gamma > 0.0 {
        -problem.gamma * sol.gap.iter().map(|g| (-g / problem.range).exp()).sum::<f64>() / n
    } else {
        0.0
    };
    el + inter
}

/// Runs the loads of `spec` on the map of `setup`, warm-starting each from the previous one
/// (see the module docs), then the theory's sweep on the map. `progress` gets the load index
/// with each report, and the number of loads with the one [`Stage::Theory`] report before the
/// theory's sweep.
///
/// # Errors
/// As [`super::run()`] for any load; [`crate::Error::Invalid`] for a spec out of range;
/// [`crate::Error::Cancelled`] when `cancel` is set, in a load or in the theory's sweep.
///
/// # Examples
/// ```
/// use asperity::gfmd::{sweep::run_sweep, GfmdOptions, GfmdSetup, GridSpec};
/// use asperity::input::preset::Preset;
/// use asperity::theory::sweep::SweepSpec;
/// use std::sync::atomic::AtomicBool;
///
/// let scene = Preset::resolve("system-1").unwrap().scene().unwrap().without_adhesion();
/// let setup = GfmdSetup {
///     scene,
///     grid: GridSpec { system_size_ratio: 2.0, bandwidth: 4.0, points_per_short_wavelength: 8.0 },
///     seed: 1,
///     surface: None,
///     rescale: true,
/// };
/// let spec = SweepSpec { from: 0.01, to: 0.1, points: 3 };
/// let sw = run_sweep(&setup, &spec, &GfmdOptions::default(), &mut |_, _| {}, &AtomicBool::new(false)).unwrap();
/// // more load, more contact on the same map
/// assert!(sw.rows.windows(2).all(|w| w[1].a_r > w[0].a_r));
/// ```
pub fn run_sweep(
    setup: &GfmdSetup,
    spec: &SweepSpec,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<GfmdSweep> {
    let t0 = Instant::now();
    let (prep, rows, iterations) = run_loads(setup, spec, opts, progress, cancel)?;
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
    let (theory, theory_error) = match prep
        .theory_scene(spec.from)
        .and_then(|sc| sweep::sweep(&sc, spec, &Options::default(), Some(cancel)))
    {
        Err(Error::Cancelled) => return Err(Error::Cancelled),
        Ok(s) => (Some(s), None),
        Err(e) => (None, Some(e.to_string())),
    };
    Ok(GfmdSweep {
        rows,
        grid: prep.surface.nx,
        seed: setup.surface.is_none().then_some(setup.seed),
        reduction: prep.reduction.clone(),
        theory,
        theory_error,
        iterations,
        elapsed_s: t0.elapsed().as_secs_f64(),
        surface: Some(prep.surface),
    })
}

/// The GFMD part of [`run_sweep`] without the theory: the prepared map, one row per load and
/// the total solver steps.
pub fn run_loads(
    setup: &GfmdSetup,
    spec: &SweepSpec,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<(Prepared, Vec<GfmdSweepRow>, usize)> {
    spec.validate()?;
    opts.validate()?;
    let prep = prepare(setup)?;
    let mut rows = Vec::new();
    let mut start: Option<Vec<f64>> = None;
    let mut iterations = 0;
    for (k, &p) in spec.pressures().iter().enumerate() {
        let problem = prep.problem(p);
        let sol = solve_from(&problem, opts, start.as_deref(), &mut |pr| progress(k, pr), cancel)?;
        iterations += sol.iterations;
        rows.push(GfmdSweepRow::measured(p, &problem, &sol, opts));
        start = Some(sol.gap);
    }
    Ok((prep, rows, iterations))
}
