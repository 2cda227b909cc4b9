//! The theory's pull-off (physics.md §6.2) and the two DMT routes' (§6.3) beside GFMD's on the
//! reference set: system II's adhesive cases, each on the maps GFMD ran (the theory on each
//! map's own spectrum, γ_s and ρ of the reduced map; the tensile path from p₁ = 10⁻⁴ as
//! GFMD's), for models 3, 4 and 5, mean over the maps.
//!
//! `cargo run --release --example theory_pull_off [SEEDS] [OUT.csv]` prints one line per case:
//! GFMD's pull-off (mean ± standard error), each model's, the bound no contact branch can
//! pass, each route's, and the summary per model; with OUT.csv it writes the table the
//! pull-off read-out is built on (`data/reference/pull-off-theory-256.csv`,
//! [`asperity::fit::pull_off_trust`]).
use asperity::fit::reference_set::{pull_off_of, reference_set};
use asperity::fit::set_gauge::cases_of;
use asperity::input::model::Model;
use asperity::theory::adhesion::pull_off;
use asperity::theory::cycle::PULL_OFF_REL;
use asperity::theory::dmt::{pull_off_route, Route, RouteOptions};
use asperity::theory::engine::Options;
use rayon::prelude::*;
use std::fmt::Write as _;

/// The set's smallest load: GFMD's tensile path starts from it.
const P1: f64 = 1e-4;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let seeds: u64 = std::env::args().nth(1).map_or(Ok(3), |s| s.parse())?;
    let out = std::env::args().nth(2);
    let start = std::time::Instant::now();
    let acc = Options::default().adhesion;
    let cases = cases_of(reference_set(), seeds)?;
    let models = [3u8, 4, 5];
    let mut rel: Vec<Vec<f64>> = vec![Vec::new(); models.len()];
    let mut csv = String::from(
        "system,thickness_qr,gamma_factor,gamma_glo,seeds,gfmd,gfmd_err,model3,model4,model5,tension_bound,bam,gap_dmt\n",
    );
    println!(
        "t*q_r  gamma  glo    GFMD pull-off        model 3     model 4     model 5     bound       bam         gap-dmt"
    );
    for c in cases.iter().filter(|c| c.gamma_factor > 0.0) {
        let Some(g) = pull_off_of(2, c.thickness_qr, c.gamma_factor) else {
            continue;
        };
        let mut line = format!(
            "{:<6} {:<6} {:.3}  {:.3e} ± {:.1e}",
            c.thickness_qr, c.gamma_factor, c.gamma_glo, g.pressure.0, g.pressure.1
        );
        let mut row = format!(
            "2,{},{},{:.10e},{},{:.10e},{:.10e}",
            c.thickness_qr, c.gamma_factor, c.gamma_glo, g.seeds, g.pressure.0, g.pressure.1
        );
        let mut bound = 0.0;
        for (i, &m) in models.iter().enumerate() {
            let per_map = c
                .scenes
                .par_iter()
                .map(|s| {
                    let scene = s.clone().with_model(Model::named(m)?)?;
                    pull_off(&scene, P1, PULL_OFF_REL, &acc, None)
                })
                .collect::<Result<Vec<_>, _>>()?;
            let mean = per_map.iter().map(|p| p.pressure).sum::<f64>() / per_map.len() as f64;
            bound = per_map.iter().map(|p| p.bound).sum::<f64>() / per_map.len() as f64;
            rel[i].push((mean / g.pressure.0 - 1.0).abs());
            line += &format!("  {mean:>10.3e}");
            write!(row, ",{mean:.10e}")?;
        }
        line += &format!("  {bound:.3e}");
        write!(row, ",{bound:.10e}")?;
        for route in Route::ALL {
            let per_map = c
                .scenes
                .par_iter()
                .map(|s| pull_off_route(s, route, &[], &RouteOptions::default()))
                .collect::<Result<Vec<_>, _>>()?;
            let mean = per_map.iter().map(|r| r.pull_off).sum::<f64>() / per_map.len() as f64;
            line += &format!("  {mean:>10.3e}");
            write!(row, ",{mean:.10e}")?;
        }
        println!("{line}");
        csv += &row;
        csv.push('\n');
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
    if let Some(path) = out {
        std::fs::write(&path, csv)?;
        println!("wrote {path}");
    }
    println!("wall time {:.1} s", start.elapsed().as_secs_f64());
    Ok(())
}
