//! Evaluating one scene at many loads: the engine's work behind sweeps and the mean gap.
//!
//! [`node_results`] evaluates [`crate::theory::engine::evaluate`] at every p* of an ascending
//! list with lean options (no Pr table, no resolution record, the ODE at the energy route's
//! tolerance [`ENERGY_RTOL`]). Every load is independent — the adhesive solver finds every
//! branch at a load on its own (`theory::adhesion`), so no continuation from a neighbouring load
//! is needed — and the loads run in parallel: results do not depend on the thread count.
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
    // every branch at every load (a warm start would only track the previous load's
    // branches and miss a pair born between two loads)
    o.adhesion.explore_branches = true;
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
                solver: format!("{solver} at p* = {p:.6e}"),
                reason,
            })),
            Err(e) => Err(e),
        }
    };
    ps.par_iter()
        .map(|&p| {
            check_cancel(cancel)?;
            keep(evaluate_node(scene, p, &opts, None, cancel), p)
        })
        .collect()
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
