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
