//! The theory on a map's spectrum coarse-grained into thin shells of ln q
//! (`surface::shells`, used by `gfmd`'s `theory` block) against the same theory on every mode
//! group of the map (the uncoarsened spectrum is the reference), and the moments the shells
//! keep.

use asperity::gfmd::{self, GfmdSetup, GridSpec};
use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::surface::spectrum::Spectrum;
use asperity::theory::{engine, gap};
use asperity::tolerances::{SHELL_MOMENT_REL, SHELL_THEORY_REL};

/// A map of system II with modes up to its Nyquist wave number (λ_s = 2Δa), so that the
/// spectrum has many more groups than shells; the full and the coarse-grained scenes.
fn scenes(model: u8, t: f64, gamma: Option<f64>, p: f64) -> (Scene, Scene) {
    let preset = Preset::resolve("system-2").unwrap();
    let mut scene = preset.scene().unwrap();
    scene.set_model(Model::named(model).unwrap()).unwrap();
    scene.set_thickness_qr(t).unwrap();
    if let Some(g) = gamma {
        scene.set_surface_energy_j_m2(g).unwrap();
    }
    scene.set_pressure(p).unwrap();
    let setup = GfmdSetup {
        scene,
        grid: GridSpec {
            system_size_ratio: 2.0,
            bandwidth: 32.0,
            points_per_short_wavelength: 2.0,
        },
        seed: 3,
        surface: None,
        rescale: true,
    };
    let prep = gfmd::prepare(&setup).unwrap();
    let coarse = prep.theory_scene(p).unwrap();
    let full = coarse
        .clone()
        .with_spectrum(Spectrum::Discrete(prep.surface.discrete_spectrum(prep.q_r).unwrap()))
        .unwrap();
    (full, coarse)
}

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

#[test]
fn shells_keep_h_rms_gradient_and_curvature() {
    let (full, coarse) = scenes(4, f64::INFINITY, None, 1e-2);
    let (Spectrum::Discrete(f), Spectrum::Discrete(c)) = (&full.spectrum(), &coarse.spectrum()) else {
        panic!("discrete spectra expected");
    };
    assert!(
        c.modes.len() * 2 < f.modes.len(),
        "{} shells' modes for {} groups",
        c.modes.len(),
        f.modes.len()
    );
    for (n, what) in [(0, "h_rms^2"), (2, "g^2"), (4, "curvature^2")] {
        let (a, b) = (f.moment(n), c.moment(n));
        assert!(rel(b, a) <= SHELL_MOMENT_REL, "{what}: {b} vs {a}");
    }
    assert!(rel(coarse.spectrum().rms_height(), full.spectrum().rms_height()) <= SHELL_MOMENT_REL);
}

#[test]
fn theory_on_shells_matches_every_mode_group() {
    let opts = engine::Options {
        adhesion_error_estimate: false,
        ..engine::Options::default()
    };
    // with adhesion on the half-space and on a slab, and without
    for (model, t, gamma, p) in [
        (4, f64::INFINITY, None, 5e-3),
        (3, 0.3, None, 5e-3),
        (4, f64::INFINITY, Some(0.0), 1e-2),
    ] {
        let (full, coarse) = scenes(model, t, gamma, p);
        let a = engine::evaluate(&full, &opts).unwrap();
        let b = engine::evaluate(&coarse, &opts).unwrap();
        let ga = gap::mean_gap_of(&full, &a, &opts).unwrap();
        let gb = gap::mean_gap_of(&coarse, &b, &opts).unwrap();
        let what = format!("model {model}, t*q_r {t}, p* {p}");
        assert_eq!(a.branches.len(), b.branches.len(), "{what}: branches");
        for (x, y, name) in [
            (b.stats.a_r, a.stats.a_r, "a_r"),
            (
                b.stats.mean_contact_stress,
                a.stats.mean_contact_stress,
                "mean contact stress",
            ),
            (gb.relative, ga.relative, "mean gap"),
            (gb.upper, ga.upper, "mean gap's upper end"),
        ] {
            assert!(rel(x, y) <= SHELL_THEORY_REL, "{what}: {name} {x} on shells vs {y}");
        }
    }
}
