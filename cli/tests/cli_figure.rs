//! `asperity figure`: the figures' numbers against independent references (`run` on the
//! same scene, eq. (18) and erf(√2 p*) evaluated here, [S] Table 1), the files it writes,
//! and its one-line errors.

mod common;

use common::asperity_here as asperity;
use common::asperity_here_ok as ok;

/// (series, x, y) rows of a figure's CSV; y None for an empty cell.
fn rows(csv: &str) -> Vec<(String, f64, Option<f64>, String)> {
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("series,x,y,note"));
    lines
        .map(|l| {
            // series names used here contain no commas; notes may (quoted, last)
            let mut c = l.splitn(4, ',');
            let s = c.next().unwrap().to_string();
            let x: f64 = c.next().unwrap().parse().unwrap();
            let y = c.next().unwrap();
            let note = c.next().unwrap_or("").to_string();
            (s, x, (!y.is_empty()).then(|| y.parse().unwrap()), note)
        })
        .collect()
}

#[test]
fn figure_7_is_run_at_the_same_thicknesses() {
    let (checked, _) = common::figure_7_against_run(&[]);
    assert!(checked >= 9, "too few converged points to compare: {checked}");
}

fn erf(x: f64) -> f64 {
    statrs::function::erf::erf(x)
}

#[test]
fn figure_1_reproduces_eq18_and_the_model_curves() {
    let rows = rows(&ok(&["figure", "1", "--format", "csv"]));
    let eq18: Vec<_> = rows.iter().filter(|r| r.0.starts_with("eq. (18)")).collect();
    assert_eq!(eq18.len(), 31);
    for (_, p, y, _) in &eq18 {
        // [S-18, S-19], written out here
        let a0 = erf(1.45 * p);
        let want = (erf(1.9 * p) * (1.0 - a0 * a0) + a0 * a0 * a0) / p;
        assert!((y.unwrap() - want).abs() < 1e-12 * want, "p* = {p}");
    }
    let at = |series: &str, p: f64| {
        rows.iter()
            .find(|r| r.0 == series && (r.1 / p - 1.0).abs() < 1e-9)
            .and_then(|r| r.2)
            .unwrap_or_else(|| panic!("{series} at {p}"))
    };
    // model 1 (W ≡ 1, half-space): a_r = erf(√2 p*) exactly (docs/reference-values.md)
    for r in rows.iter().filter(|r| r.0 == "model 1") {
        let want = erf(2f64.sqrt() * r.1) / r.1;
        assert!((r.2.unwrap() / want - 1.0).abs() < 1e-6, "model 1 at {}", r.1);
    }
    // models 2 and 3 at the ends of the range: docs/reference-values.md (5 digits)
    for (series, p, a_r) in [
        ("model 2", 1e-3, 0.00238),
        ("model 3", 1e-3, 0.00214),
        ("model 2", 1.0, 0.95582),
        ("model 3", 1.0, 0.95703),
    ] {
        let got = at(series, p) * p;
        assert!((got - a_r).abs() < 6e-6, "{series} p* = {p}: {got} vs {a_r}");
    }
    // model 3 was gauged on eq. (18): within 1 % below p* = 0.2
    for r in rows.iter().filter(|r| r.0 == "model 3" && r.1 < 0.2) {
        let (p, a0) = (r.1, erf(1.45 * r.1));
        let e = (erf(1.9 * p) * (1.0 - a0 * a0) + a0 * a0 * a0) / p;
        assert!((r.2.unwrap() / e - 1.0).abs() < 0.01, "p* = {}", r.1);
    }
}

#[test]
fn table_1_reproduces_the_paper() {
    let csv = ok(&["figure", "table-1", "--format", "csv"]);
    let mut n = 0;
    for line in csv.lines().skip(1) {
        let c: Vec<&str> = line.split(',').collect();
        if !c[0].starts_with("model") {
            continue;
        }
        let v: Vec<f64> = c[1..].iter().map(|x| x.parse().unwrap()).collect();
        // computed against [S]'s: ±3e-4 (docs/reference-values.md)
        assert!((v[0] - v[3]).abs() <= 3e-4, "{line}");
        assert!((v[1] - v[4]).abs() <= 3e-4, "{line}");
        // and the paper's own numbers as printed in [S] Table 1
        let paper = match c[0] {
            "model 1" => (0.6264, 0.1071),
            "model 2" => (0.4215, 0.0484),
            _ => (0.4670, 0.0595),
        };
        assert_eq!((v[3], v[4]), paper);
        n += 1;
    }
    assert_eq!(n, 3, "{csv}");
}

#[test]
fn svg_and_png_files_carry_every_series() {
    let dir = std::env::temp_dir().join(format!("asperity-fig-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("f5.svg");
    let png = dir.join("f5.png");
    let out = asperity(&[
        "figure",
        "5",
        "--svg",
        svg.to_str().unwrap(),
        "--png",
        png.to_str().unwrap(),
        "--format",
        "json",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let texts = common::svg_texts(&svg);
    for name in [
        "model 1",
        "model 2",
        "model 3",
        "[S] Table 1: GFMD",
        "[S] Table 1: model 3",
        "σ̄_c* (mean contact stress / E*ḡ)",
    ] {
        assert!(texts.iter().any(|t| t == name), "{name} not in {texts:?}");
    }
    assert_eq!(&std::fs::read(&png).unwrap()[..4], b"\x89PNG");
}

#[test]
fn the_text_chart_works_in_a_pipe() {
    let text = ok(&["figure", "1", "--width", "80", "--height", "24"]);
    assert!(!text.contains('\u{1b}'), "escape codes in a pipe");
    let chart: Vec<&str> = text.lines().take_while(|l| !l.starts_with("note:")).collect();
    assert!(chart.len() <= 24, "{text}");
    assert!(chart.iter().all(|l| l.chars().count() <= 80), "{text}");
    for name in ["model 1", "model 2", "model 3", "eq. (18)"] {
        assert!(text.contains(name), "{name}: {text}");
    }
    let list = ok(&["figure", "--list"]);
    for id in ["1", "2", "3", "4", "5", "6", "7", "8", "8-log", "table-1"] {
        assert!(list.lines().any(|l| l.split_whitespace().next() == Some(id)), "{list}");
    }
}

#[test]
fn gfmd_points_come_on_a_named_grid() {
    let v: serde_json::Value =
        serde_json::from_str(&ok(&["figure", "2", "--gfmd", "--grid", "32", "--format", "json"])).unwrap();
    let g = v["series"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"].as_str().unwrap().starts_with("GFMD"))
        .expect("a GFMD series");
    assert_eq!(g["name"], "GFMD (32²)");
    assert!(!g["points"].as_array().unwrap().is_empty());
    // the histogram integrates to the GFMD contact area stated in the notes
    assert!(v["notes"]
        .as_array()
        .unwrap()
        .iter()
        .any(|n| n.as_str().unwrap().contains("32² grid")));
}

fn one_line_error(args: &[&str], needle: &str) {
    let out = asperity(args);
    assert_eq!(out.status.code(), Some(2), "{args:?}");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
    assert!(err.contains(needle), "{args:?}: {err}");
}

#[test]
fn bad_figure_arguments_exit_2_with_one_line() {
    one_line_error(&["figure", "9"], "invalid figure = 9");
    one_line_error(&["figure"], "invalid figure");
    one_line_error(&["figure", "1", "--points", "1"], "--points");
    one_line_error(&["figure", "1", "--format", "xml"], "--format");
    one_line_error(&["figure", "1", "--gfmd", "--grid", "2"], "--grid");
    one_line_error(&["figure", "1", "--width", "5"], "--width");
    one_line_error(
        &["figure", "1", "--svg", "/nonexistent-dir/x.svg"],
        "/nonexistent-dir/x.svg",
    );
}

/// The ids that `figure --list` names (the first word of each line).
fn listed_ids() -> Vec<String> {
    let list = ok(&["figure", "--list"]);
    list.lines()
        .filter_map(|l| l.split_whitespace().next())
        .map(str::to_string)
        .collect()
}

/// The comma-separated ids of an "allowed …, … or a figure TOML file" text.
fn ids_named(text: &str) -> Vec<String> {
    let list = text.split(" or a figure TOML file").next().unwrap();
    let list = list.rsplit("allowed ").next().unwrap().trim();
    list.split(", ").map(str::to_string).collect()
}

#[test]
fn the_error_and_the_help_name_every_listed_figure() {
    let listed = listed_ids();
    assert!(listed.contains(&"8-log".to_string()), "{listed:?}");
    for args in [&["figure", "9"][..], &["figure"][..]] {
        let out = asperity(args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(ids_named(&err), listed, "{args:?}: {err}");
    }
    let help = ok(&["figure", "--help"]);
    let line = help
        .lines()
        .map(str::trim)
        .find(|l| l.ends_with("or a figure TOML file"))
        .unwrap_or_else(|| panic!("no figure list in the help: {help}"));
    assert_eq!(ids_named(line), listed, "{help}");
}

#[test]
fn bad_figure_files_give_the_preset_errors() {
    let dir = std::env::temp_dir().join(format!("asperity-figtoml-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = include_str!("../../figures/fig-1.toml");
    for (name, from, to, needle) in [
        ("unknown", "points = 31", "points = 31\ncolour = \"red\"", "colour"),
        ("variant", "x = \"pressure\"", "x = \"speed\"", "line 6: x:"),
        ("type", "points = 31", "points = \"many\"", "points"),
        ("model", "model = 2", "model = 7", "curve[2].model = 7"),
        ("range", "from = 1e-3", "from = 2.0", "from = 2"),
        ("preset", "preset = \"system-1\"", "preset = \"system-9\"", "system-9"),
        (
            "decades",
            "points = 31",
            "points = 31\ny_decades = 3",
            "y_decades = 3: allowed 0.5 to 300, with y_log",
        ),
    ] {
        assert!(good.contains(from), "{from}");
        let path = dir.join(format!("{name}.toml"));
        std::fs::write(&path, good.replacen(from, to, 1)).unwrap();
        let p = path.to_str().unwrap();
        one_line_error(&["figure", p], needle);
        // called by its kind, by the file's name
        one_line_error(&["figure", p], &format!("invalid figure = {name}.toml: "));
    }
    // the same file unmodified works, by path
    let path = dir.join("good.toml");
    std::fs::write(&path, good).unwrap();
    ok(&["figure", path.to_str().unwrap(), "--format", "csv", "--points", "3"]);
}

/// On a sweep figure the GFMD points come with the theory on the same map, and both are what
/// `asperity gfmd` gives for that scene and grid.
#[test]
fn gfmd_points_of_a_sweep_match_the_gfmd_command() {
    let v: serde_json::Value =
        serde_json::from_str(&ok(&["figure", "5", "--gfmd", "--grid", "32", "--format", "json"])).unwrap();
    let series = v["series"].as_array().unwrap();
    let find = |name: &str| {
        series
            .iter()
            .find(|s| s["name"] == name)
            .unwrap_or_else(|| panic!("{name}"))["points"]
            .as_array()
            .unwrap()
            .clone()
    };
    let g = find("GFMD (32²)");
    let t = find("theory on the GFMD map (model 3)");
    assert_eq!(g.len(), 4);
    let p = g[1]["x"].as_f64().unwrap();
    let pp = format!("{p:e}");
    let run: serde_json::Value = serde_json::from_str(&ok(&[
        "gfmd",
        "--preset",
        "system-1",
        "--gamma",
        "0",
        "--grid",
        "32",
        "--pressure",
        &pp,
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(g[1]["y"].as_f64(), run["mean_contact_stress"].as_f64());
    assert_eq!(t[1]["y"].as_f64(), run["theory"]["mean_contact_stress"].as_f64());
}
