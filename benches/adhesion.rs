//! Adhesive theory and load sweeps: time against error.
//!
//! - One adhesive solve of system 1 (model 3, p* = 0.01) and system 2 (model 4, p* = 0.005)
//!   for a ladder of resolutions (steps per ln q, points per width), with the relative error
//!   of a_r against a much finer solution (192, 40) printed beside each rung.
//! - A 64-point sweep of system 1 (adhesionless and adhesive; default and chart accuracy) with
//!   its largest relative a_r and ū error against a 4× finer sweep at the shared loads.

use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::theory::adhesion::{self, AdhesionAccuracy};
use asperity::theory::engine::Options;
use asperity::theory::sweep::{self, SweepSpec};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn ladder(c: &mut Criterion) {
    let mut g = c.benchmark_group("adhesive");
    g.sample_size(20);
    for (name, preset, model) in [
        ("system-1 model 3", "system-1", 3u8),
        ("system-2 model 4", "system-2", 4u8),
    ] {
        let mut scene = Preset::resolve(preset).unwrap().scene().unwrap();
        scene.set_model(Model::named(model).unwrap()).unwrap();
        let acc = |s: f64, p: f64| AdhesionAccuracy {
            steps_per_ln_q: s,
            points_per_width: p,
            explore_branches: false,
            ..AdhesionAccuracy::default()
        };
        let reference = adhesion::solve(&scene, &acc(192.0, 40.0), None, None).unwrap().a_r;
        for (s, p) in [(6.0, 3.0), (12.0, 5.0), (24.0, 10.0), (48.0, 20.0)] {
            let a = acc(s, p);
            let sol = adhesion::solve(&scene, &a, None, None).unwrap();
            eprintln!(
                "{name} [steps {s}, points {p}]: a_r = {:.8}, rel. error {:.2e}, {} iterations",
                sol.a_r,
                (sol.a_r / reference - 1.0).abs(),
                sol.iterations
            );
            g.bench_function(format!("{name} [steps {s}, points {p}]"), |b| {
                b.iter(|| {
                    adhesion::solve(black_box(&scene), black_box(&a), None, None)
                        .unwrap()
                        .a_r
                })
            });
        }
    }
    g.finish();
}

fn sweeps(c: &mut Criterion) {
    let mut g = c.benchmark_group("sweep");
    g.sample_size(10);
    let base = Preset::resolve("system-1").unwrap().scene().unwrap();
    for (name, gamma, opts) in [
        ("system-1 adhesionless", 0.0, Options::default()),
        (
            "system-1 adhesive [default]",
            base.surface_energy_j_m2(),
            Options::default(),
        ),
        (
            "system-1 adhesive [chart]",
            base.surface_energy_j_m2(),
            Options::chart(),
        ),
    ] {
        let mut scene = base.clone();
        scene.set_surface_energy_j_m2(gamma).unwrap();
        let spec = SweepSpec {
            from: 1e-3,
            to: 1.0,
            points: 64,
        };
        let fine = spec.refined(4);
        let reference = sweep::sweep(&scene, &fine, &Options::default(), None).unwrap();
        let sw = sweep::sweep(&scene, &spec, &opts, None).unwrap();
        let (ea, eg) = sw.max_errors_against(&reference, 4);
        eprintln!(
            "{name}: {} evaluations, max rel. error a_r {ea:.2e}, mean gap {eg:.2e} (vs 4x finer)",
            sw.evaluations
        );
        g.bench_function(format!("64-point {name}"), |b| {
            b.iter(|| sweep::sweep(black_box(&scene), black_box(&spec), black_box(&opts), None).unwrap())
        });
    }
    g.finish();
}

criterion_group!(benches, ladder, sweeps);
criterion_main!(benches);
