//! Whether any gauge of model 5's form can follow GFMD below p* = 10⁻³ (docs/physics.md §3.6,
//! "Below p* = 10⁻³"): per adhesive case of the small-load set (its first map), e_a =
//! ln(a_r theory / a_r GFMD) at every loading point for W(0) on a grid 0.05…1, and the W(0) that
//! is best for the case's points below 10⁻³, with the error it leaves there and above.
//!
//! `cargo run --release --example w0_small_loads > /tmp/w0-small.csv`
use asperity::fit::reference_set::small_load_set;
use asperity::fit::set_gauge::{case_errors, cases_of, model_at_w0, ModelChoice, SetCase};
use asperity::theory::cycle::PathBranch;
use asperity::theory::engine::Options;
use rayon::prelude::*;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let t0 = std::time::Instant::now();
    let cases: Vec<SetCase> = cases_of(small_load_set(), 1)?
        .into_iter()
        .filter(|c| c.gamma_factor > 0.0)
        .collect();
    let nodes: Vec<f64> = (0..20).map(|k| 0.05 + 0.05 * k as f64).collect();
    let jobs: Vec<(usize, usize)> = (0..cases.len())
        .flat_map(|c| (0..nodes.len()).map(move |w| (c, w)))
        .collect();
    let out: Vec<Option<Vec<(f64, f64)>>> = jobs
        .par_iter()
        .map(|&(ci, wi)| {
            let c = &cases[ci];
            let e = case_errors(
                c,
                &ModelChoice::Fixed(model_at_w0(c.gamma_glo, nodes[wi])),
                &Options::chart(),
            )
            .ok()?;
            Some(
                e.iter()
                    .filter(|e| e.branch == PathBranch::Loading)
                    .map(|e| (e.p, e.ln_a_r))
                    .collect(),
            )
        })
        .collect();
    println!("thickness_qr,gamma_factor,w0,p,ln_a_r");
    for (&(ci, wi), o) in jobs.iter().zip(&out) {
        let c = &cases[ci];
        for (p, e) in o.iter().flatten() {
            println!("{},{},{:.3},{p:.6e},{e:.5}", c.thickness_qr, c.gamma_factor, nodes[wi]);
        }
    }
    eprintln!("w0 scan in {:.0} s", t0.elapsed().as_secs_f64());
    Ok(())
}
