//! Per case of the reference set and the bandwidth set: the W(0) of model 5's adhesive form that
//! best fits GFMD's loading a_r at p* ≥ 10⁻³ (least squares in ln a_r), with γ̃_glo and the
//! grid and the Tabor parameter. `cargo run --release --example w0_per_case [SEEDS] [bandwidth|full]`
//! (`full`: the theory on the full system II against each case's widest GFMD).
use asperity::fit::bandwidth_gauge::full_system_cases;
use asperity::fit::reference_set::{bandwidth_set, reference_set};
use asperity::fit::set_gauge::{cases_of, tabulate};
use asperity::theory::engine::Options;

fn main() -> asperity::Result<()> {
    let seeds: u64 = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(1);
    let which = std::env::args().nth(2);
    let only_bandwidth = which.as_deref() == Some("bandwidth");
    let mut points: Vec<_> = if only_bandwidth {
        Vec::new()
    } else {
        reference_set().to_vec()
    };
    points.extend_from_slice(bandwidth_set());
    let cases = if which.as_deref() == Some("full") {
        full_system_cases()?
    } else {
        cases_of(&points, seeds)?
    };
    let nodes: Vec<f64> = (0..=19).map(|k| 0.05 + 0.05 * k as f64).collect();
    let tables = tabulate(&cases, &nodes, &Options::chart())?;
    println!("grid,thickness_qr,gamma_factor,gamma_glo,tabor,best_w0,rms_at_best,e_at_w0_0.35");
    for t in &tables {
        let cost = |w: f64| t.at(w).iter().map(|e| e * e).sum::<f64>();
        let mut best = (f64::INFINITY, 0.0);
        for k in 0..=950 {
            let w = 0.05 + 0.001 * k as f64;
            let c = cost(w);
            if c < best.0 {
                best = (c, w);
            }
        }
        let n = t.ln_a_r.len().max(1) as f64;
        let at35: Vec<String> = t.at(0.35).iter().map(|e| format!("{e:.2}")).collect();
        println!(
            "{},{},{},{:.3},{:.3},{:.3},{:.3},{}",
            t.grid,
            t.thickness_qr,
            t.gamma_factor,
            t.gamma_glo,
            t.tabor,
            best.1,
            (best.0 / n).sqrt(),
            at35.join(" ")
        );
    }
    Ok(())
}
