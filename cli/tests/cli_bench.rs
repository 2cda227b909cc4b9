//! `asperity bench --quick` runs in CI and fails if a default setting exceeds its error bound.

#[test]
fn bench_quick_passes_its_error_bounds() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(["bench", "--quick"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("### adhesionless theory"));
    assert!(stdout.contains("**yes**"), "default rungs are marked");
    assert!(!stdout.contains("FAILED"));
}
