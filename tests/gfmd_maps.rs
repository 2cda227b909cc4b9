//! Generated maps and their spectrum: a GFMD run's `reduction` record names each of h_rms, ḡ
//! and the full-contact elastic energy u_ela^(f) = (E*/4)·2π∫q²C(q)dq [S-24] of the generated
//! map that differs from the continuum spectrum's by more than 2 %, with both values, for
//! L/λ_r = 1 (no roll-off plateau) as for L/λ_r = 2, H = 0.3 and 0.8, over seeds. The test's
//! values: the continuum spectrum's closed-form moments, and the map's own real-space h_rms,
//! FFT ḡ and discrete-spectrum first moment.

use asperity::gfmd::reduction::MAP_MOMENT_REL;
use asperity::gfmd::{prepare, GfmdSetup, GridSpec};
use asperity::input::preset::Preset;
use asperity::surface::spectrum::{Normalisation, SelfAffine, Spectrum};
use asperity::tolerances::MAP_MOMENT_REPORT_ABS;

/// The percentage printed in a `not_kept` line: "... (+27.0 %: ...".
fn percent(line: &str) -> f64 {
    let open = line.rfind('(').unwrap();
    let end = line[open..].find('%').unwrap();
    line[open + 1..open + end].trim().parse().unwrap()
}

#[test]
fn gfmd_names_the_map_moments_that_differ_from_the_continuum() {
    let preset = Preset::resolve("system-2").unwrap();
    let base = preset.scene().unwrap().without_adhesion();
    let mut named = 0;
    for ratio in [1.0, 2.0] {
        for hurst in [0.3, 0.8] {
            let Spectrum::SelfAffine(sa) = base.spectrum() else {
                panic!("system-2 is self-affine")
            };
            let sa = SelfAffine::new(
                sa.system_size,
                sa.lambda_r,
                sa.lambda_s,
                hurst,
                Normalisation::RmsGradient(base.rms_gradient()),
            )
            .unwrap();
            let full = base.clone().with_spectrum(Spectrum::SelfAffine(sa)).unwrap();
            for seed in 1..=3 {
                let setup = GfmdSetup {
                    scene: full.clone(),
                    grid: GridSpec {
                        system_size_ratio: ratio,
                        bandwidth: 16.0,
                        points_per_short_wavelength: 4.0,
                    },
                    seed,
                    surface: None,
                    rescale: true,
                };
                let prep = prepare(&setup).unwrap();
                let red = prep.reduction.as_ref().unwrap();
                let spec = prep.scene.spectrum();
                let e = prep.scene.contact_modulus_pa();
                let d = Spectrum::Discrete(prep.surface.discrete_spectrum(spec.q_r()).unwrap());
                for (key, cont, map) in [
                    ("map_rms_height", spec.moment(0).sqrt(), prep.surface.rms_height()),
                    ("map_rms_gradient", spec.moment(2).sqrt(), prep.surface.rms_gradient()),
                    (
                        "map_full_contact_energy",
                        0.25 * e * spec.moment(1),
                        0.25 * e * d.moment(1),
                    ),
                ] {
                    let rel = 100.0 * (map / cont - 1.0);
                    let what = format!("L/lambda_r = {ratio}, H = {hurst}, seed {seed}: {key} {rel:+.2} %");
                    let line = red.not_kept.iter().find(|l| l.starts_with(key));
                    if rel.abs() > 100.0 * MAP_MOMENT_REL {
                        let line = line.unwrap_or_else(|| panic!("{what} not named: {:?}", red.not_kept));
                        assert!((percent(line) - rel).abs() < MAP_MOMENT_REPORT_ABS, "{what}: {line}");
                        named += 1;
                    } else {
                        assert!(line.is_none() && red.kept.iter().any(|k| k == key), "{what}: {red:?}");
                    }
                }
            }
        }
    }
    // the case is among them: no plateau, H = 0.8 (h_rms ~27 % above the continuum)
    assert!(named >= 6, "{named}");
}
