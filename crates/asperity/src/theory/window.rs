//! The hysteresis window of an adhesive scene in p*: the loads where two stable branches
//! coexist ([`crate::theory::adhesion`] finds every branch at a load), and its edges.
//!
//! On loading (p* rising from small values) the contact follows the lowest stable branch until
//! that branch ends at a fold, the **jump-in** load, and jumps to the upper branch. On
//! unloading it stays on the highest stable branch down to its own fold, the **pull-off**
//! load (below it only the lower branch is left), so between pull-off and jump-in the state
//! depends on the history. Both edges are found by bisection in ln p* on "two or more stable
//! branches at this load", to [`EDGE_REL`] in p* (or a caller's precision: [`edge_to`]).
//!
//! This module depends only on the adhesive solver, so that the sweep and the mean gap (which
//! place the loading branch's jump into contact) can use it; [`crate::theory::hysteresis`]
//! re-exports it and adds the window's edges in the other knobs.

use crate::error::Result;
use crate::input::scene::{Scene, PRESSURE_RANGE};
use crate::theory::adhesion::{self, AdhesionAccuracy};
use serde::Serialize;
use std::sync::atomic::AtomicBool;

/// Relative precision of a window edge in p* (bisection in ln p*); a sweep's edges are
/// refined to its options' `edge_rel` instead (this by default, coarser for charts).
pub const EDGE_REL: f64 = crate::theory::engine::EDGE_REL;

/// The hysteresis window around a load (edges `None` where the window runs past the allowed
/// range of p*, or the sweep's range).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Window {
    /// p* below which the unloading branch no longer exists.
    pub pull_off_pressure: Option<f64>,
    /// p* above which the loading branch no longer exists.
    pub jump_in_pressure: Option<f64>,
}

/// The number of stable branches of `scene` at p*.
///
/// # Errors
/// As [`adhesion::solve`].
pub fn stable_branches(scene: &Scene, p: f64, acc: &AdhesionAccuracy, cancel: Option<&AtomicBool>) -> Result<usize> {
    let mut s = scene.clone();
    s.pressure = p;
    let acc = AdhesionAccuracy {
        explore_branches: true,
        ..*acc
    };
    Ok(adhesion::solve(&s, &acc, None, cancel)?
        .branches
        .iter()
        .filter(|b| b.stable)
        .count())
}

/// The edge between `inside` (≥ 2 stable branches) and `outside` (one): bisection in ln p*
/// to [`EDGE_REL`]; the geometric midpoint of the last bracket.
///
/// # Errors
/// As [`adhesion::solve`].
pub fn edge(
    scene: &Scene,
    inside: f64,
    outside: f64,
    acc: &AdhesionAccuracy,
    cancel: Option<&AtomicBool>,
) -> Result<f64> {
    edge_to(scene, inside, outside, acc, EDGE_REL, cancel)
}

/// [`edge`] to a relative precision `rel` in p* instead of [`EDGE_REL`].
///
/// # Errors
/// As [`adhesion::solve`].
pub fn edge_to(
    scene: &Scene,
    inside: f64,
    outside: f64,
    acc: &AdhesionAccuracy,
    rel: f64,
    cancel: Option<&AtomicBool>,
) -> Result<f64> {
    bisect(inside, outside, true, rel, |p| stable_branches(scene, p, acc, cancel))
}

/// Bisection of a window edge between `inside` (`count` ≥ 2) and `outside`: in ln x when
/// `log` (to `rel` in x), else in x (to `rel` of the larger end); the midpoint of the last
/// bracket.
pub(crate) fn bisect(
    inside: f64,
    outside: f64,
    log: bool,
    rel: f64,
    mut count: impl FnMut(f64) -> Result<usize>,
) -> Result<f64> {
    let to = |x: f64| if log { x.ln() } else { x };
    let from = |y: f64| if log { y.exp() } else { y };
    let (mut a, mut b) = (to(inside), to(outside));
    let tol = if log {
        rel
    } else {
        rel * inside.abs().max(outside.abs())
    };
    while (a - b).abs() > tol {
        let m = 0.5 * (a + b);
        if count(from(m))? >= 2 {
            a = m;
        } else {
            b = m;
        }
    }
    Ok(from(0.5 * (a + b)))
}

/// The hysteresis window on an ascending grid of loads `ps` whose every branch was solved
/// (`stable[i]`: the number of stable branches at `ps[i]`, `None` where the solve failed):
/// the first run of loads with two or more stable branches, each edge that lies inside the
/// grid (its neighbour outside the run solved) refined by [`edge_to`] to `rel`, the two
/// edges side by side (rayon). A window that opens and closes between two grid loads is not
/// seen.
///
/// # Errors
/// As [`adhesion::solve`].
pub fn window_on_grid(
    scene: &Scene,
    ps: &[f64],
    stable: &[Option<usize>],
    acc: &AdhesionAccuracy,
    rel: f64,
    cancel: Option<&AtomicBool>,
) -> Result<Window> {
    let two = |i: usize| stable[i].is_some_and(|c| c >= 2);
    let mut w = Window {
        pull_off_pressure: None,
        jump_in_pressure: None,
    };
    let n = ps.len().min(stable.len());
    if let Some(first) = (0..n).find(|&i| two(i)) {
        let last = first + (first..n).take_while(|&i| two(i)).count() - 1;
        let refine = |inside: usize, outside: Option<usize>| -> Result<Option<f64>> {
            match outside.filter(|&o| o < n && stable[o].is_some()) {
                Some(o) => edge_to(scene, ps[inside], ps[o], acc, rel, cancel).map(Some),
                None => Ok(None),
            }
        };
        let (pull_off, jump_in) = rayon::join(|| refine(first, first.checked_sub(1)), || refine(last, Some(last + 1)));
        w.pull_off_pressure = pull_off?;
        w.jump_in_pressure = jump_in?;
    }
    Ok(w)
}

/// Factor in p* of the steps outwards from a load inside a window to bracket its edges.
pub const WINDOW_STEP: f64 = 4.0;

/// The window around the scene's own load when it lies inside one (two stable branches),
/// else `None`: steps outwards by factors of [`WINDOW_STEP`] in p* to bracket each edge, then
/// [`edge`]. An edge is `None` where the window reaches the end of the load range
/// (`PRESSURE_RANGE`): in particular a pull-off that needs a tensile load.
///
/// # Errors
/// As [`adhesion::solve`].
pub fn window_around(scene: &Scene, acc: &AdhesionAccuracy, cancel: Option<&AtomicBool>) -> Result<Option<Window>> {
    let p0 = scene.pressure;
    if scene.gamma == 0.0 || stable_branches(scene, p0, acc, cancel)? < 2 {
        return Ok(None);
    }
    let bound = |up: bool| -> Result<Option<f64>> {
        // the unloading branch of a strongly adhesive scene often holds at every positive load
        // (pull-off needs a tensile load): one solve at the end of the load range says so
        let end = if up { PRESSURE_RANGE.1 } else { PRESSURE_RANGE.0 };
        if stable_branches(scene, end, acc, cancel)? >= 2 {
            return Ok(None);
        }
        let mut inside = p0;
        loop {
            let next = if up { inside * WINDOW_STEP } else { inside / WINDOW_STEP };
            let next = if up { next.min(end) } else { next.max(end) };
            if next == end || stable_branches(scene, next, acc, cancel)? < 2 {
                return edge(scene, inside, next, acc, cancel).map(Some);
            }
            inside = next;
        }
    };
    Ok(Some(Window {
        pull_off_pressure: bound(false)?,
        jump_in_pressure: bound(true)?,
    }))
}
