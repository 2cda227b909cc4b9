//! GFMD: one adhesionless relaxation of a system-I map at p* = 0.01 to the default
//! relative force residual (1e-8), on 128² and 256² grids (L/λ_r = 2, λ_s/Δa = 8).

use asperity::gfmd::{self, GfmdOptions, GridSpec, Problem};
use asperity::input::preset::Preset;
use asperity::surface::heightmap;
use asperity::surface::spectrum::Spectrum;
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::sync::atomic::AtomicBool;

fn bench(c: &mut Criterion) {
    let preset = Preset::resolve("system-1").unwrap();
    let full = match preset.spectrum().unwrap() {
        Spectrum::SelfAffine(s) => s,
        _ => unreachable!(),
    };
    let base = GridSpec {
        system_size_ratio: 2.0,
        bandwidth: 32.0,
        points_per_short_wavelength: 8.0,
    };
    let mut g = c.benchmark_group("gfmd adhesionless p*=0.01");
    g.sample_size(10);
    for n in [128usize, 256] {
        let spec = base.with_grid(n).unwrap().spectrum(&full).unwrap();
        let s = heightmap::generate(&spec, n, 1).unwrap();
        let e = preset.material.contact_modulus_pa;
        let problem = Problem {
            surface: &s,
            modulus: e,
            thickness: f64::INFINITY,
            pressure: 0.01 * e * s.rms_gradient(),
            gamma: 0.0,
            range: 1e-9,
        };
        let cancel = AtomicBool::new(false);
        let sol = gfmd::solve(&problem, &GfmdOptions::default(), &mut |_| {}, &cancel).unwrap();
        eprintln!("{n}²: {} FIRE steps to residual {:.1e}", sol.iterations, sol.residual);
        g.bench_function(format!("{n}x{n}"), |b| {
            b.iter(|| gfmd::solve(black_box(&problem), &GfmdOptions::default(), &mut |_| {}, &cancel).unwrap())
        });
    }
    g.finish();
}

/// One periodic convolution (`RealFft2::convolve`: forward real FFT, a real kernel, inverse),
/// the unit of GFMD's cost: Polonsky–Keer does two per iteration, FIRE one per step.
fn convolve(c: &mut Criterion) {
    use asperity::numerics::fft2::RealFft2;
    use rustfft::num_complex::Complex64;
    let mut g = c.benchmark_group("fft2 convolve");
    g.sample_size(10);
    for n in [1024usize, 2048] {
        let mut plan = RealFft2::new(n, n);
        let input: Vec<f64> = (0..n * n).map(|k| ((k * 7919) % 13) as f64 - 6.0).collect();
        let values: Vec<f64> = (0..plan.spectrum_len())
            .map(|k| 1.0 / (1.0 + (k % 97) as f64))
            .collect();
        let kernel = plan.kernel(&values);
        let mut spec = vec![Complex64::new(0.0, 0.0); plan.spectrum_len()];
        let mut out = vec![0.0; n * n];
        g.bench_function(format!("{n}x{n}"), |b| {
            b.iter(|| plan.convolve(black_box(&input), &kernel, &mut spec, &mut out))
        });
    }
    g.finish();
}

criterion_group!(benches, bench, convolve);
criterion_main!(benches);
