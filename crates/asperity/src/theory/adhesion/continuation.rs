//! Pseudo-arclength continuation of the fixed point in a scalar parameter μ (Keller 1977):
//! the curve z(s) = (y(s), μ(s)) of solutions of R(y; μ) = ln G(e^y; μ) − y = 0 is followed
//! through its turning points (folds), where a natural-parameter continuation stops because
//! ∂R/∂y is singular. The bordered system
//!
//! ```text
//! [ ∂R/∂y   ∂R/∂μ ] [δy]     [ R              ]
//! [ t_y·/n  t_μ   ] [δμ] = − [ t·(z − ẑ)      ]
//! ```
//!
//! (t the unit tangent in the inner product ⟨z₁, z₂⟩ = y₁·y₂/n + μ₁μ₂, ẑ = z₀ + Δs·t the
//! predicted point) stays regular there. It is solved matrix-free by GMRES ([`super::newton`]).
//! Each crossing of the target μ* is polished by Newton at fixed μ*: that is one branch. Along
//! an S-shaped curve the segment between two folds is unstable (stability changes at every
//! fold, counted from the stable start).
//!
//! Used with μ = γ/γ_s (from the adhesionless state at μ = 0, which is exact):
//! [`super::trace_in_gamma`] reports every branch that the curve from the adhesionless state
//! meets at the scene's γ_s, and the folds it passes. Status (issue 13): the curve is followed
//! through the first fold of the thin-slab jump (system 2, model 3, t·q_r = 0.1, p* = 1e-5:
//! fold at γ/γ_s ≈ 0.813), but beyond it the corrector stalls (max|R| stagnates at
//! ~1e-5..1e-4 at any step): the discrete map is not smooth at that level there (its grid
//! spacing at the switch to the grid and its coarsening steps depend on the iterate), so the
//! trace ends and says so (`stalled`).

use super::fixed_point::{check_cancel, Attempt};
use super::newton::{gmres, norm};
use super::propagator::Marcher;
use crate::error::Result;
use crate::input::scene::Scene;
use std::sync::atomic::AtomicBool;

/// One branch met by a continuation at the target parameter.
pub(super) struct Crossing {
    /// The polished fixed point (a Newton attempt at the target).
    pub(super) attempt: Attempt,
    /// Stable (an even number of folds passed since the start).
    pub(super) stable: bool,
}

/// The outcome of one continuation.
pub(super) struct Traced {
    /// Branches met at the target, in the order of the curve.
    pub(super) crossings: Vec<Crossing>,
    /// Parameter values of the folds passed.
    pub(super) folds: Vec<f64>,
    /// Map evaluations spent.
    pub(super) evaluations: usize,
    /// The parameter and a_r(q_s) of the last point reached.
    pub(super) last: (f64, f64),
    /// Whether the trace ended because the corrector failed even at the smallest step.
    pub(super) stalled: bool,
}

/// The corrector's tolerance on max|R| (R in ln a: a relative error of a_r at the nodes);
/// each crossing of the target is then polished to the solver's own tolerance.
const CORRECTOR_TOL: f64 = 1e-6;
/// Most GMRES iterations of a corrector step (the bordered system is ill-conditioned near a
/// fold; up to the full dimension).
const GMRES_FULL: usize = 200;
/// Most continuation steps.
const MAX_STEPS: usize = 400;
/// Largest and smallest arclength steps (inner product above).
const DS_MAX: f64 = 0.25;
const DS_MIN: f64 = 1e-5;

impl<'a> Marcher<'a> {
    /// Follows the solution curve of R(y; μ) = 0 from the solution `y0` at `mu0` (μ growing
    /// at the start) until μ leaves (mu0, `mu_stop`) or a_r(q_s) reaches 0.999, and polishes
    /// every crossing of `target`. `scene_at(μ)` builds the scene of a parameter value.
    pub(super) fn arclength(
        &mut self,
        scene_at: &dyn Fn(f64) -> Scene,
        y0: Vec<f64>,
        mu0: f64,
        target: f64,
        mu_stop: f64,
        cancel: Option<&AtomicBool>,
    ) -> Result<Traced> {
        let n = y0.len();
        let nf = n as f64;
        let mut evals = 0usize;
        // initial tangent: R_y t_y = −R_μ, t = (t_y, 1) normalised
        let dmu = 1e-6;
        let (r0, _) = self.residual_y(&scene_at(mu0), &y0);
        let (r1, _) = self.residual_y(&scene_at(mu0 + dmu), &y0);
        evals += 2;
        let rmu: Vec<f64> = r1.iter().zip(&r0).map(|(a, b)| -(a - b) / dmu).collect();
        let ty = {
            let s0 = scene_at(mu0);
            let ynorm = norm(&y0).max(1.0);
            let mut apply = |v: &[f64]| -> Vec<f64> {
                let eps = 1e-7 * ynorm / norm(v).max(1e-300);
                let yp: Vec<f64> = y0.iter().zip(v).map(|(a, b)| a + eps * b).collect();
                evals += 1;
                let (rp, _) = self.residual_y(&s0, &yp);
                rp.iter().zip(&r0).map(|(a, b)| (a - b) / eps).collect()
            };
            gmres(&mut apply, &rmu, 1e-6, 60)
        };
        let mut t = unit(&ty, 1.0, nf);
        let mut z = (y0, mu0);
        let mut ds = 0.02;
        let mut folds = Vec::new();
        let mut crossings = Vec::new();
        let mut stable = true;
        let mut stalled = false;
        for _ in 0..MAX_STEPS {
            check_cancel(cancel)?;
            // predictor and bordered Newton corrector
            let pred_y: Vec<f64> = z.0.iter().zip(&t.0).map(|(a, b)| (a + ds * b).min(0.0)).collect();
            let pred_mu = z.1 + ds * t.1;
            let corr = self.correct(scene_at, &pred_y, pred_mu, &t, nf, &mut evals);
            let debug = std::env::var_os("ASPERITY_DEBUG").is_some();
            if debug {
                eprintln!(
                    "arc mu {:.6} a_end {:.4e} ds {ds:.2e} ok {}",
                    z.1,
                    z.0.last().copied().unwrap_or(0.0).exp(),
                    corr.is_some()
                );
            }
            let Some((y1, mu1, its)) = corr else {
                ds *= 0.5;
                if ds < DS_MIN {
                    stalled = true;
                    break;
                }
                continue;
            };
            // the secant is the next tangent; a sign change of its μ part is a fold
            let dy: Vec<f64> = y1.iter().zip(&z.0).map(|(a, b)| a - b).collect();
            let t_new = unit(&dy, mu1 - z.1, nf);
            if t_new.1 * t.1 < 0.0 {
                folds.push(z.1);
                stable = !stable;
            }
            // a crossing of the target: polish at fixed μ*
            if (z.1 - target) * (mu1 - target) <= 0.0 && mu1 != z.1 {
                let w = (target - z.1) / (mu1 - z.1);
                let x: Vec<f64> = z.0.iter().zip(&y1).map(|(a, b)| (a + w * (b - a)).exp()).collect();
                let st = scene_at(target);
                let mut att = self.newton(&st, &x, cancel)?;
                evals += att.iterations;
                if !att.converged {
                    // Newton stalls where the discrete map is not smooth: Anderson from there
                    let a2 = self.fixed_point(&st, x.clone(), 0.5, cancel)?;
                    evals += a2.iterations;
                    if a2.converged || a2.residual < att.residual {
                        att = a2;
                    }
                }
                if std::env::var_os("ASPERITY_DEBUG").is_some() {
                    eprintln!(
                        "crossing at {target}: converged {} residual {:.2e}",
                        att.converged, att.residual
                    );
                }
                if att.converged {
                    crossings.push(Crossing { attempt: att, stable });
                }
            }
            t = t_new;
            z = (y1, mu1);
            ds = if its <= 3 { (ds * 1.5).min(DS_MAX) } else { ds };
            let a_end = z.0.last().copied().unwrap_or(0.0).exp();
            if z.1 <= mu0 || z.1 >= mu_stop || a_end >= 0.999 {
                break;
            }
        }
        let last = (z.1, z.0.last().copied().unwrap_or(0.0).exp());
        Ok(Traced {
            crossings,
            folds,
            evaluations: evals,
            last,
            stalled,
        })
    }

    /// Bordered Newton from the predicted point: (y, μ, iterations) once max|R| ≤
    /// [`CORRECTOR_TOL`], None after 10 iterations or when |R| doubles.
    fn correct(
        &mut self,
        scene_at: &dyn Fn(f64) -> Scene,
        pred_y: &[f64],
        pred_mu: f64,
        t: &(Vec<f64>, f64),
        nf: f64,
        evals: &mut usize,
    ) -> Option<(Vec<f64>, f64, usize)> {
        let (mut y, mut mu) = (pred_y.to_vec(), pred_mu);
        let mut prev = f64::INFINITY;
        for it in 1..=10 {
            let s = scene_at(mu);
            let (r, _) = self.residual_y(&s, &y);
            *evals += 1;
            let rmax = r.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            if std::env::var_os("ASPERITY_DEBUG").is_some() {
                eprintln!("  corr {it} mu {mu:.6} |R|max {rmax:.3e}");
            }
            if !rmax.is_finite() || rmax > 2.0 * prev {
                return None;
            }
            if rmax <= CORRECTOR_TOL {
                return Some((y, mu, it));
            }
            prev = rmax;
            let arc =
                t.0.iter()
                    .zip(y.iter().zip(pred_y))
                    .map(|(a, (b, c))| a * (b - c))
                    .sum::<f64>()
                    / nf
                    + t.1 * (mu - pred_mu);
            let mut rhs: Vec<f64> = r.iter().map(|v| -v).collect();
            rhs.push(-arc);
            let ynorm = 1.0 + norm(&y) / nf.sqrt();
            let (y_ref, mu_ref) = (y.clone(), mu);
            let mut apply = |v: &[f64]| -> Vec<f64> {
                let eps = 1e-7 * ynorm / norm(v).max(1e-300);
                let yp: Vec<f64> = y_ref.iter().zip(v).map(|(a, b)| a + eps * b).collect();
                let mp = mu_ref + eps * v[v.len() - 1];
                *evals += 1;
                let (rp, _) = self.residual_y(&scene_at(mp), &yp);
                let mut out: Vec<f64> = rp.iter().zip(&r).map(|(a, b)| (a - b) / eps).collect();
                let last = t.0.iter().zip(v).map(|(a, b)| a * b).sum::<f64>() / nf + t.1 * v[v.len() - 1];
                out.push(last);
                out
            };
            let d = gmres(&mut apply, &rhs, 1e-8, (nf as usize + 1).min(GMRES_FULL));
            let k = d.len() - 1;
            for (yi, di) in y.iter_mut().zip(&d[..k]) {
                *yi = (*yi + di).min(0.0);
            }
            mu += d[k];
        }
        None
    }
}

/// The unit vector (y, μ)/‖(y, μ)‖ in the inner product y₁·y₂/n + μ₁μ₂.
fn unit(y: &[f64], mu: f64, nf: f64) -> (Vec<f64>, f64) {
    let len = (y.iter().map(|v| v * v).sum::<f64>() / nf + mu * mu).sqrt().max(1e-300);
    (y.iter().map(|v| v / len).collect(), mu / len)
}
