//! The hysteresis window of an adhesive scene: in p* ([`crate::theory::window`], re-exported
//! here) and in the other knobs at a fixed load ([`knob_edges`]): thinning the slab
//! (\[S\] Fig. 7) or raising γ_s, the small-contact branch ends at a fold where the contact
//! jumps in, and going back the large-contact branch ends at another.
//!
//! A window narrower than a sweep's step lies between two values with one stable branch each
//! and shows only as a jump of a_r between them; [`window_probes`] searches such a jump for a
//! value inside the window, so that [`knob_edges`] can bracket it. The explorer's thickness
//! chart, `asperity sweep --over` and Python's knob sweeps all find windows this way
//! ([`crate::report::sweep`]).

use crate::error::Result;
use crate::input::scene::Scene;
use crate::theory::adhesion::AdhesionAccuracy;
use crate::theory::engine::{Evaluation, Options};
use crate::theory::knob::{knob_sweep, Knob, KnobPoint, KnobSpec};
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
    knob: Knob,
    points: &[KnobPoint],
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
    knob: Knob,
    points: &[KnobPoint],
    acc: &AdhesionAccuracy,
    rel: f64,
    cancel: Option<&AtomicBool>,
) -> Result<Vec<KnobEdge>> {
    use rayon::prelude::*;
    let (lo, hi) = crate::theory::engine::EDGE_REL_RANGE;
    crate::error::check_in(crate::error::Field::EdgeRel, rel, lo, hi)?;
    let stable = |e: &Evaluation| -> Vec<f64> { e.branches.iter().filter(|b| b.stable).map(|b| b.a_r).collect() };
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

/// Neighbouring values whose a_r differ by more than this factor (both with one stable branch)
/// are searched for a hysteresis window between them. A jump into contact changes a_r by
/// orders of magnitude (system II, model 3, γ_s = 0.126–0.157 J/m²: 0.7 → 1e-4 across
/// t·q_r ≈ 0.1–0.15), a smooth stretch of a sweep by tens of percent per step; a steep
/// stretch without a window (model 1 there: a_r falls 100-fold within 7 % of t·q_r on one
/// branch) costs [`WINDOW_PROBES`] solves and marks nothing.
pub const JUMP_FACTOR: f64 = 3.0;

/// Most solves spent searching one jump for a window (bisections in ln t·q_r, or linearly in
/// γ_s: the window is found where it is wider than 1/64 of a step, ~1 % in t·q_r on the
/// explorer's grid).
pub const WINDOW_PROBES: usize = 6;

/// A value of `knob` inside a hysteresis window between `lo` and `hi` (the knob's value and
/// its evaluation, one stable branch each) whose a_r differ by more than [`JUMP_FACTOR`], and
/// its evaluation: bisection (in ln t·q_r, linearly in γ_s), each step towards the side where
/// a_r changes more, until a value has two stable branches (at most [`WINDOW_PROBES`] solves
/// by `eval`, None where a solve fails). None without such a jump, or where no window was
/// found.
///
/// # Errors
/// What `eval` returns.
pub fn window_between(
    knob: Knob,
    eval: &dyn Fn(f64) -> Result<Option<Evaluation>>,
    lo: (f64, &Evaluation),
    hi: (f64, &Evaluation),
) -> Result<Option<(f64, Evaluation)>> {
    let two = |e: &Evaluation| e.branches.iter().filter(|b| b.stable).count() >= 2;
    let jump = |a: f64, b: f64| (a.max(b) / a.min(b).max(f64::MIN_POSITIVE)).ln();
    if two(lo.1) || two(hi.1) || jump(lo.1.stats.a_r, hi.1.stats.a_r) <= JUMP_FACTOR.ln() {
        return Ok(None);
    }
    let ((mut t0, mut a0), (mut t1, mut a1)) = ((lo.0, lo.1.stats.a_r), (hi.0, hi.1.stats.a_r));
    for _ in 0..WINDOW_PROBES {
        let tm = match knob {
            Knob::Thickness => (t0 * t1).sqrt(),
            Knob::Gamma => 0.5 * (t0 + t1),
        };
        let Some(e) = eval(tm)? else {
            return Ok(None);
        };
        if two(&e) {
            return Ok(Some((tm, e)));
        }
        let am = e.stats.a_r;
        if jump(a0, am) >= jump(am, a1) {
            (t1, a1) = (tm, am);
        } else {
            (t0, a0) = (tm, am);
        }
    }
    Ok(None)
}

/// The values inside hysteresis windows that lie between neighbours of a knob sweep's
/// `points` (ascending), each with the index of its left neighbour ([`window_between`] on
/// every pair, side by side; each solve is `knob_sweep`'s at one value with `opts`, the mean
/// gap with `with_gap`). The same whatever the number of threads.
///
/// # Errors
/// [`crate::error::Error::Cancelled`]; [`crate::error::Error::Invalid`] for options out of
/// range. A probe that does not converge ends its search without an error.
pub fn window_probes(
    scene: &Scene,
    knob: Knob,
    points: &[KnobPoint],
    opts: &Options,
    with_gap: bool,
    cancel: Option<&AtomicBool>,
) -> Result<Vec<(usize, KnobPoint)>> {
    use rayon::prelude::*;
    let probe = |v: f64| -> Result<Option<Evaluation>> {
        let spec = KnobSpec {
            knob,
            from: v,
            to: v,
            points: 1,
        };
        Ok(knob_sweep(scene, &spec, opts, false, cancel)?
            .pop()
            .and_then(|p| p.result.ok()))
    };
    let found: Vec<Option<(usize, KnobPoint)>> = (0..points.len().saturating_sub(1))
        .into_par_iter()
        .map(|k| {
            let (Ok(lo), Ok(hi)) = (&points[k].result, &points[k + 1].result) else {
                return Ok(None);
            };
            let inside = window_between(knob, &probe, (points[k].value, lo), (points[k + 1].value, hi))?;
            Ok(inside.map(|(value, ev)| {
                let s = knob.apply(scene, value);
                let gap = if with_gap {
                    crate::theory::gap::mean_gap_of(&s, &ev, opts).map(Some)
                } else {
                    Ok(None)
                };
                (
                    k,
                    KnobPoint {
                        value,
                        scene: s,
                        result: Ok(ev),
                        gap,
                    },
                )
            }))
        })
        .collect::<Result<_>>()?;
    Ok(found.into_iter().flatten().collect())
}

/// `points` with `probes` ([`window_probes`] of them) in their places, and for each point
/// whether it is one of `points` (true) or a probe (false).
pub fn merge_probes(points: Vec<KnobPoint>, probes: Vec<(usize, KnobPoint)>) -> (Vec<KnobPoint>, Vec<bool>) {
    let mut merged = Vec::with_capacity(points.len() + probes.len());
    let mut given = Vec::with_capacity(merged.capacity());
    let mut probes = probes.into_iter().peekable();
    for (k, p) in points.into_iter().enumerate() {
        merged.push(p);
        given.push(true);
        while let Some((_, q)) = probes.next_if(|(j, _)| *j == k) {
            merged.push(q);
            given.push(false);
        }
    }
    (merged, given)
}
