//! The walls: γ(q) from the energy balance [S-9, S-14] and the Griffith stress σ_a(q) [S-8]
//! for a given a_r(q) at the nodes.
//!
//! ```text
//! a_r(q)γ(q) = a_r(q_s)γ_s − ∫_q^{q_s} a_r W(a_r) (q'E* f/4) dm(q'),  γ < 0 → 0
//! σ_a(q) = k_G √(q E* f(qt) γ(q)),  capped at γ_s/ρ where the model says so
//! ```
//!
//! Each step's wall is the mean of σ_a over the step with γ linear between the nodes (the
//! mean of √γ₊ in closed form), so that the fixed-point map stays smooth where γ turns positive.

use super::grid::Grid;
use crate::input::scene::Scene;
use crate::theory::slab::slab_factor_at;

/// γ(q) and σ_a*(q): at the step midpoints (walls) and at the nodes, for a_r at the nodes.
pub(super) struct Walls {
    pub(super) mid: Vec<f64>,
    pub(super) gamma_nodes: Vec<f64>,
    pub(super) sigma_nodes: Vec<f64>,
    /// Σ a W e over all steps (J/m²).
    pub(super) energy: f64,
}

pub(super) fn walls_for(scene: &Scene, grid: &Grid, a: &[f64]) -> Walls {
    let k = grid.steps.len();
    let model = scene.model;
    let gs = scene.gamma;
    let unit = scene.stress_unit();
    let t = scene.thickness_m();
    let cap = if model.cap { gs / scene.range } else { f64::INFINITY };
    // E at nodes, from the top
    let mut e_node = vec![0.0; k + 1];
    for j in (0..k).rev() {
        let am = 0.5 * (a[j] + a[j + 1]);
        e_node[j] = e_node[j + 1] + am * model.w(am) * grid.steps[j].e;
    }
    let top = a[k] * gs;
    let sigma_of = |q: f64, gamma: f64| -> f64 {
        if gamma <= 0.0 {
            return 0.0;
        }
        let s = model.k_griffith * (q * scene.modulus * slab_factor_at(q, t) * gamma).sqrt();
        s.min(cap) / unit
    };
    let gamma_of = |e: f64, am: f64| -> f64 {
        if am <= 0.0 {
            0.0
        } else {
            ((top - e) / am).max(0.0)
        }
    };
    // the wall of each step is its mean over the step: σ_a ∝ √γ rises like a square root
    // where γ(q) turns positive, and a midpoint sample would make the wall (and the fixed-point
    // map) jump each time that onset crosses a midpoint; with γ linear between the nodes the
    // mean of √γ₊ is exact and the onset enters as γ^{3/2}, smoothly
    let gamma_raw = |j: usize| -> f64 {
        if a[j] <= 0.0 {
            -1.0
        } else {
            (top - e_node[j]) / a[j]
        }
    };
    let mut mid = Vec::with_capacity(k);
    for j in 0..k {
        let q = grid.steps[j].q_mid;
        let ms = mean_sqrt_positive(gamma_raw(j), gamma_raw(j + 1));
        let s = model.k_griffith * (q * scene.modulus * slab_factor_at(q, t)).sqrt() * ms;
        mid.push(s.min(cap) / unit);
    }
    let gamma_nodes: Vec<f64> = (0..=k).map(|j| gamma_of(e_node[j], a[j])).collect();
    let sigma_nodes = (0..=k).map(|j| sigma_of(grid.q[j], gamma_nodes[j])).collect();
    Walls {
        mid,
        gamma_nodes: gamma_nodes
            .iter()
            .map(|g| if gs > 0.0 { g / gs } else { 0.0 })
            .collect(),
        sigma_nodes,
        energy: e_node[0],
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
