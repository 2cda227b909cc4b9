//! Teaching tours: ordered scenes of the explorer, each a preset state, the charts to show and
//! a caption of 2–4 lines saying what the class should see and which equation or figure of
//! \[S\] it illustrates. `t` in the explorer or `asperity tour [NAME]` starts one; ←/→ move
//! between steps, every knob still turns (h/l, ⇧←/⇧→, typing), Esc leaves the tour.
//!
//! Tours are TOML files, resolved like presets: a path, `tours/NAME.toml` under the working
//! directory, or a tour built into the binary ([`BUILTIN`]). The format (unknown keys are
//! rejected; errors are one line naming the line and the key, like presets):
//!
//! ```toml
//! name = "my-tour"
//! title = "What the class sees"
//! preset = "system-1"          # default preset of the steps
//!
//! [[step]]
//! title = "Roughness, scale by scale"
//! preset = "system-1"          # optional (default: the tour's)
//! model = 3                    # optional: 1-5 (default: the preset's)
//! pressure = 0.01              # optional p* (default: the preset's)
//! thickness_qr = inf           # optional t*q_r (default: the preset's)
//! gamma = 0.0                  # optional gamma_s in J/m^2 (default: the preset's)
//! charts = ["pr", "area-ratio", "gap"]   # big panel, lower left, lower right (1-3 names)
//! refers = ["pr"]              # optional: the charts the caption refers to (default: the
//!                              # first); the explorer focuses the first, so every size shows it
//! contrast = [["model1", "closed-form"]]  # optional: looks the caption tells apart
//! models = false               # optional: overlay all models (the M key)
//! select = "pressure"          # optional: the knob the caption tells the class to turn
//! caption = """
//! Two to four lines.
//! """
//!
//! [[step.check]]               # optional: a claim of the caption, checked against the engine
//! says = "model 1 undershoots eq. (18)"
//! quantity = "a_r/p*"          # see [`QUANTITIES`]
//! model = 1                    # optional: the step's scene with model/pressure/gamma/thickness_qr
//! value = 1.60                 # value ± rel·|value|, and/or min/max bounds,
//! rel = 0.005
//! below = { quantity = "eq18/p*" }   # and/or below/above/near another quantity or scene
//!
//! [[step.press]]               # optional: what a `{key:KEY}` of the caption does
//! says = "l turns p* up"       # see [`crate::tui::base::caption`] (also `{look:NAME}` references)
//! key = "l"
//! raises = "pressure"
//! ```
//!
//! Chart names: see [`crate::tui::charts`]. Knob names: [`Knob::NAMES`]. The checks are data only:
//! the test `cli/tests/tui_tour_claims.rs` evaluates every one of them with the engine.

use crate::looks::Role;
use crate::tui::base::caption::{self, Press};
use crate::tui::base::kinds::ChartKind;
use asperity::error::{Error, Result};
use asperity::input::model::Model;
use asperity::input::overrides::Overrides;
use asperity::input::preset::{self, Preset};
use asperity::input::scene::Scene;
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// Tours compiled into the binary (name, TOML text).
pub const BUILTIN: [(&str, &str); 1] = [("wang-muser", include_str!("../../../../tours/wang-muser.toml"))];

/// The tour `asperity tour` and `t` start by default.
pub const DEFAULT_TOUR: &str = "wang-muser";

/// Lines a caption may have.
pub const CAPTION_LINES: (usize, usize) = (2, 4);
/// Longest caption line (characters).
pub const CAPTION_WIDTH: usize = 100;
/// Steps a tour may have.
pub const STEPS: (usize, usize) = (1, 50);

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct TourFile {
    name: String,
    title: String,
    preset: Option<String>,
    #[serde(default)]
    step: Vec<StepFile>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct StepFile {
    title: String,
    preset: Option<String>,
    model: Option<i64>,
    pressure: Option<f64>,
    thickness_qr: Option<f64>,
    gamma: Option<f64>,
    charts: Vec<String>,
    refers: Option<Vec<String>>,
    #[serde(default)]
    contrast: Vec<[String; 2]>,
    models: Option<bool>,
    select: Option<String>,
    caption: String,
    #[serde(default)]
    check: Vec<Check>,
    #[serde(default)]
    press: Vec<Press>,
}

/// A knob of the parameter panel a step can select (the one its caption says to turn).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Knob {
    /// The preset.
    Preset,
    /// The model.
    Model,
    /// p*.
    Pressure,
    /// t·q_r.
    Thickness,
    /// γ_s.
    Gamma,
}

impl Knob {
    /// The names of the `select` key, in the order of [`Knob::ALL`].
    pub const NAMES: [&'static str; 5] = ["preset", "model", "pressure", "thickness_qr", "gamma"];
    /// Every knob.
    pub const ALL: [Knob; 5] = [Knob::Preset, Knob::Model, Knob::Pressure, Knob::Thickness, Knob::Gamma];

    /// The knob named `s` (see [`Knob::NAMES`]).
    pub fn parse(s: &str) -> Option<Knob> {
        Knob::NAMES.iter().position(|n| *n == s).map(|i| Knob::ALL[i])
    }
}

pub use crate::tui::base::tour_check::{Check, Side, QUANTITIES};

/// One validated step.
#[derive(Debug, Clone, PartialEq)]
pub struct Step {
    /// Short title.
    pub title: String,
    /// The preset's name or path.
    pub source: String,
    /// The preset.
    pub preset: Preset,
    /// The scene of the step.
    pub scene: Scene,
    /// Big panel, lower left, lower right.
    pub charts: [ChartKind; 3],
    /// The charts the caption refers to (indices into `charts`, at least one): the explorer
    /// focuses the first when the step opens, so a screen with fewer panels shows it.
    pub refers: Vec<usize>,
    /// Pairs of looks the caption contrasts: the tour test fails where they share their cells.
    pub contrasts: Vec<(Role, Role)>,
    /// All models overlaid.
    pub models: bool,
    /// 2–4 lines.
    pub caption: Vec<String>,
    /// The knob the caption tells the class to turn (selected when the step opens).
    pub select: Option<Knob>,
    /// The caption's claims (checked against the engine by the claims test).
    pub checks: Vec<Check>,
    /// The caption as written, its `{look:…}` and `{key:…}` references unrendered.
    pub caption_source: Vec<String>,
    /// What the keys the caption names do (checked in the explorer by the tour test).
    pub presses: Vec<Press>,
}

/// A validated tour.
#[derive(Debug, Clone, PartialEq)]
pub struct Tour {
    /// Short name.
    pub name: String,
    /// Title.
    pub title: String,
    /// Steps, in order.
    pub steps: Vec<Step>,
}

/// The 1-based line of `key` in step `step` (None: the top level), or of the step's
/// `[[step]]` header when the key is not written there.
pub fn key_line(text: &str, step: Option<usize>, key: &str) -> Option<usize> {
    let mut section: Option<usize> = None;
    let mut header = None;
    for (i, raw) in text.lines().enumerate() {
        let l = raw.split('#').next().unwrap_or("").trim();
        if l == "[[step]]" {
            section = Some(section.map_or(0, |s| s + 1));
            if section == step {
                header = Some(i + 1);
            }
            continue;
        }
        if section == step {
            if let Some((k, _)) = l.split_once('=') {
                if k.trim().trim_matches('"') == key {
                    return Some(i + 1);
                }
            }
        }
    }
    header
}

fn tour_error(source: &str, text: &str, step: Option<usize>, key: &str, msg: impl std::fmt::Display) -> Error {
    let dotted = match step {
        Some(i) => format!("step[{i}].{key}"),
        None => key.to_string(),
    };
    let message = match key_line(text, step, key) {
        Some(n) => format!("line {n}: {dotted}: {msg}"),
        None => format!("{dotted}: {msg}"),
    };
    Error::Preset {
        source: source.to_string(),
        message,
    }
}

impl Tour {
    /// Parses and validates a tour; `source` names the file in errors.
    pub fn parse(text: &str, source: &str) -> Result<Tour> {
        let file: TourFile = toml::from_str(text).map_err(|e| Error::Preset {
            source: source.to_string(),
            message: preset::toml_error_message(text, &e),
        })?;
        let err = |step: Option<usize>, key: &str, msg: String| tour_error(source, text, step, key, msg);
        if file.name.trim().is_empty() {
            return Err(err(None, "name", "must not be empty".into()));
        }
        if !(STEPS.0..=STEPS.1).contains(&file.step.len()) {
            return Err(err(
                None,
                "step",
                format!(
                    "{} steps; allowed {}..={} [[step]] tables",
                    file.step.len(),
                    STEPS.0,
                    STEPS.1
                ),
            ));
        }
        let default_preset = file
            .preset
            .clone()
            .unwrap_or_else(|| preset::DEFAULT_PRESET.to_string());
        let mut steps = Vec::with_capacity(file.step.len());
        for (i, s) in file.step.iter().enumerate() {
            steps.push(parse_step(s, i, &default_preset, &err)?);
        }
        Ok(Tour {
            name: file.name,
            title: file.title,
            steps,
        })
    }

    /// Reads a tour file.
    pub fn load(path: &Path) -> Result<Tour> {
        let text = asperity::input::file::read_text(
            path,
            "tour",
            asperity::error::Field::Other("tour".into()),
            asperity::input::preset::MAX_TOML_BYTES,
            "a tour file in TOML",
        )?;
        Tour::parse(&text, &path.display().to_string())
    }

    /// Resolves a tour like a preset: an existing file, `tours/NAME.toml` under the working
    /// directory, a built-in tour.
    pub fn resolve(name_or_path: &str) -> Result<Tour> {
        // a built-in name wins over a file of the same name in the working folder
        if let Some((_, text)) = BUILTIN.iter().find(|(n, _)| *n == name_or_path) {
            return Tour::parse(text, name_or_path);
        }
        let p = Path::new(name_or_path);
        if p.is_file() {
            return Tour::load(p);
        }
        let local = PathBuf::from("tours").join(format!("{name_or_path}.toml"));
        if !name_or_path.contains('/') && local.is_file() {
            return Tour::load(&local);
        }
        let known: Vec<String> = list_available().into_iter().map(|(n, _)| n).collect();
        Err(Error::Preset {
            source: name_or_path.to_string(),
            message: format!("no such tour file or name; known tours: {}", known.join(", ")),
        })
    }
}

/// One `[[step]]` table validated (`i`: its index, `err` names the line and key).
fn parse_step(
    s: &StepFile,
    i: usize,
    default_preset: &str,
    err: &dyn Fn(Option<usize>, &str, String) -> Error,
) -> Result<Step> {
    let at = Some(i);
    let key = if s.preset.is_some() { "preset" } else { "title" };
    let source_name = s.preset.clone().unwrap_or_else(|| default_preset.to_string());
    let p = Preset::resolve(&source_name).map_err(|e| {
        if s.preset.is_some() {
            err(at, key, e.to_string())
        } else {
            err(None, "preset", e.to_string())
        }
    })?;
    let scene = p.scene().map_err(|e| err(at, "preset", e.to_string()))?;
    let model = match s.model {
        Some(m) => Some(
            u8::try_from(m)
                .ok()
                .filter(|m| (1..=5).contains(m))
                .and_then(|m| Model::named(m).ok())
                .ok_or_else(|| err(at, "model", format!("{m}; allowed 1, 2, 3, 4 or 5")))?,
        ),
        None => None,
    };
    let overrides = Overrides {
        model,
        pressure: s.pressure,
        thickness_qr: s.thickness_qr,
        surface_energy_j_m2: s.gamma,
        ..Overrides::default()
    };
    let scene = match scene.apply(&overrides) {
        Ok(scene) => scene,
        Err(e) => {
            let key = match e.invalid_field().map(|f| f.to_string()) {
                Some(f) if f.contains("thickness") => "thickness_qr",
                Some(f) if f.contains("gamma") || f.contains("surface_energy") => "gamma",
                Some(f) if f.contains("pressure") => "pressure",
                _ => "title",
            };
            return Err(err(at, key, e.to_string()));
        }
    };
    if s.charts.is_empty() || s.charts.len() > 3 {
        return Err(err(at, "charts", format!("{} names; allowed 1 to 3", s.charts.len())));
    }
    let mut charts = [ChartKind::Pr, ChartKind::Area, ChartKind::Gap];
    for (j, name) in s.charts.iter().enumerate() {
        charts[j] = ChartKind::parse(name).ok_or_else(|| {
            let names: Vec<&str> = ChartKind::ALL.iter().map(|k| k.name()).collect();
            err(
                at,
                "charts",
                format!("unknown chart \"{name}\"; allowed {}", names.join(", ")),
            )
        })?;
    }
    let (caption_source, caption) =
        caption_of(&s.caption, crate::looks::model_slot(&scene.model())).map_err(|m| err(at, "caption", m))?;
    let refers = refers_of(s, &charts, &caption_source).map_err(|m| err(at, "refers", m))?;
    let mut contrasts = Vec::new();
    for [a, b] in &s.contrast {
        let role = |n: &str| {
            Role::named(n).ok_or_else(|| {
                let names: Vec<&str> = Role::NAMED.iter().map(|(n, _)| *n).collect();
                err(
                    at,
                    "contrast",
                    format!("unknown look \"{n}\"; allowed {}", names.join(", ")),
                )
            })
        };
        contrasts.push((role(a)?, role(b)?));
    }
    if s.title.trim().is_empty() {
        return Err(err(at, "title", "must not be empty".into()));
    }
    let select = match &s.select {
        None => None,
        Some(name) => Some(Knob::parse(name).ok_or_else(|| {
            err(
                at,
                "select",
                format!("unknown knob \"{name}\"; allowed {}", Knob::NAMES.join(", ")),
            )
        })?),
    };
    for (j, p) in s.press.iter().enumerate() {
        caption::validate(p, &Knob::NAMES)
            .map_err(|m| err(at, "press", format!("press {j} ({}): {m}", p.says.trim())))?;
    }
    for (j, c) in s.check.iter().enumerate() {
        c.validate().map_err(|m| err(at, "check", format!("check {j}: {m}")))?;
    }
    Ok(Step {
        title: s.title.trim().to_string(),
        source: source_name,
        preset: p,
        scene,
        charts,
        refers,
        contrasts,
        models: s.models.unwrap_or(false),
        caption,
        select,
        checks: s.check.clone(),
        caption_source,
        presses: s.press.clone(),
    })
}

/// The charts a step's caption refers to, as indices into its `charts` (default: the first);
/// every `{chart:NAME}` of the caption must be among them.
fn refers_of(s: &StepFile, charts: &[ChartKind; 3], caption: &[String]) -> std::result::Result<Vec<usize>, String> {
    let index = |name: &str| {
        let k = ChartKind::parse(name);
        (0..s.charts.len())
            .find(|&j| Some(charts[j]) == k)
            .ok_or_else(|| format!("\"{name}\" is not among the step's charts ({})", s.charts.join(", ")))
    };
    let refers = match &s.refers {
        None => vec![0],
        Some(names) if names.is_empty() => return Err("names no chart; give 1 to 3 of the step's charts".into()),
        Some(names) => names
            .iter()
            .map(|n| index(n))
            .collect::<std::result::Result<Vec<usize>, String>>()?,
    };
    for (_, name) in caption
        .iter()
        .flat_map(|l| caption::references(l))
        .filter(|(k, _)| k == "chart")
    {
        if !refers.iter().any(|&j| charts[j].name() == name) {
            return Err(format!("the caption names {{chart:{name}}}; add \"{name}\" to refers"));
        }
    }
    Ok(refers)
}

/// A caption's lines as written and rendered (`slot`: the model slot of the theory's colour);
/// Err says what is wrong with it.
fn caption_of(text: &str, slot: usize) -> std::result::Result<(Vec<String>, Vec<String>), String> {
    let caption_source: Vec<String> = text
        .lines()
        .map(|l| l.trim().to_string())
        .filter(|l| !l.is_empty())
        .collect();
    let caption = caption_source
        .iter()
        .map(|l| caption::render(l, slot))
        .collect::<std::result::Result<Vec<String>, String>>()?;
    if !(CAPTION_LINES.0..=CAPTION_LINES.1).contains(&caption.len()) {
        return Err(format!(
            "{} lines; allowed {} to {}",
            caption.len(),
            CAPTION_LINES.0,
            CAPTION_LINES.1
        ));
    }
    if let Some(l) = caption.iter().find(|l| l.chars().count() > CAPTION_WIDTH) {
        return Err(format!(
            "a line of {} characters; allowed {CAPTION_WIDTH}",
            l.chars().count()
        ));
    }
    Ok((caption_source, caption))
}

/// Available tours: (name, where), from `tours/` under the working directory and built in.
pub fn list_available() -> Vec<(String, String)> {
    asperity::input::preset::list_toml_files("tours", &BUILTIN.map(|(n, _)| n))
}

#[cfg(test)]
mod tests {
    use super::*;

    const GOOD: &str = r#"name = "t"
title = "A tour"
preset = "system-1"

[[step]]
title = "one"
charts = ["pr"]
caption = """
line one
line two
"""

[[step]]
title = "two"
model = 2
pressure = 0.02
gamma = 0.0
charts = ["pr-loglog", "area-ratio", "thickness"]
models = true
caption = "a\nb\nc"
"#;

    #[test]
    fn a_good_tour_parses_with_defaults() {
        let t = Tour::parse(GOOD, "good").unwrap();
        assert_eq!(t.steps.len(), 2);
        assert_eq!(t.steps[0].charts, [ChartKind::Pr, ChartKind::Area, ChartKind::Gap]);
        assert_eq!(t.steps[0].scene, Preset::resolve("system-1").unwrap().scene().unwrap());
        let s = &t.steps[1];
        assert_eq!(s.scene.model().number(), Some(2));
        assert_eq!((s.scene.pressure(), s.scene.surface_energy_j_m2()), (0.02, 0.0));
        assert_eq!(s.charts, [ChartKind::PrLog, ChartKind::AreaRatio, ChartKind::Thickness]);
        assert!(s.models);
        assert_eq!(s.caption, ["a", "b", "c"]);
    }

    #[test]
    fn a_step_takes_model_5_resolved_for_its_scene() {
        let text = GOOD
            .replace("model = 2", "model = 5")
            .replace("gamma = 0.0", "gamma = 0.1");
        let t = Tour::parse(&text, "good").unwrap();
        let m = t.steps[1].scene.model();
        assert_eq!(m.number(), Some(5));
        // its coefficients are the step's own scene's (γ̃_glo), as `m` or `--model 5` give them
        let want = Preset::resolve("system-1")
            .unwrap()
            .scene()
            .unwrap()
            .apply(&Overrides {
                model: Some(Model::named(5).unwrap()),
                pressure: Some(0.02),
                surface_energy_j_m2: Some(0.1),
                ..Overrides::default()
            })
            .unwrap()
            .model();
        assert_eq!(m, want);
        assert_ne!(m, Model::named(5).unwrap(), "model 5 left at γ̃_glo = 0");
    }

    fn error(text: &str) -> String {
        Tour::parse(text, "bad.toml").unwrap_err().to_string()
    }

    #[test]
    fn bad_fields_give_one_line_naming_line_and_key() {
        let e = error(&GOOD.replace("models = true", "modles = true"));
        assert!(
            e.starts_with("preset bad.toml: line 19: step.modles: unknown field"),
            "{e}"
        );
        let e = error(&GOOD.replace("\"area-ratio\"", "\"area-ration\""));
        assert_eq!(
            e,
            "preset bad.toml: line 18: step[1].charts: unknown chart \"area-ration\"; allowed pr, \
             pr-loglog, area, area-ratio, thickness, scales, scales-area, stress, gap, psd"
        );
        let e = error(&GOOD.replace("model = 2", "model = 7"));
        assert_eq!(e, "preset bad.toml: line 15: step[1].model: 7; allowed 1, 2, 3, 4 or 5");
        let e = error(&GOOD.replace("pressure = 0.02", "pressure = -1"));
        assert!(e.starts_with("preset bad.toml: line 16: step[1].pressure: "), "{e}");
        let e = error(&GOOD.replace("caption = \"a\\nb\\nc\"", "caption = \"only one\""));
        assert_eq!(e, "preset bad.toml: line 20: step[1].caption: 1 lines; allowed 2 to 4");
        let e = error(&GOOD.replace("pressure = 0.02", "pressure = \"x\""));
        assert!(e.starts_with("preset bad.toml: line 16: step.pressure: "), "{e}");
        assert!(!e.contains('\n'));
        let e = error("name = \"x\"\ntitle = \"y\"\n");
        assert!(e.contains("step: 0 steps"), "{e}");
    }

    #[test]
    fn the_shipped_tours_are_valid() {
        for (name, text) in BUILTIN {
            let t = Tour::parse(text, name).unwrap();
            assert!((8..=14).contains(&t.steps.len()), "{name}: {} steps", t.steps.len());
            // an 80-column terminal shows every caption line unwrapped (box borders: 2 columns)
            for l in t.steps.iter().flat_map(|s| &s.caption) {
                assert!(
                    l.chars().count() <= 76,
                    "{name}: caption line too wide for 80 columns: {l}"
                );
            }
        }
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tours");
        for f in std::fs::read_dir(dir).unwrap() {
            let f = f.unwrap().path();
            Tour::load(&f).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        }
    }
}
