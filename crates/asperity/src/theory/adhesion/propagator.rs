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
    /// (coefficient, decay rate) of the mass integral per odd sine mode.
    terms: Vec<(f64, f64)>,
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
            let kk = k as f64 * PI / x;
            self.terms.push((b * 2.0 * x / (k as f64 * PI), 0.5 * kk * kk));
        }
    }

    /// ∫_0^X p dx after a further variance dv (exact for the loaded trigonometric interpolant).
    pub(super) fn mass(&self, dv: f64) -> f64 {
        self.terms.iter().map(|&(c, r)| c * (-r * dv).exp()).sum()
    }

    /// Writes the loaded values evolved by dv back into p.
    pub(super) fn finish(&mut self, p: &mut [f64], dv: f64) {
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
    pub(super) fn apply(&mut self, p: &mut [f64], h: f64, dv: f64) -> f64 {
        self.load(p, h);
        let mass = self.mass(dv);
        self.finish(p, dv);
        mass
    }
}

/// The state of the march.
pub(super) enum State {
    /// Mirror Gaussian about the wall (x = σ + wall ≥ 0), variance v.
    Analytic,
    /// Grid values at x_j = j h.
    Grid { h: f64, p: Vec<f64> },
}

/// Result of one march.
pub(super) struct March {
    pub(super) a_nodes: Vec<f64>,
    pub(super) v_nodes: Vec<f64>,
    pub(super) v: f64,
    pub(super) wall: f64,
    pub(super) state: State,
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
        }
    }

    /// Marches the distribution through the steps with the given wall positions (σ_a* at each
    /// step's midpoint), returning a_r at the nodes and the final state.
    pub(super) fn march(&mut self, walls: &[f64]) -> March {
        let p0 = self.pressure;
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
impl March {
    /// (a_r, σ̄_c*, variance, tensile area) of the final distribution.
    pub(super) fn state_moments(
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
