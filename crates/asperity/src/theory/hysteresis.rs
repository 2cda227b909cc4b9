//! The hysteresis window of an adhesive scene in p*: the loads where two stable branches
//! coexist ([`crate::theory::adhesion`] finds every branch at a load).
//!
//! On loading (p* rising from small values) the contact follows the lowest stable branch until
//! that branch ends at a fold, the **jump-in** load, and jumps to the upper branch. On
//! unloading it stays on the highest stable branch down to its own fold, the **pull-off**
//! load (below it only the lower branch is left), so between pull-off and jump-in the state
//! depends on the history. Both edges are found by bisection in ln p* on "two or more stable
//! branches at this load", to [`EDGE_REL`] in p*.
//!
//! The same holds in the other knobs at a fixed load ([`knob_edges`]): thinning the slab
//! (\[S\] Fig. 7) or raising γ_s, the small-contact branch ends at a fold where the contact
//! jumps in, and going back the large-contact branch ends at another.

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
    bisect(inside, outside, true, |p| stable_branches(scene, p, acc, cancel))
}

/// Bisection of a window edge between `inside` (`count` ≥ 2) and `outside`: in ln x when
/// `log` (to [`EDGE_REL`] in x), else in x (to [`EDGE_REL`] of the larger end); the midpoint
/// of the last bracket.
fn bisect(inside: f64, outside: f64, log: bool, mut count: impl FnMut(f64) -> Result<usize>) -> Result<f64> {
    let to = |x: f64| if log { x.ln() } else { x };
    let from = |y: f64| if log { y.exp() } else { y };
    let (mut a, mut b) = (to(inside), to(outside));
    let tol = if log {
        EDGE_REL
    } else {
        EDGE_REL * inside.abs().max(outside.abs())
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

/// Which branch ends at a window edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum EdgeKind {
    /// The lowest stable branch (small contact) ends: a state on it jumps into contact.
    JumpIn,
    /// The highest stable branch ends: a state on it drops out of contact (pull-off).
    PullOff,
}

/// One edge of a hysteresis window in a knob other than the load (t·q_r, γ_s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct KnobEdge {
    /// The knob's value at the edge.
    pub value: f64,
    /// Which branch ends there.
    pub kind: EdgeKind,
}

/// The window edges of a knob sweep: between every two neighbouring values where one has two
/// or more stable branches and the other one, the edge by bisection (in ln t·q_r, or linearly
/// in γ_s) to [`EDGE_REL`]. Which branch ends there is read from the side with one branch: if
/// its a_r lies nearer the upper branch's of the other side, the lower branch ended (a jump
/// into contact), else the upper one (pull-off). Values whose solve failed bound no edge.
///
/// # Errors
/// As [`adhesion::solve`].
pub fn knob_edges(
    scene: &Scene,
    knob: crate::theory::knob::Knob,
    points: &[crate::theory::knob::KnobPoint],
    acc: &AdhesionAccuracy,
    cancel: Option<&AtomicBool>,
) -> Result<Vec<KnobEdge>> {
    use crate::theory::knob::Knob;
    let stable = |e: &crate::theory::engine::Evaluation| -> Vec<f64> {
        e.branches.iter().filter(|b| b.stable).map(|b| b.a_r).collect()
    };
    let acc = AdhesionAccuracy {
        explore_branches: true,
        ..*acc
    };
    let mut edges = Vec::new();
    for w in points.windows(2) {
        let (Ok(e0), Ok(e1)) = (&w[0].result, &w[1].result) else {
            continue;
        };
        let (s0, s1) = (stable(e0), stable(e1));
        if (s0.len() >= 2) == (s1.len() >= 2) {
            continue;
        }
        let ((x_in, b_in), (x_out, b_out)) = if s0.len() >= 2 {
            ((w[0].value, &s0), (w[1].value, &s1))
        } else {
            ((w[1].value, &s1), (w[0].value, &s0))
        };
        let value = bisect(x_in, x_out, knob == Knob::Thickness, |x| {
            let s = knob.apply(scene, x);
            stable_branches(&s, s.pressure, &acc, cancel)
        })?;
        let (lo, hi) = (b_in[0], b_in[b_in.len() - 1]);
        let out = b_out.first().copied().unwrap_or(f64::NAN);
        let kind = if (out - hi).abs() < (out - lo).abs() {
            EdgeKind::JumpIn
        } else {
            EdgeKind::PullOff
        };
        edges.push(KnobEdge { value, kind });
    }
    Ok(edges)
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
