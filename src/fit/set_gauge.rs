//! Gauging model 5 once on asperity's GFMD reference set, and measuring every model against
//! the set (docs/physics.md §3.6, docs/reference-set.md).
//!
//! Each case of the set (system II at one t·q_r and γ_s) is rebuilt as GFMD ran it: the map of
//! each seed on the set's 256² grid ([`crate::gfmd::result::prepare`], γ_s and ρ rescaled to
//! keep γ̃_glo and the Tabor parameter), and the theory on that map's own spectrum, averaged over
//! the maps like the GFMD values. At each stored load the error of a model is
//!
//! ```text
//! e_a = ln(a_r^theory / a_r^GFMD),     e_u = ln(ū^theory / ū^GFMD)      (ū in units of h_rms)
//! ```
//!
//! on the branch GFMD was on (loading; on unloading the theory's unloading branch where it has
//! one, else its only branch). The comparison is like for like, on the set's bandwidth
//! λ_r/λ_s = 16: the full system's theory is not the reference's (on thin slabs both the theory's
//! and GFMD's a_r move with the bandwidth, physics.md §3.6).
//!
//! The gauge fits model 5's w_f, w_b and w_s ([`crate::input::model_five`]) by least squares
//! to the e_a of the loading points at p* ≥ [`P_RESOLVED`] of every adhesive case in the
//! training set: ū is not fitted, so its errors are a test of the gauge on an observable it
//! never saw. Below [`P_RESOLVED`] the 256² grid resolves the contact too coarsely to
//! arbitrate: there the adhesionless half-space, where the theory is exact to [S-18], is off by
//! up to 1.9× (a_r < 10⁻³ is fewer than 65 nodes in contact), so those loads are reported, not
//! fitted. Cross-validation ([`cross_validate`]) refits with one thickness, then one γ_s, left
//! out and measures the left-out cases.

use super::reference_set::{reference_set, ReferencePoint};
use crate::error::{Error, Result};
use crate::gfmd::result::prepare;
use crate::gfmd::{GfmdSetup, GridSpec};
use crate::input::model::{Model, ModelKind};
use crate::input::model_five::{adhesion_measure, Gauge, GAUGE, W0_MIN};
use crate::input::preset::Preset;
use crate::input::scene::Scene;
use crate::theory::cycle::PathBranch;
use crate::theory::engine::Options;
use crate::theory::sweep::{sweep, SweepSpec};
use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt};
use nalgebra::storage::Owned;
use nalgebra::{DVector, Dyn, Matrix};
use rayon::prelude::*;

/// Smallest p* at which the set's 256² GFMD arbitrates a_r (see the module docs).
pub const P_RESOLVED: f64 = 1e-3;

/// One case of the set, rebuilt: its maps' theory scenes and its stored points (p* > 0).
#[derive(Debug, Clone)]
pub struct SetCase {
    /// Grid side N of the case's GFMD maps.
    pub grid: usize,
    /// t·q_r (∞: half-space).
    pub thickness_qr: f64,
    /// γ_s as a multiple of the preset's.
    pub gamma_factor: f64,
    /// γ̃_glo of the case.
    pub gamma_glo: f64,
    /// The theory scene on each seed's map.
    pub scenes: Vec<Scene>,
    /// The stored loading and unloading points at p* > 0.
    pub points: Vec<ReferencePoint>,
}

/// A model's error at one stored point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointError {
    /// t·q_r of the case.
    pub thickness_qr: f64,
    /// γ_s factor of the case.
    pub gamma_factor: f64,
    /// The branch.
    pub branch: PathBranch,
    /// p*.
    pub p: f64,
    /// e_a.
    pub ln_a_r: f64,
    /// e_u.
    pub ln_mean_gap: f64,
}

/// How a model is chosen per scene: a fixed model, or model 5 under a trial gauge.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ModelChoice {
    /// The same model on every scene (model 5 follows each scene's γ̃_glo with the stored gauge).
    Fixed(Model),
    /// Model 5's form with this gauge (coefficients from each scene's γ̃_glo and μ_T).
    Gauged(Gauge),
}

impl ModelChoice {
    fn on(&self, scene: &Scene) -> Result<Scene> {
        let m = match self {
            ModelChoice::Fixed(m) => *m,
            // marked custom so that the scene keeps the trial coefficients
            ModelChoice::Gauged(g) => Model {
                kind: ModelKind::Custom,
                ..g.model(scene.gamma_glo(), scene.tabor())
            },
        };
        scene.clone().with_model(m)
    }
}

/// The set's system II cases (adhesive and not), rebuilt on `seeds` maps each (1–3).
///
/// # Errors
/// Those of the preset and of the map generation.
pub fn system_two_cases(seeds: u64) -> Result<Vec<SetCase>> {
    cases_of(reference_set(), seeds)
}

/// The system II cases of `points` (one per grid, t·q_r and γ_s factor), each rebuilt on
/// `seeds` maps of its grid (at most as many as GFMD averaged there).
///
/// # Errors
/// Those of the preset and of the map generation.
pub fn cases_of(points: &[ReferencePoint], seeds: u64) -> Result<Vec<SetCase>> {
    let preset = Preset::resolve("system-2")?;
    let spec = preset
        .gfmd
        .as_ref()
        .ok_or_else(|| Error::Unsupported("system-2 has no [gfmd] table".into()))?;
    let mut keys: Vec<(usize, f64, f64, f64, u64)> = points
        .iter()
        .filter(|p| p.system == 2)
        .map(|p| {
            (
                p.grid,
                p.thickness_qr,
                p.gamma_factor,
                p.gamma_glo,
                seeds.min(p.seeds as u64),
            )
        })
        .collect();
    keys.dedup();
    keys.into_par_iter()
        .map(|(n, t, f, glo, seeds)| {
            let grid = GridSpec::from_preset(spec).with_grid(n)?;
            let full = preset.scene()?.with_thickness_qr(t)?;
            let gamma = full.surface_energy_j_m2() * f;
            let full = full.with_surface_energy_j_m2(gamma)?;
            let scenes: Vec<Scene> = (1..=seeds)
                .map(|seed| {
                    let setup = GfmdSetup {
                        scene: full.clone(),
                        grid,
                        seed,
                        surface: None,
                        rescale: true,
                    };
                    prepare(&setup)?.theory_scene(P_RESOLVED)
                })
                .collect::<Result<Vec<_>>>()?;
            let points = points
                .iter()
                .filter(|p| p.system == 2 && p.grid == n && p.thickness_qr == t && p.gamma_factor == f && p.p > 0.0)
                .copied()
                .collect();
            Ok(SetCase {
                grid: n,
                thickness_qr: t,
                gamma_factor: f,
                gamma_glo: glo,
                scenes,
                points,
            })
        })
        .collect()
}

/// The theory's (a_r, ū/h_rms, a_r unloading, ū unloading) at each of the case's loads on
/// each of `scenes`, mean over them.
fn theory_on(case: &SetCase, scenes: &[Scene], model: &ModelChoice, opts: &Options) -> Result<Vec<(f64, [f64; 4])>> {
    let mut loads: Vec<f64> = case.points.iter().map(|p| p.p).collect();
    loads.sort_by(f64::total_cmp);
    loads.dedup_by(|a, b| (*a / *b - 1.0).abs() < 1e-9);
    let (from, to) = (loads[0], loads[loads.len() - 1]);
    let spec = SweepSpec {
        from,
        to,
        points: loads.len(),
    };
    let k = scenes.len() as f64;
    let mut out: Vec<(f64, [f64; 4])> = loads.iter().map(|&p| (p, [0.0; 4])).collect();
    for scene in scenes {
        let s = sweep(&model.on(scene)?, &spec, opts, None)?;
        for (o, r) in out.iter_mut().zip(&s.rows) {
            if (r.p / o.0 - 1.0).abs() > 1e-6 {
                return Err(Error::Unsupported("the case's loads are not log-spaced".into()));
            }
            let (au, uu) = if r.a_r_unloading.is_finite() {
                (r.a_r_unloading, r.mean_gap_unloading_rel)
            } else {
                (r.a_r, r.mean_gap_rel)
            };
            for (acc, v) in o.1.iter_mut().zip([r.a_r, r.mean_gap_rel, au, uu]) {
                *acc += v / k;
            }
        }
    }
    Ok(out)
}

/// The model's error at every stored point of `case`.
///
/// # Errors
/// Those of the theory's sweep.
pub fn case_errors(case: &SetCase, model: &ModelChoice, opts: &Options) -> Result<Vec<PointError>> {
    let maps = theory_on(case, &case.scenes, model, opts)?;
    Ok(case
        .points
        .iter()
        .filter_map(|p| {
            let (_, v) = maps.iter().find(|(q, _)| (q / p.p - 1.0).abs() < 1e-6)?;
            let (a, u) = match p.branch {
                PathBranch::Loading => (v[0], v[1]),
                PathBranch::Unloading => (v[2], v[3]),
            };
            Some(PointError {
                thickness_qr: case.thickness_qr,
                gamma_factor: case.gamma_factor,
                branch: p.branch,
                p: p.p,
                ln_a_r: (a / p.a_r.0).ln(),
                ln_mean_gap: (u / p.mean_gap_rel.0).ln(),
            })
        })
        .collect())
}

/// Every case's errors (cases in parallel; the result does not depend on the threads).
///
/// # Errors
/// The first case whose theory fails.
pub fn set_errors(cases: &[SetCase], model: &ModelChoice, opts: &Options) -> Result<Vec<PointError>> {
    let per: Vec<Result<Vec<PointError>>> = cases.par_iter().map(|c| case_errors(c, model, opts)).collect();
    let mut all = Vec::new();
    for r in per {
        all.extend(r?);
    }
    Ok(all)
}

/// Mean and largest |e| of a list of errors, and their number.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ErrorSummary {
    /// Mean |e_a|.
    pub a_r_mean: f64,
    /// Largest |e_a|.
    pub a_r_worst: f64,
    /// Mean |e_u|.
    pub mean_gap_mean: f64,
    /// Largest |e_u|.
    pub mean_gap_worst: f64,
    /// Points.
    pub points: usize,
}

/// The summary of the errors that `keep` selects (NaN means where none).
pub fn summarize(errors: &[PointError], keep: impl Fn(&PointError) -> bool) -> ErrorSummary {
    let sel: Vec<&PointError> = errors.iter().filter(|e| keep(e)).collect();
    let n = sel.len();
    let mean = |f: &dyn Fn(&PointError) -> f64| sel.iter().map(|e| f(e).abs()).sum::<f64>() / n as f64;
    let worst = |f: &dyn Fn(&PointError) -> f64| sel.iter().map(|e| f(e).abs()).fold(f64::NAN, f64::max);
    ErrorSummary {
        a_r_mean: mean(&|e| e.ln_a_r),
        a_r_worst: worst(&|e| e.ln_a_r),
        mean_gap_mean: mean(&|e| e.ln_mean_gap),
        mean_gap_worst: worst(&|e| e.ln_mean_gap),
        points: n,
    }
}

/// The points the gauge is fitted to and judged on: loading, p* ≥ [`P_RESOLVED`], adhesive.
pub fn is_gauge_point(e: &PointError) -> bool {
    e.branch == PathBranch::Loading && e.p >= P_RESOLVED * (1.0 - 1e-9) && e.gamma_factor > 0.0
}

/// The gauge points' e_a of one case tabulated over model 5's W(0) (w₀ of
/// [`crate::input::model_five`], the only number of the adhesive weight that moves with the
/// gauge): the fit then reads e_a(w_b + w_s·m) (m = [`CaseTable::measure`]) off the table instead of re-solving the
/// theory (linear interpolation in w₀ between nodes).
#[derive(Debug, Clone)]
pub struct CaseTable {
    /// Grid side of the case's maps.
    pub grid: usize,
    /// The bandwidth q_s/q_r of the case's maps (what model 5 reads).
    pub bandwidth: f64,
    /// t·q_r of the case.
    pub thickness_qr: f64,
    /// γ_s factor of the case.
    pub gamma_factor: f64,
    /// γ̃_glo of the case (the w₀ of its nodes is this case's).
    pub gamma_glo: f64,
    /// The Tabor parameter μ_T of the case's maps (kept by the reduction: the full system's).
    pub tabor: f64,
    /// The adhesion measure m = γ̃_glo·μ_T^κ of the case, which the gauge's W(0) reads
    /// ([`adhesion_measure`]).
    pub measure: f64,
    /// The w₀ nodes (ascending).
    pub w0: Vec<f64>,
    /// e_a at each gauge point (outer) and node (inner).
    pub ln_a_r: Vec<Vec<f64>>,
}

impl CaseTable {
    /// e_a at every gauge point for W(0) = `w0` (clamped to the nodes' range).
    pub fn at(&self, w0: f64) -> Vec<f64> {
        let n = self.w0.len();
        let x = w0.clamp(self.w0[0], self.w0[n - 1]);
        let i = self.w0.partition_point(|&v| v <= x).clamp(1, n - 1);
        let t = (x - self.w0[i - 1]) / (self.w0[i] - self.w0[i - 1]);
        self.ln_a_r.iter().map(|e| e[i - 1] + t * (e[i] - e[i - 1])).collect()
    }
}

/// The model of W(0) `w0` at global adhesion `gamma_glo`, in model 5's form (custom, so that
/// a scene keeps it).
/// Model 5's adhesive form with W(0) = `w0` at γ̃_glo = `gamma_glo` (no rise with the measure),
/// marked custom: the model a W(0) scan solves ([`tabulate`], `examples/w0_small_loads.rs`).
pub fn model_at_w0(gamma_glo: f64, w0: f64) -> Model {
    // the gauge whose w₀ at this γ̃ is w0 (w_s = 0): the crossover s(γ̃) stays model 5's
    let g = Gauge {
        base: w0,
        slope: 0.0,
        floor: W0_MIN,
    };
    Model {
        kind: ModelKind::Custom,
        ..g.model(gamma_glo, 0.0)
    }
}

/// Tabulates e_a of the gauge points of every adhesive case over `w0_nodes` (cases and nodes in
/// parallel; the result does not depend on the threads).
///
/// # Errors
/// The first theory that fails.
pub fn tabulate(cases: &[SetCase], w0_nodes: &[f64], opts: &Options) -> Result<Vec<CaseTable>> {
    // only the gauge loads are solved
    let adhesive: Vec<SetCase> = cases
        .iter()
        .filter(|c| c.gamma_factor > 0.0)
        .map(|c| SetCase {
            points: c
                .points
                .iter()
                .filter(|p| p.p >= P_RESOLVED * (1.0 - 1e-9))
                .copied()
                .collect(),
            ..c.clone()
        })
        .collect();
    let jobs: Vec<(usize, f64)> = (0..adhesive.len())
        .flat_map(|i| w0_nodes.iter().map(move |&w| (i, w)))
        .collect();
    let cols: Vec<Result<Vec<f64>>> = jobs
        .par_iter()
        .map(|&(i, w)| {
            let c = &adhesive[i];
            let e = case_errors(c, &ModelChoice::Fixed(model_at_w0(c.gamma_glo, w)), opts)?;
            Ok(e.iter().filter(|e| is_gauge_point(e)).map(|e| e.ln_a_r).collect())
        })
        .collect();
    let mut cols = cols.into_iter();
    adhesive
        .iter()
        .map(|c| {
            let per_node: Vec<Vec<f64>> = w0_nodes
                .iter()
                .map(|_| cols.next().expect("one per job"))
                .collect::<Result<_>>()?;
            let points = per_node.first().map_or(0, Vec::len);
            let bandwidth = c
                .scenes
                .first()
                .map_or(f64::NAN, |s| s.spectrum().q_s() / s.spectrum().q_r());
            // μ_T is kept by the reduction, so the case's maps share it up to rounding
            let tabor = c.scenes.iter().map(Scene::tabor).sum::<f64>() / c.scenes.len().max(1) as f64;
            Ok(CaseTable {
                grid: c.grid,
                bandwidth,
                thickness_qr: c.thickness_qr,
                gamma_factor: c.gamma_factor,
                gamma_glo: c.gamma_glo,
                tabor,
                measure: adhesion_measure(c.gamma_glo, tabor),
                w0: w0_nodes.to_vec(),
                ln_a_r: (0..points)
                    .map(|k| per_node.iter().map(|col| col[k]).collect())
                    .collect(),
            })
        })
        .collect()
}

/// The gauge's residuals: e_a at every gauge point of `tables` under `gauge`.
pub fn gauge_residuals(tables: &[CaseTable], gauge: Gauge) -> Vec<f64> {
    tables.iter().flat_map(|t| t.at(gauge.w0(t.measure))).collect()
}

/// A least-squares problem given by its residual function, the Jacobian by central
/// differences ([`central_jacobian`]): the gauge fits of this module and of
/// [`super::bandwidth_gauge`].
pub(crate) struct ResidualProblem<F: Fn(&DVector<f64>) -> DVector<f64>> {
    /// The residuals at parameters x.
    pub(crate) residual: F,
    /// The current parameters.
    pub(crate) x: DVector<f64>,
}

impl<F: Fn(&DVector<f64>) -> DVector<f64>> LeastSquaresProblem<f64, Dyn, Dyn> for ResidualProblem<F> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, x: &DVector<f64>) {
        self.x = x.clone();
    }

    fn params(&self) -> DVector<f64> {
        self.x.clone()
    }

    fn residuals(&self) -> Option<DVector<f64>> {
        Some((self.residual)(&self.x))
    }

    fn jacobian(&self) -> Option<Matrix<f64, Dyn, Dyn, Owned<f64, Dyn, Dyn>>> {
        Some(central_jacobian(&self.residual, &self.x))
    }
}

/// The Jacobian of the residuals `at` at `x` by central differences of step 10⁻⁴ (the gauge's
/// residuals are piecewise linear in its parameters, read off tables).
pub(crate) fn central_jacobian(at: impl Fn(&DVector<f64>) -> DVector<f64>, x: &DVector<f64>) -> nalgebra::DMatrix<f64> {
    let h = 1e-4;
    let mut j = nalgebra::DMatrix::zeros(at(x).len(), x.len());
    for k in 0..x.len() {
        let (mut xp, mut xm) = (x.clone(), x.clone());
        xp[k] += h;
        xm[k] -= h;
        j.set_column(k, &((at(&xp) - at(&xm)) / (2.0 * h)));
    }
    j
}

/// Fits w_f, w_b and w_s to the gauge points of `tables` (least squares in e_a): for each
/// floor w_f on a grid of step 0.025 from [`W0_MIN`] to 0.4, w_b and w_s from a coarse scan of
/// the plane refined by Levenberg–Marquardt; the best of all.
///
/// # Errors
/// [`Error::Unsupported`] when the tables hold fewer than two gauge points.
pub fn fit_gauge(tables: &[CaseTable]) -> Result<Gauge> {
    let n: usize = tables.iter().map(|t| t.ln_a_r.len()).sum();
    if n < 2 {
        return Err(Error::Unsupported(
            "the training cases hold fewer than two gauge points".into(),
        ));
    }
    let cost = |g: Gauge| gauge_residuals(tables, g).iter().map(|e| e * e).sum::<f64>();
    let mut best = (f64::INFINITY, GAUGE);
    for f in 0..=14 {
        let floor = W0_MIN + 0.025 * f as f64;
        // the residuals are piecewise linear in the gauge: start LM from the best of a scan
        let mut start = (f64::INFINITY, GAUGE);
        for i in 0..=20 {
            for k in 0..=20 {
                let g = Gauge {
                    base: -0.2 + 0.03 * i as f64,
                    slope: 0.1 * k as f64,
                    floor,
                };
                let c = cost(g);
                if c < start.0 {
                    start = (c, g);
                }
            }
        }
        let problem = ResidualProblem {
            residual: |x: &DVector<f64>| {
                let g = Gauge {
                    base: x[0],
                    slope: x[1],
                    floor,
                };
                DVector::from_vec(gauge_residuals(tables, g))
            },
            x: DVector::from_vec(vec![start.1.base, start.1.slope]),
        };
        let (problem, _) = LevenbergMarquardt::new().minimize(problem);
        let g = Gauge {
            base: problem.x[0],
            slope: problem.x[1],
            floor,
        };
        for cand in [g, start.1] {
            let c = cost(cand);
            if c < best.0 {
                best = (c, cand);
            }
        }
    }
    Ok(best.1)
}

/// One fold of the cross-validation: what was left out, the gauge fitted without it, and its
/// errors on the left-out cases' gauge points (from the tables).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fold {
    /// The t·q_r left out (NaN when a γ_s factor was).
    pub thickness_qr: f64,
    /// The γ_s factor left out (NaN when a thickness was).
    pub gamma_factor: f64,
    /// The gauge fitted on the rest.
    pub gauge: Gauge,
    /// Mean |e_a| on the left-out gauge points.
    pub held_out_mean: f64,
    /// Largest |e_a| there.
    pub held_out_worst: f64,
    /// Their number.
    pub held_out_points: usize,
}

/// Refits the gauge with the cases of one t·q_r (or one γ_s factor) left out and measures the
/// left-out cases.
///
/// # Errors
/// Those of [`fit_gauge`].
pub fn cross_validate(tables: &[CaseTable], thickness_qr: Option<f64>, gamma_factor: Option<f64>) -> Result<Fold> {
    let out = |c: &CaseTable| Some(c.thickness_qr) == thickness_qr || Some(c.gamma_factor) == gamma_factor;
    let train: Vec<CaseTable> = tables.iter().filter(|c| !out(c)).cloned().collect();
    let test: Vec<CaseTable> = tables.iter().filter(|c| out(c)).cloned().collect();
    let gauge = fit_gauge(&train)?;
    let e = gauge_residuals(&test, gauge);
    Ok(Fold {
        thickness_qr: thickness_qr.unwrap_or(f64::NAN),
        gamma_factor: gamma_factor.unwrap_or(f64::NAN),
        gauge,
        held_out_mean: e.iter().map(|v| v.abs()).sum::<f64>() / e.len() as f64,
        held_out_worst: e.iter().map(|v| v.abs()).fold(0.0, f64::max),
        held_out_points: e.len(),
    })
}
