//! Load sweeps (issue 4): rows, shared U table, refinement error, cancellation, adhesion hook,
//! validation and the `sweep` / `run` command lines.

use asperity::engine::{self, Options};
use asperity::model::Model;
use asperity::preset::Preset;
use asperity::scene::Scene;
use asperity::sweep::{self, SweepSpec};
use asperity::tolerances::*;
use asperity::{gap, Error};
use std::process::Command;
use std::sync::atomic::AtomicBool;

fn system1(n: u8) -> Scene {
    let mut s = Preset::resolve("system-1").unwrap().scene().unwrap();
    s.gamma = 0.0;
    s.model = Model::named(n).unwrap();
    s
}

#[test]
fn rows_match_single_evaluations() {
    let s = system1(3);
    let spec = SweepSpec {
        from: 1e-3,
        to: 1.0,
        points: 64,
    };
    let sw = sweep::sweep(&s, &spec, &Options::default(), None).unwrap();
    assert_eq!(sw.rows.len(), 64);
    // spacing 0.11 in ln p*: no refinement, only the extension to full contact
    assert!(sw.evaluations < 64 + 20, "{}", sw.evaluations);
    let h_rms = s.spectrum.rms_height();
    for (r, p) in sw.rows.iter().zip(spec.pressures()) {
        assert_eq!(r.p, p);
        assert!((r.mean_gap - r.mean_gap_rel * h_rms).abs() < 1e-18);
    }
    for k in [0, 31, 63] {
        let mut one = s.clone();
        one.pressure = sw.rows[k].p;
        // a sweep evaluates its loads at the energy route's tolerance
        let mut tight = Options::default();
        tight.accuracy.rtol = gap::ENERGY_RTOL;
        let ev = engine::evaluate(&one, &tight).unwrap();
        assert_eq!(ev.a_r, sw.rows[k].a_r);
        assert_eq!(ev.elastic_energy, sw.rows[k].elastic_energy);
        assert!((ev.mean_contact_stress - sw.rows[k].mean_contact_stress).abs() < 1e-14);
        // the single-load gap (its own grid, step 0.1) agrees within the two error estimates
        let g = gap::mean_gap(&one, &Options::default()).unwrap().unwrap();
        let tol = 3.0 * (g.error + sw.rows[k].mean_gap_error) + 1e-12;
        assert!(
            (g.relative - sw.rows[k].mean_gap_rel).abs() < tol,
            "{k}: {g:?} vs {:?}",
            sw.rows[k]
        );
    }
}

#[test]
fn sixty_four_points_against_four_times_finer() {
    for n in [1, 3] {
        let s = system1(n);
        let coarse = SweepSpec {
            from: 1e-3,
            to: 1.0,
            points: 64,
        };
        let fine = SweepSpec { points: 253, ..coarse };
        let a = sweep::sweep(&s, &coarse, &Options::default(), None).unwrap();
        let b = sweep::sweep(&s, &fine, &Options::default(), None).unwrap();
        for (k, r) in a.rows.iter().enumerate() {
            let f = &b.rows[4 * k];
            assert!(((r.p - f.p) / r.p).abs() < 1e-12);
            if f.mean_gap_rel > 1e-3 {
                let rel = ((r.mean_gap_rel - f.mean_gap_rel) / f.mean_gap_rel).abs();
                assert!(rel < SWEEP_REFINEMENT_REL, "model {n} p* = {}: rel {rel:.1e}", r.p);
            }
        }
    }
}

#[test]
fn cancellation_and_validation() {
    let s = system1(1);
    let spec = SweepSpec {
        from: 1e-3,
        to: 1.0,
        points: 16,
    };
    let stop = AtomicBool::new(true);
    assert_eq!(
        sweep::sweep(&s, &spec, &Options::default(), Some(&stop)),
        Err(Error::Cancelled)
    );
    for (bad, field) in [
        (SweepSpec { from: 0.0, ..spec }, "--from"),
        (SweepSpec { to: 1e-4, ..spec }, "--to"),
        (SweepSpec { points: 0, ..spec }, "--points"),
        (SweepSpec { to: f64::NAN, ..spec }, "--to"),
    ] {
        let e = sweep::sweep(&s, &bad, &Options::default(), None)
            .unwrap_err()
            .to_string();
        assert!(e.contains(field), "{e}");
    }
    // one point
    let one = sweep::sweep(&s, &SweepSpec { points: 1, ..spec }, &Options::default(), None).unwrap();
    assert_eq!(one.rows.len(), 1);
    assert!(one.rows[0].mean_gap_rel > 0.0);
}

#[test]
fn adhesive_sweep_is_clean() {
    // An adhesive sweep (continuation from the neighbouring load) gives finite, converged rows
    // and flags any non-monotone stretch (an adhesive jump).
    for t in [f64::INFINITY, 0.05] {
        let mut s = Preset::resolve("system-2").unwrap().scene().unwrap();
        s.thickness_qr = t;
        assert!(s.gamma > 0.0);
        let spec = SweepSpec {
            from: 1e-4,
            to: 1.0,
            points: 32,
        };
        match sweep::sweep(&s, &spec, &Options::default(), None) {
            Err(e) => panic!("t = {t}: {e}"),
            Ok(sw) => {
                for r in &sw.rows {
                    assert!(r.a_r.is_finite() && r.mean_gap_rel.is_finite() && r.elastic_energy.is_finite());
                    assert!(r.converged);
                }
                let mono = sw
                    .rows
                    .windows(2)
                    .all(|w| w[1].a_r >= w[0].a_r && w[1].mean_gap_rel <= w[0].mean_gap_rel);
                assert_eq!(mono, sw.monotone);
            }
        }
    }
}

fn asperity(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

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
    // the fixed point may not converge; the sweep still returns every other load, with empty
    // (null) rows where it failed and no mean gap at or below the highest failure
    let mut s = Preset::resolve("system-2").unwrap().scene().unwrap();
    s.model = Model::named(3).unwrap();
    s.thickness_qr = 0.1;
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
            assert!(lowest_gap.is_none_or(|g| k < g));
        }
    }
    if !sw.failed_loads.is_empty() {
        assert!(sw.note.as_deref().is_some_and(|n| n.contains("did not converge")));
    }
    assert!(sw.rows.last().unwrap().converged);
    // printed: empty CSV fields and JSON nulls, never NaN
    let csv = asperity::cli::sweep::csv(&sw);
    assert!(!csv.to_lowercase().contains("nan"), "{csv}");
    let json = serde_json::to_string(&sw).unwrap();
    assert!(!json.to_lowercase().contains("nan"), "{json}");
}
