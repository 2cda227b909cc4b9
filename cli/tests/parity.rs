//! The command line only serialises the library's reports: for a few scenes and each of
//! `run`, `sweep`, `sweep --cycle`, `psd`, `gauge`, `compare` and `gfmd` (a 32² grid), the
//! JSON the binary prints carries the same names and the same numbers (to `PYTHON_CLI_REL`,
//! timings aside) as the library's report of the same inputs, serialised. Python's results are held against the
//! same JSON in python/tests/test_cli.py, so the three agree.

mod common;

use asperity::error::Field;
use asperity::fit::{self, Param};
use asperity::gfmd;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::report::{self, gfmd::GfmdSpec, sweep};
use asperity::surface::psd::PsdOptions;
use asperity::surface::readers::{self, ReadOptions};
use asperity::theory::engine::Options;
use asperity::theory::sweep::SweepSpec;
use asperity::tolerances::PYTHON_CLI_REL;
use common::asperity_json;
use serde_json::Value;
use std::sync::atomic::AtomicBool;

/// Keys the command line adds around a report (the preset's name of `run`).
const FRONT_END_KEYS: [&str; 1] = ["preset"];

/// A timing: wall time differs from run to run.
fn is_timing(key: &str) -> bool {
    key == "elapsed_s" || key.ends_with("_elapsed_s") || key.starts_with("elapsed_")
}

/// The differences between the library's value and the CLI's, key by key.
fn differences(lib: &Value, cli: &Value, path: &str, out: &mut Vec<String>) {
    match (lib, cli) {
        (Value::Object(a), Value::Object(b)) => {
            for k in a.keys().filter(|k| !b.contains_key(*k)) {
                out.push(format!("{path}.{k}: in the library's report, not in the CLI's JSON"));
            }
            for (k, v) in b {
                if is_timing(k) || (path.is_empty() && FRONT_END_KEYS.contains(&k.as_str())) {
                    continue;
                }
                match a.get(k) {
                    Some(l) => differences(l, v, &format!("{path}.{k}"), out),
                    None => out.push(format!("{path}.{k}: in the CLI's JSON, not in the library's report")),
                }
            }
        }
        (Value::Array(a), Value::Array(b)) if a.len() == b.len() => {
            for (i, (l, c)) in a.iter().zip(b).enumerate() {
                differences(l, c, &format!("{path}[{i}]"), out);
            }
        }
        (Value::Number(a), Value::Number(b)) => {
            let (x, y) = (a.as_f64().unwrap(), b.as_f64().unwrap());
            if (x - y).abs() > PYTHON_CLI_REL * x.abs().max(y.abs()) {
                out.push(format!("{path}: library {x:e}, CLI {y:e}"));
            }
        }
        (a, b) if a == b => {}
        (a, b) => out.push(format!("{path}: library {a}, CLI {b}")),
    }
}

/// Asserts that the CLI's JSON for `args` is `lib` serialised (module docs), and that the
/// report has numbers to compare.
fn same(lib: &impl serde::Serialize, args: &[&str]) {
    let lib: Value = serde_json::from_str(&serde_json::to_string(lib).unwrap()).unwrap();
    let cli = asperity_json(args);
    let mut diffs = Vec::new();
    differences(&lib, &cli, "", &mut diffs);
    assert!(diffs.is_empty(), "asperity {args:?}:\n{}", diffs.join("\n"));
    assert!(
        lib.as_object().is_some_and(|o| o.len() > 3),
        "{args:?}: an empty report"
    );
}

fn scene(preset: &str) -> (Preset, Scene) {
    let p = Preset::resolve(preset).unwrap();
    let s = p.scene().unwrap();
    (p, s)
}

fn quiet() -> impl FnMut(usize, usize) {
    |_, _| {}
}

#[test]
fn run_is_report_point() {
    let (_, s1) = scene("system-1");
    same(
        &report::point(&s1, &Options::default()).unwrap(),
        &["run", "--preset", "system-1", "--format", "json"],
    );
    let (_, s2) = scene("system-2");
    let s2 = s2.with_thickness_qr(0.5).unwrap().with_pressure(0.003).unwrap();
    same(
        &report::point(&s2, &Options::default()).unwrap(),
        &[
            "run",
            "--preset",
            "system-2",
            "--thickness",
            "0.5",
            "--pressure",
            "0.003",
            "--format",
            "json",
        ],
    );
}

#[test]
fn sweep_and_its_cycle_are_report_sweep_and_report_cycle() {
    let (_, s) = scene("system-2");
    let s = s.with_thickness_qr(1.0).unwrap();
    let loads = SweepSpec {
        from: 1e-3,
        to: 0.05,
        points: 6,
    };
    let opts = Options::default();
    let mut q = quiet();
    let lib = sweep::pressure(&s, "system-2", &[loads], &opts, false, sweep::Control::none(&mut q)).unwrap();
    same(
        &lib,
        &[
            "sweep",
            "--preset",
            "system-2",
            "--thickness",
            "1",
            "--from",
            "1e-3",
            "--to",
            "0.05",
            "--points",
            "6",
            "--format",
            "json",
        ],
    );
    let (_, s) = scene("system-2");
    let loads = SweepSpec {
        from: 1e-3,
        to: 1e-2,
        points: 4,
    };
    let mut q = quiet();
    let lib = sweep::pressure(&s, "system-2", &[loads], &opts, true, sweep::Control::none(&mut q)).unwrap();
    let args = [
        "sweep", "--preset", "system-2", "--cycle", "--from", "1e-3", "--to", "1e-2", "--points", "4", "--format",
        "json",
    ];
    same(&lib, &args);
    // the cycle alone (Python's `cycle()`) is the one under `cycle`
    let mut q = quiet();
    let c = report::cycle::cycle(&s, "system-2", &loads, &opts, sweep::Control::none(&mut q)).unwrap();
    let cli = asperity_json(&args);
    let mut diffs = Vec::new();
    differences(&serde_json::to_value(&c).unwrap(), &cli["cycle"], ".cycle", &mut diffs);
    assert!(diffs.is_empty(), "{}", diffs.join("\n"));
    assert!(!c.rows.is_empty());
}

#[test]
fn psd_is_report_psd() {
    let file = "cli/tests/fixtures/two_bands.txt";
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let map = readers::read(&std::path::Path::new(root).join(file), &ReadOptions::default()).unwrap();
    let lib = report::psd::psd(file, &map, &PsdOptions::default()).unwrap();
    same(&lib, &["psd", file, "--format", "json"]);
}

#[test]
fn gauge_is_report_gauge() {
    let (_, s) = scene("system-1");
    let (r, sc) = report::gauge::reference("eq18", None, (Some(1e-3), Some(0.3), Some(6)), &s).unwrap();
    let lib = report::gauge::GaugeReport {
        reference: r.name.clone(),
        gfmd: None,
        fit: fit::fit(&sc, &r, &Param::parse_list("c1").unwrap()).unwrap(),
        saved_preset: None,
    };
    same(
        &lib,
        &[
            "gauge",
            "--preset",
            "system-1",
            "--fit",
            "c1",
            "--reference",
            "eq18",
            "--from",
            "1e-3",
            "--to",
            "0.3",
            "--points",
            "6",
            "--format",
            "json",
        ],
    );
}

/// `compare`'s rows are the library's, notes included (a model the scene does not define is
/// worded as the command line words errors).
#[test]
fn compare_is_report_compare() {
    let (_, s) = scene("system-2");
    let (r, sc) = report::gauge::reference("eq18", None, (Some(1e-3), Some(0.3), Some(5)), &s).unwrap();
    let list = "1,3,5,yp08,xu24";
    let models = report::compare::models(list, &sc.model(), &Field::Other("--models".into())).unwrap();
    let lib = report::compare::compare(&sc, &r, &models, asperity_cli::cli::render_error);
    let args = [
        &["compare", "--preset", "system-2", "--reference", "eq18"][..],
        &["--from", "1e-3", "--to", "0.3", "--points", "5"],
        &["--models", list, "--format", "json"],
    ]
    .concat();
    let mut diffs = Vec::new();
    differences(
        &serde_json::to_value(&lib).unwrap(),
        &asperity_json(&args),
        "",
        &mut diffs,
    );
    assert!(diffs.is_empty(), "{}", diffs.join("\n"));
    assert_eq!(lib.models.len(), 5);
    assert!(lib.models.iter().any(|m| !m.scores.is_empty()), "no model scored");
}

#[test]
fn gfmd_is_the_librarys_run_of_the_spec() {
    let (p, s) = scene("system-1");
    let s = s.with_pressure(0.05).unwrap();
    let spec = GfmdSpec {
        grid: Some(32),
        ..GfmdSpec::default()
    };
    let (setup, opts) = spec.setup(&p, &s, None).unwrap();
    let lib = gfmd::run(&setup, &opts, &mut |_| {}, &AtomicBool::new(false)).unwrap();
    same(
        &lib,
        &[
            "gfmd",
            "--preset",
            "system-1",
            "--pressure",
            "0.05",
            "--grid",
            "32",
            "--format",
            "json",
        ],
    );
}
