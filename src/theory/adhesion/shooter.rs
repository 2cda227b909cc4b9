//! One scene's H(C) at one resolution (see `shooting`), as the root finders (`roots`,
//! `pair`, `tension`) take it: a shot is one forward march for C = γ(q_L), the unit of their
//! work, so they count shots and check for cancellation between them.
//!
//! They search in the scan variable
//!
//! ```text
//! w = asinh(C/c₀),   C = c₀ sinh w
//! ```
//!
//! logarithmic in |C| on both sides of 0 (c₀: a thousandth of the coarsest step's
//! full-contact energy, `roots`), and see H = F − G through its parts: F = C + I and
//! G = γ_s a_r(q_s) both rise with C, which bounds H on a cell of w (`roots::scan`).

use super::propagator::Marcher;
use super::shooting::Shot;
use super::walls::WallCoefficients;
use crate::error::Result;
use std::sync::atomic::{AtomicBool, Ordering};

/// The scan variable w = asinh(C/c₀) and back.
pub(super) struct Scale {
    pub(super) c0: f64,
}

impl Scale {
    pub(super) fn w(&self, c: f64) -> f64 {
        (c / self.c0).asinh()
    }
    pub(super) fn c(&self, w: f64) -> f64 {
        self.c0 * w.sinh()
    }
}

/// Units of round-off in the energy balance H = C + I − γ_s a_r(q_s) at a root: C and I
/// nearly cancel where adhesion is weak (C ≈ −I ≫ γ_s), so H is known to about ε·|C| per
/// term, and C itself, taken from the scan variable w (C = c₀ sinh w), to ε·|w|·|C|: Brent's
/// bracket cannot be narrower than w's ulps (it stops at 4 of them). 8 units cover that
/// bracket and the sum's few roundings.
pub(super) const BALANCE_ULPS: f64 = 8.0;

/// The round-off of H at w (J/m²): [`BALANCE_ULPS`]·ε·(1 + |w|)·|C(w)|. Far below the
/// tolerance tol·γ_s·a_r except where γ_s a_r is tiny against |C| (weak adhesion, e.g.
/// γ_s ≲ 1e-7 J/m² on system II at tol = 1e-8): there the energy balance is met to
/// round-off and the reported mismatch is the part beyond it. Its effect on a_r is bounded
/// by the weak walls' whole effect, a_r·σ_a*/p* (~1e-7 a_r at γ_s = 1e-12 J/m², far below
/// the discretisation error).
pub(super) fn balance_floor(scale: &Scale, w: f64) -> f64 {
    BALANCE_ULPS * f64::EPSILON * (1.0 + w.abs()) * scale.c(w).abs()
}

/// The solver for one scene and resolution: the marcher and the wall constants.
pub(super) struct Shooter<'a> {
    pub(super) m: Marcher<'a>,
    pub(super) coef: WallCoefficients,
    pub(super) shots: usize,
}

impl<'a> Shooter<'a> {
    pub(super) fn h(&mut self, c: f64) -> Shot {
        self.shots += 1;
        self.m.shoot(&self.coef, c, false)
    }
}

/// [`crate::error::Error::NotConverged`] where a march of `s` needed a grid beyond its bound
/// (`propagator::GRID_MAX_NODES`): its H is not to be trusted, so neither are the roots.
pub(super) fn check_bounded(s: &Shooter<'_>) -> Result<()> {
    if s.m.overflow {
        Err(crate::error::Error::NotConverged {
            solver: crate::error::Solver::AdhesiveMarch,
            reason: format!(
                "the stress distribution would need more than {} grid nodes at p* = {:.3e} \
                 (the adhesive wall ran further from it in one resolution step than the grid can \
                 follow); a finer resolution in ln q may resolve it",
                s.m.max_nodes(),
                s.m.pressure
            ),
        })
    } else {
        Ok(())
    }
}

/// [`crate::error::Error::Cancelled`] once `cancel` is set.
pub(super) fn check_cancel(cancel: Option<&AtomicBool>) -> Result<()> {
    if cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
        Err(crate::error::Error::Cancelled)
    } else {
        Ok(())
    }
}

/// A scan point: w, H and its rising part F = C + I, and G = γ_s a_r(q_s) (H = F − G).
#[derive(Clone, Copy)]
pub(super) struct Point {
    pub(super) w: f64,
    pub(super) h: f64,
    pub(super) f: f64,
    pub(super) g: f64,
}

/// H and its parts at w.
pub(super) fn point(s: &mut Shooter<'_>, scale: &Scale, w: f64, gs: f64) -> Point {
    let shot = s.h(scale.c(w));
    Point {
        w,
        h: shot.h,
        f: shot.f,
        g: gs * shot.a_s,
    }
}

/// Cells narrower than this in w (a factor 1.65 in C) may be left unsplit on the curvature
/// test of [`smooth_cell`]; wider ones only on the monotone bound.
const CURVATURE_CELL: f64 = 0.5;
/// Safety factor on the curvature estimate of [`smooth_cell`].
const CURVATURE_SAFETY: f64 = 4.0;

/// Whether cell i of `pts` (narrower than [`CURVATURE_CELL`]) can hold no root beyond what
/// its end values show, judging H'' by the largest second difference K of H at the cell's
/// ends and next to them (four neighbouring points at least): with |H''| ≤ K, H differs from
/// the chord by at most Kδ²/8 on a cell of width δ, so a cell whose ends have one sign holds
/// no pair of roots while min|H₀|, |H₁| > S·Kδ²/8, and a cell with a sign change holds one
/// root (H monotone) while |H₁ − H₀| > S·Kδ². S = [`CURVATURE_SAFETY`].
///
/// The monotone bound [F₀ − G₁, F₁ − G₀] alone cannot rule out a pair where H is small
/// against the rise of F and G (tiny loads with strong adhesion, where H ≈ 1e-3 γ_s while F
/// and G each rise by 0.4 γ_s: every cell was bisected down to `roots::SCAN_MIN_CELL`).
pub(super) fn smooth_cell(pts: &[Point], i: usize) -> bool {
    let delta = pts[i + 1].w - pts[i].w;
    if delta > CURVATURE_CELL || i == 0 || i + 2 >= pts.len() {
        return false;
    }
    let d2 = |j: usize| -> f64 {
        let (a, b, c) = (pts[j - 1], pts[j], pts[j + 1]);
        2.0 * ((c.h - b.h) / (c.w - b.w) - (b.h - a.h) / (b.w - a.w)) / (c.w - a.w)
    };
    let lo = i.saturating_sub(1).max(1);
    let hi = (i + 2).min(pts.len() - 2);
    let k = (lo..=hi).map(|j| d2(j).abs()).fold(0.0, f64::max);
    if !k.is_finite() {
        return false;
    }
    let (h0, h1) = (pts[i].h, pts[i + 1].h);
    if (h0 < 0.0) == (h1 < 0.0) {
        h0.abs().min(h1.abs()) > CURVATURE_SAFETY * k * delta * delta / 8.0
    } else {
        (h1 - h0).abs() > CURVATURE_SAFETY * k * delta * delta
    }
}
