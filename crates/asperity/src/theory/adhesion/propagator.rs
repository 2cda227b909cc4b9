//! The moving-wall propagator: one march of Pr(σ, q) through the resolution steps for given
//! wall positions σ_a*(q) [S-5, S-7], returning a_r at the nodes [S-6].
//!
//! In the wall's frame x = σ + σ_a each step (1) shifts Pr by the wall's move (8-point
//! Lagrange, odd continuation through the wall, mass below it removed) and (2) applies the
//! exact Dirichlet heat semigroup over the step's variance Δv (sine series by a length-2N FFT
//! of the odd extension; a_r is the spectral integral of the series). Δv = W^{2α}(a)·b by RK4
//! in the variance measure B. While the wall has not moved (or is > 8.5√v away) the state is
//! the mirror Gaussian about the wall and no grid is used. See the parent module for the
//! order of the splitting.

// index loops mirror the formulas (nodes j, steps k) in this numerical module
#![allow(clippy::needless_range_loop)]

use super::grid::Grid;
use super::AdhesionAccuracy;
use crate::input::scene::Scene;
use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use statrs::function::erf::erf;
use std::f64::consts::{FRAC_1_SQRT_2, PI};
use std::sync::Arc;

/// Forward and inverse FFTs of one length.
type Plan = (usize, Arc<dyn Fft<f64>>, Arc<dyn Fft<f64>>);

/// Sine-transform heat propagator on [0, X] with Dirichlet ends, for a grid of N intervals.
pub(super) struct Heat {
    planner: FftPlanner<f64>,
    plan: Option<Plan>,
    buf: Vec<Complex64>,
    scratch: Vec<Complex64>,
    /// Coefficient of the mass integral per odd sine mode k = 1, 3, 5, …
    terms: Vec<f64>,
    /// Decay rate of mode 1, ½(π/X)²: mode k decays at k² times it.
    rate1: f64,
    n: usize,
    x: f64,
}

impl Heat {
    pub(super) fn new() -> Self {
        Heat {
            planner: FftPlanner::new(),
            plan: None,
            buf: Vec::new(),
            scratch: Vec::new(),
            terms: Vec::new(),
            rate1: 0.0,
            n: 0,
            x: 0.0,
        }
    }

    /// Loads grid values p at x_j = j·h, j = 0..=N (p[0] = p[N] = 0): one forward transform
    /// of the odd extension. Afterwards [`Heat::mass`] gives ∫_0^X p dx after any extra
    /// variance dv in O(N), and [`Heat::finish`] writes the evolved values back.
    pub(super) fn load(&mut self, p: &[f64], h: f64) {
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
            self.terms.push(b * 2.0 * x / (k as f64 * PI));
        }
        self.rate1 = 0.5 * (PI / x) * (PI / x);
    }

    /// ∫_0^X p dx after a further variance dv (exact for the loaded trigonometric interpolant).
    /// exp(−r₁k²dv) by recurrence: with E = exp(−r₁dv), E^{(k+2)²} = E^{k²}·E^{4k+4} and
    /// E^{4k+4} grows by E⁸ per mode — one exp per call instead of one per mode.
    pub(super) fn mass(&self, dv: f64) -> f64 {
        let e = (-self.rate1 * dv).exp();
        let e2 = e * e;
        let e4 = e2 * e2;
        let e8 = e4 * e4;
        let (mut pow, mut ratio, mut sum) = (e, e8, 0.0);
        for &c in &self.terms {
            sum += c * pow;
            pow *= ratio;
            ratio *= e8;
            if pow < 1e-300 {
                break;
            }
        }
        sum
    }

    /// Writes the loaded values evolved by dv back into p.
    pub(super) fn finish(&mut self, p: &mut [f64], dv: f64) {
        let (n, x) = (self.n, self.x);
        let m = 2 * n;
        let (_, _, inv) = self.plan.as_ref().expect("loaded");
        // exp(−c k²)/m by the same recurrence as `mass`, applied to modes k and m − k
        let e = (-0.5 * dv * (PI / x) * (PI / x)).exp();
        let e2 = e * e;
        let (mut pow, mut ratio) = (1.0 / m as f64, e);
        for k in 0..=n {
            if pow < 1e-300 {
                pow = 0.0; // and stays 0: no denormal arithmetic
            }
            self.buf[k] *= pow;
            if k > 0 && k < n {
                self.buf[m - k] *= pow;
            }
            if pow > 0.0 {
                pow *= ratio;
                ratio *= e2;
            }
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
    pub(super) fn apply(&mut self, p: &mut [f64], h: f64, dv: f64) -> f64 {
        self.load(p, h);
        let mass = self.mass(dv);
        self.finish(p, dv);
        mass
    }
}

/// The state of the march.
#[derive(Clone)]
pub(super) enum State {
    /// Mirror Gaussian about the wall (x = σ + wall ≥ 0), variance v.
    Analytic,
    /// Grid values at x_j = j h.
    Grid { h: f64, p: Vec<f64> },
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

/// Whether n has no prime factor above 5.
fn is_smooth(mut n: usize) -> bool {
    if n == 0 {
        return false;
    }
    for f in [2, 3, 5] {
        while n.is_multiple_of(f) {
            n /= f;
        }
    }
    n == 1
}

/// The smallest n' ≥ n with no prime factor above 5.
fn smooth_size(n: usize) -> usize {
    (n.max(1)..).find(|&k| is_smooth(k)).unwrap_or(n)
}

/// Mirror-Gaussian contact fraction at distance d from the wall with variance v.
pub(super) fn mirror_area(d: f64, v: f64) -> f64 {
    if d <= 0.0 {
        0.0
    } else if v <= 0.0 {
        1.0
    } else {
        erf(d / v.sqrt() * FRAC_1_SQRT_2)
    }
}

pub(super) fn gauss(x: f64, v: f64) -> f64 {
    (-x * x / (2.0 * v)).exp() / (2.0 * PI * v).sqrt()
}

/// Points of the shift's Lagrange interpolation: the error per shift is O(h⁸ ∂⁸Pr), ~1e-9 of
/// Pr at 10 points per width (4 points gave ~1e-5 per shift, ~1e-3 after a march).
const SHIFT_POINTS: usize = 8;

/// Shifts the grid content by δ (the wall moved from −σ_a to −(σ_a + δ)): p_new(x) = p(x − δ).
pub(super) fn shift(p: &mut Vec<f64>, h: f64, delta: f64) {
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

pub(super) struct Marcher<'a> {
    pub(super) scene: &'a Scene,
    pub(super) grid: &'a Grid,
    pub(super) acc: AdhesionAccuracy,
    pub(super) heat: Heat,
    /// Test hook: start the grid at this step even if the wall has not moved.
    pub(super) force_grid_from: Option<usize>,
    /// p* of the march (the scene's unless a continuation varies it).
    pub(super) pressure: f64,
    /// Trial steps taken by shooting marches (a cost counter).
    pub(super) trials: usize,
}

impl<'a> Marcher<'a> {
    /// A marcher of `scene` on `grid` (no forced grid).
    pub(super) fn new(scene: &'a Scene, grid: &'a Grid, acc: AdhesionAccuracy) -> Self {
        Marcher {
            scene,
            grid,
            acc,
            heat: Heat::new(),
            force_grid_from: None,
            pressure: scene.pressure,
            trials: 0,
        }
    }

    /// Marches the distribution through the steps with the given wall positions (σ_a* at each
    /// step's midpoint), returning a_r at the nodes.
    pub(super) fn march(&mut self, walls: &[f64]) -> Vec<f64> {
        let k_steps = self.grid.steps.len();
        let mut a_nodes = Vec::with_capacity(k_steps + 1);
        a_nodes.push(1.0);
        let mut cur = self.start(walls.first().copied().unwrap_or(0.0));
        for &s_k in walls.iter().take(k_steps) {
            a_nodes.push(self.step(&mut cur, s_k, true));
        }
        a_nodes
    }

    /// The state before the first step (δ(σ − p*), the wall at `first_wall`).
    pub(super) fn start(&self, first_wall: f64) -> Cursor {
        Cursor {
            k: 0,
            v: 0.0,
            wall: first_wall,
            state: State::Analytic,
            b_cum: 0.0,
        }
    }

    /// a_r after step `cur.k` with the wall at `s_k` (σ_a* over the step) — without changing
    /// `cur`: one trial of the step, for a wall that depends on the step's own end (the
    /// shooting march). Costs a shift and a forward transform (no inverse).
    pub(super) fn trial(&mut self, cur: &Cursor, s_k: f64) -> f64 {
        let mut c = cur.clone();
        self.step(&mut c, s_k, false)
    }

    /// Advances `cur` by one step with the wall at `s_k`, returns a_r at the step's end.
    /// `commit` = false skips writing the evolved grid back (only a_r is wanted; `cur` is then
    /// a throw-away copy).
    pub(super) fn step(&mut self, cur: &mut Cursor, s_k: f64, commit: bool) -> f64 {
        let p0 = self.pressure;
        let model = self.scene.model;
        let ppw = self.acc.points_per_width;
        let k = cur.k;
        let st = self.grid.steps[k];
        if k > 0 {
            cur.b_cum += self.grid.steps[k - 1].b;
        }
        cur.k += 1;
        let b_cum = cur.b_cum;
        let v = cur.v;
        let forced = self.force_grid_from == Some(k) && v > 0.0;
        if let State::Analytic = cur.state {
            if s_k != cur.wall || forced {
                let wall = cur.wall;
                let d_min = p0 + wall.min(s_k);
                let v_next = v + st.b;
                let far = d_min > 8.5 * v_next.sqrt();
                if (far || v == 0.0) && self.force_grid_from.is_none_or(|f| k < f) {
                    // the image is negligible before and after (or nothing has diffused
                    // yet: still δ(σ − p*)): the wall may move freely
                    cur.wall = s_k;
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
                    cur.state = State::Grid { h, p };
                }
            }
        }
        match &mut cur.state {
            State::Analytic => {
                // RK4 in B for dv/dB = W^{2α}(a(v)), a(v) = erf((p + σ_a)/√(2v))
                let d = p0 + cur.wall;
                let rate_at = |v0: f64| move |u: f64| model.broadening(mirror_area(d, v0 + u));
                cur.v += variance_step(&rate_at(v), b_cum, st.b);
                mirror_area(d, cur.v)
            }
            State::Grid { h, p } => {
                let delta = s_k - cur.wall;
                if delta != 0.0 {
                    shift(p, *h, delta);
                    cur.wall = s_k;
                }
                // the grid reaches p + σ_a + 10√v after this step (beyond it the density is
                // below e⁻⁵⁰ of its peak): extended with zeros or cut there, to an FFT-friendly
                // size 2^a·3^b·5^c (the sine transform has length 2N, and a prime factor would
                // cost a Rader transform)
                let need = p0 + cur.wall + 10.0 * (v + st.b).sqrt();
                let n = smooth_size((need / *h).ceil() as usize + 1);
                p.resize(n + 1, 0.0);
                p[n] = 0.0;
                // the same RK4 rule in B as the analytic stage, with a(v) from the loaded
                // sine coefficients: the switch between the stages is continuous
                self.heat.load(p, *h);
                let heat = &self.heat;
                let rate = |u: f64| model.broadening(heat.mass(u).clamp(0.0, 1.0));
                let dv = variance_step(&rate, b_cum, st.b);
                let a = heat.mass(dv).clamp(0.0, 1.0);
                cur.v += dv;
                if commit {
                    self.heat.finish(p, dv);
                    // coarsen: keep every other node
                    if cur.v.sqrt() > 2.0 * ppw * *h {
                        if (p.len() - 1) % 2 == 1 {
                            p.push(0.0);
                        }
                        let coarse: Vec<f64> = p.iter().step_by(2).copied().collect();
                        *p = coarse;
                        *h *= 2.0;
                    }
                }
                a
            }
        }
    }
}

/// Where a march stands between steps.
#[derive(Clone)]
pub(super) struct Cursor {
    /// The next step's index.
    pub(super) k: usize,
    /// Accumulated variance.
    pub(super) v: f64,
    /// The wall's current position σ_a*.
    pub(super) wall: f64,
    pub(super) state: State,
    /// Σ b of the steps before the previous one (the RK4 substep rule).
    b_cum: f64,
}

/// (a_r, σ̄_c*, variance, tensile area) of a march's final distribution `state`, sampled
/// as (`sigma`, `density`) with the wall at σ* = −`wall`.
pub(super) fn state_moments(
    state: &State,
    sigma: &[f64],
    density: &[f64],
    p0: f64,
    v: f64,
    wall: f64,
) -> Option<(f64, f64, f64, f64)> {
    if let State::Analytic = state {
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
}
