//! The engine facade: one call evaluates a scene with whatever the scene needs (the
//! adhesionless mirror-Gaussian path when γ_s = 0, the adhesive solver otherwise) and returns
//! the quantities every front end shows. The CLI and the TUI call only this (and the sweep).

use crate::error::{check_in, Error, Field, Range, Result};
use crate::input::scene::Scene;
use crate::theory::adhesion::{self, AdhesionAccuracy, AdhesiveSolution, Branch, BranchState};
use crate::theory::persson::{self, Accuracy, ResolutionPoint};
use rayon::prelude::*;
use serde::Serialize;
use std::time::Instant;

/// Options of one evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Accuracy of the adhesionless variance ODE.
    pub accuracy: Accuracy,
    /// Number of σ* points of the sampled Pr(σ*).
    pub sigma_points: usize,
    /// Largest σ* of the sample (None: p* + 5Δ*).
    pub sigma_max: Option<f64>,
    /// Accuracy of the adhesive solver (used when γ_s > 0).
    pub adhesion: AdhesionAccuracy,
    /// Estimate the adhesive solver's discretisation error with three more solves, warm
    /// started from the first: at 3/2 and at 2× the steps, and at half the points per width
    /// (about 1.5× the solve's own time); without it `error_estimate` is the
    /// self-consistency residual times a_r.
    pub adhesion_error_estimate: bool,
    /// Largest grid step in ln p* of a load sweep's table of U(p*), from which the mean gap
    /// is integrated ([`crate::theory::sweep`]): coarser requested spacings are refined by an
    /// integer factor ([`SWEEP_STEP_LN`]; [`CHART_SWEEP_STEP_LN`] in [`Options::chart`]).
    pub sweep_step_ln: f64,
    /// Relative precision in p* to which a load sweep refines the edges of a hysteresis
    /// window (bisection in ln p*; [`EDGE_REL`], [`CHART_EDGE_REL`] in [`Options::chart`]).
    pub edge_rel: f64,
}

/// The default [`Options::edge_rel`] (also `theory::hysteresis::EDGE_REL`).
pub const EDGE_REL: f64 = 0.005;
/// [`Options::edge_rel`] of [`Options::chart`]: a chart's column spans ~0.1–0.2 in ln p*, so
/// 0.03 puts the marked edge inside its pixel with three bisection solves fewer per edge.
pub const CHART_EDGE_REL: f64 = 0.03;
/// Allowed [`Options::edge_rel`].
pub const EDGE_REL_RANGE: (f64, f64) = (1e-6, 0.5);

/// The default [`Options::sweep_step_ln`]: keeps the estimated gap error below ~1e-3
/// relative where ū > 1e-3 h_rms (each sweep row reports its own estimate), so a 64-point
/// chart over three decades (spacing 0.11) needs no extra loads below its last p*.
pub const SWEEP_STEP_LN: f64 = 0.15;
/// [`Options::sweep_step_ln`] of [`Options::chart`]: a 64-point chart over six decades
/// (spacing 0.22) is not refined, half the loads of [`SWEEP_STEP_LN`]; ū then moves by at
/// most 1.3e-3 relative against the default step (systems I and II, models 1, 3, 4,
/// t·q_r = 0.05…∞, adhesionless and adhesive, p* = 1e-6…1), below a chart's pixel, and each
/// row still reports its estimate. Below a jump into contact the gap carries the jump's
/// placement inside its grid step instead ([`crate::theory::gap::route`]).
pub const CHART_SWEEP_STEP_LN: f64 = 0.25;
/// Allowed [`Options::sweep_step_ln`].
pub const SWEEP_STEP_RANGE: (f64, f64) = (1e-3, 1.0);

impl Default for Options {
    fn default() -> Self {
        Options {
            accuracy: Accuracy::default(),
            sigma_points: 201,
            sigma_max: None,
            adhesion: AdhesionAccuracy::default(),
            adhesion_error_estimate: true,
            sweep_step_ln: SWEEP_STEP_LN,
            edge_rel: EDGE_REL,
        }
    }
}

/// Allowed relative tolerance of the adhesionless ODE: below 1e-12 the step control works
/// against round-off; above 1e-2 a_r is not worth reporting.
pub const RTOL_RANGE: (f64, f64) = (1e-12, 1e-2);
/// Allowed number of points of the tabulated Pr(σ*).
pub const SIGMA_POINTS_RANGE: (usize, usize) = (2, 1_000_000);
/// Allowed σ*_max: Pr(σ*) of any scene is negligible beyond σ* ~ p* + 10 (Δ ≤ 1 for ḡ-reduced
/// stresses), so a larger table would sample only zeros.
pub const SIGMA_MAX_RANGE: (f64, f64) = (1e-6, 1e3);
pub use crate::theory::adhesion::{ADHESION_POINTS_RANGE, ADHESION_STEPS_RANGE, ADHESION_TOL_RANGE};

impl Options {
    /// Checks every accuracy knob against its allowed range.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the first knob out of range ([`Field::Rtol`],
    /// [`Field::SigmaPoints`], [`Field::SigmaMax`], [`Field::AdhesionSteps`],
    /// [`Field::AdhesionPoints`], [`Field::AdhesionTol`], [`Field::SweepStep`],
    /// [`Field::EdgeRel`]).
    pub fn validate(&self) -> Result<()> {
        check_in(Field::Rtol, self.accuracy.rtol, RTOL_RANGE.0, RTOL_RANGE.1)?;
        let n = self.sigma_points;
        if !(SIGMA_POINTS_RANGE.0..=SIGMA_POINTS_RANGE.1).contains(&n) {
            return Err(Error::invalid(
                Field::SigmaPoints,
                n as f64,
                Range::whole(SIGMA_POINTS_RANGE.0 as f64, SIGMA_POINTS_RANGE.1 as f64),
            ));
        }
        if let Some(s) = self.sigma_max {
            check_in(Field::SigmaMax, s, SIGMA_MAX_RANGE.0, SIGMA_MAX_RANGE.1)?;
        }
        self.adhesion.validate()?;
        check_in(
            Field::SweepStep,
            self.sweep_step_ln,
            SWEEP_STEP_RANGE.0,
            SWEEP_STEP_RANGE.1,
        )?;
        check_in(Field::EdgeRel, self.edge_rel, EDGE_REL_RANGE.0, EDGE_REL_RANGE.1)?;
        Ok(())
    }

    /// The accuracy a chart needs (a pixel is ~1 % of an axis): the adhesive solver at half
    /// the default resolution in both directions (relative error of a_r ~1e-3, 3–4× faster),
    /// no error estimate and no search for a second branch. The explorer's sweeps use this.
    pub fn chart() -> Options {
        let mut o = Options::default();
        o.adhesion.steps_per_ln_q *= 0.5;
        o.adhesion.points_per_width *= 0.5;
        o.adhesion.explore_branches = false;
        o.adhesion_error_estimate = false;
        o.sweep_step_ln = CHART_SWEEP_STEP_LN;
        o.edge_rel = CHART_EDGE_REL;
        o
    }
}

pub use crate::contact::{ContactStats, PrCurve};

/// The result of one evaluation.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Evaluation {
    /// a_r(q_s), σ̄_c*, ⟨δσ_c²⟩* and Pr(σ*).
    #[serde(flatten)]
    pub stats: ContactStats,
    /// Width of the final stress distribution Δ* (adhesionless: √v(q_s)).
    pub width: f64,
    /// a_r(q) along the resolution.
    pub resolution: Vec<ResolutionPoint>,
    /// Estimated absolute error of a_r.
    pub error_estimate: f64,
    /// Elastic energy U per nominal area (J/m²) [S-11]; see [`crate::theory::energy`].
    pub elastic_energy: f64,
    /// σ_a*(q_s): the adhesive wall sits at σ* = −σ_a* (0 without adhesion).
    pub sigma_a: f64,
    /// Contact under tension ∫_{−σ_a}^0 Pr dσ* (0 without adhesion).
    pub tensile_area: f64,
    /// Fraction of the nominal area that left the contact through the wall, 1 − a_r.
    pub detached_fraction: f64,
    /// γ(q)/γ_s at the `resolution` points (empty without adhesion).
    pub gamma_q: Vec<f64>,
    /// σ_a*(q) at the `resolution` points (empty without adhesion).
    pub sigma_a_q: Vec<f64>,
    /// Marches of the adhesive solver (0 without adhesion: the closed form needs none).
    pub iterations: usize,
    /// Self-consistency residual |γ(q_s)/γ_s − 1| of the adhesive solution (0 without
    /// adhesion).
    pub residual: f64,
    /// The branch (serialised as "adhesionless" or "loading": the branch a loading history
    /// reaches; see [`Branch`]).
    pub branch: Branch,
    /// a_r of a distinct unloading branch (the highest stable one), if one exists.
    pub unloading_a_r: Option<f64>,
    /// Every branch at this load, lowest a_r first (empty without adhesion).
    pub branches: Vec<BranchState>,
    /// Per entry of `branches`: the net force ∫σ* Pr dσ* its contact carries (reduced; p* plus
    /// the tension carried off through the wall, physics.md §5.1). Empty without adhesion.
    #[serde(skip)]
    pub contact_loads: Vec<f64>,
    /// γ̃_glo = γ_s/u_ela^(f) [S-24].
    pub gamma_glo: f64,
    /// Wall time (s).
    pub elapsed_s: f64,
    /// The adhesive solution (warm start for a neighbouring scene).
    #[serde(skip)]
    pub adhesive: Option<Box<AdhesiveSolution>>,
}

/// Evaluates a scene: the adhesionless closed form [S-3, S-9] without adhesion, the adhesive
/// march [S-5..S-9, S-14] with every branch at its load otherwise, with an error estimate.
///
/// # Errors
/// [`crate::Error::Invalid`] for options out of range ([`Options::validate`]);
/// [`crate::Error::NotConverged`] with the reason when a solver misses its tolerance.
///
/// # Examples
/// ```
/// use asperity::input::preset::Preset;
/// use asperity::theory::engine::{evaluate, Options};
///
/// // model 1 on the adhesionless half-space: a_r = erf(p*/√(2V)) with √V = 1/2 in these
/// // reduced units, so a_r = erf(√2 p*) [S-18]
/// let scene = Preset::resolve("system-1").unwrap().scene().unwrap().without_adhesion();
/// let scene = scene.with_model(asperity::input::model::Model::named(1).unwrap()).unwrap();
/// let ev = evaluate(&scene, &Options::default()).unwrap();
/// let exact = statrs::function::erf::erf(2f64.sqrt() * scene.pressure());
/// assert!((ev.stats.a_r - exact).abs() < 1e-9);
/// ```
pub fn evaluate(scene: &Scene, opts: &Options) -> Result<Evaluation> {
    evaluate_warm(scene, opts, None, None)
}

/// Evaluates a scene, warm-starting the adhesive solver from a neighbouring evaluation and
/// checking `cancel` between the marches of the adhesive root search.
pub fn evaluate_warm(
    scene: &Scene,
    opts: &Options,
    warm: Option<&Evaluation>,
    cancel: Option<&std::sync::atomic::AtomicBool>,
) -> Result<Evaluation> {
    evaluate_continued(scene, opts, warm.as_slice(), cancel)
}

/// The contact statistics of a solution: `[a_r, σ̄_c*, ⟨δσ_c²⟩*]` and Pr(σ*) as (σ*, density).
fn stats_of(
    [a_r, mean_contact_stress, contact_stress_variance]: [f64; 3],
    (sigma, density): (Vec<f64>, Vec<f64>),
) -> ContactStats {
    ContactStats {
        a_r,
        mean_contact_stress,
        contact_stress_variance,
        pr: PrCurve { sigma, density },
    }
}

/// [`evaluate_warm`] continued along a path of evaluations of the same scene at other loads,
/// oldest first: with adhesion the solver extrapolates the branches from the last two, or
/// interpolates between them where this load lies between ([`adhesion::solve_continued`]);
/// with one it is [`evaluate_warm`].
pub fn evaluate_continued(
    scene: &Scene,
    opts: &Options,
    path: &[&Evaluation],
    cancel: Option<&std::sync::atomic::AtomicBool>,
) -> Result<Evaluation> {
    crate::work::start();
    opts.validate()?;
    let t0 = Instant::now();
    if scene.is_adhesive() {
        return evaluate_adhesive(scene, opts, path, cancel, t0);
    }
    // the elastic energy and a_r(q) near q_L need the ODE resolved where v passes p*²: at
    // small p* the default rtol steps across it (one step from q_L to q_r on a thin slab at
    // p* = 1e-7, energy 3x too high). The engine therefore integrates at rtol ≤ ENERGY_RTOL,
    // the accuracy of the energy route, so `run` and `sweep` report the same U and a_r(q).
    let fine = Accuracy {
        rtol: opts.accuracy.rtol.min(persson::ENERGY_RTOL),
        ..opts.accuracy
    };
    let sol = persson::solve(scene, &fine)?;
    let sigma_max = match opts.sigma_max {
        Some(s) => check_in(Field::SigmaMax, s, SIGMA_MAX_RANGE.0, SIGMA_MAX_RANGE.1)?,
        None => sol.default_sigma_max(),
    };
    let pr = sol.sample(sigma_max, opts.sigma_points);
    let elastic_energy = crate::theory::energy::elastic_energy(scene, |q| sol.area_at(q));
    Ok(Evaluation {
        stats: stats_of([sol.a_r, sol.mean_contact_stress, sol.contact_stress_variance], pr),
        width: sol.width,
        resolution: sol.resolution,
        error_estimate: sol.error_estimate,
        elastic_energy,
        sigma_a: 0.0,
        tensile_area: 0.0,
        detached_fraction: 1.0 - sol.a_r,
        gamma_q: Vec::new(),
        sigma_a_q: Vec::new(),
        iterations: 0,
        residual: 0.0,
        branch: Branch::Adhesionless,
        unloading_a_r: None,
        branches: Vec::new(),
        contact_loads: Vec::new(),
        gamma_glo: 0.0,
        elapsed_s: t0.elapsed().as_secs_f64(),
        adhesive: None,
    })
}

fn evaluate_adhesive(
    scene: &Scene,
    opts: &Options,
    path: &[&Evaluation],
    cancel: Option<&std::sync::atomic::AtomicBool>,
    t0: Instant,
) -> Result<Evaluation> {
    // the path's adhesive solutions (a gap in it, e.g. an adhesionless entry, keeps only
    // what follows the gap)
    let mut sols: Vec<&adhesion::AdhesiveSolution> = Vec::with_capacity(path.len());
    for e in path {
        match e.adhesive.as_deref() {
            Some(s) => sols.push(s),
            None => sols.clear(),
        }
    }
    let sol = adhesion::solve_continued(scene, &opts.adhesion, &sols, cancel)?;
    let error_estimate = if opts.adhesion_error_estimate {
        // probe each resolution in turn (their errors need not have the same sign, so one
        // combined change can hide both): S·(max(|a − a(3/2 steps)|, |a − a(2 steps)|) +
        // |a − a(points/2)|). Two step probes, because the thin slab's step error depends on
        // where the wall's onset falls in its step, and one probe can share that alignment
        // with the solve (24 and 36 steps agreed to 6e-7 where both were 1.1e-5 off). For
        // the second-order march the differences are about 0.56×, 0.75× and 3× the errors
        // they measure; S = 4 (`tolerances::ADHESION_ERROR_SAFETY`) covers the
        // pre-asymptotic scenes (measured against the oracle of `tests/adhesion_oracle.rs`
        // and 4× finer runs)
        let probe = |steps: f64, points: f64| -> Result<Option<f64>> {
            let mut coarse = opts.adhesion;
            coarse.explore_branches = false;
            coarse.steps_per_ln_q *= steps;
            coarse.points_per_width *= points;
            match adhesion::solve_checked(scene, &coarse, &[&sol], cancel) {
                Ok(c) => Ok(Some((c.a_r - sol.a_r).abs())),
                Err(Error::Cancelled) => Err(Error::Cancelled),
                // near a jump a probe may not converge although the solve did: the estimate
                // then rests on the other probes (doubled), or is unavailable
                Err(Error::NotConverged { .. }) => Ok(None),
                Err(e) => Err(e),
            }
        };
        // the probes are independent solves: run side by side (rayon), combined in a fixed
        // order, so the estimate does not depend on the number of threads
        let factors = crate::tolerances::ADHESION_ERROR_STEPS_FACTORS;
        let settings: Vec<(f64, f64)> = factors.iter().map(|&f| (f, 1.0)).chain([(1.0, 0.5)]).collect();
        let diffs = settings
            .par_iter()
            .map(|&(steps, points)| probe(steps, points))
            .collect::<Result<Vec<Option<f64>>>>()?;
        let step_diff = diffs[..factors.len()].iter().flatten().copied().reduce(f64::max);
        let point_diff = diffs[factors.len()];
        let safety = crate::tolerances::ADHESION_ERROR_SAFETY;
        let residual = sol.residual * sol.a_r;
        match (step_diff, point_diff) {
            (Some(s), Some(p)) => residual + safety * (s + p),
            (Some(d), None) | (None, Some(d)) => residual + safety * 2.0 * d,
            (None, None) => f64::NAN,
        }
    } else {
        sol.residual * sol.a_r
    };
    if !error_estimate.is_finite() {
        return Err(Error::NotConverged {
            solver: crate::error::Solver::AdhesiveTheory,
            reason: format!(
                "the self-consistency converged (a_r = {:.6}, {} branch) but neither resolution \
                 check did, so its discretisation error cannot be estimated: the state sits on the \
                 edge of a jump into contact, where the result depends on the grid; try a nearby \
                 p*, t or gamma",
                sol.a_r, sol.branch
            ),
        });
    }
    let out_q = persson::resolution_grid(scene, opts.accuracy.resolution_points);
    let resolution = out_q
        .iter()
        .map(|&q| ResolutionPoint {
            q,
            a_r: adhesion::interpolate(&sol, q, &sol.a_q),
            variance: adhesion::interpolate(&sol, q, &sol.v_q),
        })
        .collect();
    let gamma_q = out_q
        .iter()
        .map(|&q| adhesion::interpolate(&sol, q, &sol.gamma_q))
        .collect();
    let sigma_a_q = out_q
        .iter()
        .map(|&q| adhesion::interpolate(&sol, q, &sol.sigma_a_q))
        .collect();
    let pr = resample(&sol, opts);
    Ok(Evaluation {
        stats: stats_of([sol.a_r, sol.mean_contact_stress, sol.contact_stress_variance], pr),
        width: sol.width,
        resolution,
        error_estimate,
        elastic_energy: sol.elastic_energy,
        sigma_a: sol.sigma_a,
        tensile_area: sol.tensile_area,
        detached_fraction: sol.detached_fraction,
        gamma_q,
        sigma_a_q,
        iterations: sol.iterations,
        residual: sol.residual,
        branch: sol.branch,
        unloading_a_r: sol.unloading_a_r,
        branches: sol.branches.clone(),
        contact_loads: sol.contact_loads.clone(),
        gamma_glo: sol.gamma_glo,
        elapsed_s: t0.elapsed().as_secs_f64(),
        adhesive: Some(Box::new(sol)),
    })
}

/// Pr(σ*) of an adhesive solution on `sigma_points` points from −σ_a* to σ_max (linear
/// interpolation of the solver's grid; 0 beyond it).
fn resample(sol: &AdhesiveSolution, opts: &Options) -> (Vec<f64>, Vec<f64>) {
    let n = opts.sigma_points.max(2);
    let lo = -sol.sigma_a;
    let hi = match opts.sigma_max {
        Some(s) if s > lo => s,
        _ => sol.pressure + 5.0 * sol.width,
    };
    let src_s = &sol.sigma;
    let src_d = &sol.density;
    let sigma: Vec<f64> = (0..n).map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64).collect();
    let density = sigma
        .iter()
        .map(|&s| {
            let i = src_s.partition_point(|&x| x < s);
            if i == 0 || i >= src_s.len() {
                return 0.0;
            }
            let (s0, s1) = (src_s[i - 1], src_s[i]);
            let t = if s1 > s0 { (s - s0) / (s1 - s0) } else { 0.0 };
            (src_d[i - 1] + t * (src_d[i] - src_d[i - 1])).max(0.0)
        })
        .collect();
    (sigma, density)
}
