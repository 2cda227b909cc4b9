//! Every flag of every command in one declarative table ([`table`]): what it takes (its
//! [`Kind`]: a number of a library field, a count, a choice, a file to read or to write…),
//! its unit, and so its allowed values, taken from the library's ranges
//! ([`asperity::limits`]) and never restated here. [`command`] drives the clap parser from
//! it: each flag's value parser and `allow_hyphen_values` come from its row, so a value is
//! refused in one line naming the flag, the value and what is allowed while the command line
//! is parsed, before any work starts; and a flag without a row is caught by the test that
//! walks the parser (`cli/tests/cli_every_flag.rs`).
//!
//! Files to write (`--svg`, `--png`, `--save-preset`, `--save-reference`, `--save-surface`,
//! `--output`) are checked at the same time: their extension (the format written), and the
//! path as a file (`outfile`: not a folder or a device, a name the file system takes, an
//! existing file writable, a new one creatable); they are written atomically at the end.

use super::parse;
use asperity::error::Field;
use asperity::limits;
use clap::builder::ValueParser;
use std::path::{Path, PathBuf};

/// What a flag takes, and so how its value is parsed and checked.
#[derive(Debug, Clone)]
pub enum Kind {
    /// A number in the library's range of `Field` (an `f64`).
    Number(Field),
    /// A whole number in the library's range of `Field` (a `usize`).
    Count(Field),
    /// A whole number in the library's range of `Field`, kept as an `i64` (a grid side).
    Whole(Field),
    /// A seed: a whole number in the range of `Field` (0 ..= 2⁶⁴−1, a `u64`).
    Seed(Field),
    /// `tour --step`: a whole number in the range of `Field` (an `i64`; its upper end is the
    /// tour's length, checked once the tour is read).
    Step(Field),
    /// An end of `sweep --from/--to` (`Field`): a number; its range depends on `--over`.
    SweepEnd(Field),
    /// `--thickness`: a number in its range, or `inf` (kept as text).
    Thickness,
    /// `--model` of the scene: one of the variants (kept as text).
    Model,
    /// A rung of `--ladder` (λ_s/Δa, [`Field::Ladder`]).
    Ladder,
    /// One of the names clap lists (a `ValueEnum` or true/false): clap's own parser.
    Choice,
    /// A switch: no value.
    Switch,
    /// A name checked here by `check`: a preset, tour, figure or reference (a built-in name or
    /// a file), a comma-separated list of coefficients, … (a `String`).
    Text(fn(&str) -> Result<(), String>),
    /// A file to read: it exists and is not a folder (a `PathBuf`).
    InFile,
    /// A file to write, ending in one of these extensions (none: any name; a `PathBuf`).
    OutFile(&'static [&'static str]),
    /// As [`Kind::OutFile`], kept as text (`bench --output`).
    OutText(&'static [&'static str]),
}

/// One row of the table: the commands that have the flag (empty: every command with a flag
/// of that name, unless a row names the command), the flag, its kind and unit.
#[derive(Debug, Clone)]
pub struct Flag {
    /// The commands this row is for; empty for every command without a row of its own.
    pub commands: &'static [&'static str],
    /// The flag (`--pressure`) or, for a positional argument, its clap id (`file`).
    pub name: &'static str,
    /// What it takes.
    pub kind: Kind,
    /// The unit of its value ("" for a pure number or a name).
    pub unit: &'static str,
}

const fn row(name: &'static str, kind: Kind, unit: &'static str) -> Flag {
    Flag {
        commands: &[],
        name,
        kind,
        unit,
    }
}

const fn only(commands: &'static [&'static str], name: &'static str, kind: Kind, unit: &'static str) -> Flag {
    Flag {
        commands,
        name,
        kind,
        unit,
    }
}

const SVG: &[&str] = &["svg"];
const PNG: &[&str] = &["png"];
/// The text formats a map is saved in (and read back from).
const MAP_TEXT: &[&str] = &["txt", "asc", "dat"];
/// Every format a map is written in (and read back from).
const MAP_ALL: &[&str] = &["txt", "asc", "dat", "xyz", "npy", "gsf"];

/// The whole table: every flag of every command.
pub fn table() -> Vec<Flag> {
    use Kind::*;
    vec![
        // the scene (run, sweep, gfmd, tui, gauge, compare)
        row("--preset", Text(check_preset), ""),
        row("--model", Model, ""),
        row("--fudge-gamma", Number(Field::FudgeGamma), ""),
        row("--c1", Number(Field::C1), ""),
        row("--c2", Number(Field::C2), ""),
        row("--alpha", Number(Field::Alpha), ""),
        row("--k-griffith", Number(Field::KGriffith), ""),
        row("--cap", Choice, ""),
        row("--thickness", Thickness, "1/q_r"),
        row("--gamma", Number(Field::SurfaceEnergy), "J/m^2"),
        row("--pressure", Number(Field::Pressure), "E* g"),
        // a measured surface (the scene's commands, figure, psd)
        row("--surface", InFile, ""),
        row("--psd", InFile, ""),
        row("--size", Number(Field::SystemSize), "m"),
        row("--height-unit", Choice, ""),
        row("--periodic", Switch, ""),
        row("--qmin", Number(Field::QMin), "1/m"),
        row("--qmax", Number(Field::QMax), "1/m"),
        // run's accuracy knobs
        row("--sigma-points", Count(Field::SigmaPoints), ""),
        row("--sigma-max", Number(Field::SigmaMax), "E* g"),
        row("--rtol", Number(Field::Rtol), ""),
        row("--adhesion-steps", Number(Field::AdhesionSteps), "per ln q"),
        row("--adhesion-points", Number(Field::AdhesionPoints), "per width"),
        row("--adhesion-tol", Number(Field::AdhesionTol), ""),
        row("--format", Choice, ""),
        // tour
        only(&["tour"], "tour", Text(check_tour), ""),
        row("--step", Step(Field::TourStep), ""),
        row("--list", Switch, ""),
        // tui
        row("--mouse", Switch, ""),
        // bench
        row("--quick", Switch, ""),
        row("--output", OutText(&["md"]), ""),
        // sweep
        row("--over", Choice, ""),
        only(&["sweep"], "--from", SweepEnd(Field::SweepFrom), ""),
        only(&["sweep"], "--to", SweepEnd(Field::SweepTo), ""),
        only(
            &["sweep", "gfmd", "gauge", "compare"],
            "--points",
            Count(Field::SweepPoints),
            "",
        ),
        // gfmd (and gauge --reference gfmd, figure --gfmd)
        row("--grid", Whole(Field::Grid), "points"),
        row("--seed", Seed(Field::Seed), ""),
        row("--save-surface", OutFile(MAP_TEXT), ""),
        row("--tolerance", Number(Field::GfmdTolerance), ""),
        row("--max-iterations", Count(Field::MaxIterations), ""),
        row("--bins", Count(Field::Bins), ""),
        row("--method", Choice, ""),
        row("--raw-adhesion", Switch, ""),
        row("--extrapolate", Switch, ""),
        row("--cycle", Switch, ""),
        row("--pull-off", Switch, ""),
        row("--ladder", Ladder, "lambda_s/da"),
        row("--seeds", Count(Field::Seeds), ""),
        only(&["gfmd", "gauge", "compare"], "--from", Number(Field::Pressure), "E* g"),
        only(&["gfmd", "gauge", "compare"], "--to", Number(Field::Pressure), "E* g"),
        // figure
        only(&["figure"], "id", Text(check_figure), ""),
        row("--gfmd", Switch, ""),
        only(&["figure"], "--points", Count(Field::FigurePoints), ""),
        row("--width", Count(Field::ChartWidth), "characters"),
        row("--height", Count(Field::ChartHeight), "lines"),
        only(&["figure"], "--model", Text(check_figure_models), ""),
        row("--svg", OutFile(SVG), ""),
        row("--png", OutFile(PNG), ""),
        // gauge and compare
        row("--fit", Text(check_fit), ""),
        row("--reference", Text(check_reference), ""),
        row("--pr", InFile, ""),
        row("--observables", Text(check_observables), ""),
        row("--save-reference", OutFile(&["csv"]), ""),
        row("--save-preset", OutFile(&["toml"]), ""),
        row("--models", Text(check_models), ""),
        row("--fitted", InFile, ""),
        // psd
        only(&["psd"], "file", InFile, ""),
        row("--bins-per-decade", Number(Field::BinsPerDecade), "per decade"),
        // surface generate
        only(&["surface"], "action", Choice, ""),
        only(&["surface"], "--output", OutFile(MAP_ALL), ""),
        row("--hurst", Number(Field::Hurst), ""),
        row("--rolloff-wavelength", Number(Field::RolloffWavelength), "m"),
        row("--short-wavelength", Number(Field::ShortWavelength), "m"),
        row("--rms-gradient", Number(Field::RmsGradient), ""),
        row("--rms-height", Number(Field::RmsHeight), "m"),
        row("--non-periodic", Switch, ""),
    ]
}

/// The row of flag `name` of `command`: the command's own row, else the shared one.
pub fn lookup(command: &str, name: &str) -> Option<Flag> {
    let t = table();
    t.iter()
        .find(|f| f.name == name && f.commands.contains(&command))
        .or_else(|| t.iter().find(|f| f.name == name && f.commands.is_empty()))
        .cloned()
}

/// The name a row is looked up by: `--long` for a flag, the clap id for a positional.
pub fn name_of(arg: &clap::Arg) -> String {
    match arg.get_long() {
        Some(l) => format!("--{l}"),
        None => arg.get_id().to_string(),
    }
}

impl Kind {
    /// The field of the range table ([`limits::FIELDS`]) a number or a name of this kind sets;
    /// None for choices, switches, texts and files.
    pub fn field(&self) -> Option<Field> {
        match self {
            Kind::Number(f) | Kind::Count(f) | Kind::Whole(f) | Kind::Seed(f) | Kind::Step(f) | Kind::SweepEnd(f) => {
                Some(f.clone())
            }
            Kind::Thickness => Some(Field::Thickness),
            Kind::Model => Some(Field::Model),
            Kind::Ladder => Some(Field::Ladder),
            _ => None,
        }
    }

    /// What the flag accepts, in the words of its messages.
    pub fn allowed(&self, name: &str) -> String {
        let bare = name.trim_start_matches('-').replace('-', "_");
        match self {
            Kind::Number(f) | Kind::Count(f) | Kind::Whole(f) => describe(f, &bare),
            Kind::Seed(_) => format!("a whole number 0 <= seed <= {}", u64::MAX),
            Kind::Step(_) => "a whole number 1 <= step <= the tour's number of steps".into(),
            Kind::SweepEnd(_) => parse::sweep_end("").unwrap_err(),
            Kind::Thickness => describe(&Field::Thickness, "t·q_r"),
            Kind::Model => describe(&Field::Model, "model"),
            Kind::Ladder => format!("a comma-separated list of {}", describe(&Field::Ladder, "lambda_s/da")),
            Kind::Choice => "one of the names `--help` lists".into(),
            Kind::Switch => "no value".into(),
            Kind::Text(check) => check("").unwrap_err(),
            Kind::InFile => "an existing file".into(),
            Kind::OutFile(exts) | Kind::OutText(exts) => out_allowed(exts),
        }
    }

    /// The value parser of this kind, or None where clap's own one stays (choices, switches).
    fn parser(&self) -> Option<ValueParser> {
        Some(match self.clone() {
            Kind::Number(f) => ValueParser::new(parse::number(f)),
            Kind::Count(f) => ValueParser::new(parse::count(f)),
            Kind::Whole(f) => ValueParser::new(parse::whole(f)),
            Kind::Seed(_) => ValueParser::new(parse::whole_number_u64),
            Kind::Step(_) => ValueParser::new(parse::step),
            Kind::SweepEnd(_) => ValueParser::new(parse::sweep_end),
            Kind::Thickness => ValueParser::new(parse::thickness),
            Kind::Model => ValueParser::new(parse::model),
            Kind::Ladder => ValueParser::new(super::gfmd::ladder_rung),
            Kind::Choice | Kind::Switch => return None,
            Kind::Text(check) => ValueParser::new(move |s: &str| check(s).map(|()| s.to_string())),
            Kind::InFile => ValueParser::new(in_file),
            Kind::OutFile(exts) => ValueParser::new(move |s: &str| out_file(s, exts)),
            Kind::OutText(exts) => ValueParser::new(move |s: &str| out_file(s, exts).map(|_| s.to_string())),
        })
    }
}

/// A field's library range described with `name`.
fn describe(field: &Field, name: &str) -> String {
    limits::allowed(field).map_or_else(|| "a number".into(), |a| a.describe(name))
}

fn out_allowed(exts: &[&str]) -> String {
    match exts {
        [] => "a file name in an existing, writable folder".into(),
        [e] => format!("a file name ending in .{e}, in an existing, writable folder"),
        _ => format!(
            "a file name ending in .{}, in an existing, writable folder",
            exts.join(", .")
        ),
    }
}

/// A file to read: it exists and is not a folder.
pub fn in_file(s: &str) -> Result<PathBuf, String> {
    let p = PathBuf::from(s);
    if s.trim().is_empty() {
        return Err("a file name".into());
    }
    if p.is_dir() {
        return Err("a file, not a folder".into());
    }
    if !p.exists() {
        return Err("an existing file (no such file)".into());
    }
    // a FIFO or a device is refused before anything opens it (a FIFO would block)
    use asperity::input::file::{refusal, MAX_INPUT_BYTES};
    match refusal(&p, MAX_INPUT_BYTES) {
        Some(why) => Err(why),
        None => Ok(p),
    }
}

/// A file to write: the extension `exts` asks for, not a folder, in an existing folder, and
/// writable as a file ([`super::outfile::refusal`]: an existing one opened for appending, a
/// new one created and removed at once; devices, FIFOs and names over 255 bytes refused).
pub fn out_file(s: &str, exts: &[&str]) -> Result<PathBuf, String> {
    let p = PathBuf::from(s);
    let ext_ok = exts.is_empty()
        || p.extension()
            .and_then(|x| x.to_str())
            .is_some_and(|x| exts.iter().any(|e| x.eq_ignore_ascii_case(e)));
    if s.trim().is_empty() || !ext_ok {
        return Err(out_allowed(exts));
    }
    let dir = match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if !dir.is_dir() {
        return Err(format!("{} (no such folder)", out_allowed(exts)));
    }
    match super::outfile::refusal(&p) {
        Some(why) => Err(format!("{} ({why})", out_allowed(exts))),
        None => Ok(p),
    }
}

fn check_fit(s: &str) -> Result<(), String> {
    asperity::fit::Param::parse_list(s).map(|_| ()).map_err(|e| match e {
        asperity::error::Error::Invalid { allowed, .. } => allowed.describe("fit"),
        e => e.to_string(),
    })
}

/// A built-in or local name among `names`, or a file that exists.
fn name_or_file(s: &str, names: Vec<(String, String)>, what: &str) -> Result<(), String> {
    let t = s.trim();
    if !t.is_empty() && (names.iter().any(|(n, _)| n == t) || Path::new(t).is_file()) {
        return Ok(());
    }
    let list: Vec<String> = names.into_iter().map(|(n, _)| n).collect();
    Err(format!("{} or a {what} TOML file", list.join(", ")))
}

/// `--preset`: a preset's name or a preset file (its keys are checked when it is read).
fn check_preset(s: &str) -> Result<(), String> {
    name_or_file(s, asperity::input::preset::list_available(), "preset")
}

/// `tour NAME`: a tour's name or a tour file.
fn check_tour(s: &str) -> Result<(), String> {
    name_or_file(s, crate::tui::tour::list_available(), "tour")
}

/// `figure ID`: a figure of the paper or a figure file.
fn check_figure(s: &str) -> Result<(), String> {
    name_or_file(s, asperity::report::figure::list(), "figure")
}

/// `--reference`: eq18, gfmd or a CSV file that exists.
fn check_reference(s: &str) -> Result<(), String> {
    let t = s.trim();
    if t == "eq18" || t == "gfmd" || in_file(t).is_ok_and(|p| p.is_file()) {
        Ok(())
    } else {
        Err("eq18, gfmd or an existing CSV file (p, a_r, ...)".into())
    }
}

fn check_observables(s: &str) -> Result<(), String> {
    let ok = s.split(',').map(str::trim).all(|t| {
        asperity::fit::reference::Observable::ALL
            .into_iter()
            .any(|o| o.key() == t)
    });
    if ok && !s.trim().is_empty() {
        Ok(())
    } else {
        Err("a comma-separated list of a_r, mean_contact_stress, mean_gap_rel, pr".into())
    }
}

/// `compare --models`: 1–5, yp08, xu24 (a custom model comes in with --fitted).
fn check_models(s: &str) -> Result<(), String> {
    let allowed = format!(
        "a comma-separated list of {}",
        asperity::input::model::ModelKind::named_list()
    );
    let mut any = false;
    for t in s.split(',').map(str::trim).filter(|t| !t.is_empty()) {
        match t.parse::<asperity::input::model::ModelKind>() {
            Ok(asperity::input::model::ModelKind::Custom) => {
                return Err(format!("{allowed} (a custom model comes in with --fitted PRESET)"))
            }
            Ok(_) => any = true,
            Err(_) => return Err(allowed),
        }
    }
    if any {
        Ok(())
    } else {
        Err(allowed)
    }
}

/// One name of `figure --model` (a comma-separated list, split by clap).
fn check_figure_models(s: &str) -> Result<(), String> {
    check_models(s).map_err(|_| {
        format!(
            "a comma-separated list of {}",
            asperity::input::model::ModelKind::named_list()
        )
    })
}

/// The parser of the whole command line: the derived [`super::Cli`] with every flag's value
/// parser and `allow_hyphen_values` set from its row of the table (a value that starts with
/// `-` is the flag's value, refused by its range, not an unknown option).
pub fn command() -> clap::Command {
    use clap::CommandFactory;
    let mut cmd = super::Cli::command();
    let names: Vec<String> = cmd.get_subcommands().map(|s| s.get_name().to_string()).collect();
    for sub in names {
        cmd = cmd.mut_subcommand(&sub, |s| {
            let name = s.get_name().to_string();
            s.mut_args(|a| drive(&name, a))
        });
    }
    cmd
}

/// Sets one argument's parsing from its row.
fn drive(command: &str, arg: clap::Arg) -> clap::Arg {
    let name = name_of(&arg);
    let Some(flag) = lookup(command, &name) else {
        return arg;
    };
    let takes_value = arg.get_action().takes_values();
    let arg = if takes_value {
        arg.allow_hyphen_values(true)
    } else {
        arg
    };
    // a positional argument is named in messages by what it is (`invalid figure = 9`)
    let arg = if arg.get_long().is_none() && command == "figure" {
        arg.value_name("FIGURE")
    } else {
        arg
    };
    match flag.kind.parser() {
        Some(p) if takes_value => arg.value_parser(p),
        _ => arg,
    }
}
