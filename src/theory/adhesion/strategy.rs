//! The solve: every root of the scalar self-consistency (`roots`, `shooting`), the branch a
//! loading history reaches (the lowest stable root), the other branches listed, and the
//! solution built from the chosen root: its recorded march gives Pr at q_s and its moments,
//! γ(q) and σ_a(q) at the nodes, and the energy; the root's self-consistency residual
//! |γ(q_s)/γ_s − 1| is reported with it.

use super::grid::{build_grid, Grid};
use super::propagator::{gauss, shift, State};
use super::roots::{find_roots, Root};
use super::walls::sigma_at;
use super::{AdhesionAccuracy, AdhesiveSolution, Branch, BranchState};
use crate::error::{Error, Result};
use crate::input::scene::Scene;
use std::sync::atomic::AtomicBool;

/// The largest residual |γ(q_s)/γ_s − 1| accepted for a root whose bracket collapsed onto a
/// jump of the discrete H (measured: up to 1.4e-4 on system 2, model 4, t·q_r = 0.15).
pub(super) const COLLAPSED: f64 = 1e-3;

/// Solves the adhesive theory for a scene with γ_s > 0 (see the module docs). `warm` is a
/// previous solution of a nearby scene: its branches' C = γ(q_L) are re-bracketed first
/// (with `explore_branches` off the full scan then runs only when they no longer account for
/// every sign change). `cancel` aborts between marches.
///
/// # Errors
/// [`Error::Invalid`] for a bad scene or accuracy (γ_s at most
/// [`crate::input::scene::WEAK_ADHESION_GLO`]·u_ela^(f) included: no adhesion the balance
/// resolves), [`Error::Cancelled`], and
/// [`Error::NotConverged`] when no root met the tolerance.
pub fn solve(
    scene: &Scene,
    acc: &AdhesionAccuracy,
    warm: Option<&AdhesiveSolution>,
    cancel: Option<&AtomicBool>,
) -> Result<AdhesiveSolution> {
    solve_continued(scene, acc, warm.as_slice(), cancel)
}

/// Largest ratio of the next load step to the last one, in ln p*, over which
/// [`solve_continued`] extrapolates the branches' C (a sweep's steps are equal: ratio 1).
pub const EXTRAPOLATE_MAX: f64 = 2.0;

/// [`solve`] continued along a path of solutions of the same scene at other loads, oldest
/// first (a sweep's previous loads). With one, as [`solve`]'s `warm`; with two or more at
/// distinct p* and the same number of branches, each branch's C is extrapolated linearly in
/// ln p* (in asinh(C/c₀), the root scan's variable) from the last two to this scene's p*
/// (when the step is at most [`EXTRAPOLATE_MAX`] times the last one): a load step of 0.11
/// in ln p* moves a thin slab's roots by ~0.1 in that variable, and the extrapolation's
/// guess lands within ~0.01, so each root is bracketed by two marches next to it. Where
/// this scene's p* lies between the last two (a sweep's next anchor, already solved, given
/// before the last load), the same line interpolates: about half the error, and no limit
/// on the step.
///
/// # Errors
/// As [`solve`].
pub fn solve_continued(
    scene: &Scene,
    acc: &AdhesionAccuracy,
    path: &[&AdhesiveSolution],
    cancel: Option<&AtomicBool>,
) -> Result<AdhesiveSolution> {
    acc.validate()?;
    solve_checked(scene, acc, path, cancel)
}

/// [`solve_continued`] on a validated scene, at any resolution the march can run (the
/// engine's error estimate probes at half the points per width, below the allowed minimum).
pub(crate) fn solve_checked(
    scene: &Scene,
    acc: &AdhesionAccuracy,
    path: &[&AdhesiveSolution],
    cancel: Option<&AtomicBool>,
) -> Result<AdhesiveSolution> {
    // below the weakest adhesion the balance resolves the scene is adhesionless (module docs)
    if !scene.is_adhesive() {
        return Err(Error::invalid(
            crate::error::Field::SurfaceEnergy,
            scene.gamma,
            format!(
                "gamma > {} J/m^2 for the adhesive solver (weaker adhesion is below the round-off \
                 of the energy balance: the adhesionless theory answers)",
                crate::error::fmt_value(crate::input::scene::WEAK_ADHESION_GLO * scene.full_contact_energy())
            ),
        ));
    }
    match solve_at(scene, acc, path, cancel) {
        // the loading root on a jump of the discrete H: the same equations at a resolution
        // whose steps end elsewhere (see RESTEP)
        Err(Error::NotConverged { reason, .. }) if reason.starts_with(JUMP_REASON) => {
            let nudged = AdhesionAccuracy {
                steps_per_ln_q: acc.steps_per_ln_q * RESTEP,
                ..*acc
            };
            solve_at(scene, &nudged, path, cancel)
        }
        other => other,
    }
}

/// The start of the reason of a solve whose loading root sat on a jump of the discrete H
/// (its bracket collapsed with a residual beyond [`COLLAPSED`]).
const JUMP_REASON: &str = "the energy balance at q_s is off by";

/// Steps per ln q of the second try of a solve whose loading root sat on a jump of the
/// discrete H, relative to the first. The jump lies where a step's end γ changes sign: a step
/// whose wall ends at zero has its energy ∫a_r W de by the midpoint rule, one whose wall ends
/// just above zero by the pieces split at its onset, and where a_r falls fast in the step the
/// two differ (system II, model 4, t·q_r = 0.1186, γ_s = 0.157 J/m², p* = 3.5e-7: 2.5e-9 J/m²
/// in the first step, which put the next step's onset 1.6 % into it, a jump of a_r(q_s) by
/// 3.4e-3 on which the loading root sat, residual 3.2e-3). With other step ends the jump moves
/// to another C and the root is regular: a_r = 0.509314 there at 26.4 steps per ln q
/// (0.509321 at 18, 0.509312 at 30, 0.509307 at 96). Only solves that would otherwise fail
/// take the second try, so every converged result is unchanged.
const RESTEP: f64 = 1.1;

/// [`solve_checked`] at the given resolution only.
fn solve_at(
    scene: &Scene,
    acc: &AdhesionAccuracy,
    path: &[&AdhesiveSolution],
    cancel: Option<&AtomicBool>,
) -> Result<AdhesiveSolution> {
    let roots_of =
        |w: &AdhesiveSolution| -> Vec<f64> { w.branches.iter().map(|b| b.gamma_coarse * w.gamma_s).collect() };
    let (warm_c, older): (Vec<f64>, Option<(Vec<f64>, f64)>) = match path {
        _ if acc.explore_branches => (Vec::new(), None),
        [.., o, w] => {
            let (c, co) = (roots_of(w), roots_of(o));
            let (x, xw, xo) = (scene.pressure.ln(), w.pressure.ln(), o.pressure.ln());
            let r = (x - xw) / (xw - xo);
            // r > 0: beyond the last (extrapolation); −1 < r < 0: between the two
            let ok = c.len() == co.len() && r.is_finite() && r > -1.0 && r != 0.0 && r <= EXTRAPOLATE_MAX;
            (c, ok.then_some((co, r)))
        }
        [w] => (roots_of(w), None),
        [] => (Vec::new(), None),
    };
    let trend = older.as_ref().map(|(c, r)| (c.as_slice(), *r));
    let (roots, shots) = find_roots(scene, acc, &warm_c, trend, cancel)?;
    let grid = build_grid(scene, acc.steps_per_ln_q);
    let lowest = roots.iter().position(|r| r.stable).unwrap_or(0);
    let upper = roots.iter().rposition(|r| r.stable).filter(|&u| u != lowest);
    // the branch the solution reports: the loading one, or the unloading one where asked for
    // and distinct
    let chosen = match upper {
        Some(u) if acc.follow_unloading => u,
        _ => lowest,
    };
    let branches: Vec<BranchState> = roots
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let kind = if i == lowest || (r.stable && Some(i) != upper) {
                Branch::Loading
            } else if Some(i) == upper {
                Branch::Unloading
            } else {
                Branch::Unstable
            };
            branch_state(scene, &grid, r, kind)
        })
        .collect();
    let root = &roots[chosen];
    // Brent stops at tol, or when its bracket collapses onto a jump of the discrete H (the
    // march switches from the mirror Gaussian to the grid at a step that depends on C, which
    // moves H by up to ~1e-4 relative): such a root is accepted up to COLLAPSED (its residual
    // enters the error estimate, and it is below the discretisation error), beyond that it is
    // an error
    if root.h_rel.is_nan() || root.h_rel > (acc.tol * 1e3).max(COLLAPSED) {
        return Err(Error::NotConverged {
            solver: crate::error::Solver::AdhesiveSelfConsistency,
            reason: format!(
                "{JUMP_REASON} {:.1e} (relative) at the best root after {shots} marches (tolerance \
                 {:.0e}; also at {RESTEP} times the steps per ln q)",
                root.h_rel, acc.tol
            ),
        });
    }
    let mut sol = finish(scene, &grid, root, shots)?;
    if chosen != lowest {
        sol.branch = Branch::Unloading;
    }
    sol.unloading_a_r = upper.map(|u| branches[u].a_r);
    sol.branches = branches;
    sol.contact_loads = roots.iter().map(|r| contact_load(scene, &grid, r)).collect();
    Ok(sol)
}

/// The summary of one root.
fn branch_state(scene: &Scene, grid: &Grid, r: &Root, branch: Branch) -> BranchState {
    let rec = &r.record;
    let a = rec.a_nodes.last().copied().unwrap_or(0.0);
    let q_s = grid.q.last().copied().unwrap_or(0.0);
    BranchState {
        branch,
        stable: r.stable,
        a_r: a,
        sigma_a: sigma_at(scene, q_s, rec.gamma_nodes.last().copied().unwrap_or(0.0)),
        gamma_coarse: r.c / scene.gamma,
        elastic_energy: rec.energy - a * scene.gamma,
        residual: r.h_rel,
    }
}

/// The net force the contact of a root carries per nominal area, ∫σ* Pr dσ* over the contact
/// at q_s (reduced): p* + X, X = ∫σ_a(q)|da_r(q)| the tension carried off by the area that
/// detached at the wall (physics.md §4, §5.1), summed over the resolution steps with the
/// trapezoid rule (X directly, not ∫σPr − p*, which would lose it to round-off at small γ_s).
fn contact_load(scene: &Scene, grid: &Grid, r: &Root) -> f64 {
    let rec = &r.record;
    let wall = |k: usize| sigma_at(scene, grid.q[k], rec.gamma_nodes[k]);
    let n = rec.a_nodes.len().min(grid.q.len()).min(rec.gamma_nodes.len());
    let x: f64 = (1..n)
        .map(|k| 0.5 * (wall(k - 1) + wall(k)) * (rec.a_nodes[k - 1] - rec.a_nodes[k]).max(0.0))
        .sum();
    scene.pressure + x
}

/// Pr(σ*) at q_s from a recorded march's final state with the wall moved to σ_a(q_s): the
/// samples σ*, the density and the wall's position.
fn final_distribution(scene: &Scene, grid: &Grid, rec: &super::shooting::Record) -> (Vec<f64>, Vec<f64>, f64) {
    let fin = &rec.end;
    let q_s = grid.q.last().copied().unwrap_or(0.0);
    let s_end = sigma_at(scene, q_s, rec.gamma_nodes.last().copied().unwrap_or(0.0));
    let p0 = scene.pressure;
    match &fin.state {
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
        State::Grid { h, m, p } => {
            // from the wall up (zeros below the grid's lower end)
            let h = *h;
            let mut p: Vec<f64> = std::iter::repeat_n(0.0, *m).chain(p.iter().copied()).collect();
            shift(&mut p, h, s_end - fin.wall);
            let sig = (0..p.len()).map(|j| j as f64 * h - s_end).collect();
            (sig, p, s_end)
        }
    }
}

/// The solution at a root: Pr(σ*) at q_s and its moments from the recorded march's final
/// state (the wall moved to σ_a(q_s)), γ(q) and σ_a(q) at the nodes, and the energy.
pub(super) fn finish(scene: &Scene, grid: &Grid, root: &Root, iterations: usize) -> Result<AdhesiveSolution> {
    let rec = &root.record;
    let fin = &rec.end;
    let gs = scene.gamma;
    let sigma_nodes: Vec<f64> = grid
        .q
        .iter()
        .zip(&rec.gamma_nodes)
        .map(|(&q, &g)| sigma_at(scene, q, g))
        .collect();
    let p0 = scene.pressure;
    let fin_v = fin.v;
    let (sigma, density, wall_end) = final_distribution(scene, grid, rec);
    let (_, mean, var, tensile) =
        match super::propagator::state_moments(&fin.state, &sigma, &density, p0, fin_v, wall_end) {
            Some(t) => t,
            None => {
                return Err(Error::NotConverged {
                    solver: crate::error::Solver::AdhesivePropagation,
                    reason: "the stress distribution vanished".into(),
                })
            }
        };
    // a_r from the march (spectral mass); the sampled moments carry the trapezoid error
    let a_final = *rec.a_nodes.last().unwrap_or(&0.0);
    let energy = rec.energy - a_final * gs;
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
        v_q: rec.v_nodes.clone(),
        a_q: rec.a_nodes.clone(),
        gamma_q: rec.gamma_nodes.iter().map(|g| g.max(0.0) / gs).collect(),
        sigma_a_q: sigma_nodes,
        sigma,
        density,
        iterations,
        residual: root.h_rel,
        branch: Branch::Loading,
        unloading_a_r: None,
        branches: Vec::new(),
        contact_loads: Vec::new(),
        gamma_s: scene.gamma,
        elastic_energy: energy,
        gamma_glo: if u_f > 0.0 { scene.gamma / u_f } else { 0.0 },
    })
}
