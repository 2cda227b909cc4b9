//! The theory block of `gfmd` on a map's discrete spectrum: every mode group (the slow path)
//! against the spectrum coarse-grained into shells of ln q with the same moments
//! (`surface::shells`), at several shell widths: a_r, σ̄_c*, ū and the time of each
//! (BENCHMARKS.md). `cargo run --release --example theory_shells -- [WIDTH ...]`.

use asperity::gfmd::{self, GfmdSetup, GridSpec};
use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::surface::spectrum::Spectrum;
use asperity::theory::{engine, gap};
use std::time::Instant;

/// a_r, σ̄_c*, ū/h_rms of the theory block and its wall time.
fn block(scene: &Scene) -> (f64, f64, f64, f64) {
    let opts = engine::Options {
        adhesion_error_estimate: false,
        ..engine::Options::default()
    };
    let t0 = Instant::now();
    let ev = engine::evaluate(scene, &opts).expect("theory");
    let g = gap::mean_gap_of(scene, &ev, &opts).map_or(f64::NAN, |g| g.relative);
    (
        ev.stats.a_r,
        ev.stats.mean_contact_stress,
        g,
        t0.elapsed().as_secs_f64(),
    )
}

fn main() {
    let widths: Vec<f64> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let widths = if widths.is_empty() {
        vec![1.0 / 24.0, 1.0 / 48.0]
    } else {
        widths
    };
    // (system, model, t·q_r, γ_s of the preset or 0, p*)
    let scenes = [
        ("system-2", 4u8, f64::INFINITY, true, 5e-3),
        ("system-2", 3, 0.3, true, 5e-3),
        ("system-1", 4, f64::INFINITY, false, 1e-2),
    ];
    for (name, model, t, adhesive, p) in scenes {
        let preset = Preset::resolve(name).unwrap();
        let mut scene = preset.scene().unwrap();
        scene.set_model(Model::named(model).unwrap()).unwrap();
        scene.set_thickness_qr(t).unwrap();
        if !adhesive {
            scene = scene.without_adhesion();
        }
        scene.set_pressure(p).unwrap();
        let setup = GfmdSetup {
            scene,
            grid: preset.gfmd.as_ref().map(GridSpec::from_preset).unwrap(),
            seed: 1,
            surface: None,
            rescale: true,
        };
        let prep = gfmd::prepare(&setup).unwrap();
        let coarse = prep.theory_scene(p).unwrap();
        let full = prep.surface.discrete_spectrum(prep.q_r).unwrap();
        let groups = full.modes.len();
        let full_scene = coarse.clone().with_spectrum(Spectrum::Discrete(full.clone())).unwrap();
        let (a0, s0, g0, t0) = block(&full_scene);
        println!(
            "{name} model {model} t*q_r {t} gamma {:.4} p* {p}: every group ({groups}): a_r {a0:.6e} \
             sigma_c {s0:.6e} gap {g0:.6e}  {t0:.3} s",
            full_scene.surface_energy_j_m2()
        );
        for &w in &widths {
            let d = full.coarse_grained(w);
            let sc = coarse.clone().with_spectrum(Spectrum::Discrete(d.clone())).unwrap();
            let (a, s, g, tt) = block(&sc);
            let rel = |x: f64, y: f64| (x / y - 1.0).abs();
            let mom = [0, 2, 4].map(|n| rel(d.moment(n), full.moment(n)));
            println!(
                "  shells {w:.4} ({} modes): a_r {a:.6e} ({:.1e}) sigma_c {s:.6e} ({:.1e}) gap {g:.6e} ({:.1e})  \
                 {tt:.3} s; moments 0,2,4 rel {:.1e} {:.1e} {:.1e}",
                d.modes.len(),
                rel(a, a0),
                rel(s, s0),
                rel(g, g0),
                mom[0],
                mom[1],
                mom[2]
            );
        }
    }
}
