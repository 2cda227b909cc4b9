//! A scene: everything the theory needs for one evaluation, in physical units, plus the
//! reduced quantities derived from it.
//!
//! Reduced units (physics.md §1): stresses σ* = σ/(E*ḡ), pressure p* = p/(E*ḡ), thickness
//! t·q_r. Surface energy γ_s in J/m², range of adhesion ρ in m.

use crate::error::{check_range, Error, Result};
use crate::input::model::Model;
use crate::surface::spectrum::Spectrum;
use crate::theory::slab::slab_factor_at;
use serde::Serialize;

/// Inputs of one evaluation.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// Height spectrum (metres).
    pub spectrum: Spectrum,
    /// Contact modulus E* = E/(1−ν²) in Pa.
    pub modulus: f64,
    /// Slab thickness t·q_r (dimensionless); `f64::INFINITY` = semi-infinite.
    pub thickness_qr: f64,
    /// Model variant.
    pub model: Model,
    /// Reduced nominal pressure p* = p/(E*ḡ).
    pub pressure: f64,
    /// Surface energy γ_s (J/m²); 0 = no adhesion.
    pub gamma: f64,
    /// Range ρ of the adhesive interaction (m).
    pub range: f64,
}

/// Allowed reduced pressures (the engine works in floating point far beyond this; the bounds
/// keep answers meaningful: a_r = 1 to machine precision well before p* = 1e3).
pub const PRESSURE_RANGE: (f64, f64) = (1e-12, 1e3);
/// Allowed t·q_r (besides ∞).
pub const THICKNESS_RANGE: (f64, f64) = (1e-6, 1e12);

impl Scene {
    /// Validates every field, naming it in the error.
    pub fn validate(&self) -> Result<()> {
        if !(self.modulus.is_finite() && self.modulus > 0.0) {
            return Err(Error::field(
                "material.contact_modulus_pa",
                self.modulus,
                "a finite modulus > 0 (Pa)",
            ));
        }
        check_range(
            "pressure",
            self.pressure,
            PRESSURE_RANGE.0,
            PRESSURE_RANGE.1,
            &format!("{:e} <= p* <= {:e}", PRESSURE_RANGE.0, PRESSURE_RANGE.1),
        )?;
        if !self.thickness_qr.is_infinite() {
            check_range(
                "thickness",
                self.thickness_qr,
                THICKNESS_RANGE.0,
                THICKNESS_RANGE.1,
                &format!("{:e} <= t*q_r <= {:e}, or inf", THICKNESS_RANGE.0, THICKNESS_RANGE.1),
            )?;
        } else if self.thickness_qr < 0.0 {
            return Err(Error::field("thickness", self.thickness_qr, "t*q_r > 0, or inf"));
        }
        check_range("gamma", self.gamma, 0.0, 1e3, "0 <= gamma <= 1000 (J/m^2)")?;
        if !(self.range.is_finite() && self.range > 0.0) {
            return Err(Error::field("adhesion.range_m", self.range, "a finite length > 0 (m)"));
        }
        self.model.validate()
    }

    /// Thickness in metres (∞ for a semi-infinite body).
    pub fn thickness_m(&self) -> f64 {
        if self.thickness_qr.is_infinite() {
            f64::INFINITY
        } else {
            self.thickness_qr / self.spectrum.q_r()
        }
    }

    /// ḡ of the spectrum.
    pub fn rms_gradient(&self) -> f64 {
        self.spectrum.rms_gradient()
    }

    /// The unit of reduced stress, E*ḡ (Pa).
    pub fn stress_unit(&self) -> f64 {
        self.modulus * self.rms_gradient()
    }

    /// Slab factor at q (1 for a semi-infinite body, without evaluating it).
    pub fn slab(&self, q: f64) -> f64 {
        slab_factor_at(q, self.thickness_m())
    }

    /// Full-contact elastic energy per area u_ela^(f) = (E*/4) ∫ q f(qt) dm  (J/m²) [S-10, S-24].
    pub fn full_contact_energy(&self) -> f64 {
        let t = self.thickness_m();
        0.25 * self.modulus * self.spectrum.integrate(|q| q * slab_factor_at(q, t))
    }

    /// Global adhesion measure γ̃_glo = γ_s/u_ela^(f) [S-24].
    pub fn gamma_glo(&self) -> f64 {
        if self.gamma == 0.0 {
            0.0
        } else {
            self.gamma / self.full_contact_energy()
        }
    }

    /// Tabor parameter μ_T = R_c^{1/3}(γ_s/E*)^{2/3}/ρ with R_c = 2/κ_L (physics.md §4).
    pub fn tabor(&self) -> f64 {
        let rc = 2.0 / self.spectrum.rms_laplacian();
        rc.powf(1.0 / 3.0) * (self.gamma / self.modulus).powf(2.0 / 3.0) / self.range
    }

    /// The resolved inputs, for output.
    pub fn summary(&self) -> SceneSummary {
        SceneSummary {
            model: self.model.label(),
            model_number: self.model.number(),
            c1: self.model.c1,
            c2: self.model.c2,
            alpha: self.model.alpha,
            k_griffith: self.model.k_griffith,
            sigma_a_cap: self.model.cap,
            pressure: self.pressure,
            pressure_pa: self.pressure * self.stress_unit(),
            thickness_qr: finite_or_none(self.thickness_qr),
            thickness_m: finite_or_none(self.thickness_m()),
            semi_infinite: self.thickness_qr.is_infinite(),
            gamma: self.gamma,
            range_m: self.range,
            gamma_glo: self.gamma_glo(),
            tabor: if self.gamma > 0.0 { self.tabor() } else { 0.0 },
            contact_modulus_pa: self.modulus,
            rms_gradient: self.rms_gradient(),
            rms_height_m: self.spectrum.rms_height(),
            q_l: self.spectrum.q_l(),
            q_r: self.spectrum.q_r(),
            q_s: self.spectrum.q_s(),
        }
    }
}

fn finite_or_none(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

/// Resolved inputs of a scene, as printed by `run` (JSON key `scene`).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SceneSummary {
    /// "model 1".."model 4" or "custom".
    pub model: String,
    /// 1–4, or null for custom.
    pub model_number: Option<u8>,
    /// c₁.
    pub c1: f64,
    /// c₂.
    pub c2: f64,
    /// α.
    pub alpha: f64,
    /// k_G.
    pub k_griffith: f64,
    /// σ_a capped at γ_s/ρ.
    pub sigma_a_cap: bool,
    /// p*.
    pub pressure: f64,
    /// p in Pa.
    pub pressure_pa: f64,
    /// t·q_r, null = semi-infinite.
    pub thickness_qr: Option<f64>,
    /// t in m, null = semi-infinite.
    pub thickness_m: Option<f64>,
    /// true for t = ∞.
    pub semi_infinite: bool,
    /// γ_s (J/m²).
    pub gamma: f64,
    /// ρ (m).
    pub range_m: f64,
    /// γ̃_glo = γ_s/u_ela^(f).
    pub gamma_glo: f64,
    /// Tabor parameter (0 without adhesion).
    pub tabor: f64,
    /// E* (Pa).
    pub contact_modulus_pa: f64,
    /// ḡ.
    pub rms_gradient: f64,
    /// h_rms (m).
    pub rms_height_m: f64,
    /// q_L (1/m).
    pub q_l: f64,
    /// q_r (1/m).
    pub q_r: f64,
    /// q_s (1/m).
    pub q_s: f64,
}
