//! Gauging how model 5's W(0) moves with the bandwidth λ_r/λ_s (docs/physics.md §3.6).
//!
//! [`super::set_gauge`] fits w₀(γ̃_glo) = max(w_f, w_b + w_s·γ̃_glo) on the reference set's 256²
//! maps (λ_r/λ_s = 16). Between bandwidths 16 and 128 the theory's a_r at fixed W(0) moves by up
//! to 3× on thin adhesive slabs where GFMD's moves by ≤ 25 %, so one gauge cannot serve all
//! bandwidths. The second stage here keeps the set's gauge and fits its change per octave
//! ℓ = log₂(B/16) of the bandwidth B = q_s/q_r ([`crate::input::model_five::octaves`]):
//!
//! ```text
//! w_b(ℓ) = w_b + ℓ·δw_b,   w_s(ℓ) = w_s + ℓ·δw_s,   w_f(ℓ) = w_f + ℓ·δw_f
//! ```
//!
//! by least squares in e_a = ln(a_r^theory/a_r^GFMD) over the gauge points (loading, p* ≥ 10⁻³,
//! adhesive) of the *bandwidth set* (`data/reference/bandwidth-set.csv`: GFMD at 512² and
//! 1024², λ_r/λ_s = 32 and 64), tabulated over W(0) like the first stage
//! ([`super::set_gauge::tabulate`]). Cross-validation leaves one grid out, or one thickness.

use super::reference_set::{bandwidth_set, ReferencePoint};
use super::set_gauge::{gauge_residuals, CaseTable, ResidualProblem, SetCase};
use crate::error::{Error, Result};
use crate::input::model_five::{BandwidthGauge, Gauge};
use crate::input::preset::Preset;
use levenberg_marquardt::LevenbergMarquardt;
use nalgebra::DVector;

/// e_a at every gauge point of `tables` under the gauge over bandwidths `gauge` (each table at
/// its own bandwidth).
pub fn bandwidth_residuals(tables: &[CaseTable], gauge: &BandwidthGauge) -> Vec<f64> {
    tables
        .iter()
        .flat_map(|t| gauge_residuals(std::slice::from_ref(t), gauge.at(t.bandwidth)))
        .collect()
}

fn with_steps(at_set: Gauge, d: &[f64]) -> BandwidthGauge {
    BandwidthGauge {
        at_set,
        per_octave: Gauge {
            base: d[0],
            slope: d[1],
            floor: d[2],
        },
    }
}

/// Fits the steps per octave to the gauge points of `tables` (cases of several bandwidths)
/// with the set's gauge `at_set` held: a scan of (δw_b, δw_s, δw_f) refined by
/// Levenberg–Marquardt (the floor stays at or above [`crate::input::model_five::W0_MIN`], [`Gauge::w0`]).
///
/// # Errors
/// [`Error::Unsupported`] when the tables hold fewer than three gauge points.
pub fn fit_per_octave(tables: &[CaseTable], at_set: Gauge) -> Result<BandwidthGauge> {
    let n: usize = tables.iter().map(|t| t.ln_a_r.len()).sum();
    if n < 3 {
        return Err(Error::Unsupported(
            "the bandwidth cases hold fewer than three gauge points".into(),
        ));
    }
    let cost = |d: &[f64]| {
        bandwidth_residuals(tables, &with_steps(at_set, d))
            .iter()
            .map(|e| e * e)
            .sum::<f64>()
    };
    let mut best = (f64::INFINITY, [0.0; 3]);
    for i in 0..=16 {
        for k in 0..=16 {
            for f in 0..=8 {
                let d = [-0.2 + 0.025 * i as f64, -0.4 + 0.05 * k as f64, -0.04 + 0.02 * f as f64];
                let c = cost(&d);
                if c < best.0 {
                    best = (c, d);
                }
            }
        }
    }
    let problem = ResidualProblem {
        residual: |x: &DVector<f64>| DVector::from_vec(bandwidth_residuals(tables, &with_steps(at_set, x.as_slice()))),
        x: DVector::from_row_slice(&best.1),
    };
    let (problem, _) = LevenbergMarquardt::new().minimize(problem);
    let refined = [problem.x[0], problem.x[1], problem.x[2]];
    let d = if refined.iter().all(|v| v.is_finite()) && cost(&refined) < best.0 {
        refined
    } else {
        best.1
    };
    Ok(with_steps(at_set, &d))
}

/// One fold: what was left out (a grid, or a thickness), the fit without it and its errors on
/// the left-out gauge points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OctaveFold {
    /// The grid left out (0 when a thickness was).
    pub grid: usize,
    /// The t·q_r left out (NaN when a grid was).
    pub thickness_qr: f64,
    /// The gauge fitted on the rest.
    pub gauge: BandwidthGauge,
    /// Mean |e_a| on the left-out gauge points.
    pub held_out_mean: f64,
    /// Largest |e_a| there.
    pub held_out_worst: f64,
    /// Their number.
    pub held_out_points: usize,
}

/// Refits the steps per octave with one grid's (or one thickness's) cases left out of
/// `tables` and measures them.
///
/// # Errors
/// Those of [`fit_per_octave`].
pub fn leave_out(
    tables: &[CaseTable],
    at_set: Gauge,
    grid: Option<usize>,
    thickness_qr: Option<f64>,
) -> Result<OctaveFold> {
    let out = |c: &CaseTable| Some(c.grid) == grid || Some(c.thickness_qr) == thickness_qr;
    let train: Vec<CaseTable> = tables.iter().filter(|c| !out(c)).cloned().collect();
    let test: Vec<CaseTable> = tables.iter().filter(|c| out(c)).cloned().collect();
    let gauge = fit_per_octave(&train, at_set)?;
    let e = bandwidth_residuals(&test, &gauge);
    Ok(OctaveFold {
        grid: grid.unwrap_or(0),
        thickness_qr: thickness_qr.unwrap_or(f64::NAN),
        gauge,
        held_out_mean: e.iter().map(|v| v.abs()).sum::<f64>() / e.len().max(1) as f64,
        held_out_worst: e.iter().map(|v| v.abs()).fold(0.0, f64::max),
        held_out_points: e.len(),
    })
}

/// The bandwidth set's adhesive cases on the *full* system II (the continuum spectrum `run`
/// uses, λ_r/λ_s = 128), each with the points of its widest GFMD grid: what `run --model 5`
/// is judged on. The theory runs on the full scene, not on a map, so these cases test the
/// gauge at a bandwidth no table of the fit was at.
///
/// # Errors
/// Those of the preset.
pub fn full_system_cases() -> Result<Vec<SetCase>> {
    let preset = Preset::resolve("system-2")?;
    let base = preset.scene()?;
    let mut keys: Vec<(f64, f64)> = bandwidth_set()
        .iter()
        .map(|p| (p.thickness_qr, p.gamma_factor))
        .collect();
    keys.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    keys.dedup();
    let mut out = Vec::new();
    for (t, f) in keys {
        let of_case = |p: &&ReferencePoint| p.thickness_qr == t && p.gamma_factor == f;
        let widest = bandwidth_set()
            .iter()
            .filter(of_case)
            .map(|p| p.grid)
            .max()
            .unwrap_or(0);
        let points: Vec<ReferencePoint> = bandwidth_set()
            .iter()
            .filter(|p| of_case(p) && p.grid == widest)
            .copied()
            .collect();
        let scene = base
            .clone()
            .with_thickness_qr(t)?
            .with_surface_energy_j_m2(base.surface_energy_j_m2() * f)?;
        out.push(SetCase {
            grid: widest,
            thickness_qr: t,
            gamma_factor: f,
            gamma_glo: scene.gamma_glo(),
            scenes: vec![scene],
            points,
        });
    }
    Ok(out)
}
