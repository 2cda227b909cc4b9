//! Preset systems: TOML files in physical units, validated field by field.
//!
//! A preset resolves by name (`presets/NAME.toml` under the working directory, then the
//! presets built into the binary) or by path. Unknown keys are rejected; a wrong value gives
//! one line naming the field, its value and the allowed range. See `presets/system-1.toml` for
//! the documented format (units are in the key names: `_m`, `_pa`, `_j_m2`).

use crate::error::{Allowed, Error, Field, Result};
use crate::input::model::{Model, MODEL_CHOICES};
use crate::input::scene::Scene;
use crate::surface::spectrum::{Normalisation, SelfAffine, Spectrum};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Presets compiled into the binary (name, TOML text).
pub const BUILTIN: [(&str, &str); 2] = [
    ("system-1", include_str!("../../presets/system-1.toml")),
    ("system-2", include_str!("../../presets/system-2.toml")),
];

/// The default preset (system I, the contact-mechanics challenge).
pub const DEFAULT_PRESET: &str = "system-1";

/// `[surface]`: the self-affine spectrum.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SurfaceSpec {
    /// L (m).
    pub system_size_m: f64,
    /// λ_r (m).
    pub rolloff_wavelength_m: f64,
    /// λ_s (m).
    pub short_wavelength_m: f64,
    /// H.
    pub hurst: f64,
    /// ḡ (give this or `rms_height_m`).
    pub rms_gradient: Option<f64>,
    /// h_rms (m).
    pub rms_height_m: Option<f64>,
}

/// `[material]`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// E* (Pa).
    pub contact_modulus_pa: f64,
}

/// `[adhesion]`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct AdhesionSpec {
    /// γ_s (J/m²).
    pub surface_energy_j_m2: f64,
    /// ρ (m).
    pub range_m: f64,
}

/// `[load]`: the reference scene.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct LoadSpec {
    /// Reference p*.
    pub pressure: f64,
    /// t·q_r (`inf` = semi-infinite).
    pub thickness_qr: f64,
    /// Inside a hysteresis window (two stable branches at the load), the branch the scene is
    /// on: `"loading"` (the default: the state a loading history from small p* reaches) or
    /// `"unloading"` (the state a contact keeps after it jumped in at a higher load). The
    /// explorer writes it into an export made on the unloading branch; `run` and the explorer
    /// report that branch ([`Preset::follows_unloading`]). Outside a window there is one
    /// branch and the key changes nothing.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub branch: Option<LoadBranch>,
}

/// `[load] branch`: which branch of a hysteresis window the scene is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum LoadBranch {
    /// The loading branch (the lowest stable root).
    Loading,
    /// The unloading branch (the highest stable root).
    Unloading,
}

/// Model number or "custom".
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Variant {
    /// 1–4.
    Number(i64),
    /// "1".."4" or "custom".
    Name(String),
}

impl<'de> Deserialize<'de> for Variant {
    /// An integer or a string; anything else (e.g. `3.5`) is refused with the choices.
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Variant, D::Error> {
        struct V;
        impl serde::de::Visitor<'_> for V {
            type Value = Variant;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(crate::input::model::MODEL_NAMES)
            }
            fn visit_i64<E: serde::de::Error>(self, v: i64) -> std::result::Result<Variant, E> {
                Ok(Variant::Number(v))
            }
            fn visit_u64<E: serde::de::Error>(self, v: u64) -> std::result::Result<Variant, E> {
                Ok(Variant::Number(i64::try_from(v).unwrap_or(i64::MAX)))
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> std::result::Result<Variant, E> {
                Ok(Variant::Name(v.to_string()))
            }
        }
        d.deserialize_any(V)
    }
}

/// Largest preset (or other TOML input) read: presets are a few hundred bytes, and a file far
/// larger is not one (refused before parsing, so that a huge file fails at once).
pub const MAX_TOML_BYTES: u64 = 1 << 20;

/// `[model]`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ModelSpec {
    /// 1, 2, 3, 4, 5 or "custom".
    pub variant: Variant,
    /// Custom c₁.
    pub c1: Option<f64>,
    /// Custom c₂.
    pub c2: Option<f64>,
    /// Custom α.
    pub alpha: Option<f64>,
    /// Custom k_G.
    pub k_griffith: Option<f64>,
    /// Custom σ_a cap.
    pub cap: Option<bool>,
    /// γ_f of the variants "yp08" and "xu24" (default 0.42).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fudge_gamma: Option<f64>,
}

impl Default for ModelSpec {
    fn default() -> Self {
        ModelSpec {
            variant: Variant::Number(3),
            c1: None,
            c2: None,
            alpha: None,
            k_griffith: None,
            cap: None,
            fudge_gamma: None,
        }
    }
}

impl ModelSpec {
    /// The `[model]` table that gives `m` back: the number for models 1–5, the name and γ_f
    /// for YP08 and Xu24, every coefficient for a custom model.
    pub fn of_model(m: &Model) -> ModelSpec {
        use crate::input::model::ModelKind;
        match m.kind {
            ModelKind::Custom => ModelSpec {
                variant: Variant::Name("custom".into()),
                c1: Some(m.c1),
                c2: Some(m.c2),
                alpha: Some(m.alpha),
                k_griffith: Some(m.k_griffith),
                cap: Some(m.cap),
                fudge_gamma: None,
            },
            ModelKind::Yp08 | ModelKind::Xu24 => ModelSpec {
                variant: Variant::Name(m.kind.name().into()),
                fudge_gamma: m.fudge_gamma(),
                ..ModelSpec::default()
            },
            _ => ModelSpec {
                variant: Variant::Number(i64::from(m.number().unwrap_or(3))),
                ..ModelSpec::default()
            },
        }
    }
}

/// `[gfmd]`: the default reduced grid for brute-force runs (`asperity gfmd`). The reduced
/// system keeps λ_s, H and ḡ of `[surface]` and shrinks λ_r and L to these ratios, so
/// N = system_size_ratio · bandwidth · points_per_short_wavelength (see
/// `gfmd::GridSpec`); the built-in presets use 2 · 32 · 8 = 512, about a second.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct GfmdSpec {
    /// L/λ_r.
    pub system_size_ratio: u32,
    /// λ_r/λ_s.
    pub bandwidth: u32,
    /// λ_s/Δa.
    pub points_per_short_wavelength: u32,
}

/// One `[[reference]]` data point for overlays and checks.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ReferencePoint {
    /// Where the number comes from.
    pub source: String,
    /// `a_r`, `mean_contact_stress`, `contact_stress_variance` or `mean_gap_rel`.
    pub quantity: String,
    /// p*.
    pub pressure: f64,
    /// t·q_r (default ∞).
    pub thickness_qr: Option<f64>,
    /// γ_s (J/m²) of the data (default the preset's).
    pub gamma: Option<f64>,
    /// Model the value belongs to (for theory values); absent for simulations.
    pub model: Option<u8>,
    /// The value (reduced units).
    pub value: f64,
}

/// A parsed, validated preset.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Preset {
    /// Short name (used by `--preset NAME`).
    pub name: String,
    /// One-line description.
    pub description: String,
    /// Spectrum.
    pub surface: SurfaceSpec,
    /// Elastic constants.
    pub material: MaterialSpec,
    /// Adhesion.
    pub adhesion: AdhesionSpec,
    /// Reference load and thickness.
    pub load: LoadSpec,
    /// Default model.
    #[serde(default)]
    pub model: ModelSpec,
    /// Default GFMD grid.
    pub gfmd: Option<GfmdSpec>,
    /// Reference data points.
    #[serde(default)]
    pub reference: Vec<ReferencePoint>,
    /// A measured surface the scene runs on instead of `[surface]`'s spectrum (a scene the
    /// explorer exported from a measured map or PSD table). The library does not read it: the
    /// front ends read the file as their measured-surface options would; [`Preset::scene`]
    /// stays `[surface]`'s.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub measured: Option<MeasuredSpec>,
}

/// `[measured]`: the measured surface of a scene, as the front end's options that read it (a
/// height map with its side, height unit and periodicity, or a PSD table; the cut-offs).
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize, Default)]
#[serde(deny_unknown_fields)]
pub struct MeasuredSpec {
    /// A height map file: the theory runs on its PSD.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub map: Option<String>,
    /// A PSD table (CSV, q in 1/m and psd in m⁴).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub psd: Option<String>,
    /// The map's side L (m), overriding the file's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size_m: Option<f64>,
    /// Unit of the map's heights where the file states none (`nm`, `um`, `mm`, `m`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub height_unit: Option<String>,
    /// The map is periodic (no plane fit, no window).
    #[serde(default)]
    pub periodic: bool,
    /// Lower cut-off of the spectrum (1/m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub q_min_per_m: Option<f64>,
    /// Upper cut-off of the spectrum (1/m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub q_max_per_m: Option<f64>,
}

/// The error for a TOML input over [`MAX_TOML_BYTES`].
pub fn too_large(source: &str, len: u64) -> Error {
    Error::Preset {
        source: source.to_string(),
        message: format!(
            "{} bytes: allowed a preset file of at most {} bytes",
            len, MAX_TOML_BYTES
        ),
    }
}

const QUANTITIES: [&str; 4] = ["a_r", "mean_contact_stress", "contact_stress_variance", "mean_gap_rel"];

impl Preset {
    /// Parses TOML text; `source` names the file in errors.
    pub fn parse(text: &str, source: &str) -> Result<Preset> {
        if text.len() as u64 > MAX_TOML_BYTES {
            return Err(too_large(source, text.len() as u64));
        }
        let preset: Preset = toml::from_str(text).map_err(|e| Error::Preset {
            source: source.to_string(),
            message: toml_error_message(text, &e),
        })?;
        preset.validate().map_err(|e| {
            let line = e.invalid_field().and_then(|f| key_line(text, &f.to_string()));
            Error::Preset {
                source: source.to_string(),
                message: match line {
                    Some(n) => format!("line {n}: {e}"),
                    None => e.to_string(),
                },
            }
        })?;
        Ok(preset)
    }

    /// Reads a preset from a file.
    pub fn load(path: &Path) -> Result<Preset> {
        let len = std::fs::metadata(path).map(|m| m.len()).unwrap_or(0);
        if len > MAX_TOML_BYTES {
            return Err(too_large(&path.display().to_string(), len));
        }
        let field = Field::Other("preset".into());
        let text = crate::input::file::read_text(path, "preset", field, MAX_TOML_BYTES, "a preset in TOML")?;
        Preset::parse(&text, &path.display().to_string())
    }

    /// Resolves `name_or_path`: an existing file path, else `presets/NAME.toml` under the
    /// working directory, else a built-in preset.
    pub fn resolve(name_or_path: &str) -> Result<Preset> {
        let p = Path::new(name_or_path);
        if p.is_file() {
            return Preset::load(p);
        }
        if p.exists() {
            return Err(Error::Preset {
                source: name_or_path.to_string(),
                message: if p.is_dir() {
                    "is a directory, not a preset file".into()
                } else {
                    "is not a regular file".into()
                },
            });
        }
        let local = PathBuf::from("presets").join(format!("{name_or_path}.toml"));
        if !name_or_path.contains('/') && local.is_file() {
            return Preset::load(&local);
        }
        if let Some((_, text)) = BUILTIN.iter().find(|(n, _)| *n == name_or_path) {
            return Preset::parse(text, name_or_path);
        }
        let known: Vec<String> = list_available().into_iter().map(|(n, _)| n).collect();
        Err(Error::Preset {
            source: name_or_path.to_string(),
            message: format!("no such preset file or name; known presets: {}", known.join(", ")),
        })
    }

    /// Every field checked; errors name the field (`surface.hurst`, ...).
    pub fn validate(&self) -> Result<()> {
        self.spectrum()?;
        self.scene()?.validate()?;
        if let Some(g) = &self.gfmd {
            for (k, v) in [
                (Field::GfmdSizeRatio, g.system_size_ratio),
                (Field::GfmdBandwidth, g.bandwidth),
                (Field::GfmdPointsPerShortWavelength, g.points_per_short_wavelength),
            ] {
                crate::limits::check(k, f64::from(v))?;
            }
        }
        for (i, r) in self.reference.iter().enumerate() {
            if !QUANTITIES.contains(&r.quantity.as_str()) {
                return Err(Error::invalid_text(
                    Field::Other(format!("reference[{i}].quantity")),
                    &r.quantity,
                    QUANTITIES.join(", "),
                ));
            }
            if !(r.pressure.is_finite() && r.pressure > 0.0) {
                return Err(Error::invalid(
                    Field::Other(format!("reference[{i}].pressure")),
                    r.pressure,
                    "p* > 0",
                ));
            }
            if !r.value.is_finite() {
                return Err(Error::invalid(
                    Field::Other(format!("reference[{i}].value")),
                    r.value,
                    "a finite number",
                ));
            }
        }
        Ok(())
    }

    /// The spectrum of the preset.
    pub fn spectrum(&self) -> Result<Spectrum> {
        let s = &self.surface;
        let norm = match (s.rms_gradient, s.rms_height_m) {
            (Some(g), None) => Normalisation::RmsGradient(g),
            (None, Some(h)) => Normalisation::RmsHeight(h),
            _ => {
                return Err(Error::invalid_text(
                    Field::Other("surface.rms_gradient/rms_height_m".into()),
                    "both or neither",
                    "exactly one of rms_gradient and rms_height_m",
                ))
            }
        };
        Ok(Spectrum::SelfAffine(SelfAffine::new(
            s.system_size_m,
            s.rolloff_wavelength_m,
            s.short_wavelength_m,
            s.hurst,
            norm,
        )?))
    }

    /// The preset's default model.
    pub fn model(&self) -> Result<Model> {
        use crate::input::model::{ModelKind, FUDGE_GAMMA_DEFAULT};
        let m = &self.model;
        if let Variant::Name(s) = &m.variant {
            if let Ok(kind @ (ModelKind::Yp08 | ModelKind::Xu24)) = s.parse::<ModelKind>() {
                if m.c1.is_some() || m.c2.is_some() || m.alpha.is_some() || m.k_griffith.is_some() || m.cap.is_some() {
                    return Err(Error::invalid_text(
                        Field::Model,
                        s,
                        "\"custom\" when c1, c2, alpha, k_griffith or cap are given",
                    ));
                }
                return Model::fudge(kind, m.fudge_gamma.unwrap_or(FUDGE_GAMMA_DEFAULT));
            }
        }
        if let Some(g) = m.fudge_gamma {
            return Err(Error::invalid(
                Field::FudgeGamma,
                g,
                "only with variant = \"yp08\" or \"xu24\"",
            ));
        }
        let n = match &m.variant {
            Variant::Number(n) => Some(*n),
            Variant::Name(s) if s == "custom" => None,
            Variant::Name(s) => Some(
                s.parse::<i64>()
                    .map_err(|_| Error::invalid_text(Field::Model, s, Allowed::choices(MODEL_CHOICES)))?,
            ),
        };
        match n {
            Some(n) => {
                if !(1..=5).contains(&n) {
                    return Err(Error::invalid_text(Field::Model, n, Allowed::choices(MODEL_CHOICES)));
                }
                if m.c1.is_some() || m.c2.is_some() || m.alpha.is_some() || m.k_griffith.is_some() || m.cap.is_some() {
                    return Err(Error::invalid_text(
                        Field::Model,
                        n,
                        "\"custom\" when c1, c2, alpha, k_griffith or cap are given",
                    ));
                }
                Model::named(n as u8)
            }
            None => Model::custom(
                m.c1.unwrap_or(0.0),
                m.c2.unwrap_or(0.0),
                m.alpha.unwrap_or(0.5),
                m.k_griffith.unwrap_or(1.0),
                m.cap.unwrap_or(false),
            ),
        }
    }

    /// The reference scene: the preset's load, thickness, model and adhesion.
    pub fn scene(&self) -> Result<Scene> {
        let a = &self.adhesion;
        let scene = Scene {
            spectrum: self.spectrum()?,
            modulus: self.material.contact_modulus_pa,
            thickness_qr: self.load.thickness_qr,
            model: self.model()?,
            pressure: self.load.pressure,
            gamma: a.surface_energy_j_m2,
            range: a.range_m,
        };
        scene.validate()?;
        Ok(scene)
    }

    /// Whether the preset puts its scene on the unloading branch (`[load] branch =
    /// "unloading"`): the engine then follows it
    /// ([`crate::theory::adhesion::AdhesionAccuracy::follow_unloading`]).
    pub fn follows_unloading(&self) -> bool {
        self.load.branch == Some(LoadBranch::Unloading)
    }

    /// Number of grid points per side of the default GFMD grid.
    pub fn gfmd_grid(&self) -> Option<u32> {
        self.gfmd
            .as_ref()
            .map(|g| g.system_size_ratio * g.bandwidth * g.points_per_short_wavelength)
    }
}

/// One line for a TOML error: `line N: key: what`, with the 1-based line of the error's
/// span and the dotted key written on that line (the table's name for a table-level error).
pub fn toml_error_message(text: &str, e: &toml::de::Error) -> String {
    let msg = shorten_quoted(&e.message().split_whitespace().collect::<Vec<_>>().join(" "));
    let Some(span) = e.span() else { return msg };
    let start = span.start.min(text.len());
    let line_no = text[..start].matches('\n').count() + 1;
    let mut table = String::new();
    let mut key = None;
    for (i, raw) in text.lines().enumerate() {
        let l = raw.split('#').next().unwrap_or("").trim();
        if i + 1 > line_no {
            break;
        }
        if l.starts_with('[') {
            table = l.trim_matches(|c| c == '[' || c == ']').trim().to_string();
            key = (i + 1 == line_no).then(|| table.clone());
        } else if i + 1 == line_no {
            key = l.split_once('=').map(|(k, _)| {
                let k = k.trim().trim_matches('"');
                if table.is_empty() {
                    k.to_string()
                } else {
                    format!("{table}.{k}")
                }
            });
        }
    }
    match key {
        Some(k) if !k.is_empty() => format!("line {line_no}: {k}: {msg}"),
        _ => format!("line {line_no}: {msg}"),
    }
}

/// `msg` with every value the parser quotes in backticks shown as
/// [`crate::error::fmt_text`] shows it (a 301-digit float as `1e300`, a long text cut in the
/// middle), so the message stays one short line.
fn shorten_quoted(msg: &str) -> String {
    let parts: Vec<&str> = msg.split('`').collect();
    if parts.len() < 3 {
        return msg.to_string();
    }
    let mut out = String::new();
    for (i, part) in parts.iter().enumerate() {
        if i > 0 {
            out.push('`');
        }
        // odd parts lie between a pair of backticks (the last one only if closed)
        if i % 2 == 1 && i + 1 < parts.len() {
            out.push_str(&crate::error::fmt_text(part));
        } else {
            out.push_str(part);
        }
    }
    out
}

/// The 1-based line where the dotted key `table.key` (or a top-level `key`) is written in
/// `text`, if it is.
pub fn key_line(text: &str, dotted: &str) -> Option<usize> {
    let (want_table, want_key) = dotted.rsplit_once('.').unwrap_or(("", dotted));
    let mut table = String::new();
    for (i, raw) in text.lines().enumerate() {
        let l = raw.split('#').next().unwrap_or("").trim();
        if l.starts_with('[') {
            table = l.trim_matches(|c| c == '[' || c == ']').trim().to_string();
        } else if let Some((k, _)) = l.split_once('=') {
            if table == want_table && k.trim().trim_matches('"') == want_key {
                return Some(i + 1);
            }
        }
    }
    None
}

/// Available presets: (name, where) from `presets/` under the working directory and the
/// built-in ones.
pub fn list_available() -> Vec<(String, String)> {
    list_toml_files("presets", &BUILTIN.map(|(n, _)| n))
}

/// The TOML files of `dir` (under the working directory) as (stem, path), sorted, followed by
/// the `builtin` names that no file shadows, as (name, "built-in"). Presets and the front
/// ends' other TOML inputs (tours) are listed alike.
pub fn list_toml_files(dir: &str, builtin: &[&str]) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    if let Ok(rd) = std::fs::read_dir(dir) {
        let mut files: Vec<PathBuf> = rd.filter_map(|e| e.ok().map(|e| e.path())).collect();
        files.sort();
        for f in files {
            if f.extension().is_some_and(|e| e == "toml") {
                if let Some(stem) = f.file_stem().and_then(|s| s.to_str()) {
                    out.push((stem.to_string(), f.display().to_string()));
                }
            }
        }
    }
    for n in builtin {
        if !out.iter().any(|(m, _)| m == n) {
            out.push((n.to_string(), "built-in".to_string()));
        }
    }
    out
}
