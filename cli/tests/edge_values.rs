//! A property test over every numeric field at its range edges, for every command that
//! computes: each number flag of the command (enumerated from the flag table, its range the
//! library's, [`asperity::limits::allowed`]) set to one of its edges — the bounds, just inside
//! and just outside them, 0, −0, the smallest positive double, subnormals, the smallest normal
//! double — on a small scene (small grids, few loads). Whatever the value, the binary never
//! panics (exit 101, "panicked") and never prints NaN: a value in range gives a result, one
//! outside is refused.
//!
//! Counts are tried at their lower edges only (their upper bounds — 10⁶ points, 10⁹
//! iterations — are valid but long by design); a run that outlasts its time is stopped and
//! counts as no panic.

use asperity::error::{Bound, Range};
use asperity_cli::cli::flags::{self, Kind};
use proptest::prelude::*;
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// A scratch folder of this test process.
fn scratch() -> PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-edges-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The edges of `r`, in and out (`whole`: counts, lower edges only).
fn edges(r: &Range, count: bool) -> Vec<f64> {
    let mut v = vec![0.0, -0.0, 5e-324, 1e-320, f64::MIN_POSITIVE, -5e-324];
    let lo = match r.lo {
        Bound::Inclusive(l) | Bound::Exclusive(l) => Some(l),
        _ => None,
    };
    let hi = match r.hi {
        Bound::Inclusive(h) | Bound::Exclusive(h) => Some(h),
        _ => None,
    };
    if let Some(l) = lo {
        let step = if r.whole { 1.0 } else { l.abs().max(1e-300) * 1e-9 };
        v.extend([l, l - step, l + step]);
    }
    if let (Some(h), false) = (hi, count) {
        let step = if r.whole { 1.0 } else { h.abs().max(1e-300) * 1e-9 };
        v.extend([h, h + step, h - step]);
    }
    v
}

/// The command lines of the property: (command's base line, flag, value), over every number
/// flag of each command that computes.
fn cases(dir: &std::path::Path) -> Vec<(Vec<String>, String, String)> {
    let map = dir.join("map.txt");
    let rows: Vec<String> = (0..16)
        .map(|i| {
            (0..16)
                .map(|j| format!("{:e}", 1e-9 * (((i * 7 + j * 3) % 5) as f64 + 0.1 * (i * j % 3) as f64)))
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect();
    std::fs::write(&map, rows.join("\n")).unwrap();
    let map = map.display().to_string();
    let out = dir.join("gen.txt").display().to_string();
    let bases: Vec<(&str, Vec<String>)> = vec![
        ("run", vec!["run".into()]),
        (
            "sweep",
            ["sweep", "--from", "0.01", "--to", "0.1", "--points", "3"]
                .map(String::from)
                .to_vec(),
        ),
        (
            "gfmd",
            ["gfmd", "--grid", "16", "--max-iterations", "3000"]
                .map(String::from)
                .to_vec(),
        ),
        ("psd", vec!["psd".into(), map.clone(), "--size".into(), "1e-6".into()]),
        (
            "surface",
            ["surface", "generate", "--output", &out, "--grid", "16"]
                .map(String::from)
                .to_vec(),
        ),
    ];
    let cmd = flags::command();
    let mut all = Vec::new();
    for (name, base) in bases {
        let sub = cmd.get_subcommands().find(|s| s.get_name() == name).unwrap();
        for arg in sub.get_arguments().filter(|a| a.get_long().is_some()) {
            let flag = flags::name_of(arg);
            let Some(row) = flags::lookup(name, &flag) else {
                continue;
            };
            let (field, count) = match &row.kind {
                Kind::Number(f) => (f.clone(), false),
                Kind::Count(f) | Kind::Whole(f) => (f.clone(), true),
                _ => continue,
            };
            let Some(r) = asperity::limits::allowed(&field).and_then(|a| a.range().copied()) else {
                continue;
            };
            // the base's own value of the flag gives way
            let mut line = base.clone();
            if let Some(i) = line.iter().position(|a| *a == flag) {
                line.drain(i..i + 2);
            }
            for x in edges(&r, count) {
                all.push((line.clone(), flag.clone(), format!("{x:e}")));
            }
        }
    }
    all
}

/// Runs one line for at most `limit`: (exit code, or None when stopped; stdout; stderr).
fn run(args: &[String], limit: Duration) -> (Option<i32>, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .arg("--quiet")
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let code = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status.code();
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let out = child.wait_with_output().unwrap();
    (
        code,
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// NaN in printed output, as a word.
fn has_nan(text: &str) -> bool {
    text.split(|c: char| !c.is_ascii_alphanumeric())
        .any(|w| w.eq_ignore_ascii_case("nan"))
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 96,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    #[test]
    fn no_number_at_its_range_edge_panics_or_prints_nan(pick in any::<prop::sample::Index>()) {
        let dir = scratch();
        let all = cases(&dir);
        prop_assert!(all.len() > 200, "only {} cases", all.len());
        let (base, flag, value) = pick.get(&all);
        let mut args = base.clone();
        args.extend([flag.clone(), value.clone()]);
        let (code, out, err) = run(&args, Duration::from_secs(20));
        prop_assert!(code != Some(101) && !err.contains("panicked"), "{args:?}: exit {code:?}: {err}");
        prop_assert!(!has_nan(&out), "{args:?}: NaN in the output:\n{out}");
        if code == Some(2) {
            prop_assert_eq!(err.trim_end().lines().count(), 1, "{:?}: {}", args, err);
        }
    }
}
