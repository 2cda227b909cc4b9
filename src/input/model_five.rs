//! Model 5: the weight function gauged once on asperity's GFMD reference set, as a function of
//! the scene's global adhesion γ̃_glo = γ_s/u_ela^(f) [S-24] and its Tabor parameter μ_T
//! (docs/physics.md §3.6).
//!
//! \[S\]'s models 3 and 4 fix W(a) = 1 − c₁(1 − a²) − c₂(1 − a⁴) [S-17] and the broadening
//! exponent α [S-15] once for all scenes; gauged per thickness on GFMD, model 4's W(0) has to
//! rise with the slab's γ̃_glo (physics.md §3.5). Model 5 makes that rise the model:
//!
//! ```text
//! m     = γ̃_glo·μ_T^κ,  κ = ½                                  the adhesion measure
//! s(γ̃)  = 1 − exp(−γ̃_glo/γ_c)                                 crossover from no adhesion
//! w₀(m) = min(max(w_f, w_b + w_s·m), 1)                        W(0) of the adhesive weight
//! c₁    = (1 − s)·(−2/9) + s·(1 − w₀)
//! c₂    = (1 − s)·(2/3)
//! α     = (1 − s)·½ + s·¼,        k_G = 2,  σ_a capped at γ_s/ρ
//! ```
//!
//! At γ̃ = 0 these are model 3's coefficients exactly (the adhesionless scenes keep \[S\]'s gauge
//! on eq. (18) and Table 1); once adhesion counts (γ̃ ≫ γ_c) W is model 4's form
//! w₀ + (1 − w₀)a² with α = ¼ and w₀ growing linearly with m. γ_c is a continuity scale, not a
//! fitted number: the set's smallest adhesive γ̃_glo is 0.05, so it cannot resolve the
//! crossover; the floor w_f, w_b and w_s are fitted jointly on every adhesive case of the set
//! ([`crate::fit::set_gauge`]), and cross-validated by leaving one thickness and one γ_s out.
//! κ was chosen by a scan (κ ∈ {0, ¼, ½, ¾, 1}): with κ = ½ one gauge serves the bandwidths
//! λ_r/λ_s = 32, 64 and 128 nearly unchanged, where with κ = 0 (γ̃_glo alone) it had to move by
//! a third per octave.
//!
//! γ̃_glo and μ_T are the scene's, and both are kept by the reduction to a GFMD grid.
//! The bandwidth B = q_s/q_r is not kept, so a second stage ([`crate::fit::bandwidth_gauge`],
//! on GFMD at 512² and 1024²) moves each of w_b, w_s, w_f linearly in the octaves
//! ℓ = log₂(B/16), clamped to [0, 3]:
//!
//! ```text
//! w_b(ℓ) = w_b + ℓ·δw_b,   w_s(ℓ) = w_s + ℓ·δw_s,   w_f(ℓ) = w_f + ℓ·δw_f
//! ```
//!
//! with the steps of [`PER_OCTAVE`]. Outside λ_r/λ_s ∈ [16/1.5, 128·1.5] the trust read-out
//! says the gauge was not checked ([`crate::fit::trust::assess`]).

use super::model::{Model, ModelKind};

/// w_b: W(0) of the adhesive weight extrapolated to m → 0 (fitted, [`crate::fit::set_gauge`]).
pub const W0_BASE: f64 = 0.0730;
/// w_s: the rise of W(0) per unit of the adhesion measure m (fitted).
pub const W0_SLOPE: f64 = 0.6888;
/// γ_c: the γ̃_glo over which the weight crosses from model 3 to the adhesive form.
pub const CROSSOVER: f64 = 0.01;
/// w_f: the floor of W(0) at weak adhesion (fitted).
pub const W0_FLOOR: f64 = 0.125;
/// The smallest floor a gauge may have (keeps W^{2α} away from 0).
pub const W0_MIN: f64 = 0.05;
/// κ: the power of the Tabor parameter in the adhesion measure m = γ̃_glo·μ_T^κ that W(0)
/// rises with (chosen by a scan over κ ∈ {0, ¼, ½, ¾, 1}, physics.md §3.6).
pub const TABOR_EXPONENT: f64 = 0.5;

/// The adhesion measure m = γ̃_glo·μ_T^κ that model 5's W(0) rises with: the global adhesion
/// [S-24] weighted by the Tabor parameter μ_T (physics.md §4), both kept by the reduction to a
/// GFMD grid. A μ_T that is not a finite number ≥ 0 counts as 1 (the measure is then γ̃_glo).
pub fn adhesion_measure(gamma_glo: f64, tabor: f64) -> f64 {
    let t = if tabor.is_finite() && tabor >= 0.0 { tabor } else { 1.0 };
    gamma_glo * t.powf(TABOR_EXPONENT)
}

/// The gauge's three fitted numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gauge {
    /// w_b.
    pub base: f64,
    /// w_s.
    pub slope: f64,
    /// w_f.
    pub floor: f64,
}

/// The stored gauge at the set's bandwidth λ_r/λ_s = [`SET_BANDWIDTH`].
pub const GAUGE: Gauge = Gauge {
    base: W0_BASE,
    slope: W0_SLOPE,
    floor: W0_FLOOR,
};

/// λ_r/λ_s = q_s/q_r of the reference set's 256² maps, where [`GAUGE`] was fitted.
pub const SET_BANDWIDTH: f64 = 16.0;

/// The widest bandwidth the gauge's octave dependence was measured to (GFMD at 2048², the
/// paper's λ_r/λ_s = 128); beyond it the gauge is held at its value there.
pub const BANDWIDTH_MEASURED: f64 = 128.0;

/// The change of the gauge per octave of bandwidth (fitted on the bandwidth set,
/// [`crate::fit::set_gauge`]): w_b, w_s and w_f move by these per doubling of λ_r/λ_s.
pub const PER_OCTAVE: Gauge = Gauge {
    base: 0.0023,
    slope: -0.0024,
    floor: 0.0411,
};

/// Octaves ℓ = log₂(B/16) of a bandwidth B = q_s/q_r above the set's, clamped to the measured
/// range [0, log₂(128/16) = 3] (a bandwidth that is not a finite positive number counts as the
/// set's).
pub fn octaves(bandwidth: f64) -> f64 {
    if !(bandwidth.is_finite() && bandwidth > 0.0) {
        return 0.0;
    }
    (bandwidth / SET_BANDWIDTH)
        .log2()
        .clamp(0.0, (BANDWIDTH_MEASURED / SET_BANDWIDTH).log2())
}

/// Model 5's gauge over bandwidths: the gauge at the set's bandwidth and its change per octave,
/// each of w_b, w_s, w_f linear in ℓ = [`octaves`]`(B)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BandwidthGauge {
    /// The gauge at λ_r/λ_s = [`SET_BANDWIDTH`].
    pub at_set: Gauge,
    /// Its change per octave.
    pub per_octave: Gauge,
}

/// The stored gauge over bandwidths.
pub const BANDWIDTH_GAUGE: BandwidthGauge = BandwidthGauge {
    at_set: GAUGE,
    per_octave: PER_OCTAVE,
};

impl BandwidthGauge {
    /// The gauge at bandwidth `bandwidth` = q_s/q_r.
    pub fn at(&self, bandwidth: f64) -> Gauge {
        let l = octaves(bandwidth);
        let (a, d) = (self.at_set, self.per_octave);
        Gauge {
            base: a.base + l * d.base,
            slope: a.slope + l * d.slope,
            floor: a.floor + l * d.floor,
        }
    }

    /// Model 5 at global adhesion `gamma_glo`, Tabor parameter `tabor` and bandwidth
    /// `bandwidth`.
    pub fn model(&self, gamma_glo: f64, tabor: f64, bandwidth: f64) -> Model {
        self.at(bandwidth).model(gamma_glo, tabor)
    }
}

impl Gauge {
    /// c₁, c₂ and α of model 5 at global adhesion `gamma_glo` and Tabor parameter `tabor`
    /// (see the module docs).
    pub fn coefficients(&self, gamma_glo: f64, tabor: f64) -> (f64, f64, f64) {
        let g = if gamma_glo.is_finite() { gamma_glo.max(0.0) } else { 0.0 };
        let s = 1.0 - (-g / CROSSOVER).exp();
        let w0 = self.w0(adhesion_measure(g, tabor));
        let c1 = (1.0 - s) * (-2.0 / 9.0) + s * (1.0 - w0);
        let c2 = (1.0 - s) * (2.0 / 3.0);
        let alpha = (1.0 - s) * 0.5 + s * 0.25;
        (c1, c2, alpha)
    }

    /// W(0) of the adhesive weight at the adhesion measure `measure` = m
    /// ([`adhesion_measure`]): min(max(w_f, w_b + w_s·m), 1).
    pub fn w0(&self, measure: f64) -> f64 {
        (self.base + self.slope * measure).max(self.floor.max(W0_MIN)).min(1.0)
    }

    /// Model 5 with this gauge's coefficients at `gamma_glo` and `tabor`.
    pub fn model(&self, gamma_glo: f64, tabor: f64) -> Model {
        let (c1, c2, alpha) = self.coefficients(gamma_glo, tabor);
        Model {
            kind: ModelKind::Five,
            c1,
            c2,
            alpha,
            k_griffith: 2.0,
            cap: true,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn without_adhesion_it_is_model_3() {
        let m = GAUGE.model(0.0, 0.0);
        let m3 = Model::named(3).unwrap();
        assert_eq!(
            (m.c1, m.c2, m.alpha, m.k_griffith, m.cap),
            (m3.c1, m3.c2, m3.alpha, m3.k_griffith, m3.cap)
        );
    }

    #[test]
    fn with_adhesion_it_is_model_4s_form_with_w0_rising() {
        for g in [0.2, 0.5, 1.0] {
            let m = GAUGE.model(g, 1.0);
            let w0 = GAUGE.w0(g);
            assert!((m.w(0.0) - w0).abs() < 1e-6, "W(0) at γ̃ {g}");
            assert!((m.w(1.0) - 1.0).abs() < 1e-12);
            assert!((m.alpha - 0.25).abs() < 1e-6);
            m.validate().unwrap();
        }
        // valid all the way; W(0) monotone where the linear rise is above the floor (below, the
        // crossover's model 3 share e^{−γ̃/γ_c} still decays)
        let mut last = f64::NEG_INFINITY;
        for k in 0..=400 {
            let g = 2.0 * k as f64 / 400.0;
            let m = GAUGE.model(g, 1.0);
            m.validate().unwrap();
            if g > 0.2 {
                assert!(m.w(0.0) >= last - 1e-12);
                last = m.w(0.0);
            }
        }
    }
}
