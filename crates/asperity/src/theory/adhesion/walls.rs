//! The walls: the Griffith stress σ_a(q) [S-8] for the scale-dependent surface energy γ(q)
//! of the energy balance [S-9, S-14].
//!
//! ```text
//! σ_a(q) = k_G √(q E* f(qt) γ(q)),  γ < 0 → 0,  capped at γ_s/ρ where the model says so
//! ```
//!
//! Each step's wall is the mean of σ_a over the step with γ linear between the nodes (the
//! mean of √γ₊ in closed form), so that the march stays smooth where γ turns positive.

use super::grid::Grid;
use crate::input::scene::Scene;
use crate::theory::slab::slab_factor_at;

/// The constants of σ_a* = min(k_G √(q E* f γ), cap)/unit at the step midpoints.
pub(super) struct WallCoefficients {
    /// k_G √(q_mid E* f(q_mid t))/unit per step (σ_a* per √γ).
    pub(super) per_sqrt_gamma: Vec<f64>,
    /// The cap γ_s/ρ in reduced units (∞ where the model has none).
    pub(super) cap: f64,
}

impl WallCoefficients {
    pub(super) fn new(scene: &Scene, grid: &Grid) -> Self {
        WallCoefficients {
            per_sqrt_gamma: grid.steps.iter().map(|s| per_sqrt_gamma(scene, s.q_mid)).collect(),
            cap: cap(scene),
        }
    }

    /// The wall of step k for γ (J/m²) g0 at its start and g1 at its end.
    pub(super) fn mid(&self, k: usize, g0: f64, g1: f64) -> f64 {
        (self.per_sqrt_gamma[k] * mean_sqrt_positive(g0, g1)).min(self.cap)
    }
}

/// k_G √(q E* f(qt))/unit: σ_a* per √γ at wave number q.
fn per_sqrt_gamma(scene: &Scene, q: f64) -> f64 {
    scene.model.k_griffith * (q * scene.modulus * slab_factor_at(q, scene.thickness_m())).sqrt() / scene.stress_unit()
}

/// The cap γ_s/ρ of σ_a* (∞ where the model has none).
fn cap(scene: &Scene) -> f64 {
    if scene.model.cap {
        scene.gamma / scene.range / scene.stress_unit()
    } else {
        f64::INFINITY
    }
}

/// σ_a* at wave number q for γ (J/m²; ≤ 0: no wall).
pub(super) fn sigma_at(scene: &Scene, q: f64, gamma: f64) -> f64 {
    if gamma <= 0.0 {
        0.0
    } else {
        (per_sqrt_gamma(scene, q) * gamma.sqrt()).min(cap(scene))
    }
}

/// The mean over s ∈ [0, 1] of √max(0, g₀ + (g₁ − g₀)s).
fn mean_sqrt_positive(g0: f64, g1: f64) -> f64 {
    let (lo, hi) = (g0.min(g1), g0.max(g1));
    if hi <= 0.0 {
        return 0.0;
    }
    if hi - lo <= 1e-12 * hi {
        return (0.5 * (lo + hi)).max(0.0).sqrt();
    }
    let lo_part = if lo > 0.0 { lo * lo.sqrt() } else { 0.0 };
    2.0 / 3.0 * (hi * hi.sqrt() - lo_part) / (hi - lo)
}
