//! Mean gap and elastic energy: the energy route against the Yang–Persson closed
//! form, limits, monotonicity, Persson's small-load asymptote, the system-1 values and hard
//! cases.

mod common;

use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::surface::spectrum::{Normalisation, SelfAffine, Spectrum};
use asperity::theory::engine::{self, Options};
use asperity::theory::sweep::{self, SweepSpec};
use asperity::theory::{energy, gap};
use asperity::tolerances::*;

fn system1(model: Model) -> Scene {
    common::dry(1, model)
}

fn with_p(scene: &Scene, p: f64) -> Scene {
    let mut s = scene.clone();
    s.set_pressure(p).unwrap();
    s
}

fn energy_route(scene: &Scene, p: f64) -> gap::MeanGap {
    gap::mean_gap(&with_p(scene, p), &Options::default()).unwrap()
}

#[test]
fn closed_form_agrees_with_energy_route() {
    let m1 = Model::named(1).unwrap();
    // W only in the energy (α = 0), γ_P = 0.45: Persson's 2007 weighting
    let persson = Model::custom(0.55, 0.0, 0.0, 1.0, false).unwrap();
    let mut thin = system1(m1);
    thin.set_thickness_qr(1.0).unwrap();
    for scene in [system1(m1), system1(persson), thin] {
        let ps = [1e-4, 1e-2, 0.1, 0.5];
        let cf = gap::closed_form(&scene, &ps).unwrap();
        for (&p, &c) in ps.iter().zip(&cf) {
            let er = energy_route(&scene, p);
            let rel = (er.relative - c).abs() / c;
            assert!(
                rel < GAP_CLOSED_FORM_REL,
                "{} t = {}: p* = {p}: energy route {} vs closed form {c} (rel {rel:.1e})",
                scene.model().label(),
                scene.thickness_qr(),
                er.relative
            );
            // the Richardson estimate covers the grid error (factor 3); the rest, ≤ 1e-5, is the
            // accuracy of U itself (ODE rtol 1e-9, thin-slab slab factors)
            assert!(
                (er.relative - c).abs() <= 3.0 * er.error + 1e-5 * c,
                "p* = {p}: {er:?} vs {c}"
            );
            assert!((er.metres - er.relative * scene.spectrum().rms_height()).abs() < 1e-18);
        }
    }
}

#[test]
fn closed_form_needs_its_model() {
    let e = gap::closed_form(&system1(Model::named(3).unwrap()), &[0.01]).unwrap_err();
    assert!(e.to_string().contains("closed form"), "{e}");
    assert_eq!(gap::closed_form_gamma_p(&system1(Model::named(1).unwrap())), Some(1.0));
}

#[test]
fn system1_model1_values() {
    let scene = system1(Model::named(1).unwrap());
    for (p, want) in [(0.01, 1.85), (0.1, 0.23)] {
        let g = energy_route(&scene, p).relative;
        assert!(
            (g - want).abs() < SYSTEM1_GAP_ABS,
            "p* = {p}: u/h_rms = {g}, want ~{want}"
        );
    }
}

#[test]
fn energy_at_full_contact_is_u_ela_f() {
    for n in 1..=4 {
        for t in [f64::INFINITY, 0.5] {
            let mut s = system1(Model::named(n).unwrap());
            s.set_thickness_qr(t).unwrap();
            let p = gap::full_contact_pressure(&s) * 1.5;
            let ev = engine::evaluate(&with_p(&s, p), &Options::default()).unwrap();
            let uf = s.full_contact_energy();
            assert!(
                ((ev.elastic_energy - uf) / uf).abs() < FULL_CONTACT_ENERGY_REL,
                "model {n} t = {t}: U = {} vs u_ela^(f) = {uf}",
                ev.elastic_energy
            );
            // and the gap vanishes there
            let g = energy_route(&s, p).relative;
            assert!(g.abs() < 1e-12, "model {n} t = {t}: gap at full contact {g}");
        }
    }
}

#[test]
fn energy_small_load_scaling() {
    let opts = Options::default();
    let u = |s: &Scene, p: f64| engine::evaluate(&with_p(s, p), &opts).unwrap().elastic_energy;
    // U ∝ p* (∝ a_r) at small load
    let m1 = system1(Model::named(1).unwrap());
    let (u7, u8) = (u(&m1, 1e-7), u(&m1, 1e-8));
    assert!(
        ((u7 / 1e-7) / (u8 / 1e-8) - 1.0).abs() < SMALL_LOAD_ENERGY_REL,
        "{u7} {u8}"
    );
    // U ∝ a_r W: with the same a_r(q) (α = 0) and W = 0.45 + 0.55a², U → 0.45 U_model1
    let w = system1(Model::custom(0.55, 0.0, 0.0, 1.0, false).unwrap());
    let ratio = u(&w, 1e-7) / u7;
    assert!((ratio - 0.45).abs() < 0.45 * SMALL_LOAD_ENERGY_REL, "ratio {ratio}");
    // reduced energy unit
    assert!((energy::energy_unit(&m1) - 25e6 * m1.spectrum().rms_height()).abs() < 1e-6);
}

#[test]
fn gap_decreases_and_vanishes_for_every_model() {
    for n in 1..=4 {
        let s = system1(Model::named(n).unwrap());
        let spec = SweepSpec {
            from: 1e-6,
            to: 10.0,
            points: 29,
        };
        let sw = sweep::sweep(&s, &spec, &Options::default(), None).unwrap();
        assert!(sw.monotone, "model {n}");
        for w in sw.rows.windows(2) {
            assert!(
                w[1].mean_gap_rel < w[0].mean_gap_rel || w[1].mean_gap_rel < 1e-12,
                "model {n}: {w:?}"
            );
            assert!(w[1].a_r >= w[0].a_r);
            assert!(w[1].elastic_energy >= w[0].elastic_energy);
        }
        let last = sw.rows.last().unwrap();
        assert!(
            last.mean_gap_rel.abs() < 1e-12 && last.a_r == 1.0,
            "model {n}: {last:?}"
        );
        assert!(sw.rows[0].mean_gap_rel > 5.0, "model {n}: {:?}", sw.rows[0]);
    }
}

#[test]
fn persson_small_load_asymptote() {
    // a wide spectrum: λ_r/λ_s = 1e4, L/λ_r = 5
    let sa = SelfAffine::new(5e-4, 1e-4, 1e-8, 0.8, Normalisation::RmsGradient(1.0)).unwrap();
    let mut s = system1(Model::named(1).unwrap());
    s.set_spectrum(Spectrum::SelfAffine(sa)).unwrap();
    for model in [
        Model::named(1).unwrap(),
        Model::custom(0.55, 0.0, 0.0, 1.0, false).unwrap(),
    ] {
        s.set_model(model).unwrap();
        let u0 = gap::asymptotic_slope(&s).unwrap();
        let spec = SweepSpec {
            from: 1e-7,
            to: 1e-6,
            points: 2,
        };
        let sw = sweep::sweep(&s, &spec, &Options::default(), None).unwrap();
        let slope = (sw.rows[0].mean_gap_rel - sw.rows[1].mean_gap_rel) / 10f64.ln();
        assert!(
            ((slope - u0) / u0).abs() < ASYMPTOTE_SLOPE_REL,
            "{}: slope {slope} vs u0 {u0}",
            model.label()
        );
        // ū is linear in ln p* there: the mid-point lies on the chord
        let mid = energy_route(&s, 10f64.powf(-6.5)).relative;
        let chord = 0.5 * (sw.rows[0].mean_gap_rel + sw.rows[1].mean_gap_rel);
        assert!(((mid - chord) / mid).abs() < ASYMPTOTE_SLOPE_REL, "{mid} vs {chord}");
    }
}

#[test]
fn hard_cases_give_finite_monotone_gaps() {
    let mut cases: Vec<Scene> = Vec::new();
    for t in [1e-4, 1e-2, 1.0, f64::INFINITY] {
        let mut s = system1(Model::named(4).unwrap());
        s.set_thickness_qr(t).unwrap();
        cases.push(s);
    }
    for (ratio, h) in [(1e6, 0.8), (200.0, 0.05), (200.0, 0.95)] {
        let sa = SelfAffine::new(1e-4, 2e-5, 2e-5 / ratio, h, Normalisation::RmsGradient(1.0)).unwrap();
        let mut s = system1(Model::named(3).unwrap());
        s.set_spectrum(Spectrum::SelfAffine(sa)).unwrap();
        cases.push(s);
    }
    let spec = SweepSpec {
        from: 1e-8,
        to: 10.0,
        points: 10,
    };
    for s in &cases {
        let sw = sweep::sweep(s, &spec, &Options::default(), None).unwrap();
        let label = format!("t = {}, q_s = {:e}", s.thickness_qr(), s.spectrum().q_s());
        assert!(sw.monotone, "{label}");
        for r in &sw.rows {
            assert!(
                r.mean_gap_rel.is_finite() && r.mean_gap_rel >= 0.0 && r.elastic_energy.is_finite(),
                "{label}: {r:?}"
            );
            assert!(r.converged);
        }
        // thin slabs are nearly conformal (ū ≪ h_rms); thick bodies are far from contact
        let floor = if s.thickness_qr() < 1.0 { 0.0 } else { 1.0 };
        assert!(sw.rows[0].mean_gap_rel > floor, "{label}: {:?}", sw.rows[0]);
    }
}

#[test]
fn no_gap_for_non_positive_load() {
    // the energy route is singular at p = 0: a scene cannot hold p* <= 0 (the error names the
    // load and its range), so no gap is ever asked for one
    let mut s = system1(Model::named(1).unwrap());
    for p in [0.0, -0.1, f64::NAN] {
        let e = s.set_pressure(p).unwrap_err();
        assert_eq!(e.invalid_field(), Some(&asperity::error::Field::Pressure), "{e}");
        assert!(e.to_string().contains("1e-12"), "{e}");
    }
    assert!(gap::mean_gap(&s, &Options::default()).is_ok());
}

#[test]
fn gap_at_the_top_of_the_pressure_range_is_zero() {
    // p* above full contact (up to the allowed maximum 1e3): ū = 0, no grid beyond the range
    for gamma in [0.0, 0.157] {
        let mut s = Preset::resolve("system-2").unwrap().scene().unwrap();
        s.set_surface_energy_j_m2(gamma).unwrap();
        for p in [gap::full_contact_pressure(&s) * 1.01, 1e3] {
            s.set_pressure(p).unwrap();
            let g = gap::mean_gap(&s, &Options::default()).unwrap();
            assert_eq!(g.relative, 0.0, "gamma {gamma}, p* {p}");
            assert!(g.energy_reduced.is_finite());
        }
    }
}
