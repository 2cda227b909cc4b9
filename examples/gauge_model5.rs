//! Gauges model 5 on the stored reference set and cross-validates it (docs/physics.md §3.6).
//!
//! `cargo run --release --example gauge_model5 [SEEDS]` prints the fitted gauge, the error
//! table of models 3, 4 and 5 on the set, and the leave-one-out folds.
use asperity::fit::set_gauge::{
    cross_validate, fit_gauge, is_gauge_point, set_errors, summarize, system_two_cases, tabulate, ModelChoice,
    PointError,
};
use asperity::input::model::Model;
use asperity::input::model_five::GAUGE;
use asperity::theory::cycle::PathBranch;
use asperity::theory::engine::Options;

/// A row of the error table: its label and which points it keeps.
type Row = (&'static str, Box<dyn Fn(&PointError) -> bool>);

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let seeds: u64 = std::env::args().nth(1).map_or(Ok(3), |s| s.parse())?;
    let opts = Options::chart();
    let cases = system_two_cases(seeds)?;
    let t0 = std::time::Instant::now();
    let nodes: Vec<f64> = (1..=40).map(|k| 0.025 * k as f64).collect();
    let tables = tabulate(&cases, &nodes, &opts)?;
    println!("tables: {:.0} s", t0.elapsed().as_secs_f64());
    let g = fit_gauge(&tables)?;
    println!(
        "gauge: w_f = {:.4}, w_b = {:.4}, w_s = {:.4} ({:.0} s)",
        g.floor,
        g.base,
        g.slope,
        t0.elapsed().as_secs_f64()
    );
    let table = |name: &str, e: &[PointError]| {
        let rows: [Row; 4] = [
            ("gauge points (loading, p*>=1e-3, adhesive)", Box::new(is_gauge_point)),
            (
                "loading, adhesive, all p*",
                Box::new(|e: &PointError| e.branch == PathBranch::Loading && e.gamma_factor > 0.0),
            ),
            (
                "loading, no adhesion, p*>=1e-3",
                Box::new(|e: &PointError| {
                    e.branch == PathBranch::Loading && e.gamma_factor == 0.0 && e.p >= 1e-3 * 0.999
                }),
            ),
            (
                "unloading, adhesive, p*>=1e-3",
                Box::new(|e: &PointError| {
                    e.branch == PathBranch::Unloading && e.gamma_factor > 0.0 && e.p >= 1e-3 * 0.999
                }),
            ),
        ];
        for (label, keep) in rows {
            let s = summarize(e, keep);
            println!(
                "{name:>8} | {label:<44} | a_r mean {:.3} worst {:.3} | gap mean {:.3} worst {:.3} | n {}",
                s.a_r_mean, s.a_r_worst, s.mean_gap_mean, s.mean_gap_worst, s.points
            );
        }
    };
    for (name, m) in [
        ("model 3", ModelChoice::Fixed(Model::named(3)?)),
        ("model 4", ModelChoice::Fixed(Model::named(4)?)),
        ("fitted", ModelChoice::Gauged(g)),
        ("stored", ModelChoice::Gauged(GAUGE)),
    ] {
        table(name, &set_errors(&cases, &m, &opts)?);
    }
    for t in [f64::INFINITY, 1.0, 0.5, 0.3, 0.2, 0.15, 0.1] {
        let f = cross_validate(&tables, Some(t), None)?;
        println!(
            "leave t*q_r {t}: w_f {:.3} w_b {:.4} w_s {:.4} held-out a_r mean {:.3} worst {:.3} n {}",
            f.gauge.floor, f.gauge.base, f.gauge.slope, f.held_out_mean, f.held_out_worst, f.held_out_points
        );
    }
    for gf in [0.5, 1.0, 2.0] {
        let f = cross_validate(&tables, None, Some(gf))?;
        println!(
            "leave gamma x{gf}: w_f {:.3} w_b {:.4} w_s {:.4} held-out a_r mean {:.3} worst {:.3} n {}",
            f.gauge.floor, f.gauge.base, f.gauge.slope, f.held_out_mean, f.held_out_worst, f.held_out_points
        );
    }
    Ok(())
}
