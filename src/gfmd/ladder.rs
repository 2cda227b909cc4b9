//! The continuum limit with an error bar, and ensembles over seeds.
//!
//! ## Resolution ladder (physics.md §6)
//!
//! On a grid of spacing Δa, a GFMD measurement X (a_r, σ̄_c*, ⟨δσ_c²⟩*, ū/h_rms) carries a
//! discretisation error that is first order in Δa: contact edges are resolved to a node, and
//! the lattice's elastic response departs from the continuum's at q ≈ π/Δa. [`run_ladder`]
//! solves the *same realisation* (the generator draws one phase per Fourier mode in an order
//! that does not depend on N, so a map at 2N is the map at N sampled twice as finely) at
//! λ_s/Δa = h₁ < h₂ < … and [`extrapolate`] takes Δa → 0:
//!
//! ```text
//! X(Δa) = X₀ + c₁Δa + c₂Δa² + …
//! R₁ = X_f + (X_f − X_c)·Δa_f/(Δa_c − Δa_f)          (first-order Richardson, two finest rungs)
//! error = |R₁(finest pair) − R₁(next pair)|          (three or more rungs)
//!       = |R₁ − X_f|                                  (two rungs: the whole correction)
//! ```
//!
//! The error is that of a first-order estimate whose next term is unknown: the difference of
//! two successive first-order limits is three times the second-order Richardson correction for
//! a ratio of 2, so it also covers the node-counting noise of a_r (a contact edge moves by up
//! to one node between rungs), which is not a smooth function of Δa.
//!
//! ## Seeds
//!
//! [`MeanSe`]: the mean over K independent realisations (seeds s, s+1, …, s+K−1) and its
//! standard error s_K/√K (s_K the sample standard deviation); null error for K = 1.

use super::{run, GfmdOptions, GfmdResult, GfmdSetup, GridSpec, Progress};
use crate::error::{Error, Result};
use serde::Serialize;
use std::sync::atomic::AtomicBool;

/// A Δa → 0 limit and its uncertainty.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Extrapolated {
    /// The extrapolated value X₀.
    pub limit: f64,
    /// Its uncertainty (see the module docs).
    pub error: f64,
    /// The value on the finest rung.
    pub finest: f64,
}

/// Extrapolates values measured at spacings `spacing` (any unit, any order) to zero spacing
/// (see the module docs). Needs at least two distinct spacings.
pub fn extrapolate(spacing: &[f64], values: &[f64]) -> Result<Extrapolated> {
    let mut pts: Vec<(f64, f64)> = spacing.iter().cloned().zip(values.iter().cloned()).collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    pts.dedup_by(|a, b| a.0 == b.0);
    if pts.len() < 2 || pts.iter().any(|(h, v)| !(h.is_finite() && *h > 0.0 && v.is_finite())) {
        return Err(Error::Unsupported(
            "an extrapolation needs finite values at two or more distinct spacings > 0".into(),
        ));
    }
    let r1 = |(hf, xf): (f64, f64), (hc, xc): (f64, f64)| xf + (xf - xc) * hf / (hc - hf);
    let fine = r1(pts[0], pts[1]);
    let error = if pts.len() >= 3 {
        (fine - r1(pts[1], pts[2])).abs()
    } else {
        (fine - pts[0].1).abs()
    };
    Ok(Extrapolated {
        limit: fine,
        error,
        finest: pts[0].1,
    })
}

/// One rung of a ladder.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Rung {
    /// λ_s/Δa.
    pub points_per_short_wavelength: f64,
    /// Grid side N.
    pub grid: usize,
    /// Δa (m).
    pub spacing_m: f64,
    /// a_r.
    pub a_r: f64,
    /// σ̄_c*.
    pub mean_contact_stress: f64,
    /// ⟨δσ_c²⟩*.
    pub contact_stress_variance: f64,
    /// ū/h_rms.
    pub mean_gap_rel: f64,
    /// Solver steps.
    pub iterations: usize,
    /// Solver wall time (s).
    pub solve_elapsed_s: f64,
}

impl Rung {
    fn of(r: &GfmdResult, pts: f64) -> Rung {
        Rung {
            points_per_short_wavelength: pts,
            grid: r.grid,
            spacing_m: r.spacing_m,
            a_r: r.stats.a_r,
            mean_contact_stress: r.stats.mean_contact_stress,
            contact_stress_variance: r.stats.contact_stress_variance,
            mean_gap_rel: r.mean_gap_rel,
            iterations: r.iterations,
            solve_elapsed_s: r.solve_elapsed_s,
        }
    }
}

/// A resolution ladder on one realisation and its Δa → 0 limits.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Ladder {
    /// Seed of the realisation.
    pub seed: u64,
    /// The rungs, coarse to fine.
    pub rungs: Vec<Rung>,
    /// a_r at Δa → 0.
    pub a_r: Extrapolated,
    /// σ̄_c* at Δa → 0.
    pub mean_contact_stress: Extrapolated,
    /// ⟨δσ_c²⟩* at Δa → 0.
    pub contact_stress_variance: Extrapolated,
    /// ū/h_rms at Δa → 0.
    pub mean_gap_rel: Extrapolated,
}

/// Runs `setup` (a generated map) at every λ_s/Δa of `points` (same L/λ_r, λ_r/λ_s, seed) and
/// extrapolates (see the module docs). `progress` gets the rung index with each report.
///
/// # Errors
/// [`Error::Unsupported`] for a given map (only a generated one can be refined);
/// [`Error::Invalid`] for fewer than two rungs or a rung whose grid cannot be built; as
/// [`super::run()`] for each rung.
///
/// # Examples
/// ```
/// use asperity::gfmd::{ladder::run_ladder, GfmdOptions, GfmdSetup, GridSpec};
/// use asperity::input::preset::Preset;
/// use std::sync::atomic::AtomicBool;
///
/// let scene = Preset::resolve("system-1").unwrap().scene().unwrap().without_adhesion();
/// let setup = GfmdSetup {
///     scene: scene.with_pressure(0.05).unwrap(),
///     grid: GridSpec { system_size_ratio: 2.0, bandwidth: 4.0, points_per_short_wavelength: 4.0 },
///     seed: 1,
///     surface: None,
///     rescale: true,
/// };
/// let l = run_ladder(&setup, &[4.0, 8.0], &GfmdOptions::default(), &mut |_, _| {}, &AtomicBool::new(false)).unwrap();
/// assert_eq!(l.rungs.len(), 2);
/// assert!(l.a_r.limit > 0.0 && l.a_r.limit < 1.0 && l.a_r.error.is_finite());
/// ```
pub fn run_ladder(
    setup: &GfmdSetup,
    points: &[f64],
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<Ladder> {
    if setup.surface.is_some() {
        return Err(Error::Unsupported(
            "a resolution ladder needs a generated map (it refines the same realisation); \
             a loaded map has one resolution"
                .into(),
        ));
    }
    let mut pts = points.to_vec();
    pts.sort_by(f64::total_cmp);
    pts.dedup();
    let mut rungs = Vec::new();
    for (k, &p) in pts.iter().enumerate() {
        let grid = GridSpec {
            points_per_short_wavelength: p,
            ..setup.grid
        };
        let s = GfmdSetup { grid, ..setup.clone() };
        let r = run(&s, opts, &mut |pr| progress(k, pr), cancel)?;
        rungs.push(Rung::of(&r, p));
    }
    let h: Vec<f64> = rungs.iter().map(|r| r.spacing_m).collect();
    let ex = |f: fn(&Rung) -> f64| extrapolate(&h, &rungs.iter().map(f).collect::<Vec<_>>());
    Ok(Ladder {
        seed: setup.seed,
        a_r: ex(|r| r.a_r)?,
        mean_contact_stress: ex(|r| r.mean_contact_stress)?,
        contact_stress_variance: ex(|r| r.contact_stress_variance)?,
        mean_gap_rel: ex(|r| r.mean_gap_rel)?,
        rungs,
    })
}

/// A mean over realisations and its standard error.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeanSe {
    /// Mean.
    pub mean: f64,
    /// Standard error s/√K (null for K = 1).
    pub standard_error: Option<f64>,
    /// The K values.
    pub values: Vec<f64>,
}

impl MeanSe {
    /// Mean and standard error of `values` (at least one).
    pub fn of(values: Vec<f64>) -> MeanSe {
        let k = values.len() as f64;
        let mean = values.iter().sum::<f64>() / k;
        let standard_error = (values.len() > 1).then(|| {
            let var = values.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (k - 1.0);
            (var / k).sqrt()
        });
        MeanSe {
            mean,
            standard_error,
            values,
        }
    }
}

/// Mean ± standard error over seeds of the measurements (or of their Δa → 0 limits).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Ensemble {
    /// The seeds.
    pub seeds: Vec<u64>,
    /// Whether each value is a Δa → 0 limit (`--extrapolate`) or a single-grid measurement.
    pub extrapolated: bool,
    /// a_r.
    pub a_r: MeanSe,
    /// σ̄_c*.
    pub mean_contact_stress: MeanSe,
    /// ⟨δσ_c²⟩*.
    pub contact_stress_variance: MeanSe,
    /// ū/h_rms.
    pub mean_gap_rel: MeanSe,
    /// Mean of the per-seed extrapolation errors of a_r (null without `--extrapolate`): add it
    /// to the standard error for the total uncertainty of the continuum limit.
    pub a_r_extrapolation_error: Option<f64>,
    /// The ladders (empty without `--extrapolate`).
    pub ladders: Vec<Ladder>,
}

/// Runs K = `seeds` realisations (seeds `setup.seed`, `setup.seed + 1`, …), each as one run or,
/// with `ladder` given, as a resolution ladder, and reports mean ± standard error.
pub fn run_seeds(
    setup: &GfmdSetup,
    seeds: usize,
    ladder: Option<&[f64]>,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<Ensemble> {
    if seeds == 0 || setup.surface.is_some() {
        return Err(Error::Unsupported(
            "an ensemble needs K >= 1 generated maps (a loaded map is one realisation)".into(),
        ));
    }
    let ids: Vec<u64> = (0..seeds as u64).map(|k| setup.seed.wrapping_add(k)).collect();
    let mut rows: Vec<[f64; 4]> = Vec::new();
    let mut ladders = Vec::new();
    for (k, &seed) in ids.iter().enumerate() {
        let s = GfmdSetup { seed, ..setup.clone() };
        match ladder {
            Some(pts) => {
                let l = run_ladder(&s, pts, opts, &mut |_, p| progress(k, p), cancel)?;
                rows.push([
                    l.a_r.limit,
                    l.mean_contact_stress.limit,
                    l.contact_stress_variance.limit,
                    l.mean_gap_rel.limit,
                ]);
                ladders.push(l);
            }
            None => {
                let r = run(&s, opts, &mut |p| progress(k, p), cancel)?;
                rows.push([
                    r.stats.a_r,
                    r.stats.mean_contact_stress,
                    r.stats.contact_stress_variance,
                    r.mean_gap_rel,
                ]);
            }
        }
    }
    let col = |j: usize| MeanSe::of(rows.iter().map(|r| r[j]).collect());
    Ok(Ensemble {
        seeds: ids,
        extrapolated: ladder.is_some(),
        a_r: col(0),
        mean_contact_stress: col(1),
        contact_stress_variance: col(2),
        mean_gap_rel: col(3),
        a_r_extrapolation_error: (!ladders.is_empty())
            .then(|| ladders.iter().map(|l| l.a_r.error).sum::<f64>() / ladders.len() as f64),
        ladders,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extrapolation_is_exact_for_linear_and_bounded_for_quadratic() {
        let h = [4.0, 2.0, 1.0];
        let lin: Vec<f64> = h.iter().map(|x| 0.3 - 0.01 * x).collect();
        let e = extrapolate(&h, &lin).unwrap();
        assert!((e.limit - 0.3).abs() < 1e-15 && e.error < 1e-15);
        let quad: Vec<f64> = h.iter().map(|x| 0.3 - 0.01 * x + 0.002 * x * x).collect();
        let e = extrapolate(&h, &quad).unwrap();
        assert!((e.limit - 0.3).abs() <= e.error, "{e:?}");
        assert!(extrapolate(&[1.0], &[0.3]).is_err());
        assert!(extrapolate(&[1.0, 2.0], &[0.3, f64::NAN]).is_err());
    }

    #[test]
    fn standard_error_of_known_values() {
        let m = MeanSe::of(vec![1.0, 2.0, 3.0, 4.0]);
        assert_eq!(m.mean, 2.5);
        // s² = 5/3, SE = sqrt(5/12)
        assert!((m.standard_error.unwrap() - (5.0f64 / 12.0).sqrt()).abs() < 1e-15);
        assert_eq!(MeanSe::of(vec![2.0]).standard_error, None);
    }
}
