//! Tiny loads with strong adhesion: every solve ends (converged with an error bar, or one line
//! saying what could not be resolved) with bounded memory; the runaway wall of the march.

mod common;

use asperity::error::Error;
use asperity::input::scene::Scene;
use asperity::theory::adhesion::{self, AdhesionAccuracy};
use asperity::theory::{engine, hysteresis};
use asperity::tolerances::{ADHESION_DEFAULT_REL, RUNAWAY_WALL_REL, RUNAWAY_WALL_SPREAD_REL};

fn scene(model: u8, t: f64, gamma: f64, p: f64) -> Scene {
    common::at(2, model, t, gamma, p)
}

/// The scenes of the three `run` commands that aborted on a 70 GB allocation or did not end
/// (system II; model, t·q_r, γ_s, p*).
const HARD: [(u8, f64, f64, f64); 3] = [
    (2, 248.9469228963643, 1.4950200548345913, 4.068548385153941e-07),
    (2, f64::INFINITY, 1.4608574406735102, 5.326071364638265e-09),
    (1, 587.0, 0.004, 1.25e-9),
];

/// What `run` computes of the adhesive theory (the evaluation with its error estimate, and the
/// window where two stable branches coexist) ends converged with a finite error bar or with
/// one line naming what could not be resolved.
#[test]
fn the_tiny_load_commands_end_converged_or_refuse_in_one_line() {
    for (model, t, gamma, p) in HARD {
        let s = scene(model, t, gamma, p);
        let opts = engine::Options::default();
        match engine::evaluate(&s, &opts) {
            Ok(ev) => {
                assert!(ev.stats.a_r > 0.0 && ev.stats.a_r <= 1.0, "{p}: a_r {}", ev.stats.a_r);
                assert!(
                    ev.error_estimate.is_finite() && ev.error_estimate > 0.0,
                    "{p}: error {}",
                    ev.error_estimate
                );
                assert!(ev.residual <= opts.adhesion.tol * 1e3, "{p}: residual {}", ev.residual);
                let sol = ev.adhesive.as_deref().expect("adhesive");
                let w = hysteresis::window_around_from(&s, sol, &opts.adhesion, None).expect("window");
                let stable = ev.branches.iter().filter(|b| b.stable).count();
                assert_eq!(w.is_some(), stable >= 2, "{p}: {w:?}");
                if let Some(w) = w {
                    // the jump-in lies above the load, the pull-off below it
                    assert!(w.jump_in_pressure.is_none_or(|j| j > p), "{p}: {w:?}");
                    assert!(w.pull_off_pressure.is_none_or(|o| o < p), "{p}: {w:?}");
                }
            }
            Err(e @ Error::NotConverged { .. }) => {
                let line = e.to_string();
                assert!(!line.contains('\n') && line.contains("did not converge"), "{line}");
            }
            Err(e) => panic!("{p}: {e}"),
        }
    }
}

/// The root scan at the bottom of the load range (the window's pull-off check) shoots walls of
/// σ_a* ~ 1e7 behind tiny contact areas: the solve ends with bounded grids and the same
/// branches as at a thousand times the load. With strong adhesion (γ_s = 1.5 J/m²) the one
/// branch is adhesion's, blind to loads that small (a_r the same); with weak adhesion
/// (γ_s = 0.004 J/m²) the contact is the load's, a_r ∝ p* (the scaling of tiny loads).
#[test]
fn the_bottom_of_the_load_range_solves_with_bounded_grids() {
    let acc = AdhesionAccuracy::default();
    for (k, (model, t, gamma, _)) in [HARD[0], HARD[2]].into_iter().enumerate() {
        let lo = adhesion::solve(&scene(model, t, gamma, 1e-12), &acc, None, None).unwrap();
        let hi = adhesion::solve(&scene(model, t, gamma, 1e-9), &acc, None, None).unwrap();
        assert_eq!(
            lo.branches.len(),
            hi.branches.len(),
            "{:?} {:?}",
            lo.branches,
            hi.branches
        );
        assert!(lo.residual <= acc.tol * 1e3 && hi.residual <= acc.tol * 1e3);
        let ratio = if k == 0 {
            lo.a_r / hi.a_r
        } else {
            (lo.a_r / 1e-12) / (hi.a_r / 1e-9)
        };
        assert!((ratio - 1.0).abs() < 1e-2, "gamma {gamma}: ratio {ratio}");
    }
}

/// At tiny loads with strong adhesion a_r falls from 1 to ~p*/√v inside the march's first
/// step; the first step is therefore graded from v ≈ p*² (`adhesion::grid`). Without it the
/// default resolution found a spurious loading branch (a_r 6.7e-5 at 24 steps per ln q,
/// 1.9e-4 at 192, gone only at 384, where the one branch is a_r = 0.644). The default answer
/// against a 4× finer march with twice the points per width: the same branches, each a_r
/// within the default's error bar.
#[test]
fn the_default_resolution_converges_at_tiny_loads_with_strong_adhesion() {
    let fine = AdhesionAccuracy {
        steps_per_ln_q: 4.0 * AdhesionAccuracy::default().steps_per_ln_q,
        points_per_width: 2.0 * AdhesionAccuracy::default().points_per_width,
        ..AdhesionAccuracy::default()
    };
    for (model, t, gamma, p) in HARD {
        let s = scene(model, t, gamma, p);
        let ev = engine::evaluate(&s, &engine::Options::default()).unwrap();
        let reference = adhesion::solve(&s, &fine, None, None).unwrap();
        let stable = |b: &[adhesion::BranchState]| b.iter().filter(|x| x.stable).map(|x| x.a_r).collect::<Vec<_>>();
        let (a, b) = (stable(&ev.branches), stable(&reference.branches));
        assert_eq!(a.len(), b.len(), "p* {p}: {a:?} against {b:?}");
        for (x, y) in a.iter().zip(&b) {
            assert!(
                (x - y).abs() <= ev.error_estimate,
                "p* {p}: a_r {x} against {y}, error bar {}",
                ev.error_estimate
            );
        }
    }
    // the scene of the spurious branch: one branch, the adhesive one
    let (model, t, gamma, p) = HARD[0];
    let ev = engine::evaluate(&scene(model, t, gamma, p), &engine::Options::default()).unwrap();
    assert_eq!(ev.branches.len(), 1, "{:?}", ev.branches);
}

/// A prescribed wall that jumps from 0 to σ_a* = 1e3, 1e6 or 1e9 within one step (at
/// p* = 1e-9): the march offsets its grid instead of spanning the jump (1e9 would need 1e12
/// nodes), and once the wall is far nothing more is lost: a_r stays at its value after the
/// jump, and the three heights agree (the slowest wall's image is resolved on the grid, the
/// faster ones are offset: measured spread 3e-5 of a_r).
#[test]
fn a_wall_that_runs_away_leaves_the_contact_as_it_was() {
    let s = scene(1, f64::INFINITY, 0.1, 1e-9);
    let acc = AdhesionAccuracy::default();
    let q_jump = s.spectrum().breakpoints()[0] * 1.5;
    let run = |height: f64| {
        let (q, a) = adhesion::propagate_with_wall(&s, &acc, |q| if q < q_jump { 0.0 } else { height }, false).unwrap();
        let k = q.partition_point(|&x| x < q_jump) + 1;
        (a[k], *a.last().unwrap())
    };
    let ends: Vec<f64> = [1e3, 1e6, 1e9]
        .into_iter()
        .map(|height| {
            let (after, end) = run(height);
            assert!(end > 0.0 && end < 1.0, "{height}: {end}");
            assert!(
                (end / after - 1.0).abs() < RUNAWAY_WALL_REL,
                "{height}: {after} -> {end}"
            );
            end
        })
        .collect();
    for e in &ends[1..] {
        assert!((e / ends[0] - 1.0).abs() < RUNAWAY_WALL_SPREAD_REL, "{ends:?}");
    }
}

/// System II, model 4, t·q_r = 0.1186, γ_s = 0.157 J/m², p* = 3.5e-7: at the default
/// resolution the loading root sits on a jump of the discrete H (where γ at the end of the
/// march's first step changes sign; `adhesion::strategy::RESTEP`), where Brent's bracket
/// collapses at a residual of 3.2e-3. The solve tries again at slightly more steps per ln q:
/// it meets its tolerance, and a_r agrees with a 4× finer march
/// with twice the points per width within the default's error bar and within
/// [`ADHESION_DEFAULT_REL`].
#[test]
fn a_root_where_the_first_steps_end_gamma_changes_sign_converges() {
    let s = scene(4, 0.11858657076247323, 0.157, 3.5030939862794857e-07);
    let opts = engine::Options::default();
    let ev = engine::evaluate(&s, &opts).expect("converges");
    assert!(ev.residual <= opts.adhesion.tol, "residual {}", ev.residual);
    let fine = AdhesionAccuracy {
        steps_per_ln_q: 4.0 * AdhesionAccuracy::default().steps_per_ln_q,
        points_per_width: 2.0 * AdhesionAccuracy::default().points_per_width,
        ..AdhesionAccuracy::default()
    };
    let reference = adhesion::solve(&s, &fine, None, None).unwrap();
    assert_eq!(ev.branches.len(), reference.branches.len(), "{:?}", ev.branches);
    let (a, b) = (ev.stats.a_r, reference.a_r);
    assert!(
        (a - b).abs() <= ev.error_estimate,
        "a_r {a} against {b}, error bar {}",
        ev.error_estimate
    );
    assert!((a / b - 1.0).abs() <= ADHESION_DEFAULT_REL, "a_r {a} against {b}");
}
