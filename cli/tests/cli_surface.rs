//! Measured surfaces end to end: `psd`, and `run`, `sweep`, `gfmd` on a shipped map that is not
//! self-affine (tests/fixtures/two_bands.txt: two bands of roughness, one anisotropic), and the
//! theory on the CSV table of an ideal self-affine spectrum against the preset's analytic one;
//! `figure` on the map against `run` and `gfmd` on it.

mod common;
#[path = "../../tests/support/ideal_table.rs"]
mod ideal_table;

use asperity::input::preset::Preset;
use asperity::surface::spectrum::Spectrum;
use common::asperity_here as asperity;
use common::asperity_here_ok as ok;

const MAP: &str = "tests/fixtures/two_bands.txt";

fn json(args: &[&str]) -> serde_json::Value {
    serde_json::from_str(&ok(args)).unwrap()
}

fn tmp(name: &str) -> String {
    let d = std::env::temp_dir().join(format!("asperity-cli-surface-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d.join(name).display().to_string()
}

#[test]
fn psd_of_the_two_band_map() {
    let v = json(&["psd", MAP, "--periodic", "--format", "json"]);
    // the file's header: 2 µm wide, heights in nm
    assert!((v["system_size_m"].as_f64().unwrap() - 2e-6).abs() < 1e-18);
    let h = v["rms_height_m"].as_f64().unwrap();
    assert!(h > 1e-9 && h < 1e-7, "{h}");
    // the table integrates (trapezoid in ln q) to about h_rms² and has two separate bands
    let t = v["table"].as_array().unwrap();
    assert!(t.len() >= 4);
    let q: Vec<f64> = t.iter().map(|r| r["q"].as_f64().unwrap()).collect();
    let c: Vec<f64> = t.iter().map(|r| r["psd"].as_f64().unwrap()).collect();
    let peak = c.iter().cloned().fold(0.0, f64::max);
    assert!(c.iter().any(|&x| x < 1e-3 * peak), "a gap between the bands: {c:?}");
    // two bands are not self-affine: the fit's H is outside (0, 1] and the output says so
    let hurst = v["hurst"].as_f64().unwrap_or(f64::NAN);
    assert_eq!(v["self_affine"], false, "H = {hurst}");
    let table = ok(&["psd", MAP, "--periodic"]);
    assert!(table.lines().any(|l| l.starts_with("self_affine")), "{table}");
    let csv = ok(&["psd", MAP, "--periodic", "--format", "csv"]);
    assert!(csv.starts_with("q,psd\n"));
    assert_eq!(csv.lines().count(), q.len() + 1);
    for k in [
        "rms_gradient",
        "rms_curvature",
        "hurst",
        "rolloff_wavelength_m",
        "short_wavelength_m",
    ] {
        assert!(v.get(k).is_some(), "{k}");
    }
}

/// A generated self-affine map (H = 0.8, L = 4 λ_r) is recognised as self-affine, with its H.
#[test]
fn psd_of_a_self_affine_map_says_so() {
    use asperity::surface::heightmap::generate;
    use asperity::surface::spectrum::{Normalisation, SelfAffine};
    let sa = SelfAffine::new(4e-6, 1e-6, 1e-6 / 16.0, 0.8, Normalisation::RmsGradient(0.1)).unwrap();
    let path = tmp("self_affine.txt");
    generate(&sa, 128, 7)
        .unwrap()
        .save(std::path::Path::new(&path))
        .unwrap();
    let v = json(&["psd", &path, "--size", "4e-6", "--periodic", "--format", "json"]);
    assert_eq!(v["self_affine"], true);
    let h = v["hurst"].as_f64().unwrap();
    assert!((h - 0.8).abs() < asperity::tolerances::PSD_HURST_ABS, "H = {h}");
    let table = ok(&["psd", &path, "--size", "4e-6", "--periodic"]);
    assert!(!table.lines().any(|l| l.starts_with("self_affine")), "{table}");
}

#[test]
fn run_sweep_and_gfmd_on_the_two_band_map() {
    let v = json(&[
        "run",
        "--surface",
        MAP,
        "--periodic",
        "--gamma",
        "0",
        "--pressure",
        "0.1",
    ]);
    assert_eq!(v["scene"]["spectrum"], "tabulated");
    assert_eq!(v["scene"]["spectrum_source"], MAP);
    let a = v["a_r"].as_f64().unwrap();
    assert!(a > 0.0 && a < 1.0, "{a}");
    // with adhesion (the preset's gamma), and a PSD table written by `psd`
    let table = tmp("two_bands.csv");
    std::fs::write(&table, ok(&["psd", MAP, "--periodic", "--format", "csv"])).unwrap();
    let w = json(&["run", "--psd", &table, "--pressure", "0.1", "--thickness", "1"]);
    assert!(w["a_r"].as_f64().unwrap() > 0.0);
    let csv = ok(&[
        "sweep",
        "--surface",
        MAP,
        "--periodic",
        "--from",
        "0.01",
        "--to",
        "0.3",
        "--points",
        "3",
    ]);
    assert_eq!(csv.lines().count(), 4, "{csv}");
    let csv = ok(&[
        "sweep",
        "--psd",
        &table,
        "--over",
        "gamma",
        "--from",
        "0",
        "--to",
        "0.01",
        "--points",
        "2",
        "--pressure",
        "0.1",
    ]);
    assert_eq!(csv.lines().count(), 3, "{csv}");
    // GFMD on the map itself, with the theory on the map's own modes beside it
    let g = json(&["gfmd", "--surface", MAP, "--gamma", "0", "--pressure", "0.1"]);
    let ga = g["a_r"].as_f64().unwrap();
    let ta = g["theory"]["a_r"].as_f64().unwrap();
    assert!(ga > 0.0 && ga < 1.0 && ta > 0.0 && ta < 1.0, "{ga} {ta}");
}

#[test]
fn the_theory_on_the_csv_of_an_ideal_spectrum_equals_the_preset() {
    let p = Preset::resolve("system-2").unwrap();
    let Spectrum::SelfAffine(sa) = p.spectrum().unwrap() else {
        unreachable!()
    };
    let path = tmp("ideal.csv");
    std::fs::write(&path, ideal_table::ideal_csv(&sa, 50)).unwrap();
    for extra in [&["--thickness", "inf"][..], &["--thickness", "0.5", "--gamma", "0"][..]] {
        let mut base = vec!["run", "--preset", "system-2"];
        base.extend_from_slice(extra);
        let a = json(&base);
        base.extend_from_slice(&["--psd", &path]);
        let b = json(&base);
        assert_eq!(b["scene"]["spectrum"], "tabulated");
        assert_eq!(a["scene"]["spectrum"], "self-affine");
        for k in ["a_r", "mean_contact_stress", "mean_gap_rel"] {
            let (x, y) = (a[k].as_f64().unwrap(), b[k].as_f64().unwrap());
            assert!(
                (y / x - 1.0).abs() < asperity::tolerances::TABULATED_THEORY_REL,
                "{extra:?} {k}: {y} vs {x}"
            );
        }
    }
}

#[test]
fn bad_surface_input_is_one_line_and_exit_2() {
    let bad = tmp("bad.txt");
    std::fs::write(&bad, "1 2 3\n4 x 6\n").unwrap();
    let line = tmp("line.txt");
    let row: Vec<String> = (0..16).map(|k| format!("{}", (k as f64).sin())).collect();
    std::fs::write(&line, format!("{}\n", row.join(" "))).unwrap();
    let csv = tmp("bad.csv");
    std::fs::write(&csv, "q,psd\n1e6,1e-30\n2e6,-1\n").unwrap();
    for (args, needle) in [
        (
            vec!["psd", bad.as_str(), "--size", "1e-6"],
            "bad.txt:2: 'x' (not a number)",
        ),
        (vec!["run", "--psd", csv.as_str()], "row 2: psd = -1"),
        (vec!["run", "--psd", MAP], "has no columns named q and psd"),
        (
            vec!["psd", "tests/fixtures/none.npy", "--size", "1e-6"],
            "file = tests/fixtures/none.npy",
        ),
        (vec!["psd", MAP, "--bins-per-decade", "0"], "--bins-per-decade"),
        (vec!["run", "--size", "1e-6"], "missing --surface"),
        (vec!["gfmd", "--psd", csv.as_str()], "none for gfmd"),
        (vec!["run", "--surface", MAP, "--qmin", "1e20"], "--qmin"),
        (vec!["figure", "2", "--psd", csv.as_str(), "--gfmd"], "--psd"),
        (
            vec!["figure", "2", "--surface", MAP, "--gfmd", "--grid", "64"],
            "--grid",
        ),
        (vec!["figure", "table-1", "--surface", MAP], "none for table-1"),
        (
            vec![
                "figure",
                "5",
                "--surface",
                line.as_str(),
                "--size",
                "1e-5",
                "--height-unit",
                "nm",
                "--gfmd",
            ],
            "a 16 x 1 map",
        ),
    ] {
        let out = asperity(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
    }
}

/// `figure --surface`: every curve is `run` on the map at the figure's x values, the paper's
/// values (of its surfaces) are left out, and `--gfmd` runs on the map as `gfmd --surface` does.
#[test]
fn figures_on_the_two_band_map_are_run_on_it() {
    let on = ["--surface", MAP, "--periodic"];
    let (checked, csv) = common::figure_7_against_run(&on);
    assert!(checked >= 9, "too few points compared: {checked}\n{csv}");
    // the adhesionless curve on this map is not the preset's
    let preset = ok(&["figure", "7", "--format", "csv", "--points", "4"]);
    let at = |csv: &str| {
        csv.lines()
            .filter_map(|l| l.strip_prefix("adhesionless (model 4),"))
            .map(|l| {
                l.split(',')
                    .map(|c| c.parse::<f64>().unwrap_or(f64::NAN))
                    .collect::<Vec<_>>()
            })
            .find(|c| (c[0] / 0.1 - 1.0).abs() < 1e-9)
            .map(|c| c[1])
            .expect("a point at t·q_r = 0.1")
    };
    let (mine, theirs) = (at(&csv), at(&preset));
    assert!(
        (mine / theirs - 1.0).abs() > 0.01,
        "the map's spectrum was not used: {mine} {theirs}"
    );

    let mut args = vec!["figure", "5", "--gfmd", "--format", "json", "--points", "3"];
    args.extend(on);
    let v = json(&args);
    assert_eq!(v["spectrum_source"], MAP);
    assert!(v["title"].as_str().unwrap().ends_with(&format!("on {MAP}")));
    let series = v["series"].as_array().unwrap();
    assert!(
        series.iter().all(|s| !s["name"].as_str().unwrap().starts_with("[S]")),
        "the paper's values drawn on a measured map"
    );
    let notes = v["notes"].to_string();
    assert!(notes.contains("not drawn on"), "{notes}");
    let find = |prefix: &str| {
        series
            .iter()
            .find(|s| s["name"].as_str().unwrap().starts_with(prefix))
            .unwrap_or_else(|| panic!("{prefix}: {series:?}"))["points"]
            .as_array()
            .unwrap()
            .clone()
    };
    let (g, t) = (find("GFMD"), find("theory on the GFMD map"));
    let p = format!("{:e}", g[1]["x"].as_f64().unwrap());
    let mut run = vec!["gfmd", "--preset", "system-1", "--gamma", "0", "--pressure", &p];
    run.extend(on);
    let want = json(&run);
    assert_eq!(g[1]["y"].as_f64(), want["mean_contact_stress"].as_f64());
    assert_eq!(t[1]["y"].as_f64(), want["theory"]["mean_contact_stress"].as_f64());
}
