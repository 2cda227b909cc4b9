//! A scene: everything the theory needs for one evaluation, in physical units, plus the
//! reduced quantities derived from it.
//!
//! Reduced units (physics.md §1): stresses σ* = σ/(E*ḡ), pressure p* = p/(E*ḡ), thickness
//! t·q_r. Surface energy γ_s in J/m², range of adhesion ρ in m.

use crate::elastic::slab::slab_factor_at;
use crate::error::{check_in, fmt_value, Allowed, Error, Field, Range, Result};
use crate::input::model::Model;
use crate::surface::spectrum::Spectrum;
use serde::Serialize;
use std::hash::{Hash, Hasher};

/// The weakest adhesion the theory resolves, as γ̃_glo = γ_s/u_ela^(f): one unit of round-off
/// (f64::EPSILON). The adhesive solver closes the energy balance C + I − γ_s a_r(q_s) = 0,
/// whose terms are up to the full-contact elastic energy I_full ≈ u_ela^(f); a surface energy
/// below one ulp of it cannot move that balance at all, and its walls
/// (σ_a* ∝ √γ_s, at most ~1e-8 p* on systems I and II at p* ≥ 1e-3) are far below any
/// solver's error. Below it [`Scene::is_adhesive`] is false and the adhesionless theory
/// answers (the γ_s → 0 limit; `tests/weak_adhesion.rs` checks the continuity).
pub const WEAK_ADHESION_GLO: f64 = f64::EPSILON;

/// Inputs of one evaluation, in range: built by [`Scene::new`] or a preset
/// ([`crate::input::preset::Preset::scene`]) and changed by the `with_*`/`set_*` setters or
/// [`Scene::apply`], each of which validates what it changes.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// Height spectrum (metres).
    pub(crate) spectrum: Spectrum,
    /// Contact modulus E* = E/(1−ν²) in Pa.
    pub(crate) modulus: f64,
    /// Slab thickness t·q_r (dimensionless); `f64::INFINITY` = semi-infinite.
    pub(crate) thickness_qr: f64,
    /// Model variant.
    pub(crate) model: Model,
    /// Reduced nominal pressure p* = p/(E*ḡ).
    pub(crate) pressure: f64,
    /// Surface energy γ_s (J/m²); 0 = no adhesion.
    pub(crate) gamma: f64,
    /// Range ρ of the adhesive interaction (m).
    pub(crate) range: f64,
}

/// Allowed reduced pressures (the engine works in floating point far beyond this; the bounds
/// keep answers meaningful: a_r = 1 to machine precision well before p* = 1e3).
pub const PRESSURE_RANGE: (f64, f64) = (1e-12, 1e3);
/// Allowed t·q_r (besides ∞).
pub const THICKNESS_RANGE: (f64, f64) = (1e-6, 1e12);
/// Allowed surface energy γ_s (J/m²); 0 = no adhesion.
pub const SURFACE_ENERGY_RANGE: (f64, f64) = (0.0, 1e3);
/// Allowed range ρ of the adhesive interaction (m).
pub const RANGE_RANGE_M: (f64, f64) = (1e-15, 1.0);
/// Allowed contact modulus E* (Pa).
pub const MODULUS_RANGE_PA: (f64, f64) = (1e-3, 1e15);

/// A reduced slab thickness t·q_r: a number > 0, or ∞ for a semi-infinite body.
///
/// Parses `inf`, `infinity`, `∞` (any case) or a number; prints ∞ as `inf`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThicknessQr(pub f64);

impl std::str::FromStr for ThicknessQr {
    type Err = Error;

    /// # Errors
    /// [`Error::Invalid`] for [`Field::Thickness`] when the text is not `inf` or a number in
    /// [`THICKNESS_RANGE`].
    fn from_str(s: &str) -> Result<ThicknessQr> {
        let t = s.trim().to_ascii_lowercase();
        if matches!(t.as_str(), "inf" | "infinity" | "∞" | "+inf" | "+infinity") {
            return Ok(ThicknessQr(f64::INFINITY));
        }
        let allowed = thickness_allowed();
        let v: f64 = t
            .parse()
            .map_err(|_| Error::invalid_text(Field::Thickness, s.trim(), allowed.clone()))?;
        if !(THICKNESS_RANGE.0..=THICKNESS_RANGE.1).contains(&v) {
            return Err(Error::invalid(Field::Thickness, v, allowed));
        }
        Ok(ThicknessQr(v))
    }
}

impl std::fmt::Display for ThicknessQr {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.0.is_infinite() {
            f.write_str("inf")
        } else {
            write!(f, "{}", fmt_value(self.0))
        }
    }
}

/// What t·q_r accepts: [`THICKNESS_RANGE`], or `inf`.
pub fn thickness_allowed() -> Allowed {
    Allowed::RangeOr(Range::closed(THICKNESS_RANGE.0, THICKNESS_RANGE.1), vec!["inf".into()])
}

/// Hashes every input by bit pattern (−0 as +0): equal scenes hash equally, so `Scene` is a
/// cache key (the explorer's).
impl Hash for Scene {
    fn hash<H: Hasher>(&self, h: &mut H) {
        self.hash_without_pressure(h);
        canonical_bits(self.pressure).hash(h);
    }
}

/// A scene is never NaN in any input (every constructor and setter checks its ranges), so
/// equality is an equivalence.
impl Eq for Scene {}

/// The bit pattern of `x` with −0 folded onto +0 (they compare equal).
fn canonical_bits(x: f64) -> u64 {
    (x + 0.0).to_bits()
}

impl Scene {
    /// A validated scene.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the first field out of its range ([`PRESSURE_RANGE`],
    /// [`THICKNESS_RANGE`], [`SURFACE_ENERGY_RANGE`], [`RANGE_RANGE_M`],
    /// [`MODULUS_RANGE_PA`] or a model's); [`Error::Unsupported`] for a variant of the
    /// literature on an adhesive or slab scene.
    pub fn new(
        spectrum: Spectrum,
        contact_modulus_pa: f64,
        model: Model,
        pressure: f64,
        thickness_qr: f64,
        gamma_j_m2: f64,
        range_m: f64,
    ) -> Result<Scene> {
        let s = Scene {
            spectrum,
            modulus: contact_modulus_pa,
            thickness_qr,
            model,
            pressure,
            gamma: gamma_j_m2,
            range: range_m,
        };
        s.validate()?;
        let mut s = s;
        s.resolve_model();
        Ok(s)
    }

    /// Sets the coefficients of a model that follows the scene (model 5: from γ̃_glo, the Tabor
    /// parameter and the bandwidth q_s/q_r, [`crate::input::model_five`]) after an input it
    /// depends on changed.
    pub(crate) fn resolve_model(&mut self) {
        let bandwidth = self.spectrum.q_s() / self.spectrum.q_r();
        let tabor = if self.gamma > 0.0 { self.tabor() } else { 0.0 };
        self.model = self.model.for_scene_at(self.gamma_glo(), tabor, bandwidth);
    }

    /// Hashes every input but the load (the key of a load curve).
    pub fn hash_without_pressure<H: Hasher>(&self, h: &mut H) {
        self.spectrum.hash(h);
        self.model.hash(h);
        for x in [self.modulus, self.thickness_qr, self.gamma, self.range] {
            canonical_bits(x).hash(h);
        }
    }

    /// Validates every field, naming it in the error.
    ///
    /// # Errors
    /// [`Error::Invalid`] for the first of [`Field::ContactModulus`], [`Field::Pressure`],
    /// [`Field::Thickness`], [`Field::SurfaceEnergy`], [`Field::Range`] or a model field that
    /// is out of range.
    pub(crate) fn validate(&self) -> Result<()> {
        check_modulus(self.modulus)?;
        check_pressure(self.pressure)?;
        check_thickness(self.thickness_qr)?;
        check_surface_energy(self.gamma)?;
        check_range(self.range)?;
        self.model.validate()?;
        check_combination(&self.model, self.gamma, self.thickness_qr)
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
            spectrum: self.spectrum.kind().to_string(),
            spectrum_source: match &self.spectrum {
                crate::surface::spectrum::Spectrum::Tabulated(t) => Some(t.source.clone()),
                _ => None,
            },
        }
    }
}

/// Reading a scene's inputs (the fields are private: a scene is validated when it is built or
/// changed, so every `Scene` in hand is in range).
impl Scene {
    /// Height spectrum (metres).
    pub fn spectrum(&self) -> &Spectrum {
        &self.spectrum
    }

    /// Contact modulus E* = E/(1−ν²) in Pa.
    pub fn contact_modulus_pa(&self) -> f64 {
        self.modulus
    }

    /// Slab thickness t·q_r (dimensionless); `f64::INFINITY` for a semi-infinite body.
    pub fn thickness_qr(&self) -> f64 {
        self.thickness_qr
    }

    /// The model variant [S-17].
    pub fn model(&self) -> Model {
        self.model
    }

    /// Reduced nominal pressure p* = p/(E*ḡ).
    pub fn pressure(&self) -> f64 {
        self.pressure
    }

    /// Surface energy γ_s (J/m²); 0 = no adhesion.
    pub fn surface_energy_j_m2(&self) -> f64 {
        self.gamma
    }

    /// Range ρ of the adhesive interaction (m).
    pub fn range_m(&self) -> f64 {
        self.range
    }

    /// Whether adhesion registers in the theory: γ_s above [`WEAK_ADHESION_GLO`] times the
    /// full-contact elastic energy u_ela^(f) (γ̃_glo > ε). A weaker surface energy is below the
    /// round-off of the energy balance the adhesive solver closes, so every evaluation takes
    /// the adhesionless theory, its γ_s → 0 limit (`theory::adhesion`, "Weak adhesion").
    pub fn is_adhesive(&self) -> bool {
        self.gamma > 0.0 && self.gamma > WEAK_ADHESION_GLO * self.full_contact_energy()
    }

    /// The same scene without adhesion (γ_s = 0): the adhesionless twin every adhesive
    /// result is compared with. Always valid.
    pub fn without_adhesion(&self) -> Scene {
        let mut s = Scene {
            gamma: 0.0,
            ..self.clone()
        };
        s.resolve_model();
        s
    }

    /// The same scene on a semi-infinite body (t·q_r = ∞). Always valid.
    pub fn half_space(&self) -> Scene {
        let mut s = Scene {
            thickness_qr: f64::INFINITY,
            ..self.clone()
        };
        s.resolve_model();
        s
    }
}

/// Changing one input: each setter checks its value and the combinations it takes part in,
/// and leaves the scene unchanged on an error. `with_*` consume and return the scene (for
/// chains), `set_*` change it in place. Several inputs at once: [`Scene::apply`].
impl Scene {
    /// With the reduced nominal pressure p*.
    ///
    /// # Errors
    /// [`Error::Invalid`] for [`Field::Pressure`] outside [`PRESSURE_RANGE`].
    pub fn with_pressure(mut self, p: f64) -> Result<Scene> {
        self.set_pressure(p)?;
        Ok(self)
    }

    /// Sets the reduced nominal pressure p* (errors as [`Scene::with_pressure`]).
    ///
    /// # Errors
    /// As [`Scene::with_pressure`].
    pub fn set_pressure(&mut self, p: f64) -> Result<()> {
        check_pressure(p)?;
        self.pressure = p;
        Ok(())
    }

    /// With the slab thickness t·q_r (`f64::INFINITY`: semi-infinite).
    ///
    /// # Errors
    /// [`Error::Invalid`] for [`Field::Thickness`] outside [`THICKNESS_RANGE`] (and not ∞);
    /// [`Error::Unsupported`] for a finite slab with a model defined on the half-space only.
    pub fn with_thickness_qr(mut self, t: f64) -> Result<Scene> {
        self.set_thickness_qr(t)?;
        Ok(self)
    }

    /// Sets t·q_r.
    ///
    /// # Errors
    /// As [`Scene::with_thickness_qr`].
    pub fn set_thickness_qr(&mut self, t: f64) -> Result<()> {
        check_thickness(t)?;
        check_combination(&self.model, self.gamma, t)?;
        self.thickness_qr = t;
        self.resolve_model();
        Ok(())
    }

    /// With the surface energy γ_s in J/m² (0: no adhesion).
    ///
    /// # Errors
    /// [`Error::Invalid`] for [`Field::SurfaceEnergy`] outside [`SURFACE_ENERGY_RANGE`];
    /// [`Error::Unsupported`] for adhesion with a model that defines none.
    pub fn with_surface_energy_j_m2(mut self, gamma: f64) -> Result<Scene> {
        self.set_surface_energy_j_m2(gamma)?;
        Ok(self)
    }

    /// Sets γ_s in J/m².
    ///
    /// # Errors
    /// As [`Scene::with_surface_energy_j_m2`].
    pub fn set_surface_energy_j_m2(&mut self, gamma: f64) -> Result<()> {
        check_surface_energy(gamma)?;
        check_combination(&self.model, gamma, self.thickness_qr)?;
        self.gamma = gamma;
        self.resolve_model();
        Ok(())
    }

    /// With the range ρ of the adhesive interaction in m.
    ///
    /// # Errors
    /// [`Error::Invalid`] for [`Field::Range`] outside [`RANGE_RANGE_M`].
    pub fn with_range_m(mut self, range: f64) -> Result<Scene> {
        self.set_range_m(range)?;
        Ok(self)
    }

    /// Sets ρ in m.
    ///
    /// # Errors
    /// As [`Scene::with_range_m`].
    pub fn set_range_m(&mut self, range: f64) -> Result<()> {
        check_range(range)?;
        self.range = range;
        Ok(())
    }

    /// With the contact modulus E* in Pa.
    ///
    /// # Errors
    /// [`Error::Invalid`] for [`Field::ContactModulus`] outside [`MODULUS_RANGE_PA`].
    pub fn with_contact_modulus_pa(mut self, modulus: f64) -> Result<Scene> {
        self.set_contact_modulus_pa(modulus)?;
        Ok(self)
    }

    /// Sets E* in Pa.
    ///
    /// # Errors
    /// As [`Scene::with_contact_modulus_pa`].
    pub fn set_contact_modulus_pa(&mut self, modulus: f64) -> Result<()> {
        check_modulus(modulus)?;
        self.modulus = modulus;
        self.resolve_model();
        Ok(())
    }

    /// With the model variant.
    ///
    /// # Errors
    /// A model field out of range; [`Error::Unsupported`] for a model defined on the
    /// adhesionless half-space only on an adhesive or slab scene.
    pub fn with_model(mut self, model: Model) -> Result<Scene> {
        self.set_model(model)?;
        Ok(self)
    }

    /// Sets the model variant.
    ///
    /// # Errors
    /// As [`Scene::with_model`].
    pub fn set_model(&mut self, model: Model) -> Result<()> {
        model.validate()?;
        check_combination(&model, self.gamma, self.thickness_qr)?;
        self.model = model;
        self.resolve_model();
        Ok(())
    }

    /// With the height spectrum (a spectrum is validated when it is built).
    ///
    /// # Errors
    /// None today; kept a `Result` like every setter.
    pub fn with_spectrum(mut self, spectrum: Spectrum) -> Result<Scene> {
        self.set_spectrum(spectrum)?;
        Ok(self)
    }

    /// Sets the height spectrum.
    ///
    /// # Errors
    /// As [`Scene::with_spectrum`].
    pub fn set_spectrum(&mut self, spectrum: Spectrum) -> Result<()> {
        self.spectrum = spectrum;
        self.resolve_model();
        Ok(())
    }
}

fn check_pressure(p: f64) -> Result<()> {
    check_in(Field::Pressure, p, PRESSURE_RANGE.0, PRESSURE_RANGE.1).map(|_| ())
}

fn check_thickness(t: f64) -> Result<()> {
    if t == f64::INFINITY || (THICKNESS_RANGE.0..=THICKNESS_RANGE.1).contains(&t) {
        Ok(())
    } else {
        Err(Error::invalid(Field::Thickness, t, thickness_allowed()))
    }
}

fn check_surface_energy(gamma: f64) -> Result<()> {
    check_in(
        Field::SurfaceEnergy,
        gamma,
        SURFACE_ENERGY_RANGE.0,
        SURFACE_ENERGY_RANGE.1,
    )
    .map(|_| ())
}

fn check_range(range: f64) -> Result<()> {
    check_in(Field::Range, range, RANGE_RANGE_M.0, RANGE_RANGE_M.1).map(|_| ())
}

fn check_modulus(modulus: f64) -> Result<()> {
    check_in(Field::ContactModulus, modulus, MODULUS_RANGE_PA.0, MODULUS_RANGE_PA.1).map(|_| ())
}

/// The variants of the literature define neither adhesion nor slabs: refuse rather than guess.
fn check_combination(model: &Model, gamma: f64, thickness_qr: f64) -> Result<()> {
    if model.kind.is_fudge_variant() && (gamma > 0.0 || thickness_qr.is_finite()) {
        return Err(Error::Unsupported(format!(
            "{} is defined for the adhesionless half-space only (surface energy 0, thickness inf)",
            model.label()
        )));
    }
    Ok(())
}

fn finite_or_none(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

/// Resolved inputs of a scene, as printed by `run` (JSON key `scene`).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SceneSummary {
    /// "model 1".."model 5" or "custom".
    pub model: String,
    /// 1–5, or null for custom.
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
    /// The spectrum the theory ran on: "self-affine" (the preset's), "tabulated" (a PSD table
    /// or a measured map's PSD) or "discrete" (a map's own modes).
    pub spectrum: String,
    /// The file a tabulated spectrum came from (null otherwise).
    pub spectrum_source: Option<String>,
}
