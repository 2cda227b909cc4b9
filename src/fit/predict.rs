//! The theory's values at a reference's points, for one model.
//!
//! Adhesionless scenes: the variance ODE at each load ([`crate::theory::persson::solve`], at
//! [`FIT_RTOL`] so finite-difference derivatives in the coefficients are clean); adhesive
//! scenes: the engine ([`crate::theory::engine::evaluate`]). When the reference holds mean
//! gaps, one load sweep over its range ([`crate::theory::sweep`]) gives every observable,
//! cubic in ln p* between its rows.

use super::reference::{Observable, Reference};
use crate::error::{Error, Result};
use crate::input::model::Model;
use crate::input::scene::Scene;
use crate::theory::engine::{self, Options};
use crate::theory::persson::{self, Accuracy};
use crate::theory::sweep::{self, interpolate_in_ln_p, SweepSpec};
use rayon::prelude::*;

/// ODE tolerance of the predictions: 1e-10 keeps the noise in a_r near 1e-10 relative, so a
/// central difference with a step of 1e-4 in a coefficient is accurate to ~1e-6.
pub const FIT_RTOL: f64 = 1e-10;

/// Rows of the sweep used when a reference holds mean gaps: at least this many over its range.
pub const GAP_SWEEP_POINTS: usize = 48;

/// One load's prediction.
#[derive(Debug, Clone, PartialEq)]
struct AtLoad {
    a_r: f64,
    mean_contact_stress: f64,
    mean_gap_rel: f64,
    /// Pr(σ*) as (σ*, density), ascending in σ*.
    pr: Vec<(f64, f64)>,
}

fn interpolate_pr(pr: &[(f64, f64)], s: f64) -> f64 {
    if pr.is_empty() || s < pr[0].0 || s > pr[pr.len() - 1].0 {
        return 0.0;
    }
    let i = pr.partition_point(|&(x, _)| x < s);
    if i == 0 {
        return pr[0].1;
    }
    let (x0, y0) = pr[i - 1];
    let (x1, y1) = pr[i];
    if x1 <= x0 {
        return y1;
    }
    y0 + (y1 - y0) * (s - x0) / (x1 - x0)
}

/// The theory's value at each of `reference.points` (same order) for `scene` with `model`.
///
/// # Errors
/// Those of the solvers (invalid scene, no convergence).
pub fn predict(scene: &Scene, model: &Model, reference: &Reference) -> Result<Vec<f64>> {
    let mut s = scene.clone();
    s.model = *model;
    s.resolve_model();
    let loads = reference.loads();
    let obs = reference.observables();
    let max_sigma = reference
        .points
        .iter()
        .filter(|o| o.observable == Observable::Pr)
        .map(|o| o.sigma)
        .fold(0.0f64, f64::max);
    let want_pr = obs.contains(&Observable::Pr);
    let at: Vec<AtLoad> = if obs.contains(&Observable::MeanGapRel) {
        let spec = SweepSpec {
            from: loads[0],
            to: loads[loads.len() - 1],
            points: GAP_SWEEP_POINTS.max(loads.len()),
        };
        let sw = sweep::sweep(&s, &spec, &Options::default(), None)?;
        let ps: Vec<f64> = sw.rows.iter().map(|r| r.p).collect();
        let col = |f: fn(&sweep::SweepRow) -> f64| -> Vec<f64> { sw.rows.iter().map(f).collect() };
        let (a, m, g) = (col(|r| r.a_r), col(|r| r.mean_contact_stress), col(|r| r.mean_gap_rel));
        let pick = |v: &[f64], p: f64| -> f64 {
            if ps.len() == 1 {
                return v[0];
            }
            interpolate_in_ln_p(&ps, v, p).unwrap_or(f64::NAN)
        };
        let mut out = Vec::with_capacity(loads.len());
        for &p in &loads {
            let pr = if want_pr { pr_at(&s, p, max_sigma)? } else { Vec::new() };
            out.push(AtLoad {
                a_r: pick(&a, p),
                mean_contact_stress: pick(&m, p),
                mean_gap_rel: pick(&g, p),
                pr,
            });
        }
        out
    } else {
        loads
            .par_iter()
            .map(|&p| one_load(&s, p, want_pr, max_sigma))
            .collect::<Result<Vec<_>>>()?
    };
    reference
        .points
        .iter()
        .map(|o| {
            let i = loads.partition_point(|&x| x < o.p);
            let r = &at[i];
            let v = match o.observable {
                Observable::Area => r.a_r,
                Observable::MeanContactStress => r.mean_contact_stress,
                Observable::MeanGapRel => r.mean_gap_rel,
                Observable::Pr => interpolate_pr(&r.pr, o.sigma),
            };
            if v.is_finite() {
                Ok(v)
            } else {
                Err(Error::NotConverged {
                    solver: crate::error::Solver::Theory,
                    reason: format!("no finite {} at p* = {:e}", o.observable.key(), o.p),
                })
            }
        })
        .collect()
}

fn pr_at(s: &Scene, p: f64, max_sigma: f64) -> Result<Vec<(f64, f64)>> {
    let mut s = s.clone();
    s.pressure = p;
    let ev = engine::evaluate(&s, &pr_options(max_sigma))?;
    Ok(ev.stats.pr.points())
}

fn pr_options(max_sigma: f64) -> Options {
    Options {
        adhesion_error_estimate: false,
        sigma_points: 2001,
        sigma_max: Some(max_sigma.clamp(1e-3, 1e3)),
        ..Options::default()
    }
}

fn one_load(s: &Scene, p: f64, want_pr: bool, max_sigma: f64) -> Result<AtLoad> {
    let mut s = s.clone();
    s.pressure = p;
    if !s.is_adhesive() {
        let acc = Accuracy {
            rtol: FIT_RTOL,
            ..Accuracy::default()
        };
        let sol = persson::solve(&s, &acc)?;
        let pr = if want_pr {
            let (x, y) = sol.sample(max_sigma.max(1e-3), 2001);
            x.into_iter().zip(y).collect()
        } else {
            Vec::new()
        };
        return Ok(AtLoad {
            a_r: sol.a_r,
            mean_contact_stress: sol.mean_contact_stress,
            mean_gap_rel: f64::NAN,
            pr,
        });
    }
    let mut o = pr_options(max_sigma);
    if !want_pr {
        o.sigma_points = 2;
        o.sigma_max = None;
    }
    let ev = engine::evaluate(&s, &o)?;
    Ok(AtLoad {
        a_r: ev.stats.a_r,
        mean_contact_stress: ev.stats.mean_contact_stress,
        mean_gap_rel: f64::NAN,
        pr: ev.stats.pr.points(),
    })
}
