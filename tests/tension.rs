//! The theory under tension (docs/physics.md §6.2, `theory::adhesion::tension`): the contact
//! branch continued to p* ≤ 0 joins the unloading branch of p* > 0, holds less contact the
//! more tension it carries, ends at a fold (the pull-off) inside the closed-form bound, and
//! does not exist without adhesion.

use asperity::elastic::slab::slab_factor_at;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::theory::adhesion::{pull_off, solve, tensile_branch, tension_bound, AdhesionAccuracy};
use asperity::theory::cycle::PULL_OFF_REL;
use asperity::theory::engine::Options;
use asperity::tolerances::{TENSION_BOUND_REL, TENSION_CONTINUITY_REL};

fn chart() -> AdhesionAccuracy {
    AdhesionAccuracy {
        explore_branches: true,
        ..Options::chart().adhesion
    }
}

/// System II on a thin slab (t·q_r = 0.15) at the preset's γ_s: contact at p* = 0.
fn thin_slab() -> Scene {
    Preset::resolve("system-2")
        .unwrap()
        .scene()
        .unwrap()
        .with_thickness_qr(0.15)
        .unwrap()
}

#[test]
fn the_contact_branch_at_zero_load_continues_the_unloading_branch() {
    let scene = thin_slab();
    let acc = chart();
    let above = solve(&scene.clone().with_pressure(1e-7).unwrap(), &acc, None, None).unwrap();
    let upper = above
        .branches
        .iter()
        .filter(|b| b.stable)
        .map(|b| b.a_r)
        .fold(f64::NAN, f64::max);
    let at_zero = tensile_branch(&scene, 0.0, &acc, None)
        .unwrap()
        .expect("contact at p* = 0");
    assert!(
        (at_zero.a_r / upper - 1.0).abs() <= TENSION_CONTINUITY_REL,
        "p* = 0: {} against p* = 1e-7: {upper}",
        at_zero.a_r
    );
}

#[test]
fn the_pull_off_is_a_fold_inside_the_bound() {
    let scene = thin_slab();
    let acc = chart();
    let po = pull_off(&scene, 1e-4, PULL_OFF_REL, &acc, None).unwrap();
    assert!(po.pressure <= 0.0 && po.lost < po.pressure, "{po:?}");
    assert!(
        po.pressure - po.lost <= PULL_OFF_REL * po.pressure.abs().max(1e-4 * PULL_OFF_REL),
        "{po:?}"
    );
    assert!(-po.lost <= po.bound, "{po:?}");
    // held at the pull-off, gone beyond it
    let held = tensile_branch(&scene, po.pressure, &acc, None).unwrap();
    assert!(held.is_some_and(|s| s.a_r > 0.0 && (s.a_r / po.a_r - 1.0).abs() < 1e-9));
    assert!(tensile_branch(&scene, po.lost, &acc, None).unwrap().is_none());
    // the more tension, the less contact, down the path
    let a: Vec<f64> = po.path.iter().map(|s| s.a_r).collect();
    assert!(!a.is_empty() && a.windows(2).all(|w| w[1] <= w[0]), "{a:?}");
    assert!(po.a_r <= a[a.len() - 1], "{po:?}");
}

#[test]
fn the_bound_is_the_coarsest_griffith_stress() {
    for t in [f64::INFINITY, 0.3, 0.15] {
        let scene = thin_slab().with_thickness_qr(t).unwrap();
        let s = scene.summary();
        let q_l = scene.spectrum().q_l();
        let griffith =
            s.k_griffith * (q_l * s.contact_modulus_pa * slab_factor_at(q_l, scene.thickness_m()) * s.gamma).sqrt();
        let cap = if s.sigma_a_cap {
            s.gamma / s.range_m
        } else {
            f64::INFINITY
        };
        let want = griffith.min(cap) / scene.stress_unit();
        let got = tension_bound(&scene, &chart());
        assert!(
            (got / want - 1.0).abs() <= TENSION_BOUND_REL,
            "t*q_r {t}: {got} vs {want}"
        );
        // no contact branch beyond it
        assert!(tensile_branch(&scene, -want * (1.0 + 1e-9), &chart(), None)
            .unwrap()
            .is_none());
    }
}

#[test]
fn without_adhesion_nothing_holds_tension() {
    let scene = thin_slab().without_adhesion();
    assert!(tensile_branch(&scene, 0.0, &chart(), None).unwrap().is_none());
    let po = pull_off(&scene, 1e-4, PULL_OFF_REL, &chart(), None).unwrap();
    assert_eq!((po.pressure, po.a_r, po.path.len()), (0.0, 0.0, 0));
}

#[test]
fn a_positive_load_is_refused() {
    assert!(tensile_branch(&thin_slab(), 1e-4, &chart(), None).is_err());
}
