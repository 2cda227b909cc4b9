//! `asperity gfmd` through the binary: JSON, table, height-map files and errors.

mod common;

use asperity::gfmd::GfmdOptions;
use common::run as asperity;

// ---- the command ----

#[test]
fn cli_gfmd_json_table_surface_files_and_errors() {
    let dir = std::env::temp_dir().join(format!("asperity-gfmd-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let map = dir.join("map.txt");
    let map_s = map.to_str().unwrap();
    let (code, out, err) = asperity(&[
        "gfmd",
        "--preset",
        "system-1",
        "--grid",
        "64",
        "--seed",
        "3",
        // a loaded map runs gamma_s and rho as given (no full system to reduce from)
        "--raw-adhesion",
        "--save-surface",
        map_s,
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    for key in [
        "a_r",
        "mean_contact_stress",
        "contact_stress_variance",
        "mean_gap",
        "mean_gap_rel",
        "pr",
        "iterations",
        "residual",
        "elapsed_s",
        "grid",
        "converged",
        "theory",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert_eq!(v["grid"], 64);
    assert_eq!(v["converged"], true);
    assert_eq!(v["tolerance"].as_f64(), Some(GfmdOptions::default().tolerance));
    assert!(v["residual"].as_f64().unwrap() <= 1e-8);
    assert!(v["pr"]["sigma"].as_array().unwrap().len() == v["pr"]["density"].as_array().unwrap().len());
    assert!(v["theory"]["a_r"].as_f64().unwrap() > 0.0);
    // the saved map, loaded back, gives the same run
    let size = v["system_size_m"].as_f64().unwrap().to_string();
    let (code, out2, err) = asperity(&["gfmd", "--preset", "system-1", "--surface", map_s, "--size", &size]);
    assert_eq!(code, 0, "{err}");
    let w: serde_json::Value = serde_json::from_str(&out2).unwrap();
    assert_eq!(v["a_r"], w["a_r"]);
    assert_eq!(v["mean_contact_stress"], w["mean_contact_stress"]);
    assert!(w["seed"].is_null());
    // adhesion: the theory is null with its reason (until the adhesive engine lands) or present
    let (code, out3, err) = asperity(&["gfmd", "--preset", "system-2", "--grid", "64", "--gamma", "0.157"]);
    assert_eq!(code, 0, "{err}");
    let a: serde_json::Value = serde_json::from_str(&out3).unwrap();
    assert!(a["theory"].is_object() || a["theory_error"].is_string());
    // table
    let (code, out4, _) = asperity(&["gfmd", "--grid", "32", "--format", "table"]);
    assert_eq!(code, 0);
    assert!(out4.contains("a_r") && out4.contains("iterations"));
    // errors: one line, exit code 2, the field named
    for (args, field) in [
        (vec!["gfmd", "--grid", "-4"], "--grid"),
        (vec!["gfmd", "--grid", "10"], "--grid"),
        (vec!["gfmd", "--grid", "32", "--tolerance", "0"], "--tolerance"),
        (vec!["gfmd", "--grid", "32", "--pressure", "-0.1"], "--pressure"),
        (
            vec!["gfmd", "--surface", "/nonexistent/x.txt", "--size", "1e-6"],
            "/nonexistent/x.txt",
        ),
    ] {
        let (code, _, err) = asperity(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(field), "{args:?}: {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
