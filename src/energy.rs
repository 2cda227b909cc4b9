//! Elastic energy of the interface per unit nominal area [S-11, S-14]:
//!
//! ```text
//! U = −a_r(q_s)·γ_s + Σ_q u_ela(q),   u_ela(q) = a_r(q)·W(a_r(q))·(qE*f(qt)/4)·|h̃(q)|²
//!   = −a_r(q_s)·γ_s + (E*/4) ∫ a_r(q) W(a_r(q)) q f(qt) dm(q)        (J/m²)
//! ```
//!
//! with dm = 2πqC(q)dq (the spectrum's height-variance measure). a_r(q) comes from whichever
//! solver produced the scene's solution (adhesionless ODE or the adhesive fixed point).
//! Reduced energy: U* = U/(E*ḡ·h_rms), so that p*·(ū/h_rms) has the same unit.

use crate::scene::Scene;
use crate::spectrum::PANEL_WIDTH_LN;

/// U in J/m² for a given a_r(q) (evaluated on the spectrum's quadrature nodes).
pub fn elastic_energy(scene: &Scene, a_of_q: impl Fn(f64) -> f64) -> f64 {
    let t = scene.thickness_m();
    let nodes = scene.spectrum.nodes(PANEL_WIDTH_LN);
    let mut sum = 0.0;
    for m in &nodes {
        let a = a_of_q(m.q);
        sum += a * scene.model.w(a) * m.q * crate::slab::slab_factor_at(m.q, t) * m.dm;
    }
    let a_s = a_of_q(scene.spectrum.q_s());
    0.25 * scene.modulus * sum - a_s * scene.gamma
}

/// The unit of reduced energy E*ḡ·h_rms (J/m²).
pub fn energy_unit(scene: &Scene) -> f64 {
    scene.stress_unit() * scene.spectrum.rms_height()
}
