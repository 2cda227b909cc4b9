//! Speed against error: ladders of accuracy settings for each solver, timed (median of several
//! runs) and compared with a converged reference (a much finer solution, and closed forms
//! where they exist). `asperity bench` prints the tables; the full run writes BENCHMARKS.md.
//!
//! Every rung that is the solver's default carries an error bound; `--quick` fails (non-zero
//! exit) if any default rung exceeds its bound, so CI guards the accuracy of what users see.

use asperity::error::Result;
use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::theory::persson::{self, Accuracy};
use asperity::tolerances::DEFAULT_ACCURACY_REL;
use serde::Serialize;
use statrs::function::erf::erf;
use std::time::Instant;

/// One rung of a ladder.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Rung {
    /// Solver name ("adhesionless theory", ...).
    pub solver: String,
    /// The case (preset, model, load, thickness).
    pub case: String,
    /// The accuracy setting of this rung.
    pub setting: String,
    /// Whether this rung is the solver's default.
    pub default: bool,
    /// Median wall time (s).
    pub median_s: f64,
    /// Number of timed runs.
    pub runs: usize,
    /// (quantity, relative error against the reference).
    pub errors: Vec<(String, f64)>,
    /// Bound on the largest error (checked on default rungs).
    pub bound: Option<f64>,
    /// Memory of the solution's working arrays (bytes), where meaningful.
    pub memory_bytes: Option<u64>,
}

impl Rung {
    /// Largest relative error of the rung.
    pub fn max_error(&self) -> f64 {
        self.errors.iter().map(|e| e.1).fold(0.0, f64::max)
    }
    /// True if the rung has a bound and exceeds it.
    pub fn violates(&self) -> bool {
        let e = self.max_error();
        self.bound.is_some_and(|b| e.is_nan() || e > b)
    }
}

/// A hard case and its outcome.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct HardCase {
    /// Solver.
    pub solver: String,
    /// Description of the case.
    pub case: String,
    /// Outcome: "converged", or the error message.
    pub outcome: String,
    /// Key number (a_r) if converged.
    pub a_r: Option<f64>,
    /// Error estimate / residual reported by the solver.
    pub residual: Option<f64>,
    /// Wall time (s).
    pub time_s: f64,
}

/// The whole report.
#[derive(Debug, Clone, Serialize, PartialEq, Default)]
pub struct Report {
    /// Ladders.
    pub rungs: Vec<Rung>,
    /// Hard cases.
    pub hard_cases: Vec<HardCase>,
}

/// Median wall time of `f` over `runs` runs (after one warm-up), in seconds.
pub fn median_time<T>(runs: usize, mut f: impl FnMut() -> T) -> f64 {
    std::hint::black_box(f());
    let mut t: Vec<f64> = (0..runs.max(1))
        .map(|_| {
            let t0 = Instant::now();
            std::hint::black_box(f());
            t0.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(|a, b| a.partial_cmp(b).unwrap());
    t[t.len() / 2]
}

fn rel(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        a.abs()
    } else {
        (a / b - 1.0).abs()
    }
}

fn scene_of(preset: &str, model: u8, p: f64, t: f64) -> Result<Scene> {
    let mut s = Preset::resolve(preset)?.scene()?;
    s.set_model(Model::named(model)?)?;
    s.set_pressure(p)?;
    s.set_thickness_qr(t)?;
    s = s.without_adhesion();
    Ok(s)
}

fn fmt_t(t: f64) -> String {
    if t.is_infinite() {
        "inf".into()
    } else {
        format!("{t}")
    }
}

/// Ladder of the adhesionless theory: rtol from 1e-4 to 1e-10 against rtol = 1e-13 and, for
/// model 1, against erf(√2 p*).
pub fn adhesionless(quick: bool) -> Result<Report> {
    let runs = if quick { 5 } else { 51 };
    let default_rtol = Accuracy::default().rtol;
    let ladder: &[f64] = if quick {
        &[1e-5, 1e-7, 1e-9]
    } else {
        &[1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10]
    };
    let cases: &[(&str, u8, f64, f64)] = &[
        ("system-1", 1, 0.01, f64::INFINITY),
        ("system-1", 3, 0.01, f64::INFINITY),
        ("system-1", 4, 0.1, 0.5),
        ("system-2", 4, 0.005, 0.1),
    ];
    let mut rep = Report::default();
    for &(preset, model, p, t) in cases {
        let scene = scene_of(preset, model, p, t)?;
        let reference = persson::solve(
            &scene,
            &Accuracy {
                rtol: 1e-13,
                ..Accuracy::default()
            },
        )?;
        let exact_area = (model == 1 && t.is_infinite()).then(|| erf(2f64.sqrt() * p));
        for &rtol in ladder {
            let acc = Accuracy {
                rtol,
                ..Accuracy::default()
            };
            let sol = persson::solve(&scene, &acc)?;
            let time = median_time(runs, || persson::solve(&scene, &acc).map(|s| s.a_r));
            let mut errors = vec![
                ("a_r".to_string(), rel(sol.a_r, reference.a_r)),
                (
                    "mean_contact_stress".to_string(),
                    rel(sol.mean_contact_stress, reference.mean_contact_stress),
                ),
                (
                    "contact_stress_variance".to_string(),
                    rel(sol.contact_stress_variance, reference.contact_stress_variance),
                ),
            ];
            if let Some(x) = exact_area {
                errors.push(("a_r vs erf(sqrt2 p*)".into(), rel(sol.a_r, x)));
            }
            let is_default = rtol == default_rtol;
            rep.rungs.push(Rung {
                solver: asperity::error::Solver::AdhesionlessTheory.to_string(),
                case: format!("{preset} model {model} p*={p} t*q_r={}", fmt_t(t)),
                setting: format!("rtol={rtol:.0e} ({} rhs evals)", sol.evaluations),
                default: is_default,
                median_s: time,
                runs,
                errors,
                bound: is_default.then_some(DEFAULT_ACCURACY_REL),
                memory_bytes: Some((sol.trajectory.s.len() * 3 * 8 + sol.resolution.len() * 24) as u64),
            });
        }
    }
    // hard cases
    for (preset, model, p, t) in [
        ("system-1", 3u8, 1e-8, f64::INFINITY),
        ("system-1", 3, 10.0, f64::INFINITY),
        ("system-2", 4, 0.005, 1e-4),
        ("system-2", 2, 1e-8, 1e-4),
    ] {
        let scene = scene_of(preset, model, p, t)?;
        let t0 = Instant::now();
        let r = persson::solve(&scene, &Accuracy::default());
        let time_s = t0.elapsed().as_secs_f64();
        rep.hard_cases.push(HardCase {
            solver: asperity::error::Solver::AdhesionlessTheory.to_string(),
            case: format!("{preset} model {model} p*={p:e} t*q_r={}", fmt_t(t)),
            outcome: match &r {
                Ok(_) => "converged".into(),
                Err(e) => e.to_string(),
            },
            a_r: r.as_ref().ok().map(|s| s.a_r),
            residual: r.as_ref().ok().map(|s| s.error_estimate),
            time_s,
        });
    }
    Ok(rep)
}

fn adhesive_scene(preset: &str, model: u8, p: f64, t: f64) -> Result<Scene> {
    let mut s = Preset::resolve(preset)?.scene()?;
    s.set_model(Model::named(model)?)?;
    s.set_pressure(p)?;
    s.set_thickness_qr(t)?;
    Ok(s)
}

/// Ladder of the adhesive theory: (march steps per ln q, grid points per width) against a much
/// finer solution (192, 40); plus the propagator against its exact constant-wall case.
pub fn adhesive(quick: bool) -> Result<Report> {
    use asperity::theory::adhesion::{self, AdhesionAccuracy};
    use asperity::tolerances::{ADHESION_DEFAULT_REL, EXACT_WALL_ABS};
    let runs = if quick { 3 } else { 15 };
    let def = AdhesionAccuracy::default();
    let acc = |s: f64, p: f64| AdhesionAccuracy {
        steps_per_ln_q: s,
        points_per_width: p,
        explore_branches: false,
        ..def
    };
    let (reference_acc, ladder): (AdhesionAccuracy, &[(f64, f64)]) = if quick {
        (acc(96.0, 40.0), &[(12.0, 5.0), (24.0, 10.0)])
    } else {
        (
            acc(192.0, 40.0),
            &[(6.0, 3.0), (12.0, 5.0), (24.0, 10.0), (48.0, 20.0), (96.0, 20.0)],
        )
    };
    let mut cases: Vec<(&str, u8, f64, f64)> = vec![
        ("system-1", 3, 0.01, f64::INFINITY),
        ("system-2", 4, 0.005, f64::INFINITY),
    ];
    if !quick {
        cases.push(("system-1", 4, 0.01, f64::INFINITY));
        cases.push(("system-2", 4, 0.005, 0.25));
    }
    let mut rep = Report::default();
    for &(preset, model, p, t) in &cases {
        let scene = adhesive_scene(preset, model, p, t)?;
        let reference = adhesion::solve(&scene, &reference_acc, None, None)?;
        for &(st, ppw) in ladder {
            let a = acc(st, ppw);
            let sol = adhesion::solve(&scene, &a, None, None)?;
            let time = median_time(runs, || adhesion::solve(&scene, &a, None, None).map(|s| s.a_r));
            let is_default = st == def.steps_per_ln_q && ppw == def.points_per_width;
            let cells = sol.sigma.len() as u64;
            rep.rungs.push(Rung {
                solver: asperity::error::Solver::AdhesiveTheory.to_string(),
                case: format!("{preset} model {model} p*={p} t*q_r={}", fmt_t(t)),
                setting: format!("{st} steps/ln q, {ppw} points/width ({} it)", sol.iterations),
                default: is_default,
                median_s: time,
                runs,
                errors: vec![
                    ("a_r".to_string(), rel(sol.a_r, reference.a_r)),
                    (
                        "mean_contact_stress".to_string(),
                        rel(sol.mean_contact_stress, reference.mean_contact_stress),
                    ),
                ],
                bound: is_default.then_some(ADHESION_DEFAULT_REL),
                memory_bytes: Some(cells * 8 * 6 + sol.q.len() as u64 * 8 * 8),
            });
        }
    }
    // the propagator alone against its exact case: constant wall, model 1 (a_r = erf((p+σ_a)/√(2V)))
    let mut s1 = adhesive_scene("system-1", 1, 0.01, f64::INFINITY)?;
    s1 = s1.without_adhesion();
    for (st, ppw) in [(12.0, 5.0), (24.0, 10.0)] {
        let a = acc(st, ppw);
        let run = || adhesion::propagate_with_wall(&s1, &a, |_| 0.3, true).map(|r| *r.1.last().unwrap_or(&0.0));
        let got = run()?;
        let exact = erf((0.01 + 0.3) / 0.5f64.sqrt());
        let time = median_time(runs, run);
        rep.rungs.push(Rung {
            solver: asperity::error::Solver::AdhesiveTheory.to_string(),
            case: "propagator, constant wall sigma_a*=0.3, system-1 model 1 p*=0.01".into(),
            setting: format!("{st} steps/ln q, {ppw} points/width"),
            default: st == def.steps_per_ln_q,
            median_s: time,
            runs,
            errors: vec![("a_r vs erf((p+sigma_a)/sqrt(2V))".into(), (got - exact).abs())],
            bound: (st == def.steps_per_ln_q).then_some(EXACT_WALL_ABS),
            memory_bytes: None,
        });
    }
    // hard cases
    let base = adhesive_scene("system-1", 3, 0.01, f64::INFINITY)?;
    let glo = base.gamma_glo();
    let mut hard: Vec<(String, Scene)> = Vec::new();
    for target in [0.01, 10.0] {
        let mut s = base.clone();
        s.set_surface_energy_j_m2(base.surface_energy_j_m2() * target / glo)?;
        hard.push((format!("system-1 model 3 p*=0.01 gamma_glo={target}"), s));
    }
    for (p, t) in [
        (0.005, 0.15),
        (0.005, 0.1),
        (0.005, 0.01),
        (1e-5, f64::INFINITY),
        (1e-5, 0.2),
        (1e-5, 0.15),
        (1.0, f64::INFINITY),
    ] {
        hard.push((
            format!("system-2 model 4 p*={p:e} t*q_r={}", fmt_t(t)),
            adhesive_scene("system-2", 4, p, t)?,
        ));
    }
    for (case, scene) in hard {
        let t0 = Instant::now();
        let r = adhesion::solve(&scene, &def, None, None);
        rep.hard_cases.push(HardCase {
            solver: asperity::error::Solver::AdhesiveTheory.to_string(),
            case,
            outcome: match &r {
                Ok(s) if s.unloading_a_r.is_some() => format!("converged ({}), unloading branch too", s.branch),
                Ok(s) => format!("converged ({}, {} it)", s.branch, s.iterations),
                Err(e) => e.to_string(),
            },
            a_r: r.as_ref().ok().map(|s| s.a_r),
            residual: r.as_ref().ok().map(|s| s.residual),
            time_s: t0.elapsed().as_secs_f64(),
        });
    }
    Ok(rep)
}

/// Ladder of the load sweep (a_r(p*), ū(p*)): a 64-point sweep of system 1 from p* = 1e-3 to 1
/// at the default and the chart accuracy against a 4× finer sweep at the shared loads.
pub fn sweeps(quick: bool) -> Result<Report> {
    use asperity::theory::engine::Options;
    use asperity::theory::sweep::{self, SweepSpec};
    use asperity::tolerances::SWEEP_REFINEMENT_REL;
    let runs = if quick { 1 } else { 5 };
    let mut rep = Report::default();
    let base = Preset::resolve("system-1")?.scene()?;
    let spec = SweepSpec {
        from: 1e-3,
        to: 1.0,
        points: 64,
    };
    let fine = SweepSpec {
        points: 4 * 63 + 1,
        ..spec
    };
    let mut cases = vec![("adhesionless", 0.0, "default", Options::default(), true)];
    cases.push((
        "adhesive",
        base.surface_energy_j_m2(),
        "default",
        Options::default(),
        true,
    ));
    cases.push((
        "adhesive",
        base.surface_energy_j_m2(),
        "chart (explorer)",
        Options::chart(),
        false,
    ));
    for (label, gamma, setting, opts, is_default) in cases {
        let mut scene = base.clone();
        scene.set_surface_energy_j_m2(gamma)?;
        let reference = sweep::sweep(&scene, &fine, &Options::default(), None)?;
        let sw = sweep::sweep(&scene, &spec, &opts, None)?;
        let time = median_time(runs, || sweep::sweep(&scene, &spec, &opts, None).map(|s| s.rows.len()));
        let (ea, eg) = sw.max_errors_against(&reference, 4);
        rep.rungs.push(Rung {
            solver: asperity::error::Solver::LoadSweep.to_string(),
            case: format!("system-1 model 3 {label}, 64 loads p*=1e-3..1"),
            setting: format!("{setting} ({} evaluations)", sw.evaluations),
            default: is_default,
            median_s: time,
            runs,
            errors: vec![("a_r".into(), ea), ("mean_gap".into(), eg)],
            bound: is_default.then_some(SWEEP_REFINEMENT_REL),
            memory_bytes: Some(sw.evaluations as u64 * 9 * 8),
        });
    }
    Ok(rep)
}

/// Ladders of the GFMD solver: Johnson's 1-D sinusoid (contact width against the closed form,
/// λ/Δa from 64 to 512) and a self-affine system-1 surface refined in λ_s/Δa (4, 8, 16 at
/// L/λ_r = 2, λ_r/λ_s = 8) against the Richardson-extrapolated grid limit (first order in Δa,
/// from the two finest grids); in the full run also the preset grid (512²) with and without
/// adhesion, for speed. Residual 1e-8 throughout.
pub fn gfmd(quick: bool) -> Result<Report> {
    use asperity::gfmd::{self as g, GfmdOptions, GfmdSetup, GridSpec, Problem};
    use asperity::surface::heightmap::Surface;
    use asperity::tolerances::GFMD_JOHNSON_REL;
    use std::sync::atomic::AtomicBool;
    let runs = if quick { 1 } else { 3 };
    let no = AtomicBool::new(false);
    let opts = GfmdOptions::default();
    let mut rep = Report::default();
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
            let grid = preset.gfmd.as_ref().map(GridSpec::from_preset).unwrap_or(GridSpec {
                system_size_ratio: 2.0,
                bandwidth: 32.0,
                points_per_short_wavelength: 8.0,
            });
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

/// Renders the ladders as markdown tables (one per solver) and the hard cases.
pub fn markdown(rep: &Report) -> String {
    let mut out = String::new();
    let mut solvers: Vec<&str> = rep.rungs.iter().map(|r| r.solver.as_str()).collect();
    solvers.dedup();
    for solver in solvers {
        out.push_str(&format!("### {solver}\n\n"));
        out.push_str("| case | setting | default | median time | max rel. error | errors | memory |\n");
        out.push_str("|---|---|---|---|---|---|---|\n");
        for r in rep.rungs.iter().filter(|r| r.solver == solver) {
            let errs = r
                .errors
                .iter()
                .map(|(k, v)| format!("{k} {v:.1e}"))
                .collect::<Vec<_>>()
                .join(", ");
            out.push_str(&format!(
                "| {} | {} | {} | {} | {:.1e}{} | {} | {} |\n",
                r.case,
                r.setting,
                if r.default { "**yes**" } else { "" },
                fmt_time(r.median_s),
                r.max_error(),
                match r.bound {
                    Some(b) => format!(" (bound {b:.0e}{})", if r.violates() { ", **FAILED**" } else { "" }),
                    None => String::new(),
                },
                errs,
                r.memory_bytes.map_or("".into(), fmt_bytes),
            ));
        }
        out.push('\n');
    }
    if !rep.hard_cases.is_empty() {
        out.push_str("### Hard cases\n\n| solver | case | outcome | a_r | residual / error estimate | time |\n|---|---|---|---|---|---|\n");
        for h in &rep.hard_cases {
            out.push_str(&format!(
                "| {} | {} | {} | {} | {} | {} |\n",
                h.solver,
                h.case,
                h.outcome,
                h.a_r.map_or("".into(), |a| format!("{a:.6e}")),
                h.residual.map_or("".into(), |a| format!("{a:.1e}")),
                fmt_time(h.time_s)
            ));
        }
        out.push('\n');
    }
    out
}

/// "12.3 µs", "4.5 ms", "1.23 s".
pub fn fmt_time(s: f64) -> String {
    if s < 1e-3 {
        format!("{:.1} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.2} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

fn fmt_bytes(b: u64) -> String {
    if b < 1 << 20 {
        format!("{:.1} KiB", b as f64 / 1024.0)
    } else {
        format!("{:.1} MiB", b as f64 / (1 << 20) as f64)
    }
}

/// A one-line description of this machine (CPU model and core count).
pub fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
    format!("{cpu}, {cores} cores available to the process")
}

/// Why each default is what it is (the knee of each speed–error curve below).
pub const DEFAULTS: &str = "## Defaults and why\n\n\
- **Adhesionless theory: rtol = 1e-7.** Errors fall ~100× per 100× rtol while the time grows \
~1.7×; at 1e-7 a_r is good to ~1e-8 in 12–30 µs, two orders below the 1e-6 target, and a tighter \
rtol buys nothing a user can see. (The mean gap's energy route evaluates U at rtol 1e-11: it \
differentiates U in p*.)\n\
- **Adhesive theory: 24 steps per ln q, 10 grid points per width.** The knee: halving both \
(12, 5) is 4× faster but its error is 2–10× larger on system 1; doubling (48, 20) costs 4× and \
is not reliably better, because the two resolutions pull the error in opposite directions \
(convergence is first order and not monotone). The error estimate of `run` therefore halves each \
resolution separately. The explorer's load curves use (12, 5) (`Options::chart()`), ~2e-3 in \
a_r and ū, well below a pixel.\n\
- **Load sweep: grid step ≤ 0.15 in ln p\\*** (each requested point on the grid, U table shared), \
4th-order energy route: ū to ~1e-4 against a 4× finer sweep.\n\
- **GFMD: residual 1e-8, λ_s/Δa = 8 (presets' 512² grid).** The solver converges to 1e-8 in a few \
hundred FIRE steps almost independently of N; the discretisation error of a_r is first order in \
Δa (8 % at λ_s/Δa = 8 against the extrapolated limit, 4 % at 16), so a finer residual is wasted; \
λ_s/Δa = 8 is the usual compromise of the field ([S]; physics.md §6) and runs in under a second.\n\n\
Hard cases (end of the tables): each either converges (residual stated) or fails with a message \
saying what did not converge; none gives NaN.\n";

/// The heading from which BENCHMARKS.md is written by hand (measurements too long for `bench`,
/// e.g. GFMD at 2048²); `asperity bench` keeps everything from it on when it rewrites the file.
pub const HAND_WRITTEN: &str = "## Measured by hand";

/// The BENCHMARKS.md document around the tables.
pub fn document(tables: &str) -> String {
    format!(
        "# Benchmarks: speed against error\n\n\
         Generated by `cargo run --release -- bench` (this file; `--quick` runs a short version in CI and \
         fails if a default setting exceeds its error bound).\n\n\
         Machine: {}.\n\n\
         Times are medians of repeated runs; errors are relative, against a much finer solution of the \
         same solver (and closed forms where they exist). The default of each solver is marked.\n\n{}\n{}",
        machine(),
        DEFAULTS,
        tables
    )
}
