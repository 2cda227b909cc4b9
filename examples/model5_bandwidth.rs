//! Model 4 and model 5 on system II's reduced scenes of growing bandwidth and on the full
//! system (docs/physics.md §3.6): a_r at p* = 4.64e-3, t·q_r = ∞, 0.3, 0.15.
//!
//! `cargo run --release --example model5_bandwidth`
use asperity::gfmd::reduction::reduce;
use asperity::gfmd::GridSpec;
use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::theory::engine::{evaluate, Options};
fn main() {
    let preset = Preset::resolve("system-2").unwrap();
    for t in [f64::INFINITY, 0.3, 0.15] {
        for m in [4u8, 5] {
            let full = preset
                .scene()
                .unwrap()
                .with_thickness_qr(t)
                .unwrap()
                .with_model(Model::named(m).unwrap())
                .unwrap()
                .with_pressure(4.6415888336e-03)
                .unwrap();
            let mut out = vec![];
            for n in [256usize, 512, 1024, 2048] {
                let grid = GridSpec::from_preset(preset.gfmd.as_ref().unwrap())
                    .with_grid(n)
                    .unwrap();
                let (red, _) = reduce(&full, &grid, true).unwrap();
                let e = evaluate(&red, &Options::chart()).unwrap();
                out.push(format!(
                    "{n}: {:.4} (w0 {:.3} glo {:.3})",
                    e.stats.a_r,
                    red.model().w(0.0),
                    red.gamma_glo()
                ));
            }
            let e = evaluate(&full, &Options::chart()).unwrap();
            println!(
                "t {t} model {m}: {} | full {:.4} (w0 {:.3} glo {:.3})",
                out.join(", "),
                e.stats.a_r,
                full.model().w(0.0),
                full.gamma_glo()
            );
        }
    }
}
