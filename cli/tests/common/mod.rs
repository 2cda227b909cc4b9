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
