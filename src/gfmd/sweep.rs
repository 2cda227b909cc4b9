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

use super::distributed::comm::{chain_sum, Comm, Solo};
use super::fire::{relax_from, Relaxation};
use super::measure::measure_slab;
use super::problem::MapRows;
use super::{prepare, GfmdOptions, GfmdSetup, Measurements, Prepared, Problem, Progress, Solution, Stage};
use crate::error::{Error, Result};
use crate::input::scene::Scene;
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
    /// The row of a contact relaxed at p* = `p` on `problem`'s map: this rank's rows of it,
    /// `comm` joining them ([`Solo`] for the whole map), the whole map's ḡ and h_rms (m) in
    /// `moments`. Measured with [`super::measure::measure_slab`], the energy with
    /// [`energy_slab`]; every rank gets the row.
    pub fn measured<M: MapRows>(
        comm: &dyn Comm,
        p: f64,
        problem: &Problem<'_, M>,
        (rms_gradient, rms_height): (f64, f64),
        sol: &Solution,
        opts: &GfmdOptions,
    ) -> GfmdSweepRow {
        let ((nx, ny, _), heights, _) = problem.surface.layout().rows();
        let nodes = nx * ny;
        let m = measure_slab(comm, sol, opts, nodes, problem.modulus, rms_gradient, rms_height);
        let load = (problem.pressure, problem.gamma, problem.range);
        GfmdSweepRow::of(p, &m, energy_slab(comm, heights, nodes, load, sol), sol)
    }

    /// The row at p* = `p` from the measurements `m` and the energy `u` of the relaxation `sol`.
    pub fn of(p: f64, m: &Measurements, u: f64, sol: &Solution) -> GfmdSweepRow {
        GfmdSweepRow {
            p,
            a_r: m.stats.a_r,
            mean_gap_rel: m.mean_gap_rel,
            mean_gap: m.mean_gap,
            mean_contact_stress: m.stats.mean_contact_stress,
            elastic_energy: u,
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
    energy_slab(&Solo, h, h.len(), (problem.pressure, problem.gamma, problem.range), sol)
}

/// [`energy`] from this rank's rows: `heights` and `sol` hold the rank's nodes, `nodes` is the
/// whole map's count, `load` is (p₀ in Pa, γ in J/m², ρ in m). The sums run in node order
/// across the ranks ([`chain_sum`]), so the energy does not depend on the number of ranks, bit
/// for bit; every rank gets it.
pub fn energy_slab(comm: &dyn Comm, heights: &[f64], nodes: usize, load: (f64, f64, f64), sol: &Solution) -> f64 {
    let (pressure, gamma, range) = load;
    let n = nodes as f64;
    let w: Vec<f64> = sol.gap.iter().zip(heights).map(|(g, h)| g + h).collect();
    let wbar = chain_sum(comm, w.iter().copied()) / n;
    let el =
        0.5 * chain_sum(
            comm,
            w.iter().zip(&sol.stress).map(|(w, s)| (w - wbar) * (s - pressure)),
        ) / n;
    let inter = if gamma > 0.0 {
        -gamma * chain_sum(comm, sol.gap.iter().map(|g| (-g / range).exp())) / n
    } else {
        0.0
    };
    el + inter
}

/// A map a [`Walker`] relaxes on: the whole map ([`Prepared`]) or one rank's slab of it
/// (`distributed::run::PreparedSlab`).
pub(crate) trait LoadMap {
    /// How this rank holds the map.
    type Map: MapRows;
    /// The problem at p* = `p` (p₀ by the map's ḡ).
    fn problem(&self, p: f64) -> Problem<'_, Self::Map>;
    /// The scene GFMD runs, and the whole map's ḡ and h_rms (m).
    fn scene_and_moments(&self) -> (&Scene, f64, f64);
    /// The scene on the map's discrete spectrum at p* = `p` (for the theory).
    fn theory_scene(&self, p: f64) -> Result<Scene>;
    /// The side of the grid, and the full and reduced invariants (None for a loaded map).
    fn grid_and_reduction(&self) -> (usize, Option<super::reduction::Reduction>);

    /// Relaxes at p* = `p` from `start` (this rank's gap, m; `None`: first touch) and measures
    /// an equilibrium: its row (every rank gets it) and the relaxation.
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
        let out = relax_from(comm, &problem, opts, start, progress, cancel)?;
        let (_, g, h_rms) = self.scene_and_moments();
        let row = match &out {
            Relaxation::Equilibrium(sol) => Some(GfmdSweepRow::measured(comm, p, &problem, (g, h_rms), sol, opts)),
            Relaxation::ContactLost { .. } => None,
        };
        Ok((row, out))
    }
}

impl LoadMap for Prepared {
    type Map = Surface;

    fn problem(&self, p: f64) -> Problem<'_> {
        Prepared::problem(self, p)
    }

    fn scene_and_moments(&self) -> (&Scene, f64, f64) {
        (&self.scene, self.rms_gradient, self.surface.rms_height())
    }

    fn theory_scene(&self, p: f64) -> Result<Scene> {
        Prepared::theory_scene(self, p)
    }

    fn grid_and_reduction(&self) -> (usize, Option<super::reduction::Reduction>) {
        (self.surface.nx, self.reduction.clone())
    }
}

/// The walker along a path on a map (the whole map on one rank, or this rank's slab): the map,
/// this rank's part of the last relaxed gap and the step count. It relaxes one load at a time,
/// warm-started from the last state held, on either [`LoadMap`]: a load sweep
/// ([`walk_loads`]) and the load cycle's path (`cycle::walk`) are the same code for both, so
/// the loads visited (bisections included) depend only on the rows, which are equal bit for
/// bit.
pub(crate) struct Walker<'a, M> {
    comm: &'a dyn Comm,
    pub(crate) prep: M,
    opts: &'a GfmdOptions,
    gap: Option<Vec<f64>>,
    pub(crate) iterations: usize,
}

impl<'a, M: LoadMap> Walker<'a, M> {
    /// A walker on `prep` (this rank's part of the map, on `comm`) that has relaxed nothing
    /// yet.
    pub(crate) fn new(comm: &'a dyn Comm, prep: M, opts: &'a GfmdOptions) -> Self {
        Walker {
            comm,
            prep,
            opts,
            gap: None,
            iterations: 0,
        }
    }
}

impl<M: LoadMap> Walker<'_, M> {
    /// Relaxes at p* = `p` (row index `k` for progress) from the last state held; `None` when
    /// contact is lost (the state is kept).
    pub(crate) fn step(
        &mut self,
        p: f64,
        k: usize,
        progress: &mut dyn FnMut(usize, Progress),
        cancel: &AtomicBool,
    ) -> Result<Option<GfmdSweepRow>> {
        let (row, out) = self.prep.relax_at(
            self.comm,
            p,
            self.gap.as_deref(),
            self.opts,
            &mut |pr| progress(k, pr),
            cancel,
        )?;
        let Some(sol) = held(out, &mut self.iterations) else {
            return Ok(None);
        };
        self.gap = Some(sol.gap);
        Ok(row)
    }

    /// The interaction's theoretical strength γ/ρ in p* (by the map's ḡ); `None` without
    /// adhesion.
    pub(crate) fn strength(&self) -> Option<f64> {
        let (sc, g, _) = self.prep.scene_and_moments();
        (sc.gamma > 0.0).then(|| sc.gamma / sc.range / (sc.modulus * g))
    }
}

/// The equilibrium of a relaxation, its steps added to `iterations` (`None` when contact was
/// lost).
pub(crate) fn held(out: Relaxation, iterations: &mut usize) -> Option<Solution> {
    match out {
        Relaxation::Equilibrium(sol) => {
            *iterations += sol.iterations;
            Some(sol)
        }
        Relaxation::ContactLost { iterations: it } => {
            *iterations += it;
            None
        }
    }
}

/// The rows of a load sweep over `pressures` (all compressive), each load warm-started from
/// the one before.
///
/// # Errors
/// As the solver's; [`Error::NotConverged`] if contact were lost (no equilibrium).
pub(crate) fn walk_loads<M: LoadMap>(
    solver: &mut Walker<'_, M>,
    pressures: &[f64],
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<Vec<GfmdSweepRow>> {
    let mut rows = Vec::with_capacity(pressures.len());
    for (k, &p) in pressures.iter().enumerate() {
        let row = solver
            .step(p, k, progress, cancel)?
            .ok_or_else(|| Error::NotConverged {
                solver: crate::error::Solver::Gfmd,
                reason: format!("contact lost at p* = {p:e}: a sweep's loads hold no tension"),
            })?;
        rows.push(row);
    }
    Ok(rows)
}

/// The sweep of `rows` on `prep` (this rank's part of the map of `setup`) with the theory's
/// sweep on the map beside it, which rank 0 evaluates (None elsewhere); `iterations` and `t0`
/// are the steps taken and the start of the run. `progress` gets the one [`Stage::Theory`]
/// report.
///
/// # Errors
/// [`Error::Cancelled`] only (any other failure of the theory is reported beside the rows).
pub(crate) fn beside_theory<M: LoadMap>(
    comm: &dyn Comm,
    (prep, setup): (&M, &GfmdSetup),
    (rows, iterations, t0): (Vec<GfmdSweepRow>, usize, Instant),
    spec: &SweepSpec,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<GfmdSweep> {
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
    let theory = (comm.rank() == 0).then(|| prep.theory_scene(spec.from));
    let (theory, theory_error) =
        match theory.map(|sc| sc.and_then(|sc| sweep::sweep(&sc, spec, &Options::default(), Some(cancel)))) {
            None => (None, None),
            Some(Err(Error::Cancelled)) => return Err(Error::Cancelled),
            Some(Ok(s)) => (Some(s), None),
            Some(Err(e)) => (None, Some(e.to_string())),
        };
    let (grid, reduction) = prep.grid_and_reduction();
    Ok(GfmdSweep {
        rows,
        grid,
        seed: setup.surface.is_none().then_some(setup.seed),
        reduction,
        theory,
        theory_error,
        iterations,
        elapsed_s: t0.elapsed().as_secs_f64(),
        surface: None,
    })
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
    let sw = beside_theory(&Solo, (&prep, setup), (rows, iterations, t0), spec, progress, cancel)?;
    Ok(GfmdSweep {
        surface: Some(prep.surface),
        ..sw
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
    walk_on(&Solo, prepare(setup)?, &spec.pressures(), opts, progress, cancel)
}

/// The loads `loads` walked on `prep` (this rank's part of the map, on `comm`), each from the
/// last one's gap: the map, one row per load and the total solver steps.
pub(crate) fn walk_on<M: LoadMap>(
    comm: &dyn Comm,
    prep: M,
    loads: &[f64],
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<(M, Vec<GfmdSweepRow>, usize)> {
    let mut walker = Walker::new(comm, prep, opts);
    let rows = walk_loads(&mut walker, loads, progress, cancel)?;
    Ok((walker.prep, rows, walker.iterations))
}
