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
