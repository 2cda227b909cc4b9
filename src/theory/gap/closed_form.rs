//! The Yang–Persson closed form of the adhesionless mean gap: the independent check of the
//! energy route ([`super::route`]).
//!
//! # Closed form (adhesionless, W only in the energy)
//!
//! For W = γ_P + (1 − γ_P)a² in the energy and no W in the broadening (α = 0, or W ≡ 1), the
//! variance is unweighted and a_r(q) = erf(w(q)p/E*) in closed form, so (Yang & Persson 2008,
//! Persson 2007; generalised here with the slab factor: f in the energy, f² in the variance)
//!
//! ```text
//! ū(p) = √π ∫dq q² C(q) f(q) w(q) ∫_p^∞ dp'/p' [γ_P + 3(1−γ_P)P²] exp(−(w p'/E*)²)
//!      = √π ∫dq q² C f w · J(w p/E*),     P = erf(w p'/E*),
//! w(q) = (π ∫_{q_L}^{q} q'³ f² C dq')^{−1/2},
//! J(x) = γ_P E₁(x²)/2 + 3(1−γ_P) ∫_x^∞ erf(t)² e^{−t²} dt/t.
//! ```
//!
//! Dimensional check: with C in m⁴, q in 1/m and w in m/1 · 1/m^{...}: π∫q³C dq is ḡ²/2 of the
//! partial spectrum (dimensionless), so w is dimensionless and wp/E* = w ḡ p*; √π∫q²C w dq has
//! unit m. For W = f = 1 it is the energy route differentiated by hand: U = (E*/4)∫a q dm with
//! dm = 2πqC dq and V(q) = (E*²/2)π∫q³C dq, so 2V = (E*/w)², a = erf(wp/E*) and
//! dU/dp = √π∫q²C w e^{−(wp/E*)²} dq. At small p (all wp/E* ≪ 1, E₁(x²) ≈ −γ_E − 2 ln x)
//!
//! ```text
//! ū ≈ u₀ (−ln p* + const),   u₀ = √π γ_P ∫dq q² C f w   (Persson's asymptote)
//! ```
//!
//! w(q) ∝ (q − q_L)^{−1/2} near q_L: the q-integrals here use panels in ln(q − q_L) on the
//! first segment of the spectrum, which makes that end point harmless.

use crate::error::{Error, Result};
use crate::input::scene::Scene;
use crate::surface::spectrum::{Spectrum, GL8};
use crate::theory::slab::slab_factor_at;
use statrs::function::erf::erf;
use std::f64::consts::PI;

/// Which closed form applies: γ_P = 1 − c₁ when c₂ = 0 and the broadening is unweighted
/// (α = 0, or W ≡ 1); `None` otherwise.
pub fn closed_form_gamma_p(scene: &Scene) -> Option<f64> {
    let m = &scene.model;
    let unweighted = m.alpha == 0.0 || (m.c1 == 0.0 && m.c2 == 0.0);
    (m.c2 == 0.0 && unweighted && !scene.is_adhesive()).then_some(1.0 - m.c1)
}

/// Yang–Persson closed form (module docs), ū/h_rms at reduced pressures `ps`, for an
/// adhesionless scene on a continuum spectrum with c₂ = 0 and an unweighted broadening.
pub fn closed_form(scene: &Scene, ps: &[f64]) -> Result<Vec<f64>> {
    let gp = closed_form_gamma_p(scene).ok_or_else(|| {
        Error::Unsupported("the Yang-Persson closed form needs gamma = 0, c2 = 0 and alpha = 0 (or model 1)".into())
    })?;
    let Spectrum::SelfAffine(sa) = &scene.spectrum else {
        return Err(Error::Unsupported(
            "the Yang-Persson closed form is implemented for the continuum spectrum".into(),
        ));
    };
    let t = scene.thickness_m();
    let g = scene.rms_gradient();
    let h_rms = scene.spectrum.rms_height();
    // nodes (q, weight dq) with the running integral I(q) = ∫_{q_L}^q q'^3 f² C dq'
    let nodes = cumulative_nodes(scene, |q| {
        let f = slab_factor_at(q, t);
        q * q * q * f * f * sa.psd(q)
    });
    let mut out = Vec::with_capacity(ps.len());
    for &p in ps {
        let mut sum = 0.0;
        for &(q, dq, i_q) in &nodes {
            if i_q <= 0.0 {
                continue;
            }
            let w = (PI * i_q).powf(-0.5);
            let f = slab_factor_at(q, t);
            sum += dq * q * q * sa.psd(q) * f * w * inner_j(w * g * p, gp);
        }
        out.push(PI.sqrt() * sum / h_rms);
    }
    Ok(out)
}

/// Persson's small-load slope u₀/h_rms = √π γ_P ∫dq q²C f w / h_rms (see module docs).
pub fn asymptotic_slope(scene: &Scene) -> Result<f64> {
    let gp = closed_form_gamma_p(scene)
        .ok_or_else(|| Error::Unsupported("the asymptote needs the closed form's model".into()))?;
    let Spectrum::SelfAffine(sa) = &scene.spectrum else {
        return Err(Error::Unsupported("the asymptote needs the continuum spectrum".into()));
    };
    let t = scene.thickness_m();
    let nodes = cumulative_nodes(scene, |q| {
        let f = slab_factor_at(q, t);
        q * q * q * f * f * sa.psd(q)
    });
    let mut sum = 0.0;
    for &(q, dq, i_q) in &nodes {
        if i_q > 0.0 {
            sum += dq * q * q * sa.psd(q) * slab_factor_at(q, t) * (PI * i_q).powf(-0.5);
        }
    }
    Ok(PI.sqrt() * gp * sum / scene.spectrum.rms_height())
}

/// J(x) = γ_P E₁(x²)/2 + 3(1−γ_P) ∫_x^∞ erf(t)² e^{−t²} dt/t.
fn inner_j(x: f64, gp: f64) -> f64 {
    let mut j = 0.5 * gp * expint_e1(x * x);
    if gp != 1.0 {
        let top = 6.5f64;
        if x < top {
            let panels = ((top - x) / 0.5).ceil().max(1.0) as usize;
            let h = (top - x) / panels as f64;
            let mut r = 0.0;
            for k in 0..panels {
                let mid = x + (k as f64 + 0.5) * h;
                for &(xg, wg) in &GL8 {
                    for s in [-xg, xg] {
                        let tt = mid + 0.5 * h * s;
                        let e = erf(tt);
                        r += 0.5 * h * wg * e * e * (-tt * tt).exp() / tt;
                    }
                }
            }
            j += 3.0 * (1.0 - gp) * r;
        }
    }
    j
}

/// Exponential integral E₁(z), z > 0 (series for z ≤ 1, continued fraction above; ~1e-15).
pub fn expint_e1(z: f64) -> f64 {
    const EULER: f64 = 0.577_215_664_901_532_9;
    if z <= 0.0 {
        return f64::INFINITY;
    }
    if z > 700.0 {
        return 0.0;
    }
    if z <= 1.0 {
        let mut sum = 0.0;
        let mut term = 1.0;
        for k in 1..60 {
            term *= -z / k as f64;
            let add = term / k as f64;
            sum += add;
            if add.abs() < 1e-17 * sum.abs().max(1e-300) {
                break;
            }
        }
        -EULER - z.ln() - sum
    } else {
        // modified Lentz on E1(z) = e^{-z} · 1/(z + 1 − 1²/(z + 3 − 2²/(z + 5 − …)))
        let tiny = 1e-300;
        let mut b = z + 1.0;
        let mut c = 1.0 / tiny;
        let mut d = 1.0 / b;
        let mut hh = d;
        for i in 1..200 {
            let an = -((i * i) as f64);
            b += 2.0;
            d = 1.0 / (an * d + b);
            c = b + an / c;
            let del = c * d;
            hh *= del;
            if (del - 1.0).abs() < 1e-16 {
                break;
            }
        }
        hh * (-z).exp()
    }
}

/// Quadrature nodes (q, dq weight, I(q)) for ∫dq over the spectrum's support, with
/// I(q) = ∫_{q_L}^q g(q') dq' at each node. The first segment uses panels in ln(q − q_L) down to
/// 1e-16 of its width (integrands ∝ (q − q_L)^{−1/2} become smooth), the others panels of width
/// 0.1 in ln q; I at a node is the running panel sum plus an 8-point rule on the partial panel.
fn cumulative_nodes(scene: &Scene, g: impl Fn(f64) -> f64) -> Vec<(f64, f64, f64)> {
    let bp = scene.spectrum.breakpoints();
    let mut out = Vec::new();
    let mut running = 0.0;
    for (seg, w) in bp.windows(2).enumerate() {
        let (lo, hi) = (w[0], w[1]);
        // map variable y ↦ q, dq/dy on this segment
        let graded = seg == 0;
        let (ya, yb) = if graded {
            (((hi - lo) * 1e-16).ln(), (hi - lo).ln())
        } else {
            (lo.ln(), hi.ln())
        };
        let to_q = |y: f64| -> (f64, f64) {
            if graded {
                let d = y.exp();
                ((lo + d).min(hi), d)
            } else {
                let q = y.exp().clamp(lo, hi);
                (q, q)
            }
        };
        let width = if graded { 0.5 } else { 0.1 };
        let panels = ((yb - ya) / width).ceil().max(1.0) as usize;
        let h = (yb - ya) / panels as f64;
        let panel_integral = |a: f64, b: f64| -> f64 {
            let mid = 0.5 * (a + b);
            let half = 0.5 * (b - a);
            let mut s = 0.0;
            for &(xg, wg) in &GL8 {
                for sg in [-xg, xg] {
                    let (q, jac) = to_q(mid + half * sg);
                    s += half * wg * g(q) * jac;
                }
            }
            s
        };
        for k in 0..panels {
            let a = ya + k as f64 * h;
            let b = a + h;
            let mid = 0.5 * (a + b);
            let mut nodes8: Vec<(f64, f64)> = GL8.iter().rev().map(|&(x, wt)| (-x, wt)).collect();
            nodes8.extend(GL8.iter().copied());
            for (x, wt) in nodes8 {
                let y = mid + 0.5 * h * x;
                let (q, jac) = to_q(y);
                let i_q = running + panel_integral(a, y);
                out.push((q, 0.5 * h * wt * jac, i_q));
            }
            running += panel_integral(a, b);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn e1_values() {
        // Abramowitz & Stegun table 5.1: E1(0.5) = 0.5597735947761608, E1(1) = 0.21938393439552,
        // E1(2) = 0.04890051070806112, E1(10) = 4.156968929685324e-6
        for (z, e) in [
            (0.5, 0.559_773_594_776_160_8),
            (1.0, 0.219_383_934_395_520_3),
            (2.0, 0.048_900_510_708_061_12),
            (10.0, 4.156_968_929_685_324e-6),
        ] {
            assert!(
                (expint_e1(z) - e).abs() < 1e-14 * e.max(1e-3) * 10.0,
                "E1({z}) = {}",
                expint_e1(z)
            );
        }
    }
}
