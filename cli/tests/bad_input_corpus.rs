//! The bad-input corpus: command lines generated from the parser itself (every flag of every
//! command, [`asperity_cli::cli::flags::command`]) and from every kind of file a flag reads,
//! each run through the binary with work forbidden, and the rule checked line by line:
//!
//! - exit code 2, nothing on stdout, exactly one line on stderr of at most 200 characters;
//! - the line names the flag the user gave (or, for a positional argument, the file's name);
//! - it shows the value (a long one shortened) and says what is allowed;
//! - no Rust debug text (`Some(`, `Os {`, a panic, a backtrace);
//! - no computation started, and no output file left behind (each command that writes a file
//!   is given one to write, in an empty folder that must stay empty).
//!
//! Values: NaN, ±inf, 0, −0, negatives, huge (1e300, a 300-digit number, 1e400), tiny (1e-300,
//! the smallest normal double), subnormal (1e-320, 5e-324), empty, blank, words, a decimal
//! comma, hex; each flag also repeated. Files: missing, a folder, a FIFO, /dev/zero, /dev/null,
//! a `.txt` link to /dev/zero, binary, empty, truncated, a huge header, decimal commas.
//!
//! The corpus's size and pass rate per command are printed (`--nocapture`).

mod common;

use asperity_cli::cli::flags::{self, Kind};
use common::corpus::{allowed, context, every_arg, npy, run_forbidden, scratch, write_map, Ran};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One generated command line and what its refusal must show.
struct Case {
    /// The command (`run`, `psd`, ...).
    command: String,
    /// The whole argument list.
    args: Vec<String>,
    /// What the line must name: the flag, or for a positional argument the file's name.
    names: String,
    /// The value the line must show ("" for a switch repeated).
    value: String,
    /// Whether the line must say what is allowed.
    needs_allowed: bool,
    /// Whether the flag takes a comma-separated list (its refusal shows the item refused).
    list: bool,
}

/// The hard numeric and text values.
fn values() -> Vec<String> {
    let mut v: Vec<String> = [
        "nan",
        "NaN",
        "inf",
        "-inf",
        "+inf",
        "0",
        "-0",
        "-1",
        "-1e300",
        "1e300",
        "1e400",
        "1e-300",
        "2.2250738585072014e-308",
        "1e-320",
        "5e-324",
        "",
        " ",
        "abc",
        "1,5",
        "0x10",
    ]
    .into_iter()
    .map(String::from)
    .collect();
    v.push(format!("1{}", "0".repeat(299)));
    v
}

/// An output file each command that writes one is given, in the folder `out`: it must not
/// be there after a refusal.
fn output_flag(command: &str, out: &Path) -> Option<(&'static str, PathBuf)> {
    match command {
        "psd" | "figure" => Some(("--svg", out.join("chart.svg"))),
        "gauge" => Some(("--save-preset", out.join("fitted.toml"))),
        "gfmd" => Some(("--save-surface", out.join("map.txt"))),
        "bench" => Some(("--output", out.join("bench.md"))),
        _ => None,
    }
}

/// A value the row allows, for the repeated-flag cases (none: no repeated case).
fn sample(kind: &Kind, arg: &clap::Arg, dir: &Path) -> Option<String> {
    if let Kind::Choice = kind {
        return arg.get_possible_values().first().map(|p| p.get_name().to_string());
    }
    if let Kind::OutFile(exts) | Kind::OutText(exts) = kind {
        let ext = exts.first().copied().unwrap_or("txt");
        return Some(dir.join(format!("twice.{ext}")).display().to_string());
    }
    ["0.01", "1", "0.5", "2", "10", "64", "1e-6", "0", "3"]
        .into_iter()
        .find(|v| allowed(kind, arg, v))
        .map(String::from)
}

/// Every flag of every command × the hard values, and each flag repeated.
fn flag_cases(dir: &Path, out: &Path, map: &str) -> Vec<Case> {
    let mut cases = Vec::new();
    for (s, arg, name) in every_arg() {
        let (s, arg) = (s.as_str(), &arg);
        let id = arg.get_id().as_str();
        let Some(row) = flags::lookup(s, &name) else { continue };
        let positional = arg.get_long().is_none();
        let list = arg.get_value_delimiter().is_some();
        let mut base = vec![s.to_string()];
        // the map `surface generate` writes goes to the folder that must stay empty
        let written = format!("{map}.npy");
        base.extend(context(s, &name, map).into_iter().map(|a| {
            if a == written {
                out.join("map.npy").display().to_string()
            } else {
                a
            }
        }));
        if let Some((flag, path)) = output_flag(s, out).filter(|(f, _)| *f != name) {
            base.extend([flag.to_string(), path.display().to_string()]);
        }
        if !arg.get_action().takes_values() {
            // a switch given twice
            let mut args = base.clone();
            args.extend([name.clone(), name.clone()]);
            cases.push(Case {
                command: s.into(),
                args,
                names: name.clone(),
                value: String::new(),
                needs_allowed: false,
                list: false,
            });
            continue;
        }
        for v in values() {
            if allowed(&row.kind, arg, &v) {
                continue;
            }
            let mut args = base.clone();
            if !positional {
                args.push(name.clone());
            }
            args.push(v.clone());
            cases.push(Case {
                command: s.into(),
                args,
                names: if positional { id.to_string() } else { name.clone() },
                value: v,
                needs_allowed: true,
                list,
            });
        }
        // a list flag given twice appends to its list
        if positional || list {
            continue;
        }
        if let Some(v) = sample(&row.kind, arg, dir) {
            let mut args = base.clone();
            args.extend([name.clone(), v.clone(), name.clone(), v.clone()]);
            cases.push(Case {
                command: s.into(),
                args,
                names: name.clone(),
                value: v,
                needs_allowed: false,
                list: false,
            });
        }
    }
    cases
}

/// The hard files, by kind, each with the extension `ext`: (kind, path).
fn hard_files(dir: &Path, ext: &str) -> Vec<(&'static str, String)> {
    let put = |name: &str, bytes: &[u8]| {
        let p = dir.join(format!("{name}.{ext}"));
        std::fs::write(&p, bytes).unwrap();
        p.display().to_string()
    };
    let fifo = dir.join(format!("fifo.{ext}"));
    if !fifo.exists() {
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        assert!(made.is_ok_and(|s| s.success()), "mkfifo {}", fifo.display());
    }
    let link = dir.join(format!("zero-link.{ext}"));
    if !link.exists() {
        std::os::unix::fs::symlink("/dev/zero", &link).unwrap();
    }
    let folder = dir.join(format!("folder.{ext}"));
    std::fs::create_dir_all(&folder).unwrap();
    let truncated: Vec<u8> = match ext {
        "npy" => npy("{'descr': '<f8', 'fortran_order': False, 'shape': (4, 4), }", &[0; 40]),
        "gsf" => b"Gwyddion Simple Field 1.0\nXRes = 4\nYRes = 4\n\0\0\0\0\0\0\0\0".to_vec(),
        "toml" => b"[surface]\nhurst = 0.".to_vec(),
        _ => b"1e-9 2e-9 3e-9\n4e-9 5e".to_vec(),
    };
    let huge_header: Vec<u8> = match ext {
        "npy" => npy(
            "{'descr': '<f8', 'fortran_order': False, 'shape': (100000, 100000), }",
            &[0; 64],
        ),
        "gsf" => {
            b"Gwyddion Simple Field 1.0\nXRes = 31623\nYRes = 31623\nXReal = 1e-6\nYReal = 1e-6\n\0\0\0\0".to_vec()
        }
        _ => format!("# {}\n1 2\n3 4\n", "x".repeat(100_000)).into_bytes(),
    };
    let comma: &[u8] = match ext {
        "csv" => b"q,C\n1,0e6;2,5e-30\n2,0e6;1,1e-31\n",
        "toml" => b"[load]\npressure = 0,01\n",
        _ => b"-4,2247e-08 1,0220e-07 3,1e-08\n2,5e-08 -1,1e-08 4,0e-09\n1,2e-08 3,3e-08 -2,2e-08\n",
    };
    vec![
        ("missing", dir.join(format!("no-such.{ext}")).display().to_string()),
        ("folder", folder.display().to_string()),
        ("FIFO", fifo.display().to_string()),
        ("/dev/zero", "/dev/zero".into()),
        ("/dev/null", "/dev/null".into()),
        ("link to /dev/zero", link.display().to_string()),
        ("binary", put("binary", b"\x00\xff\xfe\x93 binary \x01\x02\x80\x81")),
        ("empty", put("empty", b"")),
        ("truncated", put("truncated", &truncated)),
        ("huge header", put("huge-header", &huge_header)),
        ("decimal commas", put("comma", comma)),
    ]
}

/// Every flag that reads a file × every hard file: (command, context, flag or positional id,
/// extensions).
fn file_cases(dir: &Path, out: &Path, map: &str) -> Vec<Case> {
    let readers: &[(&str, &[&str], &str, &[&str])] = &[
        ("psd", &[], "file", &["txt", "npy", "gsf"]),
        ("run", &[], "--surface", &["txt", "npy", "gsf"]),
        ("run", &[], "--psd", &["csv"]),
        ("run", &[], "--preset", &["toml"]),
        ("sweep", &["--from", "0.01", "--to", "0.1"], "--surface", &["txt"]),
        ("gfmd", &[], "--surface", &["txt", "npy"]),
        ("tui", &[], "--psd", &["csv"]),
        ("gauge", &["--fit", "w0"], "--reference", &["csv"]),
        ("gauge", &["--fit", "w0", "--reference", "eq18"], "--pr", &["csv"]),
        ("compare", &["--reference", "eq18"], "--fitted", &["toml"]),
        ("figure", &[], "id", &["toml"]),
        ("tour", &[], "tour", &["toml"]),
    ];
    let mut cases = Vec::new();
    for (command, ctx, flag, exts) in readers {
        for ext in *exts {
            for (_kind, path) in hard_files(dir, ext) {
                let mut args: Vec<String> = vec![command.to_string()];
                args.extend(ctx.iter().map(|s| s.to_string()));
                if let Some((f, p)) = output_flag(command, out) {
                    args.extend([f.to_string(), p.display().to_string()]);
                }
                let positional = !flag.starts_with("--");
                if !positional {
                    args.push(flag.to_string());
                }
                args.push(path.clone());
                if *command == "psd" || *flag == "--surface" {
                    args.extend(["--size".into(), "1e-6".into()]);
                }
                let _ = map;
                let file_name = Path::new(&path).file_name().unwrap().to_string_lossy().into_owned();
                cases.push(Case {
                    command: command.to_string(),
                    args,
                    names: if positional {
                        file_name.clone()
                    } else {
                        flag.to_string()
                    },
                    value: file_name,
                    needs_allowed: true,
                    list: false,
                });
            }
        }
    }
    cases
}

/// Rust's debug text and panics: never in a message.
const DEBUG_TEXT: &[&str] = &[
    "panicked",
    "backtrace",
    "Some(",
    "None)",
    "Os {",
    "kind:",
    "Error {",
    "Invalid {",
    "Numerical(",
    "\\\"",
    "\\n",
    "thread '",
];

/// The rule, checked on one run: the broken parts (none: the case passes).
fn check(case: &Case, r: &Ran, out: &Path) -> Vec<&'static str> {
    let line = r.err.trim_end();
    let lower = line.to_lowercase();
    let named = lower.contains(&case.names.trim_start_matches('-').to_lowercase());
    let v = case.value.trim();
    // a number too large for a double is shown as inf; a list by the item refused
    let overflows = v.parse::<f64>().is_ok_and(|x| x.is_infinite());
    let shows_value = v.chars().count() > 24
        || v.is_empty()
        || lower.contains(&v.to_lowercase())
        || (overflows && lower.contains("inf"))
        || (case.list
            && v.split(',')
                .any(|p| !p.trim().is_empty() && lower.contains(&p.trim().to_lowercase())));
    let says_allowed = !case.needs_allowed || line.split("allowed").nth(1).is_some_and(|t| t.trim().len() > 2);
    let left = std::fs::read_dir(out).map(|d| d.count()).unwrap_or(0);
    [
        (r.code != 2, "exit code not 2"),
        (!r.out.is_empty(), "stdout not empty"),
        (line.lines().count() != 1, "not one line"),
        (line.chars().count() > 200, "over 200 characters"),
        (!named, "does not name the flag"),
        (!shows_value, "does not show the value"),
        (!says_allowed, "does not say what is allowed"),
        (DEBUG_TEXT.iter().any(|d| line.contains(d)), "Rust debug text"),
        (!r.work.contains("work started: 0"), "work started"),
        (left > 0, "an output file left"),
    ]
    .into_iter()
    .filter_map(|(bad, what)| bad.then_some(what))
    .collect()
}

/// Runs every case on `workers` threads; returns (command, passed, what broke) per case.
fn run_all(cases: &[Case], dir: &Path, workers: usize) -> Vec<(String, Option<String>)> {
    let chunk = cases.len().div_ceil(workers).max(1);
    std::thread::scope(|s| {
        let handles: Vec<_> = cases
            .chunks(chunk)
            .enumerate()
            .map(|(w, part)| {
                s.spawn(move || {
                    let log = dir.join(format!("work-{w}.log"));
                    part.iter()
                        .map(|c| {
                            // each worker's own empty output folder, named in its cases
                            let out = dir.join("out");
                            let args: Vec<String> = c
                                .args
                                .iter()
                                .map(|a| {
                                    a.replace(
                                        &out.display().to_string(),
                                        &dir.join(format!("out-{w}")).display().to_string(),
                                    )
                                })
                                .collect();
                            let own_out = dir.join(format!("out-{w}"));
                            std::fs::create_dir_all(&own_out).unwrap();
                            let r = run_forbidden(&args, &log);
                            let broken = check(c, &r, &own_out);
                            // clear what a broken case left, for the next one
                            for e in std::fs::read_dir(&own_out).unwrap().flatten() {
                                let _ = std::fs::remove_file(e.path());
                            }
                            let why = (!broken.is_empty()).then(|| {
                                format!(
                                    "{:?} {:?}: {}",
                                    broken,
                                    args,
                                    r.err.trim_end().lines().next().unwrap_or("")
                                )
                            });
                            (c.command.clone(), why)
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    })
}

#[test]
fn the_bad_input_corpus_is_refused_by_the_rule() {
    let dir = scratch("cases");
    let files = dir.join("files");
    std::fs::create_dir_all(&files).unwrap();
    let out = dir.join("out");
    let map = write_map(&dir);
    let mut cases = flag_cases(&dir, &out, &map);
    let n_flags = cases.len();
    cases.extend(file_cases(&files, &out, &map));
    let results = run_all(&cases, &dir, 3);
    let _ = std::fs::remove_dir_all(&dir);
    let mut per: BTreeMap<String, (usize, usize)> = BTreeMap::new();
    let mut broken = Vec::new();
    for (command, why) in results {
        let e = per.entry(command).or_default();
        e.0 += 1;
        match why {
            None => e.1 += 1,
            Some(w) => broken.push(w),
        }
    }
    eprintln!(
        "corpus: {} cases ({n_flags} flag values, {} files)",
        cases.len(),
        cases.len() - n_flags
    );
    for (command, (n, ok)) in &per {
        eprintln!("  {command:<8} {ok:>5} / {n:<5} meet the rule");
    }
    assert!(cases.len() >= 2000, "only {} cases", cases.len());
    assert!(
        broken.is_empty(),
        "{} of {} cases break the rule:\n{}",
        broken.len(),
        cases.len(),
        broken.join("\n")
    );
}
