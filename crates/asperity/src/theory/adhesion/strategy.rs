//! The solve strategy: Anderson from the loading start, then the fallbacks as data
//! ([`Fallback`], in the order of [`plan`]), and the solution built from the converged
//! fixed point. A scene where nothing converges is an error whose message lists the attempts
//! actually made, each with its residual.

use super::fixed_point::Attempt;
use super::grid::{build_grid, Grid};
use super::propagator::{gauss, shift, Marcher, State};
use super::walls::walls_for;
use super::{AdhesionAccuracy, AdhesiveSolution, Branch};
use crate::error::{Error, Field, Result};
use crate::input::scene::Scene;
use std::sync::atomic::AtomicBool;

/// One fallback strategy, tried when the plain Anderson attempt at the requested resolution
/// stagnates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Fallback {
    /// Anderson from the same start at a nearby resolution (factors on steps per ln q and on
    /// points per width): near a jump into contact the discrete map can stagnate for one
    /// particular resolution (measured: system 2, t·q_r = 0.15, residual ~1e-4) while nearby
    /// ones converge to the same a_r within the discretisation error.
    Resolution { steps: f64, points: f64 },
    /// A start bisected between the two states of a plain-iteration cycle, then Anderson with
    /// each mixing factor in turn.
    CycleBisection { betas: &'static [f64] },
    /// Anderson from full contact (a_r ≡ 1): the upper branch.
    FullContact,
    /// Damped Anderson from the adhesionless start.
    Damped { beta: f64 },
    /// Continuation in γ_s from 0 in equal steps, each warm-started.
    GammaContinuation { stages: usize },
}

/// The fallbacks in the order they are tried: every one when `thorough` (`run`), the cheap
/// ones otherwise (sweeps).
pub(super) fn plan(thorough: bool) -> &'static [Fallback] {
    if thorough {
        &[
            Fallback::Resolution {
                steps: 1.25,
                points: 1.0,
            },
            Fallback::Resolution {
                steps: 0.8,
                points: 1.2,
            },
            Fallback::CycleBisection {
                betas: &[0.2, 0.1, 1.0],
            },
            Fallback::FullContact,
            Fallback::Damped { beta: 0.3 },
            Fallback::GammaContinuation { stages: 8 },
        ]
    } else {
        &[Fallback::CycleBisection { betas: &[0.2] }, Fallback::FullContact]
    }
}

/// Checks the solver's own knobs.
fn validate(acc: &AdhesionAccuracy) -> Result<()> {
    for (name, v, lo, hi) in [
        (Field::AdhesionSteps, acc.steps_per_ln_q, 2.0, 1e4),
        (Field::AdhesionPoints, acc.points_per_width, 2.0, 1e3),
        (Field::AdhesionTol, acc.tol, 1e-15, 1e-1),
    ] {
        if !(v >= lo && v <= hi) {
            return Err(Error::invalid(name, v, format!("{lo} <= value <= {hi}")));
        }
    }
    Ok(())
}

/// The warm start when `warm` lives on the same grid.
fn warm_start(warm: Option<&AdhesiveSolution>, grid: &Grid) -> Option<Vec<f64>> {
    match warm {
        Some(w)
            if w.a_q.len() == grid.steps.len() + 1 && w.q.first() == grid.q.first() && w.q.last() == grid.q.last() =>
        {
            Some(w.a_q.clone())
        }
        _ => None,
    }
}

/// Solves the adhesive theory for a scene with γ_s > 0 (see the module docs). `warm` is a
/// previous solution of a nearby scene (a_r at the nodes), used as the start when its grid
/// matches. `cancel` aborts between iterations.
///
/// # Errors
/// [`Error::Invalid`] for a bad scene or accuracy, [`Error::Cancelled`], and
/// [`Error::NotConverged`] listing every attempt made when no fixed point was found.
pub fn solve(
    scene: &Scene,
    acc: &AdhesionAccuracy,
    warm: Option<&AdhesiveSolution>,
    cancel: Option<&AtomicBool>,
) -> Result<AdhesiveSolution> {
    scene.validate()?;
    validate(acc)?;
    let grid = build_grid(scene, acc.steps_per_ln_q);
    let k = grid.steps.len();
    let mut m = Marcher::new(scene, &grid, *acc);
    // the adhesionless march (σ_a ≡ 0) is the loading branch's start
    let adhesionless = m.march(&vec![0.0; k]).a_nodes;
    let warm_x = warm_start(warm, &grid);
    let start = warm_x.clone().unwrap_or_else(|| adhesionless.clone());
    let mut iterations = 0;
    let mut log: Vec<String> = Vec::new();
    let att = m.fixed_point(scene, start, 1.0, cancel)?;
    iterations += att.iterations;
    let from = if warm_x.is_some() {
        "the warm start"
    } else {
        "the adhesionless state"
    };
    log.push(format!("Anderson from {from} ({:.1e})", att.residual));
    let mut best = att.residual;
    if att.converged {
        return finish(&mut m, scene, att, Branch::Loading, iterations, cancel);
    }
    for fb in plan(acc.thorough) {
        let found: Option<(Attempt, Branch)> = match *fb {
            Fallback::Resolution { steps, points } => {
                let a = AdhesionAccuracy {
                    steps_per_ln_q: acc.steps_per_ln_q * steps,
                    points_per_width: acc.points_per_width * points,
                    ..*acc
                };
                let g2 = build_grid(scene, a.steps_per_ln_q);
                let mut m2 = Marcher::new(scene, &g2, a);
                let s2 = match warm_start(warm, &g2) {
                    Some(x) => x,
                    None => m2.march(&vec![0.0; g2.steps.len()]).a_nodes,
                };
                let c = m2.fixed_point(scene, s2, 1.0, cancel)?;
                iterations += c.iterations;
                log.push(format!(
                    "Anderson at ({}, {}) ({:.1e})",
                    a.steps_per_ln_q, a.points_per_width, c.residual
                ));
                best = best.min(c.residual);
                if c.converged {
                    let mut sol = finish(&mut m2, scene, c, Branch::Loading, iterations, cancel)?;
                    sol.resolution_used = Some((a.steps_per_ln_q, a.points_per_width));
                    return Ok(sol);
                }
                None
            }
            Fallback::CycleBisection { betas } => match m.cycle_bisection(scene, &adhesionless, cancel)? {
                None => {
                    log.push("cycle bisection (no bracket)".into());
                    None
                }
                Some(x0) => {
                    iterations += 48;
                    let mut hit = None;
                    for &beta in betas {
                        let c = m.fixed_point(scene, x0.clone(), beta, cancel)?;
                        iterations += c.iterations;
                        log.push(format!("cycle bisection, beta {beta} ({:.1e})", c.residual));
                        best = best.min(c.residual);
                        if c.converged {
                            hit = Some((c, Branch::Loading));
                            break;
                        }
                    }
                    hit
                }
            },
            Fallback::FullContact => {
                let c = m.fixed_point(scene, vec![1.0; k + 1], 1.0, cancel)?;
                iterations += c.iterations;
                log.push(format!("from full contact ({:.1e})", c.residual));
                best = best.min(c.residual);
                c.converged.then_some((c, Branch::UpperFromFullContact))
            }
            Fallback::Damped { beta } => {
                let c = m.fixed_point(scene, adhesionless.clone(), beta, cancel)?;
                iterations += c.iterations;
                log.push(format!("damped, beta {beta} ({:.1e})", c.residual));
                best = best.min(c.residual);
                c.converged.then_some((c, Branch::Loading))
            }
            Fallback::GammaContinuation { stages } => {
                let mut x = adhesionless.clone();
                let mut s = scene.clone();
                let mut reached = true;
                for stage in 1..=stages {
                    s.gamma = scene.gamma * stage as f64 / stages as f64;
                    let c = m.fixed_point(&s, x.clone(), 0.5, cancel)?;
                    iterations += c.iterations;
                    if !c.converged {
                        log.push(format!(
                            "continuation in gamma (stage {stage}/{stages}: {:.1e})",
                            c.residual
                        ));
                        reached = false;
                        break;
                    }
                    x = c.x;
                }
                if reached {
                    let c = m.fixed_point(scene, x, 0.5, cancel)?;
                    iterations += c.iterations;
                    log.push(format!("continuation in gamma ({:.1e})", c.residual));
                    best = best.min(c.residual);
                    c.converged.then_some((c, Branch::LoadingGammaContinuation))
                } else {
                    None
                }
            }
        };
        if let Some((c, branch)) = found {
            return finish(&mut m, scene, c, branch, iterations, cancel);
        }
    }
    Err(Error::NotConverged {
        solver: "adhesive fixed point".into(),
        reason: format!(
            "residual {best:.2e} > tol {:.0e} after {iterations} map evaluations ({}): the loading \
             branch may not exist at this load, or it oscillates between states; try a nearby p*, t \
             or gamma",
            acc.tol,
            log.join(", ")
        ),
    })
}

/// The solution of a converged fixed point: the second branch (with `explore_branches`), the
/// final march, Pr(σ*) at q_s and its moments, and the energy.
fn finish(
    m: &mut Marcher<'_>,
    scene: &Scene,
    att: Attempt,
    branch: Branch,
    mut iterations: usize,
    cancel: Option<&AtomicBool>,
) -> Result<AdhesiveSolution> {
    let grid = m.grid;
    let acc = m.acc;
    let k = grid.steps.len();
    let mut unloading_a_r = None;
    if acc.explore_branches {
        let full = vec![1.0; k + 1];
        let up = m.fixed_point(scene, full, 1.0, cancel)?;
        iterations += up.iterations;
        if up.converged {
            let (a_up, a_lo) = (up.x[k], att.x[k]);
            if (a_up - a_lo).abs() > 1e-3 * a_lo.max(1e-12) + 100.0 * acc.tol * a_lo {
                unloading_a_r = Some(a_up);
            }
        }
    }
    let x = att.x;
    let w = walls_for(scene, grid, &x);
    m.pressure = scene.pressure;
    let fin = m.march(&w.mid);
    // the final state with the wall at σ_a(q_s)
    let s_end = *w.sigma_nodes.last().unwrap_or(&0.0);
    let p0 = scene.pressure;
    let fin_v = fin.v;
    let (sigma, density, wall_end) = match &fin.state {
        State::Analytic => {
            // mirror Gaussian about −wall: sample it
            let wall = fin.wall;
            let sd = fin.v.sqrt();
            let lo = -wall;
            let hi = p0 + 8.0 * sd.max(1e-300);
            let n = 801;
            let sig: Vec<f64> = (0..n).map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64).collect();
            let d = p0 + wall;
            let dens = sig
                .iter()
                .map(|&s| {
                    let x = s + wall;
                    if x <= 0.0 || fin.v <= 0.0 {
                        0.0
                    } else {
                        gauss(x - d, fin.v) - gauss(x + d, fin.v)
                    }
                })
                .collect();
            (sig, dens, wall)
        }
        State::Grid { h, p } => {
            let (h, mut p) = (*h, p.clone());
            shift(&mut p, h, s_end - fin.wall);
            let sig = (0..p.len()).map(|j| j as f64 * h - s_end).collect();
            (sig, p, s_end)
        }
    };
    let (_, mean, var, tensile) = match fin.state_moments(&sigma, &density, p0, fin_v, wall_end) {
        Some(t) => t,
        None => {
            return Err(Error::NotConverged {
                solver: "adhesive propagation".into(),
                reason: "the stress distribution vanished".into(),
            })
        }
    };
    // a_r from the march (spectral mass); the sampled moments carry the trapezoid error
    let a_final = *fin.a_nodes.last().unwrap_or(&0.0);
    let energy = w.energy - a_final * scene.gamma;
    let u_f = scene.full_contact_energy();
    Ok(AdhesiveSolution {
        pressure: p0,
        a_r: a_final,
        mean_contact_stress: mean,
        contact_stress_variance: var,
        width: fin_v.sqrt(),
        sigma_a: wall_end,
        tensile_area: tensile,
        detached_fraction: 1.0 - a_final,
        q: grid.q.clone(),
        v_q: fin.v_nodes,
        a_q: x,
        gamma_q: w.gamma_nodes,
        sigma_a_q: w.sigma_nodes,
        sigma,
        density,
        iterations,
        residual: att.residual,
        branch,
        unloading_a_r,
        elastic_energy: energy,
        gamma_glo: if u_f > 0.0 { scene.gamma / u_f } else { 0.0 },
        resolution_used: None,
    })
}
