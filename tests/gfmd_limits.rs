//! GFMD you can trust: the Δa → 0 limit with an error bar (Johnson's sinusoid, a
//! self-affine map), ensembles over seeds, load sweeps against single runs, the Polonsky–Keer
//! solver against FIRE, and independence of the thread count.

use asperity::gfmd::ladder::{extrapolate, run_ladder, run_seeds};
use asperity::gfmd::sweep::run_sweep;
use asperity::gfmd::{self, GfmdOptions, GfmdSetup, GridSpec, Method, Problem};
use asperity::input::preset::Preset;
use asperity::surface::heightmap::Surface;
use asperity::theory::sweep::SweepSpec;
use std::f64::consts::PI;
use std::sync::atomic::AtomicBool;

const E: f64 = 1e7;

fn opts(tol: f64) -> GfmdOptions {
    GfmdOptions {
        tolerance: tol,
        ..GfmdOptions::default()
    }
}

/// Johnson's sinusoid h = Δcos(2π(x − s)/λ), λ = L, on M × 2 nodes, at p = 0.3 p_full: the
/// contact fraction 2c/λ = (2/π) asin √(p/p_full). Node counting quantises the width to ±Δa;
/// averaging over 16 sub-grid shifts s of the crest removes that noise (the mean count of
/// nodes in an interval of width 2c over uniform shifts is 2c/Δa), leaving the systematic
/// first-order error that the ladder extrapolates away.
#[test]
fn extrapolation_recovers_johnsons_limit() {
    let (l, amp, ratio): (f64, f64, f64) = (1e-6, 1e-8, 0.3);
    let exact = 2.0 / PI * ratio.sqrt().asin();
    let p_full = PI * E * amp / l;
    let mut h = Vec::new();
    let mut a = Vec::new();
    for m in [64usize, 128, 256] {
        let da = l / m as f64;
        let mut sum = 0.0;
        let shifts = 16;
        for k in 0..shifts {
            let s = k as f64 / shifts as f64;
            let heights = (0..2 * m)
                .map(|i| amp * (2.0 * PI * ((i % m) as f64 - s) / m as f64).cos())
                .collect();
            let surf = Surface::new(m, 2, da, heights).unwrap();
            let pr = Problem {
                surface: &surf,
                modulus: E,
                thickness: f64::INFINITY,
                pressure: ratio * p_full,
                gamma: 0.0,
                range: 1e-9,
            };
            let sol = gfmd::solve(&pr, &opts(1e-10), &mut |_| {}, &AtomicBool::new(false)).unwrap();
            sum += gfmd::measure(&pr, &sol, &GfmdOptions::default()).stats.a_r;
        }
        h.push(da);
        a.push(sum / shifts as f64);
    }
    let e = extrapolate(&h, &a).unwrap();
    eprintln!(
        "Johnson: a_r at lambda/da = 64, 128, 256: {a:?}; limit {} +- {:.2e}; exact {exact}",
        e.limit, e.error
    );
    assert!((e.limit - exact).abs() <= e.error.max(1e-4), "{e:?} vs {exact}");
    assert!(e.error < 0.01 * exact, "error bar {:.2e} not below 1 %", e.error);
    assert!(
        (e.limit - exact).abs() < (a[2] - exact).abs(),
        "no better than the finest grid"
    );
}

fn small_setup(pts: f64, pressure: f64, seed: u64) -> GfmdSetup {
    let p = Preset::resolve("system-1").unwrap();
    let scene = p.scene().unwrap().without_adhesion().with_pressure(pressure).unwrap();
    GfmdSetup {
        scene,
        grid: GridSpec {
            system_size_ratio: 2.0,
            bandwidth: 4.0,
            points_per_short_wavelength: pts,
        },
        seed,
        surface: None,
        rescale: true,
    }
}

/// A self-affine map (L/λ_r = 2, λ_r/λ_s = 4): the ladder λ_s/Δa = 4, 8, 16 extrapolates to
/// within its error bar, and within 1 %, of the limit from the finer ladder 8, 16, 32 (the
/// same realisation refined to λ_s/Δa = 32).
#[test]
fn self_affine_ladder_agrees_with_the_refined_limit() {
    let setup = small_setup(8.0, 0.05, 3);
    let cancel = AtomicBool::new(false);
    let o = opts(1e-8);
    let coarse = run_ladder(&setup, &[4.0, 8.0, 16.0], &o, &mut |_, _| {}, &cancel).unwrap();
    let fine = run_ladder(&setup, &[8.0, 16.0, 32.0], &o, &mut |_, _| {}, &cancel).unwrap();
    let (c, f) = (coarse.a_r, fine.a_r);
    eprintln!(
        "self-affine a_r: rungs {:?}; limit(4,8,16) = {} +- {:.2e}, limit(8,16,32) = {} +- {:.2e}",
        fine.rungs.iter().map(|r| r.a_r).collect::<Vec<_>>(),
        c.limit,
        c.error,
        f.limit,
        f.error
    );
    assert!((c.limit - f.limit).abs() <= c.error + f.error, "{c:?} vs {f:?}");
    assert!((c.limit / f.limit - 1.0).abs() < 0.01, "{c:?} vs {f:?}");
    // the same realisation on every rung: identical discrete ḡ and h_rms
    assert_eq!(coarse.rungs[1].grid * 2, coarse.rungs[2].grid);
}

/// K seeds are K different maps, and the standard error falls like 1/√K (a factor 2 from K = 8
/// to K = 32, within the scatter of a sample standard deviation).
#[test]
fn seeds_are_independent_and_the_standard_error_shrinks() {
    let setup = small_setup(4.0, 0.05, 1);
    let cancel = AtomicBool::new(false);
    let o = opts(1e-8);
    let e8 = run_seeds(&setup, 8, None, &o, &mut |_, _| {}, &cancel).unwrap();
    let e32 = run_seeds(&setup, 32, None, &o, &mut |_, _| {}, &cancel).unwrap();
    // a_r on 32² is a multiple of 1/1024 and repeats; the mean gap identifies a realisation
    let mut v = e32.mean_gap_rel.values.clone();
    v.sort_by(f64::total_cmp);
    v.dedup();
    assert_eq!(v.len(), 32, "realisations repeat: {:?}", e32.mean_gap_rel.values);
    assert_eq!(
        &e32.a_r.values[..8],
        &e8.a_r.values[..],
        "seed S..S+7 are the first eight"
    );
    let ratio = e8.a_r.standard_error.unwrap() / e32.a_r.standard_error.unwrap();
    eprintln!(
        "a_r: K = 8: {} +- {:.2e}; K = 32: {} +- {:.2e}; ratio {ratio:.2}",
        e8.a_r.mean,
        e8.a_r.standard_error.unwrap(),
        e32.a_r.mean,
        e32.a_r.standard_error.unwrap()
    );
    assert!(ratio > 1.3 && ratio < 3.0, "{ratio}");
    assert!((e8.a_r.mean - e32.a_r.mean).abs() < 3.0 * e8.a_r.standard_error.unwrap());
}

/// GFMD's single run of `setup` at p* = `p` (the reference a sweep's row is checked against).
fn single_run(setup: &GfmdSetup, p: f64, o: &GfmdOptions) -> gfmd::GfmdResult {
    let setup = GfmdSetup {
        scene: setup.scene.clone().with_pressure(p).unwrap(),
        ..setup.clone()
    };
    gfmd::run(&setup, o, &mut |_| {}, &AtomicBool::new(false)).unwrap()
}

/// A warm-started sweep gives the single runs' answers to the solver tolerance (no adhesion:
/// one minimum per load).
#[test]
fn sweep_equals_single_runs() {
    let setup = small_setup(8.0, 0.01, 2);
    let cancel = AtomicBool::new(false);
    let o = opts(1e-10);
    let spec = SweepSpec {
        from: 0.01,
        to: 0.1,
        points: 3,
    };
    let sw = run_sweep(&setup, &spec, &o, &mut |_, _| {}, &cancel).unwrap();
    let n2 = (sw.grid * sw.grid) as f64;
    for (row, p) in sw.rows.iter().zip(spec.pressures()) {
        let single = single_run(&setup, p, &o);
        eprintln!(
            "p* = {p:.3e}: a_r {} vs {}, u {} vs {}, steps {} vs {}",
            row.a_r, single.stats.a_r, row.mean_gap_rel, single.mean_gap_rel, row.iterations, single.iterations
        );
        assert!(
            (row.a_r - single.stats.a_r).abs() <= 2.0 / n2,
            "{} vs {}",
            row.a_r,
            single.stats.a_r
        );
        assert!((row.mean_gap_rel / single.mean_gap_rel - 1.0).abs() < 1e-6);
        assert!((row.mean_contact_stress / single.stats.mean_contact_stress - 1.0).abs() < 1e-3);
    }
    let th = sw.theory.as_ref().expect("theory on the same map");
    assert_eq!(th.rows.len(), sw.rows.len());
    assert!(th.rows.iter().all(|r| r.mean_gap_rel > 0.0));
}

/// A hard-wall sweep in small load steps (system I, 32², 20 loads over p* 0.01…0.02, where
/// most steps leave the contact unchanged) gives every single run's answer, in as many steps:
/// no load spends thousands of iterations on a contact that no longer changes.
#[test]
fn small_steps_cost_what_single_runs_cost() {
    use asperity::tolerances::{GFMD_SWEEP_SINGLE_REL, GFMD_SWEEP_STEPS_FACTOR};
    let preset = Preset::resolve("system-1").unwrap();
    let setup = GfmdSetup {
        scene: preset.scene().unwrap().without_adhesion(),
        grid: GridSpec::of_preset(&preset, Some(32)).unwrap(),
        seed: 1,
        surface: None,
        rescale: true,
    };
    let (cancel, o) = (AtomicBool::new(false), GfmdOptions::default());
    let spec = SweepSpec {
        from: 0.01,
        to: 0.02,
        points: 20,
    };
    let sw = run_sweep(&setup, &spec, &o, &mut |_, _| {}, &cancel).unwrap();
    let rel = |a: f64, b: f64| (a / b - 1.0).abs();
    for (row, p) in sw.rows.iter().zip(spec.pressures()) {
        let single = single_run(&setup, p, &o);
        eprintln!(
            "p* = {p:.4e}: a_r {} vs {}, steps {} vs {}",
            row.a_r, single.stats.a_r, row.iterations, single.iterations
        );
        assert!(rel(row.a_r, single.stats.a_r) <= GFMD_SWEEP_SINGLE_REL, "p* {p}");
        assert!(
            rel(row.mean_gap_rel, single.mean_gap_rel) <= GFMD_SWEEP_SINGLE_REL,
            "p* {p}"
        );
        assert!(
            rel(row.mean_contact_stress, single.stats.mean_contact_stress) <= GFMD_SWEEP_SINGLE_REL,
            "p* {p}"
        );
        assert!(
            row.iterations <= GFMD_SWEEP_STEPS_FACTOR * single.iterations,
            "p* {p}: {} steps against {}",
            row.iterations,
            single.iterations
        );
    }
}

/// Polonsky–Keer and FIRE reach the same configuration (same criterion), and a run does not
/// depend on the number of threads, bit for bit.
#[test]
fn methods_agree_and_threads_do_not_matter() {
    let setup = small_setup(16.0, 0.02, 4); // 512² > the parallel threshold
    let cancel = AtomicBool::new(false);
    let mut results = Vec::new();
    for method in [Method::Fire, Method::PolonskyKeer] {
        for threads in [1, 2] {
            let o = GfmdOptions { method, ..opts(1e-8) };
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            let r = pool.install(|| gfmd::run(&setup, &o, &mut |_| {}, &cancel)).unwrap();
            eprintln!(
                "{method:?}, {threads} thread(s): a_r {}, {} steps",
                r.stats.a_r, r.iterations
            );
            results.push(r);
        }
    }
    assert_eq!(results[0].stats.a_r, results[1].stats.a_r);
    assert_eq!(results[0].mean_gap, results[1].mean_gap);
    assert_eq!(results[2].stats.a_r, results[3].stats.a_r);
    assert_eq!(results[2].mean_gap, results[3].mean_gap);
    let n2 = (results[0].grid * results[0].grid) as f64;
    assert!((results[0].stats.a_r - results[2].stats.a_r).abs() <= 3.0 / n2);
    assert!((results[0].mean_gap / results[2].mean_gap - 1.0).abs() < 1e-6);
}

/// The default minimiser by scene class, as measured (BENCHMARKS.md, "--method auto"):
/// Polonsky–Keer for the hard wall of a half-space on every generated grid (to 8192²); FIRE
/// above (measured maps only), on every slab (PK's iterations explode as the slab thins: 19 138 against FIRE's 661 steps at
/// t·q_r = 0.3, 256²) and with adhesion (PK is a hard-wall method); the explicit choices do
/// what they say. A run shows it: PK iterations on a half-space, none on a slab.
#[test]
fn auto_method_by_scene_class() {
    use asperity::gfmd::Method;
    assert_eq!(Method::default(), Method::Auto);
    for (nodes, half_space, pk) in [
        (256 * 256, true, true),
        (2048 * 2048, true, true),
        (4096 * 4096, true, true),
        (8192 * 8192, true, true),
        (8192 * 8192 + 1, true, false),
        (256 * 256, false, false),
        (2048 * 2048, false, false),
    ] {
        assert_eq!(
            Method::Auto.uses_pk(nodes, half_space),
            pk,
            "{nodes} nodes, half-space {half_space}"
        );
    }
    assert!(Method::PolonskyKeer.uses_pk(4096 * 4096, false));
    assert!(!Method::Fire.uses_pk(64 * 64, true));
    let p = Preset::resolve("system-2").unwrap();
    for (thickness, pk) in [(f64::INFINITY, true), (1.0, false)] {
        let scene = p
            .scene()
            .unwrap()
            .without_adhesion()
            .with_pressure(0.009)
            .unwrap()
            .with_thickness_qr(thickness)
            .unwrap();
        let setup = GfmdSetup {
            scene,
            grid: GridSpec::from_preset(p.gfmd.as_ref().unwrap()).with_grid(64).unwrap(),
            seed: 1,
            surface: None,
            rescale: true,
        };
        let r = gfmd::run(&setup, &GfmdOptions::default(), &mut |_| {}, &AtomicBool::new(false)).unwrap();
        assert_eq!(
            r.pk_iterations > 0,
            pk,
            "t*q_r = {thickness}: {} PK iterations",
            r.pk_iterations
        );
    }
}
