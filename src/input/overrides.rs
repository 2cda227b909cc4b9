//! Overrides of a scene: the inputs a front end changes on a preset's scene (command-line
//! flags, a tour's step, the explorer's knobs), applied and validated together.
//!
//! Units as in [`Scene`]: p* reduced by E*ḡ, t·q_r reduced by the roll-off wave number
//! (∞ for a semi-infinite body), γ_s in J/m², ρ in m, E* in Pa.

use crate::error::Result;
use crate::input::model::Model;
use crate::input::scene::Scene;
use crate::surface::spectrum::Spectrum;

/// What to change on a scene; `None` keeps the scene's value.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Overrides {
    /// The model variant.
    pub model: Option<Model>,
    /// Reduced nominal pressure p*.
    pub pressure: Option<f64>,
    /// Slab thickness t·q_r (`f64::INFINITY` for a semi-infinite body).
    pub thickness_qr: Option<f64>,
    /// Surface energy γ_s (J/m²); 0 switches adhesion off.
    pub surface_energy_j_m2: Option<f64>,
    /// Range ρ of the adhesive interaction (m).
    pub range_m: Option<f64>,
    /// Contact modulus E* (Pa).
    pub contact_modulus_pa: Option<f64>,
    /// The height spectrum (a measured surface's, a PSD table's).
    pub spectrum: Option<Spectrum>,
}

impl Overrides {
    /// Whether nothing is overridden.
    pub fn is_empty(&self) -> bool {
        *self == Overrides::default()
    }
}

impl Scene {
    /// This scene with `o` applied, validated once as a whole (so that, e.g., a model that
    /// needs a semi-infinite body and the thickness that makes it one may change together).
    ///
    /// # Errors
    /// [`crate::Error::Invalid`] naming the first field out of its range, or
    /// [`crate::Error::Unsupported`] for a combination no model defines (see
    /// [`Scene::new`]).
    ///
    /// # Examples
    /// ```
    /// use asperity::input::overrides::Overrides;
    /// use asperity::input::preset::Preset;
    ///
    /// let scene = Preset::resolve("system-2").unwrap().scene().unwrap();
    /// let thin = scene
    ///     .apply(&Overrides { thickness_qr: Some(0.3), pressure: Some(1e-3), ..Overrides::default() })
    ///     .unwrap();
    /// assert_eq!((thin.thickness_qr(), thin.pressure()), (0.3, 1e-3));
    /// // a value out of range names its field and the range
    /// let bad = scene.apply(&Overrides { pressure: Some(-1.0), ..Overrides::default() });
    /// assert!(bad.unwrap_err().to_string().contains("pressure"));
    /// ```
    pub fn apply(&self, o: &Overrides) -> Result<Scene> {
        let mut s = self.clone();
        if let Some(m) = o.model {
            s.model = m;
        }
        if let Some(p) = o.pressure {
            s.pressure = p;
        }
        if let Some(t) = o.thickness_qr {
            s.thickness_qr = t;
        }
        if let Some(g) = o.surface_energy_j_m2 {
            s.gamma = g;
        }
        if let Some(r) = o.range_m {
            s.range = r;
        }
        if let Some(e) = o.contact_modulus_pa {
            s.modulus = e;
        }
        if let Some(sp) = &o.spectrum {
            s.spectrum = sp.clone();
        }
        s.validate()?;
        s.resolve_model();
        Ok(s)
    }
}
