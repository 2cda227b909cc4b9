//! `asperity sweep` and the gap/energy fields of `run`, through the binary.

mod common;

use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::theory::engine::Options;
use asperity::theory::sweep::{self, SweepSpec};
use asperity::tolerances::*;
use common::run as asperity;

#[test]
fn sweep_command_csv_and_json() {
    let (code, out, err) = asperity(&[
        "sweep", "--preset", "system-1", "--model", "1", "--gamma", "0", "--from", "0.01", "--to", "0.1", "--points",
        "3",
    ]);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert!(lines[0].starts_with("p,a_r,mean_gap_rel,mean_gap,mean_contact_stress,elastic_energy,converged"));
    assert_eq!(lines.len(), 4);
    let first: Vec<&str> = lines[1].split(',').collect();
    let p: f64 = first[0].parse().unwrap();
    let a: f64 = first[1].parse().unwrap();
    let g: f64 = first[2].parse().unwrap();
    assert!((p - 0.01).abs() < 1e-15);
    assert!((a / statrs::function::erf::erf(2f64.sqrt() * 0.01) - 1.0).abs() < MODEL1_ERF_REL);
    assert!((g - 1.8466).abs() < 1e-3, "{g}");
    assert_eq!(first[6], "true");

    let (code, out, err) = asperity(&[
        "sweep", "--preset", "system-1", "--from", "0.01", "--to", "0.1", "--points", "2", "--format", "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["rows"].as_array().unwrap().len(), 2);
    assert!(v["rows"][0]["mean_gap"].as_f64().unwrap() > 0.0);

    let (code, _, err) = asperity(&["sweep", "--preset", "system-1", "--from", "0.1", "--to", "0.01"]);
    assert_eq!(code, 2);
    assert!(err.contains("--to"), "{err}");
}

#[test]
fn run_json_has_gap_and_energy() {
    let (code, out, err) = asperity(&[
        "run",
        "--preset",
        "system-1",
        "--model",
        "1",
        "--gamma",
        "0",
        "--pressure",
        "0.1",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let rel = v["mean_gap_rel"].as_f64().unwrap();
    let m = v["mean_gap"].as_f64().unwrap();
    let h = v["scene"]["rms_height_m"].as_f64().unwrap();
    assert!((rel - 0.234688).abs() < 1e-5, "{rel}");
    assert!((m - rel * h).abs() < 1e-15);
    assert!(v["elastic_energy"].as_f64().unwrap() > 0.0);
}

#[test]
fn a_sweep_keeps_going_past_loads_that_do_not_converge() {
    // system 2, model 3, t·q_r = 0.1: at p* ~ 1e-4 the contact sits on the edge of a jump and
    // the adhesive solve may not converge; the sweep still returns every other load, with empty
    // (null) rows where it failed, and no mean gap in them
    let mut s = Preset::resolve("system-2").unwrap().scene().unwrap();
    s.set_model(Model::named(3).unwrap()).unwrap();
    s.set_thickness_qr(0.1).unwrap();
    let spec = SweepSpec {
        from: 1e-4,
        to: 1.0,
        points: 5,
    };
    let sw = sweep::sweep(&s, &spec, &Options::chart(), None).unwrap();
    let lowest_gap = sw.rows.iter().position(|r| r.mean_gap_rel.is_finite());
    for (k, r) in sw.rows.iter().enumerate() {
        if r.converged {
            assert!(r.a_r.is_finite() && (0.0..=1.0).contains(&r.a_r), "{r:?}");
        } else {
            assert!(r.a_r.is_nan() && sw.failed_loads.contains(&r.p), "{r:?}");
            // with adhesion each row's gap is its own state's: a failed load has none
            assert!(r.mean_gap_rel.is_nan() && lowest_gap != Some(k), "{r:?}");
        }
    }
    if !sw.failed_loads.is_empty() {
        assert!(sw.note.as_deref().is_some_and(|n| n.contains("did not converge")));
    }
    assert!(sw.rows.last().unwrap().converged);
    // printed: empty CSV fields and JSON nulls, never NaN
    use asperity_cli::cli::sweep::{csv, Row};
    let rows: Vec<Row> = sw.rows.iter().map(|r| Row::new(*r, &s)).collect();
    let csv = csv(&rows);
    assert!(!csv.to_lowercase().contains("nan"), "{csv}");
    let json = serde_json::to_string(&sw).unwrap();
    assert!(!json.to_lowercase().contains("nan"), "{json}");
}

/// A hard point of system 2 (model 4, t·q_r 0.1186, γ_s 0.157, p* 3.5e-7): at the default
/// resolution its loading root sits on a jump of the discrete H and only the second try at
/// more steps per ln q converges; with the root refinement cut to one march neither try
/// does, and a sweep starting there keeps the row, empty, with a one-line reason beside it
/// (JSON `reason`, the CSV's last column, quoted), and the other rows carry none.
#[test]
fn a_failed_row_keeps_its_place_with_a_one_line_reason() {
    use asperity_cli::cli::sweep::{csv, Row, CSV_HEADER};
    let mut s = Preset::resolve("system-2").unwrap().scene().unwrap();
    s.set_thickness_qr(0.11858657076247323).unwrap();
    let p = 3.5030939862794857e-07;
    let spec = SweepSpec {
        from: p,
        to: 1e-6,
        points: 2,
    };
    let mut opts = Options::default();
    opts.adhesion.max_iterations = 1;
    let sw = sweep::sweep(&s, &spec, &opts, None).unwrap();
    assert_eq!(sw.rows.len(), 2);
    assert_eq!(sw.reasons.len(), 2);
    let (r0, why) = (&sw.rows[0], sw.reasons[0].as_deref());
    assert!(!r0.converged && r0.a_r.is_nan() && r0.p == p, "{r0:?}");
    let why = why.expect("a reason for the failed row");
    assert!(why.contains("did not converge") && !why.contains('\n'), "{why}");
    assert!(sw.rows[1].converged && sw.reasons[1].is_none());
    let rows: Vec<Row> = sw
        .rows
        .iter()
        .zip(&sw.reasons)
        .map(|(r, w)| Row::new(*r, &s).with_reason(w.clone()))
        .collect();
    let v = serde_json::to_value(&rows).unwrap();
    assert_eq!(v[0]["reason"].as_str(), Some(why));
    assert!(v[1]["reason"].is_null());
    let text = csv(&rows);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 3, "{text}");
    assert!(CSV_HEADER.ends_with(",reason"));
    let quoted = format!("\"{}\"", why.replace('"', "\"\""));
    assert!(
        lines[1].ends_with(&quoted) || (lines[1].ends_with(why) && !why.contains(',')),
        "{}",
        lines[1]
    );
    assert!(
        lines[2].ends_with(','),
        "a converged row's reason is empty: {}",
        lines[2]
    );
}

fn asperity_out(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap()
}

fn run_json(args: &[&str]) -> serde_json::Value {
    let out = asperity_out(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// `sweep --over thickness|gamma`: every row is `run` at that scene (same engine, same
/// options: equal to 1e-12), the new columns are what they say, and [S-18] appears only where
/// it applies.
#[test]
fn sweeps_over_thickness_and_gamma_match_run() {
    for (over, from, to, flag, extra) in [
        ("thickness", "0.1", "10", "--thickness", vec!["--gamma", "0"]),
        ("gamma", "0", "0.05", "--gamma", vec!["--thickness", "1"]),
    ] {
        let mut args = vec![
            "sweep",
            "--preset",
            "system-2",
            "--over",
            over,
            "--from",
            from,
            "--to",
            to,
            "--points",
            "3",
            "--pressure",
            "0.01",
            "--format",
            "json",
        ];
        args.extend(extra.iter().copied());
        let sw = run_json(&args);
        let rows = sw["rows"].as_array().unwrap();
        assert_eq!(rows.len(), 3);
        for r in rows {
            let value = if over == "thickness" {
                r["thickness_qr"].as_f64().unwrap()
            } else {
                r["gamma"].as_f64().unwrap()
            };
            let v = format!("{value:e}");
            let mut rargs = vec!["run", "--preset", "system-2", "--pressure", "0.01", flag, &v];
            rargs.extend(extra.iter().copied());
            let run = run_json(&rargs);
            for k in ["a_r", "mean_contact_stress", "contact_stress_variance", "mean_gap_rel"] {
                let (a, b) = (r[k].as_f64().unwrap(), run[k].as_f64().unwrap());
                assert!((a - b).abs() <= 1e-12 * b.abs(), "{over} {v} {k}: sweep {a} run {b}");
            }
            let ratio = r["a_r_over_p"].as_f64().unwrap();
            assert!((ratio - r["a_r"].as_f64().unwrap() / 0.01).abs() < 1e-12);
            // a finite slab or adhesion: eq. (18) does not apply
            assert!(r["a_r_eq18"].is_null(), "{r}");
        }
    }
}

#[test]
fn load_sweep_columns_carry_eq18_and_the_variance() {
    let out = asperity_out(&[
        "sweep", "--preset", "system-1", "--gamma", "0", "--from", "0.01", "--to", "0.1", "--points", "2",
    ]);
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    for line in lines {
        let c: Vec<&str> = line.split(',').collect();
        let p: f64 = c[col("p")].parse().unwrap();
        let eq18: f64 = c[col("a_r_eq18")].parse().unwrap();
        // independent reference: docs/reference-values.md, eq. (18) column
        let want = if (p - 0.01).abs() < 1e-9 { 0.02144 } else { 0.21054 };
        assert!((eq18 - want).abs() < 1e-5, "{line}");
        let var: f64 = c[col("contact_stress_variance")].parse().unwrap();
        if (p - 0.01).abs() < 1e-9 {
            // Table 1 of [S], model 3 at p* = 0.01: 0.0595 (docs: ±3e-4)
            assert!((var - 0.0595).abs() < 3e-4, "{line}");
        }
        assert_eq!(c[col("thickness_qr")], "inf");
    }
}

#[test]
fn bad_sweep_knobs_are_one_line_errors() {
    for (args, needle) in [
        (
            vec!["sweep", "--over", "thickness", "--from", "0", "--to", "1"],
            "--from",
        ),
        (
            vec!["sweep", "--over", "gamma", "--from", "0.1", "--to", "0.01"],
            "--to",
        ),
        (vec!["sweep", "--over", "speed", "--from", "0.1", "--to", "1"], "--over"),
        (
            vec!["sweep", "--from", "0.1", "--to", "1", "--pressure", "0.1"],
            "--pressure",
        ),
    ] {
        let out = asperity_out(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

/// The tour's "Jump into contact" scene (tours/wang-muser.toml: system II, model 3,
/// γ_s = 0.1256 J/m², p* = 1e-4) swept over t·q_r from 0.05 to 1: its hysteresis window
/// (t·q_r ≈ 0.099–0.101) is far narrower than the step, and `sweep --over thickness` reports
/// the window the explorer's thickness chart finds (the same probe, edges to 0.5 % against the
/// chart's 3 %), at 8 and at 16 points.
#[test]
fn a_thickness_sweep_reports_the_window_the_explorer_finds() {
    use asperity::theory::engine::{CHART_EDGE_REL, EDGE_REL};
    use asperity_cli::tui::base::tour::{Tour, DEFAULT_TOUR};
    use asperity_cli::tui::effects::engine::thickness_sweep;
    let tour = Tour::resolve(DEFAULT_TOUR).unwrap();
    let step = tour.steps.iter().find(|s| s.title == "Jump into contact");
    let scene = step.unwrap().scene.clone();
    let chart = thickness_sweep(&scene, &std::sync::atomic::AtomicBool::new(false)).unwrap();
    assert_eq!((chart.jump_in.len(), chart.pull_off.len()), (1, 1), "{chart:?}");
    let near = |a: f64, b: f64| (a / b - 1.0).abs() <= CHART_EDGE_REL + EDGE_REL;
    for points in ["8", "16"] {
        let sw = run_json(&[
            "sweep",
            "--preset",
            "system-2",
            "--model",
            "3",
            "--gamma",
            "0.1256",
            "--pressure",
            "1e-4",
            "--over",
            "thickness",
            "--from",
            "0.05",
            "--to",
            "1",
            "--points",
            points,
            "--format",
            "json",
        ]);
        assert_eq!(sw["rows"].as_array().unwrap().len(), points.parse::<usize>().unwrap());
        let edges = sw["window_edges"].as_array().unwrap();
        let edge = |kind: &str| {
            let v: Vec<f64> = edges
                .iter()
                .filter(|e| e["kind"] == kind)
                .map(|e| e["value"].as_f64().unwrap())
                .collect();
            assert_eq!(v.len(), 1, "{points} points: {edges:?}");
            v[0]
        };
        let (jump_in, pull_off) = (edge("jump_in"), edge("pull_off"));
        assert!(jump_in < pull_off, "{jump_in} {pull_off}");
        assert!(
            near(jump_in, chart.jump_in[0]) && near(pull_off, chart.pull_off[0]),
            "{points} points: sweep {jump_in}..{pull_off}, explorer {:?}..{:?}",
            chart.jump_in,
            chart.pull_off
        );
    }
}
