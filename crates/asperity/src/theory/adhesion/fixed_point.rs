//! The self-consistent fixed point x = G(x), x = a_r at the step nodes, G = march ∘ walls:
//! safeguarded Anderson mixing (type II, Walker & Ni 2011, depth 6) in y = ln a, and the
//! bisected start between the two states of a cycle near a jump into contact.

// index loops mirror the formulas in this numerical module
#![allow(clippy::needless_range_loop)]

use super::propagator::Marcher;
use super::walls::walls_for;
use crate::error::{Error, Result};
use crate::input::scene::Scene;
use std::sync::atomic::{AtomicBool, Ordering};

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
pub(super) struct Attempt {
    pub(super) x: Vec<f64>,
    pub(super) residual: f64,
    pub(super) iterations: usize,
    pub(super) converged: bool,
}

pub(super) fn residual_of(x: &[f64], gx: &[f64]) -> f64 {
    let scale = x
        .last()
        .copied()
        .unwrap_or(1.0)
        .max(gx.last().copied().unwrap_or(1.0))
        .max(1e-300);
    x.iter().zip(gx).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) / scale
}

pub(super) fn check_cancel(cancel: Option<&AtomicBool>) -> Result<()> {
    if cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
        Err(Error::Cancelled)
    } else {
        Ok(())
    }
}

impl<'a> Marcher<'a> {
    /// G(x): the walls of x, then one march (at the p* of `scene`).
    pub(super) fn map(&mut self, scene: &Scene, x: &[f64]) -> Vec<f64> {
        self.pressure = scene.pressure;
        let w = walls_for(scene, self.grid, x);
        self.march(&w.mid).a_nodes
    }

    /// Safeguarded Anderson mixing in y = ln a (positivity for free); restarts from the best
    /// iterate with half the mixing when the residual grows tenfold.
    pub(super) fn fixed_point(
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
    pub(super) fn cycle_bisection(
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

#[cfg(test)]
mod tests {
    use super::*;

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
