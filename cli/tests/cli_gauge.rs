//! `gauge`, `compare` and the named variants on the command line: what works, and bad input
//! as one line with exit code 2.

mod common;

use common::run as asperity;

fn tmp(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("asperity-cli-gauge-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

#[test]
fn bad_input_is_one_line_with_exit_2() {
    let bad = tmp("bad.csv", "p,a_r\n0.01,0.02\n0.02,oops\n");
    for (args, want) in [
        (
            vec!["gauge", "--fit", "c1,cap", "--reference", "eq18"],
            "invalid --fit = c1,cap",
        ),
        (
            vec!["gauge", "--fit", "c3", "--reference", "eq18"],
            "invalid --fit = c3",
        ),
        (
            vec!["gauge", "--fit", "c1,w0", "--reference", "eq18"],
            "c1 or w0, not both",
        ),
        (
            vec!["gauge", "--fit", "c1", "--reference", "/nonexistent/ref.csv"],
            "invalid --reference = /nonexistent/ref.csv: allowed eq18, gfmd or an existing CSV file",
        ),
        (
            vec!["gauge", "--fit", "c1", "--reference", bad.as_str()],
            "bad.csv: line 3, column a_r = oops",
        ),
        (
            vec!["gauge", "--fit", "c1", "--reference", "eq18", "--from", "0"],
            "invalid --from = 0",
        ),
        (
            vec!["gauge", "--model", "1", "--fit", "c1,k_griffith", "--reference", "eq18"],
            "condition number",
        ),
        (
            vec![
                "gauge",
                "--model",
                "xu24",
                "--gamma",
                "0",
                "--fit",
                "c1",
                "--reference",
                "eq18",
            ],
            "not Xu24",
        ),
        (vec!["run", "--model", "yp08"], "adhesionless half-space only"),
        (
            vec!["run", "--model", "xu24", "--gamma", "0", "--thickness", "1"],
            "adhesionless half-space only",
        ),
        (
            vec!["run", "--model", "3", "--fudge-gamma", "0.3"],
            "invalid --model = 3",
        ),
        (
            vec!["run", "--model", "yp08", "--gamma", "0", "--fudge-gamma", "2"],
            "invalid --fudge-gamma = 2",
        ),
        (vec!["run", "--model", "yp09"], "invalid --model = yp09"),
        (
            vec!["compare", "--reference", "eq18", "--models", "3,custom"],
            "invalid --models = 3,custom: allowed a comma-separated list of 1, 2, 3, 4, 5, yp08, xu24 (a custom model",
        ),
        (vec!["figure", "1", "--model", "xu25"], "invalid --model = xu25"),
    ] {
        let (code, _, err) = asperity(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {err}");
    }
}

#[test]
fn variants_run_sweep_and_figure() {
    let (code, out, err) = asperity(&[
        "run",
        "--model",
        "xu24",
        "--gamma",
        "0",
        "--pressure",
        "0.01",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["scene"]["model"], "Xu24");
    // a_r/p* at p* = 0.01 lies between eq. (18)'s 2.14 and the small-p* slope 2.46
    let ratio = v["a_r"].as_f64().unwrap() / 0.01;
    assert!(ratio > 2.14 && ratio < 2.47, "{ratio}");
    let (code, out, err) = asperity(&[
        "sweep", "--model", "yp08", "--gamma", "0", "--from", "0.001", "--to", "0.1", "--points", "4",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(!out.is_empty());
    let (code, out, err) = asperity(&[
        "figure",
        "1",
        "--model",
        "yp08,xu24",
        "--format",
        "csv",
        "--points",
        "5",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("YP08") && out.contains("Xu24") && out.contains("model 3"),
        "{out}"
    );
}

#[test]
fn gauge_saves_a_preset_that_compare_reads() {
    let dir = std::env::temp_dir().join(format!("asperity-cli-gauge-save-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let preset = dir.join("gauged.toml").display().to_string();
    let svg = dir.join("gauge.svg").display().to_string();
    let (code, out, err) = asperity(&[
        "gauge",
        "--model",
        "1",
        "--fit",
        "c1,c2",
        "--reference",
        "eq18",
        "--points",
        "11",
        "--save-preset",
        &preset,
        "--svg",
        &svg,
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("c1") && out.contains("correlation") && out.contains("preset written"),
        "{out}"
    );
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
    let (code, out, err) = asperity(&[
        "compare",
        "--reference",
        "eq18",
        "--points",
        "11",
        "--fitted",
        &preset,
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let rows = v["models"].as_array().unwrap();
    assert_eq!(rows.len(), 7);
    let score = |name: &str, k: &str| {
        rows.iter().find(|r| r["model"] == name).unwrap()["scores"][0][k]
            .as_f64()
            .unwrap()
    };
    // the fitted model's worst point is closer to eq. (18) than model 3's, both well below
    // model 1's (mean errors: model 1 22 %, model 3 and the fit below 1 %)
    assert!(score("gauged", "max") < score("model 3", "max"), "{out}");
    assert!(
        score("gauged", "mean") < 0.01 && score("model 3", "mean") < 0.01,
        "{out}"
    );
    assert!(score("model 1", "mean") > 0.2, "{out}");
}

/// `gauge --reference gfmd` (2 seeds, 3 loads, 64² system II without adhesion) against the
/// independent path: the same loads run by `asperity gfmd --from --to --points` per seed,
/// averaged here, written as a reference CSV and fitted on the reduced scene that gauge saved
/// as a preset. Same reference rows, same fitted w0 and standard error.
#[test]
fn gfmd_reference_equals_its_numbers_as_a_csv_reference() {
    use asperity::tolerances::{GFMD_REFERENCE_FIT_REL, GFMD_REFERENCE_ROWS_REL};
    let dir = std::env::temp_dir().join(format!("asperity-cli-gauge-gfmd-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let red = dir.join("reduced.toml").display().to_string();
    let saved = dir.join("saved.csv").display().to_string();
    let scene = ["--preset", "system-2", "--gamma", "0", "--model", "4"];
    let loads = ["--from", "0.005", "--to", "0.02", "--points", "3"];
    let mut args: Vec<&str> = vec![
        "gauge",
        "--fit",
        "w0",
        "--reference",
        "gfmd",
        "--grid",
        "64",
        "--seeds",
        "2",
    ];
    args.extend(scene);
    args.extend(loads);
    args.extend(["--save-preset", &red, "--save-reference", &saved, "--format", "json"]);
    let (code, out, err) = asperity(&args);
    assert_eq!(code, 0, "{err}");
    let g: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(g["reference"], "gfmd");
    assert_eq!(g["gfmd"]["grid"], 64);

    // the same sweeps, one `gfmd` run per seed
    let mut per_seed: Vec<Vec<(f64, f64, f64)>> = Vec::new();
    for seed in ["1", "2"] {
        let mut a: Vec<&str> = vec!["gfmd", "--grid", "64", "--seed", seed, "--format", "json"];
        a.extend(&scene[..4]);
        a.extend(loads);
        let (code, out, err) = asperity(&a);
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        per_seed.push(
            v["rows"]
                .as_array()
                .unwrap()
                .iter()
                .map(|r| {
                    let f = |k: &str| r[k].as_f64().unwrap();
                    (f("p"), f("a_r"), f("mean_gap_rel"))
                })
                .collect(),
        );
    }
    let mean_se = |x: [f64; 2]| {
        let m = (x[0] + x[1]) / 2.0;
        let var = ((x[0] - m).powi(2) + (x[1] - m).powi(2)) / 1.0;
        (m, (var / 2.0).sqrt())
    };
    let mut csv = String::from("p,a_r,a_r_err,mean_gap_rel,mean_gap_rel_err\n");
    let rows = g["gfmd"]["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 3);
    for k in 0..3 {
        let (p, a1, u1) = per_seed[0][k];
        let (_, a2, u2) = per_seed[1][k];
        let (a, ae) = mean_se([a1, a2]);
        let (u, ue) = mean_se([u1, u2]);
        for (key, want) in [
            ("a_r", a),
            ("a_r_err", ae),
            ("mean_gap_rel", u),
            ("mean_gap_rel_err", ue),
        ] {
            let got = rows[k][key].as_f64().unwrap();
            assert!(
                (got / want - 1.0).abs() < GFMD_REFERENCE_ROWS_REL,
                "load {k} {key}: {got} vs {want}"
            );
        }
        csv += &format!("{p:e},{a:e},{ae:e},{u:e},{ue:e}\n");
    }
    let path = dir.join("by_hand.csv").display().to_string();
    std::fs::write(&path, csv).unwrap();
    let by_csv = |file: &str| {
        let (code, out, err) = asperity(&[
            "gauge",
            "--preset",
            &red,
            "--model",
            "4",
            "--fit",
            "w0",
            "--reference",
            file,
            "--format",
            "json",
        ]);
        assert_eq!(code, 0, "{err}");
        serde_json::from_str::<serde_json::Value>(&out).unwrap()
    };
    for c in [by_csv(&path), by_csv(&saved)] {
        for k in ["value", "std_error"] {
            let (x, y) = (g["params"][0][k].as_f64().unwrap(), c["params"][0][k].as_f64().unwrap());
            assert!(
                (x / y - 1.0).abs() < GFMD_REFERENCE_FIT_REL,
                "w0 {k}: gfmd {x} vs csv {y}"
            );
        }
        let (x, y) = (g["chi2"].as_f64().unwrap(), c["chi2"].as_f64().unwrap());
        assert!((x / y - 1.0).abs() < GFMD_REFERENCE_FIT_REL, "chi2 {x} vs {y}");
    }
}
