//! Parsing and error lines of the command line: value parsers that state each flag's allowed
//! range (the library's, [`asperity::limits`]) when a value does not parse or lies outside
//! it, the command-line name of every field, and one line per error.

use asperity::error::{Allowed, Error, Field, Range};
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
        Field::Other(k) if k == asperity::input::model::FUDGE_GAMMA_KEY => "--fudge-gamma",
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

/// A value parser for a count given by its range directly (a flag of the front end alone,
/// e.g. the chart's `--width`).
pub fn count_in(
    name: &'static str,
    lo: usize,
    hi: usize,
) -> impl Fn(&str) -> std::result::Result<usize, String> + Clone + Send + Sync + 'static {
    move |s: &str| {
        let r = Range::whole(lo as f64, hi as f64);
        match s.trim().parse::<f64>() {
            Ok(x) if r.contains(x) => Ok(x as usize),
            _ => Err(r.describe(name)),
        }
    }
}

/// Parses a count (a whole number ≥ 0); the library checks its range.
pub fn whole_number(s: &str) -> std::result::Result<usize, String> {
    whole_number_u64(s).and_then(|v| usize::try_from(v).map_err(|_| "a whole number >= 0".to_string()))
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

/// A value parser for a file to write: a non-empty path, with the extension `ext` where one
/// is required (`--png` writes PNG only).
pub fn out_path(
    ext: Option<&'static str>,
) -> impl Fn(&str) -> std::result::Result<std::path::PathBuf, String> + Clone + Send + Sync + 'static {
    move |s: &str| {
        let p = std::path::PathBuf::from(s);
        let ok_ext = ext.is_none_or(|e| {
            p.extension()
                .and_then(|x| x.to_str())
                .is_some_and(|x| x.eq_ignore_ascii_case(e))
        });
        if s.trim().is_empty() || !ok_ext {
            return Err(match ext {
                Some(e) => format!("a file name ending in .{e}"),
                None => "a file name".into(),
            });
        }
        Ok(p)
    }
}

/// A value parser for a file to read: a non-empty path.
pub fn in_path(s: &str) -> std::result::Result<std::path::PathBuf, String> {
    if s.trim().is_empty() {
        return Err("a file name".into());
    }
    Ok(std::path::PathBuf::from(s))
}

/// A command-line parse error in one line, in the same shape as the other input errors:
/// `invalid --flag = value: allowed …` where clap knows the flag and value, else clap's
/// first line.
pub fn clap_error_line(e: &clap::Error) -> String {
    use clap::error::{ContextKind, ContextValue};
    let text = |k| match e.get(k) {
        Some(ContextValue::String(s)) => Some(s.clone()),
        _ => None,
    };
    if let (Some(arg), Some(value)) = (text(ContextKind::InvalidArg), text(ContextKind::InvalidValue)) {
        let flag = arg.split_whitespace().next().unwrap_or(&arg).to_string();
        // a positional argument, `[FIGURE]` or `<FILE>`: by its name, `figure`, `file`
        let flag = if flag.starts_with(['[', '<']) {
            flag.trim_matches(|c| matches!(c, '[' | ']' | '<' | '>' | '.'))
                .to_ascii_lowercase()
        } else {
            flag
        };
        let allowed = match e.get(ContextKind::ValidValue) {
            Some(ContextValue::Strings(v)) => v.join(", "),
            _ => std::error::Error::source(e)
                .map(|s| s.to_string())
                .unwrap_or_else(|| "see --help".into()),
        };
        return format!(
            "invalid {flag} = {}: allowed {allowed}",
            asperity::error::fmt_text(&value)
        );
    }
    if e.kind() == clap::error::ErrorKind::MissingRequiredArgument {
        if let Some(ContextValue::Strings(missing)) = e.get(ContextKind::InvalidArg) {
            let names: Vec<&str> = missing
                .iter()
                .map(|m| m.split_whitespace().next().unwrap_or(m))
                .collect();
            return format!(
                "missing {}: required by the other flags given (see --help)",
                names.join(", ")
            );
        }
    }
    if e.kind() == clap::error::ErrorKind::ArgumentConflict {
        if let (Some(arg), Some(prior)) = (text(ContextKind::InvalidArg), text(ContextKind::PriorArg)) {
            if arg == prior {
                let flag = arg.split_whitespace().next().unwrap_or(&arg).to_string();
                return repeated_flag(&flag, &std::env::args().collect::<Vec<_>>());
            }
        }
    }
    let rendered = e.to_string();
    let first = rendered.lines().next().unwrap_or("").trim();
    let first = first.strip_prefix("error: ").unwrap_or(first);
    if e.kind() == clap::error::ErrorKind::UnknownArgument {
        // name the command whose flags are allowed
        // (the usage line names the command, then the arguments given: keep the command)
        let cmd: Vec<&str> = rendered
            .lines()
            .find_map(|l| l.trim().strip_prefix("Usage: "))
            .map(|u| {
                u.split_whitespace()
                    .take_while(|w| !w.starts_with(['-', '<', '[']))
                    .collect()
            })
            .unwrap_or_default();
        let cmd = if cmd.is_empty() {
            "asperity".to_string()
        } else {
            cmd.join(" ")
        };
        return format!("{first}: allowed the flags of `{cmd} --help`");
    }
    first.to_string()
}

/// The message of a flag given more than once (`args`: the command line): every flag takes
/// one value, so a repeated one is refused (not the last taken silently), naming the values.
pub fn repeated_flag(flag: &str, args: &[String]) -> String {
    let with_eq = format!("{flag}=");
    let mut values = Vec::new();
    let mut it = args.iter().peekable();
    while let Some(a) = it.next() {
        if let Some(v) = a.strip_prefix(&with_eq) {
            values.push(asperity::error::fmt_text(v));
        } else if a == flag {
            if let Some(v) = it.peek().filter(|v| !v.starts_with("--")) {
                values.push(asperity::error::fmt_text(v));
            }
        }
    }
    if values.len() >= 2 {
        format!("repeated {flag} = {}: allowed once (one value)", values.join(", "))
    } else {
        format!("repeated {flag}: allowed once")
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
