//! `asperity surface generate`: the map it writes, read back by the library's readers in every
//! format, has the requested ḡ or h_rms (tolerances in `asperity::tolerances`), its PSD has the
//! requested Hurst exponent in the self-affine range (the PSD fit of `asperity psd`, against
//! the requested H within `GENERATED_HURST_ABS`), the same seed gives the same map, and inputs the
//! spectrum cannot take are refused in one line naming the flag.

mod common;

use asperity::surface::readers::{self, ReadOptions};
use asperity::tolerances::{GENERATED_HURST_ABS, GENERATED_NORM_F32_REL, GENERATED_NORM_REL};
use std::path::PathBuf;

/// The readers' options: a NumPy file states no side, so it is given (the generator's 1e-4 m).
fn side(ext: &str) -> ReadOptions {
    ReadOptions {
        size: (ext == "npy").then_some(1e-4),
        ..ReadOptions::default()
    }
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-generate-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn generate(out: &std::path::Path, extra: &[&str]) -> serde_json::Value {
    let p = out.display().to_string();
    let mut args = vec!["surface", "generate", "--output", p.as_str(), "--format", "json"];
    args.extend_from_slice(extra);
    common::asperity_json(&args)
}

#[test]
fn every_format_reads_back_with_the_requested_rms_gradient() {
    let dir = scratch("formats");
    for ext in ["txt", "asc", "dat", "xyz", "npy", "gsf"] {
        let out = dir.join(format!("map.{ext}"));
        let j = generate(&out, &["--grid", "32", "--rms-gradient", "0.5", "--seed", "7"]);
        assert_eq!(j["grid"], 32);
        let s = readers::read(&out, &side(ext)).unwrap();
        assert_eq!((s.nx, s.ny), (32, 32), "{ext}");
        let tol = if ext == "gsf" {
            GENERATED_NORM_F32_REL
        } else {
            GENERATED_NORM_REL
        };
        let g = s.rms_gradient();
        assert!((g / 0.5 - 1.0).abs() < tol, "{ext}: g = {g}, asked 0.5");
        assert!(
            (s.size_x() / 1e-4 - 1.0).abs() < tol,
            "{ext}: L = {} m, asked 1e-4",
            s.size_x()
        );
    }
}

#[test]
fn the_rms_height_is_the_requested_one() {
    let dir = scratch("height");
    let out = dir.join("map.npy");
    let j = generate(&out, &["--grid", "64", "--rms-height", "2e-7"]);
    let s = readers::read(&out, &side("npy")).unwrap();
    let h = s.rms_height();
    assert!((h / 2e-7 - 1.0).abs() < GENERATED_NORM_REL, "h_rms = {h}");
    assert!((j["rms_height_m"].as_f64().unwrap() / 2e-7 - 1.0).abs() < GENERATED_NORM_REL);
}

#[test]
fn the_psd_of_the_map_has_the_requested_hurst_exponent() {
    let dir = scratch("hurst");
    for hurst in [0.5, 0.8] {
        let out = dir.join(format!("map-{hurst}.npy"));
        let h = hurst.to_string();
        // L/lambda_r = 2, lambda_r/lambda_s = 16, 4 points per lambda_s
        generate(
            &out,
            &[
                "--grid",
                "128",
                "--size",
                "1e-4",
                "--rolloff-wavelength",
                "5e-5",
                "--short-wavelength",
                "3.125e-6",
                "--hurst",
                &h,
            ],
        );
        let p = out.display().to_string();
        let psd = common::asperity_json(&["psd", &p, "--size", "1e-4", "--periodic", "--format", "json"]);
        assert_eq!(psd["self_affine"], true, "H = {hurst}: {psd}");
        let fitted = psd["hurst"].as_f64().unwrap();
        assert!(
            (fitted - hurst).abs() < GENERATED_HURST_ABS,
            "asked H = {hurst}, the PSD fit gives {fitted}"
        );
    }
}

#[test]
fn a_seed_gives_the_same_map_and_another_seed_another() {
    let dir = scratch("seed");
    let (a, b, c) = (dir.join("a.npy"), dir.join("b.npy"), dir.join("c.npy"));
    generate(&a, &["--grid", "16", "--seed", "3"]);
    generate(&b, &["--grid", "16", "--seed", "3"]);
    generate(&c, &["--grid", "16", "--seed", "4"]);
    let read = |p: &PathBuf| std::fs::read(p).unwrap();
    assert_eq!(read(&a), read(&b));
    assert_ne!(read(&a), read(&c));
}

#[test]
fn a_non_periodic_map_is_a_window_of_a_larger_one() {
    let dir = scratch("window");
    let out = dir.join("map.txt");
    let j = generate(&out, &["--grid", "64", "--non-periodic"]);
    assert_eq!(j["periodic"], false);
    let s = readers::read(&out, &ReadOptions::default()).unwrap();
    // the jump across the window's edge is of the order of the heights (a periodic map's is
    // one step)
    let n = s.nx;
    let edge: f64 = (0..n)
        .map(|i| (s.heights[i * n] - s.heights[i * n + n - 1]).powi(2))
        .sum::<f64>()
        / n as f64;
    let step: f64 = (0..n)
        .map(|i| (s.heights[i * n] - s.heights[i * n + 1]).powi(2))
        .sum::<f64>()
        / n as f64;
    assert!(edge > 4.0 * step, "edge jump² {edge:e} against a step² {step:e}");
}

#[test]
fn a_spectrum_the_grid_cannot_hold_is_refused_in_one_line() {
    let dir = scratch("bad");
    let out = dir.join("map.npy").display().to_string();
    for (args, flag) in [
        (vec!["--grid", "16", "--short-wavelength", "1e-6"], "--grid"),
        (vec!["--rolloff-wavelength", "2e-4"], "--rolloff-wavelength"),
        (vec!["--hurst", "1.5"], "--hurst"),
    ] {
        let mut full = vec!["surface", "generate", "--output", out.as_str()];
        full.extend(args.iter().copied());
        let o = common::asperity(&full);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{full:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(flag), "{full:?}: {err}");
    }
    assert!(!dir.join("map.npy").exists());
}

#[test]
fn the_json_keys_are_the_documented_ones() {
    let dir = scratch("keys");
    let j = generate(&dir.join("map.gsf"), &["--grid", "16"]);
    let mut keys: Vec<&str> = j.as_object().unwrap().keys().map(String::as_str).collect();
    keys.sort();
    let mut want = [
        "file",
        "grid",
        "system_size_m",
        "spacing_m",
        "hurst",
        "rolloff_wavelength_m",
        "short_wavelength_m",
        "rms_height_m",
        "rms_gradient",
        "periodic",
        "seed",
        "elapsed_s",
    ];
    want.sort();
    assert_eq!(keys, want);
}
