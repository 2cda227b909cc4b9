//! The theory's pull-off (physics.md §6.2) beside GFMD's on the reference set: system II's
//! adhesive cases, each on the maps GFMD ran (the theory on each map's own spectrum, the
//! tensile path from p₁ = 10⁻⁴ as GFMD's), for models 3, 4 and 5.
//!
//! `cargo run --release --example theory_pull_off [SEEDS]` prints one line per case: GFMD's
//! pull-off (mean ± standard error), each model's (mean over the maps), the bound no contact
//! branch can pass, and the summary per model (mean and worst |theory/GFMD − 1|).
use asperity::fit::reference_set::{pull_offs, reference_set};
use asperity::fit::set_gauge::cases_of;
use asperity::input::model::Model;
use asperity::theory::adhesion::pull_off;
use asperity::theory::cycle::PULL_OFF_REL;
use asperity::theory::engine::Options;

/// The set's smallest load: GFMD's tensile path starts from it.
const P1: f64 = 1e-4;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let seeds: u64 = std::env::args().nth(1).map_or(Ok(3), |s| s.parse())?;
    let acc = Options::default().adhesion;
    let cases = cases_of(reference_set(), seeds)?;
    let models = [3u8, 4, 5];
    let mut rel: Vec<Vec<f64>> = vec![Vec::new(); models.len()];
    println!("t*q_r  gamma  glo    GFMD pull-off        model 3     model 4     model 5     bound");
    for c in cases.iter().filter(|c| c.gamma_factor > 0.0) {
        let Some(g) = pull_offs()
            .iter()
            .find(|r| r.system == 2 && r.thickness_qr == c.thickness_qr && r.gamma_factor == c.gamma_factor)
        else {
            continue;
        };
        let mut line = format!(
            "{:<6} {:<6} {:.3}  {:.3e} ± {:.1e}",
            c.thickness_qr, c.gamma_factor, c.gamma_glo, g.pressure.0, g.pressure.1
        );
        let mut bound = 0.0;
        for (i, &m) in models.iter().enumerate() {
            let mut sum = 0.0;
            for s in &c.scenes {
                let scene = s.clone().with_model(Model::named(m)?)?;
                let po = pull_off(&scene, P1, PULL_OFF_REL, &acc, None)?;
                sum += po.pressure;
                bound = po.bound;
            }
            let mean = sum / c.scenes.len() as f64;
            rel[i].push((mean / g.pressure.0 - 1.0).abs());
            line += &format!("  {mean:>10.3e}");
        }
        println!("{line}  {bound:.3e}");
    }
    for (i, &m) in models.iter().enumerate() {
        let r = &rel[i];
        let mean = r.iter().sum::<f64>() / r.len().max(1) as f64;
        let worst = r.iter().copied().fold(0.0, f64::max);
        let within = r.iter().filter(|&&x| x <= 0.3).count();
        println!(
            "model {m}: mean |theory/GFMD - 1| = {mean:.3}, worst {worst:.3}, within 30 %: {within} of {}",
            r.len()
        );
    }
    Ok(())
}
