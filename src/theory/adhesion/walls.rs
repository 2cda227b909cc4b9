//! The walls: the Griffith stress σ_a(q) [S-8] for the scale-dependent surface energy γ(q)
//! of the energy balance [S-9, S-14].
//!
//! ```text
//! σ_a(q) = k_G √(q E* f(qt) γ(q)),  γ < 0 → 0,  capped at γ_s/ρ where the model says so
//! ```
//!
//! The propagator takes the wall at the nodes q_k and moves it linearly in v between them
//! (a constant drift per step, `propagator`): second order in the step.

use super::grid::Grid;
use crate::input::scene::Scene;
use crate::theory::slab::slab_factor_at;

/// The constants of σ_a* = min(k_G √(q E* f γ), cap)/unit at the nodes.
pub(super) struct WallCoefficients {
    /// k_G √(q_k E* f(q_k t))/unit at the nodes q_k (σ_a* per √γ).
    pub(super) per_sqrt_gamma_node: Vec<f64>,
    /// The cap γ_s/ρ in reduced units (∞ where the model has none).
    pub(super) cap: f64,
}

impl WallCoefficients {
    pub(super) fn new(scene: &Scene, grid: &Grid) -> Self {
        WallCoefficients {
            per_sqrt_gamma_node: grid.q.iter().map(|&q| per_sqrt_gamma(scene, q)).collect(),
            cap: cap(scene),
        }
    }

    /// The wall at node k (the end of step k − 1) for γ (J/m²; ≤ 0: no wall).
    pub(super) fn node(&self, k: usize, g: f64) -> f64 {
        if g <= 0.0 {
            0.0
        } else {
            (self.per_sqrt_gamma_node[k] * g.sqrt()).min(self.cap)
        }
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
