//! asperity's own GFMD reference set (data/reference, docs/reference-set.md): a fast subset is
//! recomputed and must reproduce the stored values within their error bars. The subset is
//! one seed of one adhesive case (system II, half-space, the preset's γ_s: a load cycle on the
//! set's 256² grid), compared row by row with the stored rows of the same seed; each quantity
//! within the seed-to-seed standard error of the set at that load (or the floor of
//! [`REFERENCE_SET_FLOOR`] where the set has one seed), and the pull-off within its bracket.

use asperity::gfmd::cycle::{run_cycle, CycleSpec, PathBranch};
use asperity::gfmd::{GfmdOptions, GfmdSetup, GridSpec};
use asperity::input::preset::Preset;
use asperity::tolerances::{REFERENCE_SET_FLOOR, REFERENCE_SET_SE};
use std::collections::HashMap;
use std::sync::atomic::AtomicBool;

const GRID: usize = 256;
const RUNS: &str = include_str!("../data/reference/runs-256.csv");
const SET: &str = include_str!("../data/reference/reference-set-256.csv");
const SMALL_RUNS: &str = include_str!("../data/reference/runs-small-256.csv");

/// The rows of a CSV with a header, as maps from column to cell.
fn table(text: &str) -> Vec<HashMap<String, String>> {
    let mut lines = text.lines().filter(|l| !l.starts_with('#') && !l.trim().is_empty());
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    lines
        .map(|l| header.iter().cloned().zip(l.split(',').map(String::from)).collect())
        .collect()
}

fn num(row: &HashMap<String, String>, key: &str) -> Option<f64> {
    row.get(key).and_then(|s| s.parse().ok())
}

/// GFMD's path on system II at the preset's γ_s, the set's 256² reduction, map `seed`.
fn system2_path(seed: u64, spec: CycleSpec) -> asperity::gfmd::cycle::GfmdCycle {
    let preset = Preset::resolve("system-2").unwrap();
    let setup = GfmdSetup {
        scene: preset.scene().unwrap(),
        grid: GridSpec::from_preset(preset.gfmd.as_ref().unwrap())
            .with_grid(GRID)
            .unwrap(),
        seed,
        surface: None,
        rescale: true,
    };
    run_cycle(
        &setup,
        &spec,
        &GfmdOptions::default(),
        &mut |_, _| {},
        &AtomicBool::new(false),
    )
    .unwrap()
}

#[test]
fn a_subset_of_the_reference_set_is_reproduced_within_its_error_bars() {
    let (t, f, seed) = ("inf", "1", 1u64);
    let of_case =
        |r: &&HashMap<String, String>| r["system"] == "system-2" && r["thickness_qr"] == t && r["gamma_factor"] == f;
    let runs = table(RUNS);
    let stored: Vec<_> = runs
        .iter()
        .filter(of_case)
        .filter(|r| r["seed"] == seed.to_string())
        .collect();
    assert!(stored.len() > 10, "the stored case has {} rows", stored.len());
    let set = table(SET);
    let set: Vec<_> = set.iter().filter(of_case).collect();

    let c = system2_path(
        seed,
        CycleSpec {
            from: 1e-4,
            to: 1e-2,
            points: 7,
            cycle: true,
        },
    );

    let rows: Vec<_> = stored.iter().filter(|r| r["branch"] != "pull_off").collect();
    assert_eq!(c.rows.len(), rows.len(), "the path has as many loads as stored");
    for (got, want) in c.rows.iter().zip(&rows) {
        let branch = match got.branch {
            PathBranch::Loading => "loading",
            PathBranch::Unloading => "unloading",
        };
        let p = num(want, "p").unwrap();
        assert_eq!(branch, want["branch"]);
        assert!(
            (got.row.p - p).abs() <= 1e-9 * p.abs().max(1e-12),
            "{} against {p}",
            got.row.p
        );
        let bar = set
            .iter()
            .find(|s| s["branch"] == branch && num(s, "p").is_some_and(|q| (q - p).abs() <= 1e-9 * p.abs()));
        for (key, value) in [
            ("a_r", got.row.a_r),
            ("mean_gap_rel", got.row.mean_gap_rel),
            ("mean_contact_stress", got.row.mean_contact_stress),
        ] {
            let want_v = num(want, key).unwrap();
            let se = bar.and_then(|s| num(s, &format!("{key}_err"))).unwrap_or(0.0);
            let allowed = (REFERENCE_SET_SE * se).max(REFERENCE_SET_FLOOR * want_v.abs().max(1e-3));
            assert!(
                (value - want_v).abs() <= allowed,
                "{branch} p* {p:e} {key}: {value} against the stored {want_v} (allowed ±{allowed:e})"
            );
        }
    }
    let pull_off = stored
        .iter()
        .find(|r| r["branch"] == "pull_off")
        .map(|r| num(r, "p").unwrap());
    let (got, want) = (c.pull_off_pressure.unwrap(), pull_off.unwrap());
    let [lost, held] = c.pull_off_bracket.unwrap();
    assert!(
        (got - want).abs() <= (held - lost).abs(),
        "pull-off {got} against {want}"
    );
}

/// The small-load set's smallest loads are reproduced: one map (system II, half-space, the
/// preset's γ_s, seed 1) loaded from p* = 1e-5 to 1e-4 (the first four loads of its stored
/// cycle: the cycle's loading leg is this sweep), a_r and ū/h_rms within the floor of
/// [`REFERENCE_SET_FLOOR`] of the stored rows of the same seed.
#[test]
fn the_small_load_sets_smallest_loads_are_reproduced() {
    let runs = table(SMALL_RUNS);
    let stored: Vec<_> = runs
        .iter()
        .filter(|r| {
            r["system"] == "system-2"
                && r["thickness_qr"] == "inf"
                && r["gamma_factor"] == "1"
                && r["seed"] == "1"
                && r["branch"] == "loading"
        })
        .take(4)
        .collect();
    assert_eq!(stored.len(), 4);
    let c = system2_path(
        1,
        CycleSpec {
            from: 1e-5,
            to: 1e-4,
            points: 4,
            cycle: false,
        },
    );
    assert_eq!(c.rows.len(), 4);
    for (got, want) in c.rows.iter().zip(&stored) {
        let p = num(want, "p").unwrap();
        assert!((got.row.p / p - 1.0).abs() < 1e-9, "{} against {p}", got.row.p);
        for (key, value) in [("a_r", got.row.a_r), ("mean_gap_rel", got.row.mean_gap_rel)] {
            let want_v = num(want, key).unwrap();
            assert!(
                (value - want_v).abs() <= REFERENCE_SET_FLOOR * want_v.abs(),
                "p* {p:e} {key}: {value} against the stored {want_v}"
            );
        }
    }
}

mod trust {
    use super::{num, table};
    use asperity::fit::trust::assess;
    use asperity::input::preset::Preset;

    fn system2(t: f64, gamma: f64, p: f64) -> asperity::input::scene::Scene {
        Preset::resolve("system-2")
            .unwrap()
            .scene()
            .unwrap()
            .with_thickness_qr(t)
            .unwrap()
            .with_surface_energy_j_m2(gamma)
            .unwrap()
            .with_pressure(p)
            .unwrap()
    }

    /// The stored loading point of system II, half-space, the preset's γ_s at p* = 1e-3 in the
    /// set the read-out uses.
    fn stored_point() -> asperity::fit::reference_set::ReferencePoint {
        *asperity::fit::reference_set::combined_set()
            .iter()
            .find(|r| {
                r.system == 2
                    && r.thickness_qr.is_infinite()
                    && r.gamma_factor == 1.0
                    && r.branch == asperity::theory::cycle::PathBranch::Loading
                    && (r.p / 1e-3 - 1.0).abs() < 1e-9
            })
            .expect("the stored point")
    }

    #[test]
    fn at_a_stored_point_the_read_out_is_that_points_measured_error() {
        // the CSV row the library parsed, read here on its own
        let row = stored_point();
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/data/reference/small-load-256.csv"
        ))
        .unwrap();
        let csv = table(&text);
        let stored = csv
            .iter()
            .find(|r| {
                r["thickness_qr"] == "inf"
                    && r["gamma_factor"] == "1"
                    && r["branch"] == "loading"
                    && (num(r, "p").unwrap() / 1e-3 - 1.0).abs() < 1e-9
            })
            .expect("the small-load set's row");
        assert_eq!(row.a_r.0, num(stored, "a_r").unwrap());
        let tr = assess(&system2(f64::INFINITY, 0.157, row.p));
        assert!(tr.inside, "{:?}", tr.outside);
        assert!(tr.known, "{}", tr.summary);
        let first = tr.nearest[0];
        assert!(first.distance < 1e-3, "{first:?}");
        let want = (num(stored, "theory_a_r").unwrap() / num(stored, "a_r").unwrap())
            .ln()
            .abs();
        let got = first.log_error().abs();
        assert!((got - want).abs() < 1e-9, "{got} against {want}");
        assert_eq!(tr.measured_model, 4);
        assert!(tr.same_model);
        assert!(tr.a_r_worst_ratio >= (tr.a_r_log_error).exp() - 1e-12);
        assert!(tr.summary.starts_with("inside"), "{}", tr.summary);
    }

    #[test]
    fn model_5_reads_its_own_measured_error() {
        // the same stored point on the set's own bandwidth (the 256² reduction of the scene,
        // λ_r/λ_s = 16): the error of model 5's own column there
        let row = stored_point();
        let own = row.theory_models[4].0;
        let own = if own > 0.0 { own } else { row.theory5_a_r };
        let p = row.p;
        let preset = Preset::resolve("system-2").unwrap();
        let full = system2(f64::INFINITY, 0.157, p)
            .with_model(asperity::input::model::Model::named(5).unwrap())
            .unwrap();
        let grid = asperity::gfmd::GridSpec::from_preset(preset.gfmd.as_ref().unwrap())
            .with_grid(256)
            .unwrap();
        let (reduced, _) = asperity::gfmd::reduction::reduce(&full, &grid, true).unwrap();
        let tr = assess(&reduced);
        assert_eq!(tr.measured_model, 5, "{}", tr.summary);
        assert!(tr.same_model, "{}", tr.summary);
        let first = tr.nearest[0];
        assert!(first.distance < 1e-2, "{first:?}");
        assert!((first.a_r_theory / own - 1.0).abs() < 1e-9);
        // and it is not model 4's
        let m4 = assess(&system2(f64::INFINITY, 0.157, p));
        assert_ne!(m4.nearest[0].a_r_theory, first.a_r_theory);
        assert_eq!(m4.measured_model, 4);

        // the full system (λ_r/λ_s = 128) reads model 5 on the full system against the widest
        // GFMD of the bandwidth set (2048² for this case), a_r only; its theory is `run`'s
        let tr = assess(&full);
        assert_eq!(tr.measured_model, 5);
        assert!(tr.summary.contains("full system II"), "{}", tr.summary);
        let first = tr.nearest[0];
        assert!(first.distance < 1e-2, "{first:?}");
        let widest = asperity::fit::reference_set::bandwidth_set()
            .iter()
            .find(|r| {
                r.thickness_qr.is_infinite() && r.gamma_factor == 1.0 && r.grid == 2048 && (r.p / p - 1.0).abs() < 1e-9
            })
            .expect("the 2048² half-space point");
        assert!((first.a_r_gfmd / widest.a_r.0 - 1.0).abs() < 1e-12);
        let run = asperity::theory::engine::evaluate(&full, &asperity::theory::engine::Options::default()).unwrap();
        assert!(
            (first.a_r_theory / run.stats.a_r - 1.0).abs() < 1e-6,
            "{} against run's {}",
            first.a_r_theory,
            run.stats.a_r
        );
        assert!(tr.mean_gap_log_error.is_none());
    }

    #[test]
    fn outside_the_set_each_excess_is_named() {
        let tr = assess(&system2(f64::INFINITY, 0.157, 1e-7));
        assert!(!tr.inside);
        assert!(tr.outside[0].contains("2.0 decades below"), "{:?}", tr.outside);
        let tr = assess(&system2(0.05, 0.157, 1e-3));
        assert!(tr.outside.iter().any(|o| o.contains("thinner")), "{:?}", tr.outside);
        assert!(tr.summary.starts_with("outside"), "{}", tr.summary);
    }

    #[test]
    fn gfmds_pull_off_is_read_at_the_nearest_measured_case() {
        let tr = assess(&system2(0.3, 0.157, 1e-3));
        let po = tr.pull_off.expect("a measured case");
        assert!(po.distance < 1e-9, "{po:?}");
        assert_eq!((po.thickness_qr, po.gamma_factor), (Some(0.3), 1.0));
        let stored = asperity::fit::reference_set::small_load_pull_offs()
            .iter()
            .find(|r| r.thickness_qr == 0.3 && r.gamma_factor == 1.0)
            .expect("the stored case");
        assert_eq!(po.pull_off_pressure, stored.pressure.0);
        assert!(po.pull_off_pressure < 0.0);
        assert!(assess(&system2(0.3, 0.0, 1e-3)).pull_off.is_none());
    }

    #[test]
    fn far_from_every_stored_load_no_error_is_claimed() {
        // three decades below the set's smallest load: no case has a point within reach
        let tr = assess(&system2(f64::INFINITY, 0.157, 1e-8));
        assert!(!tr.known);
        assert!(tr.a_r_log_error.is_nan() && tr.a_r_band_ratio.is_nan());
        assert!(tr.summary.contains("no error known"), "{}", tr.summary);
        // at a stored load the band holds the case's own error and GFMD's standard error
        let tr = assess(&system2(0.3, 0.157, 1e-3));
        assert!(tr.known, "{}", tr.summary);
        let own = tr.nearest[0];
        assert!(own.distance < 1e-9, "{own:?}");
        assert!(tr.a_r_band_ratio.ln() >= own.log_error().abs() + 2.0 * own.a_r_rel_se - 1e-12);
    }
}
