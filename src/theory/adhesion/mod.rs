//! Persson theory with adhesion: a moving absorbing wall, the scale-dependent surface energy
//! and the self-consistent solution with all its branches (physics.md §4; [S-5..S-9, S-14]).
//!
//! # Equations
//!
//! Reduced units: σ* = σ/(E*ḡ), variance v = V/(E*ḡ)². Resolution q acts as time; the stress
//! distribution diffuses in the accumulated variance
//!
//! ```text
//! dv = W(a_r(q))^{2α} · f(qt)² q² dm / (4ḡ²),   dm = 2πqC dq       [S-2, S-15]
//! ∂Pr/∂v = ½ ∂²Pr/∂σ²  on σ > −σ_a(q),   Pr(−σ_a(q), q) = 0,   Pr(σ, q_L) = δ(σ − p*)  [S-5, S-7]
//! a_r(q) = ∫_{−σ_a}^∞ Pr dσ                                         [S-6]
//! σ_a(q) = k_G √(q E* f(qt) γ(q)),  capped at γ_s/ρ where the model says so   [S-8]
//! a_r(q)γ(q) = a_r(q_s)γ_s − ∫_q^{q_s} a_r W(a_r) (q'E* f/4) dm(q'),  γ < 0 → 0   [S-9, S-14]
//! ```
//!
//! (a_s(q) of [S-9] taken as a_r(q): physics.md §7 erratum 7.) Mass that crosses the wall
//! detaches: 1 − a_r(q_s) is the non-contact fraction, ∫_{−σ_a}^0 Pr dσ the contact under
//! tension. With σ_a > 0 the mirror kernel does not conserve ∫σPr (physics.md §4); the mean
//! stress in contact is reported as computed.
//!
//! # Propagation (moving wall)
//!
//! The march runs over steps in ln q (uniform per PSD segment). In the frame x = σ + σ_a the
//! wall sits at x = 0; its motion between the nodes (linear in v, σ_a at the nodes from γ
//! there) is a drift c = dσ_a/dv, and each step applies the exact solution operator of
//! ∂p/∂v = ½p'' − cp' with p(0) = 0 for constant c: the image solution with weights e^{−2cy}
//! (`propagator`), a sine-type transform (a length-2N complex FFT of the weighted odd
//! extension), a heat factor exp(−½κ²Δv) and a shift phase per mode, and back. For a fixed
//! wall this is the mirror-Gaussian solution, spectrally accurate in space and exact in v, so
//! σ_a ≡ const is reproduced to round-off (a_r is the spectral integral of the series; the
//! trapezoid rule would be O(h²) because Pr'(wall) ≠ 0); a moving wall is second order in the
//! step (measured order 2.0, `tests/adhesion.rs`). A wall receding into the distribution
//! (c < 0) is Strang-split: half a shift, the heat step with the wall held, the other half
//! (second order; the growing weights e^{2|c|y} are avoided). Where a wall runs away faster
//! than the grid resolves its image weight e^{−2cy} (2c·h > 2, right after an onset, where
//! σ_a ∝ √γ starts at infinite speed) the grid is refined first.
//!
//! Δv = W^{2α}(a)·∫_step f²q²dm/(4ḡ²) by RK4 in the variance measure B with a(v) from the
//! loaded coefficients. While the wall has not moved since the start (σ_a constant, in
//! particular σ_a = 0 at coarse scales where γ(q) = 0), or while the wall is too far from the
//! distribution to matter (p* + σ_a > 8.5√v, image mass < 1e-17), Pr is the mirror Gaussian
//! about the wall and v follows the autonomous ODE dv/dB = W^{2α}(a(v)), integrated with RK4
//! in B (no grid). The grid starts from that mirror Gaussian with spacing
//! h = √v/`points_per_width`, reaches p* + σ_a + 10√v (rounded up to an FFT-friendly size
//! 2^a·3^b·5^c), is coarsened by 2 (keeping every other node, exact) whenever √v exceeds
//! 2·`points_per_width`·h, and starts at x₀ > 0 (3√v below where the density falls under 1e-16
//! of its peak) while the wall runs ahead of the distribution, so its size stays bounded
//! (~25·`points_per_width` nodes) from p* = 1e-8 to full contact.
//!
//! # Self-consistency: one scalar equation, every branch
//!
//! γ(q) needs a_r at all finer scales and a_r needs σ_a at all coarser ones. Written with
//! C = γ(q_L) the energy balance runs forward (`shooting`):
//! a_r(q)γ(q) = C + ∫_{q_L}^{q} a_r W (q'E*f/4) dm, so for given C one march from q_L to q_s
//! yields everything, and self-consistency is the scalar equation
//!
//! ```text
//! H(C) = C + I(C) − γ_s a_r(q_s; C) = 0,   I = ∫_{q_L}^{q_s} a_r W (qE*f/4) dm,   C ∈ [−I_full, γ_s]
//! ```
//!
//! with H(−I_full) < 0 < H(γ_s): a root always exists. `roots` finds every root (a scan in
//! asinh(C/c₀), logarithmic in |C| on both sides of 0, at half resolution, then Brent's method
//! at the requested one), so every branch of the scene at this load is found without
//! iterating a map that loses contraction near a jump into contact (the map
//! a ↦ march(σ_a(γ(a))) is ill-conditioned exactly there: an error δH in the balance moves γ
//! by δH/a_r(q), which is large where γ(q) turns positive at small a_r). A root where H rises
//! is stable; where it falls (between two rising ones), unstable. The loading branch — what a
//! loading history from small p* reaches — is the lowest stable root; the highest stable root,
//! where it differs, is the unloading branch (hysteresis), reported as `unloading_a_r` and in
//! `branches`. `residual` is |H|/(γ_s a_r(q_s)) = |γ(q_s)/γ_s − 1| at the root (≤ `tol`).
//!
//! # Weak adhesion: the limit γ_s → 0
//!
//! Where γ_s a_r(q_s) is tiny against the elastic energy I (≈ the full-contact u_ela^(f)),
//! the root sits at C ≈ −I and H = C + I − γ_s a_r is a near-cancellation: it is known only to
//! its round-off, ~ε(1 + |w|)|C| (`shooter::BALANCE_ULPS`), and the relative tolerance
//! tol·γ_s·a_r can lie below that (γ_s ≲ 1e-7 J/m² on system II at the default tol = 1e-8).
//! There Brent's bracket narrows to the scan variable's ulps, the balance is met to round-off,
//! and the reported residual is the mismatch beyond it. What that round-off leaves open moves
//! a_r by less than the weak walls' whole effect, a_r·σ_a*/p* with σ_a* ∝ √γ_s (1e-7 a_r at
//! γ_s = 1e-12 J/m² on systems I and II), far below the discretisation error. Where γ_s is
//! below one ulp of u_ela^(f) (γ̃_glo ≤ ε, [`crate::input::scene::WEAK_ADHESION_GLO`]) it
//! cannot move the balance at all: the scene is not adhesive ([`Scene::is_adhesive`]) and
//! every front end evaluates it with the adhesionless theory, its γ_s → 0 limit. The two
//! answers meet to the adhesive march's discretisation error (the march with the walls at
//! zero against the adhesionless ODE: 1e-4 relative on system I at the default resolution);
//! `tests/weak_adhesion.rs` sweeps γ_s from 5e-324 to 1e-3 J/m².
//!
//! # Files
//!
//! `grid` (resolution steps), `heat` (the exact drift–diffusion step with an absorbing wall),
//! `moments` (the final distribution's moments),
//! `propagator` (the march for given walls, one step at a time), `wall_motion` (the wall's
//! move on the march's grid within a piece), `regrid` (shift, refine and re-offset the
//! march's grid),
//! `walls` (σ_a(q) for γ(q)), `shooting` (the forward march for given C), `shooter` (H(C)
//! shot by shot, in the scan variable), `roots` (all roots of H), `pair` (whether the pair of roots that merges at a fold persists), `strategy` (the branch chosen and the solution assembled), `tension` (the contact branch
//! under tension, p* ≤ 0, and the theory's pull-off), and this module
//! (accuracy, result types, entry points).

mod grid;
mod heat;
mod moments;
mod pair;
mod propagator;
mod regrid;
mod roots;
pub mod scales;
mod shooter;
mod shooting;
mod strategy;
mod tension;
mod wall_motion;
mod walls;

pub use pair::pair_at;
pub(crate) use strategy::solve_checked;
pub use strategy::{solve, solve_continued, EXTRAPOLATE_MAX};
pub use tension::{pull_off, tensile_branch, tension_bound, TensilePullOff};

use crate::error::{check_in, Field, Result};
use crate::input::scene::Scene;
use serde::{Serialize, Serializer};
use std::fmt;

/// Accuracy and strategy of the adhesive solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdhesionAccuracy {
    /// March steps per unit of ln q (per PSD segment, at least 4 per segment).
    pub steps_per_ln_q: f64,
    /// Grid nodes per standard deviation √v of the stress distribution.
    pub points_per_width: f64,
    /// Self-consistency tolerance: |γ(q_s)/γ_s − 1| ≤ tol at each root (the energy balance
    /// [S-14] at the finest scale).
    pub tol: f64,
    /// Most root-refinement marches per branch.
    pub max_iterations: usize,
    /// Scan for every branch even when a warm start (a nearby solution) is given. Off in
    /// sweeps: the branches of the previous load are tracked, and the scan runs only when they
    /// no longer account for every sign change of H.
    pub explore_branches: bool,
    /// Which branch the solution reports (its Pr, moments, wall, energy): `false` the
    /// loading branch (the lowest stable root: the state a loading history from small p*
    /// reaches), `true` the unloading branch (the highest stable root) where the load has two
    /// stable branches — the state an unloading history keeps inside a hysteresis window.
    /// Outside a window both choices give the one stable branch. Every branch is listed in
    /// [`AdhesiveSolution::branches`] either way.
    pub follow_unloading: bool,
}

/// Allowed march steps per ln q: at least 4 because the engine's error estimate compares
/// with half the resolution; the same range wherever the knob is set.
pub const ADHESION_STEPS_RANGE: (f64, f64) = (4.0, 1e4);
/// Allowed grid points per width (at least 4, as [`ADHESION_STEPS_RANGE`]).
pub const ADHESION_POINTS_RANGE: (f64, f64) = (4.0, 1e3);
/// Allowed self-consistency tolerance |γ(q_s)/γ_s − 1|.
pub const ADHESION_TOL_RANGE: (f64, f64) = (1e-14, 1e-1);

impl AdhesionAccuracy {
    /// Checks the knobs against [`ADHESION_STEPS_RANGE`], [`ADHESION_POINTS_RANGE`] and
    /// [`ADHESION_TOL_RANGE`] (the engine and [`solve`] use this one check).
    ///
    /// # Errors
    /// [`crate::Error::Invalid`] naming [`Field::AdhesionSteps`], [`Field::AdhesionPoints`] or
    /// [`Field::AdhesionTol`], or [`Field::MaxIterations`] for zero marches.
    pub fn validate(&self) -> Result<()> {
        check_in(
            Field::AdhesionSteps,
            self.steps_per_ln_q,
            ADHESION_STEPS_RANGE.0,
            ADHESION_STEPS_RANGE.1,
        )?;
        check_in(
            Field::AdhesionPoints,
            self.points_per_width,
            ADHESION_POINTS_RANGE.0,
            ADHESION_POINTS_RANGE.1,
        )?;
        check_in(Field::AdhesionTol, self.tol, ADHESION_TOL_RANGE.0, ADHESION_TOL_RANGE.1)?;
        Ok(())
    }
}

impl Default for AdhesionAccuracy {
    /// The `run` default (24 steps per ln q, 10 points per width): relative a_r error
    /// 1e-5–1e-4 against the slow oracle and a 4× finer run on systems I and II, thin slabs
    /// included (the `ladder` and the oracle tests, BENCHMARKS.md).
    fn default() -> Self {
        AdhesionAccuracy {
            steps_per_ln_q: 24.0,
            points_per_width: 10.0,
            tol: 1e-8,
            max_iterations: 200,
            explore_branches: true,
            follow_unloading: false,
        }
    }
}

/// The branch a solution lies on. Serialised (and displayed) as the strings of the public
/// JSON: "adhesionless", "loading", "unloading", "unstable".
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Branch {
    /// No adhesion (γ_s = 0): a single solution.
    Adhesionless,
    /// The lowest stable branch: the state a loading history from small p* reaches.
    Loading,
    /// The highest stable branch where it differs from the loading one: the state an
    /// unloading history keeps (hysteresis).
    Unloading,
    /// A branch between two stable ones (H falls through its root): not reached by any
    /// history.
    Unstable,
}

impl Branch {
    /// The public string of the branch.
    pub fn as_str(self) -> &'static str {
        match self {
            Branch::Adhesionless => "adhesionless",
            Branch::Loading => "loading",
            Branch::Unloading => "unloading",
            Branch::Unstable => "unstable",
        }
    }
}

impl fmt::Display for Branch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl Serialize for Branch {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

/// The self-consistent adhesive solution of one scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AdhesiveSolution {
    /// p*.
    pub pressure: f64,
    /// a_r(q_s), tensile part included.
    pub a_r: f64,
    /// σ̄_c* = ∫σPr/a_r (reduced; with detachment not equal to p*/a_r).
    pub mean_contact_stress: f64,
    /// ⟨δσ_c²⟩* (reduced by (E*ḡ)²).
    pub contact_stress_variance: f64,
    /// √v(q_s): the accumulated broadening.
    pub width: f64,
    /// σ_a*(q_s): the wall sits at σ* = −σ_a*.
    pub sigma_a: f64,
    /// Contact under tension, ∫_{−σ_a}^0 Pr dσ.
    pub tensile_area: f64,
    /// Fraction of the nominal area that detached (crossed the wall): 1 − a_r.
    pub detached_fraction: f64,
    /// Resolution nodes q (1/m).
    pub q: Vec<f64>,
    /// a_r at the nodes.
    pub a_q: Vec<f64>,
    /// v(q) = V/(E*ḡ)² at the nodes.
    pub v_q: Vec<f64>,
    /// γ(q)/γ_s at the nodes.
    pub gamma_q: Vec<f64>,
    /// σ_a*(q) at the nodes.
    pub sigma_a_q: Vec<f64>,
    /// Pr(σ*) at q_s: σ* grid (ascending, from −σ_a*).
    pub sigma: Vec<f64>,
    /// Pr(σ*) at q_s (∫ = a_r).
    pub density: Vec<f64>,
    /// Marches of the root search (the scan and the refinement of every root).
    pub iterations: usize,
    /// Self-consistency residual at the chosen root: |H|/(γ_s a_r(q_s)) = |γ(q_s)/γ_s − 1|.
    pub residual: f64,
    /// Which branch the solution is on: loading, or unloading where
    /// [`AdhesionAccuracy::follow_unloading`] asked for it and the load has two stable branches.
    pub branch: Branch,
    /// a_r of a distinct unloading branch (the highest stable root), if one was found.
    pub unloading_a_r: Option<f64>,
    /// U = −a_r γ_s + Σ a W (qE*f/4) dm (J/m²) [S-11, S-14].
    pub elastic_energy: f64,
    /// Global adhesion measure γ̃_glo.
    pub gamma_glo: f64,
    /// Every branch of the scene at this load, lowest a_r first (the chosen one included).
    pub branches: Vec<BranchState>,
    /// Per entry of `branches`: the net force its contact carries per nominal area,
    /// ∫σ* Pr dσ* over the contact (reduced): p* plus the tension carried off through the wall
    /// (physics.md §4; it sets the branch's mean gap, §5.1).
    pub contact_loads: Vec<f64>,
    /// γ_s of the scene (J/m²).
    pub gamma_s: f64,
}

/// One branch of the adhesive solution at a load: a root of the scalar self-consistency.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BranchState {
    /// Which branch: "loading" (the lowest stable), "unloading" (the highest stable, where
    /// distinct), "unstable" (between them).
    pub branch: Branch,
    /// Whether the branch is stable (H rises through its root).
    pub stable: bool,
    /// a_r(q_s).
    pub a_r: f64,
    /// σ_a*(q_s).
    pub sigma_a: f64,
    /// γ(q_L)/γ_s: the effective surface energy at the coarsest scale, the root's C/γ_s.
    pub gamma_coarse: f64,
    /// U (J/m²) of the branch [S-11, S-14].
    pub elastic_energy: f64,
    /// The branch's own self-consistency residual |γ(q_s)/γ_s − 1| at its root.
    pub residual: f64,
}
/// Propagates Pr through the scene's resolution with a prescribed wall σ_a*(q) (reduced,
/// evaluated at the nodes q_k; the wall moves linearly in v between them) and no
/// self-consistency: the propagator alone, for tests against the exact cases.
/// `grid_from_start` forces the grid from the first step on (otherwise a wall that never
/// moves is handled by the mirror Gaussian). Returns the nodes q and a_r(q).
pub fn propagate_with_wall(
    scene: &Scene,
    acc: &AdhesionAccuracy,
    wall: impl Fn(f64) -> f64,
    grid_from_start: bool,
) -> Result<(Vec<f64>, Vec<f64>)> {
    let grid = grid::build_grid(scene, acc.steps_per_ln_q);
    let walls: Vec<f64> = grid.q.iter().map(|&q| wall(q)).collect();
    // a wall that leaves zero inside a step: where (bisection in ln q)
    let onsets: Vec<Option<f64>> = grid
        .q
        .windows(2)
        .zip(walls.windows(2))
        .map(|(q, w)| {
            (w[0] == 0.0 && w[1] > 0.0).then(|| {
                let (l0, l1) = (q[0].ln(), q[1].ln());
                let (mut lo, mut hi) = (0.0, 1.0);
                for _ in 0..40 {
                    let mid = 0.5 * (lo + hi);
                    if wall((l0 + mid * (l1 - l0)).exp()) > 0.0 {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                lo
            })
        })
        .collect();
    let mut m = propagator::Marcher {
        scene,
        grid: &grid,
        acc: *acc,
        heat: propagator::Heat::new(),
        force_grid_from: grid_from_start.then_some(1),
        pressure: scene.pressure,
        trials: 0,
        step_aw: None,
        overflow: false,
    };
    let a = m.march(&walls, &onsets);
    if m.overflow {
        return Err(crate::error::Error::NotConverged {
            solver: crate::error::Solver::AdhesiveMarch,
            reason: format!("the prescribed wall needs more than {} grid nodes", m.max_nodes()),
        });
    }
    Ok((grid.q.clone(), a))
}

/// γ(q)/γ_s and σ_a*(q) interpolated at resolution q (linear in ln q between nodes).
pub fn interpolate(sol: &AdhesiveSolution, q: f64, values: &[f64]) -> f64 {
    let i = sol.q.partition_point(|&x| x < q);
    if i == 0 {
        return values[0];
    }
    if i >= sol.q.len() {
        return *values.last().unwrap_or(&0.0);
    }
    let (l, l0, l1) = (q.ln(), sol.q[i - 1].ln(), sol.q[i].ln());
    // a q within rounding of a node is that node (at q_L the grid's first nodes can differ by
    // an ulp, where ln q − ln q₀ = 0 and ln q₁ − ln q₀ = 0 would give 0/0)
    if l <= l0 || l1 <= l0 {
        return values[i - 1];
    }
    let t = ((l - l0) / (l1 - l0)).min(1.0);
    values[i - 1] + t * (values[i] - values[i - 1])
}
