//! Helpers shared by the binary's integration tests: running `asperity` and reading what it
//! prints.
#![allow(dead_code)]

pub mod corpus;

use std::process::{Command, Output};

/// Runs the `asperity` binary with `args` in the repository root (where `presets/`,
/// `figures/` and `tours/` are).
pub fn asperity(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .output()
        .expect("the asperity binary runs")
}

/// Runs `asperity` and returns its stdout, failing the test (with stderr) unless it succeeds.
pub fn asperity_ok(args: &[&str]) -> String {
    let out = asperity(args);
    assert!(
        out.status.success(),
        "asperity {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("utf-8 output")
}

/// Runs `asperity` and parses its stdout as JSON.
pub fn asperity_json(args: &[&str]) -> serde_json::Value {
    serde_json::from_str(&asperity_ok(args)).expect("JSON on stdout")
}

/// Runs `asperity` with `args` in the binary package's folder (`cli/`, where cargo runs its
/// tests: fixture paths `tests/fixtures/...` are relative to it).
pub fn asperity_here(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the asperity binary runs")
}

/// Runs `asperity` as [`asperity_here`] and returns (exit code, stdout, stderr).
pub fn run(args: &[&str]) -> (i32, String, String) {
    let out = asperity_here(args);
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Runs `asperity` as [`asperity_here`] and returns its stdout, failing the test (with
/// stderr) unless it succeeds.
pub fn asperity_here_ok(args: &[&str]) -> String {
    let out = asperity_here(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("utf-8 output")
}

/// Figure 7 (`--points 4` and `extra`, e.g. a measured surface) against `run` on the same
/// scene at the figure file's thicknesses 0.01, 0.1, 1 and 10, for model 3, model 4 and the
/// adhesionless curve: every value equal to 1e-9, an empty point only with its note.
/// Returns the number of points compared and the figure's CSV.
pub fn figure_7_against_run(extra: &[&str]) -> (usize, String) {
    let mut args = vec!["figure", "7", "--format", "csv", "--points", "4"];
    args.extend_from_slice(extra);
    let csv = asperity_here_ok(&args);
    let mut checked = 0;
    for (series, model, gamma) in [
        ("model 3", "3", None),
        ("model 4", "4", None),
        ("adhesionless (model 4)", "4", Some("0")),
    ] {
        let prefix = format!("{series},");
        let mut found = 0;
        for line in csv.lines().filter(|l| l.starts_with(&prefix)) {
            // series,x,y,note (the names here have no commas; a note may, last)
            let c: Vec<&str> = line.splitn(4, ',').collect();
            let t: f64 = c[1].parse().unwrap();
            // the file's thicknesses, among the points refinement added
            if ((t.log10() * 1e6).round() / 1e6).fract() != 0.0 {
                continue;
            }
            found += 1;
            if c[2].is_empty() {
                // a thin-slab adhesive point may not converge: it is reported, not invented
                assert!(
                    !c.get(3).unwrap_or(&"").is_empty(),
                    "{series} t = {t}: empty without a note"
                );
                continue;
            }
            let y: f64 = c[2].parse().unwrap();
            let mut run = vec![
                "run",
                "--preset",
                "system-2",
                "--pressure",
                "0.005",
                "--model",
                model,
                "--thickness",
                c[1],
                "--format",
                "json",
            ];
            run.extend_from_slice(extra);
            if let Some(g) = gamma {
                run.extend(["--gamma", g]);
            }
            let v: serde_json::Value = serde_json::from_str(&asperity_here_ok(&run)).unwrap();
            let want = v["a_r"].as_f64().unwrap();
            assert!((y - want).abs() <= 1e-9, "{series} t = {t}: figure {y} run {want}");
            checked += 1;
        }
        assert_eq!(found, 4, "{series}: {csv}");
    }
    (checked, csv)
}

/// A synthetic hysteresis on a load sweep: the unloading branch a_r = 0.45 + 0.3 p* between
/// the pull-off load `pull` and the jump-in load `jump` (none elsewhere), and both loads.
pub fn add_hysteresis(sw: &mut asperity_cli::tui::base::data::SweepData, jump: f64, pull: f64) {
    sw.a_r_unloading =
        sw.p.iter()
            .map(|&p| {
                if (pull..jump).contains(&p) {
                    0.45 + 0.3 * p
                } else {
                    f64::NAN
                }
            })
            .collect();
    sw.jump_in = Some(jump);
    sw.pull_off = Some(pull);
}

/// The self-affine C(q) of `sa` sampled at `n + 1` log-spaced q from q_L to q_s: a measured
/// table of an ideal surface, (q in 1/m, C in m⁴).
pub fn ideal_table(sa: &asperity::surface::spectrum::SelfAffine, n: usize) -> (Vec<f64>, Vec<f64>) {
    let q: Vec<f64> = (0..=n)
        .map(|k| sa.q_l() * (sa.q_s() / sa.q_l()).powf(k as f64 / n as f64))
        .collect();
    let c = q.iter().map(|&x| sa.psd(x.clamp(sa.q_l(), sa.q_s()))).collect();
    (q, c)
}

/// Presses `g` in the explorer and returns the id of the GFMD run it starts.
pub fn start_gfmd(a: &mut asperity_cli::tui::app::App) -> u64 {
    use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
    let cs = asperity_cli::tui::drive::press(a, KeyEvent::new(KeyCode::Char('g'), KeyModifiers::NONE));
    cs.iter()
        .find_map(|c| match c {
            asperity_cli::tui::model::command::Command::StartGfmd { id, .. } => Some(*id),
            _ => None,
        })
        .expect("g starts a run")
}

/// A finished GFMD run for the explorer's tests at load `p`: a histogram shaped like the
/// theory of system 1 at p* = 0.01 and a little wider, a 512² grid, two sweep loads and the
/// theory on the map at three.
pub fn synthetic_gfmd(p: f64) -> asperity_cli::tui::base::gfmd_view::GfmdView {
    let pr: Vec<(f64, f64)> = (0..60)
        .map(|i| {
            let s = -0.5 + 2.2 * (i as f64 + 0.5) / 60.0;
            (s, 0.04 * (-(s - 0.3) * (s - 0.3) / 0.3).exp())
        })
        .collect();
    asperity_cli::tui::base::gfmd_view::GfmdView {
        pressure: p,
        a_r: 0.0418,
        mean_contact_stress: 0.2434,
        gap_rel: 1.4,
        pr,
        grid: 512,
        iterations: 475,
        elapsed_s: 1.0,
        theory_a_r: Some(0.0299),
        sweep: vec![(0.0033, 0.015, 2.0), (0.03, 0.11, 0.9)],
        theory_sweep: vec![(0.0033, 0.011, 2.1), (0.01, 0.03, 1.5), (0.03, 0.09, 0.95)],
        invariants: vec![],
        sweep_error: None,
    }
}

/// The leaf keys of a TOML value (a preset as its `Serialize` gives it, a tour) (dotted; `reference.0.value` for the
/// first `[[reference]]` entry), with their TOML values.
pub fn leaves(v: &toml::Value, prefix: &str, out: &mut Vec<(String, toml::Value)>) {
    match v {
        toml::Value::Table(t) => {
            for (k, x) in t {
                let p = if prefix.is_empty() {
                    k.clone()
                } else {
                    format!("{prefix}.{k}")
                };
                leaves(x, &p, out);
            }
        }
        toml::Value::Array(a) if a.iter().all(|x| x.is_table()) => {
            for (i, x) in a.iter().enumerate() {
                leaves(x, &format!("{prefix}.{i}"), out);
            }
        }
        _ => out.push((prefix.to_string(), v.clone())),
    }
}

/// The text of every `<text>` element of the SVG file at `path`, trimmed; the file must parse
/// as XML with an `<svg>` root.
pub fn svg_texts(path: &std::path::Path) -> Vec<String> {
    let text = std::fs::read_to_string(path).unwrap();
    let doc = roxmltree::Document::parse(&text).expect("the SVG parses as XML");
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text().map(|t| t.trim().to_string()))
        .collect()
}

/// A preset's `[model]` with every option set (model 4's number, each coefficient, the cap
/// and the fudge factor): a preset carrying it serialises every key of the table.
pub fn model_with_every_option() -> asperity::input::preset::ModelSpec {
    asperity::input::preset::ModelSpec {
        variant: asperity::input::preset::Variant::Number(4),
        c1: Some(0.0),
        c2: Some(0.0),
        alpha: Some(0.0),
        k_griffith: Some(0.0),
        cap: Some(true),
        fudge_gamma: Some(1.0),
    }
}
