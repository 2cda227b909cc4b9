//! Elastic energy of the interface per unit nominal area [S-11, S-14]:
//!
//! ```text
//! U = −a_r(q_s)·γ_s + Σ_q u_ela(q),   u_ela(q) = a_r(q)·W(a_r(q))·(qE*f(qt)/4)·|h̃(q)|²
//!   = −a_r(q_s)·γ_s + (E*/4) ∫ a_r(q) W(a_r(q)) q f(qt) dm(q)        (J/m²)
//! ```
//!
//! with dm = 2πqC(q)dq (the spectrum's height-variance measure). a_r(q) comes from whichever
//! solver produced the scene's solution (adhesionless ODE or the adhesive self-consistent solution).
//! Reduced energy: U* = U/(E*ḡ·h_rms), so that p*·(ū/h_rms) has the same unit.
//!
//! Quadrature: near q_L the variance grows linearly, V ∝ q − q_L, so at small load
//! a_r(q) ≈ p/√(2V) ∝ (q − q_L)^{−1/2}: an end-point singularity that Gauss panels in ln q
//! integrate only to ~1e-4. The first segment of a continuum spectrum is therefore integrated
//! with 8-point panels of width 1 in ln(q − q_L) (down to 1e-16 of its width, where the
//! neglected part is < 1e-8 relative), which makes the integrand smooth; the other segments use
//! the spectrum's panels ([`crate::surface::spectrum::Spectrum::nodes`]).

use crate::input::scene::Scene;
use crate::surface::spectrum::{Mode, Spectrum, GL8, PANEL_WIDTH_LN};

/// Quadrature nodes (q, dm) for the energy integral (see the module docs).
pub fn energy_nodes(spectrum: &Spectrum) -> Vec<Mode> {
    if !spectrum.is_continuum() {
        return spectrum.nodes(PANEL_WIDTH_LN);
    }
    let bp = spectrum.breakpoints();
    let (lo, hi) = (bp[0], bp[1]);
    let (ya, yb) = (((hi - lo) * 1e-16).ln(), (hi - lo).ln());
    let panels = (yb - ya).ceil() as usize;
    let h = (yb - ya) / panels as f64;
    let mut out = Vec::with_capacity(panels * 8 + 400);
    for k in 0..panels {
        let mid = ya + (k as f64 + 0.5) * h;
        let signed = GL8.iter().rev().map(|&(x, w)| (-x, w)).chain(GL8.iter().copied());
        for (x, wt) in signed {
            let d = (mid + 0.5 * h * x).exp();
            let q = (lo + d).min(hi);
            // dm = 2πqC dq, dq = d·du
            let c = match spectrum {
                Spectrum::SelfAffine(sa) if bp.len() > 2 => sa.c0,
                other => other.psd(q),
            };
            out.push(Mode {
                q,
                dm: 0.5 * h * wt * 2.0 * std::f64::consts::PI * q * c * d,
            });
        }
    }
    // the remaining segments: the spectrum's own panels after those of the first segment
    let first = ((hi.ln() - lo.ln()) / PANEL_WIDTH_LN).ceil().max(1.0) as usize * 8;
    out.extend(spectrum.nodes(PANEL_WIDTH_LN).into_iter().skip(first));
    out
}

/// U in J/m² for a given a_r(q) (evaluated on [`energy_nodes`]).
pub fn elastic_energy(scene: &Scene, a_of_q: impl Fn(f64) -> f64) -> f64 {
    let t = scene.thickness_m();
    let nodes = energy_nodes(&scene.spectrum);
    let mut sum = 0.0;
    for m in &nodes {
        let a = a_of_q(m.q);
        sum += a * scene.model.w(a) * m.q * crate::theory::slab::slab_factor_at(m.q, t) * m.dm;
    }
    let a_s = a_of_q(scene.spectrum.q_s());
    0.25 * scene.modulus * sum - a_s * scene.gamma
}

/// The unit of reduced energy E*ḡ·h_rms (J/m²).
pub fn energy_unit(scene: &Scene) -> f64 {
    scene.stress_unit() * scene.spectrum.rms_height()
}
