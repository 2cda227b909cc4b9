//! Which power κ of the Tabor parameter model 5's adhesion measure m = γ̃_glo·μ_T^κ should carry
//! (docs/physics.md §3.6): for κ ∈ {0, ¼, ½, ¾, 1}, the gauge (w_f, w_b, w_s) fitted on each
//! bandwidth's tables alone — the set's 256² maps (λ_r/λ_s = 16), the bandwidth set's 512² and
//! 1024² maps (32, 64) and the full system II against its widest GFMD (128) — with its
//! in-sample error and its errors with one thickness, then one γ_s, left out.
//!
//! `cargo run --release --example tabor_exponent_scan` (about 20 CPU minutes: the tables).
use asperity::fit::bandwidth_gauge::full_system_cases;
use asperity::fit::reference_set::bandwidth_set;
use asperity::fit::set_gauge::{
    cases_of, cross_validate, fit_gauge, gauge_residuals, system_two_cases, tabulate, CaseTable,
};
use asperity::theory::engine::Options;

fn mean_worst(e: &[f64]) -> (f64, f64) {
    let a = e.iter().map(|v| v.abs());
    (a.clone().sum::<f64>() / e.len().max(1) as f64, a.fold(0.0, f64::max))
}

/// Pooled held-out mean and worst |e_a| of the folds that leave out each value of the
/// thickness (`by_thickness`) or of the γ_s factor ([`cross_validate`]).
fn folds(tables: &[CaseTable], by_thickness: bool) -> Result<(f64, f64), Box<dyn std::error::Error>> {
    let key = |t: &CaseTable| if by_thickness { t.thickness_qr } else { t.gamma_factor };
    let mut values: Vec<f64> = tables.iter().map(key).collect();
    values.sort_by(f64::total_cmp);
    values.dedup();
    let (mut sum, mut n, mut worst) = (0.0, 0, 0.0f64);
    for v in values {
        let f = if by_thickness {
            cross_validate(tables, Some(v), None)?
        } else {
            cross_validate(tables, None, Some(v))?
        };
        sum += f.held_out_mean * f.held_out_points as f64;
        n += f.held_out_points;
        worst = worst.max(f.held_out_worst);
    }
    Ok((sum / n.max(1) as f64, worst))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let opts = Options::chart();
    let nodes: Vec<f64> = (1..=40).map(|k| 0.025 * k as f64).collect();
    let maps = cases_of(bandwidth_set(), 1)?;
    let groups = [
        ("256² maps (16)", tabulate(&system_two_cases(1)?, &nodes, &opts)?),
        (
            "512² maps (32)",
            tabulate(
                &maps.iter().filter(|c| c.grid == 512).cloned().collect::<Vec<_>>(),
                &nodes,
                &opts,
            )?,
        ),
        (
            "1024² maps (64)",
            tabulate(
                &maps.iter().filter(|c| c.grid == 1024).cloned().collect::<Vec<_>>(),
                &nodes,
                &opts,
            )?,
        ),
        ("full system (128)", tabulate(&full_system_cases()?, &nodes, &opts)?),
    ];
    println!("| tables | κ | w_f | w_b | w_s | in-sample mean / worst | thickness out | γ_s out |");
    println!("|---|---|---|---|---|---|---|---|");
    for (name, tables) in &groups {
        for kappa in [0.0, 0.25, 0.5, 0.75, 1.0] {
            let ts: Vec<CaseTable> = tables
                .iter()
                .map(|t| CaseTable {
                    measure: t.gamma_glo * t.tabor.powf(kappa),
                    ..t.clone()
                })
                .collect();
            let g = fit_gauge(&ts)?;
            let (m, w) = mean_worst(&gauge_residuals(&ts, g));
            let (tm, tw) = folds(&ts, true)?;
            let (gm, gw) = folds(&ts, false)?;
            println!(
                "| {name} | {kappa} | {:.3} | {:.3} | {:.3} | {m:.3} / {w:.3} | {tm:.3} / {tw:.3} | {gm:.3} / {gw:.3} |",
                g.floor, g.base, g.slope
            );
        }
    }
    Ok(())
}
