//! Overrides of a scene: the inputs a front end changes on a preset's scene (command-line
//! flags, a tour's step, the explorer's knobs, Python's keywords), applied and validated
//! together: the model from its kind and coefficients ([`ModelChanges`]), and the engine's
//! options from the accuracy knobs ([`AccuracyKnobs`]). Front ends parse their strings into
//! these and assemble nothing else.
//!
//! Units as in [`Scene`]: p* reduced by E*ḡ, t·q_r reduced by the roll-off wave number
//! (∞ for a semi-infinite body), γ_s in J/m², ρ in m, E* in Pa.

use crate::error::{Error, Field, Result};
use crate::input::model::{Model, ModelKind};
use crate::input::scene::Scene;
use crate::surface::spectrum::Spectrum;
use crate::theory::adhesion::AdhesionAccuracy;
use crate::theory::engine::Options;
use crate::theory::persson::Accuracy;

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
    /// Changes to the model (after `model`): its kind by name and its coefficients.
    pub model_changes: ModelChanges,
    /// The accuracy knobs of the evaluation ([`Overrides::options`]; no part of the scene).
    pub accuracy: AccuracyKnobs,
}

/// Changes to a scene's model as a front end takes them (`model`, `c1`, `c2`, `alpha`,
/// `k_griffith`, `cap`, `fudge_gamma`); `None` keeps the current value.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ModelChanges {
    /// The model's kind (`1`–`5`, `custom`, `yp08`, `xu24` parse into it).
    pub kind: Option<ModelKind>,
    /// c1 of W(a) (implies a custom model).
    pub c1: Option<f64>,
    /// c2 of W(a) (implies a custom model).
    pub c2: Option<f64>,
    /// The broadening exponent α (implies a custom model).
    pub alpha: Option<f64>,
    /// The Griffith factor k_G (implies a custom model).
    pub k_griffith: Option<f64>,
    /// Whether σ_a is capped (implies a custom model).
    pub cap: Option<bool>,
    /// The factor γ_f of the yp08 and xu24 variants.
    pub fudge_gamma: Option<f64>,
}

impl ModelChanges {
    /// Whether nothing is changed.
    pub fn is_empty(&self) -> bool {
        *self == ModelChanges::default()
    }

    /// The model after these changes to `current`: a named kind replaces it (`custom` keeps
    /// the current coefficients), any of c1, c2, α, k_G, cap makes it custom with those set,
    /// `fudge_gamma` sets the factor of a yp08 or xu24 model.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the model for coefficients with a kind other than custom, or
    /// `fudge_gamma` on a model other than yp08 and xu24; what [`Model::of_kind`],
    /// [`Model::custom`] and [`Model::fudge`] return for values out of range.
    pub fn apply(&self, current: Model) -> Result<Model> {
        let mut model = current;
        if let Some(kind) = self.kind {
            model = match kind {
                ModelKind::Custom => Model {
                    kind: ModelKind::Custom,
                    ..model
                },
                kind => Model::of_kind(kind, &model)?,
            };
        }
        let custom = self.c1.is_some()
            || self.c2.is_some()
            || self.alpha.is_some()
            || self.k_griffith.is_some()
            || self.cap.is_some();
        if custom {
            if let Some(kind) = self.kind.filter(|k| *k != ModelKind::Custom) {
                return Err(Error::invalid_text(
                    Field::Model,
                    kind.name(),
                    "custom when c1, c2, alpha, k_griffith or cap are given",
                ));
            }
            model = Model::custom(
                self.c1.unwrap_or(model.c1),
                self.c2.unwrap_or(model.c2),
                self.alpha.unwrap_or(model.alpha),
                self.k_griffith.unwrap_or(model.k_griffith),
                self.cap.unwrap_or(model.cap),
            )?;
        }
        if let Some(g) = self.fudge_gamma {
            if !model.kind.is_fudge_variant() {
                return Err(Error::invalid_text(
                    Field::Model,
                    model.kind.name(),
                    "yp08 or xu24 when fudge_gamma is given",
                ));
            }
            model = Model::fudge(model.kind, g)?;
        }
        Ok(model)
    }
}

/// The accuracy knobs of an evaluation as a front end takes them (`asperity run`'s flags,
/// Python's `evaluate` keywords); `None` keeps [`Options::default`]'s value.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AccuracyKnobs {
    /// Points of the Pr(σ*) table.
    pub sigma_points: Option<usize>,
    /// Largest σ* of the Pr table.
    pub sigma_max: Option<f64>,
    /// Relative tolerance of the adhesionless variance ODE.
    pub rtol: Option<f64>,
    /// Steps per unit ln q of the adhesive solver.
    pub adhesion_steps: Option<f64>,
    /// Points per width of Pr of the adhesive solver.
    pub adhesion_points: Option<f64>,
    /// Tolerance |γ(q_s)/γ_s − 1| of the adhesive self-consistency.
    pub adhesion_tol: Option<f64>,
}

impl AccuracyKnobs {
    /// The engine's options with these knobs (not validated: [`Options::validate`] names the
    /// knob out of range).
    pub fn options(&self) -> Options {
        let (d, a) = (Options::default(), AdhesionAccuracy::default());
        Options {
            accuracy: Accuracy {
                rtol: self.rtol.unwrap_or(Accuracy::default().rtol),
                ..Accuracy::default()
            },
            sigma_points: self.sigma_points.unwrap_or(d.sigma_points),
            sigma_max: self.sigma_max,
            adhesion: AdhesionAccuracy {
                steps_per_ln_q: self.adhesion_steps.unwrap_or(a.steps_per_ln_q),
                points_per_width: self.adhesion_points.unwrap_or(a.points_per_width),
                tol: self.adhesion_tol.unwrap_or(a.tol),
                ..a
            },
            ..d
        }
    }
}

impl Overrides {
    /// Whether nothing is overridden.
    pub fn is_empty(&self) -> bool {
        *self == Overrides::default()
    }

    /// The engine's options of these overrides' accuracy knobs ([`AccuracyKnobs::options`]).
    pub fn options(&self) -> Options {
        self.accuracy.options()
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
        if !o.model_changes.is_empty() {
            s.model = o.model_changes.apply(s.model)?;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::preset::Preset;

    #[test]
    fn model_changes_make_the_model_the_front_ends_made() {
        let three = Model::named(3).unwrap();
        let custom = ModelChanges {
            alpha: Some(1.5),
            ..ModelChanges::default()
        }
        .apply(three)
        .unwrap();
        assert_eq!(
            (custom.kind, custom.alpha, custom.c1),
            (ModelKind::Custom, 1.5, three.c1)
        );
        let four = ModelChanges {
            kind: Some(ModelKind::Four),
            ..ModelChanges::default()
        };
        assert_eq!(four.apply(three).unwrap(), Model::named(4).unwrap());
        let clash = ModelChanges {
            alpha: Some(1.5),
            ..four
        };
        let e = clash.apply(three).unwrap_err().to_string();
        assert!(e.contains("custom when") && e.contains("model"), "{e}");
        let fudge = ModelChanges {
            fudge_gamma: Some(0.5),
            ..ModelChanges::default()
        };
        assert!(fudge.apply(three).unwrap_err().to_string().contains("yp08 or xu24"));
        // through a scene: the same as setting the model
        let scene = Preset::resolve("system-2").unwrap().scene().unwrap();
        let via = scene
            .apply(&Overrides {
                model_changes: four,
                ..Overrides::default()
            })
            .unwrap();
        assert_eq!(
            via.model(),
            scene.clone().with_model(Model::named(4).unwrap()).unwrap().model()
        );
    }

    #[test]
    fn accuracy_knobs_default_to_the_default_options() {
        assert_eq!(AccuracyKnobs::default().options(), Options::default());
        let o = AccuracyKnobs {
            rtol: Some(1e-6),
            adhesion_tol: Some(1e-3),
            sigma_points: Some(51),
            ..AccuracyKnobs::default()
        }
        .options();
        assert_eq!((o.accuracy.rtol, o.adhesion.tol, o.sigma_points), (1e-6, 1e-3, 51));
        assert_eq!(o.adhesion.steps_per_ln_q, AdhesionAccuracy::default().steps_per_ln_q);
    }

    #[test]
    fn gfmd_method_names_and_the_default_grid_live_in_the_library() {
        use crate::gfmd::{GridSpec, Method};
        assert_eq!("pk".parse::<Method>().unwrap(), Method::PolonskyKeer);
        let e = "cg".parse::<Method>().unwrap_err().to_string();
        assert!(e.contains("method") && e.contains("auto, pk or fire"), "{e}");
        let bare = Preset::resolve("system-2").unwrap();
        let g = GridSpec::of_preset(&bare, None).unwrap();
        assert!(g.n() >= 4);
        assert!(GridSpec::of_preset(&bare, Some(3))
            .unwrap_err()
            .to_string()
            .contains("N >= 4"));
        assert_eq!(GridSpec::of_preset(&bare, Some(64)).unwrap().n(), 64);
    }
}
