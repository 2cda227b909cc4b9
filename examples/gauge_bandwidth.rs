//! Gauges model 5's change per octave of bandwidth on the bandwidth set and checks it where it
//! was not fitted (docs/physics.md §3.6).
//!
//! `cargo run --release --example gauge_bandwidth [SEEDS]` prints the fitted steps per octave,
//! the error of models 4 and 5 (the set's gauge alone, and with the steps) on the bandwidth
//! set's gauge points per grid, the folds (one grid, one thickness left out), and the theory on
//! the full system II beside the 2048² GFMD points (never fitted).
use asperity::fit::bandwidth_gauge::{bandwidth_residuals, fit_per_octave, leave_out};
use asperity::fit::reference_set::bandwidth_set;
use asperity::fit::set_gauge::{case_errors, cases_of, is_gauge_point, tabulate, CaseTable, ModelChoice};
use asperity::input::model::Model;
use asperity::input::model_five::{BandwidthGauge, Gauge, GAUGE};
use asperity::input::preset::Preset;
use asperity::theory::engine::Options;

/// The grid held out of every fit: the full bandwidth, a check only.
const CHECK_GRID: usize = 2048;

fn stats(e: &[f64]) -> (f64, f64, usize) {
    let n = e.len();
    (
        e.iter().map(|v| v.abs()).sum::<f64>() / n.max(1) as f64,
        e.iter().map(|v| v.abs()).fold(0.0, f64::max),
        n,
    )
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let seeds: u64 = std::env::args().nth(1).map_or(Ok(3), |s| s.parse())?;
    let opts = Options::chart();
    let cases = cases_of(bandwidth_set(), seeds)?;
    let t0 = std::time::Instant::now();
    let nodes: Vec<f64> = (2..=20).map(|k| 0.05 * k as f64).collect();
    let tables = tabulate(&cases, &nodes, &opts)?;
    let (fit_tables, check_tables): (Vec<CaseTable>, Vec<CaseTable>) =
        tables.into_iter().partition(|t| t.grid != CHECK_GRID);
    println!("tables: {:.0} s", t0.elapsed().as_secs_f64());
    let fitted = fit_per_octave(&fit_tables, GAUGE)?;
    let d = fitted.per_octave;
    println!(
        "per octave: dw_b = {:.4}, dw_s = {:.4}, dw_f = {:.4}",
        d.base, d.slope, d.floor
    );
    let set_only = BandwidthGauge {
        at_set: GAUGE,
        per_octave: Gauge {
            base: 0.0,
            slope: 0.0,
            floor: 0.0,
        },
    };
    let m4 = ModelChoice::Fixed(Model::named(4)?);
    let mut grids: Vec<usize> = cases.iter().map(|c| c.grid).collect();
    grids.sort_unstable();
    grids.dedup();
    for &grid in &grids {
        let sel = |t: &CaseTable| t.grid == grid;
        let ts: Vec<CaseTable> = fit_tables
            .iter()
            .chain(&check_tables)
            .filter(|t| sel(t))
            .cloned()
            .collect();
        let mut e4 = Vec::new();
        for c in cases.iter().filter(|c| c.grid == grid) {
            e4.extend(
                case_errors(c, &m4, &opts)?
                    .iter()
                    .filter(|e| is_gauge_point(e))
                    .map(|e| e.ln_a_r),
            );
        }
        for (name, e) in [
            ("model 4", e4),
            ("model 5, set gauge", bandwidth_residuals(&ts, &set_only)),
            ("model 5, per octave", bandwidth_residuals(&ts, &fitted)),
        ] {
            let (m, w, n) = stats(&e);
            println!("grid {grid:>5} | {name:<20} | a_r mean {m:.3} worst {w:.3} | n {n}");
        }
    }
    for g in grids.iter().filter(|&&g| g != CHECK_GRID) {
        let f = leave_out(&fit_tables, GAUGE, Some(*g), None)?;
        let p = f.gauge.per_octave;
        println!(
            "leave grid {g}: dw_b {:.4} dw_s {:.4} dw_f {:.4} held-out mean {:.3} worst {:.3} n {}",
            p.base, p.slope, p.floor, f.held_out_mean, f.held_out_worst, f.held_out_points
        );
    }
    for t in [f64::INFINITY, 1.0, 0.5, 0.3, 0.2, 0.15, 0.1] {
        if !fit_tables.iter().any(|c| c.thickness_qr == t) {
            continue;
        }
        let f = leave_out(&fit_tables, GAUGE, None, Some(t))?;
        let p = f.gauge.per_octave;
        println!(
            "leave t*q_r {t}: dw_b {:.4} dw_s {:.4} dw_f {:.4} held-out mean {:.3} worst {:.3} n {}",
            p.base, p.slope, p.floor, f.held_out_mean, f.held_out_worst, f.held_out_points
        );
    }
    full_system(&opts, &fitted)?;
    Ok(())
}

/// The theory on the full system II (`run`'s scene) beside the 2048² GFMD points.
fn full_system(opts: &Options, fitted: &BandwidthGauge) -> Result<(), Box<dyn std::error::Error>> {
    let preset = Preset::resolve("system-2")?;
    for p in bandwidth_set().iter().filter(|p| p.grid == CHECK_GRID) {
        let scene = preset
            .scene()?
            .with_thickness_qr(p.thickness_qr)?
            .with_surface_energy_j_m2(preset.scene()?.surface_energy_j_m2() * p.gamma_factor)?
            .with_pressure(p.p)?;
        let mut line = format!(
            "full system t*q_r {} gamma x{} p* {:.2e}: GFMD {:.4} ± {:.4}",
            p.thickness_qr, p.gamma_factor, p.p, p.a_r.0, p.a_r.1
        );
        let custom = |g: Gauge| Model {
            kind: asperity::input::model::ModelKind::Custom,
            ..g.model(scene.gamma_glo(), scene.tabor())
        };
        let bw = scene.spectrum().q_s() / scene.spectrum().q_r();
        for (name, m) in [
            ("4", Model::named(4)?),
            ("5 set", custom(GAUGE)),
            ("5 fitted", custom(fitted.at(bw))),
            ("5 stored", Model::named(5)?),
        ] {
            let r = asperity::theory::engine::evaluate(&scene.clone().with_model(m)?, opts)?.stats;
            line += &format!(" | {name} {:.4} ({:.2}x)", r.a_r, r.a_r / p.a_r.0);
        }
        println!("{line}");
    }
    Ok(())
}
