//! Load sweeps: a_r(p*), ū(p*)/h_rms, σ̄_c*(p*) and U(p*) on a log-spaced p* range.
//!
//! One sweep evaluates the scene ([`crate::engine::evaluate`]) on a single uniform grid in
//! ln p*: the requested points (from `from` to `to`, log-spaced), refined by an integer factor
//! when their spacing exceeds [`SWEEP_STEP_LN`], and extended with the same step up
//! to full contact. The mean gap at every requested point then comes from one cumulative pass
//! over that U table ([`crate::gap::GapTable`]); nothing is evaluated twice. A 64-point chart
//! sweep of system 1 from p* = 1e-3 to 1 costs 64 + 13 engine evaluations.
//!
//! Adhesionless loads are independent and run in parallel (rayon). Adhesive loads are run in
//! order of increasing p* (the loading branch, continuation from the neighbouring load): the
//! warm start is [`evaluate_node`]: each load starts the fixed point from the previous load's
//! a_r(q), which cuts the iterations and keeps the sweep on the loading branch (an adhesive
//! jump shows as a non-monotone stretch, flagged by [`Sweep::monotone`]).
//!
//! Cancellation: the caller may pass an `AtomicBool`; when it is set the sweep stops between
//! evaluations and returns [`Error::Cancelled`].

use crate::engine::{self, Evaluation, Options};
use crate::error::{Error, Result};
use crate::gap::{self, GapTable};
use crate::scene::{Scene, PRESSURE_RANGE};
use rayon::prelude::*;
use serde::Serialize;
use std::sync::atomic::{AtomicBool, Ordering};

/// Largest grid step in ln p* of a sweep's U table: coarser requested spacings are refined by
/// an integer factor. 0.15 keeps the estimated gap error below ~1e-3 relative where
/// ū > 1e-3 h_rms (each row reports its own estimate), so a 64-point chart over three decades
/// (spacing 0.11) needs no extra loads below `to`.
pub const SWEEP_STEP_LN: f64 = 0.15;

/// The load range of a sweep (reduced pressures, log-spaced).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepSpec {
    /// First p*.
    pub from: f64,
    /// Last p* (≥ from; equal only with one point).
    pub to: f64,
    /// Number of points (≥ 1).
    pub points: usize,
}

impl SweepSpec {
    /// Checks the range against the engine's pressure range.
    pub fn validate(&self) -> Result<()> {
        let allowed = format!("{:e} <= p* <= {:e}", PRESSURE_RANGE.0, PRESSURE_RANGE.1);
        for (name, v) in [("--from", self.from), ("--to", self.to)] {
            if !(v >= PRESSURE_RANGE.0 && v <= PRESSURE_RANGE.1) {
                return Err(Error::field(name, v, allowed.clone()));
            }
        }
        if !(1..=100_000).contains(&self.points) {
            return Err(Error::field("--points", self.points, "1 <= points <= 100000"));
        }
        if self.points > 1 && self.to <= self.from {
            return Err(Error::field(
                "--to",
                self.to,
                format!("a p* > --from = {} (or --points 1)", self.from),
            ));
        }
        Ok(())
    }

    /// The requested loads.
    pub fn pressures(&self) -> Vec<f64> {
        if self.points == 1 {
            return vec![self.from];
        }
        let (a, b) = (self.from.ln(), self.to.ln());
        (0..self.points)
            .map(|i| (a + (b - a) * i as f64 / (self.points - 1) as f64).exp())
            .collect()
    }
}

/// One load of a sweep.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SweepRow {
    /// p*.
    pub p: f64,
    /// a_r(q_s).
    pub a_r: f64,
    /// ū/h_rms.
    pub mean_gap_rel: f64,
    /// ū (m).
    pub mean_gap: f64,
    /// σ̄_c* (reduced by E*ḡ).
    pub mean_contact_stress: f64,
    /// U (J/m²) [S-11].
    pub elastic_energy: f64,
    /// Whether the engine converged at this load.
    pub converged: bool,
    /// U* = U/(E*ḡh_rms).
    pub elastic_energy_reduced: f64,
    /// Estimated absolute quadrature error of ū/h_rms.
    pub mean_gap_error: f64,
}

/// The result of a sweep.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sweep {
    /// One row per requested load, in increasing p*.
    pub rows: Vec<SweepRow>,
    /// Number of engine evaluations spent (requested loads + refinement + extension).
    pub evaluations: usize,
    /// p* at which the contact is full (the top of the gap grid).
    pub full_contact_pressure: f64,
    /// Whether every monotonicity the physics implies held (a_r increasing, ū decreasing);
    /// false flags a branch change (e.g. an adhesive jump) inside the range.
    pub monotone: bool,
}

/// Options that make per-load evaluations cheap (no Pr table, no resolution record) and
/// accurate enough for the energy route ([`gap::ENERGY_RTOL`]).
fn lean(opts: &Options) -> Options {
    let mut o = *opts;
    o.sigma_points = 2;
    o.accuracy.resolution_points = 2;
    o.accuracy.rtol = o.accuracy.rtol.min(gap::ENERGY_RTOL);
    o.adhesion_error_estimate = false;
    o.adhesion.explore_branches = false;
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

/// Evaluates the scene at every p* of `ps` (ascending): in parallel without adhesion; with it
/// in order of increasing load with continuation, one chunk of the range per thread.
pub fn evaluations(scene: &Scene, ps: &[f64], opts: &Options, cancel: Option<&AtomicBool>) -> Result<Vec<Evaluation>> {
    let opts = lean(opts);
    if scene.gamma == 0.0 {
        ps.par_iter()
            .map(|&p| {
                check_cancel(cancel)?;
                evaluate_node(scene, p, &opts, None, cancel)
            })
            .collect()
    } else {
        // continuation runs in order of increasing load; the range is cut into one chunk per
        // worker thread (each ≥ MIN_CHUNK loads), each chunk starting cold, i.e. from the
        // adhesionless solution: the loading branch, like the continuation itself
        let threads = rayon::current_num_threads().clamp(1, 8);
        let chunks = (ps.len() / MIN_CHUNK).clamp(1, threads);
        let size = ps.len().div_ceil(chunks);
        let parts: Vec<Result<Vec<Evaluation>>> = ps
            .par_chunks(size.max(1))
            .map(|part| {
                let mut out: Vec<Evaluation> = Vec::with_capacity(part.len());
                for &p in part {
                    check_cancel(cancel)?;
                    // a warm start from the wrong side of a jump can stall: retry cold (from
                    // the adhesionless start, the loading branch) before giving up
                    let ev = match evaluate_node(scene, p, &opts, out.last(), cancel) {
                        Err(Error::NotConverged { .. }) if !out.is_empty() => {
                            evaluate_node(scene, p, &opts, None, cancel)
                        }
                        r => r,
                    }
                    .map_err(|e| match e {
                        Error::NotConverged { solver, reason } => Error::NotConverged {
                            solver: format!("{solver} at p* = {p:.6e}"),
                            reason,
                        },
                        e => e,
                    })?;
                    out.push(ev);
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
}

/// Fewest loads per continuation chunk of an adhesive sweep.
const MIN_CHUNK: usize = 16;

/// U* = U/(E*ḡh_rms) at every p* of `ps` (see [`evaluations`]).
pub fn energies(scene: &Scene, ps: &[f64], opts: &Options, cancel: Option<&AtomicBool>) -> Result<Vec<f64>> {
    let unit = crate::energy::energy_unit(scene);
    Ok(evaluations(scene, ps, opts, cancel)?
        .iter()
        .map(|e| e.elastic_energy / unit)
        .collect())
}

/// Runs a sweep (see the module docs).
pub fn sweep(scene: &Scene, spec: &SweepSpec, opts: &Options, cancel: Option<&AtomicBool>) -> Result<Sweep> {
    spec.validate()?;
    let mut s0 = scene.clone();
    s0.pressure = spec.from;
    s0.validate()?;
    // grid: requested points refined by an integer factor m, extended to full contact
    let x0 = spec.from.ln();
    let (step, m) = if spec.points > 1 {
        let hs = (spec.to / spec.from).ln() / (spec.points - 1) as f64;
        let m = (hs / SWEEP_STEP_LN).ceil().max(1.0) as usize;
        (hs / m as f64, m)
    } else {
        (gap::GAP_STEP_LN, 1)
    };
    let p_full = gap::full_contact_pressure(scene);
    let last_req = (spec.points - 1) * m;
    let x_top = p_full.ln().max(spec.to.ln());
    let mut n = last_req + 1;
    while x0 + (n - 1) as f64 * step < x_top - 1e-12 || n < 9 {
        n += 1;
    }
    let requested = spec.pressures();
    let ps: Vec<f64> = (0..n)
        .map(|i| {
            if i % m == 0 && i / m < spec.points {
                // requested points exactly as the spec computes them
                requested[i / m]
            } else {
                (x0 + i as f64 * step).exp()
            }
        })
        .map(|p: f64| p.min(PRESSURE_RANGE.1))
        .collect();
    let evs = evaluations(scene, &ps, opts, cancel)?;
    let unit = crate::energy::energy_unit(scene);
    let energy: Vec<f64> = evs.iter().map(|e| e.elastic_energy / unit).collect();
    let table = GapTable::from_energy(x0, step, energy)?;
    let h_rms = scene.spectrum.rms_height();
    let rows: Vec<SweepRow> = (0..spec.points)
        .map(|k| {
            let i = k * m;
            let e = &evs[i];
            SweepRow {
                p: ps[i],
                a_r: e.a_r,
                mean_gap_rel: table.gap[i],
                mean_gap: table.gap[i] * h_rms,
                mean_contact_stress: e.mean_contact_stress,
                elastic_energy: e.elastic_energy,
                converged: e.converged,
                elastic_energy_reduced: table.energy[i],
                mean_gap_error: table.error[i],
            }
        })
        .collect();
    let monotone = rows
        .windows(2)
        .all(|w| w[1].a_r >= w[0].a_r && w[1].mean_gap_rel <= w[0].mean_gap_rel);
    Ok(Sweep {
        rows,
        evaluations: n,
        full_contact_pressure: p_full,
        monotone,
    })
}
