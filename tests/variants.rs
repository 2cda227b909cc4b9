//! The literature variants YP08 and Xu24 against their own formulas, evaluated here with
//! methods that share no code with the solver (docs/physics.md §3.4).

mod common;

use asperity::error::Error;
use asperity::input::model::{Model, ModelKind, FUDGE_GAMMA_DEFAULT};
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::theory::persson::{self, Accuracy};
use asperity::tolerances::*;
use statrs::function::erf::erf;
use std::f64::consts::PI;

fn system1(model: Model, p: f64) -> Scene {
    common::dry(1, model).with_pressure(p).unwrap()
}

fn solve(s: &Scene) -> persson::Solution {
    persson::solve(s, &Accuracy::default()).unwrap()
}

/// YP08 on the half-space: dv/dG = S(a(v))/4 in the gradient fraction G is autonomous, so
/// v(q_s) solves 4∫₀^v dv'/S(a(v')) = 1, S(a) = γ_f + (1 − γ_f)a², a = erf(p/√(2v)).
/// Simpson in ln v' and bisection.
fn yp08_oracle(gamma_f: f64, p: f64) -> f64 {
    common::autonomous_variance(p, |a| 1.0 / (gamma_f + (1.0 - gamma_f) * a * a))
}

#[test]
fn yp08_matches_its_autonomous_oracle() {
    for g in [FUDGE_GAMMA_DEFAULT, 0.2, 0.8] {
        for p in [1e-5, 0.01, 0.2, 1.0] {
            // the oracle is good to ~1e-9; the ODE at its default rtol to ~2e-7 for γ_f = 0.2
            let acc = Accuracy {
                rtol: 1e-9,
                ..Accuracy::default()
            };
            let sol = persson::solve(&system1(Model::fudge(ModelKind::Yp08, g).unwrap(), p), &acc).unwrap();
            let vo = yp08_oracle(g, p);
            let v = sol.width * sol.width;
            assert!((v / vo - 1.0).abs() < ORACLE_REL, "γ_f {g} p* {p}: {v} vs {vo}");
        }
    }
}

#[test]
fn yp08_at_0_45_is_model_2() {
    // S = 0.45 + 0.55a² is Persson's W_P of [S-16] with c₁ = 0.55: model 2
    for p in [1e-3, 0.05, 0.5] {
        let a = solve(&system1(Model::fudge(ModelKind::Yp08, 0.45).unwrap(), p)).a_r;
        let b = solve(&system1(Model::named(2).unwrap(), p)).a_r;
        assert!((a / b - 1.0).abs() < MODEL1_ERF_REL, "p* {p}: {a} vs {b}");
    }
}

/// Xu24 on the half-space: a = erf(√2 p/√S(a)), S(a) = γ_f + (1 − γ_f)a (v₁ = 1/4). Solved
/// here by the secant method on a − erf(·), started from erf(√2p) and erf(√(2/γ_f)p).
fn xu24_oracle(gamma_f: f64, p: f64) -> f64 {
    let f = |a: f64| a - erf(2f64.sqrt() * p / (gamma_f + (1.0 - gamma_f) * a).sqrt());
    let (mut x0, mut x1) = (erf(2f64.sqrt() * p), erf((2.0 / gamma_f).sqrt() * p));
    for _ in 0..100 {
        let (f0, f1) = (f(x0), f(x1));
        if f1 == f0 {
            break;
        }
        let x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
        x0 = x1;
        x1 = x2.clamp(1e-300, 1.0);
        if (x1 - x0).abs() <= 1e-15 * x1 {
            break;
        }
    }
    x1
}

#[test]
fn xu24_matches_its_closed_form() {
    for g in [FUDGE_GAMMA_DEFAULT, 0.2, 0.8] {
        for p in [1e-6, 1e-3, 0.05, 0.3, 1.0] {
            let sol = solve(&system1(Model::fudge(ModelKind::Xu24, g).unwrap(), p));
            let a = xu24_oracle(g, p);
            assert!(
                (sol.a_r / a - 1.0).abs() < ORACLE_REL,
                "γ_f {g} p* {p}: {} vs {a}",
                sol.a_r
            );
            // the resolution's last point is the final a_r; a_r(q) never rises with q
            let r = &sol.resolution;
            assert!((r.last().unwrap().a_r / sol.a_r - 1.0).abs() < ORACLE_REL);
            assert!(r.windows(2).all(|w| w[1].a_r <= w[0].a_r * (1.0 + 1e-12)));
        }
    }
    // small p*: a_r/p* → (2/√π)√(2/γ_f) (S → γ_f as a → 0); 2.4624 for γ_f = 0.42
    let p = 1e-7;
    let a = solve(&system1(Model::fudge(ModelKind::Xu24, 0.42).unwrap(), p)).a_r;
    let slope = 2.0 / PI.sqrt() * (2.0f64 / 0.42).sqrt();
    assert!(
        (a / p / slope - 1.0).abs() < ASYMPTOTE_SLOPE_REL,
        "{} vs {slope}",
        a / p
    );
    assert!((slope - 2.4624).abs() < 1e-4);
}

#[test]
fn unit_fudge_gamma_is_original_persson() {
    // γ_f = 1: S ≡ 1 for both variants, a_r = erf(√2 p*)
    for kind in [ModelKind::Yp08, ModelKind::Xu24] {
        for p in [1e-4, 0.1, 0.7] {
            let a = solve(&system1(Model::fudge(kind, 1.0).unwrap(), p)).a_r;
            let e = erf(2f64.sqrt() * p);
            assert!((a / e - 1.0).abs() < MODEL1_ERF_REL, "{kind:?} p* {p}: {a} vs {e}");
        }
    }
}

#[test]
fn variants_refuse_adhesion_and_slabs_and_bad_gamma() {
    for kind in [ModelKind::Yp08, ModelKind::Xu24] {
        let m = Model::fudge(kind, 0.42).unwrap();
        // each setter refuses what the variant does not define, and leaves the scene as it was
        let mut s = system1(m, 0.01);
        let before = s.clone();
        assert!(
            matches!(s.set_surface_energy_j_m2(0.05), Err(Error::Unsupported(ref t)) if t.contains("adhesionless half-space"))
        );
        assert!(matches!(s.set_thickness_qr(1.0), Err(Error::Unsupported(_))));
        assert_eq!(s, before);
        // and so does a scene built with the variant on an adhesive slab
        let adhesive = Preset::resolve("system-2").unwrap().scene().unwrap();
        assert!(matches!(adhesive.with_model(m), Err(Error::Unsupported(_))));
        for g in [0.0, -0.1, 1.5, f64::NAN] {
            let e = Model::fudge(kind, g).unwrap_err().to_string();
            assert!(e.contains("model.fudge_gamma"), "{e}");
        }
    }
}

#[test]
fn preset_keys_for_the_variants() {
    let base = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/presets/system-1.toml"))
        .unwrap()
        .replace("surface_energy_j_m2 = 0.05", "surface_energy_j_m2 = 0.0");
    let text = base.replace("variant = 3 ", "variant = \"xu24\"\nfudge_gamma = 0.3\n");
    let m = Preset::parse(&text, "t").unwrap().model().unwrap();
    assert_eq!(m.kind, ModelKind::Xu24);
    assert!((m.fudge_gamma().unwrap() - 0.3).abs() < 1e-15);
    let text = base.replace("variant = 3 ", "variant = 2\nfudge_gamma = 0.3\n");
    let e = Preset::parse(&text, "t").unwrap_err().to_string();
    assert!(e.contains("fudge_gamma"), "{e}");
    // on the adhesive preset the variant is refused in one line
    let text = base.replace("surface_energy_j_m2 = 0.0", "surface_energy_j_m2 = 0.05");
    let text = text.replace("variant = 3 ", "variant = \"yp08\"\n");
    let e = Preset::parse(&text, "t").unwrap_err().to_string();
    assert!(
        e.contains("adhesionless half-space only") && e.lines().count() == 1,
        "{e}"
    );
}
