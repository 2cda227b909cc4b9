//! Every flag of every command, enumerated from the parser itself (clap's introspection of
//! [`asperity_cli::cli::flags::command`], not a hand list), against a set of hard values:
//! where the flag's row of the table ([`asperity_cli::cli::flags::table`]) says a value is
//! allowed, the parser accepts it; where it is not, the binary exits with code 2 and one line
//! of at most 200 characters naming the flag, the value and what is allowed, and no
//! computation started (the binary runs with `ASPERITY_FORBID_WORK`: a computation that
//! starts panics, and `ASPERITY_WORK_LOG` records how many started).
//!
//! The same for the surface readers (empty, 1×1, ragged, NaN/inf/1e200 heights, all zero,
//! truncated, wrong dtype, garbage, a 10⁹-point header) and the numeric keys of a preset
//! (every key of a preset and of a tour: cli_every_key.rs).

mod common;

use asperity_cli::cli::flags;
use common::corpus::{allowed, context, every_arg, npy, run_forbidden, scratch, write_map};
use std::path::Path;

/// Runs the binary with work forbidden; returns (exit code, stdout, stderr, work started).
fn run(args: &[String], log: &Path) -> (i32, String, String, String) {
    let r = run_forbidden(args, log);
    (r.code, r.out, r.err, r.work)
}

/// The hard values: -1, 0, 1e300, nan, inf, '', abc, a 300-digit number, a missing file, a
/// folder.
fn values(dir: &Path) -> Vec<String> {
    vec![
        "-1".into(),
        "0".into(),
        "1e300".into(),
        "nan".into(),
        "inf".into(),
        String::new(),
        "abc".into(),
        format!("1{}", "0".repeat(299)),
        dir.join("no-such-file.txt").display().to_string(),
        dir.display().to_string(),
    ]
}

/// Checks one refused case: exit 2, nothing on stdout, one line of at most 200 characters
/// naming `name` and saying what is allowed, no computation started.
fn refused_well(code: i32, out: &str, err: &str, log: &str, name: &str, v: &str) -> Result<(), String> {
    let line = err.trim_end();
    let named = line
        .to_ascii_lowercase()
        .contains(&name.trim_start_matches('-').to_ascii_lowercase());
    let shows_value = v.chars().count() > 24
        || (v.is_empty() && line.contains("\"\""))
        || line.to_ascii_lowercase().contains(&v.trim().to_ascii_lowercase());
    let allowed_text = line.split("allowed").nth(1).is_some_and(|t| t.trim().len() > 2);
    let problems: Vec<&str> = [
        (code != 2, "exit code not 2"),
        (!out.is_empty(), "stdout not empty"),
        (line.lines().count() != 1, "not one line"),
        (line.chars().count() > 200, "longer than 200 characters"),
        (!named, "does not name the flag"),
        (!shows_value, "does not show the value"),
        (!allowed_text, "does not say what is allowed"),
        (!log.contains("work started: 0"), "work started"),
    ]
    .into_iter()
    .filter_map(|(bad, what)| bad.then_some(what))
    .collect();
    if problems.is_empty() {
        Ok(())
    } else {
        Err(format!("{problems:?} (exit {code}): {line}"))
    }
}

#[test]
fn every_flag_of_every_command_refuses_hard_values_in_one_line_before_any_work() {
    let dir = scratch("flags");
    let log = dir.join("work.log");
    let map = write_map(&dir);
    let (mut cases, mut flags_seen, mut accepted) = (0, 0, 0);
    let mut broken = Vec::new();
    for (s, arg, name) in every_arg() {
        let (s, arg) = (s.as_str(), &arg);
        let id = arg.get_id().as_str();
        let Some(row) = flags::lookup(s, &name) else {
            broken.push(format!("{s} {name}: no row in the flag table"));
            continue;
        };
        flags_seen += 1;
        if !arg.get_action().takes_values() {
            continue;
        }
        let positional = arg.get_long().is_none();
        for v in values(&dir) {
            cases += 1;
            let mut args = vec![s.to_string()];
            args.extend(context(s, &name, &map));
            if !positional {
                args.push(name.clone());
            }
            args.push(v.clone());
            if allowed(&row.kind, arg, &v) {
                accepted += 1;
                // the parser takes it (other flags may still be missing: not a value error)
                let mut full = vec!["asperity".to_string()];
                full.extend(args.iter().cloned());
                if let Err(e) = flags::command().try_get_matches_from(&full) {
                    use clap::error::ErrorKind::*;
                    if matches!(e.kind(), ValueValidation | InvalidValue | UnknownArgument) {
                        broken.push(format!("{args:?}: refused a value the table allows: {e}"));
                    }
                }
                continue;
            }
            let (code, out, err, work) = run(&args, &log);
            if let Err(why) = refused_well(code, &out, &err, &work, if positional { id } else { &name }, &v) {
                broken.push(format!("{args:?}: {why}"));
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    eprintln!("{flags_seen} flags enumerated; {cases} cases, {accepted} of them allowed values");
    assert!(flags_seen >= 90, "only {flags_seen} flags enumerated");
    assert!(cases >= 700, "only {cases} cases");
    assert!(accepted > 0 && accepted < cases / 4, "{accepted} of {cases} accepted");
    assert!(
        broken.is_empty(),
        "{} of {cases} cases break the rule:\n{}",
        broken.len(),
        broken.join("\n")
    );
}

#[test]
fn every_row_of_the_table_is_a_flag_of_the_parser() {
    let cmd = flags::command();
    for row in flags::table() {
        let found = cmd
            .get_subcommands()
            .filter(|s| row.commands.is_empty() || row.commands.contains(&s.get_name()))
            .any(|s| s.get_arguments().any(|a| flags::name_of(a) == row.name));
        assert!(found, "{} ({:?}): no such flag", row.name, row.commands);
    }
}

/// Writes `bytes` as `name` in `dir`; returns its path.
fn file(dir: &Path, name: &str, bytes: &[u8]) -> String {
    let p = dir.join(name);
    std::fs::write(&p, bytes).unwrap();
    p.display().to_string()
}

#[test]
fn every_hard_surface_file_is_refused_in_one_line_naming_the_file() {
    let dir = scratch("maps");
    let log = dir.join("work.log");
    let f8 = |n: usize| vec![0u8; 8 * n];
    let gsf_huge = {
        let mut b = b"Gwyddion Simple Field 1.0\nXRes = 31623\nYRes = 31623\nXReal = 1e-6\nYReal = 1e-6\n".to_vec();
        while !b.len().is_multiple_of(4) {
            b.push(0);
        }
        b.extend([0u8; 16]);
        b
    };
    let cases: Vec<(String, &str)> = vec![
        (file(&dir, "empty.txt", b""), "empty"),
        (file(&dir, "one.txt", b"1e-9\n"), "1x1"),
        (
            file(&dir, "ragged.txt", b"1e-9 2e-9 3e-9\n1e-9 2e-9\n3e-9 1e-9 2e-9\n"),
            "ragged",
        ),
        (file(&dir, "nan.txt", b"1e-9 nan\n2e-9 3e-9\n"), "NaN"),
        (file(&dir, "inf.txt", b"1e-9 inf\n2e-9 3e-9\n"), "inf"),
        (file(&dir, "huge.txt", b"1e200 0\n0 -1e200\n"), "1e200"),
        (
            file(&dir, "zero.txt", b"0 0 0 0\n0 0 0 0\n0 0 0 0\n0 0 0 0\n"),
            "all zero",
        ),
        (file(&dir, "garbage.txt", b"\x00\xff\xfe binary \x01\x02"), "garbage"),
        (
            file(&dir, "garbage.npy", b"\x00\xff\xfe binary \x01\x02"),
            "garbage npy",
        ),
        (
            file(&dir, "garbage.gsf", b"\x00\xff\xfe binary \x01\x02"),
            "garbage gsf",
        ),
        (
            file(
                &dir,
                "truncated.npy",
                &npy("{'descr': '<f8', 'fortran_order': False, 'shape': (4, 4), }", &f8(5)),
            ),
            "truncated",
        ),
        (
            file(
                &dir,
                "dtype.npy",
                &npy("{'descr': '<c16', 'fortran_order': False, 'shape': (2, 2), }", &f8(8)),
            ),
            "wrong dtype",
        ),
        (file(&dir, "huge-header.gsf", &gsf_huge), "a 10^9-point header"),
        (
            file(&dir, "wide.txt", b"# Width: 1e300 m\n1e-9 2e-9\n3e-9 1e-9\n"),
            "a 1e300 m width",
        ),
    ];
    let mut broken = Vec::new();
    let mut n = 0;
    for (path, what) in &cases {
        let name = Path::new(path).file_name().unwrap().to_str().unwrap().to_string();
        // the 1e300 m width is the file's own: without --size (which would override it)
        let own_size = *what == "a 1e300 m width";
        let size: Vec<String> = if own_size {
            vec![]
        } else {
            vec!["--size".into(), "1e-6".into()]
        };
        for mut args in [
            vec!["psd".to_string(), path.clone()],
            vec!["run".to_string(), "--surface".into(), path.clone()],
            vec!["gfmd".to_string(), "--surface".into(), path.clone()],
        ] {
            args.extend(size.iter().cloned());
            n += 1;
            let (code, out, err, work) = run(&args, &log);
            let line = err.trim_end();
            let ok = code == 2
                && out.is_empty()
                && line.lines().count() == 1
                && line.chars().count() <= 200
                && line.contains(&name)
                && !(own_size && line.contains("--size"))
                && work.contains("work started: 0");
            if !ok {
                broken.push(format!("{what}: {args:?} -> exit {code}: {line}"));
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(n >= 40, "{n} cases");
    assert!(broken.is_empty(), "{} of {n}:\n{}", broken.len(), broken.join("\n"));
}

#[test]
fn every_numeric_preset_key_refuses_hard_values_naming_the_key() {
    let dir = scratch("presets");
    let log = dir.join("work.log");
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../presets/system-2.toml")).unwrap();
    let mut section = String::new();
    let (mut n, mut broken) = (0, Vec::new());
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if t.starts_with('[') {
            section = t.trim_matches(|c| c == '[' || c == ']').to_string();
            continue;
        }
        let Some((key, value)) = t.split_once('=') else {
            continue;
        };
        let (key, value) = (key.trim(), value.split('#').next().unwrap().trim());
        if value.parse::<f64>().is_err() {
            continue;
        }
        let dotted = if section.is_empty() {
            key.to_string()
        } else {
            format!("{section}.{key}")
        };
        for bad in ["-1", "0", "1e300", "nan", "inf", "\"abc\"", "1e-300"] {
            let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
            lines[i] = format!("{key} = {bad}");
            let p = dir.join("preset.toml");
            std::fs::write(&p, lines.join("\n")).unwrap();
            n += 1;
            let args = vec!["run".to_string(), "--preset".into(), p.display().to_string()];
            let (code, out, err, _) = run(&args, &log);
            let line = err.trim_end();
            // refused before any work, naming the key; or valid for the key (the theory then
            // starts, which this mode forbids: a panic naming the forbidden work)
            let accepted = line.contains("work was forbidden");
            let refused = code == 2 && out.is_empty() && line.lines().count() == 1 && line.contains(&dotted);
            let never_valid = matches!(bad, "nan" | "\"abc\"");
            if !(refused || (accepted && !never_valid)) {
                broken.push(format!(
                    "{dotted} = {bad}: exit {code}: {}",
                    line.lines().last().unwrap_or("")
                ));
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(n >= 60, "{n} cases");
    assert!(broken.is_empty(), "{} of {n}:\n{}", broken.len(), broken.join("\n"));
}
