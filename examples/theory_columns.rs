//! The theory columns of the small-load set (docs/reference-set.md, "Small loads and finite
//! size"): models 1–5 at every stored load of every system II case, on each map GFMD ran
//! (γ_s and ρ rescaled as GFMD ran them), mean over the maps, on the branch the path is on
//! (the unloading branch inside a hysteresis window on the unloading rows).
//!
//! `cargo run --release --example theory_columns > data/reference/theory-models-small-256.csv`
//!
//! A case whose sweep fails for a model (no adhesive solution found at some load) is left out
//! for that model, with one line on stderr: the trust read-out then falls back to the set's
//! columns there.
use asperity::fit::reference_set::small_load_set;
use asperity::fit::set_gauge::{case_errors, cases_of, ModelChoice};
use asperity::input::model::Model;
use asperity::theory::engine::Options;
use rayon::prelude::*;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let t0 = std::time::Instant::now();
    let cases = cases_of(small_load_set(), 3)?;
    let opts = Options::default();
    let jobs: Vec<(usize, u8)> = (0..cases.len()).flat_map(|c| (1..=5u8).map(move |m| (c, m))).collect();
    let rows: Vec<Vec<String>> = jobs
        .par_iter()
        .map(|&(ci, m)| {
            let c = &cases[ci];
            let model = ModelChoice::Fixed(Model::named(m).expect("models 1-5 exist"));
            let errs = match case_errors(c, &model, &opts) {
                Ok(e) => e,
                Err(e) => {
                    eprintln!(
                        "t*q_r {} gamma x{} model {m}: left out ({e})",
                        c.thickness_qr, c.gamma_factor
                    );
                    return Vec::new();
                }
            };
            let t = if c.thickness_qr.is_finite() {
                format!("{}", c.thickness_qr)
            } else {
                "inf".into()
            };
            c.points
                .iter()
                .filter_map(|p| {
                    let e = errs.iter().find(|e| e.branch == p.branch && e.p == p.p)?;
                    let branch = p.branch.name();
                    Some(format!(
                        "system-2,{t},{},{branch},{:.10e},{m},{:.10e},{:.10e}",
                        c.gamma_factor,
                        p.p,
                        p.a_r.0 * e.ln_a_r.exp(),
                        p.mean_gap_rel.0 * e.ln_mean_gap.exp()
                    ))
                })
                .collect()
        })
        .collect();
    println!("system,thickness_qr,gamma_factor,branch,p,model,theory_a_r,theory_mean_gap_rel");
    for r in rows.into_iter().flatten() {
        println!("{r}");
    }
    eprintln!(
        "theory columns: {} cases x 5 models in {:.0} s",
        cases.len(),
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}
