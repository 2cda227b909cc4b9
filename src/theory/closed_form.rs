//! Closed-form references: the quasi-exact a_r(p*) fit of \[S\] and the asymptotes of the
//! adhesionless Pr(σ*).
//!
//! ```text
//! a_r(p*) = erf(1.9 p*)·(1 − a₀²(p*)) + a₀³(p*),   a₀(p*) = erf(1.45 p*)        [S-18, S-19]
//! ```
//!
//! [S-18] reproduces GFMD data for adhesionless, semi-infinite, self-affine solids with
//! H = 0.3, 0.5, 0.8; model 3 was gauged to it. Small p*: a_r ≈ (2/√π)·1.9·p* ≈ 2.144 p*.
//!
//! The adhesionless stress distribution is the mirror Gaussian Pr(σ) = [G_Δ(σ − p) − G_Δ(σ + p)]
//! [S-22] (σ, p, Δ reduced by E*ḡ; ∫Pr dσ = a_r). Its asymptotes (\[S\] Fig. 3):
//!
//! ```text
//! σ → 0:  Pr(σ) ≈ σ · 2p φ(p/Δ)/Δ³             (linear, whatever W is)
//! σ ≫ Δ:  Pr(σ) ≈ σ · 2p φ(σ/Δ)/Δ³             (Gaussian tail; ∝ σ exp(−2σ²) for Δ = 1/2)
//! ```
//!
//! with φ the standard normal density. The tail form holds for p ≪ Δ and σp ≪ Δ², the regime of
//! \[S\] Fig. 3 (p* = 0.01, Δ ≈ 1/2); in general Pr = φ((σ − p)/Δ)(1 − e^{−2σp/Δ²})/Δ exactly.

use statrs::function::erf::erf;
use std::f64::consts::PI;

/// a₀(p*) = erf(1.45 p*) [S-19]: the large-p* asymptote for adhesionless half-spaces.
pub fn eq19_a0(p: f64) -> f64 {
    erf(1.45 * p)
}

/// a_r(p*) of [S-18]: erf(1.9p*)(1 − a₀²) + a₀³.
pub fn eq18_area(p: f64) -> f64 {
    let a0 = eq19_a0(p);
    erf(1.9 * p) * (1.0 - a0 * a0) + a0 * a0 * a0
}

fn phi(x: f64) -> f64 {
    (-0.5 * x * x).exp() / (2.0 * PI).sqrt()
}

/// Small-stress asymptote of the mirror Gaussian: Pr(σ) ≈ σ·2pφ(p/Δ)/Δ³.
pub fn pr_small_stress(sigma: f64, p: f64, delta: f64) -> f64 {
    sigma * 2.0 * p * phi(p / delta) / delta.powi(3)
}

/// Large-stress (Gaussian-tail) asymptote of the mirror Gaussian for p ≪ Δ:
/// Pr(σ) ≈ σ·2pφ(σ/Δ)/Δ³.
pub fn pr_large_stress(sigma: f64, p: f64, delta: f64) -> f64 {
    sigma * 2.0 * p * phi(sigma / delta) / delta.powi(3)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::mirror;

    #[test]
    fn eq18_matches_the_tabulated_values() {
        // docs/reference-values.md, "Eq. (18) of [S]" column (5 significant digits)
        for (p, a) in [
            (0.001, 0.00214),
            (0.01, 0.02144),
            (0.05, 0.10671),
            (0.1, 0.21054),
            (0.2, 0.39982),
            (0.5, 0.76001),
            (1.0, 0.96231),
        ] {
            assert!((eq18_area(p) / a - 1.0).abs() < 3e-3, "p* = {p}: {}", eq18_area(p));
        }
        // small-p* slope 2·1.9/√π
        assert!((eq18_area(1e-8) / 1e-8 - 3.8 / PI.sqrt()).abs() < 1e-6);
    }

    #[test]
    fn asymptotes_of_the_mirror_gaussian() {
        let (p, d) = (0.01, 0.5);
        for s in [1e-6, 1e-5, 1e-4] {
            let r = mirror::density(s, p, d) / pr_small_stress(s, p, d);
            assert!((r - 1.0).abs() < 1e-3, "σ = {s}: {r}");
        }
        for s in [3.0, 4.0] {
            let r = mirror::density(s, p, d) / pr_large_stress(s, p, d);
            // exact/asymptote = e^{−p²/2Δ²}·sinh(σp/Δ²)/(σp/Δ²) = 1 + O(σ²p²/Δ⁴)
            assert!((r - 1.0).abs() < 5e-3, "σ = {s}: {r}");
        }
    }
}
