//! The gauge workflow end to end: what `gfmd --format csv` writes (a load sweep, or a load
//! cycle with its `#` lines, unloading and tension rows) is a reference `gauge --reference`
//! reads as written, fitting the loading rows only; and gauge's output says why the fit
//! stopped in words, with no solver type names (`Converged { ftol: … }`).

mod common;

fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-gauge-workflow-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// `gfmd` on a 32² map of the sample preset, its CSV written to `path`; returns the CSV.
fn gfmd_csv(path: &std::path::Path, extra: &[&str]) -> String {
    let mut args = vec![
        "gfmd",
        "--preset",
        "data/samples/sample.toml",
        "--grid",
        "32",
        "--format",
        "csv",
        "--quiet",
    ];
    args.extend_from_slice(extra);
    let csv = common::asperity_ok(&args);
    std::fs::write(path, &csv).unwrap();
    csv
}

#[test]
fn a_gfmd_sweep_csv_is_a_reference_and_the_output_has_no_debug_text() {
    let dir = scratch("sweep");
    let path = dir.join("gfmd.csv");
    let csv = gfmd_csv(
        &path,
        &["--gamma", "0", "--from", "1e-3", "--to", "1e-1", "--points", "4"],
    );
    let rows = csv.lines().skip(1).count();
    let p = path.display().to_string();
    let base = [
        "gauge",
        "--preset",
        "data/samples/sample.toml",
        "--gamma",
        "0",
        "--model",
        "4",
        "--fit",
        "c1",
        "--reference",
        p.as_str(),
        "--observables",
        "a_r",
    ];
    let mut json = base.to_vec();
    json.extend(["--format", "json"]);
    let j = common::asperity_json(&json);
    assert_eq!(j["points"], rows, "one a_r point per converged GFMD row: {j}");
    let words = j["termination"].as_str().unwrap();
    assert!(words.starts_with("converged"), "{words}");
    let mut table = base.to_vec();
    table.extend(["--format", "table"]);
    let t = common::asperity_ok(&table);
    assert!(
        !t.contains(" { ") && !t.contains("ftol"),
        "solver type names in the table:\n{t}"
    );
}

#[test]
fn a_gfmd_cycle_csv_gives_its_loading_rows() {
    let dir = scratch("cycle");
    let path = dir.join("cycle.csv");
    let csv = gfmd_csv(&path, &["--cycle", "--from", "1e-3", "--to", "1e-2", "--points", "3"]);
    let loading = csv.lines().filter(|l| l.ends_with(",loading")).count();
    assert!(csv.lines().any(|l| l.ends_with(",unloading")), "{csv}");
    let p = path.display().to_string();
    let j = common::asperity_json(&[
        "gauge",
        "--preset",
        "data/samples/sample.toml",
        "--model",
        "4",
        "--fit",
        "c1",
        "--reference",
        &p,
        "--observables",
        "a_r",
        "--format",
        "json",
    ]);
    assert_eq!(j["points"], loading, "{j}");
}
