//! The public interface: the JSON keys of `run`, `sweep`, `gfmd`, `figure` and the bench report's rungs,
//! and the CSV columns of `sweep`, `gfmd` and `figure`, as first published. Scripts
//! depend on them: a change may add keys, never remove or rename one.

mod common;

use common::asperity_here_ok;
use std::collections::BTreeSet;

fn json(args: &[&str]) -> serde_json::Value {
    serde_json::from_str(&asperity_here_ok(args)).unwrap()
}

/// Dotted paths of every key of nested objects (arrays are not entered).
fn keys(v: &serde_json::Value, prefix: &str, out: &mut BTreeSet<String>) {
    if let Some(o) = v.as_object() {
        for (k, x) in o {
            let path = format!("{prefix}{k}");
            keys(x, &format!("{path}."), out);
            out.insert(path);
        }
    }
}

fn assert_has(v: &serde_json::Value, expected: &[&str], what: &str) {
    let mut got = BTreeSet::new();
    keys(v, "", &mut got);
    let missing: Vec<&&str> = expected.iter().filter(|k| !got.contains(**k)).collect();
    assert!(
        missing.is_empty(),
        "{what}: keys missing from the public interface: {missing:?}"
    );
}

const SCENE: &[&str] = &[
    "scene",
    "scene.alpha",
    "scene.c1",
    "scene.c2",
    "scene.contact_modulus_pa",
    "scene.gamma",
    "scene.gamma_glo",
    "scene.k_griffith",
    "scene.model",
    "scene.model_number",
    "scene.pressure",
    "scene.pressure_pa",
    "scene.q_l",
    "scene.q_r",
    "scene.q_s",
    "scene.range_m",
    "scene.rms_gradient",
    "scene.rms_height_m",
    "scene.semi_infinite",
    "scene.spectrum",
    "scene.spectrum_source",
    "scene.sigma_a_cap",
    "scene.tabor",
    "scene.thickness_m",
    "scene.thickness_qr",
];

const RUN: &[&str] = &[
    "a_r",
    "branch",
    "branches",
    "contact_stress_variance",
    "converged",
    "detached_fraction",
    "elapsed_gap_s",
    "elapsed_s",
    "elapsed_solve_s",
    "elapsed_window_s",
    "elastic_energy",
    "error_estimate",
    "gamma_q",
    "iterations",
    "jump_in_pressure",
    "mean_contact_stress",
    "mean_gap",
    "mean_gap_lower_rel",
    "mean_gap_rel",
    // the gap's bracket, error bar and what it is (docs/physics.md §5.1)
    "mean_gap_upper_rel",
    "mean_gap_error",
    "contact_load",
    "mean_gap_about",
    "pr",
    "pr.density",
    "pr.sigma",
    "preset",
    "pull_off_pressure",
    "residual",
    "resolution",
    "resolution.a_r",
    "resolution.q",
    "sigma_a",
    "sigma_a_q",
    "tensile_area",
    "unloading_a_r",
    // the preferred name of unloading_a_r (asperity::report::names)
    "a_r_unloading",
    "width",
];

#[test]
fn psd_keys_and_columns() {
    let map = "tests/fixtures/two_bands.txt";
    let v = json(&["psd", map, "--format", "json"]);
    assert_has(
        &v,
        &[
            "file",
            "points",
            "system_size_m",
            "rms_height_m",
            "rms_gradient",
            "rms_curvature",
            "hurst",
            "hurst_error",
            "rolloff_wavelength_m",
            "rolloff_wavelength_range_m",
            "short_wavelength_m",
            "short_wavelength_range_m",
            "self_affine",
            "line_scan",
            "window",
            "detrend",
            "elapsed_s",
            "table",
        ],
        "psd",
    );
    assert_has(&v["table"][0], &["q", "psd", "modes"], "psd table");
    assert!(asperity_here_ok(&["psd", map, "--format", "csv"]).starts_with("q,psd\n"));
}

#[test]
fn run_keys() {
    for gamma in ["0", "0.05"] {
        let v = json(&["run", "--preset", "system-1", "--gamma", gamma]);
        assert_has(&v, RUN, "run");
        assert_has(&v, SCENE, "run");
        assert_has(
            &v,
            &[
                "trust",
                "trust.inside",
                "trust.outside",
                "trust.set",
                "trust.nearest",
                "trust.measured_model",
                "trust.same_model",
                "trust.a_r_log_error",
                "trust.a_r_worst_ratio",
                "trust.a_r_band_ratio",
                "trust.known",
                "trust.finite_size_log_error",
                "trust.bandwidth_log_error",
                "trust.pull_off",
                "trust.mean_gap_log_error",
                "trust.summary",
            ],
            "run trust",
        );
        if gamma != "0" {
            assert_has(
                &v["branches"][0],
                &[
                    "a_r",
                    "branch",
                    "elastic_energy",
                    "gamma_coarse",
                    "residual",
                    "mean_gap_rel",
                    "mean_gap_reversible_rel",
                    "sigma_a",
                    "stable",
                    "mean_gap_lower_rel",
                    "mean_gap_upper_rel",
                    "mean_gap_error",
                    "contact_load",
                ],
                "run branches",
            );
        }
    }
}

#[test]
fn sweep_keys_and_columns() {
    let v = json(&[
        "sweep", "--preset", "system-1", "--from", "0.01", "--to", "0.1", "--points", "2", "--format", "json",
    ]);
    assert_has(
        &v,
        &[
            "evaluations",
            "failed_loads",
            "full_contact_pressure",
            "monotone",
            "preset",
            "rows",
            // the hysteresis window's edges
            "jump_in_pressure",
            "pull_off_pressure",
            "window_edges",
        ],
        "sweep",
    );
    assert_has(&v, SCENE, "sweep");
    assert_has(
        &v["rows"][0],
        &[
            "a_r",
            "converged",
            "elastic_energy",
            "elastic_energy_reduced",
            "mean_contact_stress",
            "mean_gap",
            "mean_gap_error",
            "mean_gap_rel",
            "p",
            // sweeps over any knob
            "contact_stress_variance",
            "a_r_over_p",
            "a_r_eq18",
            "thickness_qr",
            "gamma",
            // both branches
            "a_r_unloading",
            "branches",
            // the mean gap's lower bound
            "mean_gap_lower_rel",
            // the gap of each branch with its bracket (docs/physics.md §5.1)
            "mean_gap_upper_rel",
            "contact_load",
            "mean_gap_unloading_rel",
            "mean_gap_unloading_error",
            "mean_gap_unloading_lower_rel",
            "contact_load_unloading",
            "reason",
        ],
        "sweep rows",
    );
    assert_has(&v, &["over", "failed_values"], "sweep");
    let header = asperity_here_ok(&[
        "sweep", "--preset", "system-1", "--from", "0.01", "--to", "0.1", "--points", "2",
    ])
    .lines()
    .next()
    .unwrap_or("")
    .to_string();
    assert!(header.contains(",a_r_unloading,branches"), "{header}");
    assert!(
        header.contains(
            ",mean_gap_lower_rel,mean_gap_upper_rel,contact_load,mean_gap_unloading_rel,\
             mean_gap_unloading_error,mean_gap_unloading_lower_rel,contact_load_unloading"
        ),
        "{header}"
    );
    assert!(header.contains(",trust_inside,trust_a_r_log_error"), "{header}");
    // a failed row's one-line reason, last
    assert!(header.ends_with(",reason"), "{header}");
    assert!(
        header.starts_with(
            "p,a_r,mean_gap_rel,mean_gap,mean_contact_stress,elastic_energy,converged,elastic_energy_reduced,mean_gap_error,\
             contact_stress_variance,a_r_over_p,a_r_eq18,thickness_qr,gamma"
        ),
        "{header}"
    );
}

#[test]
fn gfmd_keys() {
    let v = json(&["gfmd", "--grid", "32"]);
    assert_has(
        &v,
        &[
            "a_r",
            "adhesion_resolution",
            "contact_nodes",
            "contact_stress_variance",
            "converged",
            "elapsed_s",
            "gamma",
            "grid",
            "grid_spec",
            "grid_spec.bandwidth",
            "grid_spec.points_per_short_wavelength",
            "grid_spec.system_size_ratio",
            "iterations",
            "mean_contact_stress",
            "mean_gap",
            "mean_gap_rel",
            "pr",
            "pr.density",
            "pr.sigma",
            "pressure",
            "pressure_pa",
            "range_m",
            "residual",
            "rms_gradient",
            "rms_height_m",
            "seed",
            "solve_elapsed_s",
            "spacing_m",
            "system_size_m",
            "theory",
            "theory.a_r",
            "theory.contact_stress_variance",
            "theory.mean_contact_stress",
            "theory.model",
            "theory.pr",
            "theory.pr.density",
            "theory.pr.sigma",
            "theory.width",
            "theory_elapsed_s",
            "theory_error",
            "thickness_qr",
            "tolerance",
            // GFMD's solver and timings
            "pk_iterations",
            "theory.mean_gap",
            "theory.mean_gap_rel",
            "reduction",
            "reduction.full",
            "reduction.full.pressure",
            "reduction.full.gamma_glo",
            "reduction.full.tabor",
            "reduction.full.thickness_qr",
            "reduction.full.system_size_ratio",
            "reduction.full.bandwidth",
            "reduction.full.tensile_stress",
            "reduction.full.gamma",
            "reduction.full.range_m",
            "reduction.reduced",
            "reduction.reduced.gamma_glo",
            "reduction.reduced.tabor",
            "reduction.rescaled",
            "reduction.gamma_scale",
            "reduction.range_scale",
            "reduction.adhesion_resolution",
            "reduction.kept",
            "reduction.not_kept",
        ],
        "gfmd",
    );
}

#[test]
fn gfmd_study_and_sweep_keys() {
    let v = json(&["gfmd", "--grid", "32", "--extrapolate", "--seeds", "2"]);
    assert_has(
        &v,
        &[
            "a_r",
            "reduction",
            "extrapolation",
            "extrapolation.seed",
            "extrapolation.rungs",
            "extrapolation.a_r",
            "extrapolation.a_r.limit",
            "extrapolation.a_r.error",
            "extrapolation.a_r.finest",
            "extrapolation.mean_contact_stress",
            "extrapolation.contact_stress_variance",
            "extrapolation.mean_gap_rel",
            "ensemble",
            "ensemble.seeds",
            "ensemble.extrapolated",
            "ensemble.a_r",
            "ensemble.a_r.mean",
            "ensemble.a_r.standard_error",
            "ensemble.a_r.values",
            "ensemble.mean_contact_stress",
            "ensemble.contact_stress_variance",
            "ensemble.mean_gap_rel",
            "ensemble.a_r_extrapolation_error",
            "ensemble.ladders",
        ],
        "gfmd --extrapolate --seeds",
    );
    let rung = &v["extrapolation"]["rungs"][0];
    assert_has(
        rung,
        &[
            "points_per_short_wavelength",
            "grid",
            "spacing_m",
            "a_r",
            "mean_contact_stress",
            "contact_stress_variance",
            "mean_gap_rel",
            "iterations",
            "solve_elapsed_s",
        ],
        "ladder rung",
    );
    let sw = json(&[
        "gfmd", "--grid", "32", "--gamma", "0", "--from", "0.01", "--to", "0.1", "--points", "2",
    ]);
    assert_has(
        &sw,
        &[
            "rows",
            "grid",
            "seed",
            "reduction",
            "theory",
            "theory.rows",
            "theory_error",
            "iterations",
            "elapsed_s",
        ],
        "gfmd sweep",
    );
    assert_has(
        &sw["rows"][0],
        &[
            "p",
            "a_r",
            "mean_gap_rel",
            "mean_gap",
            "mean_contact_stress",
            "elastic_energy",
            "converged",
            "contact_stress_variance",
            "iterations",
            "residual",
        ],
        "gfmd sweep row",
    );
}

/// `gfmd --format csv`: the same header for a single run and a sweep; sweep's column names
/// where GFMD measures the same quantity, then GFMD's own and the theory's on the same map.
#[test]
fn gfmd_csv_columns() {
    const COLUMNS: &str = "p,a_r,mean_gap_rel,mean_gap,mean_contact_stress,elastic_energy,converged,\
                           contact_stress_variance,iterations,residual,theory_a_r,theory_mean_gap_rel,\
                           theory_mean_contact_stress";
    let columns: Vec<&str> = COLUMNS.split(',').map(str::trim).collect();
    for args in [
        &["gfmd", "--grid", "32", "--gamma", "0", "--format", "csv"][..],
        &[
            "gfmd", "--grid", "32", "--gamma", "0", "--from", "0.01", "--to", "0.1", "--points", "2", "--format", "csv",
        ][..],
    ] {
        let text = asperity_here_ok(args);
        let mut lines = text.lines();
        let header: Vec<&str> = lines.next().unwrap_or("").split(',').collect();
        assert_eq!(header, columns, "{args:?}");
        let rows: Vec<&str> = lines.collect();
        assert!(!rows.is_empty(), "{args:?}: no rows");
        for row in rows {
            assert_eq!(row.split(',').count(), columns.len(), "{args:?}: {row}");
        }
    }
    assert_eq!(asperity_cli::cli::gfmd::GFMD_CSV_HEADER, columns.join(","));
    let sweep: Vec<&str> = asperity_cli::cli::sweep::CSV_HEADER.split(',').collect();
    for c in &columns[..8] {
        assert!(sweep.contains(c), "{c} is not a column of sweep");
    }
}

#[test]
fn bench_rung_keys() {
    let rung = asperity_cli::benchmark::Rung {
        solver: "s".into(),
        case: "c".into(),
        setting: "x".into(),
        default: true,
        median_s: 1.0,
        runs: 1,
        errors: vec![("a_r".into(), 1e-3)],
        bound: Some(1e-2),
        memory_bytes: None,
    };
    let v = serde_json::to_value(&rung).unwrap();
    assert_has(
        &v,
        &[
            "solver",
            "case",
            "setting",
            "default",
            "median_s",
            "runs",
            "errors",
            "bound",
            "memory_bytes",
        ],
        "bench rung",
    );
}

/// The explorer's names that files and fingers depend on: chart names (used by tour files),
/// the keys of the key table, the tour TOML keys (a tour using every key parses) and the
/// columns of the explorer's load CSV.
#[test]
fn explorer_names() {
    use asperity_cli::tui::base::keys::TABLE;
    use asperity_cli::tui::charts::ChartKind;
    use asperity_cli::tui::tour::Tour;
    let names: Vec<&str> = ChartKind::ALL.iter().map(|k| k.name()).collect();
    for n in [
        "pr",
        "pr-loglog",
        "area",
        "area-ratio",
        "thickness",
        "stress",
        "gap",
        "scales",
        "scales-area",
        "psd",
    ] {
        assert!(names.contains(&n), "chart {n} missing");
    }
    let labels: Vec<&str> = TABLE.iter().map(|b| b.label).collect();
    for l in [
        "m", "p", "r", "e", "a", "c", "g", "v", "f", "M", "t", "s", "[", "]", "Space",
    ] {
        assert!(labels.contains(&l), "key {l} missing");
    }
    let every_key = r#"name = "n"
title = "t"
preset = "system-1"
[[step]]
title = "s"
preset = "system-2"
model = 4
pressure = 0.005
thickness_qr = 1.0
gamma = 0.0
charts = ["pr", "thickness", "gap"]
models = true
caption = "a\nb"
"#;
    Tour::parse(every_key, "every-key").unwrap();
    let dir = std::env::temp_dir().join(format!("asperity-keys-export-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut app = asperity_cli::tui::app::App::new(
        "system-1",
        asperity::input::preset::Preset::resolve("system-1").unwrap(),
    )
    .unwrap();
    app.jobs.export_dir = dir.clone();
    asperity_cli::tui::drive::compute_now(&mut app, &mut Default::default());
    let paths = asperity_cli::tui::effects::export::export(&app).unwrap();
    let csv = std::fs::read_to_string(paths.iter().find(|p| p.ends_with("-loads.csv")).unwrap()).unwrap();
    let header = csv.lines().find(|l| !l.starts_with('#')).unwrap();
    for col in ["p", "a_r", "mean_gap_rel", "mean_contact_stress", "converged"] {
        assert!(header.split(',').any(|c| c == col), "column {col} missing: {header}");
    }
    app.set_charts([ChartKind::Scales, ChartKind::ScalesArea, ChartKind::Area]);
    asperity_cli::tui::drive::compute_now(&mut app, &mut Default::default());
    let paths = asperity_cli::tui::effects::export::export(&app).unwrap();
    let csv = std::fs::read_to_string(paths.iter().find(|p| p.ends_with("-scales.csv")).unwrap()).unwrap();
    let header = csv.lines().find(|l| !l.starts_with('#')).unwrap();
    assert_eq!(header, "frame,q_over_q_l,a_r_q,sigma_a_q,sigma,density");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The keys of every object in the array at `key`.
fn element_keys(v: &serde_json::Value, key: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for e in v[key].as_array().unwrap_or_else(|| panic!("{key} is not an array")) {
        keys(e, "", &mut out);
    }
    out
}

#[test]
fn gauge_and_compare_keys() {
    let v = json(&[
        "gauge",
        "--model",
        "1",
        "--fit",
        "c1,c2",
        "--reference",
        "eq18",
        "--points",
        "9",
        "--format",
        "json",
    ]);
    assert_has(
        &v,
        &[
            "reference",
            "params",
            "correlation",
            "condition_number",
            "residuals",
            "chi2",
            "chi2_reduced",
            "points",
            "evaluations",
            "termination",
            "model",
            "model.c1",
            "model.c2",
            "model.alpha",
            "model.k_griffith",
            "model.cap",
            "start",
            "elapsed_s",
            "saved_preset",
            "gfmd",
        ],
        "gauge",
    );
    for k in ["name", "value", "std_error", "start"] {
        assert!(element_keys(&v, "params").contains(k), "gauge params.{k}");
    }
    for k in ["observable", "points", "rms", "max_abs", "rms_start"] {
        assert!(element_keys(&v, "residuals").contains(k), "gauge residuals.{k}");
    }
    let v = json(&[
        "compare",
        "--reference",
        "eq18",
        "--points",
        "5",
        "--models",
        "3,xu24",
        "--format",
        "json",
    ]);
    assert_has(&v, &["reference", "models"], "compare");
    let m = element_keys(&v, "models");
    for k in ["model", "scores"] {
        assert!(m.contains(k), "compare models.{k}");
    }
    let s = element_keys(&v["models"][0], "scores");
    for k in ["observable", "points", "mean", "max"] {
        assert!(s.contains(k), "compare scores.{k}");
    }
}

#[test]
fn gauge_gfmd_reference_keys() {
    let v = json(&[
        "gauge",
        "--preset",
        "system-2",
        "--gamma",
        "0",
        "--fit",
        "w0",
        "--reference",
        "gfmd",
        "--grid",
        "32",
        "--points",
        "2",
        "--format",
        "json",
    ]);
    assert_has(
        &v,
        &[
            "gfmd.grid",
            "gfmd.seeds",
            "gfmd.ladder",
            "gfmd.rows",
            "gfmd.reduction",
            "gfmd.iterations",
            "gfmd.elapsed_s",
        ],
        "gauge --reference gfmd",
    );
    let r = element_keys(&v["gfmd"], "rows");
    for k in [
        "p",
        "a_r",
        "a_r_err",
        "mean_contact_stress",
        "mean_contact_stress_err",
        "mean_gap_rel",
        "mean_gap_rel_err",
    ] {
        assert!(r.contains(k), "gauge gfmd.rows.{k}");
    }
}

#[test]
fn figure_keys_and_columns() {
    let v = json(&["figure", "2", "--format", "json", "--points", "5"]);
    assert_has(
        &v,
        &[
            "id", "title", "preset", "x_label", "y_label", "x_log", "y_log", "series", "notes",
        ],
        "figure",
    );
    assert!(element_keys(&v, "series").is_superset(&["name", "points", "style"].map(String::from).into()));
    let points = element_keys(&v["series"][0], "points");
    assert!(points.is_superset(&["x", "y"].map(String::from).into()), "{points:?}");
    // on a measured surface the figure names it
    let w = json(&[
        "figure",
        "2",
        "--format",
        "json",
        "--points",
        "5",
        "--surface",
        "tests/fixtures/two_bands.txt",
        "--periodic",
    ]);
    assert_has(&w, &["spectrum_source"], "figure --surface");
    let csv = asperity_here_ok(&["figure", "2", "--format", "csv", "--points", "5"]);
    assert_eq!(csv.lines().next(), Some("series,x,y,note"));
}

/// `gfmd --cycle`: the sweep's keys, each row's `branch`, the pull-off and the jump-in; the
/// CSV has the sweep's columns then `branch`, after `#` lines.
#[test]
fn gfmd_cycle_keys_and_columns() {
    let args = [
        "gfmd", "--grid", "32", "--from", "0.005", "--to", "0.02", "--points", "2", "--cycle",
    ];
    let c = json(&args);
    assert_has(
        &c,
        &[
            "rows",
            "pull_off_pressure",
            "pull_off_bracket",
            "jump_in_pressure",
            "jump_in_bracket",
            "note",
            "grid",
            "seed",
            "reduction",
            "theory",
            "theory_cycle",
            "theory_cycle.pull_off_pressure",
            "theory_cycle.pull_off_bracket",
            "theory_cycle.tension_bound",
            "theory_cycle.note",
            "theory_error",
            "iterations",
            "elapsed_s",
        ],
        "gfmd --cycle",
    );
    assert_has(
        &c["rows"][0],
        &[
            "branch",
            "p",
            "a_r",
            "mean_gap_rel",
            "mean_contact_stress",
            "contact_stress_variance",
            "residual",
        ],
        "gfmd --cycle row",
    );
    let text = asperity_here_ok(&[&args[..], &["--format", "csv"]].concat());
    let header = text.lines().find(|l| !l.starts_with('#')).unwrap();
    assert_eq!(header, format!("{},branch", asperity_cli::cli::gfmd::GFMD_CSV_HEADER));
    assert!(text.contains("# pull_off_pressure: "), "{text}");
    assert!(text.contains("# theory_pull_off_pressure: "), "{text}");
    // the theory's path beside it has the rows of `sweep --cycle`
    assert_has(
        &c["theory_cycle"]["rows"][0],
        &["branch", "p", "a_r", "on_unloading_branch", "a_r_unloading_pinned"],
        "gfmd --cycle theory_cycle row",
    );
}

/// `sweep --cycle`: the load sweep's keys and `cycle` (rows with `branch`); the CSV's columns.
#[test]
fn sweep_cycle_keys_and_columns() {
    let args = [
        "sweep", "--preset", "system-2", "--from", "0.001", "--to", "0.01", "--points", "3", "--cycle",
    ];
    let mut json_args = args.to_vec();
    json_args.extend(["--format", "json"]);
    let v = json(&json_args);
    assert_has(
        &v,
        &[
            "rows",
            "pull_off_pressure",
            "jump_in_pressure",
            "cycle",
            "cycle.rows",
            "cycle.note",
            "cycle.unloading_branch_ends",
            "cycle.pull_off_pressure",
            "cycle.pull_off_bracket",
            "cycle.tension_bound",
        ],
        "sweep --cycle",
    );
    assert_has(
        &v["cycle"]["rows"][0],
        &[
            "branch",
            "p",
            "a_r",
            "mean_gap_rel",
            "mean_contact_stress",
            "on_unloading_branch",
            "a_r_unloading_pinned",
        ],
        "sweep --cycle row",
    );
    let text = asperity_here_ok(&args);
    let header = text.lines().find(|l| !l.starts_with('#')).unwrap();
    assert_eq!(header, asperity_cli::cli::sweep::CYCLE_CSV_HEADER);
    assert_eq!(text.lines().filter(|l| !l.starts_with('#')).count(), 1 + 5);
}

/// The pull-off read-out's keys: `run --pull-off` adds `pull_off`; `sweep --cycle` carries it
/// beside its cycle (and in its CSV's `#` lines).
#[test]
fn pull_off_read_out_keys() {
    const PULL_OFF: &[&str] = &[
        "pull_off_pressure",
        "pull_off_bracket",
        "tension_bound",
        "bam_pull_off_pressure",
        "gap_dmt_pull_off_pressure",
        "gfmd",
        "trust",
        "trust.known",
        "trust.measured_model",
        "trust.cases",
        "trust.theory_ratio",
        "trust.bam_ratio",
        "trust.gap_dmt_ratio",
        "trust.bracketed",
        "trust.summary",
        "notes",
        "estimate",
        "estimate.pull_off_pressure",
        "estimate.band",
        "estimate.band_factor",
        "estimate.band_coverage",
        "estimate.band_held",
        "estimate.coefficients",
        "estimate.held_out",
        "estimate.held_out.cases",
        "estimate.held_out.mean_abs_ln",
        "estimate.held_out.worst_factor",
        "estimate.held_out.within_1_5",
        "estimate.outside",
        "estimate.summary",
    ];
    let run = json(&["run", "--preset", "system-2", "--thickness", "0.3", "--pull-off"]);
    assert_has(&run["pull_off"], PULL_OFF, "run --pull-off");
    assert_has(
        &run["pull_off"]["trust"]["cases"][0],
        &[
            "thickness_qr",
            "gamma_factor",
            "gamma_glo",
            "gfmd",
            "gfmd_err",
            "theory_ratio",
            "bam_ratio",
            "gap_dmt_ratio",
            "distance",
        ],
        "run --pull-off case",
    );
    assert!(json(&["run", "--preset", "system-2"]).get("pull_off").is_none());
    let cycle = [
        "sweep",
        "--preset",
        "system-2",
        "--thickness",
        "0.3",
        "--cycle",
        "--from",
        "1e-3",
        "--to",
        "1e-2",
        "--points",
        "2",
        "--format",
    ];
    let sweep = json(&[&cycle[..], &["json"]].concat());
    assert_has(&sweep["pull_off"], PULL_OFF, "sweep --cycle");
    let csv = asperity_here_ok(&[&cycle[..], &["csv"]].concat());
    for line in [
        "# bam_pull_off_pressure: -",
        "# gap_dmt_pull_off_pressure: -",
        "# gfmd_pull_off_pressure: -",
        "# pull_off_trust: ",
        "# pull_off_estimate: -",
        "# pull_off_estimate_summary: gauged estimate -",
    ] {
        assert!(csv.contains(line), "{line} in\n{csv}");
    }
}
