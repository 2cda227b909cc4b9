//! The hysteresis window of an adhesive scene in p*: the loads where two stable branches
//! coexist ([`crate::theory::adhesion`] finds every branch at a load).
//!
//! On loading (p* rising from small values) the contact follows the lowest stable branch until
//! that branch ends at a fold, the **jump-in** load, and jumps to the upper branch. On
//! unloading it stays on the highest stable branch down to its own fold, the **pull-off**
//! load (below it only the lower branch is left), so between pull-off and jump-in the state
//! depends on the history. Both edges are found by bisection in ln p* on "two or more stable
//! branches at this load", to [`EDGE_REL`] in p*.

use crate::error::Result;
use crate::input::scene::{Scene, PRESSURE_RANGE};
use crate::theory::adhesion::{self, AdhesionAccuracy};
use serde::Serialize;
use std::sync::atomic::AtomicBool;

/// Relative precision of a window edge in p* (bisection in ln p*).
pub const EDGE_REL: f64 = 0.005;

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
    let (mut a, mut b) = (inside.ln(), outside.ln());
    while (a - b).abs() > EDGE_REL {
        let m = 0.5 * (a + b);
        if stable_branches(scene, m.exp(), acc, cancel)? >= 2 {
            a = m;
        } else {
            b = m;
        }
    }
    Ok((0.5 * (a + b)).exp())
}

/// The window around the scene's own load when it lies inside one (two stable branches),
/// else `None`: steps outwards by factors of 2 in p* to bracket each edge, then [`edge`].
///
/// # Errors
/// As [`adhesion::solve`].
pub fn window_around(scene: &Scene, acc: &AdhesionAccuracy, cancel: Option<&AtomicBool>) -> Result<Option<Window>> {
    let p0 = scene.pressure;
    if scene.gamma == 0.0 || stable_branches(scene, p0, acc, cancel)? < 2 {
        return Ok(None);
    }
    let bound = |up: bool| -> Result<Option<f64>> {
        let mut inside = p0;
        loop {
            let next = if up { inside * 2.0 } else { inside * 0.5 };
            if !(PRESSURE_RANGE.0..=PRESSURE_RANGE.1).contains(&next) {
                return Ok(None);
            }
            if stable_branches(scene, next, acc, cancel)? < 2 {
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
