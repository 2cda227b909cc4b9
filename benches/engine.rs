//! One adhesionless evaluation: time at the default accuracy, with the relative
//! error of a_r against a refined solution (rtol = 1e-13) printed beside it.

use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::theory::persson::{self, Accuracy};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("adhesionless");
    for (name, preset, model, t) in [
        ("system-1 model 3 p*=0.01 t=inf", "system-1", 3u8, f64::INFINITY),
        ("system-1 model 4 p*=0.01 t*q_r=0.5", "system-1", 4u8, 0.5),
        ("system-2 model 4 p*=0.005 t*q_r=0.1", "system-2", 4u8, 0.1),
    ] {
        let mut scene = Preset::resolve(preset).unwrap().scene().unwrap();
        scene.set_surface_energy_j_m2(0.0).unwrap();
        scene.set_model(Model::named(model).unwrap()).unwrap();
        scene.set_thickness_qr(t).unwrap();
        for (label, rtol) in [
            ("default", Accuracy::default().rtol),
            ("rtol=1e-6", 1e-6),
            ("rtol=1e-11", 1e-11),
        ] {
            let acc = Accuracy {
                rtol,
                ..Accuracy::default()
            };
            let reference = persson::solve(&scene, &Accuracy { rtol: 1e-13, ..acc }).unwrap();
            let sol = persson::solve(&scene, &acc).unwrap();
            eprintln!(
                "{name} [{label}]: a_r = {:.10}, rel. error {:.2e} (estimate {:.2e}), {} rhs evaluations",
                sol.a_r,
                (sol.a_r / reference.a_r - 1.0).abs(),
                sol.error_estimate / reference.a_r,
                sol.evaluations
            );
            g.bench_function(format!("{name} [{label}]"), |b| {
                b.iter(|| persson::solve(black_box(&scene), black_box(&acc)).unwrap().a_r)
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
