//! The GFMD ladders: Johnson's 1-D sinusoid against its closed form, and a self-affine surface
//! refined in λ_s/Δa against the Richardson-extrapolated grid limit.

use super::ladder::{median_time, rel, Report, Rung};
use asperity::error::Result;
use asperity::input::preset::Preset;

/// Ladders of the GFMD solver: Johnson's 1-D sinusoid (contact width against the closed form,
/// λ/Δa from 64 to 512) and a self-affine system-1 surface refined in λ_s/Δa (4, 8, 16 at
/// L/λ_r = 2, λ_r/λ_s = 8) against the Richardson-extrapolated grid limit (first order in Δa,
/// from the two finest grids); in the full run also the preset grid (512²) with and without
/// adhesion, for speed. Residual 1e-8 throughout.
pub fn gfmd(quick: bool) -> Result<Report> {
    use asperity::gfmd::{self as g, GfmdOptions, GfmdSetup, GridSpec};
    use std::sync::atomic::AtomicBool;
    let runs = if quick { 1 } else { 3 };
    let no = AtomicBool::new(false);
    let opts = GfmdOptions::default();
    let mut rep = Report::default();
    johnson(quick, runs, &mut rep)?;
    // self-affine, refined in λ_s/Δa, against the extrapolated limit
    let ppws: &[f64] = &[4.0, 8.0, 16.0];
    let mut results = Vec::new();
    for &ppw in ppws {
        let grid = GridSpec {
            system_size_ratio: 2.0,
            bandwidth: 8.0,
            points_per_short_wavelength: ppw,
        };
        let mut scene = Preset::resolve("system-1")?.scene()?;
        scene = scene.without_adhesion();
        scene.set_pressure(0.01)?;
        let setup = GfmdSetup {
            scene,
            grid,
            seed: 7,
            surface: None,
            rescale: true,
        };
        let r = g::run(&setup, &opts, &mut |_| {}, &no)?;
        let time = median_time(runs, || g::run(&setup, &opts, &mut |_| {}, &no).map(|r| r.stats.a_r));
        results.push((ppw, grid.n(), r, time));
    }
    let n = results.len();
    let extrap = |f: &dyn Fn(&asperity::gfmd::GfmdResult) -> f64| 2.0 * f(&results[n - 1].2) - f(&results[n - 2].2);
    let a_inf = extrap(&|r| r.stats.a_r);
    let s_inf = extrap(&|r| r.stats.mean_contact_stress);
    let u_inf = extrap(&|r| r.mean_gap_rel);
    for (ppw, nn, r, time) in &results {
        rep.rungs.push(Rung {
            solver: asperity::error::Solver::Gfmd.to_string(),
            case: "system-1 reduced (L/lambda_r = 2, lambda_r/lambda_s = 8) p*=0.01, seed 7".into(),
            setting: format!("lambda_s/da = {ppw}, N = {nn} ({} steps)", r.iterations),
            default: *ppw == 8.0,
            median_s: *time,
            runs,
            errors: vec![
                ("a_r vs extrapolated".into(), rel(r.stats.a_r, a_inf)),
                ("mean_contact_stress".into(), rel(r.stats.mean_contact_stress, s_inf)),
                ("mean_gap".into(), rel(r.mean_gap_rel, u_inf)),
            ],
            bound: None,
            memory_bytes: Some((nn * nn * 100) as u64),
        });
    }
    if !quick {
        for (label, gamma) in [("adhesionless", 0.0), ("adhesive", -1.0)] {
            let preset = Preset::resolve("system-1")?;
            let mut scene = preset.scene()?;
            if gamma == 0.0 {
                scene = scene.without_adhesion();
            }
            let grid = GridSpec::of_preset(&preset, None)?;
            let setup = GfmdSetup {
                scene,
                grid,
                seed: 1,
                surface: None,
                rescale: true,
            };
            let r = g::run(&setup, &opts, &mut |_| {}, &no)?;
            rep.rungs.push(Rung {
                solver: asperity::error::Solver::Gfmd.to_string(),
                case: format!("system-1 preset grid {label} p*=0.01"),
                setting: format!("N = {} ({} steps, a_r = {:.5})", r.grid, r.iterations, r.stats.a_r),
                default: false,
                median_s: r.solve_elapsed_s,
                runs: 1,
                errors: vec![("force residual".into(), r.residual)],
                bound: None,
                memory_bytes: Some((r.grid * r.grid * 100) as u64),
            });
        }
    }
    Ok(rep)
}

/// Johnson's 1-D sinusoid: the contact width against its closed form, λ/Δa from 64 (128 in
/// the quick run) to 1024.
fn johnson(quick: bool, runs: usize, rep: &mut Report) -> Result<()> {
    use asperity::gfmd::{self as g, GfmdOptions, Problem};
    use asperity::surface::heightmap::Surface;
    use asperity::tolerances::GFMD_JOHNSON_REL;
    use std::sync::atomic::AtomicBool;
    let no = AtomicBool::new(false);
    let opts = GfmdOptions::default();
    // Johnson: h = Δ cos(2πx/λ), p̄ = 0.3 p_full, p_full = πE*Δ/λ; sin²(πc/λ) = p̄/p_full
    let ladder: &[usize] = if quick { &[128, 512] } else { &[64, 128, 256, 512, 1024] };
    for &nx in ladder {
        let (da, amp, e) = (1e-8, 1e-8, 1e7);
        let h: Vec<f64> = (0..nx * 2)
            .map(|i| amp * (2.0 * std::f64::consts::PI * (i % nx) as f64 / nx as f64).cos())
            .collect();
        let surf = Surface::new(nx, 2, da, h)?;
        let lambda = nx as f64 * da;
        let p_full = std::f64::consts::PI * e * amp / lambda;
        let pr = Problem {
            surface: &surf,
            modulus: e,
            thickness: f64::INFINITY,
            pressure: 0.3 * p_full,
            gamma: 0.0,
            range: 1e-9,
        };
        let sol = g::solve(&pr, &opts, &mut |_| {}, &no)?;
        let width = sol.on_wall[..nx].iter().filter(|&&c| c).count() as f64 * da;
        let c_exact = lambda / std::f64::consts::PI * 0.3f64.sqrt().asin();
        let time = median_time(runs, || g::solve(&pr, &opts, &mut |_| {}, &no).map(|s| s.iterations));
        rep.rungs.push(Rung {
            solver: asperity::error::Solver::Gfmd.to_string(),
            case: "Johnson sinusoid, p = 0.3 p_full".into(),
            setting: format!("lambda/da = {nx} ({} steps)", sol.iterations),
            default: nx == 512,
            median_s: time,
            runs,
            errors: vec![("contact width vs closed form".into(), rel(width, 2.0 * c_exact))],
            bound: (nx == 512).then_some(GFMD_JOHNSON_REL),
            memory_bytes: Some((nx * 2 * 100) as u64),
        });
    }
    Ok(())
}
