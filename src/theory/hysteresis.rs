//! The hysteresis window of an adhesive scene: in p* ([`crate::theory::window`], re-exported
//! here) and in the other knobs at a fixed load ([`knob_edges`]): thinning the slab
//! (\[S\] Fig. 7) or raising γ_s, the small-contact branch ends at a fold where the contact
//! jumps in, and going back the large-contact branch ends at another.

use crate::error::Result;
use crate::input::scene::Scene;
use crate::theory::adhesion::AdhesionAccuracy;
use crate::theory::window::bisect;
use serde::Serialize;
use std::sync::atomic::AtomicBool;

pub use crate::theory::window::{
    edge, edge_to, stable_branches, window_around, window_around_from, window_on_branches, window_on_grid, Window,
    EDGE_REL, WINDOW_STEP,
};

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
/// As [`crate::theory::adhesion::solve`].
pub fn knob_edges(
    scene: &Scene,
    knob: crate::theory::knob::Knob,
    points: &[crate::theory::knob::KnobPoint],
    acc: &AdhesionAccuracy,
    cancel: Option<&AtomicBool>,
) -> Result<Vec<KnobEdge>> {
    knob_edges_to(scene, knob, points, acc, EDGE_REL, cancel)
}

/// [`knob_edges`] to the relative precision `rel` in the knob (a chart needs less than
/// [`EDGE_REL`]); the edges are bisected side by side (rayon), each the same whatever the
/// number of threads.
///
/// # Errors
/// [`crate::error::Error::Invalid`] for `rel` outside
/// [`crate::theory::engine::EDGE_REL_RANGE`]; else as [`crate::theory::adhesion::solve`].
pub fn knob_edges_to(
    scene: &Scene,
    knob: crate::theory::knob::Knob,
    points: &[crate::theory::knob::KnobPoint],
    acc: &AdhesionAccuracy,
    rel: f64,
    cancel: Option<&AtomicBool>,
) -> Result<Vec<KnobEdge>> {
    use crate::theory::knob::Knob;
    use rayon::prelude::*;
    let (lo, hi) = crate::theory::engine::EDGE_REL_RANGE;
    crate::error::check_in(crate::error::Field::EdgeRel, rel, lo, hi)?;
    let stable = |e: &crate::theory::engine::Evaluation| -> Vec<f64> {
        e.branches.iter().filter(|b| b.stable).map(|b| b.a_r).collect()
    };
    let acc = AdhesionAccuracy {
        explore_branches: true,
        ..*acc
    };
    // the neighbours with two or more stable branches on one side only, inside first
    let mut pairs = Vec::new();
    for w in points.windows(2) {
        let (Ok(e0), Ok(e1)) = (&w[0].result, &w[1].result) else {
            continue;
        };
        let (s0, s1) = (stable(e0), stable(e1));
        if (s0.len() >= 2) == (s1.len() >= 2) {
            continue;
        }
        pairs.push(if s0.len() >= 2 {
            ((w[0].value, s0), (w[1].value, s1))
        } else {
            ((w[1].value, s1), (w[0].value, s0))
        });
    }
    pairs
        .par_iter()
        .map(|((x_in, b_in), (x_out, b_out))| {
            let value = bisect(*x_in, *x_out, knob == Knob::Thickness, rel, |x| {
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
            Ok(KnobEdge { value, kind })
        })
        .collect()
}
