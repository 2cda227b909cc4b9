//! The headless `run` command end to end: JSON fields, ∫Pr = a_r, errors on stderr.

mod common;

use common::run as asperity;

fn json(args: &[&str]) -> serde_json::Value {
    let (code, out, err) = asperity(args);
    assert_eq!(code, 0, "stderr: {err}");
    serde_json::from_str(&out).unwrap()
}

#[test]
fn run_json_has_the_public_fields() {
    let v = json(&[
        "run",
        "--preset",
        "system-1",
        "--model",
        "1",
        "--pressure",
        "0.01",
        "--gamma",
        "0",
    ]);
    for key in [
        "a_r",
        "mean_contact_stress",
        "contact_stress_variance",
        "converged",
        "elapsed_s",
        "scene",
        "pr",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    let a = v["a_r"].as_f64().unwrap();
    let exact = statrs::function::erf::erf(2f64.sqrt() * 0.01);
    assert!((a - exact).abs() < 1e-9);
    // `converged` is computed from the result (a finite error bar, a_r in [0, 1]); the
    // closed form here has an error bar at round-off
    assert_eq!(v["converged"], true);
    assert!(v["error_estimate"].as_f64().unwrap() < 1e-9, "{}", v["error_estimate"]);
    assert!(v["scene"].get("thickness_qr").is_some() && v["scene"]["thickness_qr"].is_null());
    assert!(v["scene"].get("gamma_glo").is_some());
    // ∫density dσ = a_r on the printed grid (trapezoid, 2001 points over p + 5Δ: the cut
    // tail is e^{-12.5}-small, the trapezoid error ~1e-6)
    let v = json(&[
        "run",
        "--preset",
        "system-1",
        "--gamma",
        "0",
        "--sigma-points",
        "2001",
        "--sigma-max",
        "3",
    ]);
    let s: Vec<f64> = v["pr"]["sigma"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let d: Vec<f64> = v["pr"]["density"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let integral: f64 = s
        .windows(2)
        .zip(d.windows(2))
        .map(|(s, d)| 0.5 * (s[1] - s[0]) * (d[0] + d[1]))
        .sum();
    let a = v["a_r"].as_f64().unwrap();
    assert!((integral / a - 1.0).abs() < 1e-5, "{integral} vs {a}");
}

#[test]
fn thickness_flag_and_table_format() {
    let v = json(&["run", "--preset", "system-2", "--gamma", "0", "--thickness", "0.25"]);
    assert!((v["scene"]["thickness_qr"].as_f64().unwrap() - 0.25).abs() < 1e-15);
    let (code, out, _) = asperity(&["run", "--gamma", "0", "--format", "table"]);
    assert_eq!(code, 0);
    assert!(out.contains("a_r") && out.contains("mean_contact_stress"));
}

#[test]
fn custom_model_from_flags() {
    // c1 = c2 = 0, alpha = 1/2 is model 1
    let v = json(&[
        "run", "--gamma", "0", "--model", "custom", "--c1", "0", "--c2", "0", "--alpha", "0.5",
    ]);
    assert_eq!(v["scene"]["model"], "custom");
    let exact = statrs::function::erf::erf(2f64.sqrt() * 0.01);
    assert!((v["a_r"].as_f64().unwrap() - exact).abs() < 1e-9);
}

#[test]
fn bad_flags_give_one_line_errors() {
    let cases: [(&[&str], &str); 6] = [
        (&["run", "--thickness", "-1"], "--thickness = -1"),
        (&["run", "--pressure", "nan"], "--pressure = nan"),
        (&["run", "--pressure", "-0.1"], "--pressure = -0.1"),
        (&["run", "--model", "9"], "--model = 9"),
        (&["run", "--preset", "nope"], "--preset = nope"),
        (&["run", "--gamma", "0", "--model", "custom", "--c1", "2"], "--c1/--c2"),
    ];
    for (args, needle) in cases {
        let (code, out, err) = asperity(args);
        assert_ne!(code, 0, "{args:?}");
        assert!(out.is_empty(), "{args:?}: stdout {out}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
    }
}
