//! Figure files: what a figure of \[S\] plots, as TOML (`figures/fig-N.toml`, built into the
//! library; any other file can be given by path). Parsed and validated like presets: unknown
//! or mistyped fields give one line naming the file, the line and the key.
//!
//! ```toml
//! id = "7"                      # what `asperity figure ID` calls it
//! title = "..."                 # chart title
//! description = "..."           # one line for `asperity figure --list`
//! preset = "system-2"           # the system
//! x = "thickness"               # pressure | thickness | gamma | stress
//! y = "a_r"                     # a_r | a_r_over_p | mean_contact_stress |
//!                               # contact_stress_variance | mean_gap_rel | pr
//! x_log = true                  # log axes (default false)
//! y_log = false
//! y_decades = 3                 # (log y only, optional) decades drawn below the largest value
//! from = 0.01                   # x range (stress figures: only `to`, the largest σ*)
//! to = 10.0
//! points = 13                   # values of x (stress figures: σ* samples)
//! pressure = 0.005              # scene overrides for every curve (optional):
//! thickness_qr = inf            #   p*, t·q_r, γ_s (J/m²), model
//! gamma = 0.157
//! model = 4
//! gfmd_at = [0.1, 0.3]          # x values of the brute-force points (`--gfmd`)
//! gfmd = true                   # stress figures: a GFMD histogram per curve scene
//!
//! [[curve]]                     # one theory curve; the same overrides, per curve
//! label = "model 3"
//! model = 3
//!
//! [[closed_form]]               # a reference curve: eq18 | pr_small_stress | pr_large_stress
//! kind = "eq18"
//! label = "eq. (18)"
//! model = 1                     # (asymptotes: the curve whose width Δ they use)
//!
//! [[paper]]                     # a value [S] states in its text or tables, drawn as a point
//! label = "[S] Table 1: GFMD"
//! x = 0.01
//! y = 0.4963
//! model = 1                     # (optional) the model it is of: drawn in that model's colour
//! ```

use crate::error::{Error, Result};
use crate::input::model::{Model, ModelKind};
use crate::input::preset::{toml_error_message, Preset};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The figures of \[S\] built into the library: (id, file text).
pub const BUILTIN: [(&str, &str); 9] = [
    ("1", include_str!("../../../figures/fig-1.toml")),
    ("2", include_str!("../../../figures/fig-2.toml")),
    ("3", include_str!("../../../figures/fig-3.toml")),
    ("4", include_str!("../../../figures/fig-4.toml")),
    ("5", include_str!("../../../figures/fig-5.toml")),
    ("6", include_str!("../../../figures/fig-6.toml")),
    ("7", include_str!("../../../figures/fig-7.toml")),
    ("8", include_str!("../../../figures/fig-8.toml")),
    ("8-log", include_str!("../../../figures/fig-8-log.toml")),
];

/// The id of Table 1 of \[S\], the one figure id that is computed without a figure file.
pub const TABLE_1: &str = "table-1";

/// Every id `asperity figure` accepts, in the order `--list` names them.
pub fn ids() -> Vec<&'static str> {
    BUILTIN.iter().map(|(id, _)| *id).chain([TABLE_1]).collect()
}

/// The ids a message or the help names as allowed: "1, 2, …, table-1 or a figure TOML file".
pub fn allowed() -> String {
    format!("{} or a figure TOML file", ids().join(", "))
}

/// The x axis of a figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum XAxis {
    /// p* (a load sweep).
    Pressure,
    /// t·q_r (a thickness sweep at the figure's p*).
    Thickness,
    /// γ_s in J/m² (at the figure's p*).
    Gamma,
    /// σ* (the stress distribution at the figure's p*).
    Stress,
}

/// The y axis of a figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum YAxis {
    /// a_r.
    AR,
    /// a_r/p*.
    AROverP,
    /// σ̄_c*.
    MeanContactStress,
    /// ⟨δσ_c²⟩*.
    ContactStressVariance,
    /// ū/h_rms.
    MeanGapRel,
    /// Pr(σ*) (with x = stress).
    Pr,
}

/// A closed-form reference curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ClosedFormKind {
    /// a_r(p*) of [S-18] (or a_r/p* when y is a_r_over_p).
    Eq18,
    /// Pr(σ) ≈ σ·2pφ(p/Δ)/Δ³, the linear small-stress asymptote.
    PrSmallStress,
    /// Pr(σ) ≈ σ·2pφ(σ/Δ)/Δ³, the Gaussian large-stress asymptote.
    PrLargeStress,
}

/// Scene overrides of a figure or a curve (absent: the preset's or the figure's).
#[derive(Debug, Clone, Copy, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Overrides {
    /// p*.
    pub pressure: Option<f64>,
    /// t·q_r (`inf`: semi-infinite).
    pub thickness_qr: Option<f64>,
    /// γ_s (J/m²).
    pub gamma: Option<f64>,
    /// Model 1–4.
    pub model: Option<u8>,
}

impl Overrides {
    /// p*, t·q_r, γ_s and the model, in the order of the fields.
    pub fn new(pressure: Option<f64>, thickness_qr: Option<f64>, gamma: Option<f64>, model: Option<u8>) -> Self {
        Overrides {
            pressure,
            thickness_qr,
            gamma,
            model,
        }
    }
}

/// One theory curve.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct CurveSpec {
    /// Legend label.
    pub label: String,
    /// p*.
    pub pressure: Option<f64>,
    /// t·q_r.
    pub thickness_qr: Option<f64>,
    /// γ_s (J/m²).
    pub gamma: Option<f64>,
    /// Model 1–4.
    pub model: Option<u8>,
    /// A named variant instead of a numbered model: "yp08" or "xu24" (adhesionless
    /// half-space only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub variant: Option<String>,
}

impl CurveSpec {
    /// A curve of `kind` at the figure's scene, labelled `model N` or with the variant's name.
    pub fn of_model(kind: ModelKind) -> Result<CurveSpec> {
        let label = match kind.number() {
            Some(n) => format!("model {n}"),
            None => Model::of_kind(kind, &Model::named(1)?)?.label(),
        };
        Ok(CurveSpec {
            label,
            pressure: None,
            thickness_qr: None,
            gamma: None,
            model: kind.number(),
            variant: kind.number().is_none().then(|| kind.name().to_string()),
        })
    }

    /// The curve's overrides.
    pub fn overrides(&self) -> Overrides {
        Overrides::new(self.pressure, self.thickness_qr, self.gamma, self.model)
    }
}

/// One closed-form reference curve.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ClosedFormSpec {
    /// Which formula.
    pub kind: ClosedFormKind,
    /// Legend label.
    pub label: String,
    /// For the asymptotes: the model whose width Δ (at the figure's scene) they use.
    pub model: Option<u8>,
}

/// A value stated in \[S\]'s text or tables.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct PaperPoint {
    /// Legend label (points with the same label form one series).
    pub label: String,
    /// x.
    pub x: f64,
    /// y.
    pub y: f64,
    /// The model the value is of (drawn in its colour), if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub model: Option<u8>,
}

/// A parsed, validated figure file.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FigureSpec {
    /// Identifier (`asperity figure ID`).
    pub id: String,
    /// Chart title.
    pub title: String,
    /// One line for `--list`.
    pub description: String,
    /// Preset name or path.
    pub preset: String,
    /// x axis.
    pub x: XAxis,
    /// y axis.
    pub y: YAxis,
    /// Logarithmic x axis.
    #[serde(default)]
    pub x_log: bool,
    /// Logarithmic y axis.
    #[serde(default)]
    pub y_log: bool,
    /// On a log y axis, the decades drawn below the largest value of the figure (a Pr tail
    /// falls to 1e-300 and would squeeze the curves into the top rows); all when absent.
    pub y_decades: Option<f64>,
    /// First x (sweeps; stress figures ignore it).
    pub from: Option<f64>,
    /// Last x (sweeps) or largest σ* (stress figures).
    pub to: f64,
    /// Number of x values.
    pub points: usize,
    /// p* of every curve (default the preset's).
    pub pressure: Option<f64>,
    /// t·q_r of every curve.
    pub thickness_qr: Option<f64>,
    /// γ_s of every curve.
    pub gamma: Option<f64>,
    /// Model of every curve.
    pub model: Option<u8>,
    /// x values of the GFMD points (sweeps).
    #[serde(default)]
    pub gfmd_at: Vec<f64>,
    /// Stress figures: one GFMD histogram per curve scene.
    #[serde(default)]
    pub gfmd: bool,
    /// Theory curves.
    #[serde(default)]
    pub curve: Vec<CurveSpec>,
    /// Closed-form reference curves.
    #[serde(default)]
    pub closed_form: Vec<ClosedFormSpec>,
    /// Values stated in \[S\].
    #[serde(default)]
    pub paper: Vec<PaperPoint>,
}

fn bad(source: &str, message: String) -> Error {
    Error::Preset {
        source: source.to_string(),
        message,
    }
}

impl FigureSpec {
    /// The figure-wide overrides.
    pub fn overrides(&self) -> Overrides {
        Overrides::new(self.pressure, self.thickness_qr, self.gamma, self.model)
    }

    /// Parses TOML text; `source` names the file in errors (the same one-line errors as
    /// presets: `preset SOURCE: line N: key: what`).
    pub fn parse(text: &str, source: &str) -> Result<FigureSpec> {
        let spec: FigureSpec = toml::from_str(text).map_err(|e| bad(source, toml_error_message(text, &e)))?;
        spec.validate().map_err(|m| bad(source, m))?;
        Ok(spec)
    }

    /// Reads a figure file.
    pub fn load(path: &Path) -> Result<FigureSpec> {
        let text = crate::input::file::read_text(
            path,
            "figure",
            crate::error::Field::Other("figure".into()),
            crate::input::preset::MAX_TOML_BYTES,
            "a figure file in TOML",
        )?;
        FigureSpec::parse(&text, &path.display().to_string())
    }

    /// Every field checked; the message names the key.
    fn validate(&self) -> std::result::Result<(), String> {
        let key = |k: &str, v: String, allowed: &str| format!("{k} = {v}: allowed {allowed}");
        Preset::resolve(&self.preset).map_err(|e| format!("preset: {e}"))?;
        let stress = self.x == XAxis::Stress;
        if stress != (self.y == YAxis::Pr) {
            return Err(key(
                "y",
                format!("{:?}", self.y).to_lowercase(),
                "pr exactly when x = \"stress\"",
            ));
        }
        if !(self.to.is_finite() && self.to > 0.0) {
            return Err(key("to", self.to.to_string(), "a number > 0"));
        }
        if let Some(d) = self.y_decades {
            if !(self.y_log && d.is_finite() && (0.5..=300.0).contains(&d)) {
                return Err(key("y_decades", d.to_string(), "0.5 to 300, with y_log = true"));
            }
        }
        if !(2..=100_000).contains(&self.points) {
            return Err(key("points", self.points.to_string(), "2 <= points <= 100000"));
        }
        if !stress {
            match self.from {
                Some(f) if f.is_finite() && f >= 0.0 && f < self.to => {
                    if f == 0.0 && (self.x_log || self.x != XAxis::Gamma) {
                        return Err(key("from", "0".into(), "a number > 0 (log-spaced axis)"));
                    }
                }
                Some(f) => return Err(key("from", f.to_string(), "0 <= from < to")),
                None => return Err("from: missing (the first x of a sweep)".into()),
            }
        }
        let check_model = |k: &str, m: Option<u8>| match m {
            Some(n) if !(1..=4).contains(&n) => Err(key(k, n.to_string(), "1, 2, 3 or 4")),
            _ => Ok(()),
        };
        check_model("model", self.model)?;
        for (i, c) in self.curve.iter().enumerate() {
            check_model(&format!("curve[{}].model", i + 1), c.model)?;
        }
        for (i, p) in self.paper.iter().enumerate() {
            check_model(&format!("paper[{}].model", i + 1), p.model)?;
        }
        for (i, c) in self.closed_form.iter().enumerate() {
            check_model(&format!("closed_form[{}].model", i + 1), c.model)?;
            let ok = match c.kind {
                ClosedFormKind::Eq18 => self.x == XAxis::Pressure && matches!(self.y, YAxis::AR | YAxis::AROverP),
                _ => stress && c.model.is_some(),
            };
            if !ok {
                return Err(key(
                    &format!("closed_form[{}].kind", i + 1),
                    format!("{:?}", c.kind).to_lowercase(),
                    "eq18 on an a_r or a_r_over_p sweep over pressure; the Pr asymptotes on a stress figure, with a model",
                ));
            }
        }
        if self.curve.is_empty() {
            return Err("curve: at least one [[curve]] is needed".into());
        }
        if stress && !self.gfmd_at.is_empty() {
            return Err(key(
                "gfmd_at",
                format!("{:?}", self.gfmd_at),
                "none on a stress figure (use gfmd = true)",
            ));
        }
        if !stress && self.gfmd {
            return Err(key("gfmd", "true".into(), "false on a sweep (use gfmd_at = [x, ...])"));
        }
        // every scene must be valid: the preset's scene with the overrides
        let preset = Preset::resolve(&self.preset).map_err(|e| format!("preset: {e}"))?;
        for (i, c) in self.curve.iter().enumerate() {
            curve_scene(&preset, &self.overrides(), &c.overrides()).map_err(|e| format!("curve[{}]: {e}", i + 1))?;
        }
        Ok(())
    }
}

/// Resolves `id_or_path`: an existing file, else a built-in figure id.
pub fn resolve(id_or_path: &str) -> Result<FigureSpec> {
    // a built-in id wins over a file of the same name in the working folder
    if let Some((_, text)) = BUILTIN.iter().find(|(n, _)| *n == id_or_path) {
        return FigureSpec::parse(text, &format!("figures/fig-{id_or_path}.toml"));
    }
    let p = Path::new(id_or_path);
    if p.is_file() {
        return FigureSpec::load(p);
    }
    Err(Error::field("figure", crate::error::fmt_text(id_or_path), allowed()))
}
/// The scene of a curve: the preset's, then the figure's overrides, then the curve's.
pub fn curve_scene(
    preset: &Preset,
    fig: &Overrides,
    curve: &Overrides,
) -> crate::error::Result<crate::input::scene::Scene> {
    // the curve's values over the figure's, validated once
    let pick = |f: fn(&Overrides) -> Option<f64>| f(curve).or(f(fig));
    let model = match curve.model.or(fig.model) {
        Some(m) => Some(Model::named(m)?),
        None => None,
    };
    preset.scene()?.apply(&crate::input::overrides::Overrides {
        model,
        pressure: pick(|o| o.pressure),
        thickness_qr: pick(|o| o.thickness_qr),
        surface_energy_j_m2: pick(|o| o.gamma),
        ..Default::default()
    })
}
