//! [`crate::gfmd::measure()`] on slabs: the same a_r, σ̄_c*, ⟨δσ_c²⟩*, Pr(σ*) and ū, bit for
//! bit, from every rank's rows (the sums in node order through
//! [`super::comm::chain_sum`], the extremes and the histogram counts exact in any order).

use super::comm::{all_max, all_min, all_sum_counts, chain_sum, Comm};
use crate::contact::{ContactStats, PrCurve};
use crate::gfmd::{GfmdOptions, Measurements, Solution};

/// Measures a relaxed contact from this rank's rows of `sol` (`nodes` in the whole map;
/// `modulus` E*; ḡ and h_rms of the whole map). Every rank gets the result.
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
