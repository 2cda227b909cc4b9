//! Every bad input one line: a table of bad values over the flags of every command. Each must
//! exit with code 2 before any work starts, print exactly one line on stderr, and that line
//! must name the flag, show the value compactly and state the allowed range or choices.

mod common;

use common::asperity;

/// (arguments before the bad value, the flag, the bad values, what the line must state).
type Case = (
    &'static [&'static str],
    &'static str,
    &'static [&'static str],
    &'static str,
);

const NUMBERS: &[&str] = &["abc", "-1", "1e300", "nan", ""];

const CASES: &[Case] = &[
    // run: the scene and the accuracy knobs
    (&["run"], "--pressure", NUMBERS, "1e-12 <= pressure <= 1000"),
    (&["run"], "--gamma", &["abc", "-1", "1e300", ""], "0 <= gamma_s <= 1000"),
    (
        &["run"],
        "--thickness",
        &["abc", "-1", "0", "1e300", ""],
        "1e-6 <= t·q_r <= 1e12, or inf",
    ),
    (&["run"], "--alpha", &["abc", "-1", "5", "1e300"], "0 <= alpha <= 4"),
    (&["run"], "--k-griffith", &["abc", "0", "-1", "1e300"], "0 < k_G <= 100"),
    (
        &["run"],
        "--c1",
        &["abc", "1e300", "-1e300", "nan"],
        "-1000 <= c1 <= 1000",
    ),
    (
        &["run"],
        "--c2",
        &["abc", "1e300", "-1e300", "nan"],
        "-1000 <= c2 <= 1000",
    ),
    (
        &["run"],
        "--model",
        &["7", "-1", "abc", "3.5", ""],
        "1, 2, 3, 4, 5, custom, yp08 or xu24",
    ),
    (&["run"], "--cap", &["maybe", "-1"], "true, false"),
    (&["run"], "--format", &["xml", "-1"], "json, table"),
    (
        &["run"],
        "--rtol",
        &["abc", "-1", "1e-300", "1"],
        "1e-12 <= rtol <= 0.01",
    ),
    (
        &["run"],
        "--sigma-points",
        &["-1", "0", "1", "2.5", "abc", "1e300"],
        "2 <= sigma_points <= 1e6",
    ),
    (
        &["run"],
        "--sigma-max",
        &["abc", "-1", "1e300"],
        "1e-6 <= sigma_max <= 1000",
    ),
    (
        &["run"],
        "--adhesion-steps",
        &["abc", "3", "-1", "1e300"],
        "4 <= adhesion_steps <= 10000",
    ),
    (
        &["run"],
        "--adhesion-points",
        &["abc", "3", "-1", "2000"],
        "4 <= adhesion_points <= 1000",
    ),
    (
        &["run"],
        "--adhesion-tol",
        &["abc", "-1", "1"],
        "1e-14 <= adhesion_tol <= 0.1",
    ),
    // sweep
    (
        &["sweep", "--to", "0.1"],
        "--from",
        &["abc", ""],
        "1e-12 <= p* <= 1000 for --over pressure",
    ),
    (
        &["sweep", "--from", "0.01"],
        "--to",
        &["abc", ""],
        "1e-12 <= p* <= 1000 for --over pressure",
    ),
    (
        &["sweep", "--from", "0.01", "--to", "0.1"],
        "--points",
        &["-1", "0", "abc", "1e300"],
        "1 <= points <= 100000",
    ),
    (
        &["sweep", "--from", "0.01", "--to", "0.1"],
        "--over",
        &["-1", "load"],
        "pressure, thickness, gamma",
    ),
    (
        &["sweep", "--from", "0.01", "--to", "0.1"],
        "--format",
        &["-1", "xml"],
        "csv, json",
    ),
    (
        &["sweep", "--over", "gamma", "--from", "0", "--to", "0.1"],
        "--pressure",
        &["abc", "-1"],
        "1e-12 <= pressure <= 1000",
    ),
    (
        &["sweep", "--from", "0.01", "--to", "0.1"],
        "--thickness",
        &["abc", "-1"],
        "1e-6 <= t·q_r <= 1e12, or inf",
    ),
    // gfmd
    (
        &["gfmd"],
        "--grid",
        &["-1", "3", "abc", "4.5", "1e300"],
        "4 <= grid <= 8192",
    ),
    (
        &["gfmd"],
        "--tolerance",
        &["abc", "-1", "2", "1e-300"],
        "1e-14 <= tolerance < 1",
    ),
    (
        &["gfmd"],
        "--max-iterations",
        &["-1", "0", "abc"],
        "max_iterations >= 1",
    ),
    (&["gfmd"], "--bins", &["-1", "0", "abc", "1e300"], "1 <= bins <= 1e6"),
    (&["gfmd"], "--seeds", &["-1", "0", "5000", "abc"], "1 <= seeds <= 1000"),
    (&["gfmd"], "--seed", &["-1", "abc", "1.5"], "0 <= seed <="),
    (&["gfmd"], "--method", &["-1", "newton"], "auto, pk, fire"),
    (&["gfmd"], "--pressure", &["abc", "-1"], "1e-12 <= pressure <= 1000"),
    (
        &["gfmd", "--extrapolate"],
        "--ladder",
        &["1", "abc", "1000"],
        "2 <= lambda_s/da <= 256",
    ),
    (
        &["gfmd", "--from", "0.01", "--to", "0.1"],
        "--points",
        &["-1", "0", "abc"],
        "1 <= points <= 100000",
    ),
    (&["gfmd", "--size", "1e-6"], "--surface", &[""], "a file name"),
    (
        &["gfmd", "--surface", "cli/tests/fixtures/two_bands.txt"],
        "--size",
        &["abc", "-1", "1e300"],
        "1e-12 <= system_size_m <= 1000",
    ),
    // gauge --reference gfmd: the flags of gfmd, and the gfmd-only flags with another reference
    (
        &["gauge", "--fit", "w0", "--reference", "gfmd"],
        "--seeds",
        &["-1", "0", "5000", "abc"],
        "1 <= seeds <= 1000",
    ),
    (
        &["gauge", "--fit", "w0", "--reference", "gfmd"],
        "--grid",
        &["-1", "3", "abc", "4.5"],
        "4 <= grid <= 8192",
    ),
    (
        &["gauge", "--fit", "w0", "--reference", "gfmd"],
        "--seed",
        &["-1", "abc", "1.5"],
        "0 <= seed <=",
    ),
    (
        &["gauge", "--fit", "w0", "--reference", "gfmd", "--extrapolate"],
        "--ladder",
        &["1", "abc", "1000"],
        "2 <= lambda_s/da <= 256",
    ),
    (
        &["gauge", "--fit", "w0", "--reference", "gfmd"],
        "--method",
        &["-1", "newton"],
        "auto, pk, fire",
    ),
    (
        &["gauge", "--fit", "w0", "--reference", "gfmd"],
        "--save-reference",
        &["", "x.txt"],
        "a file name ending in .csv",
    ),
    (
        &["gauge", "--fit", "c1", "--reference", "eq18"],
        "--seeds",
        &["3"],
        "only with --reference gfmd",
    ),
    (
        &["compare", "--reference", "eq18"],
        "--grid",
        &["64"],
        "only with --reference gfmd",
    ),
    (
        &["gauge", "--fit", "c1", "--reference", "eq18"],
        "--observables",
        &["abc", "mean_gap_rel"],
        "a comma-separated list of a_r, mean_contact_stress, mean_gap_rel, pr",
    ),
    // figure
    (
        &["figure", "3"],
        "--width",
        &["-1", "5", "abc", "1e300"],
        "20 <= width <= 1000",
    ),
    (
        &["figure", "3"],
        "--height",
        &["-1", "5", "abc"],
        "10 <= height <= 1000",
    ),
    (
        &["figure", "3"],
        "--points",
        &["-1", "1", "abc"],
        "2 <= points <= 100000",
    ),
    (&["figure", "3"], "--format", &["-1", "pdf"], "chart, table, csv, json"),
    (
        &["figure", "3"],
        "--png",
        &["abc", "", "x.svg"],
        "a file name ending in .png",
    ),
    (&["figure", "3"], "--svg", &[""], "a file name"),
    (
        &["figure", "3", "--gfmd"],
        "--grid",
        &["-1", "abc"],
        "4 <= grid <= 8192",
    ),
    // tour, bench, tui
    (&["tour"], "--step", &["-1", "0", "abc"], "1 <= step"),
    (&["bench", "--quick"], "--output", &["/nonexistent/x.md", ""], "a file"),
    (&["tui"], "--pressure", &["abc", "-1"], "1e-12 <= pressure <= 1000"),
    (&["tui"], "--thickness", &["abc", "-1"], "or inf"),
];

/// The value as the line shows it: numbers of more than 12 characters in scientific form,
/// an empty value as `""`.
fn shown(v: &str) -> String {
    if v.is_empty() {
        "\"\"".into()
    } else {
        v.to_string()
    }
}

#[test]
fn every_bad_value_is_one_line_with_flag_value_and_range() {
    let mut n = 0;
    let mut broken = Vec::new();
    for (before, flag, values, allowed) in CASES {
        for v in *values {
            let mut args: Vec<&str> = before.to_vec();
            args.push(flag);
            args.push(v);
            n += 1;
            let out = asperity(&args);
            let err = String::from_utf8_lossy(&out.stderr).to_string();
            let line = err.trim_end();
            let want_flag = format!("invalid {flag} = {}", shown(v));
            let ok = out.status.code() == Some(2)
                && out.stdout.is_empty()
                && line.lines().count() == 1
                && line.contains(&want_flag)
                && line.contains(allowed)
                && line.len() < 300;
            if !ok {
                broken.push(format!("{args:?} -> {:?}: {line}", out.status.code()));
            }
        }
    }
    assert!(n >= 100, "only {n} cases");
    assert!(
        broken.is_empty(),
        "{} of {n} cases break the rule:\n{}",
        broken.len(),
        broken.join("\n")
    );
}

#[test]
fn other_bad_input_is_one_line_too() {
    let dir = std::env::temp_dir().join(format!("asperity-bad-table-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let preset = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../presets/system-2.toml")).unwrap();
    let variant = dir.join("variant.toml");
    let line = preset.lines().position(|l| l.starts_with("variant")).unwrap() + 1;
    let text: String = preset
        .lines()
        .map(|l| if l.starts_with("variant") { "variant = 3.5" } else { l })
        .collect::<Vec<_>>()
        .join("\n");
    std::fs::write(&variant, text).unwrap();
    let huge = dir.join("huge.toml");
    let keys: String = (0..200_000).map(|i| format!("k{i} = 1\n")).collect();
    std::fs::write(&huge, keys).unwrap();
    let v = variant.to_str().unwrap();
    let h = huge.to_str().unwrap();
    let cases: Vec<(Vec<&str>, Vec<String>)> = vec![
        (
            vec!["run", "--preset", v],
            vec![
                format!("line {line}: model.variant"),
                asperity::input::model::MODEL_NAMES.into(),
            ],
        ),
        (vec!["run", "--preset", h], vec!["at most 1048576 bytes".into()]),
        (
            vec!["run", "--preset", "system-1", "--c1", "1e300"],
            vec!["--c1 = 1e300".into(), "-1000 <= c1 <= 1000".into()],
        ),
        (
            vec!["run", "--preset", "system-1", "--c1", "900"],
            vec!["--c1/--c2 = (900, ".into(), "W(a)".into()],
        ),
        (vec!["run", "-1"], vec!["'-1'".into(), "asperity run --help".into()]),
        (
            vec!["run", "--no-such-flag"],
            vec!["--no-such-flag".into(), "asperity run --help".into()],
        ),
        (vec!["tour", "-1"], vec!["tour = -1".into(), "wang-muser".into()]),
        (vec!["figure", "-1"], vec!["figure = -1".into(), "table-1".into()]),
        (vec!["gfmd", "--size", "1e-5"], vec!["missing --surface".into()]),
    ];
    for (args, needles) in cases {
        let out = asperity(&args);
        let err = String::from_utf8_lossy(&out.stderr).to_string();
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        for n in needles {
            assert!(err.contains(&n), "{args:?}: {n:?} not in {err}");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_built_in_figure_wins_over_a_file_of_that_name() {
    let dir = std::env::temp_dir().join(format!("asperity-figure-name-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("3"), "not a figure").unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(["figure", "--list"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(out.status.success());
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(["figure", "3", "--format", "csv", "--points", "2"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(!err.contains("read 3"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
