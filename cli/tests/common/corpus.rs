//! The bad-input corpus's shared parts: every flag of the parser, running the binary with work
//! forbidden, a scratch folder per test, and whether a flag's row of the table allows a value (decided from the
//! row's kind and the library's ranges, never by running the parser).

use asperity::error::Range;
use asperity_cli::cli::flags::{self, Kind};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Every argument of every command of the parser ([`flags::command`]) but help and version:
/// (command, argument, its name in the flag table).
pub fn every_arg() -> Vec<(String, clap::Arg, String)> {
    let cmd = flags::command();
    cmd.get_subcommands()
        .flat_map(|sub| {
            sub.get_arguments()
                .filter(|arg| !matches!(arg.get_id().as_str(), "help" | "version"))
                .map(|arg| (sub.get_name().to_string(), arg.clone(), flags::name_of(arg)))
        })
        .collect()
}

/// A scratch folder of this test process.
pub fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-corpus-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// What one run of the binary left: exit code, stdout, stderr and the work log's line.
pub struct Ran {
    /// The exit code (-1 when killed by a signal).
    pub code: i32,
    /// Everything on stdout.
    pub out: String,
    /// Everything on stderr.
    pub err: String,
    /// The work log (`work started: N`).
    pub work: String,
}

/// Runs the binary in the repository root with work forbidden (a computation that starts
/// panics) and the work log at `log`.
pub fn run_forbidden(args: &[String], log: &Path) -> Ran {
    let _ = std::fs::remove_file(log);
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .env(asperity_cli::cli::FORBID_WORK_ENV, "1")
        .env(asperity_cli::cli::WORK_LOG_ENV, log)
        .env_remove("RUST_BACKTRACE")
        .output()
        .unwrap();
    Ran {
        code: out.status.code().unwrap_or(-1),
        out: String::from_utf8_lossy(&out.stdout).into_owned(),
        err: String::from_utf8_lossy(&out.stderr).into_owned(),
        work: std::fs::read_to_string(log).unwrap_or_default(),
    }
}

/// Whether the table's row `kind` of `arg` allows `v`.
pub fn allowed(kind: &Kind, arg: &clap::Arg, v: &str) -> bool {
    let num = v.trim().parse::<f64>().ok();
    let in_range = |r: Option<Range>| matches!((num, r), (Some(x), Some(r)) if r.contains(x));
    let field_range = |f: &asperity::error::Field| asperity::limits::allowed(f).and_then(|a| a.range().copied());
    match kind {
        Kind::Number(f) => in_range(field_range(f)),
        // a count is a machine integer too
        Kind::Count(f) => in_range(field_range(f)) && num.is_some_and(|x| x <= usize::MAX as f64),
        Kind::Whole(f) => in_range(field_range(f)) && num.is_some_and(|x| x <= i64::MAX as f64),
        Kind::Seed(_) => v.trim().parse::<u64>().is_ok(),
        Kind::Step(_) => num.is_some_and(|x| x >= 1.0 && x.fract() == 0.0 && x <= i64::MAX as f64),
        // the default --over pressure
        Kind::SweepEnd(_) => in_range(field_range(&asperity::error::Field::Pressure)),
        Kind::Thickness => {
            num.is_some_and(|x| x == f64::INFINITY) || in_range(field_range(&asperity::error::Field::Thickness))
        }
        Kind::Model => v.parse::<asperity::input::model::ModelKind>().is_ok(),
        Kind::Ladder => in_range(field_range(&asperity::error::Field::Ladder)),
        Kind::Choice => arg
            .get_possible_values()
            .iter()
            .any(|p| p.matches(v, arg.is_ignore_case_set())),
        Kind::Switch => true,
        // a name or a list: as its own check says; a file to read: none of the hard values
        Kind::Text(check) => check(v).is_ok(),
        Kind::InFile => false,
        Kind::OutFile(exts) | Kind::OutText(exts) => {
            let p = Path::new(v);
            let ext = p.extension().and_then(|e| e.to_str()).unwrap_or("");
            let dir = p
                .parent()
                .filter(|d| !d.as_os_str().is_empty())
                .unwrap_or(Path::new("."));
            !v.is_empty() && !p.is_dir() && exts.contains(&ext) && dir.is_dir()
        }
    }
}

/// Flags a command needs to get to its own checks, with values that pass them (`map`: a
/// small height map for `psd`'s positional FILE), leaving out `skip`.
pub fn context(sub: &str, skip: &str, map: &str) -> Vec<String> {
    // a map to write, beside the map read
    let out = format!("{map}.npy");
    let all: Vec<(&str, &str)> = match sub {
        "sweep" => vec![("--from", "0.01"), ("--to", "0.1")],
        "gauge" => vec![("--fit", "w0"), ("--reference", "eq18")],
        "compare" => vec![("--reference", "eq18")],
        "psd" => vec![("file", map)],
        "surface" => vec![("action", "generate"), ("--output", out.as_str())],
        _ => vec![],
    };
    let mut out = Vec::new();
    for (k, v) in all.into_iter().filter(|(k, _)| *k != skip) {
        if k.starts_with("--") {
            out.push(k.to_string());
        }
        out.push(v.to_string());
    }
    out
}

/// A small rough map (8 × 8) in `dir`, for `psd`'s positional FILE; returns its path.
pub fn write_map(dir: &Path) -> String {
    let p = dir.join("ok.txt");
    let rows: Vec<String> = (0..8)
        .map(|i| {
            (0..8)
                .map(|j| format!("{:e}", 1e-9 * ((i * 7 + j * 3) % 5) as f64))
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect();
    std::fs::write(&p, rows.join("\n")).unwrap();
    p.display().to_string()
}

/// A NumPy file: the header (dict text) and `data`, as version 1.0.
pub fn npy(header: &str, data: &[u8]) -> Vec<u8> {
    let mut h = header.to_string();
    while !(10 + h.len() + 1).is_multiple_of(64) {
        h.push(' ');
    }
    h.push('\n');
    let mut b = b"\x93NUMPY\x01\x00".to_vec();
    b.extend((h.len() as u16).to_le_bytes());
    b.extend(h.as_bytes());
    b.extend(data);
    b
}
