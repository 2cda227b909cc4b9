//! `asperity run` on adhesive scenes: the JSON fields and the accuracy knobs.

use std::process::Command;

#[test]
fn run_json_has_the_adhesion_fields() {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(["run", "--preset", "system-1", "--format", "json"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in [
        "gamma_q",
        "sigma_a_q",
        "detached_fraction",
        "iterations",
        "residual",
        "branch",
    ] {
        assert!(!v[key].is_null(), "{key}");
    }
    assert_eq!(v["branch"], "loading");
    assert!(
        v["scene"]["gamma"].as_f64().unwrap() > 0.0,
        "the preset's gamma is the default"
    );
    let sigma = v["pr"]["sigma"].as_array().unwrap();
    assert!(sigma[0].as_f64().unwrap() < 0.0, "the tensile part is included");
    assert!(v["mean_gap_rel"].as_f64().unwrap() > 0.0);
    // the accuracy knobs: a finer run agrees within the default's error estimate
    let est = v["error_estimate"].as_f64().unwrap();
    let a = v["a_r"].as_f64().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args([
            "run",
            "--preset",
            "system-1",
            "--adhesion-steps",
            "48",
            "--adhesion-points",
            "20",
        ])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let fine: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(
        (fine["a_r"].as_f64().unwrap() - a).abs() < 3.0 * est,
        "{} vs {a} (estimate {est})",
        fine["a_r"]
    );
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(["run", "--preset", "system-1", "--adhesion-steps", "0.5"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--adhesion-steps"));
    // --gamma 0 takes the adhesionless path
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(["run", "--preset", "system-1", "--gamma", "0", "--format", "json"])
        .output()
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["branch"], "adhesionless");
    assert_eq!(v["iterations"], 0);
}
