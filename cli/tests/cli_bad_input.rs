//! Bad input at the command line: one line on stderr naming the field (by its flag or preset
//! key), the value and the allowed range, and exit code 2.

use std::process::Command;

fn fails(args: &[&str], needles: &[&str]) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?}: stdout not empty");
    assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: not one line: {err}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: expected {n:?} in {err:?}");
    }
    assert!(err.len() < 400, "{args:?}: too long: {err}");
}

#[test]
fn negative_numbers_are_values_not_options() {
    fails(&["run", "--thickness", "-inf"], &["--thickness = -inf", "or inf"]);
    fails(&["run", "--thickness", "-1"], &["--thickness = -1", "1e-6 <= t·q_r"]);
    fails(&["run", "--alpha", "-1"], &["--alpha = -1", "0 <= alpha <= 4"]);
    fails(&["run", "--rtol", "-1"], &["--rtol = -1", "1e-12 <= rtol <= 0.01"]);
    fails(
        &["run", "--adhesion-tol", "-1"],
        &["--adhesion-tol = -1", "<= adhesion_tol <="],
    );
    fails(
        &["run", "--sigma-max", "-1"],
        &["--sigma-max = -1", "<= sigma_max <= 1000"],
    );
    fails(
        &["sweep", "--from", "0.01", "--to", "0.1", "--points", "-5"],
        &["--points = -5", "whole number"],
    );
    fails(
        &["sweep", "--from", "0.01", "--to", "0.1", "--points", "0"],
        &["--points = 0", "1 <= points"],
    );
    fails(&["gfmd", "--grid", "32", "--tolerance", "-1"], &["--tolerance = -1"]);
}

#[test]
fn one_range_per_knob() {
    // the same range whichever check catches it (it was "4..10000" in one place, "2..1000" in
    // another)
    fails(
        &["run", "--adhesion-points", "3"],
        &["--adhesion-points = 3", "4 <= adhesion_points <= 1000"],
    );
    fails(
        &["run", "--adhesion-points", "2000"],
        &["--adhesion-points = 2000", "4 <= adhesion_points <= 1000"],
    );
    fails(
        &["run", "--adhesion-steps", "3"],
        &["--adhesion-steps = 3", "4 <= adhesion_steps <= 10000"],
    );
}

#[test]
fn values_that_would_break_a_solver_are_refused_up_front() {
    fails(&["run", "--rtol", "1e-300"], &["--rtol = 1e-300"]);
    fails(&["run", "--sigma-max", "1e300"], &["--sigma-max = 1e300"]);
    fails(&["run", "--pressure", "1e300"], &["--pressure = 1e300", "<= 1000"]);
    let dir = std::env::temp_dir().join(format!("asperity-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../presets/system-2.toml")).unwrap();
    let bad = dir.join("flat-gradient.toml");
    std::fs::write(&bad, text.replace("rms_gradient = 1.0", "rms_gradient = 1e-300")).unwrap();
    fails(
        &["run", "--preset", bad.to_str().unwrap()],
        &["surface.rms_gradient = 1e-300", "1e-6 <= rms_gradient <= 100"],
    );
    // TOML type errors name the line and the key
    let typed = dir.join("typed.toml");
    std::fs::write(&typed, text.replace("hurst = 0.8", "hurst = \"steep\"")).unwrap();
    let line = text.lines().position(|l| l.starts_with("hurst")).unwrap() + 1;
    fails(
        &["run", "--preset", typed.to_str().unwrap()],
        &[&format!("line {line}: surface.hurst:"), "expected f64"],
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn numbers_print_compactly_and_files_are_named_for_what_they_are() {
    let huge = format!("1{}", "0".repeat(300));
    fails(&["run", "--pressure", &huge], &["--pressure = 1e300"]);
    fails(
        &["run", "--preset", "/dev/zero"],
        &["--preset = /dev/zero", "or a preset TOML file"],
    );
    fails(
        &["run", "--preset", std::env::temp_dir().to_str().unwrap()],
        &["--preset = ", "or a preset TOML file"],
    );
    fails(
        &["run", "--preset", "no-such-system"],
        &["--preset = no-such-system", "system-1, system-2"],
    );
}

#[test]
fn gfmd_blames_the_map_not_the_pressure() {
    let dir = std::env::temp_dir().join(format!("asperity-bad-map-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let write = |name: &str, rows: &[&str]| {
        let p = dir.join(name);
        std::fs::write(&p, rows.join("\n")).unwrap();
        p.to_str().unwrap().to_string()
    };
    let flat = write("flat.txt", &["1e-9 1e-9 1e-9 1e-9"; 4]);
    let huge = write("huge.txt", &["1e200 0 -1e200 0", "0 0 0 0", "0 0 0 0", "0 0 0 0"]);
    let ok = write("ok.txt", &["1e-8 0 -1e-8 0", "0 0 0 0", "1e-8 0 -1e-8 0", "0 0 0 0"]);
    fails(
        &["gfmd", "--surface", &flat, "--size", "1e-6"],
        &["--surface = flat.txt: a flat map"],
    );
    fails(
        &["gfmd", "--surface", &huge, "--size", "1e-6"],
        &["--surface", "rms gradient"],
    );
    fails(
        &["gfmd", "--surface", &ok, "--size", "1e300"],
        &["--size = 1e300", "<= 1000"],
    );
    fails(
        &["gfmd", "--surface", &ok, "--size", "1"],
        &["--surface", "rms gradient"],
    );
    for f in [&flat, &huge, &ok] {
        let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
            .args(["gfmd", "--surface", f, "--size", "1e300"])
            .output()
            .unwrap();
        assert!(!String::from_utf8_lossy(&out.stderr).contains("--pressure"));
    }
    fails(&["gfmd", "--size", "1e-6"], &["missing --surface"]);
    fails(
        &["gfmd", "--grid", "32", "--seeds", "0"],
        &["--seeds = 0", "1 <= seeds"],
    );
    fails(
        &["gfmd", "--grid", "32", "--extrapolate", "--ladder", "8"],
        &["--ladder", "two or more"],
    );
    // a flag that would be ignored is refused: the ladder needs --extrapolate, the number of
    // loads a sweep, and a sweep or cycle runs on one map (no --seeds)
    // an unknown flag names the command whose --help lists the flags, not the flags given
    fails(
        &["run", "--format", "json", "--branch", "x"],
        &["'--branch'", "allowed the flags of `asperity run --help`"],
    );
    fails(&["gfmd", "--grid", "32", "--ladder", "4,8"], &["missing --extrapolate"]);
    fails(
        &["gauge", "--fit", "w0", "--reference", "gfmd", "--ladder", "4,8"],
        &["missing --extrapolate"],
    );
    fails(&["gfmd", "--grid", "32", "--points", "5"], &["missing --to, --from"]);
    fails(
        &["gfmd", "--grid", "32", "--from", "1e-3", "--to", "1e-2", "--seeds", "3"],
        &["--from", "--seeds"],
    );
    fails(
        &["gfmd", "--grid", "32", "--extrapolate", "--ladder", "1,8"],
        &["--ladder = 1", "<= lambda_s/da"],
    );
    // a sweep downwards unloads (gfmd --cycle); a cycle must turn above its start
    fails(
        &[
            "gfmd", "--grid", "32", "--from", "0.1", "--to", "0.01", "--points", "3", "--cycle",
        ],
        &["--to = 0.01", "turning load"],
    );
    let _ = std::fs::remove_dir_all(&dir);
}
