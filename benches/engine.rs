//! One adhesionless evaluation: time at the default accuracy, with the relative
//! error of a_r against a refined solution (rtol = 1e-13) printed beside it; and the same
//! evaluation on a tabulated PSD (a `--psd` table) of 10³ and of 10⁶ rows, table included:
//! a long table is resampled once (`surface::tabulated::MAX_TABLE_ROWS`), so the second
//! should take about the first's time plus one pass over the rows.

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

fn bench_table_rows(c: &mut Criterion) {
    use asperity::surface::spectrum::{Spectrum, Tabulated};
    let mut g = c.benchmark_group("psd table");
    g.sample_size(10);
    let scene = Preset::resolve("system-1").unwrap().scene().unwrap().without_adhesion();
    let Spectrum::SelfAffine(sa) = scene.spectrum().clone() else {
        panic!("system-1 has a self-affine spectrum")
    };
    for rows in [1_000usize, 1_000_000] {
        let q: Vec<f64> = (0..rows)
            .map(|k| sa.q_l() * (sa.q_s() / sa.q_l()).powf(k as f64 / (rows - 1) as f64))
            .collect();
        let psd: Vec<f64> = q.iter().map(|&x| sa.psd(x)).collect();
        g.bench_function(format!("system-1 adhesionless, {rows} rows"), |b| {
            b.iter(|| {
                let t = Tabulated::new(q.clone(), psd.clone(), "bench", None, None).unwrap();
                let s = scene.clone().with_spectrum(Spectrum::Tabulated(t)).unwrap();
                persson::solve(black_box(&s), &Accuracy::default()).unwrap().a_r
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench, bench_table_rows);
criterion_main!(benches);
