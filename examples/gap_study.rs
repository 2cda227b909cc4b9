//! The mean gap with adhesion on the small-load set (docs/physics.md §5.1, "What GFMD says
//! about the load mapping"): for every adhesive case and stored loading point, model 5's
//! branch gap ū₀(p_c), the adhesionless gap ū₀(p₀) at the same load, and ū₀(p₀ + φX) for a
//! ladder of fractions φ of the theory's edge tension X = p_c − p₀, mean over the case's maps.
//!
//! `cargo run --release --example gap_study > /tmp/gap-study.csv`
use asperity::fit::reference_set::small_load_set;
use asperity::fit::set_gauge::cases_of;
use asperity::input::model::Model;
use asperity::theory::cycle::PathBranch;
use asperity::theory::engine::Options;
use asperity::theory::gap::state::DryGap;
use asperity::theory::sweep::{sweep, SweepSpec};
use rayon::prelude::*;

const PHI: [f64; 9] = [0.0, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let t0 = std::time::Instant::now();
    let cases = cases_of(small_load_set(), 3)?;
    let opts = Options::default();
    let rows: Vec<String> = cases
        .par_iter()
        .filter(|c| c.gamma_factor > 0.0)
        .flat_map(|c| {
            let mut loads: Vec<f64> = c
                .points
                .iter()
                .filter(|p| p.branch == PathBranch::Loading)
                .map(|p| p.p)
                .collect();
            loads.sort_by(f64::total_cmp);
            loads.dedup_by(|a, b| (*a / *b - 1.0).abs() < 1e-9);
            let spec = SweepSpec {
                from: loads[0],
                to: loads[loads.len() - 1],
                points: loads.len(),
            };
            let k = c.scenes.len() as f64;
            let mut acc = vec![[0.0f64; 4 + PHI.len()]; loads.len()];
            for scene in &c.scenes {
                let mut run = || -> Result<(), Box<dyn std::error::Error>> {
                    let s = scene.clone().with_model(Model::named(5).expect("model 5"))?;
                    let sw = sweep(&s, &spec, &opts, None)?;
                    let dry = DryGap::new(&s, spec.from, &opts)?;
                    for (a, r) in acc.iter_mut().zip(&sw.rows) {
                        let x = (r.contact_load - r.p).max(0.0);
                        a[0] += r.a_r / k;
                        a[1] += r.mean_gap_rel / k;
                        a[2] += r.mean_gap_upper_rel / k;
                        a[3] += x / r.p / k;
                        for (j, phi) in PHI.iter().enumerate() {
                            a[4 + j] += dry.gap_at(r.p + phi * x)?.0 / k;
                        }
                    }
                    Ok(())
                };
                if let Err(e) = run() {
                    eprintln!("t*q_r {} gamma x{}: {e}", c.thickness_qr, c.gamma_factor);
                    return Vec::new();
                }
            }
            let t = if c.thickness_qr.is_finite() {
                format!("{}", c.thickness_qr)
            } else {
                "inf".into()
            };
            loads
                .iter()
                .zip(&acc)
                .map(|(p, a)| {
                    let cols: Vec<String> = a.iter().map(|v| format!("{v:.6e}")).collect();
                    format!("{t},{},{p:.10e},{}", c.gamma_factor, cols.join(","))
                })
                .collect::<Vec<_>>()
        })
        .collect();
    let phis: Vec<String> = PHI.iter().map(|f| format!("gap_phi_{f}")).collect();
    println!(
        "thickness_qr,gamma_factor,p,a_r,mean_gap_rel,mean_gap_upper_rel,x_over_p,{}",
        phis.join(",")
    );
    for r in rows {
        println!("{r}");
    }
    eprintln!("gap study in {:.0} s", t0.elapsed().as_secs_f64());
    Ok(())
}
