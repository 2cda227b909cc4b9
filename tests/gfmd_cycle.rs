//! GFMD through the load cycle (`asperity::gfmd::cycle`): without adhesion unloading retraces
//! loading (a unique minimum at every load) and no tension is held; with adhesion unloading
//! keeps at least as much contact as loading at every load, and the contact holds tension up
//! to a pull-off p* < 0 that the bracket encloses.

mod common;

use asperity::gfmd::cycle::{run_cycle, CycleSpec, GfmdCycle, PathBranch};
use asperity::gfmd::{GfmdOptions, GfmdSetup, GridSpec};
use asperity::tolerances::GFMD_RETRACE_A_R;
use std::sync::atomic::AtomicBool;

/// A 64² reduced grid (L/λ_r = 2, λ_r/λ_s = 4, λ_s/Δa = 8).
fn small() -> GridSpec {
    GridSpec {
        system_size_ratio: 2.0,
        bandwidth: 4.0,
        points_per_short_wavelength: 8.0,
    }
}

/// GFMD's load path `spec` on `scene`'s 64² map of seed `seed`, default options.
fn path_of(scene: asperity::input::scene::Scene, seed: u64, spec: &CycleSpec) -> GfmdCycle {
    let setup = GfmdSetup {
        scene,
        grid: small(),
        seed,
        surface: None,
        rescale: true,
    };
    run_cycle(
        &setup,
        spec,
        &GfmdOptions::default(),
        &mut |_, _| {},
        &AtomicBool::new(false),
    )
    .unwrap()
}

fn cycle(from: f64, to: f64, points: usize) -> CycleSpec {
    CycleSpec {
        from,
        to,
        points,
        cycle: true,
    }
}

#[test]
fn without_adhesion_unloading_retraces_loading() {
    for t in [f64::INFINITY, 0.5] {
        let scene = common::preset("system-2")
            .without_adhesion()
            .with_thickness_qr(t)
            .unwrap();
        let c = path_of(scene, 3, &cycle(0.005, 0.05, 4));
        let load: Vec<_> = c.rows.iter().filter(|r| r.branch == PathBranch::Loading).collect();
        let unload: Vec<_> = c.rows.iter().filter(|r| r.branch == PathBranch::Unloading).collect();
        assert_eq!(load.len(), 4);
        assert_eq!(unload.len(), 3, "t·q_r {t}: no tensile rows without adhesion");
        for u in &unload {
            let l = load.iter().find(|l| l.row.p == u.row.p).expect("same loads");
            assert!(
                (u.row.a_r - l.row.a_r).abs() <= GFMD_RETRACE_A_R,
                "t·q_r {t} p* {}: a_r {} unloading, {} loading",
                u.row.p,
                u.row.a_r,
                l.row.a_r
            );
            assert!((u.row.mean_gap_rel / l.row.mean_gap_rel - 1.0).abs() < 1e-4);
        }
        assert_eq!(c.pull_off_pressure, Some(0.0));
        assert!(c.note.as_deref().unwrap().contains("no adhesion"));
        assert!(c.theory.is_some());
    }
}

#[test]
fn with_adhesion_unloading_keeps_more_contact_and_pulls_off_under_tension() {
    for t in [f64::INFINITY, 0.3] {
        let scene = common::preset("system-2").with_thickness_qr(t).unwrap();
        let c = path_of(scene, 1, &cycle(0.002, 0.02, 3));
        let load: Vec<_> = c.rows.iter().filter(|r| r.branch == PathBranch::Loading).collect();
        for u in c.rows.iter().filter(|r| r.branch == PathBranch::Unloading) {
            if let Some(l) = load.iter().find(|l| l.row.p == u.row.p) {
                assert!(
                    u.row.a_r >= l.row.a_r,
                    "t·q_r {t} p* {}: {} < {}",
                    u.row.p,
                    u.row.a_r,
                    l.row.a_r
                );
            }
        }
        let pull_off = c.pull_off_pressure.expect("a pull-off");
        let [lost, held] = c.pull_off_bracket.expect("a bracket");
        assert!(pull_off < 0.0, "t·q_r {t}: pull-off {pull_off}");
        assert!(lost < held && held == pull_off, "t·q_r {t}: bracket {lost} {held}");
        // the bracket is a few per cent of the pull-off wide
        assert!((held - lost) < 0.1 * held.abs(), "t·q_r {t}: bracket {lost} {held}");
        // the most tensile row is the pull-off, and every tensile row holds contact
        let last = c.rows.last().unwrap();
        let most = c.rows.iter().map(|r| r.row.p).fold(f64::INFINITY, f64::min);
        assert_eq!(most, pull_off);
        assert!(last.row.a_r > 0.0);
        assert!(c.rows.iter().all(|r| r.row.a_r > 0.0 && r.row.mean_gap_rel.is_finite()));
    }
}

#[test]
fn a_plain_sweep_downwards_unloads() {
    let scene = common::preset("system-2");
    let spec = CycleSpec {
        from: 0.02,
        to: 0.002,
        points: 3,
        cycle: false,
    };
    let c = path_of(scene, 2, &spec);
    let ps: Vec<f64> = c.rows.iter().map(|r| r.row.p).collect();
    assert_eq!(ps.len(), 3);
    assert!(ps.windows(2).all(|w| w[1] < w[0]), "{ps:?}");
    assert_eq!(c.rows[0].branch, PathBranch::Loading);
    assert!(c.rows[1..].iter().all(|r| r.branch == PathBranch::Unloading));
    assert_eq!(c.pull_off_pressure, None);
}

#[test]
fn a_cycle_turning_below_its_start_is_refused() {
    let e = cycle(0.02, 0.01, 3).validate().unwrap_err();
    assert!(e.to_string().contains("turning load"), "{e}");
}

#[test]
fn the_theory_path_goes_up_on_loading_and_down_on_unloading() {
    use asperity::theory::cycle::path;
    use asperity::theory::engine::Options;
    use asperity::theory::sweep::{sweep, SweepSpec};
    // system II, model 3, t·q_r = 0.1, 0.8 γ_s: a hysteresis window from below 1e-6 to the
    // jump-in at p* ≈ 2.3e-4
    let scene = common::at(2, 3, 0.1, 0.1256, 1e-6);
    let spec = SweepSpec {
        from: 1e-6,
        to: 1e-2,
        points: 9,
    };
    let sw = sweep(&scene, &spec, &Options::default(), None).unwrap();
    let c = path(&sw);
    assert_eq!(c.rows.len(), 2 * 9 - 1);
    let (up, down) = c.rows.split_at(9);
    assert!(up
        .iter()
        .all(|r| r.branch == PathBranch::Loading && !r.on_unloading_branch));
    assert!(down.iter().all(|r| r.branch == PathBranch::Unloading));
    for d in down {
        let u = up.iter().find(|u| u.p == d.p).unwrap();
        assert!(d.a_r >= u.a_r, "p* {}: unloading {} < loading {}", d.p, d.a_r, u.a_r);
        // the unloading branch is the sweep's own where it exists
        let row = sw.rows.iter().find(|r| r.p == d.p).unwrap();
        assert_eq!(d.on_unloading_branch, row.a_r_unloading.is_finite());
    }
    assert!(down.iter().any(|d| d.on_unloading_branch), "a window at t·q_r = 0.1");
    assert!(c.jump_in_pressure.is_some_and(|p| p > 1e-4 && p < 1e-3));
    // the unloading branch reaches the smallest load: its pull-off is in tension
    assert!(c.note.contains("still exists"), "{}", c.note);
}
