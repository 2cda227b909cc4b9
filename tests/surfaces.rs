//! Measured surfaces: the readers (round trips and bad files), the PSD of a map against the
//! spectrum it was generated from, and the theory on a tabulated spectrum against the analytic
//! one.

use asperity::input::preset::Preset;
use asperity::surface::heightmap::{generate, Surface};
use asperity::surface::psd::{analyse, PsdOptions};
use asperity::surface::readers::{self, Format, ReadOptions, Unit};
use asperity::surface::spectrum::{Normalisation, SelfAffine, Spectrum, Tabulated};
use asperity::theory::engine;
use asperity::tolerances::{PSD_HURST_ABS, PSD_MOMENT_REL, PSD_WINDOWED_MOMENT_REL, TABULATED_THEORY_REL};
use std::f64::consts::PI;

#[path = "support/ideal_table.rs"]
mod ideal_table;

fn map(nx: usize, ny: usize) -> Surface {
    let h = (0..nx * ny)
        .map(|k| {
            let (x, y) = ((k % nx) as f64, (k / nx) as f64);
            1e-7 * ((0.7 * x).sin() + (0.31 * y + 0.2 * x).cos()) + 3e-9 * (k as f64).sqrt()
        })
        .collect();
    Surface::new(nx, ny, 2.5e-7, h).unwrap()
}

#[test]
fn every_reader_reads_back_what_its_writer_wrote() {
    for s in [map(12, 12), map(16, 9), map(40, 1)] {
        for f in [Format::Text, Format::Xyz, Format::Npy, Format::Gsf] {
            let bytes = asperity::surface::writers::encode(&s, f).unwrap();
            // npy carries no lateral size
            let opts = ReadOptions {
                size: (f == Format::Npy).then(|| s.size_x()),
                height_unit: None,
            };
            let back = readers::parse(&bytes, f, "mem", &opts).unwrap_or_else(|e| panic!("{f:?}: {e}"));
            assert_eq!((back.nx, back.ny), (s.nx, s.ny), "{f:?}");
            assert!(
                (back.spacing / s.spacing - 1.0).abs() < 1e-12,
                "{f:?}: {}",
                back.spacing
            );
            let tol = if f == Format::Gsf { 1e-7 } else { 0.0 };
            for (a, b) in back.heights.iter().zip(&s.heights) {
                assert!((a - b).abs() <= tol * b.abs(), "{f:?}: {a} vs {b}");
            }
        }
    }
}

#[test]
fn height_units_and_sizes() {
    let text = "# Width: 2.0 µm\n# Value units: nm\n1 2 3 4\n5 6 7 8\n1 1 1 1\n2 2 2 2\n";
    let s = readers::parse(text.as_bytes(), Format::Text, "t", &ReadOptions::default()).unwrap();
    assert!((s.size_x() - 2e-6).abs() < 1e-18 && (s.heights[1] - 2e-9).abs() < 1e-21);
    // the caller's unit where the file states none; the caller's size overrides
    let s = readers::parse(
        b"1 2\n3 4\n",
        Format::Text,
        "t",
        &ReadOptions {
            size: Some(1e-3),
            height_unit: Some(Unit::Um),
        },
    )
    .unwrap();
    assert!((s.heights[3] - 4e-6).abs() < 1e-18 && (s.spacing - 5e-4).abs() < 1e-15);
    // xyz in micrometres: coordinates follow the heights' unit
    let xyz = "0 0 1\n1 0 2\n0 1 3\n1 1 4\n";
    let s = readers::parse(
        xyz.as_bytes(),
        Format::Xyz,
        "x",
        &ReadOptions {
            size: None,
            height_unit: Some(Unit::Um),
        },
    )
    .unwrap();
    assert!((s.size_x() - 2e-6).abs() < 1e-18 && (s.heights[2] - 3e-6).abs() < 1e-18);
}

#[test]
fn bad_files_give_one_line_naming_the_file_the_place_and_the_fault() {
    let gsf_ok = asperity::surface::writers::encode(&map(4, 4), Format::Gsf).unwrap();
    let npy_ok = asperity::surface::writers::encode(&map(4, 4), Format::Npy).unwrap();
    let no_size = ReadOptions::default();
    let cases: Vec<(Format, Vec<u8>, &str)> = vec![
        (
            Format::Text,
            b"1 2 3\n4 x 6\n".to_vec(),
            "bad.txt:2: 'x' (not a number)",
        ),
        (Format::Text, b"1 2 3\n4 5\n".to_vec(), "bad.txt:2: a row of 2 values"),
        (Format::Text, b"1 2\nnan 4\n".to_vec(), "bad.txt:2: 'nan' (not finite)"),
        (Format::Text, b"# nothing\n".to_vec(), "bad.txt:1: no data"),
        (
            Format::Text,
            b"# Value units: furlong\n1 2\n".to_vec(),
            "bad.txt:1: height unit 'furlong'",
        ),
        (Format::Text, vec![0x31, 0x20, 0xff, 0x0a], "bad.txt:byte 2: not UTF-8"),
        (Format::Xyz, b"0 0 1\n1 0 2\n0 1\n".to_vec(), "bad.txt:3: 2 columns"),
        (
            Format::Xyz,
            b"0 0 1\n1 0 2\n3 0 2\n".to_vec(),
            "bad.txt:grid: uneven spacing",
        ),
        (
            Format::Xyz,
            b"0 0 1\n1 0 2\n0 1 3\n".to_vec(),
            "bad.txt:grid: 3 points for a 2 x 2 grid",
        ),
        (
            Format::Gsf,
            b"Gwyddion Simple Field 0.9\n".to_vec(),
            "bad.txt:byte 0: no 'Gwyddion Simple Field 1.0' line",
        ),
        (
            Format::Gsf,
            gsf_ok[..gsf_ok.len() - 6].to_vec(),
            "data bytes, 64 needed",
        ),
        (
            Format::Gsf,
            String::from_utf8_lossy(&gsf_ok)
                .replace("XRes = 4", "XRes = four")
                .into_bytes(),
            "bad.txt:2: XRes = four",
        ),
        (Format::Npy, b"not numpy".to_vec(), "bad.txt:byte 0: not a NumPy file"),
        (
            Format::Npy,
            npy_ok[..npy_ok.len() - 8].to_vec(),
            "bad.txt:data: truncated",
        ),
    ];
    for (f, bytes, needle) in cases {
        let opts = ReadOptions {
            size: Some(1e-6),
            height_unit: None,
        };
        let e = readers::parse(&bytes, f, "bad.txt", &opts).unwrap_err().to_string();
        assert!(e.contains(needle), "{f:?} {needle:?}: {e}");
        assert!(!e.contains('\n'), "{e}");
    }
    // no lateral size: the size field is named
    let e = readers::parse(&npy_ok, Format::Npy, "a.npy", &no_size)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("surface.system_size_m") && e.contains("a.npy gives no lateral size"),
        "{e}"
    );
    let e = readers::format_of(std::path::Path::new("x.sdf"))
        .unwrap_err()
        .to_string();
    assert!(e.contains(".gsf"), "{e}");
}

/// Generated maps of L/λ_r = 4, λ_r/λ_s = 16 (8 points per λ_s) over seeds and H.
fn generated(hurst: f64, seed: u64) -> (SelfAffine, Surface) {
    let sa = SelfAffine::new(64e-6, 16e-6, 1e-6, hurst, Normalisation::RmsGradient(0.5)).unwrap();
    (sa, generate(&sa, 512, seed).unwrap())
}

#[test]
fn the_psd_of_generated_maps_recovers_the_spectrum() {
    for &hurst in &[0.3, 0.6, 0.9] {
        for seed in 1..=3 {
            let (sa, s) = generated(hurst, seed);
            let spec = Spectrum::SelfAffine(sa);
            for periodic in [true, false] {
                let a = analyse(
                    &s,
                    &PsdOptions {
                        periodic,
                        ..PsdOptions::default()
                    },
                )
                .unwrap();
                let fit = a.fit.unwrap();
                let what = format!("H {hurst} seed {seed} periodic {periodic}");
                let moment_rel = if periodic {
                    PSD_MOMENT_REL
                } else {
                    PSD_WINDOWED_MOMENT_REL
                };
                assert!(
                    (fit.hurst - hurst).abs() < PSD_HURST_ABS,
                    "{what}: H = {} ± {}",
                    fit.hurst,
                    fit.hurst_error
                );
                assert!(
                    (a.rms_gradient / spec.rms_gradient() - 1.0).abs() < moment_rel,
                    "{what}: g {}",
                    a.rms_gradient
                );
                assert!(
                    (a.rms_height / spec.rms_height() - 1.0).abs() < moment_rel,
                    "{what}: h {} vs {}",
                    a.rms_height,
                    spec.rms_height()
                );
                // q_r and q_s within their bins
                assert!(
                    (fit.q_r / sa.q_r()).ln().abs() < 0.3,
                    "{what}: q_r {} vs {}",
                    fit.q_r,
                    sa.q_r()
                );
                assert!(
                    fit.q_s <= sa.q_s() * 1.01 && fit.q_s > sa.q_s() / 1.4,
                    "{what}: q_s {} vs {}",
                    fit.q_s,
                    sa.q_s()
                );
                // the table integrates to the variance (2π∫qC dq by the trapezoid in ln q)
                let m0: f64 = a
                    .bins
                    .windows(2)
                    .map(|w| {
                        let f = |b: &asperity::surface::psd::PsdBin| 2.0 * PI * b.q * b.q * b.psd;
                        0.5 * (f(&w[0]) + f(&w[1])) * (w[1].q / w[0].q).ln()
                    })
                    .sum();
                assert!(m0 > 0.5 * spec.moment(0) && m0 < 1.5 * spec.moment(0), "{what}: {m0}");
            }
        }
    }
}

#[test]
fn a_line_scan_gives_the_isotropic_spectrum() {
    // a profile with the exact 1-D PSD of the isotropic power law C = K q^{-2(1+H)}:
    // C₁(q) = K q^{-(1+2H)} √π Γ(H+½)/Γ(1+H), amplitude |h̃| = √(2π C₁/L) per mode
    let (n, l, hurst) = (1 << 13, 1e-3, 0.7);
    let k = 1e-30;
    let g = |x: f64| statrs::function::gamma::gamma(x);
    let c1 = |q: f64| k * q.powf(-(1.0 + 2.0 * hurst)) * PI.sqrt() * g(hurst + 0.5) / g(1.0 + hurst);
    let mut rng = asperity::surface::heightmap::SplitMix64::new(5);
    let mut h = vec![0.0; n];
    for m in 1..n / 2 {
        let q = 2.0 * PI * m as f64 / l;
        let amp = (2.0 * PI * c1(q) / l).sqrt();
        let ph = 2.0 * PI * rng.next_f64();
        for (i, v) in h.iter_mut().enumerate() {
            *v += 2.0 * amp * (q * i as f64 * l / n as f64 + ph).cos();
        }
    }
    let s = Surface::new(n, 1, l / n as f64, h).unwrap();
    let a = analyse(
        &s,
        &PsdOptions {
            periodic: true,
            ..PsdOptions::default()
        },
    )
    .unwrap();
    assert!(a.line_scan);
    let fit = a.fit.unwrap();
    assert!((fit.hurst - hurst).abs() < PSD_HURST_ABS, "H = {}", fit.hurst);
    // the converted bins against the 2-D law (each bin's mean of a power law: within 5 %)
    for b in &a.bins[2..a.bins.len() - 2] {
        let exact = k * b.q.powf(-2.0 * (1.0 + hurst));
        assert!((b.psd / exact - 1.0).abs() < 0.05, "q {}: {} vs {exact}", b.q, b.psd);
    }
}

/// The analytic C(q) written as a table at q_L, q_r, q_s and log-spaced points between.
fn table_of(sa: &SelfAffine) -> Tabulated {
    let csv = ideal_table::ideal_csv(sa, 60);
    Tabulated::parse_csv(&csv, "ideal.csv", None, None).unwrap()
}

#[test]
fn the_theory_on_an_ideal_table_equals_the_analytic_spectrum() {
    let opts = engine::Options::default();
    for (preset, thickness, gamma) in [
        ("system-1", f64::INFINITY, 0.0),
        ("system-2", 0.5, 0.0),
        ("system-2", f64::INFINITY, -1.0),
    ] {
        let p = Preset::resolve(preset).unwrap();
        let mut scene = p.scene().unwrap();
        scene.set_thickness_qr(thickness).unwrap();
        if gamma >= 0.0 {
            scene.set_surface_energy_j_m2(gamma).unwrap();
        }
        let Spectrum::SelfAffine(sa) = scene.spectrum().clone() else {
            unreachable!()
        };
        let mut tab = scene.clone();
        tab.set_spectrum(Spectrum::Tabulated(table_of(&sa))).unwrap();
        assert_eq!(tab.spectrum().q_r(), sa.q_r());
        let (a, b) = (
            engine::evaluate(&scene, &opts).unwrap(),
            engine::evaluate(&tab, &opts).unwrap(),
        );
        let rel = |x: f64, y: f64| (x / y - 1.0).abs();
        let what = format!("{preset} t {thickness} gamma {}", scene.surface_energy_j_m2());
        assert!(
            rel(b.stats.a_r, a.stats.a_r) < TABULATED_THEORY_REL,
            "{what}: a_r {} vs {}",
            b.stats.a_r,
            a.stats.a_r
        );
        assert!(
            rel(b.stats.mean_contact_stress, a.stats.mean_contact_stress) < TABULATED_THEORY_REL,
            "{what}: sigma_c {} vs {}",
            b.stats.mean_contact_stress,
            a.stats.mean_contact_stress
        );
        let ga = asperity::theory::gap::mean_gap(&scene, &opts).unwrap();
        let gb = asperity::theory::gap::mean_gap(&tab, &opts).unwrap();
        assert!(
            rel(gb.relative, ga.relative) < TABULATED_THEORY_REL,
            "{what}: gap {} vs {}",
            gb.relative,
            ga.relative
        );
    }
}
