//! Persson theory with adhesion: a moving absorbing wall, the scale-dependent surface energy
//! and the self-consistent fixed point (physics.md §4; [S-5..S-9, S-14]).
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
//! wall sits at x = 0. Each step holds the wall at its mean over the step (with γ linear in ln q
//! between nodes, the mean of √γ₊ in closed form: smooth where γ turns positive) and
//!
//! 1. shifts Pr by the change of σ_a since the previous step (8-point Lagrange interpolation;
//!    the stencil uses the odd continuation of Pr through the wall, mass below the wall is
//!    removed), then
//! 2. applies the exact heat semigroup of the Dirichlet problem on [0, X] to the grid values:
//!    sine transform (a length-2N complex FFT of the odd extension), multiply mode k by
//!    exp(−½(kπ/X)²Δv), transform back. For a fixed wall this is the image (mirror-Gaussian)
//!    solution, spectrally accurate in space and exact in v, so σ_a ≡ const is reproduced to
//!    round-off (a_r is the spectral integral of the sine series; the trapezoid rule would be
//!    O(h²) because Pr'(wall) ≠ 0). A moving wall adds the piecewise-constant wall motion and
//!    the shift: each shift leaves an empty gap of width δ at the wall that the next heat step
//!    fills, and this splitting is first order at the absorbing boundary (measured order ≈ 1.2,
//!    `tests/adhesion.rs`).
//!
//! Δv = W^{2α}(ā)·∫_step f²q²dm/(4ḡ²) with ā the mean of a_r at both ends of the step
//! (predictor–corrector: the step is taken twice). While the wall has not moved since the start
//! (σ_a constant, in particular σ_a = 0 at coarse scales where γ(q) = 0), or while the wall is
//! too far from the distribution to matter (p* + σ_a > 8.5√v, image mass < 1e-17), Pr is the
//! mirror Gaussian about the wall and v follows the autonomous ODE dv/dB = W^{2α}(a(v)),
//! integrated with RK4 in B (no grid). The grid starts from that mirror Gaussian with spacing
//! h = √v/`points_per_width`, grows with the distribution and is coarsened by 2 (keeping every
//! other node, exact) whenever √v exceeds 2·`points_per_width`·h, so its size stays bounded
//! (~20·`points_per_width` nodes) from p* = 1e-8 to full contact.
//!
//! # Self-consistency
//!
//! γ(q) needs a_r at all finer scales and a_r needs σ_a at all coarser ones: the unknown is
//! the function a_r(q) at the step nodes, x ↦ G(x) = march(σ_a(γ(x))). The fixed point is
//! found with Anderson mixing (depth 6, Walker–Ni type II), started from the adhesionless
//! solution (the loading branch), until max|G(x) − x| ≤ `tol`·a_r(q_s). If Anderson stalls,
//! it is retried at two nearby resolutions; then, where plain iteration falls into a two-state
//! cycle (near a jump into contact), from a start bisected between the cycle's states; then
//! from full contact (reported as the upper branch); then with damped mixing; then with
//! continuation in γ_s (from γ = 0 in growing steps, each warm-started). A scene where none of these converges is an
//! error ([`Error::NotConverged`]) that names the residual. With `explore_branches`, the fixed
//! point is also sought from full contact (a_r ≡ 1, the unloading branch); if it converges to
//! a different state, both are reported (hysteresis: the loading branch is the answer, the
//! other is `unloading_a_r`).
//!
//! Diagnostics: with `ASPERITY_DEBUG` set, every fixed-point iteration prints its residual and
//! a_r(q_s) to stderr.

// index loops mirror the formulas (nodes j, steps k) in this numerical module
#![allow(clippy::needless_range_loop)]

use crate::error::{Error, Field, Result};
use crate::input::scene::Scene;
use crate::surface::spectrum::{Spectrum, GL4};
use crate::theory::slab::slab_factor_at;
use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use serde::Serialize;
use statrs::function::erf::erf;
use std::f64::consts::{FRAC_1_SQRT_2, PI};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// Accuracy and strategy of the adhesive solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdhesionAccuracy {
    /// March steps per unit of ln q (per PSD segment, at least 4 per segment).
    pub steps_per_ln_q: f64,
    /// Grid nodes per standard deviation √v of the stress distribution.
    pub points_per_width: f64,
    /// Fixed-point tolerance: max_q |G(a) − a| ≤ tol · a_r(q_s).
    pub tol: f64,
    /// Most fixed-point iterations per attempt.
    pub max_iterations: usize,
    /// Also look for an unloading branch (started from full contact).
    pub explore_branches: bool,
    /// Use every fallback when a fixed point stalls (two nearby resolutions, damped mixing,
    /// continuation in γ: up to seconds on a hard case). Off in sweeps, where a load that
    /// stalls is reported as such after the cheap fallbacks (cycle bisection, full contact).
    pub thorough: bool,
}

impl Default for AdhesionAccuracy {
    /// The interactive/`run` default: relative error of a_r ~1e-3 against a 4× finer solution
    /// on systems 1 and 2 (`tests/adhesion.rs`); ~10 ms per solve on system 1.
    fn default() -> Self {
        AdhesionAccuracy {
            steps_per_ln_q: 24.0,
            points_per_width: 10.0,
            tol: 1e-8,
            max_iterations: 200,
            explore_branches: true,
            thorough: true,
        }
    }
}

/// One march step between two resolution nodes.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Step {
    /// Midpoint wave number (geometric mean; for a discrete shell its |q|).
    q_mid: f64,
    /// ∫_step f²q²dm/(4ḡ²): the step's variance increment for W = 1.
    b: f64,
    /// ∫_step (qE*f/4) dm (J/m²): full-contact elastic energy of the step's modes.
    e: f64,
}

/// The step grid of a scene (q nodes and steps).
#[derive(Debug, Clone, PartialEq)]
struct Grid {
    q: Vec<f64>,
    steps: Vec<Step>,
}

fn build_grid(scene: &Scene, steps_per_ln_q: f64) -> Grid {
    let t = scene.thickness_m();
    let g2 = scene.spectrum.moment(2);
    let es = scene.modulus;
    match &scene.spectrum {
        Spectrum::SelfAffine(sa) => {
            let bp = scene.spectrum.breakpoints();
            let mut q = vec![bp[0]];
            let mut steps = Vec::new();
            // ∫_{s0}^{s1} g(q) dm over ln q with 2 GL4 panels per step (the integrands are smooth)
            let integ = |s0: f64, s1: f64, g: &dyn Fn(f64) -> f64| -> f64 {
                let mut sum = 0.0;
                for half in 0..2 {
                    let a = s0 + (s1 - s0) * half as f64 / 2.0;
                    let bb = a + (s1 - s0) / 2.0;
                    for &(x, w) in &GL4 {
                        let s = 0.5 * (a + bb) + 0.5 * (bb - a) * x;
                        let qq = s.exp();
                        sum += 0.5 * (bb - a) * w * g(qq) * sa.dm_dlnq(qq);
                    }
                }
                sum
            };
            for w in bp.windows(2) {
                let (s0, s1) = (w[0].ln(), w[1].ln());
                let n = ((s1 - s0) * steps_per_ln_q).ceil().max(4.0) as usize;
                for k in 0..n {
                    let a = s0 + (s1 - s0) * k as f64 / n as f64;
                    let bb = s0 + (s1 - s0) * (k + 1) as f64 / n as f64;
                    let mid = 0.5 * (a + bb);
                    let bfun = |qq: f64| {
                        let f = slab_factor_at(qq, t);
                        f * f * qq * qq / (4.0 * g2)
                    };
                    let efun = |qq: f64| qq * es * slab_factor_at(qq, t) / 4.0;
                    steps.push(Step {
                        q_mid: mid.exp(),
                        b: integ(a, bb, &bfun),
                        e: integ(a, bb, &efun),
                    });
                    q.push(bb.exp());
                }
            }
            Grid { q, steps }
        }
        Spectrum::Discrete(d) => {
            let mut q = vec![d.modes[0].q];
            let mut steps = Vec::with_capacity(d.modes.len());
            for m in &d.modes {
                let f = slab_factor_at(m.q, t);
                let e = m.q * es * f / 4.0 * m.dm;
                steps.push(Step {
                    q_mid: m.q,
                    b: f * f * m.q * m.q * m.dm / (4.0 * g2),
                    e,
                });
                q.push(m.q);
            }
            Grid { q, steps }
        }
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
    /// Fixed-point iterations (all attempts).
    pub iterations: usize,
    /// Final fixed-point residual max|G(a) − a| / a_r(q_s).
    pub residual: f64,
    /// "loading" (from the adhesionless start), "loading (continuation in gamma)", or "upper
    /// (from full contact)" where the loading iteration could not lock on.
    pub branch: String,
    /// a_r of a distinct unloading branch (from full contact), if one was found.
    pub unloading_a_r: Option<f64>,
    /// U = −a_r γ_s + Σ a W (qE*f/4) dm (J/m²) [S-11, S-14].
    pub elastic_energy: f64,
    /// Global adhesion measure γ̃_glo.
    pub gamma_glo: f64,
    /// The (steps per ln q, points per width) actually used when the requested resolution
    /// stagnated and a nearby one converged; None when the requested one did.
    pub resolution_used: Option<(f64, f64)>,
}

/// Forward and inverse FFTs of one length.
type Plan = (usize, Arc<dyn Fft<f64>>, Arc<dyn Fft<f64>>);

/// Sine-transform heat propagator on [0, X] with Dirichlet ends, for a grid of N intervals.
struct Heat {
    planner: FftPlanner<f64>,
    plan: Option<Plan>,
    buf: Vec<Complex64>,
    scratch: Vec<Complex64>,
    /// (coefficient, decay rate) of the mass integral per odd sine mode.
    terms: Vec<(f64, f64)>,
    n: usize,
    x: f64,
}

impl Heat {
    fn new() -> Self {
        Heat {
            planner: FftPlanner::new(),
            plan: None,
            buf: Vec::new(),
            scratch: Vec::new(),
            terms: Vec::new(),
            n: 0,
            x: 0.0,
        }
    }

    /// Loads grid values p at x_j = j·h, j = 0..=N (p[0] = p[N] = 0): one forward transform
    /// of the odd extension. Afterwards [`Heat::mass`] gives ∫_0^X p dx after any extra
    /// variance dv in O(N), and [`Heat::finish`] writes the evolved values back.
    fn load(&mut self, p: &[f64], h: f64) {
        let n = p.len() - 1;
        let m = 2 * n;
        if self.plan.as_ref().map(|pl| pl.0) != Some(m) {
            let fwd = self.planner.plan_fft_forward(m);
            let inv = self.planner.plan_fft_inverse(m);
            let len = fwd.get_inplace_scratch_len().max(inv.get_inplace_scratch_len());
            self.scratch = vec![Complex64::new(0.0, 0.0); len];
            self.plan = Some((m, fwd, inv));
        }
        let (_, fwd, _) = self.plan.as_ref().expect("planned");
        self.buf.clear();
        self.buf.resize(m, Complex64::new(0.0, 0.0));
        for j in 1..n {
            self.buf[j] = Complex64::new(p[j], 0.0);
            self.buf[m - j] = Complex64::new(-p[j], 0.0);
        }
        fwd.process_with_scratch(&mut self.buf, &mut self.scratch);
        let x = n as f64 * h;
        self.n = n;
        self.x = x;
        // ∫_0^X p dx = Σ_{k odd} b_k·2X/(kπ) for p = Σ b_k sin(kπx/X), b_k = −2 Im(c_k),
        // c = FFT/M: spectral, where the trapezoid rule is O(h²) because p'(0) ≠ 0
        self.terms.clear();
        for k in (1..n).step_by(2) {
            let b = -2.0 * self.buf[k].im / m as f64;
            let kk = k as f64 * PI / x;
            self.terms.push((b * 2.0 * x / (k as f64 * PI), 0.5 * kk * kk));
        }
    }

    /// ∫_0^X p dx after a further variance dv (exact for the loaded trigonometric interpolant).
    fn mass(&self, dv: f64) -> f64 {
        self.terms.iter().map(|&(c, r)| c * (-r * dv).exp()).sum()
    }

    /// Writes the loaded values evolved by dv back into p.
    fn finish(&mut self, p: &mut [f64], dv: f64) {
        let (n, x) = (self.n, self.x);
        let m = 2 * n;
        let (_, _, inv) = self.plan.as_ref().expect("loaded");
        let c = 0.5 * dv * (PI / x) * (PI / x);
        for k in 0..m {
            let kk = k.min(m - k) as f64;
            self.buf[k] *= (-c * kk * kk).exp() / m as f64;
        }
        inv.process_with_scratch(&mut self.buf, &mut self.scratch);
        p[0] = 0.0;
        p[n] = 0.0;
        for j in 1..n {
            p[j] = self.buf[j].re;
        }
    }

    /// Evolves p by dv and returns its integral.
    #[cfg(test)]
    fn apply(&mut self, p: &mut [f64], h: f64, dv: f64) -> f64 {
        self.load(p, h);
        let mass = self.mass(dv);
        self.finish(p, dv);
        mass
    }
}

/// The state of the march.
enum State {
    /// Mirror Gaussian about the wall (x = σ + wall ≥ 0), variance v.
    Analytic,
    /// Grid values at x_j = j h.
    Grid { h: f64, p: Vec<f64> },
}

/// Result of one march.
struct March {
    a_nodes: Vec<f64>,
    v_nodes: Vec<f64>,
    v: f64,
    wall: f64,
    state: State,
}

/// The variance increment of one march step: RK4 in the variance measure B for
/// du/dB = `rate(u)` from u = 0 over the step's `b`, with [`substeps`]. The analytic and the
/// grid stage both use it, so switching between them is continuous.
fn variance_step(rate: &dyn Fn(f64) -> f64, b_before: f64, b: f64) -> f64 {
    let nsub = substeps(b_before, b);
    let hb = b / nsub as f64;
    let mut u = 0.0;
    for _ in 0..nsub {
        let k1 = rate(u);
        let k2 = rate(u + 0.5 * hb * k1);
        let k3 = rate(u + 0.5 * hb * k2);
        let k4 = rate(u + hb * k3);
        u += hb * (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
    }
    u
}

/// RK4 substeps of a march step: 8 while the accumulated variance measure is still small
/// against the step's (a_r falls fast there), else 1. A function of the grid only, never of
/// the iterate, so that the fixed-point map stays continuous.
fn substeps(b_before: f64, b: f64) -> usize {
    if b_before < 4.0 * b {
        8
    } else {
        1
    }
}

/// Mirror-Gaussian contact fraction at distance d from the wall with variance v.
fn mirror_area(d: f64, v: f64) -> f64 {
    if d <= 0.0 {
        0.0
    } else if v <= 0.0 {
        1.0
    } else {
        erf(d / v.sqrt() * FRAC_1_SQRT_2)
    }
}

fn gauss(x: f64, v: f64) -> f64 {
    (-x * x / (2.0 * v)).exp() / (2.0 * PI * v).sqrt()
}

/// Points of the shift's Lagrange interpolation: the error per shift is O(h⁸ ∂⁸Pr), ~1e-9 of
/// Pr at 10 points per width (4 points gave ~1e-5 per shift, ~1e-3 after a march).
const SHIFT_POINTS: usize = 8;

/// Shifts the grid content by δ (the wall moved from −σ_a to −(σ_a + δ)): p_new(x) = p(x − δ).
fn shift(p: &mut Vec<f64>, h: f64, delta: f64) {
    if delta == 0.0 {
        return;
    }
    let n = p.len() - 1;
    // grow the grid so nothing falls off the far end
    let extra = if delta > 0.0 {
        (delta / h).ceil() as usize + 2
    } else {
        0
    };
    let old = p.clone();
    let val = |i: isize| -> f64 {
        if i < 0 {
            let k = (-i) as usize;
            if k <= n {
                -old[k]
            } else {
                0.0
            }
        } else if (i as usize) <= n {
            old[i as usize]
        } else {
            0.0
        }
    };
    let new_n = n + extra;
    p.clear();
    p.resize(new_n + 1, 0.0);
    // every node shifts by the same fraction of a cell: one set of Lagrange weights
    let shift_cells = delta / h;
    let frac = (-shift_cells) - (-shift_cells).floor();
    let base = (-shift_cells).floor() as isize;
    let half = SHIFT_POINTS as isize / 2;
    let mut w = [0.0f64; SHIFT_POINTS];
    for (l, wl) in w.iter_mut().enumerate() {
        let ol = l as f64 - (half - 1) as f64;
        let mut prod = 1.0;
        for jj in 0..SHIFT_POINTS {
            if jj != l {
                let oj = jj as f64 - (half - 1) as f64;
                prod *= (frac - oj) / (ol - oj);
            }
        }
        *wl = prod;
    }
    for (j, pj) in p.iter_mut().enumerate().take(new_n).skip(1) {
        let t = j as f64 - shift_cells;
        if t <= 0.0 {
            continue; // below the old wall: no mass
        }
        let i = j as isize + base;
        let mut acc = 0.0;
        for (l, wl) in w.iter().enumerate() {
            acc += wl * val(i + l as isize - (half - 1));
        }
        *pj = acc;
    }
    p[0] = 0.0;
    p[new_n] = 0.0;
}

struct Marcher<'a> {
    scene: &'a Scene,
    grid: &'a Grid,
    acc: AdhesionAccuracy,
    heat: Heat,
    /// Test hook: start the grid at this step even if the wall has not moved.
    force_grid_from: Option<usize>,
}

impl<'a> Marcher<'a> {
    /// Marches the distribution through the steps with the given wall positions (σ_a* at each
    /// step's midpoint), returning a_r at the nodes and the final state.
    fn march(&mut self, walls: &[f64]) -> March {
        let p0 = self.scene.pressure;
        let model = self.scene.model;
        let ppw = self.acc.points_per_width;
        let k_steps = self.grid.steps.len();
        let mut a_nodes = Vec::with_capacity(k_steps + 1);
        a_nodes.push(1.0);
        let mut v_nodes = Vec::with_capacity(k_steps + 1);
        v_nodes.push(0.0);
        let mut v = 0.0f64;
        let mut wall = walls.first().copied().unwrap_or(0.0);
        let mut state = State::Analytic;
        let mut b_cum = 0.0;
        for (k, st) in self.grid.steps.iter().enumerate() {
            if k > 0 {
                b_cum += self.grid.steps[k - 1].b;
            }
            let s_k = walls[k];
            let forced = self.force_grid_from == Some(k) && v > 0.0;
            if let State::Analytic = state {
                if s_k != wall || forced {
                    let d_min = p0 + wall.min(s_k);
                    let v_next = v + st.b;
                    let far = d_min > 8.5 * v_next.sqrt();
                    if (far || v == 0.0) && self.force_grid_from.is_none_or(|f| k < f) {
                        // the image is negligible before and after (or nothing has diffused
                        // yet: still δ(σ − p*)): the wall may move freely
                        wall = s_k;
                    } else {
                        // switch to the grid, starting from the mirror Gaussian about `wall`
                        let h = v.sqrt() / ppw;
                        let d = p0 + wall;
                        let x_max = d + 10.0 * v.sqrt();
                        let n = (x_max / h).ceil() as usize + 1;
                        let p: Vec<f64> = (0..=n)
                            .map(|j| {
                                if j == 0 || j == n {
                                    0.0
                                } else {
                                    let x = j as f64 * h;
                                    gauss(x - d, v) - gauss(x + d, v)
                                }
                            })
                            .collect();
                        state = State::Grid { h, p };
                    }
                }
            }
            match &mut state {
                State::Analytic => {
                    // RK4 in B for dv/dB = W^{2α}(a(v)), a(v) = erf((p + σ_a)/√(2v))
                    let d = p0 + wall;
                    let rate_at = |v0: f64| move |u: f64| model.broadening(mirror_area(d, v0 + u));
                    v += variance_step(&rate_at(v), b_cum, st.b);
                    a_nodes.push(mirror_area(d, v));
                    v_nodes.push(v);
                }
                State::Grid { h, p } => {
                    let delta = s_k - wall;
                    if delta != 0.0 {
                        shift(p, *h, delta);
                        wall = s_k;
                    }
                    // extend the grid so that it reaches p + σ_a + 10√v after this step
                    let need = p0 + wall + 10.0 * (v + st.b).sqrt();
                    let n_need = (need / *h).ceil() as usize + 1;
                    if p.len() - 1 < n_need {
                        p.resize(n_need + 1, 0.0);
                    }
                    // the same RK4 rule in B as the analytic stage, with a(v) from the loaded
                    // sine coefficients: the switch between the stages is continuous
                    self.heat.load(p, *h);
                    let heat = &self.heat;
                    let rate = |u: f64| model.broadening(heat.mass(u).clamp(0.0, 1.0));
                    let dv = variance_step(&rate, b_cum, st.b);
                    let a = heat.mass(dv).clamp(0.0, 1.0);
                    self.heat.finish(p, dv);
                    v += dv;
                    a_nodes.push(a);
                    v_nodes.push(v);
                    // coarsen: keep every other node
                    if v.sqrt() > 2.0 * ppw * *h {
                        if (p.len() - 1) % 2 == 1 {
                            p.push(0.0);
                        }
                        let coarse: Vec<f64> = p.iter().step_by(2).copied().collect();
                        *p = coarse;
                        *h *= 2.0;
                    }
                }
            }
        }
        March {
            a_nodes,
            v_nodes,
            v,
            wall,
            state,
        }
    }
}

/// γ(q) and σ_a*(q): at the step midpoints (walls) and at the nodes, for a_r at the nodes.
struct Walls {
    mid: Vec<f64>,
    gamma_nodes: Vec<f64>,
    sigma_nodes: Vec<f64>,
    /// Σ a W e over all steps (J/m²).
    energy: f64,
}

fn walls_for(scene: &Scene, grid: &Grid, a: &[f64]) -> Walls {
    let k = grid.steps.len();
    let model = scene.model;
    let gs = scene.gamma;
    let unit = scene.stress_unit();
    let t = scene.thickness_m();
    let cap = if model.cap { gs / scene.range } else { f64::INFINITY };
    // E at nodes, from the top
    let mut e_node = vec![0.0; k + 1];
    for j in (0..k).rev() {
        let am = 0.5 * (a[j] + a[j + 1]);
        e_node[j] = e_node[j + 1] + am * model.w(am) * grid.steps[j].e;
    }
    let top = a[k] * gs;
    let sigma_of = |q: f64, gamma: f64| -> f64 {
        if gamma <= 0.0 {
            return 0.0;
        }
        let s = model.k_griffith * (q * scene.modulus * slab_factor_at(q, t) * gamma).sqrt();
        s.min(cap) / unit
    };
    let gamma_of = |e: f64, am: f64| -> f64 {
        if am <= 0.0 {
            0.0
        } else {
            ((top - e) / am).max(0.0)
        }
    };
    // the wall of each step is its mean over the step: σ_a ∝ √γ rises like a square root
    // where γ(q) turns positive, and a midpoint sample would make the wall (and the fixed-point
    // map) jump each time that onset crosses a midpoint; with γ linear between the nodes the
    // mean of √γ₊ is exact and the onset enters as γ^{3/2}, smoothly
    let gamma_raw = |j: usize| -> f64 {
        if a[j] <= 0.0 {
            -1.0
        } else {
            (top - e_node[j]) / a[j]
        }
    };
    let mut mid = Vec::with_capacity(k);
    for j in 0..k {
        let q = grid.steps[j].q_mid;
        let ms = mean_sqrt_positive(gamma_raw(j), gamma_raw(j + 1));
        let s = model.k_griffith * (q * scene.modulus * slab_factor_at(q, t)).sqrt() * ms;
        mid.push(s.min(cap) / unit);
    }
    let gamma_nodes: Vec<f64> = (0..=k).map(|j| gamma_of(e_node[j], a[j])).collect();
    let sigma_nodes = (0..=k).map(|j| sigma_of(grid.q[j], gamma_nodes[j])).collect();
    Walls {
        mid,
        gamma_nodes: gamma_nodes
            .iter()
            .map(|g| if gs > 0.0 { g / gs } else { 0.0 })
            .collect(),
        sigma_nodes,
        energy: e_node[0],
    }
}

/// The mean over s ∈ [0, 1] of √max(0, g₀ + (g₁ − g₀)s).
fn mean_sqrt_positive(g0: f64, g1: f64) -> f64 {
    let (lo, hi) = (g0.min(g1), g0.max(g1));
    if hi <= 0.0 {
        return 0.0;
    }
    if hi - lo <= 1e-12 * hi {
        return (0.5 * (lo + hi)).max(0.0).sqrt();
    }
    let lo_part = if lo > 0.0 { lo * lo.sqrt() } else { 0.0 };
    2.0 / 3.0 * (hi * hi.sqrt() - lo_part) / (hi - lo)
}

/// Anderson mixing (type II, Walker & Ni 2011) for y = G(y) in y = ln a ∈ [−690, 0]^n.
struct Anderson {
    depth: usize,
    beta: f64,
    dx: Vec<Vec<f64>>,
    dr: Vec<Vec<f64>>,
    last: Option<(Vec<f64>, Vec<f64>)>,
}

impl Anderson {
    fn new(depth: usize, beta: f64) -> Self {
        Anderson {
            depth,
            beta,
            dx: Vec::new(),
            dr: Vec::new(),
            last: None,
        }
    }

    fn next(&mut self, x: &[f64], r: &[f64]) -> Vec<f64> {
        if let Some((xl, rl)) = self.last.take() {
            self.dx.push(x.iter().zip(&xl).map(|(a, b)| a - b).collect());
            self.dr.push(r.iter().zip(&rl).map(|(a, b)| a - b).collect());
            if self.dx.len() > self.depth {
                self.dx.remove(0);
                self.dr.remove(0);
            }
        }
        self.last = Some((x.to_vec(), r.to_vec()));
        let m = self.dr.len();
        let mut out: Vec<f64> = x.iter().zip(r).map(|(a, b)| a + self.beta * b).collect();
        if m > 0 {
            // least squares min |r − ΔR γ|: normal equations with Tikhonov regularisation
            let mut a = vec![vec![0.0; m]; m];
            let mut rhs = vec![0.0; m];
            for i in 0..m {
                for j in 0..m {
                    a[i][j] = dot(&self.dr[i], &self.dr[j]);
                }
                rhs[i] = dot(&self.dr[i], r);
            }
            let scale = (0..m).map(|i| a[i][i]).fold(0.0, f64::max);
            for (i, row) in a.iter_mut().enumerate() {
                row[i] += 1e-12 * scale + 1e-300;
            }
            if let Some(g) = solve_small(a, rhs) {
                for i in 0..m {
                    for (o, (dxi, dri)) in out.iter_mut().zip(self.dx[i].iter().zip(&self.dr[i])) {
                        *o -= g[i] * (dxi + self.beta * dri);
                    }
                }
            }
        }
        for o in &mut out {
            *o = o.clamp(-690.0, 0.0);
        }
        out
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Gaussian elimination with partial pivoting (m ≤ 8).
fn solve_small(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
    let m = b.len();
    for c in 0..m {
        let piv = (c..m).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))?;
        if a[piv][c].abs() < 1e-300 || !a[piv][c].is_finite() {
            return None;
        }
        a.swap(c, piv);
        b.swap(c, piv);
        for r in c + 1..m {
            let f = a[r][c] / a[c][c];
            for cc in c..m {
                a[r][cc] -= f * a[c][cc];
            }
            b[r] -= f * b[c];
        }
    }
    let mut x = vec![0.0; m];
    for r in (0..m).rev() {
        let s: f64 = (r + 1..m).map(|c| a[r][c] * x[c]).sum();
        x[r] = (b[r] - s) / a[r][r];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Iterations without the residual halving after which an Anderson attempt gives up.
const STAGNATION: usize = 40;

/// Outcome of one fixed-point attempt.
struct Attempt {
    x: Vec<f64>,
    residual: f64,
    iterations: usize,
    converged: bool,
}

fn residual_of(x: &[f64], gx: &[f64]) -> f64 {
    let scale = x
        .last()
        .copied()
        .unwrap_or(1.0)
        .max(gx.last().copied().unwrap_or(1.0))
        .max(1e-300);
    x.iter().zip(gx).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) / scale
}

fn check_cancel(cancel: Option<&AtomicBool>) -> Result<()> {
    if cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
        Err(Error::Cancelled)
    } else {
        Ok(())
    }
}

impl<'a> Marcher<'a> {
    fn map(&mut self, scene: &Scene, x: &[f64]) -> Vec<f64> {
        let w = walls_for(scene, self.grid, x);
        self.march(&w.mid).a_nodes
    }

    /// Safeguarded Anderson mixing in y = ln a (positivity for free); restarts from the best
    /// iterate with half the mixing when the residual grows tenfold.
    fn fixed_point(
        &mut self,
        scene: &Scene,
        start: Vec<f64>,
        beta: f64,
        cancel: Option<&AtomicBool>,
    ) -> Result<Attempt> {
        let to_y = |a: &[f64]| -> Vec<f64> { a.iter().map(|v| v.max(1e-300).ln()).collect() };
        let mut y = to_y(&start);
        let mut beta = beta;
        let mut anderson = Anderson::new(6, beta);
        let mut best: (f64, Vec<f64>, Vec<f64>) = (f64::INFINITY, start.clone(), start);
        let debug = std::env::var_os("ASPERITY_DEBUG").is_some();
        let mut restarts = 0;
        let mut used = 0;
        let mut best_it = 0;
        for it in 1..=self.acc.max_iterations {
            used = it;
            check_cancel(cancel)?;
            let x: Vec<f64> = y.iter().map(|v| v.exp()).collect();
            let gx = self.map(scene, &x);
            let res = residual_of(&x, &gx);
            if debug {
                eprintln!(
                    "it {it} beta {beta} res {res:.3e} a_end {:.6} -> {:.6}",
                    x[x.len() - 1],
                    gx[gx.len() - 1]
                );
            }
            if res <= self.acc.tol {
                return Ok(Attempt {
                    x: gx,
                    residual: res,
                    iterations: it,
                    converged: true,
                });
            }
            if res < best.0 {
                if res < 0.5 * best.0 {
                    best_it = it;
                }
                best = (res, x.clone(), gx.clone());
            } else if !self.acc.thorough && it >= 60 && best.0 > 0.05 {
                // a sweep's quick attempt: 60 iterations without getting near a solution
                break;
            } else if best.0 < 0.05 && it > best_it + STAGNATION {
                // close to a solution, but no halving of the residual for STAGNATION
                // iterations (the wide search before that is left alone)
                break;
            } else if !res.is_finite() || res > 10.0 * best.0 {
                restarts += 1;
                if restarts > 6 {
                    break;
                }
                // the extrapolation went astray: restart from the best iterate, damped
                beta = (beta * 0.5).max(0.05);
                anderson = Anderson::new(6, beta);
                let gy = to_y(&best.2);
                let by = to_y(&best.1);
                y = by.iter().zip(&gy).map(|(b, g)| b + beta * (g - b)).collect();
                continue;
            }
            let gy = to_y(&gx);
            let r: Vec<f64> = gy.iter().zip(&y).map(|(a, b)| a - b).collect();
            y = anderson.next(&y, &r);
        }
        Ok(Attempt {
            x: best.2,
            residual: best.0,
            iterations: used,
            converged: false,
        })
    }
}

impl<'a> Marcher<'a> {
    /// A start for the fixed point where plain iteration falls into a two-state cycle (the map
    /// overshoots: more contact at fine scales means more elastic energy, less γ, less
    /// contact). A few plain iterations from `start` give the two states A and B of the cycle;
    /// on the path x(λ) = A^{1−λ}B^λ the end-node residual ln G(x)_K − ln x_K changes sign, and
    /// bisection finds where it vanishes: close to the fixed point in the unstable direction.
    /// None when no sign change brackets it.
    fn cycle_bisection(
        &mut self,
        scene: &Scene,
        start: &[f64],
        cancel: Option<&AtomicBool>,
    ) -> Result<Option<Vec<f64>>> {
        let k = start.len() - 1;
        let mut x = start.to_vec();
        for _ in 0..6 {
            check_cancel(cancel)?;
            x = self.map(scene, &x);
        }
        let a = x;
        let b = self.map(scene, &a);
        let mix = |l: f64| -> Vec<f64> {
            a.iter()
                .zip(&b)
                .map(|(u, v)| ((1.0 - l) * u.max(1e-300).ln() + l * v.max(1e-300).ln()).exp())
                .collect()
        };
        let side = |m: &mut Self, l: f64| -> f64 {
            let x = mix(l);
            let g = m.map(scene, &x);
            g[k].max(1e-300).ln() - x[k].max(1e-300).ln()
        };
        let (mut lo, mut hi) = (0.0, 1.0);
        let s_lo = side(self, lo);
        let s_hi = side(self, hi);
        if !(s_lo.is_finite() && s_hi.is_finite()) || (s_lo > 0.0) == (s_hi > 0.0) {
            return Ok(None);
        }
        for _ in 0..40 {
            check_cancel(cancel)?;
            let mid = 0.5 * (lo + hi);
            if (side(self, mid) > 0.0) == (s_lo > 0.0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Ok(Some(mix(0.5 * (lo + hi))))
    }
}

/// Solves the adhesive theory for a scene with γ_s > 0 (see the module docs). `warm` is a
/// previous solution of a nearby scene (a_r at the nodes), used as the start when its grid
/// matches. `cancel` aborts between iterations.
pub fn solve(
    scene: &Scene,
    acc: &AdhesionAccuracy,
    warm: Option<&AdhesiveSolution>,
    cancel: Option<&AtomicBool>,
) -> Result<AdhesiveSolution> {
    scene.validate()?;
    for (name, v, lo, hi) in [
        (Field::AdhesionSteps, acc.steps_per_ln_q, 2.0, 1e4),
        (Field::AdhesionPoints, acc.points_per_width, 2.0, 1e3),
        (Field::AdhesionTol, acc.tol, 1e-15, 1e-1),
    ] {
        if !(v >= lo && v <= hi) {
            return Err(Error::invalid(name, v, format!("{lo} <= value <= {hi}")));
        }
    }
    // Near a jump into contact the discrete map can stagnate for one particular resolution
    // (measured: system 2, t·q_r = 0.15, a few loads, residual ~1e-4) while slightly different
    // resolutions converge to the same a_r within the discretisation error. So: Anderson at the
    // requested resolution, then at two nearby ones, and only then the slow fallbacks (damped
    // mixing, continuation in γ) at the requested one.
    let variants: &[(f64, f64)] = if acc.thorough {
        &[(1.0, 1.0), (1.25, 1.0), (0.8, 1.2)]
    } else {
        &[(1.0, 1.0)]
    };
    let mut first_err = None;
    for (i, &(fs, fp)) in variants.iter().enumerate() {
        let a = AdhesionAccuracy {
            steps_per_ln_q: acc.steps_per_ln_q * fs,
            points_per_width: acc.points_per_width * fp,
            ..*acc
        };
        match solve_at(scene, &a, warm, cancel, false) {
            Ok(mut sol) => {
                if i > 0 {
                    sol.resolution_used = Some((a.steps_per_ln_q, a.points_per_width));
                }
                return Ok(sol);
            }
            Err(Error::NotConverged { solver, reason }) => {
                first_err.get_or_insert(Error::NotConverged { solver, reason });
            }
            Err(e) => return Err(e),
        }
    }
    match solve_at(scene, acc, warm, cancel, true) {
        Ok(sol) => Ok(sol),
        Err(Error::NotConverged { .. }) => Err(first_err.unwrap_or(Error::NotConverged {
            solver: "adhesive fixed point".into(),
            reason: "no attempt converged".into(),
        })),
        Err(e) => Err(e),
    }
}

fn solve_at(
    scene: &Scene,
    acc: &AdhesionAccuracy,
    warm: Option<&AdhesiveSolution>,
    cancel: Option<&AtomicBool>,
    fallbacks: bool,
) -> Result<AdhesiveSolution> {
    let grid = build_grid(scene, acc.steps_per_ln_q);
    let k = grid.steps.len();
    let mut m = Marcher {
        scene,
        grid: &grid,
        acc: *acc,
        heat: Heat::new(),
        force_grid_from: None,
    };
    // the adhesionless march (σ_a ≡ 0) is the loading branch's start
    let zero = vec![0.0; k];
    let adhesionless = m.march(&zero).a_nodes;
    let start = match warm {
        Some(w) if w.a_q.len() == k + 1 && w.q.first() == grid.q.first() && w.q.last() == grid.q.last() => {
            w.a_q.clone()
        }
        _ => adhesionless.clone(),
    };
    let mut iterations = 0;
    let mut branch = "loading".to_string();
    let mut att = m.fixed_point(scene, start, 1.0, cancel)?;
    iterations += att.iterations;
    if !att.converged && fallbacks {
        // a two-state cycle: bisect between its states for a start near the fixed point
        if let Some(x0) = m.cycle_bisection(scene, &adhesionless, cancel)? {
            iterations += 48;
            let betas: &[f64] = if acc.thorough { &[0.2, 0.1, 1.0] } else { &[0.2] };
            for &beta in betas {
                let c = m.fixed_point(scene, x0.clone(), beta, cancel)?;
                iterations += c.iterations;
                if c.converged {
                    att = c;
                    break;
                }
            }
        }
    }
    if !att.converged && fallbacks {
        // from full contact: where the adhesionless-connected state has no fixed point the
        // iteration from below wanders (the contact jumps in); the state above is found from
        // a ≡ 1 and reported as the upper branch
        let up = m.fixed_point(scene, vec![1.0; k + 1], 1.0, cancel)?;
        iterations += up.iterations;
        if up.converged {
            att = up;
            branch = "upper (from full contact)".into();
        }
    }
    if !att.converged && fallbacks && acc.thorough {
        // damped restart from the adhesionless start
        let a2 = m.fixed_point(scene, adhesionless.clone(), 0.3, cancel)?;
        iterations += a2.iterations;
        if a2.converged || a2.residual < att.residual {
            att = a2;
        }
    }
    if !att.converged && fallbacks && acc.thorough {
        // continuation in γ_s from 0, each stage warm-started
        let mut x = adhesionless.clone();
        let mut s = scene.clone();
        let mut ok = true;
        for stage in 1..=8 {
            s.gamma = scene.gamma * stage as f64 / 8.0;
            let a3 = m.fixed_point(&s, x.clone(), 0.5, cancel)?;
            iterations += a3.iterations;
            if !a3.converged {
                ok = false;
                break;
            }
            x = a3.x;
        }
        if ok {
            let a4 = m.fixed_point(scene, x, 0.5, cancel)?;
            iterations += a4.iterations;
            if a4.converged {
                att = a4;
                branch = "loading (continuation in gamma)".into();
            }
        }
    }
    if !att.converged {
        return Err(Error::NotConverged {
            solver: "adhesive fixed point".into(),
            reason: format!(
                "residual {:.2e} > tol {:.0e} after {iterations} map evaluations (Anderson at three \
                 nearby resolutions, damped restart and continuation in gamma): the loading branch may not \
                 exist at this load, or it oscillates between states; try a nearby p*, t or gamma",
                att.residual, acc.tol
            ),
        });
    }
    let mut unloading_a_r = None;
    if acc.explore_branches {
        let full = vec![1.0; k + 1];
        let up = m.fixed_point(scene, full, 1.0, cancel)?;
        iterations += up.iterations;
        if up.converged {
            let (a_up, a_lo) = (up.x[k], att.x[k]);
            if (a_up - a_lo).abs() > 1e-3 * a_lo.max(1e-12) + 100.0 * acc.tol * a_lo {
                unloading_a_r = Some(a_up);
            }
        }
    }
    let x = att.x;
    let w = walls_for(scene, &grid, &x);
    let fin = m.march(&w.mid);
    // the final state with the wall at σ_a(q_s)
    let s_end = *w.sigma_nodes.last().unwrap_or(&0.0);
    let p0 = scene.pressure;
    let fin_v = fin.v;
    let (sigma, density, wall_end) = match &fin.state {
        State::Analytic => {
            // mirror Gaussian about −wall: sample it
            let wall = fin.wall;
            let sd = fin.v.sqrt();
            let lo = -wall;
            let hi = p0 + 8.0 * sd.max(1e-300);
            let n = 801;
            let sig: Vec<f64> = (0..n).map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64).collect();
            let d = p0 + wall;
            let dens = sig
                .iter()
                .map(|&s| {
                    let x = s + wall;
                    if x <= 0.0 || fin.v <= 0.0 {
                        0.0
                    } else {
                        gauss(x - d, fin.v) - gauss(x + d, fin.v)
                    }
                })
                .collect();
            (sig, dens, wall)
        }
        State::Grid { h, p } => {
            let (h, mut p) = (*h, p.clone());
            shift(&mut p, h, s_end - fin.wall);
            let sig = (0..p.len()).map(|j| j as f64 * h - s_end).collect();
            (sig, p, s_end)
        }
    };
    let (_, mean, var, tensile) = match fin.state_moments(&sigma, &density, p0, fin_v, wall_end) {
        Some(t) => t,
        None => {
            return Err(Error::NotConverged {
                solver: "adhesive propagation".into(),
                reason: "the stress distribution vanished".into(),
            })
        }
    };
    // a_r from the march (spectral mass); the sampled moments carry the trapezoid error
    let a_final = *fin.a_nodes.last().unwrap_or(&0.0);
    let energy = w.energy - a_final * scene.gamma;
    let u_f = scene.full_contact_energy();
    Ok(AdhesiveSolution {
        pressure: p0,
        a_r: a_final,
        mean_contact_stress: mean,
        contact_stress_variance: var,
        width: fin_v.sqrt(),
        sigma_a: wall_end,
        tensile_area: tensile,
        detached_fraction: 1.0 - a_final,
        q: grid.q.clone(),
        v_q: fin.v_nodes,
        a_q: x,
        gamma_q: w.gamma_nodes,
        sigma_a_q: w.sigma_nodes,
        sigma,
        density,
        iterations,
        residual: att.residual,
        branch,
        unloading_a_r,
        elastic_energy: energy,
        gamma_glo: if u_f > 0.0 { scene.gamma / u_f } else { 0.0 },
        resolution_used: None,
    })
}

impl March {
    /// (a_r, σ̄_c*, variance, tensile area) of the final distribution.
    fn state_moments(
        &self,
        sigma: &[f64],
        density: &[f64],
        p0: f64,
        v: f64,
        wall: f64,
    ) -> Option<(f64, f64, f64, f64)> {
        if let State::Analytic = self.state {
            // closed forms of the mirror Gaussian about −wall (shift σ' = σ + wall)
            let d = p0 + wall;
            let sd = v.sqrt();
            let a = crate::theory::mirror::area(d, sd);
            if a <= 0.0 {
                return None;
            }
            let (m1, var) = crate::theory::mirror::contact_moments(d, sd);
            // tensile part: ∫_0^{wall} of the mirror density in σ'
            let tens = if wall > 0.0 && sd > 0.0 {
                let c = |x: f64| 0.5 * (erf((x - d) / (sd * 2f64.sqrt())) - erf((x + d) / (sd * 2f64.sqrt())));
                (c(wall) - c(0.0)).max(0.0)
            } else {
                0.0
            };
            return Some((a, m1 - wall, var, tens));
        }
        let h = sigma.get(1).map(|s1| s1 - sigma[0]).unwrap_or(0.0);
        // trapezoid with the Euler–Maclaurin end correction at the wall (f(0) = 0, f'(0) ≠ 0;
        // f'(0) from a one-sided 3-point difference): O(h³) instead of O(h²)
        let integrate = |f: &dyn Fn(usize) -> f64| -> f64 {
            let n = density.len();
            let sum: f64 = (0..n).map(f).sum::<f64>() * h;
            if n < 3 {
                return sum;
            }
            let d0 = (-3.0 * f(0) + 4.0 * f(1) - f(2)) / (2.0 * h);
            sum + h * h / 12.0 * d0
        };
        let m0 = integrate(&|j| density[j]);
        if m0.is_nan() || m0 <= 0.0 {
            return None;
        }
        let m1 = integrate(&|j| sigma[j] * density[j]) / m0;
        let m2 = integrate(&|j| (sigma[j] - m1) * (sigma[j] - m1) * density[j]) / m0;
        let tens: f64 = sigma
            .iter()
            .zip(density)
            .filter(|(s, _)| **s < 0.0)
            .map(|(_, p)| p)
            .sum::<f64>()
            * h;
        Some((m0, m1, m2.max(0.0), tens))
    }
}

/// Propagates Pr through the scene's resolution with a prescribed wall σ_a*(q) (reduced,
/// evaluated at each step's midpoint q) and no self-consistency: the propagator alone, for
/// tests against the exact cases. `grid_from_start` forces the grid from the first step on
/// (otherwise a wall that never moves is handled by the mirror Gaussian). Returns the nodes
/// q and a_r(q).
pub fn propagate_with_wall(
    scene: &Scene,
    acc: &AdhesionAccuracy,
    wall: impl Fn(f64) -> f64,
    grid_from_start: bool,
) -> Result<(Vec<f64>, Vec<f64>)> {
    scene.validate()?;
    let grid = build_grid(scene, acc.steps_per_ln_q);
    let walls: Vec<f64> = grid.steps.iter().map(|s| wall(s.q_mid)).collect();
    let mut m = Marcher {
        scene,
        grid: &grid,
        acc: *acc,
        heat: Heat::new(),
        force_grid_from: grid_from_start.then_some(1),
    };
    let out = m.march(&walls);
    Ok((grid.q.clone(), out.a_nodes))
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
    let (q0, q1) = (sol.q[i - 1], sol.q[i]);
    if q1 <= q0 {
        return values[i];
    }
    let t = (q.ln() - q0.ln()) / (q1.ln() - q0.ln());
    values[i - 1] + t * (values[i] - values[i - 1])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn heat_matches_mirror_gaussian() {
        // a mirror Gaussian of variance v0 evolved by dv is the mirror Gaussian of v0 + dv
        let (d, v0, dv): (f64, f64, f64) = (0.3, 0.01, 0.02);
        let h = 0.1f64.sqrt() / 20.0;
        let n = ((d + 12.0 * (v0 + dv).sqrt()) / h).ceil() as usize;
        let mut p: Vec<f64> = (0..=n)
            .map(|j| {
                let x = j as f64 * h;
                if j == 0 || j == n {
                    0.0
                } else {
                    gauss(x - d, v0) - gauss(x + d, v0)
                }
            })
            .collect();
        let mass = Heat::new().apply(&mut p, h, dv);
        let v = v0 + dv;
        assert!((mass - erf(d / (2.0 * v).sqrt())).abs() < 1e-10, "{mass}");
        for (j, pj) in p.iter().enumerate() {
            let x = j as f64 * h;
            let exact = gauss(x - d, v) - gauss(x + d, v);
            assert!((pj - exact).abs() < 1e-12, "{j}: {pj} vs {exact}");
        }
    }

    #[test]
    fn shift_is_exact_for_cubics_away_from_the_wall() {
        let h = 0.1;
        let mut p: Vec<f64> = (0..=40).map(|j| (j as f64 * h).powi(3) - (j as f64 * h)).collect();
        p[0] = 0.0;
        let last = p.len() - 1;
        p[last] = 0.0;
        let orig = p.clone();
        shift(&mut p, h, 0.037);
        for j in 3..35 {
            let x = j as f64 * h - 0.037;
            let want = x.powi(3) - x;
            assert!((p[j] - want).abs() < 1e-12, "{j}: {} vs {want}", p[j]);
        }
        let _ = orig;
    }

    #[test]
    fn anderson_solves_a_linear_contraction() {
        // x = 0.5 x + c (componentwise, with coupling): fixed point in a few iterations
        let c = [-0.1, -0.2, -0.3]; // ln a < 0
        let g = |x: &[f64]| vec![0.5 * x[1] + c[0], 0.5 * x[2] + c[1], 0.5 * x[0] + c[2]];
        let mut and = Anderson::new(6, 1.0);
        let mut x = vec![0.0; 3];
        for _ in 0..20 {
            let gx = g(&x);
            let r: Vec<f64> = gx.iter().zip(&x).map(|(a, b)| a - b).collect();
            if r.iter().all(|v| v.abs() < 1e-14) {
                break;
            }
            x = and.next(&x, &r);
        }
        let gx = g(&x);
        for i in 0..3 {
            assert!((gx[i] - x[i]).abs() < 1e-12);
        }
    }
}
