//! Gauging the theory as \[S\] did: weighted least squares of chosen model coefficients
//! against reference data, with standard errors, correlations and identifiability.
//!
//! The fitted model is the custom one of [S-17] (W(a) = 1 − c₁(1 − a²) − c₂(1 − a⁴), Δp ∝
//! W^α [S-15], σ_a = k_G√(qE*fγ) [S-8]); the parameters are any of c₁, c₂, α, k_G and
//! w₀ = W(0) = 1 − c₁ − c₂ (model 4's "W(a_r → 0)"; fitting w₀ moves c₁ at fixed c₂). The
//! residual of observation i is r_i = (y_model − y_i)/s_i with s_i its standard error where the
//! reference gives one, else |y_i| (relative residuals, as \[S\] Fig. 1 plots a_r/p*), and for a
//! Pr(σ*) bin the peak of its histogram. Levenberg–Marquardt (the `levenberg-marquardt` crate,
//! MINPACK's algorithm) minimises χ² = Σr_i²; the Jacobian is a central difference.
//!
//! At the optimum, with J the Jacobian of r: covariance C = s²(JᵀJ)⁻¹, s² = χ²/(n − k) when
//! the weights are relative (the misfit sets the scale), s² = 1 when every point has its
//! standard error (then χ²/(n − k) is reported as the reduced χ²). Standard errors are √C_jj,
//! correlations C_jk/√(C_jj C_kk). Identifiability: J with unit-scaled columns has singular
//! values σ₁ ≥ … ≥ σ_k; its condition number σ₁/σ_k above [`MAX_CONDITION`] (or a zero
//! column) means the data pin down only some combinations: the right singular vector of σ_k
//! names the unconstrained one, and the fit says so instead of reporting error bars; so it
//! does for a single parameter whose standard error exceeds [`WEAK_SE_FACTOR`] × its size.

pub mod bandwidth_gauge;
pub mod compare;
pub mod finite_size;
pub mod gfmd_reference;
pub mod predict;
pub mod pull_off_gauge;
pub mod pull_off_trust;
pub mod reference;
pub mod reference_set;
mod residuals;
pub mod set_gauge;
mod table;
pub mod trust;
pub mod trust_band;

use crate::error::{Error, Field, Result};
use crate::input::model::{Model, ModelKind};
use crate::input::scene::Scene;
use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt};
use nalgebra::{DMatrix, DVector};
pub use predict::predict;
use reference::Reference;
use residuals::Problem;
use serde::Serialize;
use std::time::Instant;

/// Largest condition number of the column-scaled Jacobian for which the fit reports error
/// bars: beyond it, relative changes of 1e-8 in the data move some combination by O(1).
pub const MAX_CONDITION: f64 = 1e8;

/// A fit whose W dips below this somewhere on [0, 1] has run into the edge of the model's
/// range (W ≥ 0): the reference asks for more than the model can give.
pub const EDGE_W: f64 = 1e-4;

/// A fitted value whose standard error exceeds this many times max(|value|, 0.1) is not
/// determined by the data (e.g. k_G where the σ_a cap is active): the fit says so.
pub const WEAK_SE_FACTOR: f64 = 5.0;

/// Likewise for α within this of its range [0, 4].
pub const EDGE_ALPHA: f64 = 1e-3;

/// A coefficient the fit may move.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Param {
    /// c₁ of [S-17].
    C1,
    /// c₂ of [S-17].
    C2,
    /// α of Δp ∝ W^α [S-15].
    Alpha,
    /// k_G of [S-8].
    KGriffith,
    /// W(0) = 1 − c₁ − c₂ (moves c₁).
    W0,
}

impl Param {
    /// The name as `--fit` takes it.
    pub fn key(self) -> &'static str {
        match self {
            Param::C1 => "c1",
            Param::C2 => "c2",
            Param::Alpha => "alpha",
            Param::KGriffith => "k_griffith",
            Param::W0 => "w0",
        }
    }

    /// The value in `m`.
    pub fn get(self, m: &Model) -> f64 {
        match self {
            Param::C1 => m.c1,
            Param::C2 => m.c2,
            Param::Alpha => m.alpha,
            Param::KGriffith => m.k_griffith,
            Param::W0 => 1.0 - m.c1 - m.c2,
        }
    }

    fn set(self, m: &mut Model, x: f64) {
        match self {
            Param::C1 => m.c1 = x,
            Param::C2 => m.c2 = x,
            Param::Alpha => m.alpha = x,
            Param::KGriffith => m.k_griffith = x,
            Param::W0 => m.c1 = 1.0 - x - m.c2,
        }
    }

    /// Parses a comma-separated list (`c1,c2`), refusing repeats, `cap` (a switch) and
    /// c₁ with w₀ (both set c₁).
    ///
    /// # Errors
    /// [`Error::Invalid`] for the field `fit`.
    pub fn parse_list(s: &str) -> Result<Vec<Param>> {
        let allowed = "a comma-separated list of c1, c2, alpha, k_griffith, w0";
        let mut v = Vec::new();
        for t in s.split(',').map(|t| t.trim().to_ascii_lowercase()) {
            let p = match t.as_str() {
                "c1" => Param::C1,
                "c2" => Param::C2,
                "alpha" => Param::Alpha,
                "k_griffith" | "k-griffith" | "kg" => Param::KGriffith,
                "w0" => Param::W0,
                "cap" => {
                    return Err(Error::invalid_text(
                        Field::Other("fit".into()),
                        s.trim(),
                        "c1, c2, alpha, k_griffith, w0: cap is a switch, not a coefficient (compare cap = true and false instead)",
                    ))
                }
                _ => return Err(Error::invalid_text(Field::Other("fit".into()), s.trim(), allowed)),
            };
            if v.contains(&p) {
                return Err(Error::invalid_text(
                    Field::Other("fit".into()),
                    s.trim(),
                    "each parameter once",
                ));
            }
            v.push(p);
        }
        if v.contains(&Param::C1) && v.contains(&Param::W0) {
            return Err(Error::invalid_text(
                Field::Other("fit".into()),
                s.trim(),
                "c1 or w0, not both (w0 = 1 - c1 - c2 moves c1)",
            ));
        }
        Ok(v)
    }
}

/// A fitted coefficient.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FittedParam {
    /// `c1`, `c2`, `alpha`, `k_griffith` or `w0`.
    pub name: &'static str,
    /// Best value.
    pub value: f64,
    /// Standard error.
    pub std_error: f64,
    /// Starting value.
    pub start: f64,
}

/// The misfit of one observable at the optimum (and at the start).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ObservableResidual {
    /// `a_r`, `mean_contact_stress`, `mean_gap_rel` or `pr`.
    pub observable: &'static str,
    /// Number of points.
    pub points: usize,
    /// Root mean square of the weighted residuals r_i at the optimum.
    pub rms: f64,
    /// Largest |r_i| at the optimum.
    pub max_abs: f64,
    /// Root mean square of r_i at the start.
    pub rms_start: f64,
}

/// The result of [`fit`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Fit {
    /// The fitted coefficients, in the order asked.
    pub params: Vec<FittedParam>,
    /// Correlation matrix of the fitted coefficients (same order).
    pub correlation: Vec<Vec<f64>>,
    /// Condition number of the column-scaled Jacobian at the optimum.
    pub condition_number: f64,
    /// Per observable misfit.
    pub residuals: Vec<ObservableResidual>,
    /// χ² = Σr_i² at the optimum.
    pub chi2: f64,
    /// χ²/(n − k) when every point has its standard error, else `None`.
    pub chi2_reduced: Option<f64>,
    /// Number of observations n.
    pub points: usize,
    /// Evaluations of the theory at the reference (each a solve at every load).
    pub evaluations: usize,
    /// Why the optimiser stopped.
    pub termination: String,
    /// The fitted model (kind custom).
    pub model: Model,
    /// The starting model (kind custom).
    pub start: Model,
    /// Wall time (s).
    pub elapsed_s: f64,
}

/// The starting model of a fit: `m`'s coefficients as a custom model.
///
/// # Errors
/// [`Error::Unsupported`] for Xu24, whose S acts on the total variance, not on [S-17].
pub fn custom_start(m: &Model) -> Result<Model> {
    if m.kind == ModelKind::Xu24 {
        return Err(Error::Unsupported(
            "gauging fits the custom model of [S-17]; start from model 1-4, custom or YP08, not Xu24".into(),
        ));
    }
    Ok(Model {
        kind: ModelKind::Custom,
        ..*m
    })
}

/// Fits `params` of the custom model starting from `scene.model` to `reference` (module
/// docs).
///
/// # Errors
/// [`Error::NotConverged`] when the optimiser stops without converging or the data cannot
/// identify the parameters (with the condition number and the unconstrained combination);
/// [`Error::Invalid`] when there are no more points than parameters or the best fit leaves
/// the model's range (W < 0 on [0, 1], α outside [0, 4]); the solvers' errors.
pub fn fit(scene: &Scene, reference: &Reference, params: &[Param]) -> Result<Fit> {
    crate::work::start();
    let t0 = Instant::now();
    let start = custom_start(&scene.model)?;
    let n = reference.points.len();
    let k = params.len();
    check_sizes(n, k)?;
    let x0 = DVector::from_iterator(k, params.iter().map(|p| p.get(&start)));
    let mut problem = Problem::new(scene, reference, params, start, x0.clone());
    // the starting point must be computable: a bad scene or reference is the user's to fix
    predict(scene, &start, reference)?;
    let r0 = problem.residuals_at(&x0);
    problem.set_params(&x0);
    let (mut problem, report) = LevenbergMarquardt::new().with_patience(200).minimize(problem);
    let x = problem.x.clone();
    let r = problem.residuals_at(&x);
    let evaluations = problem.evaluations + report.number_of_evaluations * (2 * k);
    if !report.termination.was_successful() {
        let why = match problem.error.take() {
            Some(e) => format!(
                "{}; the theory failed on the way: {e}",
                termination_words(&report.termination)
            ),
            None => format!(
                "{} after {} evaluations",
                termination_words(&report.termination),
                report.number_of_evaluations
            ),
        };
        return Err(Error::NotConverged {
            solver: crate::error::Solver::GaugeLevenbergMarquardt,
            reason: why,
        });
    }
    let model = problem.model_at(&x);
    check_within_range(&model, &r, n)?;
    let j = problem.jacobian_at(&x);
    let cond = check_identifiable(&j, params)?;
    let chi2 = r.norm_squared();
    let dof = (n - k) as f64;
    let with_errors = reference.has_errors();
    let s2 = if with_errors { 1.0 } else { chi2 / dof };
    let cov = covariance(&j, s2)?;
    let fitted = fitted_params(params, &x, &x0, &cov)?;
    Ok(Fit {
        params: fitted,
        correlation: correlation(&cov, k),
        condition_number: cond,
        residuals: observable_residuals(reference, &r, &r0),
        chi2,
        chi2_reduced: with_errors.then_some(chi2 / dof),
        points: n,
        evaluations,
        termination: termination_words(&report.termination),
        model,
        start,
        elapsed_s: t0.elapsed().as_secs_f64(),
    })
}

/// [`Error::Invalid`] for no parameter to fit (k = 0) or no more points than parameters
/// (n ≤ k: nothing left to estimate the misfit from).
fn check_sizes(n: usize, k: usize) -> Result<()> {
    if k == 0 {
        return Err(Error::invalid_text(
            Field::Other("fit".into()),
            "(none)",
            "at least one of c1, c2, alpha, k_griffith, w0",
        ));
    }
    if n <= k {
        return Err(Error::invalid(
            Field::Other("reference".into()),
            n as f64,
            format!("more points than fitted parameters ({k})"),
        ));
    }
    Ok(())
}

/// [`Error::NotConverged`] where the best fit `model` (residuals `r` at n points) leaves the
/// model's range or runs into its edge (min W < [`EDGE_W`], α within [`EDGE_ALPHA`] of 0 or
/// 4): the reference asks for more than the model can give, and error bars there would mean
/// nothing.
fn check_within_range(model: &Model, r: &DVector<f64>, n: usize) -> Result<()> {
    model.validate().map_err(|e| Error::NotConverged {
        solver: crate::error::Solver::Gauge,
        reason: format!(
            "the best fit leaves the model's range ({e}): the reference lies outside what the model can reach"
        ),
    })?;
    if model.w_min() < EDGE_W || model.alpha <= EDGE_ALPHA || model.alpha >= 4.0 - EDGE_ALPHA {
        let rms = (r.norm_squared() / n as f64).sqrt();
        return Err(Error::NotConverged {
            solver: crate::error::Solver::Gauge,
            reason: format!(
                "the best fit runs into the edge of the model's range (min W = {:.2e}, alpha = {}) with an rms misfit of {:.3}: the reference lies outside what the model can reach within its range",
                model.w_min(),
                model.alpha,
                rms
            ),
        });
    }
    Ok(())
}

/// The condition number of the Jacobian `j` at the optimum ([`identifiability`]), or
/// [`Error::NotConverged`] naming the unconstrained combination of `params` where it exceeds
/// [`MAX_CONDITION`] (module docs).
fn check_identifiable(j: &DMatrix<f64>, params: &[Param]) -> Result<f64> {
    let (cond, weakest) = identifiability(j);
    if cond.is_nan() || cond > MAX_CONDITION {
        let combo: Vec<String> = params
            .iter()
            .zip(weakest.iter())
            .filter(|(_, w)| w.abs() > 1e-3)
            .map(|(p, w)| format!("{w:+.3}·{}", p.key()))
            .collect();
        return Err(Error::NotConverged {
            solver: crate::error::Solver::Gauge,
            reason: format!(
                "the data cannot identify the parameters: condition number {} > {MAX_CONDITION:e}; unconstrained combination (scaled) {}",
                crate::error::fmt_value(cond),
                combo.join(" ")
            ),
        });
    }
    Ok(cond)
}

/// The covariance C = s²(JᵀJ)⁻¹ of the fitted coefficients (module docs).
fn covariance(j: &DMatrix<f64>, s2: f64) -> Result<DMatrix<f64>> {
    let jtj = j.transpose() * j;
    Ok(jtj.try_inverse().ok_or_else(|| Error::NotConverged {
        solver: crate::error::Solver::Gauge,
        reason: "JᵀJ is singular at the optimum: the data cannot identify the parameters".into(),
    })? * s2)
}

/// The fitted coefficients with their standard errors √C_jj, or [`Error::NotConverged`] for
/// the first whose standard error exceeds [`WEAK_SE_FACTOR`] × max(|value|, 0.1): the data do
/// not pin it down.
fn fitted_params(
    params: &[Param],
    x: &DVector<f64>,
    x0: &DVector<f64>,
    cov: &DMatrix<f64>,
) -> Result<Vec<FittedParam>> {
    let fitted: Vec<FittedParam> = params
        .iter()
        .enumerate()
        .map(|(i, p)| FittedParam {
            name: p.key(),
            value: x[i],
            std_error: cov[(i, i)].max(0.0).sqrt(),
            start: x0[i],
        })
        .collect();
    if let Some(p) = fitted
        .iter()
        .find(|p: &&FittedParam| p.std_error.is_nan() || p.std_error > WEAK_SE_FACTOR * p.value.abs().max(0.1))
    {
        return Err(Error::NotConverged {
            solver: crate::error::Solver::Gauge,
            reason: format!(
                "the data cannot pin down {}: {} ± {} (a standard error above {WEAK_SE_FACTOR} × max(|value|, 0.1)); hold it fixed or add observables that depend on it",
                p.name,
                crate::error::fmt_value(p.value),
                crate::error::fmt_value(p.std_error)
            ),
        });
    }
    Ok(fitted)
}

/// The correlations C_ab/√(C_aa C_bb) of the k fitted coefficients.
fn correlation(cov: &DMatrix<f64>, k: usize) -> Vec<Vec<f64>> {
    (0..k)
        .map(|a| {
            (0..k)
                .map(|b| cov[(a, b)] / (cov[(a, a)] * cov[(b, b)]).sqrt())
                .collect()
        })
        .collect()
}

/// Per observable of the reference, the misfit of the residuals `r` at the optimum and `r0`
/// at the start.
fn observable_residuals(reference: &Reference, r: &DVector<f64>, r0: &DVector<f64>) -> Vec<ObservableResidual> {
    let n = reference.points.len();
    reference
        .observables()
        .into_iter()
        .map(|o| {
            let idx: Vec<usize> = (0..n).filter(|&i| reference.points[i].observable == o).collect();
            let rms = |v: &DVector<f64>| (idx.iter().map(|&i| v[i] * v[i]).sum::<f64>() / idx.len() as f64).sqrt();
            ObservableResidual {
                observable: o.key(),
                points: idx.len(),
                rms: rms(r),
                max_abs: idx.iter().map(|&i| r[i].abs()).fold(0.0, f64::max),
                rms_start: rms(r0),
            }
        })
        .collect()
}

/// Condition number of J with unit-norm columns, and the right singular vector of its smallest
/// singular value (the least constrained combination of the scaled parameters). A zero column
/// gives an infinite condition number and that parameter alone.
pub fn identifiability(j: &DMatrix<f64>) -> (f64, Vec<f64>) {
    let k = j.ncols();
    let mut js = j.clone();
    for c in 0..k {
        let norm = j.column(c).norm();
        if norm.is_nan() || norm <= 0.0 || !norm.is_finite() {
            let mut v = vec![0.0; k];
            v[c] = 1.0;
            return (f64::INFINITY, v);
        }
        js.column_mut(c).scale_mut(1.0 / norm);
    }
    let svd = js.svd(false, true);
    let s = &svd.singular_values;
    let (mut imax, mut imin) = (0, 0);
    for i in 0..s.len() {
        if s[i] > s[imax] {
            imax = i;
        }
        if s[i] < s[imin] {
            imin = i;
        }
    }
    let cond = if s[imin] > 0.0 {
        s[imax] / s[imin]
    } else {
        f64::INFINITY
    };
    let v = svd
        .v_t
        .map(|vt| vt.row(imin).iter().copied().collect())
        .unwrap_or_else(|| vec![0.0; k]);
    (cond, v)
}

/// Why Levenberg–Marquardt stopped, in words (not the solver's type names).
fn termination_words(t: &levenberg_marquardt::TerminationReason) -> String {
    use levenberg_marquardt::TerminationReason as T;
    match t {
        T::Converged { ftol: true, xtol: true } => "converged (the misfit and the parameters stopped changing)".into(),
        T::Converged { ftol: true, .. } => "converged (the misfit stopped changing)".into(),
        T::Converged { .. } => "converged (the parameters stopped changing)".into(),
        T::ResidualsZero => "converged (the model meets every point)".into(),
        T::Orthogonal => "converged (the misfit is orthogonal to every parameter's effect)".into(),
        T::LostPatience => "stopped: the evaluation budget ran out".into(),
        T::NoImprovementPossible(what) => format!("stopped: no improvement possible ({what})"),
        T::Numerical(what) => format!("stopped: a non-finite value ({what})"),
        T::User(what) => format!("stopped: {what}"),
        T::NoParameters => "stopped: no parameters to fit".into(),
        T::NoResiduals => "stopped: no reference points".into(),
        T::WrongDimensions(what) => format!("stopped: wrong dimensions ({what})"),
    }
}
