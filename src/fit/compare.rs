//! How far a model's predictions lie from a reference: per observable, the mean and largest
//! relative error |y_model/y_ref − 1| (a_r, σ̄_c*, ū/h_rms), and for Pr(σ*) histograms the L1
//! distance ∫|Pr_model − Pr_ref|dσ* (midpoint bin widths), averaged over the histograms.

use super::predict;
use super::reference::{Observable, Reference};
use crate::error::Result;
use crate::input::model::Model;
use crate::input::scene::Scene;
use serde::Serialize;

/// One observable's score.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Score {
    /// `a_r`, `mean_contact_stress`, `mean_gap_rel` or `pr`.
    pub observable: &'static str,
    /// Number of reference values (for `pr`: histograms).
    pub points: usize,
    /// Mean |y/y_ref − 1| (for `pr`: mean L1 distance).
    pub mean: f64,
    /// Largest |y/y_ref − 1| (for `pr`: largest L1 distance).
    pub max: f64,
}

/// The scores of `model` on `scene` against `reference`, in [`Observable`] order.
///
/// # Errors
/// Those of [`predict::predict`] (a scene the model does not define, no convergence).
pub fn score(scene: &Scene, model: &Model, reference: &Reference) -> Result<Vec<Score>> {
    let y = predict::predict(scene, model, reference)?;
    let pts = &reference.points;
    let mut out = Vec::new();
    for o in reference.observables() {
        let idx: Vec<usize> = (0..pts.len()).filter(|&i| pts[i].observable == o).collect();
        if o == Observable::Pr {
            let mut loads: Vec<f64> = idx.iter().map(|&i| pts[i].p).collect();
            loads.sort_by(f64::total_cmp);
            loads.dedup();
            let l1: Vec<f64> = loads
                .iter()
                .map(|&p| {
                    let mut bins: Vec<(f64, f64)> = idx
                        .iter()
                        .filter(|&&i| pts[i].p == p)
                        .map(|&i| (pts[i].sigma, (y[i] - pts[i].value).abs()))
                        .collect();
                    bins.sort_by(|a, b| a.0.total_cmp(&b.0));
                    let n = bins.len();
                    (0..n)
                        .map(|k| {
                            let lo = if k == 0 {
                                bins[0].0
                            } else {
                                0.5 * (bins[k - 1].0 + bins[k].0)
                            };
                            let hi = if k + 1 == n {
                                bins[n - 1].0
                            } else {
                                0.5 * (bins[k].0 + bins[k + 1].0)
                            };
                            bins[k].1 * (hi - lo)
                        })
                        .sum()
                })
                .collect();
            out.push(Score {
                observable: o.key(),
                points: l1.len(),
                mean: l1.iter().sum::<f64>() / l1.len().max(1) as f64,
                max: l1.iter().copied().fold(0.0, f64::max),
            });
        } else {
            let rel: Vec<f64> = idx.iter().map(|&i| (y[i] / pts[i].value - 1.0).abs()).collect();
            out.push(Score {
                observable: o.key(),
                points: rel.len(),
                mean: rel.iter().sum::<f64>() / rel.len().max(1) as f64,
                max: rel.iter().copied().fold(0.0, f64::max),
            });
        }
    }
    Ok(out)
}
