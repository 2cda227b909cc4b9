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

criterion_group!(benches, bench);
criterion_main!(benches);
