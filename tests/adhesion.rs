//! The adhesive theory: the moving-wall propagator against its exact cases and its
//! order of convergence, the self-consistent solutions of systems I and II against [S]'s
//! findings, grid convergence, ∫Pr = a_r, the CLI fields, and hard cases.

mod common;

use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::surface::spectrum::{Normalisation, SelfAffine, Spectrum};
use asperity::theory::adhesion::{self, AdhesionAccuracy, Branch};
use asperity::theory::engine::{self, Options};
use asperity::theory::persson::{self, Accuracy};
use asperity::tolerances::*;
use asperity::Error;
use statrs::function::erf::erf;

fn system(n: u8, model: u8) -> Scene {
    common::system(n, model)
}

/// a_r(q_s) of the propagator alone with a prescribed wall (`adhesion::propagate_with_wall`).
fn a_r_at_q_s(s: &Scene, acc: &AdhesionAccuracy, wall: impl Fn(f64) -> f64, from_start: bool) -> f64 {
    let (_, a) = adhesion::propagate_with_wall(s, acc, wall, from_start).unwrap();
    *a.last().unwrap()
}

fn quick() -> Options {
    Options {
        adhesion_error_estimate: false,
        adhesion: AdhesionAccuracy {
            explore_branches: false,
            ..AdhesionAccuracy::default()
        },
        ..Options::default()
    }
}

#[test]
fn constant_wall_on_the_grid_is_exact() {
    // W ≡ 1 (model 1), half-space: V(q_s) = 1/4 and a_r = erf((p + σ_a)/√(2V)) exactly; the
    // grid is forced from the first step, so the sine propagator does all the work
    let s = system(1, 1);
    for (p, sa) in [(0.01, 0.0), (0.01, 0.3), (0.2, 0.05), (1e-4, 1.0)] {
        let mut sc = s.clone();
        sc.set_pressure(p).unwrap();
        let (_, a) = adhesion::propagate_with_wall(&sc, &AdhesionAccuracy::default(), |_| sa, true).unwrap();
        let exact = erf((p + sa) / (2.0 * 0.25f64).sqrt());
        let got = *a.last().unwrap();
        assert!(
            (got - exact).abs() < EXACT_WALL_ABS,
            "p* {p}, sigma_a {sa}: {got} vs {exact} ({:.1e})",
            got - exact
        );
    }
}

#[test]
fn zero_wall_reproduces_the_adhesionless_ode() {
    // σ_a ≡ 0 with W-coupled broadening (models 2-4) and a slab: the march (RK4 in the
    // variance measure) against the adaptive Dormand–Prince ODE of the adhesionless engine
    for (model, t) in [(2, f64::INFINITY), (3, f64::INFINITY), (4, 0.5), (3, 2.0)] {
        let mut s = system(1, model);
        s.set_thickness_qr(t).unwrap();
        let reference = persson::solve(&s, &Accuracy::default()).unwrap().a_r;
        let (_, a) = adhesion::propagate_with_wall(&s, &AdhesionAccuracy::default(), |_| 0.0, false).unwrap();
        let got = *a.last().unwrap();
        assert!(
            (got / reference - 1.0).abs() < ZERO_WALL_REL,
            "model {model}, t {t}: {got} vs {reference}"
        );
    }
}

#[test]
fn moving_wall_converges_with_resolution() {
    // a wall that opens linearly in ln q from 0 to 0.6, model 3 on system 1 at p* = 0.01:
    // errors against a 32x finer solution fall with the resolution (second order, see the
    // tolerance). The rungs start at 2x (12 steps per ln q): a wall from zero grows by more
    // than 1/ONSET_GROWTH (0.95) per step over its first 19 steps, which are split like an
    // onset; at 6 steps per ln q (41 steps from q_L to q_s) those are half the rise and make
    // that rung better than the rate (8.2e-5 against 3.0e-5 at 2x: order 1.44)
    let s = system(1, 3);
    let (lq, ls) = (s.spectrum().q_l().ln(), s.spectrum().q_s().ln());
    let wall = |q: f64| 0.6 * (q.ln() - lq) / (ls - lq);
    let run = |k: f64| {
        let acc = AdhesionAccuracy {
            steps_per_ln_q: 6.0 * k,
            points_per_width: 4.0 * k,
            ..AdhesionAccuracy::default()
        };
        a_r_at_q_s(&s, &acc, wall, false)
    };
    let reference = run(32.0);
    let errs: Vec<f64> = [2.0, 4.0, 8.0].iter().map(|&k| (run(k) - reference).abs()).collect();
    let orders: Vec<f64> = errs.windows(2).map(|w| (w[0] / w[1]).log2()).collect();
    eprintln!("moving wall: errors {errs:?}, orders {orders:?}");
    for o in &orders {
        assert!(*o > MOVING_WALL_MIN_ORDER, "errors {errs:?}, orders {orders:?}");
    }
}

#[test]
fn receding_wall_is_second_order_accurate() {
    // σ_a falling linearly in ln q moves the wall into the distribution: the step shifts half,
    // diffuses with the wall held, shifts the other half (Strang); the shift-then-hold step
    // before it was first order (1e-3 at 24 steps per ln q)
    let mut s = system(1, 1);
    s = s.without_adhesion();
    let (lq, ls) = (s.spectrum().q_l().ln(), s.spectrum().q_s().ln());
    let wall = |q: f64| 0.4 - 0.35 * (q.ln() - lq) / (ls - lq);
    let run = |steps: f64| {
        let acc = AdhesionAccuracy {
            steps_per_ln_q: steps,
            points_per_width: 20.0,
            ..AdhesionAccuracy::default()
        };
        a_r_at_q_s(&s, &acc, wall, true)
    };
    let reference = run(384.0);
    for steps in [12.0, 24.0, 48.0] {
        let err = (run(steps) - reference).abs();
        assert!(err < RECEDING_WALL_ABS, "{steps} steps per ln q: error {err:e}");
    }
}

#[test]
fn a_wall_starting_like_a_square_root_converges_spectrally() {
    // σ_a ∝ √γ leaves zero at infinite speed: the first pieces after the onset weight the image
    // by e^{−2cy} with 2c·h up to 15 at 10 points per width, which the grid did not resolve
    // (a_r off by 2e-4, falling like h²); the grid is refined there
    let mut s = system(1, 1);
    s = s.without_adhesion();
    let (lq, ls) = (s.spectrum().q_l().ln(), s.spectrum().q_s().ln());
    let wall = |q: f64| {
        let t = (q.ln() - lq) / (ls - lq);
        0.7 * ((t - 0.8).max(0.0) / 0.2).sqrt()
    };
    let run = |ppw: f64| {
        let acc = AdhesionAccuracy {
            points_per_width: ppw,
            ..AdhesionAccuracy::default()
        };
        a_r_at_q_s(&s, &acc, wall, true)
    };
    let reference = run(80.0);
    for ppw in [5.0, 10.0, 20.0] {
        let err = (run(ppw) / reference - 1.0).abs();
        assert!(err < ONSET_WALL_REL, "{ppw} points per width: error {err:e}");
    }
}

#[test]
fn system1_adhesion_adds_tens_of_percent() {
    // [S] §3.2: the challenge's adhesion raises a_r by about 50 % at small load; the theory
    // (models 3 and 4) by a few tens of percent. Measured: model 3 0.02142 → 0.02905 (+36 %),
    // model 4 0.02072 → 0.03109 (+50 %).
    for (model, lo, hi) in [(3, 1.2, 1.6), (4, 1.3, 1.7)] {
        let s = system(1, model);
        let ev = engine::evaluate(&s, &Options::default()).unwrap();
        let mut dry = s.clone();
        dry.set_surface_energy_j_m2(0.0).unwrap();
        let a0 = engine::evaluate(&dry, &Options::default()).unwrap().stats.a_r;
        let ratio = ev.stats.a_r / a0;
        assert!(
            ratio > lo && ratio < hi,
            "model {model}: {} / {a0} = {ratio}",
            ev.stats.a_r
        );
        assert!(ev.residual <= 1e-8, "{}", ev.residual);
        assert!(
            ev.error_estimate < ADHESION_ESTIMATE_REL * ev.stats.a_r,
            "{}",
            ev.error_estimate
        );
        assert_eq!(ev.branch, Branch::Loading);
        assert!(ev.sigma_a > 0.0 && ev.tensile_area > 0.0);
        assert!((ev.detached_fraction - (1.0 - ev.stats.a_r)).abs() < 1e-15);
    }
}

#[test]
fn system2_adhesion_multiplies_contact_and_thin_slabs_jump_towards_full_contact() {
    // [S] Fig. 7 at p* = 0.005: adhesionless a_r just over 1 %; adhesion multiplies it for the
    // semi-infinite solid (model 4: 0.0104 → 0.0222, ×2.1); thinner slabs climb steeply
    // towards full contact (t·q_r = 0.25: 0.183, 0.05: 0.859, 0.02: 0.998)
    let s = system(2, 4);
    let mut dry = s.clone();
    dry.set_surface_energy_j_m2(0.0).unwrap();
    let a0 = engine::evaluate(&dry, &quick()).unwrap().stats.a_r;
    assert!(a0 > 0.01 && a0 < 0.0115, "{a0}");
    let mut prev = 0.0;
    for t in [f64::INFINITY, 1.0, 0.5, 0.25, 0.05, 0.02] {
        let mut sc = s.clone();
        sc.set_thickness_qr(t).unwrap();
        let ev = engine::evaluate(&sc, &quick()).unwrap();
        assert!(ev.stats.a_r > prev, "t {t}: {} after {prev}", ev.stats.a_r);
        if t.is_infinite() {
            assert!(ev.stats.a_r / a0 > 1.8, "semi-infinite: {} / {a0}", ev.stats.a_r);
        }
        prev = ev.stats.a_r;
    }
    assert!(prev > 0.99, "{prev}");
}

#[test]
fn default_accuracy_against_a_finer_solution() {
    // the default resolution (24 steps per ln q, 10 points per width) against 4x finer, for
    // both systems at their reference loads
    for (n, model) in [(1, 3), (2, 4)] {
        let s = system(n, model);
        let fine = AdhesionAccuracy {
            steps_per_ln_q: 96.0,
            points_per_width: 40.0,
            explore_branches: false,
            ..AdhesionAccuracy::default()
        };
        let a_fine = adhesion::solve(&s, &fine, None, None).unwrap().a_r;
        let ev = engine::evaluate(&s, &Options::default()).unwrap();
        let err = (ev.stats.a_r / a_fine - 1.0).abs();
        assert!(
            err < ADHESION_DEFAULT_REL,
            "system {n}: {} vs {a_fine} ({err:.1e})",
            ev.stats.a_r
        );
        // the half-resolution estimate is of the right size (within 10x of the error)
        assert!(
            ev.error_estimate >= 0.1 * err * a_fine,
            "{} vs {err}",
            ev.error_estimate
        );
    }
}

#[test]
fn pr_integrates_to_a_r_and_starts_at_the_wall() {
    let mut s = system(2, 4);
    s.set_thickness_qr(0.5).unwrap();
    let opts = Options {
        sigma_points: 4001,
        ..quick()
    };
    let ev = engine::evaluate(&s, &opts).unwrap();
    let sig = &ev.stats.pr.sigma;
    assert!((sig[0] + ev.sigma_a).abs() < 1e-12);
    let mut integral = 0.0;
    for i in 1..sig.len() {
        integral += 0.5 * (ev.stats.pr.density[i] + ev.stats.pr.density[i - 1]) * (sig[i] - sig[i - 1]);
    }
    assert!(
        (integral / ev.stats.a_r - 1.0).abs() < ADHESIVE_PR_INTEGRAL_REL,
        "{integral} vs {}",
        ev.stats.a_r
    );
    // the tensile part carries mass
    assert!(ev.tensile_area > 0.01 * ev.stats.a_r);
    assert!(ev.stats.pr.density.iter().all(|d| d.is_finite() && *d >= 0.0));
    assert_eq!(ev.gamma_q.len(), ev.resolution.len());
    // γ(q) ≤ γ_s up to the energy balance's residual at q_s
    assert!(ev.gamma_q.iter().all(|g| (0.0..=1.0 + ev.residual + 1e-12).contains(g)));
}

#[test]
fn hard_cases_converge_or_say_why() {
    let mut cases = Vec::new();
    let base = system(1, 3);
    let glo = base.gamma_glo();
    for target in [0.01, 0.1, 1.0, 10.0] {
        let mut s = base.clone();
        s.set_surface_energy_j_m2(base.surface_energy_j_m2() * target / glo)
            .unwrap();
        cases.push(s);
    }
    for t in [0.01, 0.1, 1.0] {
        let mut s = system(2, 4);
        s.set_thickness_qr(t).unwrap();
        cases.push(s);
    }
    for p in [1e-5, 1.0] {
        let mut s = base.clone();
        s.set_pressure(p).unwrap();
        cases.push(s);
    }
    let sa = SelfAffine::new(1e-4, 2e-5, 2e-9, 0.8, Normalisation::RmsGradient(1.0)).unwrap();
    let mut wide = base.clone();
    wide.set_spectrum(Spectrum::SelfAffine(sa)).unwrap();
    cases.push(wide);
    let mut converged = 0;
    for (i, s) in cases.iter().enumerate() {
        match engine::evaluate(s, &quick()) {
            Ok(ev) => {
                assert!(
                    ev.stats.a_r.is_finite() && (0.0..=1.0).contains(&ev.stats.a_r),
                    "case {i}: {}",
                    ev.stats.a_r
                );
                assert!(ev.stats.mean_contact_stress.is_finite() && ev.stats.contact_stress_variance.is_finite());
                assert!(ev.residual <= 1e-3, "case {i}: residual {}", ev.residual);
                assert!(ev.error_estimate.is_finite() && ev.error_estimate >= 0.0, "case {i}");
                converged += 1;
            }
            // the two ways the adhesive engine says why: the energy balance at q_s missed
            // its tolerance (with the numbers), or the resolution checks did
            Err(Error::NotConverged { reason, .. }) => assert!(
                reason.contains("energy balance at q_s is off by") || reason.contains("neither resolution check"),
                "case {i}: {reason}"
            ),
            Err(e) => panic!("case {i}: unexpected error {e}"),
        }
    }
    // the hard cases are hard, not hopeless: every one converges at this accuracy
    assert_eq!(converged, cases.len(), "{converged} of {} converged", cases.len());
}

#[test]
fn tiny_loads_with_strong_adhesion_converge_and_refine() {
    // system 2, model 4 (σ_a capped), thin slabs, p* ≤ 1e-7: the root sits at C = γ(q_L) ≈ 0,
    // where a wall starting from the delta at the first step made H(C) jump (not converged,
    // |γ(q_s)/γ_s − 1| of 1e-2 to 0.3 at the best root). Each converges, and a_r agrees with a
    // run at twice the resolution in both directions.
    for (t, frac, p) in [(0.1, 0.8, 1e-8), (0.15, 1.0, 1e-9), (0.2, 1.5, 1e-7)] {
        let mut s = system(2, 4);
        s.set_thickness_qr(t).unwrap();
        s.set_surface_energy_j_m2(s.surface_energy_j_m2() * frac).unwrap();
        s.set_pressure(p).unwrap();
        let acc = AdhesionAccuracy::default();
        let sol = adhesion::solve(&s, &acc, None, None).unwrap();
        assert!(
            sol.residual <= acc.tol,
            "t {t} γ×{frac} p* {p}: residual {}",
            sol.residual
        );
        let fine = AdhesionAccuracy {
            steps_per_ln_q: 2.0 * acc.steps_per_ln_q,
            points_per_width: 2.0 * acc.points_per_width,
            ..acc
        };
        let f = adhesion::solve(&s, &fine, None, None).unwrap();
        eprintln!("t {t} γ×{frac} p* {p}: a_r {} vs {} (2x finer)", sol.a_r, f.a_r);
        assert!(
            (sol.a_r / f.a_r - 1.0).abs() < TINY_LOAD_REFINEMENT_REL,
            "t {t} γ×{frac} p* {p}: {} vs {}",
            sol.a_r,
            f.a_r
        );
    }
}

#[test]
fn every_branch_is_smooth_across_an_onset_threshold() {
    // system 2, model 3, t·q_r = 0.1, 0.8 γ_s inside its hysteresis window: near p* = 1.2e-7
    // the unloading root's wall turns on right at the first resolution node. The step after it
    // used to judge the onset from a γ of the other sign than the one that had set the wall,
    // H(C) jumped there, and the root fell onto the jump (a_r 2 % low, |γ(q_s)/γ_s − 1| of 3e-3
    // unchecked, the unloading mean gap lost). Every branch meets the tolerance, and the
    // unloading a_r lies on the line through its neighbours.
    let mut s = system(2, 3);
    s.set_thickness_qr(0.1).unwrap();
    s.set_surface_energy_j_m2(s.surface_energy_j_m2() * 0.8).unwrap();
    let acc = AdhesionAccuracy::default();
    let upper: Vec<f64> = [1.1e-7, 1.215e-7, 1.343e-7]
        .iter()
        .map(|&p| {
            s.set_pressure(p).unwrap();
            let sol = adhesion::solve(&s, &acc, None, None).unwrap();
            assert_eq!(sol.branches.len(), 3, "p* {p}: {:?}", sol.branches);
            for b in &sol.branches {
                assert!(b.residual <= acc.tol, "p* {p}: {b:?}");
            }
            sol.unloading_a_r.unwrap()
        })
        .collect();
    let (l0, l1, l2) = (1.1e-7f64.ln(), 1.215e-7f64.ln(), 1.343e-7f64.ln());
    let line = upper[0] + (upper[2] - upper[0]) * (l1 - l0) / (l2 - l0);
    assert!(
        (upper[1] / line - 1.0).abs() < ONSET_THRESHOLD_SMOOTH_REL,
        "{upper:?}: {} off the line",
        upper[1] / line - 1.0
    );
}

#[test]
fn sweep_across_the_thin_slab_transition() {
    // system 2 at t·q_r = 0.15: contact jumps from ~1 % (adhesionless) to ~40 % at small load;
    // the loading branch is followed load by load with no NaN, a_r rising and ū falling
    let mut s = system(2, 4);
    s.set_thickness_qr(0.15).unwrap();
    let spec = asperity::theory::sweep::SweepSpec {
        from: 1e-4,
        to: 0.3,
        points: 12,
    };
    let sw = asperity::theory::sweep::sweep(&s, &spec, &Options::chart(), None).unwrap();
    for r in &sw.rows {
        assert!(r.converged && r.a_r.is_finite(), "{r:?}");
        // a gap is either admissible (≥ 0) or withheld, and then the note says so
        // (near full contact the energy route with adhesion dips below 0: docs/physics.md §5)
        if r.mean_gap_rel.is_finite() {
            assert!(r.mean_gap_rel >= 0.0, "{r:?}");
        } else {
            assert!(
                sw.note.as_deref().unwrap_or("").contains("withheld"),
                "{r:?} {:?}",
                sw.note
            );
        }
    }
    // the gap is known over the small-load part of the jump, where it matters
    assert!(sw.rows[..6].iter().all(|r| r.mean_gap_rel.is_finite()), "{:?}", sw.rows);
    assert!(sw.rows[0].a_r > 0.3, "{:?}", sw.rows[0]);
    assert!(sw.monotone);
}

#[test]
fn the_shooting_root_is_a_fixed_point_of_the_prescribed_wall_march() {
    // system 1 (no jump): one branch; the march with the root's walls reproduces the root's
    // a_r(q) (the residual is that march against the root, computed by the solver)
    let mut s = system(1, 3);
    s.set_pressure(0.01).unwrap();
    let sol = adhesion::solve(&s, &AdhesionAccuracy::default(), None, None).unwrap();
    assert_eq!(sol.branches.len(), 1, "{:?}", sol.branches);
    assert!(sol.branches[0].stable);
    assert!(sol.residual < 1e-6, "{}", sol.residual);
    assert!((sol.branches[0].a_r / sol.a_r - 1.0).abs() < 1e-6);
}

/// The thin-slab grid (system 2, models 3 and 4, thin slabs, small loads): every point solves,
/// with its time and branches. `cargo test -p asperity --release --test adhesion -- --ignored
/// --nocapture issue_grid`.
#[test]
#[ignore]
fn issue_grid() {
    let mut times = Vec::new();
    let only = std::env::var("GRID_ONLY").ok();
    for sys in [2u8, 1] {
        for model in [3u8, 4] {
            for t in [0.05, 0.08, 0.1, 0.12, 0.15, 0.2, 0.3, 0.5] {
                for p in [1e-6, 1e-5, 1e-4, 1e-3, 5e-3, 0.02, 0.1] {
                    if let Some(o) = &only {
                        if *o != format!("{sys} {model} {t} {p:e}") {
                            continue;
                        }
                    }
                    let mut s = system(sys, model);
                    s.set_thickness_qr(t).unwrap();
                    s.set_pressure(p).unwrap();
                    let t0 = std::time::Instant::now();
                    let r = adhesion::solve(&s, &AdhesionAccuracy::default(), None, None);
                    let dt = t0.elapsed().as_secs_f64();
                    times.push(dt);
                    match r {
                        Ok(sol) => println!(
                            "sys {sys} m {model} t {t} p {p:e}: a_r {:.8e} shots {} res {:.1e} {:.1} ms branches {:?}",
                            sol.a_r,
                            sol.iterations,
                            sol.residual,
                            dt * 1e3,
                            sol.branches
                                .iter()
                                .map(|b| (b.branch.as_str(), (b.a_r * 1e4).round() / 1e4))
                                .collect::<Vec<_>>()
                        ),
                        Err(e) => println!("sys {sys} m {model} t {t} p {p:e}: ERROR {e} {:.1} ms", dt * 1e3),
                    }
                }
            }
        }
    }
    times.sort_by(|a, b| a.total_cmp(b));
    println!(
        "median {:.1} ms, worst {:.1} ms",
        times[times.len() / 2] * 1e3,
        times[times.len() - 1] * 1e3
    );
}

/// Prints the branches of system 2 (model 3, t·q_r = 0.1) against γ and p*.
#[test]
#[ignore]
fn branch_map() {
    for model in [3u8, 4] {
        for t in [0.1, 0.15, 0.2] {
            for frac in [0.2, 0.4, 0.6, 0.7, 0.8, 0.9, 1.0, 1.5, 2.0] {
                for p in [1e-6, 1e-4, 1e-2] {
                    let mut s = system(2, model);
                    s.set_thickness_qr(t).unwrap();
                    s.set_pressure(p).unwrap();
                    s.set_surface_energy_j_m2(s.surface_energy_j_m2() * frac).unwrap();
                    let sol = adhesion::solve(&s, &AdhesionAccuracy::default(), None, None).unwrap();
                    if sol.branches.len() > 1 {
                        println!(
                            "m {model} t {t} g {frac} p {p:e}: {:?}",
                            sol.branches
                                .iter()
                                .map(|b| (b.branch.as_str(), (b.a_r * 1e4).round() / 1e4))
                                .collect::<Vec<_>>()
                        );
                    }
                }
            }
        }
    }
}

/// Prints every scene's branches, marches and time over a map of hard scenes (thin slabs,
/// strong adhesion, tiny loads), to compare root finders:
/// `cargo test -p asperity --release --test adhesion -- --ignored --nocapture branch_census`.
#[test]
#[ignore]
fn branch_census() {
    let (mut total_ms, mut total_shots) = (0.0, 0);
    for model in [3u8, 4] {
        for t in [0.08, 0.1, 0.15, 0.2] {
            for frac in [0.4, 0.8, 1.0, 1.5] {
                for p in [1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3] {
                    let mut s = system(2, model);
                    s.set_thickness_qr(t).unwrap();
                    s.set_pressure(p).unwrap();
                    s.set_surface_energy_j_m2(s.surface_energy_j_m2() * frac).unwrap();
                    let t0 = std::time::Instant::now();
                    let r = adhesion::solve(&s, &AdhesionAccuracy::default(), None, None);
                    let ms = t0.elapsed().as_secs_f64() * 1e3;
                    total_ms += ms;
                    let sol = match r {
                        Ok(sol) => sol,
                        Err(e) => {
                            println!("m {model} t {t} g {frac} p {p:e}: ERROR {e} {ms:.0} ms");
                            continue;
                        }
                    };
                    total_shots += sol.iterations;
                    let worst = sol.branches.iter().map(|b| b.residual).fold(0.0, f64::max);
                    println!(
                        "m {model} t {t} g {frac} p {p:e}: {} {:?} worst residual {worst:.1e} shots {} {ms:.0} ms",
                        sol.branches.len(),
                        sol.branches
                            .iter()
                            .map(|b| format!("{:.5e}", b.a_r))
                            .collect::<Vec<_>>(),
                        sol.iterations
                    );
                }
            }
        }
    }
    println!("total {total_ms:.0} ms, {total_shots} shots");
}

#[test]
fn hysteresis_window_has_three_branches_and_brackets_the_load() {
    // system 2, model 3, t·q_r = 0.1 at 0.8 γ_s: between pull-off and jump-in the loading branch
    // (small a_r), an unstable one and the unloading branch (a_r ≈ 0.42) coexist
    let mut s = system(2, 3);
    s.set_thickness_qr(0.1).unwrap();
    s.set_surface_energy_j_m2(s.surface_energy_j_m2() * 0.8).unwrap();
    s.set_pressure(1e-5).unwrap();
    let acc = AdhesionAccuracy::default();
    let sol = adhesion::solve(&s, &acc, None, None).unwrap();
    let b = &sol.branches;
    assert_eq!(b.len(), 3, "{b:?}");
    assert!(b[0].stable && !b[1].stable && b[2].stable, "{b:?}");
    assert!(b[0].a_r < b[1].a_r && b[1].a_r < b[2].a_r, "{b:?}");
    assert_eq!(sol.branch, Branch::Loading);
    assert!((sol.a_r - b[0].a_r).abs() < 1e-15);
    assert_eq!(sol.unloading_a_r, Some(b[2].a_r));
    // the effective coarse-scale surface energy rises from branch to branch (C orders them)
    assert!(b[0].gamma_coarse < b[1].gamma_coarse && b[1].gamma_coarse < b[2].gamma_coarse);
    let w = asperity::theory::hysteresis::window_around(&s, &acc, None)
        .unwrap()
        .unwrap();
    // at 0.8 γ_s the unloading branch holds at every positive load (a_r ≈ 0.42 from p* = 1e-5
    // down to 1e-12: pull-off needs a tensile load), so the window has no pull-off edge
    assert_eq!(w.pull_off_pressure, None, "{w:?}");
    let hi = w.jump_in_pressure.unwrap();
    assert!(1e-5 < hi, "{w:?}");
    let mut t = s.clone();
    t.set_pressure(asperity::input::scene::PRESSURE_RANGE.0).unwrap();
    let o = adhesion::solve(&t, &acc, None, None).unwrap();
    assert_eq!(o.branches.len(), 3, "{:?}", o.branches);
    assert!((o.branches[2].a_r / b[2].a_r - 1.0).abs() < 0.01, "{:?}", o.branches);
    // just above the jump-in a single stable branch is left: the upper one
    let mut t = s.clone();
    t.set_pressure(hi * 1.1).unwrap();
    let o = adhesion::solve(&t, &acc, None, None).unwrap();
    assert_eq!(o.branches.iter().filter(|b| b.stable).count(), 1, "{:?}", o.branches);
    assert!(o.a_r > 0.1, "{}", o.a_r);
}

#[test]
fn the_thin_slab_grid_converges_everywhere() {
    // the thin-slab grid where an iterated map loses contraction (system 2, models 3 and 4,
    // t·q_r 0.08–0.15, p* ≤ 1e-4): every point ends converged, on a stable branch, with
    // 0 < a_r ≤ 1 and a self-consistent energy balance
    for model in [3u8, 4] {
        for t in [0.08, 0.1, 0.12, 0.15] {
            for p in [1e-6, 1e-5, 1e-4] {
                let mut s = system(2, model);
                s.set_thickness_qr(t).unwrap();
                s.set_pressure(p).unwrap();
                let sol = adhesion::solve(&s, &AdhesionAccuracy::default(), None, None)
                    .unwrap_or_else(|e| panic!("model {model}, t {t}, p {p}: {e}"));
                assert!(sol.a_r > 0.0 && sol.a_r <= 1.0, "{}", sol.a_r);
                assert!(
                    sol.residual <= AdhesionAccuracy::default().tol * 1e3,
                    "{}",
                    sol.residual
                );
                assert!(sol.branches.iter().any(|b| b.stable && (b.a_r - sol.a_r).abs() < 1e-15));
            }
        }
    }
}

/// The accuracy ladder behind the default `AdhesionAccuracy` (BENCHMARKS.md): the
/// relative a_r error of one adhesive solve against (192, 40) and its time, for rungs (steps
/// per ln q, points per width) on system I (model 3, p* = 0.01) and system II (model 4,
/// p* = 0.005, t·q_r = ∞ and 0.25). `cargo test -p asperity --test adhesion -- --ignored
/// --nocapture ladder`.
#[test]
#[ignore]
fn ladder() {
    let acc = |s: f64, p: f64| AdhesionAccuracy {
        steps_per_ln_q: s,
        points_per_width: p,
        explore_branches: false,
        ..AdhesionAccuracy::default()
    };
    for (n, model, t) in [(1u8, 3u8, f64::INFINITY), (2, 4, f64::INFINITY), (2, 4, 0.25)] {
        let mut s = system(n, model);
        s.set_thickness_qr(t).unwrap();
        let reference = adhesion::solve(&s, &acc(192.0, 40.0), None, None).unwrap().a_r;
        for (st, pp) in [
            (8.0, 5.0),
            (12.0, 5.0),
            (16.0, 6.0),
            (24.0, 8.0),
            (24.0, 10.0),
            (32.0, 10.0),
            (48.0, 12.0),
        ] {
            let a = acc(st, pp);
            let t0 = std::time::Instant::now();
            let mut reps = 0;
            let mut a_r = 0.0;
            while reps < 3 || t0.elapsed().as_secs_f64() < 0.3 {
                a_r = adhesion::solve(&s, &a, None, None).unwrap().a_r;
                reps += 1;
            }
            println!(
                "system {n} model {model} t {t} ({st}, {pp}): a_r {a_r:.8} rel. error {:.2e} {:.1} ms",
                (a_r / reference - 1.0).abs(),
                t0.elapsed().as_secs_f64() / reps as f64 * 1e3
            );
        }
    }
}

#[test]
fn a_thickness_sweep_finds_the_window_edges_in_t() {
    // system II, model 3 at 0.8 γ_s and p* = 1e-5: at t·q_r = 0.1 three branches coexist
    // (`hysteresis_window_has_three_branches_and_brackets_the_load`). Thinning the slab from
    // 0.16, the small-contact branch ends at a fold (the contact jumps in); thickening it from
    // 0.06, the large-contact branch ends at another (the window is narrow: 7 values from 0.04
    // to 0.4 put none inside it, and the sweep then shows the jump between two rows only). Independent check of each edge: the
    // number of stable branches, solved directly 2 % on either side, and which branch is left.
    use asperity::theory::hysteresis::{self, EdgeKind};
    use asperity::theory::knob::{self, Knob, KnobSpec};
    let mut s = system(2, 3);
    s.set_surface_energy_j_m2(s.surface_energy_j_m2() * 0.8).unwrap();
    s.set_pressure(1e-5).unwrap();
    let spec = KnobSpec {
        knob: Knob::Thickness,
        from: 0.06,
        to: 0.16,
        points: 11,
    };
    let opts = Options {
        adhesion_error_estimate: false,
        ..Options::default()
    };
    let pts = knob::knob_sweep(&s, &spec, &opts, false, None).unwrap();
    let edges = hysteresis::knob_edges(&s, Knob::Thickness, &pts, &opts.adhesion, None).unwrap();
    // a precision outside the engine's range is refused before any bisection
    for rel in [0.0, -0.1, f64::NAN, 0.9] {
        let r = hysteresis::knob_edges_to(&s, Knob::Thickness, &pts, &opts.adhesion, rel, None);
        assert!(
            matches!(r, Err(asperity::error::Error::Invalid { .. })),
            "rel {rel}: {r:?}"
        );
    }
    for p in &pts {
        let e = p.result.as_ref().unwrap();
        eprintln!(
            "t {:.4}: {:?}",
            p.value,
            e.branches.iter().map(|b| (b.a_r, b.stable)).collect::<Vec<_>>()
        );
    }
    eprintln!("{edges:?}");
    assert!(
        edges.iter().any(|e| e.kind == EdgeKind::JumpIn) && edges.iter().any(|e| e.kind == EdgeKind::PullOff),
        "{edges:?}"
    );
    let acc = AdhesionAccuracy::default();
    let stable_at = |t: f64| {
        let mut x = s.clone();
        x.set_thickness_qr(t).unwrap();
        adhesion::solve(&x, &acc, None, None)
            .unwrap()
            .branches
            .into_iter()
            .filter(|b| b.stable)
            .map(|b| b.a_r)
            .collect::<Vec<f64>>()
    };
    for e in &edges {
        let (below, above) = (stable_at(e.value * 0.98), stable_at(e.value * 1.02));
        assert_ne!(below.len() >= 2, above.len() >= 2, "{e:?}: {below:?} {above:?}");
        // the window lies between the two edges: thick slabs keep the small contact only, thin
        // ones the large; the branch left outside is the lower one at the pull-off edge
        let (inside, outside) = if below.len() >= 2 {
            (&below, &above)
        } else {
            (&above, &below)
        };
        let left_lower = (outside[0] - inside[0]).abs() < (outside[0] - inside[inside.len() - 1]).abs();
        assert_eq!(left_lower, e.kind == EdgeKind::PullOff, "{e:?}: {inside:?} {outside:?}");
    }
}

#[test]
fn a_solve_does_not_depend_on_what_its_thread_solved_before() {
    // the propagator keeps its FFT plans per thread across solves (adhesion::heat): a plan
    // must depend on its length only, or the last bits of a result (and so of a sweep, whose
    // loads land on whichever rayon thread is free) depend on the thread's history. System 1
    // in a fresh thread, and in a thread that first solved a thin slab of system 2 (other grid
    // sizes planned first): the same bits, error estimate included.
    let solve = |warm_up: bool| {
        std::thread::spawn(move || {
            if warm_up {
                let mut s = Preset::resolve("system-2").unwrap().scene().unwrap();
                s.set_model(Model::named(4).unwrap()).unwrap();
                s.set_thickness_qr(0.25).unwrap();
                engine::evaluate(&s, &Options::default()).unwrap();
            }
            let s = Preset::resolve("system-1").unwrap().scene().unwrap();
            let e = engine::evaluate(&s, &Options::default()).unwrap();
            (e.stats.a_r.to_bits(), e.error_estimate.to_bits(), e.residual.to_bits())
        })
        .join()
        .unwrap()
    };
    assert_eq!(solve(false), solve(true));
}
