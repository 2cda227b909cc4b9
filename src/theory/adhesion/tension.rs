//! The theory under tension (physics.md §6.2): the contact branch continued to p* ≤ 0, and
//! the theory's pull-off.
//!
//! # Equations
//!
//! The march, the walls and the energy balance are those of p* > 0 (`shooting`, [S-5..S-9,
//! S-14]); only the start changes. At q_L the distribution is δ(σ* − p*) [S-1] and the wall
//! sits at −σ_a*(q_L) = −κ_L √C, κ_L = k_G √(q_L E* f(q_L t))/(E*ḡ), capped at γ_s/ρ where the
//! model has the cap [S-8]. Under tension (p* < 0) the delta lies inside the wall only if
//!
//! ```text
//! p* + σ_a*(q_L; C) > 0   ⇔   C > C_min = (p*/κ_L)²   (and |p*| below the cap)
//! ```
//!
//! For C ≤ C_min nothing is in contact, a_r ≡ 0 and H(C) = C, whose root C = 0 is the detached
//! state: the lowest stable branch under tension. On (C_min, γ_s], H(C_min⁺) = C_min ≥ 0 (the
//! distance p* + σ_a closes, a_r(q_s) → 0) and H(γ_s) ≥ 0, so roots with contact come in pairs:
//! an unstable one (H falls through it) and above it the **contact branch** (H rises), the
//! highest stable root, which continues the unloading branch of p* > 0. Where the pair merges
//! (a fold: min H = 0) the contact can carry no more tension: the theory's **pull-off**.
//! No load beyond −min(κ_L √γ_s, cap) can be held at all (C ≤ γ_s at any root).
//!
//! # Search
//!
//! At each load H is scanned on (C_min, γ_s] as at p* > 0 (`roots::scan`, the monotone bound
//! on each cell), and where the scan shows no negative H the smallest scan value is minimised
//! by a golden-section search in w = asinh(C/c₀) (a shallow dip next to the fold is narrower
//! than a scan cell); the highest sign change from − to + is refined by Brent's method.
//!
//! The pull-off follows the path GFMD's cycle takes (physics.md §6.1): p* = 0, −p₁, −2p₁,
//! −4p₁, … until the contact branch is gone, then the bracket between the last load held and
//! the first lost is bisected (geometrically in |p*|, arithmetically from 0) to `rel` of the
//! pull-off. The mean gap is not defined under tension (§6.2) and is not computed.

use super::grid::build_grid;
use super::propagator::Marcher;
use super::roots::{refine, scan};
use super::shooter::{check_bounded, point, Point, Scale, Shooter};
use super::strategy::{finish, COLLAPSED};
use super::walls::WallCoefficients;
use super::{AdhesionAccuracy, AdhesiveSolution, Branch};
use crate::error::{Error, Result, Solver};
use crate::input::scene::Scene;
use serde::Serialize;
use std::sync::atomic::AtomicBool;

/// Golden-section steps of the dip search (the bracket shrinks by 0.618 per step: two scan
/// cells of w shrink below 1e-3).
const DIP_STEPS: usize = 16;

/// The most loads of the doubling path and of the bisection each.
const MAX_LOADS: usize = 60;

/// The contact branch of `scene` at p* = `p` ≤ 0 (the scene's own p* is ignored), or None
/// where no contact branch exists at that load. The solution's `branch` is
/// [`Branch::Unloading`]; its mean gap is not defined.
///
/// # Errors
/// [`Error::Invalid`] for p* > 0, [`Error::Cancelled`], and [`Error::NotConverged`] where the
/// root found does not meet the tolerance or the march overflowed its grid.
pub fn tensile_branch(
    scene: &Scene,
    p: f64,
    acc: &AdhesionAccuracy,
    cancel: Option<&AtomicBool>,
) -> Result<Option<AdhesiveSolution>> {
    if p > 0.0 || p.is_nan() {
        return Err(Error::invalid(
            crate::error::Field::Pressure,
            p,
            "the tensile branch is for p* <= 0",
        ));
    }
    let gs = scene.gamma;
    if gs <= 0.0 {
        return Ok(None);
    }
    let mut s = scene.clone();
    s.pressure = p;
    let grid = build_grid(&s, acc.steps_per_ln_q);
    let mut sh = Shooter {
        m: Marcher::new(&s, &grid, *acc),
        coef: WallCoefficients::new(&s, &grid),
        shots: 0,
    };
    let kappa = sh.coef.per_sqrt_gamma_node[0];
    if -p >= (kappa * gs.sqrt()).min(sh.coef.cap) {
        return Ok(None);
    }
    let c_min = (p / kappa).powi(2);
    let i_full = sh.m.full_energy();
    let e0 = if grid.e_scale > 0.0 { grid.e_scale } else { i_full }.max(1e-300);
    let scale = Scale { c0: 1e-3 * e0.min(gs) };
    let (w_lo, w_hi) = (scale.w(c_min) + 1e-9, scale.w(gs));
    let mut pts = scan(&mut sh, &scale, w_lo, w_hi, gs, cancel)?;
    if !pts.iter().any(|q| q.h < 0.0) {
        if let Some(dip) = dip(&mut sh, &scale, &pts, gs) {
            pts.push(dip);
            pts.sort_by(|a, b| a.w.total_cmp(&b.w));
        }
    }
    let Some(i) = pts.windows(2).rposition(|w| w[0].h < 0.0 && w[1].h >= 0.0) else {
        check_bounded(&sh)?;
        return Ok(None);
    };
    let (a, b) = (pts[i], pts[i + 1]);
    let root = refine(&mut sh, &scale, a.w, a.h, b.w, b.h, acc.tol * gs, cancel)?;
    check_bounded(&sh)?;
    if root.h_rel.is_nan() || root.h_rel > (acc.tol * 1e3).max(COLLAPSED) {
        return Err(Error::NotConverged {
            solver: Solver::AdhesiveSelfConsistency,
            reason: format!(
                "under tension at p* = {p:.3e} the energy balance at q_s is off by {:.1e} (relative) \
                 at the contact branch (tolerance {:.0e})",
                root.h_rel, acc.tol
            ),
        });
    }
    let mut sol = finish(&s, &grid, &root, sh.shots)?;
    sol.branch = Branch::Unloading;
    Ok(Some(sol))
}

/// The smallest H near the scan's smallest value (golden section in w over the two cells
/// next to it), where the scan showed none below zero: the dip of a contact pair about to
/// merge.
fn dip(sh: &mut Shooter<'_>, scale: &Scale, pts: &[Point], gs: f64) -> Option<Point> {
    let k = (1..pts.len().saturating_sub(1)).min_by(|&i, &j| pts[i].h.total_cmp(&pts[j].h))?;
    let at = |sh: &mut Shooter<'_>, w: f64| point(sh, scale, w, gs);
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let (mut lo, mut hi) = (pts[k - 1].w, pts[k + 1].w);
    let mut x1 = at(sh, hi - r * (hi - lo));
    let mut x2 = at(sh, lo + r * (hi - lo));
    for _ in 0..DIP_STEPS {
        if x1.h < 0.0 || x2.h < 0.0 {
            break;
        }
        if x1.h < x2.h {
            hi = x2.w;
            x2 = x1;
            x1 = at(sh, hi - r * (hi - lo));
        } else {
            lo = x1.w;
            x1 = x2;
            x2 = at(sh, lo + r * (hi - lo));
        }
    }
    Some(if x1.h < x2.h { x1 } else { x2 })
}

/// The theory's pull-off along a tensile path (see the module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TensilePullOff {
    /// The most tensile p* at which the contact branch was held (≤ 0; 0 where it does not
    /// exist even at p* = 0: the contact then ends at p* → 0⁺, as without adhesion).
    pub pressure: f64,
    /// The nearest p* beyond it tried, where no contact branch exists (the bracket's other end).
    pub lost: f64,
    /// a_r of the contact branch at `pressure` (0 where none is held).
    pub a_r: f64,
    /// The most tension any contact branch can hold: min(κ_L √γ_s, γ_s/ρ) in p* (the
    /// coarsest scale's Griffith stress at full surface energy, capped where the model caps).
    pub bound: f64,
    /// The contact branch at the path's loads p* = 0, −p₁, −2p₁, … that held it, in order.
    #[serde(skip)]
    pub path: Vec<AdhesiveSolution>,
}

/// The pull-off of `scene` (see the module docs): the path 0, −`step`, −2`step`, … and the
/// bisection of the last bracket to `rel` of the pull-off (or of `step` where only p* = 0 held).
///
/// # Errors
/// [`Error::Invalid`] for `step` or `rel` not positive and finite; otherwise as
/// [`tensile_branch`].
pub fn pull_off(
    scene: &Scene,
    step: f64,
    rel: f64,
    acc: &AdhesionAccuracy,
    cancel: Option<&AtomicBool>,
) -> Result<TensilePullOff> {
    use crate::error::Field;
    if !(step > 0.0 && step.is_finite()) {
        return Err(Error::invalid(
            Field::SweepStep,
            step,
            "a finite p* > 0 (the tensile path's first step)",
        ));
    }
    if !(rel > 0.0 && rel < 1.0) {
        return Err(Error::invalid(
            Field::EdgeRel,
            rel,
            "(0, 1) (the pull-off's relative precision)",
        ));
    }
    let bound = tension_bound(scene, acc);
    let mut path: Vec<AdhesiveSolution> = Vec::new();
    let mut held: Option<(f64, f64)> = None;
    let mut lost = f64::NAN;
    let mut p = 0.0;
    for k in 0..MAX_LOADS {
        match tensile_branch(scene, p, acc, cancel)? {
            Some(sol) => {
                held = Some((p, sol.a_r));
                path.push(sol);
                p = -step * 2f64.powi(k as i32);
            }
            None => {
                lost = p;
                break;
            }
        }
    }
    let Some((mut at, mut a_r)) = held else {
        return Ok(TensilePullOff {
            pressure: 0.0,
            lost: 0.0,
            a_r: 0.0,
            bound,
            path,
        });
    };
    if lost.is_nan() {
        return Err(Error::NotConverged {
            solver: Solver::AdhesiveTheory,
            reason: format!("the contact branch still held at p* = {at:.3e} after {MAX_LOADS} loads"),
        });
    }
    for _ in 0..MAX_LOADS {
        let width = at - lost;
        if (at < 0.0 && width <= rel * -at) || (at == 0.0 && -lost <= rel * step) {
            break;
        }
        let mid = if at < 0.0 { -(at * lost).sqrt() } else { 0.5 * lost };
        match tensile_branch(scene, mid, acc, cancel)? {
            Some(sol) => {
                at = mid;
                a_r = sol.a_r;
            }
            None => lost = mid,
        }
    }
    Ok(TensilePullOff {
        pressure: at,
        lost,
        a_r,
        bound,
        path,
    })
}

/// min(κ_L √γ_s, γ_s/ρ): beyond this tension (in p*) no contact branch exists (module docs).
pub fn tension_bound(scene: &Scene, acc: &AdhesionAccuracy) -> f64 {
    let grid = build_grid(scene, acc.steps_per_ln_q);
    let coef = WallCoefficients::new(scene, &grid);
    (coef.per_sqrt_gamma_node[0] * scene.gamma.max(0.0).sqrt()).min(coef.cap)
}
