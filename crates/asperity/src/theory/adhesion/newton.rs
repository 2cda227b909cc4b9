//! Newton–Krylov for the fixed point and for its continuation in the load.
//!
//! The unknown is y = ln a_r at the step nodes and the residual R(y; λ) = ln G(e^y; p*) − y,
//! λ = ln p*. Near a jump into contact the map G has one strongly expanding direction (its
//! output moves ~70× its input there, so plain and Anderson iteration fall into cycles), but
//! R itself is smooth: Newton's method does not care whether the fixed point attracts the
//! iteration. Jacobian-vector products are forward differences of R (one march each) and the
//! linear systems are solved by GMRES (Saad & Schultz 1986) without restarts: the spectrum of
//! ∂G/∂y is a few large eigenvalues plus a cluster near 0, so GMRES needs few iterations.
//!
//! Pseudo-arclength continuation (Keller 1977) adds λ to the unknowns and one equation,
//! t·(z − ẑ) = 0, with t the unit tangent of the curve z(s) = (y, λ)(s) and ẑ the predicted
//! point: the bordered system is regular at a fold, where ∂R/∂y is singular, so the curve is
//! followed through turning points ([`super::continuation`]).

use super::fixed_point::{check_cancel, Attempt};
use super::propagator::Marcher;
use crate::error::Result;
use crate::input::scene::Scene;
use std::sync::atomic::AtomicBool;

/// Most GMRES iterations per linear solve.
const GMRES_MAX: usize = 80;
/// Most Newton steps per solve.
const NEWTON_MAX: usize = 30;

/// Euclidean norm.
pub(super) fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// GMRES for A x = b from x = 0 with Givens rotations; `apply` computes A v. Stops at
/// ‖b − Ax‖ ≤ rtol‖b‖ or after `max` iterations and returns the best x.
pub(super) fn gmres(apply: &mut dyn FnMut(&[f64]) -> Vec<f64>, b: &[f64], rtol: f64, max: usize) -> Vec<f64> {
    let n = b.len();
    let beta = norm(b);
    if beta == 0.0 || !beta.is_finite() {
        return vec![0.0; n];
    }
    let mut basis: Vec<Vec<f64>> = vec![b.iter().map(|x| x / beta).collect()];
    let mut h: Vec<Vec<f64>> = Vec::new(); // columns of the Hessenberg matrix (rotated)
    let (mut cs, mut sn) = (Vec::<f64>::new(), Vec::<f64>::new());
    let mut g = vec![beta];
    for j in 0..max.min(n) {
        let mut w = apply(&basis[j]);
        let mut col = vec![0.0; j + 2];
        for (i, v) in basis.iter().enumerate() {
            let hij: f64 = w.iter().zip(v).map(|(a, b)| a * b).sum();
            col[i] = hij;
            for (wk, vk) in w.iter_mut().zip(v) {
                *wk -= hij * vk;
            }
        }
        let hn = norm(&w);
        col[j + 1] = hn;
        for i in 0..j {
            let t = cs[i] * col[i] + sn[i] * col[i + 1];
            col[i + 1] = -sn[i] * col[i] + cs[i] * col[i + 1];
            col[i] = t;
        }
        let r = col[j].hypot(col[j + 1]);
        let (c, s) = if r == 0.0 {
            (1.0, 0.0)
        } else {
            (col[j] / r, col[j + 1] / r)
        };
        cs.push(c);
        sn.push(s);
        col[j] = r;
        col[j + 1] = 0.0;
        g.push(-s * g[j]);
        g[j] *= c;
        h.push(col);
        let done = g[j + 1].abs() <= rtol * beta || hn <= 1e-300 || !hn.is_finite();
        if !done {
            basis.push(w.iter().map(|x| x / hn).collect());
        }
        if done || j + 1 == max.min(n) {
            break;
        }
    }
    // back substitution for the coefficients
    let m = h.len();
    let mut coef = vec![0.0; m];
    for i in (0..m).rev() {
        let s: f64 = (i + 1..m).map(|k| h[k][i] * coef[k]).sum();
        coef[i] = if h[i][i] != 0.0 { (g[i] - s) / h[i][i] } else { 0.0 };
    }
    let mut x = vec![0.0; n];
    for (c, v) in coef.iter().zip(&basis) {
        for (xk, vk) in x.iter_mut().zip(v) {
            *xk += c * vk;
        }
    }
    if x.iter().all(|v| v.is_finite()) {
        x
    } else {
        vec![0.0; n]
    }
}

/// ln a from a (a ≥ 1e-300).
pub(super) fn ln_a(a: &[f64]) -> Vec<f64> {
    a.iter().map(|v| v.max(1e-300).ln()).collect()
}

impl<'a> Marcher<'a> {
    /// R(y) = ln G(e^y) − y at the p* of `scene`, with G(e^y).
    pub(super) fn residual_y(&mut self, scene: &Scene, y: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let x: Vec<f64> = y.iter().map(|v| v.exp()).collect();
        let gx = self.map(scene, &x);
        let r = ln_a(&gx).iter().zip(y).map(|(g, v)| g - v).collect();
        (r, gx)
    }

    /// Newton–GMRES for R(y) = 0 at fixed p* from `start` (a at the nodes), with a
    /// backtracking line search on ‖R‖. Converged when max|G(x) − x| ≤ tol·a_r(q_s), as the
    /// Anderson attempts.
    pub(super) fn newton(&mut self, scene: &Scene, start: &[f64], cancel: Option<&AtomicBool>) -> Result<Attempt> {
        let tol = self.acc.tol;
        let mut y = ln_a(start);
        let (mut r, mut gx) = self.residual_y(scene, &y);
        let mut evals = 1;
        let mut best = Attempt {
            x: gx.clone(),
            residual: f64::INFINITY,
            iterations: 0,
            converged: false,
        };
        for _ in 0..NEWTON_MAX {
            check_cancel(cancel)?;
            let x: Vec<f64> = y.iter().map(|v| v.exp()).collect();
            let res = super::fixed_point::residual_of(&x, &gx);
            if res < best.residual {
                best.x = gx.clone();
                best.residual = res;
            }
            if res <= tol {
                best.converged = true;
                break;
            }
            let rn = norm(&r);
            // J v = (R(y + εv) − R(y))/ε
            let ynorm = 1.0 + norm(&y) / (y.len() as f64).sqrt();
            let mut apply = |v: &[f64]| -> Vec<f64> {
                let vn = norm(v).max(1e-300);
                let eps = 1e-7 * ynorm / vn;
                let yp: Vec<f64> = y.iter().zip(v).map(|(a, b)| a + eps * b).collect();
                evals += 1;
                let (rp, _) = self.residual_y(scene, &yp);
                rp.iter().zip(&r).map(|(a, b)| (a - b) / eps).collect()
            };
            let minus_r: Vec<f64> = r.iter().map(|v| -v).collect();
            let dy = gmres(&mut apply, &minus_r, 1e-6, GMRES_MAX);
            if std::env::var_os("ASPERITY_DEBUG").is_some() {
                let jdy = apply(&dy);
                let lin: Vec<f64> = jdy.iter().zip(&r).map(|(a, b)| a + b).collect();
                eprintln!(
                    "newton res {res:.3e} |R| {rn:.3e} |dy| {:.3e} lin {:.3e} a_end {:.4e}",
                    norm(&dy),
                    norm(&lin),
                    x[x.len() - 1]
                );
            }
            // backtracking on ‖R‖
            let mut lambda = 1.0;
            let mut accepted = false;
            for _ in 0..8 {
                let yt: Vec<f64> = y.iter().zip(&dy).map(|(a, b)| (a + lambda * b).min(0.0)).collect();
                let (rt, gt) = self.residual_y(scene, &yt);
                evals += 1;
                let rtn = norm(&rt);
                if std::env::var_os("ASPERITY_DEBUG").is_some() {
                    eprintln!("  lambda {lambda} |R| {rtn:.3e}");
                }
                if rtn.is_finite() && rtn < (1.0 - 1e-4 * lambda) * rn {
                    y = yt;
                    r = rt;
                    gx = gt;
                    accepted = true;
                    break;
                }
                lambda *= 0.5;
            }
            if !accepted {
                break;
            }
        }
        best.iterations = evals;
        Ok(best)
    }
}
