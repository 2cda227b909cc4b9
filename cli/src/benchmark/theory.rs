//! The theory's ladders: the adhesionless solver's rtol, the adhesive march's steps and grid,
//! and the load and thickness sweeps, each against a much finer solution or a closed form
//! (erf(√2 p*) for model 1, [S-18]; the propagator's exact constant-wall case).

use super::ladder::{fmt_t, median_time, rel, scene_of, HardCase, Report, Rung};
use asperity::error::Result;
use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::theory::persson::{self, Accuracy};
use asperity::tolerances::DEFAULT_ACCURACY_REL;
use statrs::function::erf::erf;
use std::time::Instant;

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
    let fine = spec.refined(4);
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
