//! Measurements of a relaxed contact (reduced units σ* = σ/(E*ḡ), ḡ the map's discrete rms gradient)
//!
//! - contact: a node is in contact when it sits on the hard wall (g = 0 after projection, or
//!   g ≤ `contact_gap` if that is set > 0). With adhesion the contact stress can be tensile,
//!   down to −γ/ρ; nodes off the wall feel the attraction but are not counted;
//! - a_r: fraction of nodes in contact; σ̄_c*, ⟨δσ_c²⟩*: mean and variance of σ* over contact
//!   nodes (without adhesion σ̄_c = p₀/a_r to within the residual);
//! - Pr(σ*): histogram of σ* over contact nodes, counts divided by all nodes and by the bin
//!   width, so that ∫Pr dσ* = a_r exactly;
//! - ū = ⟨g⟩ over all nodes (m), and ū/h_rms.
//!
//! One implementation serves the whole map and the slabs of a distributed run
//! ([`measure_slab`]; [`measure()`] is its one-rank case).

use super::distributed::comm::{all_max, all_min, all_sum_counts, chain_sum, Comm, Solo};
use super::{GfmdOptions, Problem, Solution};
use crate::contact::{ContactStats, PrCurve};
use serde::Serialize;

/// Measured quantities of a relaxed contact (reduced stresses by E*ḡ of the map).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Measurements {
    /// The fraction of nodes in contact, σ̄_c* and ⟨δσ_c²⟩* over contact nodes, and the Pr(σ*)
    /// histogram (bin centres, ∫ = a_r).
    #[serde(flatten)]
    pub stats: ContactStats,
    /// ū = ⟨g⟩ (m).
    pub mean_gap: f64,
    /// ū/h_rms.
    pub mean_gap_rel: f64,
    /// Number of contact nodes.
    pub contact_nodes: usize,
    /// The stress unit E*ḡ (Pa).
    pub stress_unit: f64,
}

/// Measures a relaxed contact (see the module docs for the definitions): [`measure_slab`] on
/// one rank holding the whole map.
pub fn measure(problem: &Problem<'_>, sol: &Solution, opts: &GfmdOptions) -> Measurements {
    let s = problem.surface;
    measure_slab(
        &Solo,
        sol,
        opts,
        sol.gap.len(),
        problem.modulus,
        s.rms_gradient(),
        s.rms_height(),
    )
}

/// Measures a relaxed contact from this rank's rows of `sol` (`nodes` in the whole map;
/// `modulus` E*; ḡ and h_rms of the whole map); every rank gets the result. The sums run in
/// node order across the ranks ([`chain_sum`]), the extremes and the histogram counts are exact
/// in any order, so the result does not depend on the number of ranks, bit for bit;
/// [`measure()`] is this on one rank.
pub fn measure_slab(
    comm: &dyn Comm,
    sol: &Solution,
    opts: &GfmdOptions,
    nodes: usize,
    modulus: f64,
    rms_gradient: f64,
    rms_height: f64,
) -> Measurements {
    let n = nodes;
    let unit = modulus * rms_gradient;
    let stresses: Vec<f64> = sol
        .stress
        .iter()
        .zip(sol.on_wall.iter().zip(&sol.gap))
        .filter(|(_, (&w, &g))| w || (opts.contact_gap > 0.0 && g <= opts.contact_gap))
        .map(|(&x, _)| x / unit)
        .collect();
    let nc = all_sum_counts(comm, &[stresses.len()])[0];
    let (mean, var) = if nc > 0 {
        let m = chain_sum(comm, stresses.iter().copied()) / nc as f64;
        (m, chain_sum(comm, stresses.iter().map(|x| (x - m).powi(2))) / nc as f64)
    } else {
        (0.0, 0.0)
    };
    let mean_gap = chain_sum(comm, sol.gap.iter().copied()) / n as f64;
    let pr = if nc > 0 {
        let lo = all_min(comm, stresses.iter().cloned().fold(0.0, f64::min));
        let hi = all_max(comm, stresses.iter().cloned().fold(f64::NEG_INFINITY, f64::max));
        let bins = opts.pr_bins.max(1);
        let width = if hi > lo {
            (hi - lo) / bins as f64 * (1.0 + 1e-12)
        } else {
            hi.abs().max(1e-12)
        };
        let mut counts = vec![0usize; bins];
        for &x in &stresses {
            let k = (((x - lo) / width) as usize).min(bins - 1);
            counts[k] += 1;
        }
        let counts = all_sum_counts(comm, &counts);
        PrCurve {
            sigma: (0..bins).map(|k| lo + (k as f64 + 0.5) * width).collect(),
            density: counts.iter().map(|&c| c as f64 / (n as f64 * width)).collect(),
        }
    } else {
        PrCurve::default()
    };
    Measurements {
        stats: ContactStats {
            a_r: nc as f64 / n as f64,
            mean_contact_stress: mean,
            contact_stress_variance: var,
            pr,
        },
        mean_gap,
        mean_gap_rel: mean_gap / rms_height,
        contact_nodes: nc,
        stress_unit: unit,
    }
}
