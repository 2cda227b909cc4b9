//! Helpers shared by the binary's integration tests: running `asperity` and reading what it
//! prints.
#![allow(dead_code)]

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

/// A finished GFMD run for the explorer's tests at load `p`: a histogram shaped like the
/// theory of system 1 at p* = 0.01 and a little wider, a 512² grid, two sweep loads and the
/// theory on the map at three.
pub fn synthetic_gfmd(p: f64) -> asperity_cli::tui::data::GfmdView {
    let pr: Vec<(f64, f64)> = (0..60)
        .map(|i| {
            let s = -0.5 + 2.2 * (i as f64 + 0.5) / 60.0;
            (s, 0.04 * (-(s - 0.3) * (s - 0.3) / 0.3).exp())
        })
        .collect();
    asperity_cli::tui::data::GfmdView {
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
