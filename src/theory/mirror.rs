//! The mirror-Gaussian stress distribution of the adhesionless theory [S-7, S-22], with its
//! moments in closed form.
//!
//! With an absorbing wall at σ = 0 and total broadening variance Δ² (reduced units σ/(E*ḡ)):
//!
//! ```text
//! Pr(σ) = [G_Δ(σ − p) − G_Δ(σ + p)],  σ ≥ 0,   G_Δ the normal density of variance Δ²
//! a_r   = ∫Pr dσ       = erf(p / (√2 Δ))
//! ∫σ Pr dσ             = p                                  (load balance)
//! ∫σ² Pr dσ            = (p² + Δ²)·a_r + 2pΔ·φ(p/Δ),        φ the standard normal density
//! ```
//!
//! The mean stress inside the contact is σ̄_c = p/a_r and its variance ⟨δσ_c²⟩ = M₂/a_r − σ̄_c²
//! (Table 1 of \[S\]). The density is evaluated as 2e^{−(a²+b²)/2} sinh(ab)/(√(2π)Δ) with
//! a = σ/Δ, b = p/Δ, which has no cancellation when p ≪ Δ.

use statrs::function::erf::erf;
use std::f64::consts::{FRAC_1_SQRT_2, PI};

/// Contact fraction a_r = erf(p/(√2Δ)); 1 when Δ = 0 and p > 0.
pub fn area(p: f64, delta: f64) -> f64 {
    if p <= 0.0 {
        return 0.0;
    }
    if delta <= 0.0 {
        return 1.0;
    }
    erf(p / delta * FRAC_1_SQRT_2)
}

/// Pr(σ) of the mirror Gaussian (0 for σ < 0).
pub fn density(sigma: f64, p: f64, delta: f64) -> f64 {
    if sigma < 0.0 || delta <= 0.0 || p <= 0.0 {
        return 0.0;
    }
    let a = sigma / delta;
    let b = p / delta;
    let ab = a * b;
    // 2 e^{−(a²+b²)/2} sinh(ab) = e^{−(a−b)²/2} − e^{−(a+b)²/2}
    let v = if ab < 20.0 {
        2.0 * (-(a * a + b * b) / 2.0).exp() * ab.sinh()
    } else {
        (-(a - b) * (a - b) / 2.0).exp() * (1.0 - (-2.0 * ab).exp())
    };
    v / ((2.0 * PI).sqrt() * delta)
}

/// Second moment ∫σ² Pr dσ.
pub fn second_moment(p: f64, delta: f64) -> f64 {
    if p <= 0.0 {
        return 0.0;
    }
    if delta <= 0.0 {
        return p * p;
    }
    let b = p / delta;
    (p * p + delta * delta) * area(p, delta) + 2.0 * p * delta * (-(b * b) / 2.0).exp() / (2.0 * PI).sqrt()
}

/// Mean stress inside the contact σ̄_c = p/a_r and its variance ⟨δσ_c²⟩.
pub fn contact_moments(p: f64, delta: f64) -> (f64, f64) {
    let a = area(p, delta);
    if a <= 0.0 {
        // p → 0: the Rayleigh limits σ̄_c → Δ√(π/2), variance → (4−π)/2·Δ²
        return (delta * (PI / 2.0).sqrt(), (4.0 - PI) / 2.0 * delta * delta);
    }
    let mean = p / a;
    let var = (second_moment(p, delta) / a - mean * mean).max(0.0);
    (mean, var)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn trapezoid(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
        let h = (b - a) / n as f64;
        (0..=n)
            .map(|i| f(a + i as f64 * h) * if i == 0 || i == n { 0.5 } else { 1.0 })
            .sum::<f64>()
            * h
    }

    #[test]
    fn moments_match_numerical_integrals() {
        for (p, d) in [(0.01, 0.5), (0.3, 0.4), (1.0, 0.5), (1e-6, 0.5), (2.0, 0.1)] {
            let hi = p + 12.0 * d;
            let n = 200_000;
            let m0 = trapezoid(|s| density(s, p, d), 0.0, hi, n);
            let m1 = trapezoid(|s| s * density(s, p, d), 0.0, hi, n);
            let m2 = trapezoid(|s| s * s * density(s, p, d), 0.0, hi, n);
            assert!((m0 / area(p, d) - 1.0).abs() < 1e-8, "p {p}: {m0}");
            assert!((m1 / p - 1.0).abs() < 1e-7, "p {p}: {m1}");
            assert!((m2 / second_moment(p, d) - 1.0).abs() < 1e-7, "p {p}");
        }
    }

    #[test]
    fn rayleigh_limit() {
        let d = 0.5;
        let (m, v) = contact_moments(1e-9, d);
        assert!((m / (d * (PI / 2.0).sqrt()) - 1.0).abs() < 1e-8);
        assert!((v / ((4.0 - PI) / 2.0 * d * d) - 1.0).abs() < 1e-6);
    }
}
