//! The attraction of the two DMT-type routes (physics.md §6.3), in reduced stress
//! p_att* = p_att/(E*ḡ), at one state of the adhesionless contact.
//!
//! - Bearing-area model (Ciavarella, Meccanica 53 (2018) 241): a Maugis–Dugdale law of strength
//!   σ0 and range Δr acts on the area of the *undeformed* surface whose heights lie within Δr
//!   of the counter-surface at mean separation ū; heights Gaussian of rms h_rms:
//!   p_att = σ0 · ½ erfc((ū − Δr)/(√2 h_rms)). For GFMD's law v(g) = −γ_s e^{−g/ρ}:
//!   σ0 = γ_s/ρ and Δr = ρ (the same work of adhesion σ0Δr = γ_s).
//! - The DMT attraction over Persson's distribution of interfacial separations (Persson &
//!   Scaraggi, J. Chem. Phys. 141, 124701 (2014); P(u) after Almqvist et al., JMPS 59 (2011)
//!   2355): p_att = ∫ P(u) σ(u) du with σ(u) = (γ_s/ρ) e^{−u/ρ} and
//!   P(u) = a_r(q_s) δ(u) + ∫ (−da_r(ζ)) [φ_s(u − ū_ζ) + φ_s(u + ū_ζ)] over the magnification:
//!   the area that leaves contact at resolution ζ lies at the mean separation ū_ζ of the
//!   contact patches seen at ζ, spread by the rms height s_ζ of the roughness finer than ζ.
//!   ū_ζ is the Yang–Persson gap of that finer roughness at the patches' pressure p/a_r(ζ)
//!   (physics.md §5, with the slab factor and the model's own variance v(q)).

use crate::input::scene::Scene;
use crate::surface::spectrum::PANEL_WIDTH_LN;
use crate::theory::gap::expint_e1;
use crate::theory::persson::Solution;
use statrs::function::erf::erfc;
use std::f64::consts::{FRAC_1_SQRT_2, PI};

/// The scaled complementary error function erfcx(x) = e^{x²} erfc(x), for x ≥ 0.
pub fn erfcx(x: f64) -> f64 {
    if x < 25.0 {
        (x * x).exp() * erfc(x)
    } else {
        // asymptotic series, relative error below 1e-11 for x ≥ 25
        let y = 1.0 / (2.0 * x * x);
        (1.0 - y * (1.0 - 3.0 * y * (1.0 - 5.0 * y))) / (x * PI.sqrt())
    }
}

/// ∫_0^∞ e^{−u} [φ_s(u − m) + φ_s(u + m)] du, φ_s the normal density of rms `s`: the mean of
/// e^{−u} over a Gaussian of mean m ≥ 0 folded at u = 0 (the mirror term keeps the area that
/// the Gaussian puts below 0). Lengths in units of the range ρ. 1 at m = s = 0.
pub fn folded_exponential(m: f64, s: f64) -> f64 {
    if s <= 1e-12 * m.abs().max(1.0) {
        return (-m.max(0.0)).exp();
    }
    half_exponential(m, s) + half_exponential(-m, s)
}

/// ∫_0^∞ e^{−u} φ_s(u − m) du = e^{s²/2 − m} Φ((m − s²)/s), without overflow.
fn half_exponential(m: f64, s: f64) -> f64 {
    let x = (s * s - m) / (std::f64::consts::SQRT_2 * s);
    if x < 0.0 {
        // m > s²: the exponent s²/2 − m is below −s²/2
        (0.5 * s * s - m).exp() * 0.5 * erfc(x)
    } else {
        0.5 * (-(m * m) / (2.0 * s * s)).exp() * erfcx(x)
    }
}

/// The bearing-area attraction p_att* = σ0* · ½ erfc((ū − Δr)/(√2 h_rms)), `gap` = ū/h_rms,
/// `range` = Δr/h_rms, `strength` = σ0*.
pub fn bearing_area(gap: f64, range: f64, strength: f64) -> f64 {
    strength * 0.5 * erfc((gap - range) * FRAC_1_SQRT_2)
}

/// The scene's spectral quantities the gap distribution needs, on the spectrum's quadrature
/// nodes (the modes themselves for a map's spectrum), sorted by q.
#[derive(Debug, Clone)]
pub struct SpectralNodes {
    q: Vec<f64>,
    dm: Vec<f64>,
    /// q f(qt)/(4ḡ h_rms): the gap per unit of dm·√(2/(πΔv))·½E₁ (reduced by h_rms).
    weight: Vec<f64>,
    /// Σ_{q_j ≥ q_i} dm_j / h_rms²: the mean-square height of the roughness from q_i up.
    tail: Vec<f64>,
    /// The resolutions ζ at which the detached area is binned (log-spaced, q_L to q_s).
    zeta: Vec<f64>,
}

impl SpectralNodes {
    /// The nodes of `scene` and `zeta_points` (≥ 2) log-spaced resolutions.
    pub fn new(scene: &Scene, zeta_points: usize) -> SpectralNodes {
        let spec = scene.spectrum();
        let mut modes = spec.nodes(PANEL_WIDTH_LN);
        modes.sort_by(|a, b| a.q.total_cmp(&b.q));
        let h2 = spec.moment(0);
        let (g, h) = (spec.rms_gradient(), h2.sqrt());
        let q: Vec<f64> = modes.iter().map(|m| m.q).collect();
        let dm: Vec<f64> = modes.iter().map(|m| m.dm).collect();
        let weight = q.iter().map(|&q| q * scene.slab(q) / (4.0 * g * h)).collect();
        let mut tail = vec![0.0; q.len()];
        let mut acc = 0.0;
        for i in (0..q.len()).rev() {
            acc += dm[i] / h2;
            tail[i] = acc;
        }
        let (lo, hi) = (spec.q_l().ln(), spec.q_s().ln());
        let n = zeta_points.max(2);
        let zeta = (0..n)
            .map(|k| (lo + (hi - lo) * k as f64 / (n - 1) as f64).exp())
            .collect();
        SpectralNodes {
            q,
            dm,
            weight,
            tail,
            zeta,
        }
    }

    /// The first node index with q > `zeta`.
    fn first_above(&self, zeta: f64) -> usize {
        self.q.partition_point(|&q| q <= zeta)
    }

    /// ū_ζ/h_rms: the Yang–Persson gap of the roughness finer than ζ under the patches'
    /// pressure p_ζ = p*/a_r(ζ), with v(q) − v(ζ) the variance that roughness adds
    /// (physics.md §6.3), and s_ζ²/h_rms², that roughness's mean-square height.
    pub fn patch_gap(&self, sol: &Solution, v_nodes: &[f64], zeta: f64) -> (f64, f64) {
        let i0 = self.first_above(zeta);
        if i0 >= self.q.len() {
            return (0.0, 0.0);
        }
        let v0 = sol.variance_at(zeta);
        let a = sol.area_at(zeta);
        if a <= 0.0 {
            return (f64::INFINITY, self.tail[i0]);
        }
        let p = sol.pressure / a;
        let gap: f64 = (i0..self.q.len())
            .filter_map(|j| {
                let dv = v_nodes[j] - v0;
                (dv > 0.0).then(|| {
                    let z = p * p / (2.0 * dv);
                    self.dm[j] * self.weight[j] * (2.0 / (PI * dv)).sqrt() * 0.5 * expint_e1(z)
                })
            })
            .sum();
        (gap, self.tail[i0])
    }

    /// [`SpectralNodes::patch_gap`] with the variance at the nodes taken from `sol`.
    pub fn patch_gap_at(&self, sol: &Solution, zeta: f64) -> (f64, f64) {
        let v_nodes: Vec<f64> = self.q.iter().map(|&q| sol.variance_at(q)).collect();
        self.patch_gap(sol, &v_nodes, zeta)
    }

    /// The DMT attraction over the gap distribution, p_att*, of the adhesionless state `sol`:
    /// σ0*·[a_r(q_s) + Σ_ζ Δa_r(ζ) ⟨e^{−u/ρ}⟩_ζ]; `range` = ρ/h_rms, `strength` = σ0* = γ_s/(ρE*ḡ).
    pub fn gap_distribution(&self, sol: &Solution, range: f64, strength: f64) -> f64 {
        let v_nodes: Vec<f64> = self.q.iter().map(|&q| sol.variance_at(q)).collect();
        let mut sum = sol.area_at(*self.zeta.last().unwrap_or(&f64::INFINITY));
        for w in self.zeta.windows(2) {
            let da = (sol.area_at(w[0]) - sol.area_at(w[1])).max(0.0);
            if da <= 0.0 {
                continue;
            }
            let mid = (w[0] * w[1]).sqrt();
            let (gap, s2) = self.patch_gap(sol, &v_nodes, mid);
            if gap.is_finite() {
                sum += da * folded_exponential(gap / range, s2.sqrt() / range);
            }
        }
        strength * sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ∫_0^∞ e^{−u}[φ_s(u−m) + φ_s(u+m)] du by the trapezoid rule on a fine grid.
    fn quadrature(m: f64, s: f64) -> f64 {
        let n = 200_000;
        let top = m + 12.0 * s + 40.0;
        let h = top / n as f64;
        let phi = |x: f64| (-(x * x) / (2.0 * s * s)).exp() / (s * (2.0 * PI).sqrt());
        let f = |u: f64| (-u).exp() * (phi(u - m) + phi(u + m));
        (0..=n)
            .map(|i| {
                let u = i as f64 * h;
                let w = if i == 0 || i == n { 0.5 } else { 1.0 };
                w * f(u)
            })
            .sum::<f64>()
            * h
    }

    #[test]
    fn the_folded_exponential_matches_quadrature_and_its_limits() {
        for &(m, s) in &[(0.0, 0.5), (1.0, 0.3), (3.0, 2.0), (0.2, 5.0), (20.0, 3.0), (2.0, 0.05)] {
            let (a, b) = (folded_exponential(m, s), quadrature(m, s));
            assert!((a / b - 1.0).abs() < 1e-6, "m {m} s {s}: {a} vs {b}");
        }
        assert!((folded_exponential(2.0, 0.0) - (-2.0f64).exp()).abs() < 1e-15);
        assert_eq!(folded_exponential(0.0, 0.0), 1.0);
        // far from the wall and wide: no overflow, positive, below 1
        for &(m, s) in &[(500.0, 40.0), (1e4, 10.0), (30.0, 300.0)] {
            let v = folded_exponential(m, s);
            assert!(v.is_finite() && (0.0..=1.0).contains(&v), "{m} {s}: {v}");
        }
    }

    #[test]
    fn erfcx_is_continuous_where_its_branches_meet() {
        let (a, b) = (erfcx(25.0 - 1e-9), erfcx(25.0 + 1e-9));
        assert!((a / b - 1.0).abs() < 1e-9, "{a} {b}");
        assert!((erfcx(0.0) - 1.0).abs() < 1e-15);
    }
}
