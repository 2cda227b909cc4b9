//! Model 5's bandwidth steps gauged like for like on the full bandwidth: the theory on the full
//! system II (the continuum spectrum `run` uses, λ_r/λ_s = 128) against the bandwidth set's
//! widest GFMD of each case (docs/physics.md §3.6), cross-validated by leaving one thickness and
//! one γ_s out.
//!
//! `cargo run --release --example gauge_full_system` prints the fitted steps per octave, the
//! error of model 4, of the stored model 5 and of the fit on those points, and the folds.
use asperity::fit::bandwidth_gauge::{bandwidth_residuals, fit_per_octave, full_system_cases, leave_out};
use asperity::fit::set_gauge::{case_errors, tabulate, CaseTable, ModelChoice};
use asperity::input::model::Model;
use asperity::input::model_five::{BANDWIDTH_GAUGE, GAUGE};
use asperity::theory::engine::Options;

fn stats(e: &[f64]) -> (f64, f64, usize) {
    let n = e.len();
    let a: Vec<f64> = e.iter().map(|v| v.abs()).collect();
    (
        a.iter().sum::<f64>() / n.max(1) as f64,
        a.iter().copied().fold(0.0, f64::max),
        n,
    )
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let opts = Options::chart();
    let cases = full_system_cases()?;
    let t0 = std::time::Instant::now();
    let nodes: Vec<f64> = (2..=20).map(|k| 0.05 * k as f64).collect();
    let tables = tabulate(&cases, &nodes, &opts)?;
    println!("tables: {} cases, {:.0} s", tables.len(), t0.elapsed().as_secs_f64());
    let fitted = fit_per_octave(&tables, GAUGE)?;
    let d = fitted.per_octave;
    println!(
        "per octave: dw_b = {:.4}, dw_s = {:.4}, dw_f = {:.4}",
        d.base, d.slope, d.floor
    );
    let mut e4 = Vec::new();
    for c in &cases {
        e4.extend(
            case_errors(c, &ModelChoice::Fixed(Model::named(4)?), &opts)?
                .iter()
                .map(|e| e.ln_a_r),
        );
    }
    for (name, e) in [
        ("model 4", e4),
        ("model 5 stored", bandwidth_residuals(&tables, &BANDWIDTH_GAUGE)),
        ("model 5 fitted here", bandwidth_residuals(&tables, &fitted)),
    ] {
        let (m, w, n) = stats(&e);
        println!("{name:<20} | a_r mean {m:.3} worst {w:.3} | n {n}");
    }
    let mut pooled = Vec::new();
    for t in [f64::INFINITY, 1.0, 0.5, 0.3, 0.2, 0.15, 0.1] {
        let f = leave_out(&tables, GAUGE, None, Some(t))?;
        let p = f.gauge.per_octave;
        pooled.push((f.held_out_mean, f.held_out_points));
        println!(
            "leave t*q_r {t}: dw_b {:.4} dw_s {:.4} dw_f {:.4} held-out mean {:.3} worst {:.3} n {}",
            p.base, p.slope, p.floor, f.held_out_mean, f.held_out_worst, f.held_out_points
        );
    }
    for g in [0.5, 1.0, 2.0] {
        let (train, test): (Vec<CaseTable>, Vec<CaseTable>) = tables.iter().cloned().partition(|c| c.gamma_factor != g);
        let fit = fit_per_octave(&train, GAUGE)?;
        let (m, w, n) = stats(&bandwidth_residuals(&test, &fit));
        let p = fit.per_octave;
        pooled.push((m, n));
        println!(
            "leave gamma x{g}: dw_b {:.4} dw_s {:.4} dw_f {:.4} held-out mean {m:.3} worst {w:.3} n {n}",
            p.base, p.slope, p.floor
        );
    }
    let (s, n) = pooled
        .iter()
        .fold((0.0, 0), |(s, n), &(m, k)| (s + m * k as f64, n + k));
    println!(
        "pooled held-out mean |e_a| over both kinds of fold: {:.3}",
        s / n.max(1) as f64
    );
    Ok(())
}
