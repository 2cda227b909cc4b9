//! Model 5's theory columns for the reference set (docs/reference-set.md, "The trust
//! read-out"): at every stored point of system II (adhesive or not), model 5's a_r and ū/h_rms on each map GFMD
//! ran, mean over the maps, the branch the path is on (as the set's model-4 columns).
//!
//! `cargo run --release --example model5_columns > data/reference/theory-model5-256.csv`
//!
//! With `full`: model 5 on the *full* system II (λ_r/λ_s = 128, what `run --model 5` computes)
//! at every load of the bandwidth set's cases, the columns the trust read-out uses for a model 5
//! scene of the full bandwidth (`> data/reference/theory-model5-full.csv`). Its ū column is NaN:
//! ū/h_rms grows with ln(λ_r/λ_s), so the full system's ū is not comparable with GFMD's on a
//! 1024² map (λ_r/λ_s = 64).
use asperity::fit::bandwidth_gauge::full_system_cases;
use asperity::fit::reference_set::reference_set;
use asperity::fit::set_gauge::{case_errors, cases_of, ModelChoice};
use asperity::input::model::Model;
use asperity::theory::engine::Options;
use rayon::prelude::*;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let full = std::env::args().nth(1).as_deref() == Some("full");
    let cases = if full {
        full_system_cases()?
    } else {
        cases_of(reference_set(), 3)?
    };
    let model = ModelChoice::Fixed(Model::named(5)?);
    let opts = Options::default();
    let rows: Vec<Vec<String>> = cases
        .par_iter()
        .map(|c| -> Result<Vec<String>, asperity::error::Error> {
            let errs = case_errors(c, &model, &opts)?;
            Ok(c.points
                .iter()
                .filter_map(|p| {
                    let e = errs.iter().find(|e| e.branch == p.branch && e.p == p.p)?;
                    let branch = p.branch.name();
                    let t = if c.thickness_qr.is_finite() {
                        format!("{}", c.thickness_qr)
                    } else {
                        "inf".into()
                    };
                    Some(format!(
                        "system-2,{t},{},{branch},{:.10e},{:.10e},{:.10e}",
                        c.gamma_factor,
                        p.p,
                        p.a_r.0 * e.ln_a_r.exp(),
                        if full {
                            f64::NAN
                        } else {
                            p.mean_gap_rel.0 * e.ln_mean_gap.exp()
                        }
                    ))
                })
                .collect())
        })
        .collect::<Result<_, _>>()?;
    println!("system,thickness_qr,gamma_factor,branch,p,theory_a_r,theory_mean_gap_rel");
    for r in rows.into_iter().flatten() {
        println!("{r}");
    }
    Ok(())
}
