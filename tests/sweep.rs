//! Load sweeps: rows, shared U table, refinement error, cancellation, adhesion hook,
//! validation and the `sweep` / `run` command lines.

mod common;

use asperity::error::Field;
use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::theory::engine::{self, Options};
use asperity::theory::gap;
use asperity::theory::sweep::{self, SweepSpec};
use asperity::tolerances::*;
use asperity::Error;

use std::sync::atomic::AtomicBool;

/// The sweep of `points` log-spaced loads from p* = `from` to `to`.
fn loads(from: f64, to: f64, points: usize) -> SweepSpec {
    SweepSpec { from, to, points }
}

fn system1(n: u8) -> Scene {
    common::dry(1, Model::named(n).unwrap())
}

/// System 2, model 3, t·q_r = 0.1, 0.8 γ_s, and a sweep 1e-6…1e-3 that holds its hysteresis
/// window's jump-in (three branches from below 1e-6 up to ~2.3e-4).
fn thin_slab_window() -> (Scene, SweepSpec) {
    let mut s = Preset::resolve("system-2").unwrap().scene().unwrap();
    s.set_model(Model::named(3).unwrap()).unwrap();
    s.set_thickness_qr(0.1).unwrap();
    s.set_surface_energy_j_m2(s.surface_energy_j_m2() * 0.8).unwrap();
    let spec = loads(1e-6, 1e-3, 14);
    (s, spec)
}

/// The row's load evaluated on its own with `opts`, after checking the row's a_r against it
/// to `tol` (relative) and its branch count.
fn scanned_row(s: &Scene, r: &sweep::SweepRow, opts: &Options, tol: f64) -> engine::Evaluation {
    let mut one = s.clone();
    one.set_pressure(r.p).unwrap();
    let ev = engine::evaluate(&one, opts).unwrap();
    assert!(
        (r.a_r / ev.stats.a_r - 1.0).abs() < tol,
        "p* {}: {} vs {}",
        r.p,
        r.a_r,
        ev.stats.a_r
    );
    assert_eq!(r.branches, ev.branches.len().max(1), "p* {}", r.p);
    ev
}

/// `f` on a pool of `threads` threads.
fn on_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(f)
}

#[test]
fn rows_match_single_evaluations() {
    let s = system1(3);
    let spec = loads(1e-3, 1.0, 64);
    let sw = sweep::sweep(&s, &spec, &Options::default(), None).unwrap();
    assert_eq!(sw.rows.len(), 64);
    // spacing 0.11 in ln p*: no refinement, only the extension to full contact
    assert!(sw.evaluations < 64 + 20, "{}", sw.evaluations);
    let h_rms = s.spectrum().rms_height();
    for (r, p) in sw.rows.iter().zip(spec.pressures()) {
        assert_eq!(r.p, p);
        assert!((r.mean_gap - r.mean_gap_rel * h_rms).abs() < 1e-18);
    }
    for k in [0, 31, 63] {
        let mut one = s.clone();
        one.set_pressure(sw.rows[k].p).unwrap();
        // a sweep evaluates its loads at the energy route's tolerance
        let mut tight = Options::default();
        tight.accuracy.rtol = gap::ENERGY_RTOL;
        let ev = engine::evaluate(&one, &tight).unwrap();
        assert_eq!(ev.stats.a_r, sw.rows[k].a_r);
        assert_eq!(ev.elastic_energy, sw.rows[k].elastic_energy);
        assert!((ev.stats.mean_contact_stress - sw.rows[k].mean_contact_stress).abs() < 1e-14);
        // the single-load gap (its own grid, step 0.1) agrees within the two error estimates
        let g = gap::mean_gap(&one, &Options::default()).unwrap();
        let tol = 3.0 * (g.error + sw.rows[k].mean_gap_error) + 1e-12;
        assert!(
            (g.relative - sw.rows[k].mean_gap_rel).abs() < tol,
            "{k}: {g:?} vs {:?}",
            sw.rows[k]
        );
    }
}

#[test]
fn sixty_four_points_against_four_times_finer() {
    for n in [1, 3] {
        let s = system1(n);
        let coarse = loads(1e-3, 1.0, 64);
        let fine = SweepSpec { points: 253, ..coarse };
        let a = sweep::sweep(&s, &coarse, &Options::default(), None).unwrap();
        let b = sweep::sweep(&s, &fine, &Options::default(), None).unwrap();
        for (k, r) in a.rows.iter().enumerate() {
            let f = &b.rows[4 * k];
            assert!(((r.p - f.p) / r.p).abs() < 1e-12);
            if f.mean_gap_rel > 1e-3 {
                let rel = ((r.mean_gap_rel - f.mean_gap_rel) / f.mean_gap_rel).abs();
                assert!(rel < SWEEP_REFINEMENT_REL, "model {n} p* = {}: rel {rel:.1e}", r.p);
            }
        }
    }
}

#[test]
fn cancellation_and_validation() {
    let s = system1(1);
    let spec = loads(1e-3, 1.0, 16);
    let stop = AtomicBool::new(true);
    assert_eq!(
        sweep::sweep(&s, &spec, &Options::default(), Some(&stop)),
        Err(Error::Cancelled)
    );
    for (bad, field) in [
        (SweepSpec { from: 0.0, ..spec }, Field::SweepFrom),
        (SweepSpec { to: 1e-4, ..spec }, Field::SweepTo),
        (SweepSpec { points: 0, ..spec }, Field::SweepPoints),
        (SweepSpec { to: f64::NAN, ..spec }, Field::SweepTo),
    ] {
        let e = sweep::sweep(&s, &bad, &Options::default(), None).unwrap_err();
        assert_eq!(e.invalid_field(), Some(&field), "{e}");
        assert!(e.to_string().contains(field.key()), "{e}");
    }
    // one point
    let one = sweep::sweep(&s, &SweepSpec { points: 1, ..spec }, &Options::default(), None).unwrap();
    assert_eq!(one.rows.len(), 1);
    assert!(one.rows[0].mean_gap_rel > 0.0);
}

#[test]
fn adhesive_sweep_is_clean() {
    // An adhesive sweep (continuation from the neighbouring load) gives finite, converged rows
    // and flags any non-monotone stretch (an adhesive jump).
    for t in [f64::INFINITY, 0.05] {
        let mut s = Preset::resolve("system-2").unwrap().scene().unwrap();
        s.set_thickness_qr(t).unwrap();
        assert!(s.surface_energy_j_m2() > 0.0);
        let spec = loads(1e-4, 1.0, 32);
        match sweep::sweep(&s, &spec, &Options::default(), None) {
            Err(e) => panic!("t = {t}: {e}"),
            Ok(sw) => {
                for r in &sw.rows {
                    assert!(r.a_r.is_finite() && r.elastic_energy.is_finite());
                    assert!(r.converged);
                    // ū is admissible (≥ 0, docs/physics.md §5.1), or missing with a note
                    if r.mean_gap_rel.is_finite() {
                        assert!(r.mean_gap_rel >= 0.0, "t = {t}: {r:?}");
                    } else {
                        assert!(sw.note.is_some(), "t = {t}: {r:?}");
                    }
                }
                // every load converged: every gap is known (the thin slab's too, since the
                // gap from the stored energy is never negative)
                assert!(sw.rows.iter().all(|r| r.mean_gap_rel.is_finite()), "{:?}", sw.note);
                let gaps_fall = |a: f64, b: f64| !a.is_finite() || !b.is_finite() || b <= a;
                let mono = sw
                    .rows
                    .windows(2)
                    .all(|w| w[1].a_r >= w[0].a_r && gaps_fall(w[0].mean_gap_rel, w[1].mean_gap_rel));
                assert_eq!(mono, sw.monotone);
            }
        }
    }
}

#[test]
fn adhesive_sweeps_do_not_depend_on_the_thread_count() {
    // 40 loads (three continuation chunks) on one and on two threads give
    // the same numbers bit for bit
    let s = Preset::resolve("system-1").unwrap().scene().unwrap();
    assert!(s.surface_energy_j_m2() > 0.0);
    let spec = loads(1e-3, 0.3, 40);
    let opts = Options::chart();
    let on = |threads: usize| on_threads(threads, || sweep::sweep(&s, &spec, &opts, None).unwrap());
    let (one, two) = (on(1), on(2));
    assert!(one.failed_loads.is_empty());
    for (a, b) in one.rows.iter().zip(&two.rows) {
        assert_eq!(a.a_r.to_bits(), b.a_r.to_bits(), "p* {}", a.p);
        assert_eq!(a.mean_gap_rel.to_bits(), b.mean_gap_rel.to_bits(), "p* {}", a.p);
        assert_eq!(a.elastic_energy.to_bits(), b.elastic_energy.to_bits(), "p* {}", a.p);
    }
}

#[test]
fn window_sweeps_do_not_depend_on_the_thread_count() {
    // a hysteresis window (system 2, model 3, t·q_r = 0.1, 0.8 γ_s): loads tracked across
    // its edge from the anchor with more branches, the jump-in aimed by pairs of solves side
    // by side (theory::window); one and two threads give the same bits
    let (s, spec) = thin_slab_window();
    let opts = Options::chart();
    let on = |threads: usize| on_threads(threads, || sweep::sweep(&s, &spec, &opts, None).unwrap());
    let (one, two) = (on(1), on(2));
    let bits = |p: Option<f64>| p.map(f64::to_bits);
    assert!(one.jump_in_pressure.is_some());
    assert_eq!(bits(one.jump_in_pressure), bits(two.jump_in_pressure));
    for (a, b) in one.rows.iter().zip(&two.rows) {
        assert_eq!(a.branches, b.branches, "p* {}", a.p);
        assert_eq!(a.a_r.to_bits(), b.a_r.to_bits(), "p* {}", a.p);
        assert_eq!(a.a_r_unloading.to_bits(), b.a_r_unloading.to_bits(), "p* {}", a.p);
        assert_eq!(a.mean_gap_rel.to_bits(), b.mean_gap_rel.to_bits(), "p* {}", a.p);
    }
}

#[test]
fn tracked_loads_agree_with_full_scans() {
    // a sweep scans every branch only at every ANCHOR_STRIDE-th load and tracks the root in
    // between (64 loads in about a second); every row against its own full scan
    let mut s = Preset::resolve("system-2").unwrap().scene().unwrap();
    s.set_model(Model::named(4).unwrap()).unwrap();
    s.set_thickness_qr(0.1).unwrap();
    let spec = loads(1e-5, 1.0, 16);
    let mut opts = Options::default();
    let sw = sweep::sweep(&s, &spec, &opts, None).unwrap();
    opts.accuracy.rtol = gap::ENERGY_RTOL;
    opts.adhesion_error_estimate = false;
    let rel = |a: f64, b: f64| (a / b - 1.0).abs();
    for r in &sw.rows {
        let ev = scanned_row(&s, r, &opts, TRACKED_VS_SCANNED_REL);
        assert!(
            rel(r.elastic_energy, ev.elastic_energy) < TRACKED_VS_SCANNED_ENERGY_REL,
            "p* {}: {} vs {}",
            r.p,
            r.elastic_energy,
            ev.elastic_energy
        );
    }
}

#[test]
fn tracked_loads_inside_a_window_agree_with_full_scans() {
    // inside a hysteresis window (system 2, model 3, t·q_r = 0.1, 0.8 γ_s: three branches
    // from below 1e-6 up to the jump-in at ~2.3e-4) the loads between anchors track three
    // roots each, from C interpolated towards the next anchor (adhesion::solve_continued);
    // every row against its own full scan at the same (chart) accuracy: both stable branches
    // and the branch count, and the jump-in marked between the last row with three and the
    // first with one
    let (s, spec) = thin_slab_window();
    let opts = Options::chart();
    let sw = sweep::sweep(&s, &spec, &opts, None).unwrap();
    let mut scan = opts;
    scan.accuracy.rtol = gap::ENERGY_RTOL;
    scan.adhesion.explore_branches = true;
    let rel = |a: f64, b: f64| (a / b - 1.0).abs();
    for r in &sw.rows {
        let ev = scanned_row(&s, r, &scan, TRACKED_VS_SCANNED_REL);
        match ev.unloading_a_r {
            Some(u) => assert!(
                rel(r.a_r_unloading, u) < TRACKED_VS_SCANNED_REL,
                "p* {}: {} vs {u}",
                r.p,
                r.a_r_unloading
            ),
            None => assert!(r.a_r_unloading.is_nan(), "p* {}", r.p),
        }
    }
    assert!(sw.rows[0].branches == 3 && sw.rows[13].branches == 1, "{:?}", sw.rows);
    let jump = sw.jump_in_pressure.expect("the jump-in lies in the range");
    let last3 = sw.rows.iter().rposition(|r| r.branches == 3).unwrap();
    assert!(
        sw.rows[last3].p < jump && jump < sw.rows[last3 + 1].p,
        "{jump} {:?}",
        sw.rows
    );
    // the edge (aimed by the fold's normal form, theory::window) to its precision: full scans
    // one edge_rel either side find two stable branches below and one above
    let stable = |p: f64| asperity::theory::window::stable_branches(&s, p, &opts.adhesion, None).unwrap();
    let step = opts.edge_rel.exp();
    assert_eq!(stable(jump / step), 2, "below {jump}");
    assert_eq!(stable(jump * step), 1, "above {jump}");
}

#[test]
fn run_and_sweep_agree_at_small_loads_on_a_thin_slab() {
    // system 2 without adhesion, model 3, t·q_r = 0.1, p* = 1e-7 (an ODE at
    // rtol 1e-7 stepped from q_L to q_r in one go has a cubic interpolant that dips below
    // zero: a_r(q) = 1 over a band of q and U three times too high)
    let mut s = Preset::resolve("system-2").unwrap().scene().unwrap();
    s = s.without_adhesion();
    s.set_model(Model::named(3).unwrap()).unwrap();
    s.set_thickness_qr(0.1).unwrap();
    for p in [1e-7, 1e-5] {
        s.set_pressure(p).unwrap();
        let ev = engine::evaluate(&s, &Options::default()).unwrap();
        let sw = sweep::sweep(&s, &loads(p, p, 1), &Options::default(), None).unwrap();
        let rel = |a: f64, b: f64| (a / b - 1.0).abs();
        assert!(
            rel(ev.elastic_energy, sw.rows[0].elastic_energy) < RUN_SWEEP_REL,
            "p* {p}: run {} vs sweep {}",
            ev.elastic_energy,
            sw.rows[0].elastic_energy
        );
        assert!(rel(ev.stats.a_r, sw.rows[0].a_r) < RUN_SWEEP_REL);
        // a_r(q) never rises with the resolution
        for w in ev.resolution.windows(2) {
            assert!(w[1].a_r <= w[0].a_r, "p* {p}: a_r rises at q = {:.4e}", w[1].q);
        }
        // converged: U from an ODE solved at rtol 1e-13 (100x finer than the engine's)
        let fine = asperity::theory::persson::solve(
            &s,
            &asperity::theory::persson::Accuracy {
                rtol: 1e-13,
                ..Default::default()
            },
        )
        .unwrap();
        let u = asperity::theory::energy::elastic_energy(&s, |q| fine.area_at(q));
        eprintln!("p* {p}: U {} vs {u} at rtol 1e-13", ev.elastic_energy);
        assert!(
            rel(ev.elastic_energy, u) < THIN_SLAB_SMALL_LOAD_ENERGY_REL,
            "p* {p}: {} vs {u}",
            ev.elastic_energy
        );
    }
}
