//! The adhesive theory against an independent slow oracle: `oracle/`
//! solves the same equations ([S-5..S-9, S-14]) with finite differences, a Shortley–Weller
//! absorbing wall, extrapolated backward Euler in the variance and bisection on the scalar
//! C = γ(q_L), sharing no code with `theory::adhesion` (like RustFFT's naive DFT beside its
//! FFT). First the oracle's own accuracy (the paper's numbers, closed forms of a fixed and a
//! linearly moving wall, the adhesionless limit), then the fast solver against it.
//!
//! The default tests take a few seconds (ten scenes); the larger sets are ignored (each a
//! few minutes in the test profile): `cargo test -p asperity --test adhesion_oracle --
//! --ignored --nocapture` runs the five-level refinement study of the oracle, a 44-scene
//! comparison (default and 4× finer fast solver), and the issue's 112-point grid of system II
//! (the error estimate's coverage there, and where the fast solver does not converge).

mod oracle;

mod common;

use asperity::input::scene::Scene;
use asperity::theory::adhesion::{self, AdhesionAccuracy};
use asperity::theory::engine::{self, Options};
use asperity::theory::persson::{self, Accuracy};
use asperity::tolerances::*;
use oracle::march::{march, Path, Resolution};
use oracle::physics::{slab_factor, Physics};
use oracle::solve::{default_resolution, loading};
use statrs::distribution::{ContinuousCDF, Normal};
use statrs::function::erf::erf;

const INF: f64 = f64::INFINITY;

fn scene(n: u8, model: u8, t: f64, p: f64) -> Scene {
    let s = common::system(n, model);
    let g = s.surface_energy_j_m2();
    common::at(n, model, t, g, p)
}

fn phi(x: f64) -> f64 {
    Normal::new(0.0, 1.0).unwrap().cdf(x)
}

/// The oracle's march with a prescribed wall σ_a*(v), extrapolated over two levels as the
/// self-consistent answer is.
fn prescribed(s: &Scene, wall: &dyn Fn(f64) -> f64) -> (f64, f64) {
    let ph = Physics::from_scene(s);
    let run = |res: &Resolution| {
        let path = Path::new(&ph, res);
        march(&ph, &path, res, &|_q, v, _a, _j| wall(v), None)
    };
    let res = default_resolution();
    let (o1, o2) = (run(&res), run(&res.refined(2.0)));
    (2.0 * o2.a_r - o1.a_r, o2.v)
}

#[test]
fn oracle_formulas_match_the_paper_and_the_scene() {
    // physics.md §2: f(0.1) = 1.66333e−4, f(0.5) = 0.0198054, f(1) = 0.135457, f(2) = 0.585116,
    // f(5) = 0.994466 (6 digits); thin plate f → x³/6; the series/closed-form switch at x = 1
    for (x, f) in [
        (0.1, 1.66333e-4),
        (0.5, 0.0198054),
        (1.0, 0.135457),
        (2.0, 0.585116),
        (5.0, 0.994466),
    ] {
        assert!(
            (slab_factor(x) / f - 1.0).abs() < 5e-6,
            "f({x}) = {} vs {f}",
            slab_factor(x)
        );
    }
    let x = 1e-3;
    assert!((slab_factor(x) / (x * x * x / 6.0) - 1.0).abs() < 1e-5);
    let (below, above) = (slab_factor(1.0 - 1e-12), slab_factor(1.0));
    assert!((below / above - 1.0).abs() < 1e-11, "{below} vs {above}");
    // the oracle's own quadratures against the library's closed forms: ḡ and u_ela^(f)
    for s in [scene(1, 3, INF, 0.01), scene(2, 4, 0.25, 0.005)] {
        let ph = Physics::from_scene(&s);
        assert!(
            (ph.gbar / s.rms_gradient() - 1.0).abs() < 1e-10,
            "{} vs {}",
            ph.gbar,
            s.rms_gradient()
        );
        let u = ph.integrate_panels(|q| ph.e_density(q));
        assert!((u / s.full_contact_energy() - 1.0).abs() < 1e-10);
        let path = Path::new(&ph, &default_resolution());
        assert!((path.e_full / u - 1.0).abs() < 1e-10, "{} vs {u}", path.e_full);
    }
}

#[test]
fn oracle_fixed_wall_is_the_mirror_gaussian() {
    // W ≡ 1 (model 1), half-space: V(q_s) = 1/4 and a_r = erf((p* + σ_a)/√(2V)) [S-7]
    for (p, sa) in [(0.01, 0.0), (0.01, 0.3), (0.2, 0.05), (1e-4, 0.5)] {
        let s = scene(1, 1, INF, p);
        let (a, v) = prescribed(&s, &|_| sa);
        assert!((v - 0.25).abs() < 1e-12, "{v}");
        let exact = erf((p + sa) / (2.0 * v).sqrt());
        eprintln!("fixed wall p* {p}, σ_a {sa}: {a:.9} vs {exact:.9} ({:.1e})", a - exact);
        assert!(
            (a - exact).abs() < ORACLE_WALL_REL * exact,
            "p* {p}, σ_a {sa}: {a} vs {exact}"
        );
    }
}

#[test]
fn oracle_moving_wall_is_bachelier_levy() {
    // a wall moving linearly in the variance, σ_a = s₀ + c·v (model 1, half-space): the
    // distance of the stress from the wall is a Brownian motion with drift c started at
    // d = p* + s₀, killed at 0, so a_r = Φ((d + cV)/√V) − e^{−2cd}·Φ((cV − d)/√V)
    // (Bachelier–Lévy). c > 0 opens the wall, c < 0 sweeps it into the distribution.
    for (p, s0, c) in [(0.01, 0.05, 0.4), (0.01, 0.3, -1.0), (1e-4, 0.0, 2.0), (0.1, 0.6, -2.0)] {
        let s = scene(1, 1, INF, p);
        let (a, v) = prescribed(&s, &|v| s0 + c * v);
        let d = p + s0;
        let exact = phi((d + c * v) / v.sqrt()) - (-2.0 * c * d).exp() * phi((c * v - d) / v.sqrt());
        eprintln!(
            "moving wall p* {p}, s0 {s0}, c {c}: {a:.9} vs {exact:.9} ({:.1e})",
            a - exact
        );
        assert!(
            (a - exact).abs() < ORACLE_WALL_REL * exact,
            "p* {p}, s0 {s0}, c {c}: {a} vs {exact}"
        );
    }
}

#[test]
fn oracle_without_adhesion_is_the_adhesionless_theory() {
    // γ_s = 0: the root of H is C = −I, σ_a ≡ 0 and the march is the W-coupled mirror
    // Gaussian: erf(√2 p*) for model 1 on a half-space, the adaptive ODE of `persson` (code
    // independent of the adhesive path) otherwise
    let cases = [
        (1, 1, INF, 0.01),
        (1, 3, INF, 1e-3),
        (2, 4, 0.25, 0.005),
        (2, 3, 1.0, 0.05),
    ];
    for (n, m, t, p) in cases {
        let mut s = scene(n, m, t, p);
        s = s.without_adhesion();
        let o = loading(&Physics::from_scene(&s), &default_resolution(), 6);
        let reference = if m == 1 && t.is_infinite() {
            erf(2f64.sqrt() * p)
        } else {
            persson::solve(&s, &Accuracy::default()).unwrap().a_r
        };
        let err = (o.a_r / reference - 1.0).abs();
        eprintln!(
            "adhesionless system {n}, model {m}, t {t}, p* {p}: {:.9} vs {reference:.9} ({err:.1e})",
            o.a_r
        );
        assert_eq!(o.all.len(), 1);
        assert!(o.sigma_a < 1e-6, "{}", o.sigma_a);
        assert!(err < ORACLE_ADHESIONLESS_REL, "{} vs {reference}", o.a_r);
    }
}

/// Scenes of the default comparison: system I and II, models 1–4, t = ∞ down to t·q_r = 0.15,
/// p* from 1e-5 to 0.05, none in a hysteresis window (the oracle finds one root).
fn default_scenes() -> [Scene; 10] {
    [
        scene(1, 3, INF, 0.01),
        scene(1, 4, INF, 0.003),
        scene(1, 1, INF, 0.05),
        scene(2, 4, INF, 0.005),
        scene(2, 4, 0.25, 0.005),
        scene(2, 3, 0.3, 1e-3),
        scene(2, 4, 0.3, 1e-4),
        scene(2, 3, 0.25, 1e-2),
        scene(2, 3, 0.3, 1e-5),
        scene(2, 4, 0.15, 1e-2),
    ]
}

/// The fast solver at its default accuracy against the oracle: within its own error estimate
/// plus the oracle's bar on ≥ 95 % of the scenes and never more than 2× below it (the honest
/// error bar of item 6), and within `ADHESION_ORACLE_REL`·a_r
/// plus the oracle's bar; with `fine_too`, a 4× finer fast run within
/// `ADHESION_ORACLE_FINE_REL`·a_r plus the oracle's bar. Every scene is reported before the
/// failures are.
fn agree(scenes: &[Scene], res: &Resolution, fine_too: bool) {
    let mut worst: f64 = 0.0;
    let mut worst_fine: f64 = 0.0;
    let mut failures = Vec::new();
    // estimates below the error (plus the oracle's bar): item 6's criterion, ≥ 95 % covered
    // and none more than 2× below
    let mut misses: Vec<(f64, String)> = Vec::new();
    for s in scenes {
        let t0 = std::time::Instant::now();
        let o = loading(&Physics::from_scene(s), res, 6);
        let t_oracle = t0.elapsed().as_secs_f64();
        let label = format!(
            "system-{}, model {}, t·q_r {}, p* {}",
            if s.spectrum().q_r() > 4e5 { 2 } else { 1 },
            s.model().kind.number().unwrap(),
            s.thickness_qr(),
            s.pressure()
        );
        if o.all.len() != 1 {
            failures.push(format!("{label}: several branches {:?}", o.all));
            continue;
        }
        let ev = engine::evaluate(s, &Options::default()).unwrap();
        let err = (ev.stats.a_r - o.a_r).abs();
        eprintln!(
            "{label}: fast {:.7} (estimate {:.1e}) oracle {:.7} ± {:.1e} ({t_oracle:.2} s): error {:.1e} ({:.1e} relative)",
            ev.stats.a_r,
            ev.error_estimate,
            o.a_r,
            o.error,
            err,
            err / o.a_r
        );
        worst = worst.max(err / o.a_r);
        if err > ADHESION_ORACLE_REL * o.a_r + o.error {
            failures.push(format!("{label}: {} vs {} ± {}", ev.stats.a_r, o.a_r, o.error));
        }
        if err > ev.error_estimate + o.error {
            misses.push((
                (ev.error_estimate + o.error) / err,
                format!("{label}: error {err:.2e} > estimate {:.2e}", ev.error_estimate),
            ));
        }
        if fine_too {
            let a = adhesion::solve(s, &four_times_finer(), None, None).unwrap().a_r;
            let e = (a - o.a_r).abs();
            eprintln!("  4x finer: {a:.7}, error {e:.1e} ({:.1e} relative)", e / o.a_r);
            worst_fine = worst_fine.max(e / o.a_r);
            if e > ADHESION_ORACLE_FINE_REL * o.a_r + o.error {
                failures.push(format!("{label}: 4x finer {a} vs {} ± {}", o.a_r, o.error));
            }
        }
    }
    eprintln!("worst relative error {worst:.1e} (default), {worst_fine:.1e} (4x finer)");
    eprintln!(
        "estimate below the error on {} of {} scenes: {misses:?}",
        misses.len(),
        scenes.len()
    );
    if misses.len() as f64 > (1.0 - ERROR_BAR_COVERAGE) * scenes.len() as f64
        || misses.iter().any(|(r, _)| *r < ERROR_BAR_WORST_RATIO)
    {
        failures.extend(misses.into_iter().map(|(r, m)| format!("{m} (ratio {r:.2})")));
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn fast_solver_agrees_with_the_oracle_semi_infinite_and_thick() {
    agree(&default_scenes()[..5], &default_resolution(), false);
}

#[test]
fn fast_solver_agrees_with_the_oracle_on_thin_slabs() {
    agree(&default_scenes()[5..], &default_resolution(), false);
}

#[test]
fn every_branch_of_a_hysteresis_window_agrees_with_the_oracle() {
    // system II, model 3, t·q_r = 0.1 at 0.8 γ_s, p* = 1e-5 (the window of
    // `adhesion::hysteresis_window_has_three_branches_and_brackets_the_load`): the oracle's
    // scan (steps of 4^(1/12) in C + I₀: the upper two roots lie a factor 1.2 apart) finds
    // three roots of H, the middle one where H falls (unstable), and the fast solver's
    // branches match them one by one
    let mut s = scene(2, 3, 0.1, 1e-5);
    s.set_surface_energy_j_m2(s.surface_energy_j_m2() * 0.8).unwrap();
    let ph = Physics::from_scene(&s);
    let res = default_resolution();
    let oracle = oracle::solve::branches(&ph, &res, 8, 12);
    let fast = adhesion::solve(&s, &AdhesionAccuracy::default(), None, None)
        .unwrap()
        .branches;
    eprintln!(
        "oracle {oracle:.6?}\nfast {:?}",
        fast.iter().map(|b| (b.a_r, b.stable)).collect::<Vec<_>>()
    );
    assert_eq!(oracle.len(), 3, "{oracle:?}");
    assert_eq!(fast.len(), 3);
    // H > 0 between the first two roots, < 0 between the last two: the middle one is unstable
    let path = Path::new(&ph, &res);
    let h = |c: f64| oracle::solve::residual(&ph, &path, &res, c).0;
    assert!(h(0.5 * (oracle[0].2 + oracle[1].2)) > 0.0);
    assert!(h(0.5 * (oracle[1].2 + oracle[2].2)) < 0.0);
    assert!(fast[0].stable && !fast[1].stable && fast[2].stable);
    for ((a, bar, _), b) in oracle.iter().zip(&fast) {
        assert!(
            (b.a_r - a).abs() <= ADHESION_ORACLE_REL * a + bar,
            "{} vs {a} ± {bar}",
            b.a_r
        );
    }
}

#[test]
#[ignore]
fn fast_solver_agrees_with_the_oracle_on_a_larger_set() {
    let mut scenes = Vec::new();
    for m in 1..=4 {
        for p in [1e-3, 1e-2, 0.1] {
            scenes.push(scene(1, m, INF, p));
        }
    }
    for m in [3, 4] {
        for t in [INF, 0.5, 0.3, 0.25] {
            for p in [1e-4, 1e-3, 1e-2, 0.05] {
                scenes.push(scene(2, m, t, p));
            }
        }
    }
    agree(&scenes, &default_resolution().refined(2.0), true);
}

#[test]
#[ignore]
fn oracle_refinement_study() {
    // five levels (each: steps split in two, h/√2) of the self-consistent oracle; the
    // two-level extrapolation and its error bar at each pair of levels, against the finest
    // extrapolation
    let scenes = [
        scene(1, 1, INF, 0.01),
        scene(1, 3, INF, 0.01),
        scene(1, 1, INF, 0.05),
        scene(2, 4, 0.25, 0.005),
        scene(2, 3, 0.3, 1e-3),
        scene(2, 3, 0.25, 1e-2),
        scene(2, 4, 0.3, 1e-4),
    ];
    let res = default_resolution();
    for s in scenes {
        let ph = Physics::from_scene(&s);
        let r1 = oracle::solve::roots(&ph, &res, 6);
        let mut c = r1[0].c;
        let mut levels = vec![r1[0].outcome.a_r];
        for k in [2.0, 4.0, 8.0, 16.0] {
            let r = oracle::solve::root_near(&ph, &res.refined(k), c, 1e-5 * (ph.gamma + 1.0));
            c = r.c;
            levels.push(r.outcome.a_r);
        }
        let best = 2.0 * levels[4] - levels[3];
        eprintln!(
            "model {}, t·q_r {}, p* {}: levels {levels:.8?}",
            s.model().kind.number().unwrap(),
            s.thickness_qr(),
            s.pressure()
        );
        for w in 0..4 {
            let (a1, a2) = (levels[w], levels[w + 1]);
            let ext = 2.0 * a2 - a1;
            let bar = oracle::solve::ERROR_FRACTION * (a2 - a1).abs() + oracle::solve::ERROR_FLOOR * ext;
            eprintln!(
                "  levels {}-{}: {ext:.8} ± {bar:.1e}, off the finest by {:.1e} ({:.2} of the bar)",
                w + 1,
                w + 2,
                ext - best,
                (ext - best).abs() / bar
            );
            if w < 3 {
                assert!((ext - best).abs() <= bar, "levels {}-{}", w + 1, w + 2);
            }
        }
    }
}

/// The fast solver at 4× the default resolution in both directions (one branch).
fn four_times_finer() -> AdhesionAccuracy {
    let d = AdhesionAccuracy::default();
    AdhesionAccuracy {
        steps_per_ln_q: 4.0 * d.steps_per_ln_q,
        points_per_width: 4.0 * d.points_per_width,
        explore_branches: false,
        ..d
    }
}

/// Sorts (estimate/error, scene) lowest first, prints the count below 1 and the lowest five
/// under `what`, and returns that count.
fn sort_and_count_misses(ratios: &mut [(f64, String)], what: &str) -> usize {
    ratios.sort_by(|a, b| a.0.total_cmp(&b.0));
    let misses = ratios.iter().filter(|r| r.0 < 1.0).count();
    eprintln!(
        "{what}: {} points, {misses} missed by the estimate; lowest ratios {:?}",
        ratios.len(),
        &ratios[..ratios.len().min(5)]
    );
    misses
}

/// The issue's grid (system II, models 3 and 4, t·q_r = 0.05…0.5, p* = 1e-6…0.1): the oracle's
/// roots of H at every point, and the fast solver's `error_estimate` against its error from the
/// oracle wherever it converges. A point counts as a miss when the error exceeds the estimate
/// by more than the oracle's bar; misses must stay ≤ 5 % and no estimate more than 2× below
/// the error (less the bar); the same against a 4× finer fast run. Prints one row per point
/// and the count of points where the fast solver did not converge (not
/// asserted here).
#[test]
#[ignore]
fn fast_solver_on_the_issue_grid() {
    let mut not_converged = 0;
    let mut points = 0;
    let mut ratios = Vec::new();
    let mut ratios_fine = Vec::new();
    for m in [3, 4] {
        for t in [0.05, 0.08, 0.1, 0.12, 0.15, 0.2, 0.3, 0.5] {
            for p in [1e-6, 1e-5, 1e-4, 1e-3, 5e-3, 0.02, 0.1] {
                let s = scene(2, m, t, p);
                let o = loading(&Physics::from_scene(&s), &default_resolution(), 8);
                points += 1;
                let t0 = std::time::Instant::now();
                let fast = engine::evaluate(&s, &Options::default());
                let tf = t0.elapsed().as_secs_f64();
                match fast {
                    Ok(ev) => {
                        let err = (ev.stats.a_r - o.a_r).abs();
                        eprintln!(
                            "| {m} | {t} | {p:e} | {:.6} ± {:.0e} | {} | {:.6} | {:.1e} | {:.1e} | {tf:.2} s |",
                            o.a_r,
                            o.error,
                            o.all.len(),
                            ev.stats.a_r,
                            err / o.a_r,
                            ev.error_estimate / o.a_r
                        );
                        // resolved errors only: below the oracle's bar the ratio means nothing
                        if err > o.error {
                            ratios.push((ev.error_estimate / (err - o.error), format!("model {m}, t {t}, p* {p}")));
                        }
                        // and against a 4× finer fast run, resolved everywhere
                        if let Ok(f) = adhesion::solve(&s, &four_times_finer(), ev.adhesive.as_deref(), None) {
                            let e = (ev.stats.a_r - f.a_r).abs();
                            ratios_fine.push((ev.error_estimate / e, format!("model {m}, t {t}, p* {p}")));
                        }
                    }
                    Err(e) => {
                        not_converged += 1;
                        let e = e.to_string();
                        eprintln!(
                            "| {m} | {t} | {p:e} | {:.6} ± {:.0e} | {} | failed: {} | | | {tf:.2} s |",
                            o.a_r,
                            o.error,
                            o.all.len(),
                            &e[..e.len().min(60)]
                        );
                    }
                }
            }
        }
    }
    let converged = points - not_converged;
    eprintln!("{points} points, the fast solver did not converge on {not_converged}; of {converged} converged:");
    let misses = sort_and_count_misses(&mut ratios, "resolved by the oracle");
    let misses_fine = sort_and_count_misses(&mut ratios_fine, "against a 4x finer run");
    assert!(
        misses as f64 <= (1.0 - ERROR_BAR_COVERAGE) * converged as f64,
        "{ratios:?}"
    );
    assert!(ratios.iter().all(|r| r.0 >= ERROR_BAR_WORST_RATIO), "{ratios:?}");
    assert!(
        misses_fine as f64 <= (1.0 - ERROR_BAR_COVERAGE) * ratios_fine.len() as f64,
        "{ratios_fine:?}"
    );
    assert!(
        ratios_fine.iter().all(|r| r.0 >= ERROR_BAR_WORST_RATIO),
        "{ratios_fine:?}"
    );
}

/// Every branch: on system II (models 3 and 4, t·q_r = 0.1 and 0.15, γ_s = 0.6…1× the
/// preset's, p* = 1e-5 and 1e-3) the fast solver's `branches` against the oracle's roots of H
/// (scan steps of 4^(1/12) in C + I₀): the same number of roots, each a_r within
/// `ADHESION_ORACLE_REL`·a_r plus the oracle's bar. Prints the scenes with several branches.
#[test]
#[ignore]
fn fast_solver_finds_the_oracles_branches() {
    let mut failures = Vec::new();
    let mut several = 0;
    for m in [3, 4] {
        for t in [0.1, 0.15] {
            for g in [0.6, 0.8, 1.0] {
                for p in [1e-5, 1e-3] {
                    let mut s = scene(2, m, t, p);
                    s.set_surface_energy_j_m2(s.surface_energy_j_m2() * g).unwrap();
                    let found = oracle::solve::branches(&Physics::from_scene(&s), &default_resolution(), 8, 12);
                    let oracle: Vec<f64> = found.iter().map(|r| r.0).collect();
                    let bars: Vec<f64> = found.iter().map(|r| r.1).collect();
                    let sol = adhesion::solve(&s, &AdhesionAccuracy::default(), None, None).unwrap();
                    let fast: Vec<f64> = sol.branches.iter().map(|b| b.a_r).collect();
                    let label = format!("model {m}, t·q_r {t}, γ×{g}, p* {p}");
                    if oracle.len() > 1 || fast.len() > 1 {
                        several += 1;
                        eprintln!("{label}: oracle {oracle:.6?}, fast {fast:.6?}");
                    }
                    let agree = oracle.len() == fast.len()
                        && oracle
                            .iter()
                            .zip(&bars)
                            .zip(&fast)
                            .all(|((o, bar), f)| (o - f).abs() <= ADHESION_ORACLE_REL * o + bar);
                    if !agree {
                        failures.push(format!("{label}: oracle {oracle:?}, fast {fast:?}"));
                    }
                }
            }
        }
    }
    eprintln!("{several} scenes with several branches");
    assert!(failures.is_empty(), "{failures:#?}");
}
