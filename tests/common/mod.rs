//! Scenes shared by the library's integration tests: the preset systems of [S] (docs/systems.md)
//! with a model, a thickness, a surface energy and a load. Each test file that uses them says
//! `mod common;`.
#![allow(dead_code)]

use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;

/// The scene of a built-in preset as it ships.
pub fn preset(name: &str) -> Scene {
    Preset::resolve(name).unwrap().scene().unwrap()
}

/// System `n` of [S] (1 or 2, with its surface energy) with model `model` (1–4).
pub fn system(n: u8, model: u8) -> Scene {
    preset(&format!("system-{n}"))
        .with_model(Model::named(model).unwrap())
        .unwrap()
}

/// System `n` without adhesion, with any model (the variants of the literature included).
pub fn dry(n: u8, model: Model) -> Scene {
    preset(&format!("system-{n}"))
        .without_adhesion()
        .with_model(model)
        .unwrap()
}

/// System `n` with model `model`, t·q_r, γ_s (J/m²) and p*.
pub fn at(n: u8, model: u8, thickness_qr: f64, gamma_j_m2: f64, p: f64) -> Scene {
    system(n, model)
        .with_thickness_qr(thickness_qr)
        .unwrap()
        .with_surface_energy_j_m2(gamma_j_m2)
        .unwrap()
        .with_pressure(p)
        .unwrap()
}

/// v(q_s) of a half-space's load where the variance's law in the gradient fraction G is
/// autonomous: dv/dG = 1/(4 w(a(v))), a = erf(p*/√(2v)), so G(v) = 4∫₀^v w(a(v')) dv' and v(q_s)
/// solves G(v) = 1 (w(1) = 1: no contact lost, the plain law). Simpson's rule in ln v' and
/// bisection, sharing no code with the library's ODE solver.
pub fn autonomous_variance(p: f64, w: impl Fn(f64) -> f64) -> f64 {
    use statrs::function::erf::erf;
    let g_of = |v: f64| -> f64 {
        // below lo, a = 1 and w = 1: contributes 4·lo
        let lo = (1e-12 * p * p).min(1e-14 * v);
        let n = 4000;
        let (a, b) = (lo.ln(), v.ln());
        let h = (b - a) / n as f64;
        let integrand = |y: f64| {
            let vv = y.exp();
            vv * w(erf(p / (2.0 * vv).sqrt()))
        };
        let mut s = integrand(a) + integrand(b);
        for i in 1..n {
            s += integrand(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
        }
        4.0 * (lo + s * h / 3.0)
    };
    let (mut lo, mut hi) = (1e-6f64, 10.0f64);
    for _ in 0..200 {
        let mid = (lo * hi).sqrt();
        if g_of(mid) > 1.0 {
            hi = mid
        } else {
            lo = mid
        }
    }
    (lo * hi).sqrt()
}
