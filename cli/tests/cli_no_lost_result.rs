//! No silent or lost result: each case that once printed a wrong number, lost a result or
//! hid why it failed, as a regression test.

mod common;

use common::{asperity, asperity_json};

fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-lost-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn stderr_of(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn the_table_shows_a_small_contact_area_as_itself_not_zero() {
    let args = ["run", "--preset", "system-2", "--pressure", "1e-9"];
    let v = asperity_json(&args);
    let a_r = v["a_r"].as_f64().unwrap();
    assert!(a_r > 0.0 && a_r < 1e-4, "a_r {a_r}");
    let mut t = args.to_vec();
    t.extend(["--format", "table"]);
    let out = asperity(&t);
    let text = String::from_utf8_lossy(&out.stdout);
    let line = text.lines().find(|l| l.starts_with("a_r ")).expect("an a_r line");
    let shown: f64 = line.split_whitespace().nth(1).unwrap().parse().unwrap();
    // the table's value is the JSON's, to its printed digits
    assert!((shown / a_r - 1.0).abs() < 1e-6, "{line} against {a_r}");
    assert!(!line.contains("0.00000000"), "{line}");
}

#[test]
fn an_unconverged_result_says_why_in_json_table_and_exit_code() {
    // an adhesive thin slab at a tiny load with a tolerance tighter than the march reaches
    let base = [
        "run",
        "--preset",
        "system-2",
        "--pressure",
        "4e-9",
        "--thickness",
        "58",
        "--gamma",
        "11.8",
    ];
    let out = asperity(&base);
    let err = stderr_of(&out);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap_or_default();
    match v["converged"].as_bool() {
        Some(true) => {
            assert_eq!(out.status.code(), Some(0), "{err}");
            assert!(v.get("converged_note").is_none());
        }
        Some(false) => {
            let note = v["converged_note"].as_str().expect("a reason with converged: false");
            assert!(!note.is_empty() && !note.contains('\n'), "{note}");
            assert_eq!(out.status.code(), Some(asperity_cli::cli::EXIT_NOT_CONVERGED), "{err}");
            assert!(
                err.contains("not converged") && err.trim_end().lines().count() == 1,
                "{err}"
            );
            let mut t = base.to_vec();
            t.extend(["--format", "table"]);
            let table = String::from_utf8_lossy(&asperity(&t).stdout).into_owned();
            let line = table.lines().find(|l| l.starts_with("converged")).unwrap();
            assert!(line.contains("false: "), "{line}");
        }
        // or it fails in one line, with the reason
        None => {
            assert_eq!(out.status.code(), Some(2), "{err}");
            assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        }
    }
}

#[test]
fn psd_refuses_a_map_it_cannot_measure_like_run() {
    let dir = scratch("psd");
    let map = dir.join("huge.txt");
    std::fs::write(&map, "1e200 0 -1e200 0\n0 0 0 0\n0 1e200 0 0\n0 0 0 -1e200\n").unwrap();
    let m = map.to_str().unwrap();
    for args in [
        vec!["psd", m, "--size", "1e-6"],
        vec!["psd", m, "--size", "1e-6", "--format", "json"],
        vec!["run", "--surface", m, "--size", "1e-6"],
    ] {
        let out = asperity(&args);
        let err = stderr_of(&out);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains("huge.txt"), "{args:?}: {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_coarsest_scale_reports_numbers_not_null() {
    for p in ["1e-9", "1e-7", "1e-5"] {
        let v = asperity_json(&["run", "--preset", "system-2", "--pressure", p]);
        for key in ["gamma_q", "sigma_a_q"] {
            let a = v[key].as_array().unwrap();
            assert!(
                a.iter().all(|x| x.is_f64()),
                "p* {p}: {key} has null: {:?}",
                &a[..3.min(a.len())]
            );
        }
        let a = v["resolution"]["a_r"].as_array().unwrap();
        assert!(a.iter().all(|x| x.is_f64()), "p* {p}: resolution.a_r has null");
        // the coarsest scale is full contact: a_r(q_L) = 1
        assert_eq!(a[0].as_f64(), Some(1.0), "p* {p}");
    }
}

#[test]
fn the_system_2_point_gets_a_solution_or_a_reason() {
    let args = [
        "run",
        "--preset",
        "system-2",
        "--model",
        "4",
        "--thickness",
        "0.11858657076247323",
        "--gamma",
        "0.157",
        "--pressure",
        "3.5030939862794857e-07",
    ];
    let out = asperity(&args);
    let err = stderr_of(&out);
    match out.status.code() {
        Some(0) => {
            let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
            let a = v["a_r"].as_f64().unwrap();
            assert!((0.0..=1.0).contains(&a), "{a}");
        }
        Some(2) | Some(3) => {
            assert_eq!(err.trim_end().lines().count(), 1, "{err}");
            assert!(err.len() > 20, "{err}");
        }
        c => panic!("exit {c:?}: {err}"),
    }
}

#[test]
fn a_map_saved_by_gfmd_is_read_back_without_size() {
    let dir = scratch("map");
    let map = dir.join("saved.txt");
    let m = map.to_str().unwrap();
    let out = asperity(&["gfmd", "--preset", "system-1", "--grid", "32", "--save-surface", m]);
    assert!(out.status.success(), "{}", stderr_of(&out));
    let v = asperity_json(&["psd", m, "--periodic", "--format", "json"]);
    let g = asperity_json(&["gfmd", "--preset", "system-1", "--grid", "32"]);
    let size = v["system_size_m"].as_f64().unwrap();
    // the side the header states: 32 spacings of the saved grid
    let want = g["grid"]["system_size_m"]
        .as_f64()
        .or_else(|| g["system_size_m"].as_f64())
        .unwrap_or(size);
    assert!((size / want - 1.0).abs() < 1e-12, "{size} against {want}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn output_files_are_checked_before_any_work() {
    let dir = scratch("out");
    let d = dir.to_str().unwrap();
    let cases: Vec<Vec<&str>> = vec![
        vec![
            "gauge",
            "--preset",
            "system-2",
            "--fit",
            "w0",
            "--reference",
            "gfmd",
            "--png",
            "before-after",
        ],
        vec!["gauge", "--fit", "w0", "--reference", "eq18", "--svg", "x.png"],
        vec![
            "gauge",
            "--fit",
            "w0",
            "--reference",
            "eq18",
            "--save-preset",
            "/no/such/dir/x.toml",
        ],
        vec!["compare", "--reference", "eq18", "--png", d],
        vec!["compare", "--reference", "gfmd", "--models", "abc"],
        vec!["gfmd", "--grid", "32", "--save-surface", "/no/such/dir/map.txt"],
        vec!["psd", "tests/fixtures/two_bands.txt", "--svg", ""],
        vec!["figure", "3", "--png", "x.svg"],
    ];
    for args in cases {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_asperity"))
            .args(&args)
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .env(asperity_cli::cli::FORBID_WORK_ENV, "1")
            .output()
            .unwrap();
        let err = stderr_of(&out);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains("invalid --"), "{args:?}: {err}");
        assert!(!err.trim_end().ends_with("allowed"), "{args:?}: {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn polonsky_keer_on_a_slab_is_refused_before_any_step() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args([
            "gfmd",
            "--preset",
            "system-2",
            "--grid",
            "32",
            "--thickness",
            "1",
            "--method",
            "pk",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env(asperity_cli::cli::FORBID_WORK_ENV, "1")
        .output()
        .unwrap();
    let err = stderr_of(&out);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("--method = pk on a slab") && err.contains("fire"), "{err}");
}

#[test]
fn a_long_psd_table_is_resampled_once_with_a_line_saying_so() {
    use asperity::surface::spectrum::Spectrum;
    let dir = scratch("table");
    let scene = asperity::input::preset::Preset::resolve("system-1")
        .unwrap()
        .scene()
        .unwrap();
    let Spectrum::SelfAffine(sa) = scene.spectrum().clone() else {
        panic!("system-1 is self-affine")
    };
    let mut a_r = Vec::new();
    for rows in [1_000, 20_000] {
        let (q, c) = common::ideal_table(&sa, rows);
        let path = dir.join(format!("t{rows}.csv"));
        std::fs::write(&path, asperity::surface::tabulated::to_csv(&q, &c)).unwrap();
        let p = path.to_str().unwrap();
        let out = asperity(&["run", "--preset", "system-1", "--gamma", "0", "--psd", p]);
        let err = stderr_of(&out);
        assert!(out.status.success(), "{err}");
        assert_eq!(err.contains("resampled once"), rows > 4096, "{rows} rows: {err}");
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        a_r.push(v["a_r"].as_f64().unwrap());
    }
    let rel = (a_r[1] / a_r[0] - 1.0).abs();
    assert!(rel < asperity::tolerances::RESAMPLED_TABLE_REL, "{a_r:?}");
    let _ = std::fs::remove_dir_all(&dir);
}
