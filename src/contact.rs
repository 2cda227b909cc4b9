//! The result currency: what every solver says about a contact.
//!
//! [`ContactStats`] is embedded (serde-flattened, so its keys sit at the top level of a JSON
//! object) in every result that describes one contact: the theory's
//! [`crate::theory::engine::Evaluation`], GFMD's [`crate::gfmd::Measurements`] and
//! [`crate::gfmd::GfmdResult`], and the theory on a GFMD map,
//! [`crate::gfmd::TheoryComparison`]. Adding a contact quantity means adding it here once.
//!
//! Conventions (docs/physics.md §1): stresses are reduced by E*ḡ, σ* = σ/(E*ḡ); Pr(σ*) is
//! the distribution of interfacial stress normalised so that ∫Pr dσ* = a_r; the mean contact
//! stress is σ̄_c* = ∫σ* Pr dσ*/a_r and, by force balance without adhesion, a_r·σ̄_c* = p*
//! [S-2]; the variance is ⟨δσ_c²⟩* = ∫(σ* − σ̄_c*)² Pr dσ*/a_r, reduced by (E*ḡ)².

use serde::Serialize;

/// Pr(σ*) sampled on a grid (reduced units; ∫density dσ* = a_r).
#[derive(Debug, Clone, Serialize, PartialEq, Default)]
pub struct PrCurve {
    /// σ* grid (ascending; starts at −σ_a* when adhesion is on).
    pub sigma: Vec<f64>,
    /// Pr(σ*).
    pub density: Vec<f64>,
}

impl PrCurve {
    /// The curve as (σ*, Pr) points, for plotting.
    pub fn points(&self) -> Vec<(f64, f64)> {
        self.sigma.iter().copied().zip(self.density.iter().copied()).collect()
    }

    /// ∫Pr dσ* by the trapezoidal rule (equals a_r up to the sampling error).
    pub fn integral(&self) -> f64 {
        self.sigma
            .windows(2)
            .zip(self.density.windows(2))
            .map(|(s, d)| 0.5 * (s[1] - s[0]) * (d[0] + d[1]))
            .sum()
    }
}

/// The statistics of one contact, whichever solver produced them.
#[derive(Debug, Clone, Serialize, PartialEq, Default)]
pub struct ContactStats {
    /// Relative contact area a_r (at full resolution, q = q_s, for the theory; the fraction of
    /// nodes in contact for GFMD).
    pub a_r: f64,
    /// σ̄_c*, the mean stress in the contact (reduced by E*ḡ).
    pub mean_contact_stress: f64,
    /// ⟨δσ_c²⟩*, the variance of the contact stress (reduced by (E*ḡ)²).
    pub contact_stress_variance: f64,
    /// Pr(σ*), ∫density dσ* = a_r.
    pub pr: PrCurve,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integral_of_a_box_is_its_area() {
        let pr = PrCurve {
            sigma: vec![0.0, 1.0, 2.0],
            density: vec![0.5, 0.5, 0.5],
        };
        assert!((pr.integral() - 1.0).abs() < 1e-15);
        assert_eq!(pr.points()[1], (1.0, 0.5));
    }
}
