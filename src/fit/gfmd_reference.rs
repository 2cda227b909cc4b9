//! A GFMD load sweep as a reference for gauging: the brute-force data the theory's
//! coefficients are fitted to, computed on the scene itself.
//!
//! For each of K realisations (seeds s, s+1, …, s+K−1) a warm-started load sweep
//! ([`crate::gfmd::sweep::run_loads`]) runs on the reduced grid of the scene
//! ([`crate::gfmd::reduction`]); with a resolution ladder (λ_s/Δa = h₁ < h₂ < …) every rung runs
//! the same realisation and each load's values are taken to Δa → 0 by
//! [`crate::gfmd::ladder::extrapolate`]. Per load p* and observable X the reference holds
//!
//! ```text
//! X̄ = (1/K) Σ_k X_k                          (X_k: seed k's value, or its Δa → 0 limit)
//! s_X² = s_K²/K + ē_X²                        (s_K the sample standard deviation over seeds,
//!                                              ē_X the mean extrapolation error over seeds)
//! ```
//!
//! with the standard error s_X as the weight of the fit ([`super::fit`]); a term that is not
//! measured (K = 1, or no ladder) is left out, and with neither the reference carries no errors
//! (relative residuals). Observables: a_r and ū/h_rms, and σ̄_c* with adhesion only: without
//! adhesion σ̄_c* = p*/a_r holds to the solver tolerance, so it would count a_r twice.
//!
//! The theory is fitted on [`GfmdReference::scene`], the scene GFMD runs: the reduced
//! self-affine spectrum (same H, λ_s, ḡ, p*, t·q_r; L and λ_r of the grid) with γ_s and ρ
//! rescaled to keep γ̃_glo and the Tabor parameter, so that a_r and ū/h_rms are compared
//! like for like (ū/h_rms depends on λ_r/λ_s, which the reduction does not keep).

use super::reference::{Observable, Observation, Reference};
use crate::error::{Error, Field, Result};
use crate::gfmd::ladder::{extrapolate, MeanSe};
use crate::gfmd::reduction::Reduction;
use crate::gfmd::sweep::{run_loads, GfmdSweepRow};
use crate::gfmd::{GfmdOptions, GfmdSetup, GridSpec, Progress};
use crate::input::scene::Scene;
use crate::theory::sweep::SweepSpec;
use serde::Serialize;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// What to run.
#[derive(Debug, Clone, PartialEq)]
pub struct GfmdReferenceSpec {
    /// The loads (log-spaced p*).
    pub loads: SweepSpec,
    /// Number of realisations K (seeds `setup.seed`, `setup.seed + 1`, …).
    pub seeds: usize,
    /// λ_s/Δa of each rung of a resolution ladder (None: the setup's grid only).
    pub ladder: Option<Vec<f64>>,
}

/// One load of the reference: mean over seeds and standard error (the reference CSV's
/// columns).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GfmdReferenceRow {
    /// p*.
    pub p: f64,
    /// a_r.
    pub a_r: f64,
    /// Its standard error (null when not measured, see the module docs).
    pub a_r_err: Option<f64>,
    /// σ̄_c*.
    pub mean_contact_stress: f64,
    /// Its standard error.
    pub mean_contact_stress_err: Option<f64>,
    /// ū/h_rms.
    pub mean_gap_rel: f64,
    /// Its standard error.
    pub mean_gap_rel_err: Option<f64>,
}

/// Where a GFMD reference run stands (for a progress line).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stage {
    /// Index of the realisation (0-based) and their number.
    pub seed_index: usize,
    /// K.
    pub seeds: usize,
    /// Index of the ladder rung (0 without a ladder) and their number.
    pub rung: usize,
    /// Number of rungs (1 without a ladder).
    pub rungs: usize,
    /// Index of the load and their number.
    pub load: usize,
    /// Number of loads.
    pub loads: usize,
    /// Grid side N of this rung.
    pub grid: usize,
}

/// A GFMD reference and how it was obtained.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GfmdReference {
    /// Grid side N of the setup's grid (the finest rung's with a ladder is larger).
    pub grid: usize,
    /// The seeds.
    pub seeds: Vec<u64>,
    /// λ_s/Δa of the ladder's rungs (null without a ladder).
    pub ladder: Option<Vec<f64>>,
    /// One row per load, increasing p*.
    pub rows: Vec<GfmdReferenceRow>,
    /// The full and reduced systems' invariants (null for a loaded map).
    pub reduction: Option<Reduction>,
    /// Total solver steps.
    pub iterations: usize,
    /// Wall time (s).
    pub elapsed_s: f64,
    /// The scene GFMD ran (the theory is fitted on it, see the module docs).
    #[serde(skip)]
    pub scene: Scene,
    /// The rows as a reference set.
    #[serde(skip)]
    pub reference: Reference,
}

/// Largest K.
pub const MAX_SEEDS: usize = 1000;

/// Runs the sweeps of `spec` on `setup` and builds the reference (see the module docs).
/// `progress` gets the stage with each solver report.
///
/// # Errors
/// [`Error::Invalid`] for K outside 1..=[`MAX_SEEDS`] or a ladder of fewer than two distinct
/// rungs; [`Error::Unsupported`] for several seeds or a ladder on a loaded map; those of the
/// solver (no convergence, cancelled).
pub fn gfmd_reference(
    setup: &GfmdSetup,
    spec: &GfmdReferenceSpec,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(&Stage, Progress),
    cancel: &AtomicBool,
) -> Result<GfmdReference> {
    let t0 = Instant::now();
    if !(1..=MAX_SEEDS).contains(&spec.seeds) {
        return Err(Error::invalid(
            Field::Seeds,
            spec.seeds as f64,
            format!("1 <= seeds <= {MAX_SEEDS}"),
        ));
    }
    let rungs: Vec<f64> = match &spec.ladder {
        Some(l) => {
            let mut l = l.clone();
            l.sort_by(f64::total_cmp);
            l.dedup();
            if l.len() < 2 {
                return Err(Error::invalid_text(
                    Field::Ladder,
                    format!("{} distinct rung(s)", l.len()),
                    "two or more distinct lambda_s/da",
                ));
            }
            l
        }
        None => vec![setup.grid.points_per_short_wavelength],
    };
    if setup.surface.is_some() && (spec.seeds > 1 || spec.ladder.is_some()) {
        return Err(Error::Unsupported(
            "a loaded map is one realisation at one resolution: no ensemble over seeds, no ladder".into(),
        ));
    }
    spec.loads.validate()?;
    let loads = spec.loads.pressures();
    let seeds: Vec<u64> = (0..spec.seeds as u64).map(|k| setup.seed.wrapping_add(k)).collect();
    // values[seed][observable][load] (limits with a ladder), errors likewise
    let mut values: Vec<[Vec<f64>; 3]> = Vec::new();
    let mut ext_err: Vec<[Vec<f64>; 3]> = Vec::new();
    let mut iterations = 0;
    let mut scene = None;
    let mut reduction = None;
    for (si, &seed) in seeds.iter().enumerate() {
        let mut per_rung: Vec<Vec<GfmdSweepRow>> = Vec::new();
        for (ri, &pts) in rungs.iter().enumerate() {
            let grid = GridSpec {
                points_per_short_wavelength: pts,
                ..setup.grid
            };
            let s = GfmdSetup {
                seed,
                grid: if spec.ladder.is_some() { grid } else { setup.grid },
                ..setup.clone()
            };
            let mut stage = Stage {
                seed_index: si,
                seeds: seeds.len(),
                rung: ri,
                rungs: rungs.len(),
                load: 0,
                loads: loads.len(),
                grid: setup.surface.as_ref().map_or(s.grid.n(), |m| m.nx),
            };
            let (prep, rows, it) = run_loads(
                &s,
                &spec.loads,
                opts,
                &mut |k, p| {
                    stage.load = k;
                    progress(&stage, p)
                },
                cancel,
            )?;
            iterations += it;
            if scene.is_none() {
                scene = Some(prep.scene);
                reduction = prep.reduction;
            }
            per_rung.push(rows);
        }
        let col = |rows: &[GfmdSweepRow], j: usize| -> Vec<f64> {
            rows.iter()
                .map(|r| match j {
                    0 => r.a_r,
                    1 => r.mean_contact_stress,
                    _ => r.mean_gap_rel,
                })
                .collect()
        };
        if spec.ladder.is_some() {
            // Δa ∝ 1/(λ_s/Δa) at fixed λ_s
            let h: Vec<f64> = rungs.iter().map(|p| 1.0 / p).collect();
            let mut v: [Vec<f64>; 3] = Default::default();
            let mut e: [Vec<f64>; 3] = Default::default();
            for j in 0..3 {
                for k in 0..loads.len() {
                    let x: Vec<f64> = per_rung.iter().map(|rows| col(rows, j)[k]).collect();
                    let ex = extrapolate(&h, &x)?;
                    v[j].push(ex.limit);
                    e[j].push(ex.error);
                }
            }
            values.push(v);
            ext_err.push(e);
        } else {
            let rows = &per_rung[0];
            values.push([col(rows, 0), col(rows, 1), col(rows, 2)]);
        }
    }
    let scene = scene.expect("at least one sweep ran");
    let mut rows = Vec::with_capacity(loads.len());
    for (k, &p) in loads.iter().enumerate() {
        let stat = |j: usize| -> (f64, Option<f64>) {
            let m = MeanSe::of(values.iter().map(|v| v[j][k]).collect());
            let ext =
                (!ext_err.is_empty()).then(|| ext_err.iter().map(|e| e[j][k]).sum::<f64>() / ext_err.len() as f64);
            let var = m.standard_error.map(|s| s * s).unwrap_or(0.0) + ext.map(|e| e * e).unwrap_or(0.0);
            let err = (m.standard_error.is_some() || ext.is_some())
                .then(|| var.sqrt())
                .filter(|s| s.is_finite() && *s > 0.0);
            (m.mean, err)
        };
        let (a_r, a_r_err) = stat(0);
        let (mean_contact_stress, mean_contact_stress_err) = stat(1);
        let (mean_gap_rel, mean_gap_rel_err) = stat(2);
        rows.push(GfmdReferenceRow {
            p,
            a_r,
            a_r_err,
            mean_contact_stress,
            mean_contact_stress_err,
            mean_gap_rel,
            mean_gap_rel_err,
        });
    }
    let reference = to_reference(&rows, scene.gamma > 0.0);
    Ok(GfmdReference {
        grid: setup.surface.as_ref().map_or(setup.grid.n(), |s| s.nx),
        seeds,
        ladder: spec.ladder.as_ref().map(|_| rungs.clone()),
        rows,
        reduction,
        iterations,
        elapsed_s: t0.elapsed().as_secs_f64(),
        scene,
        reference,
    })
}

/// The rows as a [`Reference`] named "gfmd": a_r and ū/h_rms, and σ̄_c* when `adhesive`
/// (module docs); a value that is not finite or out of its observable's range is left out.
pub fn to_reference(rows: &[GfmdReferenceRow], adhesive: bool) -> Reference {
    let mut points = Vec::new();
    for r in rows {
        let mut push = |observable, value: f64, error| {
            let ok = match observable {
                Observable::Area => value > 0.0 && value <= 1.0,
                _ => value.is_finite() && value > 0.0,
            };
            if ok {
                points.push(Observation {
                    p: r.p,
                    observable,
                    value,
                    error,
                    sigma: 0.0,
                });
            }
        };
        push(Observable::Area, r.a_r, r.a_r_err);
        if adhesive {
            push(
                Observable::MeanContactStress,
                r.mean_contact_stress,
                r.mean_contact_stress_err,
            );
        }
        push(Observable::MeanGapRel, r.mean_gap_rel, r.mean_gap_rel_err);
    }
    Reference {
        name: "gfmd".into(),
        points,
    }
}

/// The rows as a reference CSV with the observables of [`to_reference`]
/// ([`super::reference::parse_csv`] reads it back to the same reference; an error not measured
/// is an empty cell).
pub fn to_csv(rows: &[GfmdReferenceRow], adhesive: bool) -> String {
    let e = |x: Option<f64>| x.map_or(String::new(), |x| format!("{x:e}"));
    let mut out = String::from("p,a_r,a_r_err,");
    if adhesive {
        out.push_str("mean_contact_stress,mean_contact_stress_err,");
    }
    out.push_str("mean_gap_rel,mean_gap_rel_err\n");
    for r in rows {
        out.push_str(&format!("{:e},{:e},{},", r.p, r.a_r, e(r.a_r_err)));
        if adhesive {
            out.push_str(&format!(
                "{:e},{},",
                r.mean_contact_stress,
                e(r.mean_contact_stress_err)
            ));
        }
        out.push_str(&format!("{:e},{}\n", r.mean_gap_rel, e(r.mean_gap_rel_err)));
    }
    out
}
