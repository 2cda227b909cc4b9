//! Evaluating one scene at many loads: the engine's work behind sweeps and the mean gap.
//!
//! [`node_results`] evaluates [`crate::theory::engine::evaluate`] at every p* of an ascending
//! list with lean options (no Pr table, no resolution record, the ODE at the energy route's
//! tolerance [`ENERGY_RTOL`]). Adhesionless loads are independent and run
//! in parallel; adhesive loads run in order of increasing p*, each warm-started from the
//! previous converged load (continuation along the loading branch), in chunks that start cold.
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
    o.adhesion.explore_branches = false;
    o.adhesion.thorough = false;
    o
}

/// Evaluates one load, warm-started from the neighbouring load's result (continuation), and
/// abandoning an adhesive fixed point when `cancel` is set.
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

/// One load's outcome: the evaluation, or why its solver did not converge.
type NodeResult = std::result::Result<Evaluation, Error>;

/// Evaluates the scene at every p* of `ps` (ascending), keeping a load whose solver did not
/// converge as an `Err` and going on (cancellation and invalid input end the whole call): in
/// parallel without adhesion; with it in order of increasing load with continuation, in
/// chunks of a fixed length (independent of the number of threads).
pub fn node_results(scene: &Scene, ps: &[f64], opts: &Options, cancel: Option<&AtomicBool>) -> Result<Vec<NodeResult>> {
    let opts = lean(opts);
    let keep = |r: Result<Evaluation>, p: f64| -> Result<NodeResult> {
        match r {
            Ok(ev) => Ok(Ok(ev)),
            Err(Error::NotConverged { solver, reason }) => Ok(Err(Error::NotConverged {
                solver: format!("{solver} at p* = {p:.6e}"),
                reason,
            })),
            Err(e) => Err(e),
        }
    };
    if scene.gamma == 0.0 {
        return ps
            .par_iter()
            .map(|&p| {
                check_cancel(cancel)?;
                keep(evaluate_node(scene, p, &opts, None, cancel), p)
            })
            .collect();
    }
    // continuation runs in order of increasing load; the range is cut into chunks by a fixed
    // rule (CHUNK loads each, evened out), never by the number of threads, so the result is the
    // same on any machine; each chunk starts cold, i.e. from the adhesionless solution: the
    // loading branch, like the continuation itself
    let size = chunk_size(ps.len());
    let parts: Vec<Result<Vec<NodeResult>>> = ps
        .par_chunks(size.max(1))
        .map(|part| {
            let mut out: Vec<NodeResult> = Vec::with_capacity(part.len());
            for &p in part {
                check_cancel(cancel)?;
                let warm = out.iter().rev().find_map(|r| r.as_ref().ok());
                // a warm start from the wrong side of a jump can stall: retry cold (from the
                // adhesionless start, the loading branch) before giving up on this load
                let r = match evaluate_node(scene, p, &opts, warm, cancel) {
                    Err(Error::NotConverged { .. }) if warm.is_some() => evaluate_node(scene, p, &opts, None, cancel),
                    r => r,
                };
                out.push(keep(r, p)?);
            }
            Ok(out)
        })
        .collect();
    let mut out = Vec::with_capacity(ps.len());
    for part in parts {
        out.extend(part?);
    }
    Ok(out)
}

/// Evaluates the scene at every p* of `ps` (see [`node_results`]); the first load whose
/// solver did not converge makes the whole call an error naming that p*.
pub fn evaluations(scene: &Scene, ps: &[f64], opts: &Options, cancel: Option<&AtomicBool>) -> Result<Vec<Evaluation>> {
    node_results(scene, ps, opts, cancel)?.into_iter().collect()
}

/// Loads per continuation chunk of an adhesive sweep (at most; the chunks are evened out).
const CHUNK: usize = 16;

/// The chunk length of an adhesive sweep of `n` loads: ⌈n/CHUNK⌉ chunks of equal length
/// (the last one shorter). A function of `n` only: results do not depend on the thread count.
fn chunk_size(n: usize) -> usize {
    let chunks = n.div_ceil(CHUNK).max(1);
    n.div_ceil(chunks).max(1)
}

/// U* = U/(E*ḡh_rms) at every p* of `ps` (see [`evaluations`]).
pub fn energies(scene: &Scene, ps: &[f64], opts: &Options, cancel: Option<&AtomicBool>) -> Result<Vec<f64>> {
    let unit = crate::theory::energy::energy_unit(scene);
    Ok(evaluations(scene, ps, opts, cancel)?
        .iter()
        .map(|e| e.elastic_energy / unit)
        .collect())
}
