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
