//! The four model variants of \[S\] and a fully custom one.
//!
//! Weight function [S-17]:  W(a) = 1 − c₁(1 − a²) − c₂(1 − a⁴).
//! It weights the elastic energy of a mode, u_ela ∝ a_r·W [S-14], and the stress broadening,
//! Δp ∝ W^α [S-15] (α = ½ in \[S\]'s models 1–3, ¼ in model 4). The Griffith criterion is
//! σ_a = k_G √(q E* f γ(q)) [S-8] with k_G = 2 for models 3, 4 ("twice the given value",
//! \[S\] §2.3), optionally capped at the theoretical adhesive stress γ_s/ρ.
//!
//! | model | c₁ | c₂ | α | k_G | cap |
//! |---|---|---|---|---|---|
//! | 1 | 0 | 0 | ½ | 1 | no |
//! | 2 | 0.55 | 0 | ½ | 1 | no |
//! | 3 | −2/9 | 2/3 | ½ | 2 | yes |
//! | 4 | 0.65 | 0 | ¼ | 2 | yes |
//!
//! Model 4 is printed in \[S\] as W = 0.35 + 0.65(1 − a²), contradicting "W(a_r → 0) = 0.35"
//! in the next sentence; physics.md §7 erratum 2 fixes it to W = 0.35 + 0.65a² (c₁ = 0.65).
//!
//! Two named variants of the literature, defined for the adhesionless half-space only
//! (docs/physics.md §3.4), each with its fitting parameter γ_f (`model.fudge_gamma`):
//!
//! | variant | weight | where it acts | γ_f |
//! |---|---|---|---|
//! | YP08 (Yang & Persson 2008) | S(a) = γ_f + (1 − γ_f)a² | variance increments, dV = S(a_r(q))·dV₁ | 0.42 |
//! | Xu24 (Xu et al. 2024) | S(a) = γ_f + (1 − γ_f)a | the whole variance: a_r = erf(p/√(2S(a_r)V₁)) | 0.42 |
//!
//! Both are stored as c₁ = 1 − γ_f, c₂ = 0, α = ½, k_G = 1, no cap: YP08 *is* [S-17] with
//! c₁ = 1 − γ_f on the broadening (model 2 is γ_f = 0.45), so every solver takes it as is;
//! Xu24's S is linear in a and acts on the total variance, which the adhesionless solver
//! treats on its own ([`crate::theory::persson`]).

use crate::error::{fmt_value, Allowed, Error, Field, Range, Result};
use serde::{Deserialize, Serialize};

/// The model variants by name, from [`ModelKind::ALL`].
pub const MODEL_CHOICES: [&str; 8] = {
    let mut names = [""; 8];
    let mut i = 0;
    while i < names.len() {
        names[i] = ModelKind::ALL[i].name();
        i += 1;
    }
    names
};
/// Allowed c₁ and c₂ each (W(a) ≥ 0 on [0, 1] is checked on the pair): the paper's models
/// have |c| ≤ 1; beyond 1000 W spans more orders of magnitude than the broadening resolves.
pub const C_RANGE: Range = Range::closed(-1e3, 1e3);
/// Allowed α, the exponent of W in the stress broadening [S-15].
pub const ALPHA_RANGE: Range = Range::closed(0.0, 4.0);
/// Allowed k_G, the Griffith prefactor [S-8].
pub const K_GRIFFITH_RANGE: Range = Range::open_closed(0.0, 100.0);

/// Which variant of the theory a [`Model`] is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ModelKind {
    /// Model 1: original Persson theory.
    One,
    /// Model 2: Persson's energy weight also applied to the broadening.
    Two,
    /// Model 3: gauged on [S-18].
    Three,
    /// Model 4: re-tuned for the thin adhesive system II.
    Four,
    /// Model 5: W(0) and α a function of the scene's γ̃_glo, gauged once on asperity's GFMD
    /// reference set ([`super::model_five`]); model 3 without adhesion.
    Five,
    /// Every coefficient set by the user.
    Custom,
    /// Yang & Persson 2008: S = γ_f + (1 − γ_f)a² on the variance increments.
    Yp08,
    /// Xu et al. 2024: a_r = erf(p/√(2(γ_f + (1 − γ_f)a_r)V₁)).
    Xu24,
}

/// The default fitting parameter γ_f of [`ModelKind::Yp08`] and [`ModelKind::Xu24`].
pub const FUDGE_GAMMA_DEFAULT: f64 = 0.42;
/// Allowed γ_f: S(a) must stay positive on (0, 1] and not exceed 1 (a reduction of the
/// variance, as in both papers).
pub const FUDGE_GAMMA_RANGE: (f64, f64) = (0.0, 1.0);

/// The canonical key of γ_f (preset `[model]` key `fudge_gamma`).
pub const FUDGE_GAMMA_KEY: &str = "model.fudge_gamma";

/// Coefficients of one variant of the theory. Build with [`Model::named`] or [`Model::custom`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Model {
    /// Which variant.
    pub kind: ModelKind,
    /// c₁ of [S-17].
    pub c1: f64,
    /// c₂ of [S-17].
    pub c2: f64,
    /// Broadening exponent α: Δp ∝ W^α.
    pub alpha: f64,
    /// Griffith prefactor k_G in σ_a = k_G √(qE*fγ).
    pub k_griffith: f64,
    /// Whether σ_a is capped at γ_s/ρ.
    pub cap: bool,
}

/// Hashes the coefficients by their bit patterns (a cache key for front ends).
impl std::hash::Hash for Model {
    fn hash<H: std::hash::Hasher>(&self, h: &mut H) {
        self.kind.name().hash(h);
        for x in [self.c1, self.c2, self.alpha, self.k_griffith] {
            x.to_bits().hash(h);
        }
        self.cap.hash(h);
    }
}

impl std::str::FromStr for ModelKind {
    type Err = Error;

    /// `1`–`5`, `custom`, `yp08` or `xu24` (case-insensitive, surrounding blanks ignored).
    ///
    /// # Errors
    /// [`Error::Invalid`] for [`Field::Model`] naming the allowed values.
    fn from_str(s: &str) -> Result<ModelKind> {
        match s.trim().to_ascii_lowercase().as_str() {
            "1" => Ok(ModelKind::One),
            "2" => Ok(ModelKind::Two),
            "3" => Ok(ModelKind::Three),
            "4" => Ok(ModelKind::Four),
            "5" => Ok(ModelKind::Five),
            "custom" => Ok(ModelKind::Custom),
            "yp08" => Ok(ModelKind::Yp08),
            "xu24" => Ok(ModelKind::Xu24),
            _ => Err(Error::invalid_text(
                Field::Model,
                s.trim(),
                Allowed::choices(MODEL_CHOICES),
            )),
        }
    }
}

/// The allowed model names, in words (every one of [`ModelKind::ALL`]; a test holds them to it).
pub const MODEL_NAMES: &str = "1, 2, 3, 4, 5, custom, yp08 or xu24";

impl ModelKind {
    /// Every variant, in the order lists name them: the one list every list of models
    /// (messages, help, choices) is printed from.
    pub const ALL: [ModelKind; 8] = [
        ModelKind::One,
        ModelKind::Two,
        ModelKind::Three,
        ModelKind::Four,
        ModelKind::Five,
        ModelKind::Custom,
        ModelKind::Yp08,
        ModelKind::Xu24,
    ];

    /// The names of the variants `keep` selects, comma-separated (`1, 2, 3, 4, 5, yp08, xu24`).
    pub fn list(keep: impl Fn(ModelKind) -> bool) -> String {
        let names: Vec<&str> = ModelKind::ALL
            .into_iter()
            .filter(|&k| keep(k))
            .map(ModelKind::name)
            .collect();
        names.join(", ")
    }

    /// The names of the variants a comparison takes (all but custom, which comes with its
    /// coefficients), comma-separated.
    pub fn named_list() -> String {
        ModelKind::list(|k| k != ModelKind::Custom)
    }

    /// The model number 1–5, or `None` for custom and the named variants.
    pub fn number(self) -> Option<u8> {
        match self {
            ModelKind::One => Some(1),
            ModelKind::Two => Some(2),
            ModelKind::Three => Some(3),
            ModelKind::Four => Some(4),
            ModelKind::Five => Some(5),
            ModelKind::Custom | ModelKind::Yp08 | ModelKind::Xu24 => None,
        }
    }

    /// True for the literature variants YP08 and Xu24 (fitting parameter γ_f, adhesionless
    /// half-space only).
    pub fn is_fudge_variant(self) -> bool {
        matches!(self, ModelKind::Yp08 | ModelKind::Xu24)
    }

    /// The name as `--model` and a preset's `variant` take it: "1".."5", "custom", "yp08",
    /// "xu24".
    pub const fn name(self) -> &'static str {
        match self {
            ModelKind::One => "1",
            ModelKind::Two => "2",
            ModelKind::Three => "3",
            ModelKind::Four => "4",
            ModelKind::Five => "5",
            ModelKind::Custom => "custom",
            ModelKind::Yp08 => "yp08",
            ModelKind::Xu24 => "xu24",
        }
    }
}

impl Model {
    /// The model of kind `kind`: the named coefficients for models 1–4; for
    /// [`ModelKind::Custom`], `current`'s coefficients marked custom (so that switching to
    /// custom keeps what the user had and lets them edit it).
    ///
    /// # Errors
    /// Those of [`Model::custom`] when `current`'s coefficients are not a valid model.
    pub fn of_kind(kind: ModelKind, current: &Model) -> Result<Model> {
        match kind {
            ModelKind::Custom => Model::custom(current.c1, current.c2, current.alpha, current.k_griffith, current.cap),
            ModelKind::Yp08 | ModelKind::Xu24 => {
                Model::fudge(kind, current.fudge_gamma().unwrap_or(FUDGE_GAMMA_DEFAULT))
            }
            _ => Model::named(kind.number().unwrap_or(3)),
        }
    }

    /// This model as a scene of global adhesion `gamma_glo` and Tabor parameter `tabor` at the
    /// reference set's bandwidth uses it (model 5, [`super::model_five`]); every other kind is
    /// returned unchanged.
    pub fn for_scene(&self, gamma_glo: f64, tabor: f64) -> Model {
        self.for_scene_at(gamma_glo, tabor, super::model_five::SET_BANDWIDTH)
    }

    /// The coefficients this model takes on a scene of global adhesion `gamma_glo`, Tabor
    /// parameter `tabor` and bandwidth q_s/q_r = `bandwidth` (model 5:
    /// [`super::model_five::BANDWIDTH_GAUGE`]; every other model is itself).
    pub fn for_scene_at(&self, gamma_glo: f64, tabor: f64, bandwidth: f64) -> Model {
        match self.kind {
            ModelKind::Five => super::model_five::BANDWIDTH_GAUGE.model(gamma_glo, tabor, bandwidth),
            _ => *self,
        }
    }

    /// YP08 or Xu24 with fitting parameter γ_f (c₁ = 1 − γ_f, c₂ = 0, α = ½, k_G = 1, no cap).
    ///
    /// # Errors
    /// [`Error::Invalid`] for `model.fudge_gamma` outside (0, 1], or for [`Field::Model`]
    /// when `kind` is not one of the two.
    pub fn fudge(kind: ModelKind, gamma_f: f64) -> Result<Model> {
        if !kind.is_fudge_variant() {
            return Err(Error::invalid_text(Field::Model, kind.name(), "yp08 or xu24"));
        }
        if !(gamma_f > FUDGE_GAMMA_RANGE.0 && gamma_f <= FUDGE_GAMMA_RANGE.1) {
            return Err(Error::invalid(Field::FudgeGamma, gamma_f, "0 < fudge_gamma <= 1"));
        }
        Ok(Model {
            kind,
            c1: 1.0 - gamma_f,
            c2: 0.0,
            alpha: 0.5,
            k_griffith: 1.0,
            cap: false,
        })
    }

    /// γ_f of YP08 and Xu24 (1 − c₁); `None` for the other kinds.
    pub fn fudge_gamma(&self) -> Option<f64> {
        self.kind.is_fudge_variant().then_some(1.0 - self.c1)
    }

    /// Model 1–4 of \[S\] (model 4 with erratum 2 applied); model 5 at γ̃_glo = 0 (a scene
    /// sets its coefficients from its own γ̃_glo and μ_T, [`Model::for_scene`]).
    ///
    /// # Errors
    /// [`Error::Invalid`] for [`Field::Model`] when `n` is not 1–5.
    pub fn named(n: u8) -> Result<Model> {
        if n == 5 {
            return Ok(super::model_five::GAUGE.model(0.0, 0.0));
        }
        let m = match n {
            1 => (ModelKind::One, 0.0, 0.0, 0.5, 1.0, false),
            2 => (ModelKind::Two, 0.55, 0.0, 0.5, 1.0, false),
            3 => (ModelKind::Three, -2.0 / 9.0, 2.0 / 3.0, 0.5, 2.0, true),
            4 => (ModelKind::Four, 0.65, 0.0, 0.25, 2.0, true),
            _ => return Err(Error::invalid_text(Field::Model, n, Allowed::choices(MODEL_CHOICES))),
        };
        Ok(Model {
            kind: m.0,
            c1: m.1,
            c2: m.2,
            alpha: m.3,
            k_griffith: m.4,
            cap: m.5,
        })
    }

    /// A custom model; validated: W(a) ≥ 0 on [0, 1], 0 ≤ α ≤ 4, k_G > 0. α = 0 puts W only
    /// in the elastic energy (Persson 2007, Yang & Persson 2008), not in the broadening.
    pub fn custom(c1: f64, c2: f64, alpha: f64, k_griffith: f64, cap: bool) -> Result<Model> {
        let m = Model {
            kind: ModelKind::Custom,
            c1,
            c2,
            alpha,
            k_griffith,
            cap,
        };
        m.validate()?;
        Ok(m)
    }

    /// Checks the coefficients (used for custom models and after user edits).
    ///
    /// # Errors
    /// [`Error::Invalid`] for [`Field::C1`] or [`Field::C2`] outside [`C_RANGE`], [`Field::Alpha`]
    /// outside [`ALPHA_RANGE`], [`Field::KGriffith`] outside [`K_GRIFFITH_RANGE`], and
    /// [`Field::WeightCoefficients`] when W(a) < 0 somewhere on [0, 1].
    pub fn validate(&self) -> Result<()> {
        C_RANGE.check(Field::C1, self.c1)?;
        C_RANGE.check(Field::C2, self.c2)?;
        ALPHA_RANGE.check(Field::Alpha, self.alpha)?;
        K_GRIFFITH_RANGE.check(Field::KGriffith, self.k_griffith)?;
        if self.kind.is_fudge_variant() && !(self.c1 >= 0.0 && self.c1 < 1.0) {
            return Err(Error::invalid(
                Field::FudgeGamma,
                1.0 - self.c1,
                Range::open_closed(0.0, 1.0),
            ));
        }
        let wmin = self.w_min();
        if wmin < 0.0 {
            return Err(Error::invalid_text(
                Field::WeightCoefficients,
                format!(
                    "({}, {}) giving min W = {}",
                    fmt_value(self.c1),
                    fmt_value(self.c2),
                    fmt_value((wmin * 1e4).round() / 1e4)
                ),
                "coefficients with W(a) = 1 - c1(1-a^2) - c2(1-a^4) >= 0 for all 0 <= a <= 1",
            ));
        }
        Ok(())
    }

    /// W(a) of [S-17]; for Xu24 its linear S(a) = 1 − c₁(1 − a) = γ_f + (1 − γ_f)a (the
    /// weight of the elastic energy [S-14]).
    #[inline]
    pub fn w(&self, a: f64) -> f64 {
        if self.kind == ModelKind::Xu24 {
            return 1.0 - self.c1 * (1.0 - a);
        }
        let b = a * a;
        1.0 - self.c1 * (1.0 - b) - self.c2 * (1.0 - b * b)
    }

    /// The broadening weight W(a)^{2α} that multiplies the stress variance [S-15].
    /// W is clamped at 0 (it can only be negative through rounding for a valid model).
    /// α = 0 gives 1 for every W, W = 0 included (W only in the energy).
    #[inline]
    pub fn broadening(&self, a: f64) -> f64 {
        if self.alpha == 0.0 {
            return 1.0;
        }
        let w = self.w(a).max(0.0);
        if self.alpha == 0.5 {
            w
        } else if self.alpha == 0.25 {
            w.sqrt()
        } else {
            w.powf(2.0 * self.alpha)
        }
    }

    /// True when the broadening weight W^{2α} is identically 1 (c₁ = c₂ = 0, or α = 0): the
    /// variance is then a plain quadrature, no ODE needed.
    pub fn constant_broadening(&self) -> bool {
        (self.c1 == 0.0 && self.c2 == 0.0) || self.alpha == 0.0
    }

    /// Minimum of W over a ∈ [0, 1] (W is quadratic in b = a²).
    pub fn w_min(&self) -> f64 {
        let w0 = 1.0 - self.c1 - self.c2;
        let mut m = w0.min(1.0);
        if self.c2 > 0.0 {
            let b = -self.c1 / (2.0 * self.c2);
            if b > 0.0 && b < 1.0 {
                m = m.min(w0 + self.c1 * b + self.c2 * b * b);
            }
        }
        m
    }

    /// Short human-readable name: "model 3" or "custom".
    pub fn label(&self) -> String {
        match self.kind {
            ModelKind::One => "model 1".into(),
            ModelKind::Two => "model 2".into(),
            ModelKind::Three => "model 3".into(),
            ModelKind::Four => "model 4".into(),
            ModelKind::Five => "model 5".into(),
            ModelKind::Custom => "custom".into(),
            ModelKind::Yp08 => "YP08".into(),
            ModelKind::Xu24 => "Xu24".into(),
        }
    }

    /// The model number 1–5, or `None` for custom and the named variants.
    pub fn number(&self) -> Option<u8> {
        self.kind.number()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_list_of_models_is_the_list_of_variants() {
        let all = ModelKind::list(|_| true);
        assert_eq!(all, MODEL_CHOICES.join(", "));
        let (head, last) = all.rsplit_once(", ").unwrap();
        assert_eq!(MODEL_NAMES, format!("{head} or {last}"));
        for k in ModelKind::ALL {
            assert_eq!(k.name().parse::<ModelKind>().unwrap(), k);
        }
    }

    #[test]
    fn weight_limits() {
        // W(1) = 1 for every model; W(0) = 1 − c1 − c2: 1, 0.45, 5/9, 0.35
        for (n, w0) in [(1, 1.0), (2, 0.45), (3, 5.0 / 9.0), (4, 0.35)] {
            let m = Model::named(n).unwrap();
            assert!((m.w(1.0) - 1.0).abs() < 1e-15);
            assert!((m.w(0.0) - w0).abs() < 1e-15, "model {n}");
            assert!(m.w_min() <= w0 + 1e-15 && m.w_min() > 0.0, "model {n}");
        }
        // [S] §2.3: model 3's W "remains larger than one half" on [0, 1]; its minimum is at
        // a² = 1/6: W = 5/9 − 1/27 + 1/54 = 29/54
        let m3 = Model::named(3).unwrap();
        assert!((m3.w_min() - 29.0 / 54.0).abs() < 1e-15);
        // model 4 with the erratum: W = 0.35 + 0.65 a²
        let m4 = Model::named(4).unwrap();
        assert!((m4.w(0.5) - (0.35 + 0.65 * 0.25)).abs() < 1e-15);
        // broadening exponent: model 4 variance weight is W^{1/2}
        assert!((m4.broadening(0.0) - 0.35f64.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn custom_validation() {
        assert!(Model::custom(0.5, 0.0, 0.5, 1.0, false).is_ok());
        let e = Model::custom(1.5, 0.0, 0.5, 1.0, false).unwrap_err().to_string();
        assert!(e.contains("model.c1/c2"), "{e}");
        let e = Model::custom(0.0, 0.0, -0.1, 1.0, false).unwrap_err().to_string();
        assert!(e.contains("model.alpha") && e.contains("0 <= alpha <= 4"), "{e}");
        let e = Model::custom(0.0, 0.0, 4.5, 1.0, false).unwrap_err().to_string();
        assert!(e.contains("model.alpha"), "{e}");
        // α = 0: W only in the energy; the broadening weight is 1 even where W = 0
        let m0 = Model::custom(1.0, 0.0, 0.0, 1.0, false).unwrap();
        assert_eq!(m0.w(0.0), 0.0);
        assert_eq!(m0.broadening(0.0), 1.0);
        assert_eq!(m0.broadening(0.7), 1.0);
        let e = Model::custom(f64::NAN, 0.0, 0.5, 1.0, false).unwrap_err().to_string();
        assert!(e.contains("model.c1"), "{e}");
        // interior minimum: c1 = -2, c2 = 2 → W(b) = 1 − 2b + 2b²... min at b = 0.5: 0.5
        let m = Model::custom(-2.0, 2.0, 0.5, 1.0, false).unwrap();
        assert!((m.w_min() - 0.5).abs() < 1e-15);
        assert!(Model::named(6).unwrap_err().to_string().contains("model.variant = 6"));
    }
}
