//! Parsing and error lines of the command line: value parsers that state each flag's allowed
//! range (the library's, [`asperity::limits`]) when a value does not parse or lies outside
//! it, the command-line name of every field, and one line per error.

use asperity::error::{Allowed, Error, Field};
use asperity::limits;

/// The command-line name of a field: its flag where one sets it, else its canonical key.
pub fn field_name(field: &Field) -> &str {
    match field {
        Field::Pressure => "--pressure",
        Field::Thickness => "--thickness",
        Field::SurfaceEnergy => "--gamma",
        Field::Model => "--model",
        Field::C1 => "--c1",
        Field::C2 => "--c2",
        Field::Alpha => "--alpha",
        Field::KGriffith => "--k-griffith",
        Field::WeightCoefficients => "--c1/--c2",
        Field::Rtol => "--rtol",
        Field::AdhesionSteps => "--adhesion-steps",
        Field::AdhesionPoints => "--adhesion-points",
        Field::AdhesionTol => "--adhesion-tol",
        Field::SigmaMax => "--sigma-max",
        Field::SigmaPoints => "--sigma-points",
        Field::SweepFrom => "--from",
        Field::SweepTo => "--to",
        Field::SweepPoints => "--points",
        Field::Grid => "--grid",
        Field::GfmdTolerance => "--tolerance",
        Field::MaxIterations => "--max-iterations",
        Field::Bins => "--bins",
        Field::SystemSize => "--size",
        Field::HeightMap => "--surface",
        Field::Seeds => "--seeds",
        Field::Ladder => "--ladder",
        Field::Seed => "--seed",
        Field::FudgeGamma => "--fudge-gamma",
        Field::QMin => "--qmin",
        Field::QMax => "--qmax",
        Field::BinsPerDecade => "--bins-per-decade",
        Field::FigurePoints => "--points",
        Field::ChartWidth => "--width",
        Field::ChartHeight => "--height",
        Field::TourStep => "--step",
        Field::Other(k) if k == "fit" => "--fit",
        Field::Other(k) if k == "reference" => "--reference",
        Field::Other(k) if k == "method" => "--method",
        Field::Other(k) if k == "psd" => "--psd",
        Field::Other(k) if k == "preset" => "--preset",
        Field::Other(k) if k == "pr" => "--pr",
        other => other.key(),
    }
}

/// The name inside a range description: the field's short key (`pressure`, `t·q_r`, ...).
fn range_name(field: &Field) -> &str {
    match field {
        Field::Thickness => "t·q_r",
        Field::SurfaceEnergy => "gamma_s",
        Field::KGriffith => "k_G",
        Field::QMin => "qmin",
        Field::QMax => "qmax",
        other => other.short(),
    }
}

/// An error in the command line's words: invalid fields are named by their flag.
pub fn render_error(e: &Error) -> String {
    match e {
        Error::Invalid { field, value, allowed } => {
            format!(
                "invalid {} = {value}: allowed {}",
                field_name(field),
                allowed.describe(range_name(field))
            )
        }
        e => e.to_string(),
    }
}

/// What a number flag accepts, for its parse error: the field's range where the library has
/// one for it alone, else `a number`.
fn allowed_for(field: &Field) -> String {
    match limits::allowed(field) {
        Some(a) => a.describe(range_name(field)),
        None => "a number".into(),
    }
}

/// A value parser for a number flag that sets `field`: a text that is not a number, or a
/// number outside the field's range ([`limits::allowed`]), is refused with that range, so
/// that `--pressure abc` and `--pressure -1` say the same thing.
pub fn number(field: Field) -> impl Fn(&str) -> std::result::Result<f64, String> + Clone + Send + Sync + 'static {
    move |s: &str| {
        let allowed = || allowed_for(&field);
        let x: f64 = s.trim().parse().map_err(|_| allowed())?;
        match limits::allowed(&field).as_ref().and_then(Allowed::range) {
            Some(r) if !r.contains(x) => Err(allowed()),
            _ => Ok(x),
        }
    }
}

/// A value parser for a count flag that sets `field` (a whole number in the field's range).
pub fn count(field: Field) -> impl Fn(&str) -> std::result::Result<usize, String> + Clone + Send + Sync + 'static {
    move |s: &str| {
        let allowed = || allowed_for(&field);
        let x: f64 = s.trim().parse().map_err(|_| allowed())?;
        let ok = match limits::allowed(&field).as_ref().and_then(Allowed::range) {
            Some(r) => r.contains(x),
            None => x >= 0.0 && x.fract() == 0.0,
        };
        if x > usize::MAX as f64 {
            return Err(format!(
                "{}, at most {}",
                allowed(),
                asperity::error::fmt_value(usize::MAX as f64)
            ));
        }
        if !ok {
            return Err(allowed());
        }
        Ok(x as usize)
    }
}

/// Parses a whole number ≥ 0 (e.g. a seed: every such number is one).
pub fn whole_number_u64(s: &str) -> std::result::Result<u64, String> {
    s.trim()
        .parse::<u64>()
        .map_err(|_| format!("a whole number 0 <= seed <= {}", u64::MAX))
}

/// A value parser for a whole-number flag that sets `field` and may be given as any integer
/// (e.g. `--grid`): the field's range, checked here.
pub fn whole(field: Field) -> impl Fn(&str) -> std::result::Result<i64, String> + Clone + Send + Sync + 'static {
    move |s: &str| {
        let n = count(field.clone())(s)?;
        i64::try_from(n).map_err(|_| allowed_for(&field))
    }
}

/// A value parser for the ends of `sweep --from/--to`, whose range depends on `--over`: a
/// number, else the three ranges.
pub fn sweep_end(s: &str) -> std::result::Result<f64, String> {
    s.trim().parse::<f64>().map_err(|_| {
        let d = |f: Field, name: &str| limits::allowed(&f).map(|a| a.describe(name)).unwrap_or_default();
        format!(
            "a number in the range of the swept knob ({} for --over pressure; see --help)",
            d(Field::Pressure, "p*")
        )
    })
}

/// A value parser for `--thickness`: a number in the range, or `inf` (kept as text, as given).
pub fn thickness(s: &str) -> std::result::Result<String, String> {
    s.parse::<asperity::input::scene::ThicknessQr>()
        .map(|_| s.to_string())
        .map_err(|_| allowed_for(&Field::Thickness))
}

/// A value parser for `--model`: one of the variants by name.
pub fn model(s: &str) -> std::result::Result<String, String> {
    s.parse::<asperity::input::model::ModelKind>()
        .map(|_| s.to_string())
        .map_err(|_| allowed_for(&Field::Model))
}

/// A preset that could not be read or parsed, as the flag `flag` that named it: one line
/// naming the flag, the file by its name with what is wrong, and what the flag takes.
pub fn preset_under_flag(e: Error, flag: &str) -> Error {
    match toml_under(e, flag, "a preset name (`asperity presets`) or a preset TOML file") {
        Error::Invalid {
            field: Field::Other(k),
            value,
            allowed,
        } if k == "preset" => Error::Invalid {
            field: Field::Other(flag.into()),
            value,
            allowed,
        },
        e => e,
    }
}

/// A TOML file (a preset, a figure, a tour) that could not be read or parsed, as the flag or
/// argument `flag` that named it, `allowed` saying what it takes: the file by its name with
/// what is wrong with it.
pub fn toml_under(e: Error, flag: &str, allowed: &str) -> Error {
    match e {
        Error::Preset { source, message } => {
            let name = std::path::Path::new(&source)
                .file_name()
                .map_or(source.clone(), |n| n.to_string_lossy().into_owned());
            let one_line = message.split_whitespace().collect::<Vec<_>>().join(" ");
            // a key's own range where the reader states one, else what the flag takes
            let said = one_line
                .rsplit_once(": allowed ")
                .or_else(|| one_line.rsplit_once("; allowed "));
            let (what, allowed) = match said {
                Some((w, a)) => (w.to_string(), a.to_string()),
                None => (one_line, allowed.to_string()),
            };
            Error::Invalid {
                field: Field::Other(flag.into()),
                // the reader's own one-line message: its key and line are the point of it
                value: format!("{name}: {what}"),
                allowed: allowed.into(),
            }
        }
        e => e,
    }
}

/// A value parser for `tour --step` (its upper end depends on the tour, checked once it is
/// read).
pub fn step(s: &str) -> std::result::Result<i64, String> {
    match s.trim().parse::<f64>() {
        Ok(x) if x >= 1.0 && x.fract() == 0.0 && x <= i64::MAX as f64 => Ok(x as i64),
        _ => Err("a whole number 1 <= step <= the tour's number of steps".into()),
    }
}

/// `--method pk` on a slab, refused before any step ([`asperity::gfmd::Method::check_on`]).
///
/// # Errors
/// [`Error::Invalid`] naming `--method` for `pk` (`pk` true) when the scene's t·q_r is finite.
pub fn refuse_pk_on_slab(pk: bool, scene: &asperity::input::scene::Scene) -> asperity::error::Result<()> {
    if pk {
        asperity::gfmd::Method::PolonskyKeer.check_on(scene)?;
    }
    Ok(())
}
