//! Evaluating one scene at many loads: the engine's work behind sweeps and the mean gap.
//!
//! [`node_results`] evaluates [`crate::theory::engine::evaluate`] at every p* of an ascending
//! list with lean options (no Pr table, no resolution record, the ODE at the energy route's
//! tolerance [`ENERGY_RTOL`]). With adhesion every [`ANCHOR_STRIDE`]-th load (an anchor)
//! scans for every branch (`theory::adhesion`); the loads between two anchors track their
//! neighbour's roots (a warm start from C interpolated between the neighbour and the next
//! anchor, falling back to the scan when a root is not where it was or the roots no longer
//! alternate in sign): upwards from the lower anchor, or downwards from the upper one where
//! it has more branches (an edge of a hysteresis window lies between them: the pair of
//! roots that ends at the fold is tracked up to it, and the first load past it scans).
//! Anchors run in parallel, then the stretches between them: which load starts from which is
//! fixed by the list, so results do not depend on the thread count. A window that opens and
//! closes between two anchors (narrower than four load steps) is not seen.
//! [`energies`] gives U* = U/(E*ḡh_rms) [S-11] at those loads, the input of the energy route to
//! the mean gap [S-12] ([`crate::theory::gap`]) and of [`crate::theory::sweep`].
//!
//! Both `gap` and `sweep` depend on this module; it depends on neither's tables, so the three
//! form no cycle ([`ENERGY_RTOL`] lives in [`crate::theory::persson`], below all three).

use crate::error::{Error, Result};
use crate::input::scene::Scene;
use crate::theory::engine::{self, Evaluation, Options};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

pub use crate::theory::persson::ENERGY_RTOL;

/// Options that make per-load evaluations cheap (no Pr table, no resolution record) and
/// accurate enough for the energy route ([`ENERGY_RTOL`]).
fn lean(opts: &Options) -> Options {
    let mut o = *opts;
    o.sigma_points = 2;
    o.accuracy.resolution_points = 2;
    o.accuracy.rtol = o.accuracy.rtol.min(ENERGY_RTOL);
    o.adhesion_error_estimate = false;
    // every branch (the anchors, and every load of a window); `node_results` turns this off
    // where it tracks a root
    o.adhesion.explore_branches = true;
    o
}

/// Evaluates one load, warm-started from the neighbouring load's result (continuation), and
/// abandoning an adhesive solve when `cancel` is set.
pub fn evaluate_node(
    scene: &Scene,
    p: f64,
    opts: &Options,
    previous: Option<&Evaluation>,
    cancel: Option<&AtomicBool>,
) -> Result<Evaluation> {
    let mut s = scene.clone();
    s.pressure = p;
    engine::evaluate_warm(&s, opts, previous, cancel)
}

fn check_cancel(cancel: Option<&AtomicBool>) -> Result<()> {
    if cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
        Err(Error::Cancelled)
    } else {
        Ok(())
    }
}

/// Every this many loads (by index in the ascending list) the adhesive solver scans for every
/// branch; between two such anchors that have the same number of branches, each load tracks
/// the previous one's roots (2–4 marches each instead of 10–20 marches' worth for a scan).
/// The anchors do not depend on the thread count, so neither do the results.
pub const ANCHOR_STRIDE: usize = 4;

/// One load's outcome: the evaluation, or why its solver did not converge.
pub type NodeResult = std::result::Result<Evaluation, Error>;

/// Evaluates the scene at every p* of `ps` (ascending), keeping a load whose solver did not
/// converge as an `Err` and going on (cancellation and invalid input end the whole call), in
/// parallel (the order of the results is that of `ps`, whatever the number of threads).
pub fn node_results(scene: &Scene, ps: &[f64], opts: &Options, cancel: Option<&AtomicBool>) -> Result<Vec<NodeResult>> {
    let opts = lean(opts);
    let keep = |r: Result<Evaluation>, p: f64| -> Result<NodeResult> {
        match r {
            Ok(ev) => Ok(Ok(ev)),
            Err(Error::NotConverged { solver, reason }) => Ok(Err(Error::NotConverged {
                solver,
                reason: format!("at p* = {p:.6e}: {reason}"),
            })),
            Err(e) => Err(e),
        }
    };
    // one load scanned for every branch
    let scanned = |p: f64| -> Result<NodeResult> {
        check_cancel(cancel)?;
        keep(evaluate_node(scene, p, &opts, None, cancel), p)
    };
    if scene.gamma <= 0.0 || ps.len() <= ANCHOR_STRIDE {
        return ps.par_iter().map(|&p| scanned(p)).collect();
    }
    // anchors: every ANCHOR_STRIDE-th load and the last, each with a full root scan
    let n = ps.len();
    let anchors: Vec<usize> = (0..n)
        .step_by(ANCHOR_STRIDE)
        .chain((!(n - 1).is_multiple_of(ANCHOR_STRIDE)).then_some(n - 1))
        .collect();
    let anchor_results: Vec<NodeResult> = anchors.par_iter().map(|&i| scanned(ps[i])).collect::<Result<_>>()?;
    // the loads between two anchors: tracked from one anchor to the other, from the lower
    // one unless the upper has more branches (an edge of a window between them: the branches
    // that end at its fold are tracked up to it, where their brackets fail and the load is
    // scanned); every load scanned where an anchor failed
    let count = |r: &NodeResult| r.as_ref().ok().map(|e| e.branches.len().max(1));
    let mut tracked = opts;
    tracked.adhesion.explore_branches = false;
    let segments: Vec<Vec<NodeResult>> = anchors
        .par_windows(2)
        .zip(anchor_results.par_windows(2))
        .map(|(ij, rs)| -> Result<Vec<NodeResult>> {
            let (lower, upper) = (count(&rs[0]), count(&rs[1]));
            let track = lower.is_some() && upper.is_some();
            let down = upper > lower;
            let (from, to) = if down { (&rs[1], &rs[0]) } else { (&rs[0], &rs[1]) };
            let mut idx: Vec<usize> = (ij[0] + 1..ij[1]).collect();
            if down {
                idx.reverse();
            }
            let mut out: Vec<NodeResult> = Vec::with_capacity(idx.len());
            for &i in &idx {
                let p = ps[i];
                let r = if track {
                    check_cancel(cancel)?;
                    // the last converged load of the stretch (the anchor it starts from
                    // first) and the anchor it runs to, for the solver to interpolate the
                    // roots between where both have as many (half the error of extrapolating
                    // from the last two, and the first load after the anchor gets a trend
                    // too)
                    let last = out.last().unwrap_or(from);
                    let path: Vec<&Evaluation> = match (to, last) {
                        (Ok(next), Ok(l)) => vec![next, l],
                        (_, Ok(l)) => vec![l],
                        (_, Err(_)) => Vec::new(),
                    };
                    let mut s = scene.clone();
                    s.pressure = p;
                    keep(engine::evaluate_continued(&s, &tracked, &path, cancel), p)?
                } else {
                    scanned(p)?
                };
                out.push(r);
            }
            if down {
                out.reverse();
            }
            Ok(out)
        })
        .collect::<Result<_>>()?;
    let mut results = Vec::with_capacity(n);
    let mut anchor_results = anchor_results.into_iter();
    for seg in segments {
        results.extend(anchor_results.next());
        results.extend(seg);
    }
    results.extend(anchor_results);
    Ok(results)
}

/// Evaluates the scene at every p* of `ps` (see [`node_results`]); the first load whose
/// solver did not converge makes the whole call an error naming that p*.
pub fn evaluations(scene: &Scene, ps: &[f64], opts: &Options, cancel: Option<&AtomicBool>) -> Result<Vec<Evaluation>> {
    node_results(scene, ps, opts, cancel)?.into_iter().collect()
}

/// U* = U/(E*ḡh_rms) at every p* of `ps` (see [`evaluations`]).
pub fn energies(scene: &Scene, ps: &[f64], opts: &Options, cancel: Option<&AtomicBool>) -> Result<Vec<f64>> {
    let unit = crate::theory::energy::energy_unit(scene);
    Ok(evaluations(scene, ps, opts, cancel)?
        .iter()
        .map(|e| e.elastic_energy / unit)
        .collect())
}
