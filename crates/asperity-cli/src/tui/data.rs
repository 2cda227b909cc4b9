//! The only place the explorer reads [`Evaluation`] and [`Sweep`] fields: everything the
//! views show is copied into the small structs below. When the engine grows fields (the
//! adhesive solver's σ_a*, branch, iterations, residual, detached fraction), wire them in
//! [`wall_marker`], [`branch_label`] and [`PointData::from_evaluation`]; nothing else in
//! `tui` needs to change.

use asperity::theory::engine::Evaluation;
use asperity::theory::sweep::Sweep;

/// Position of the tensile wall in the Pr(σ*) chart, σ* = −σ_a* (reduced). `None` when there
/// is no wall to draw (adhesionless, or the engine does not report it).
pub fn wall_marker(ev: &Evaluation) -> Option<f64> {
    (ev.sigma_a > 0.0).then_some(-ev.sigma_a)
}

/// One-word state of the solution for the read-out: "converged" or (with
/// adhesion) the branch and iteration count.
pub fn branch_label(ev: &Evaluation) -> String {
    if ev.branch == "adhesionless" {
        return "converged".into();
    }
    let mut s = format!("{} ({} it)", ev.branch, ev.iterations);
    if ev.unloading_a_r.is_some() {
        s.push_str(", 2 branches");
    }
    s
}

/// Extra read-outs (label, value) shown under "state" in the panel, in this order.
pub fn extra_readouts(ev: &Evaluation) -> Vec<(String, String)> {
    if ev.branch == "adhesionless" {
        return Vec::new();
    }
    let mut v = vec![
        ("σ_a*".into(), format!("{:.4}", ev.sigma_a)),
        ("tensile".into(), super::view::sig(ev.tensile_area, 3)),
        ("residual".into(), format!("{:.1e}", ev.residual)),
    ];
    if let Some(u) = ev.unloading_a_r {
        v.push(("unload a_r".into(), format!("{u:.5}")));
    }
    v
}

/// What the explorer shows of one evaluation at the current p*.
#[derive(Debug, Clone, PartialEq)]
pub struct PointData {
    /// a_r.
    pub a_r: f64,
    /// σ̄_c*.
    pub mean_contact_stress: f64,
    /// See [`branch_label`].
    pub branch: String,
    /// Estimated absolute error of a_r.
    pub error_estimate: f64,
    /// Wall time of the evaluation (s).
    pub elapsed_s: f64,
    /// Pr(σ*) as (σ*, density) over whatever σ* range the engine sampled (negative σ* with
    /// adhesion).
    pub pr: Vec<(f64, f64)>,
    /// −σ_a*, see [`wall_marker`].
    pub wall: Option<f64>,
    /// Pr(σ*) of the same scene without adhesion (only computed when γ_s > 0).
    pub adhesionless: Option<Vec<(f64, f64)>>,
    /// See [`extra_readouts`].
    pub extra: Vec<(String, String)>,
    /// Width Δ* of the stress distribution (adhesionless: the mirror Gaussian's).
    pub width: f64,
    /// p* of the evaluation.
    pub pressure: f64,
    /// Adhesionless only: Pr(σ*) of the mirror Gaussian [S-22] on a log-spaced σ* grid (for
    /// the log–log chart, whose small-stress end a linear grid does not reach).
    pub pr_log: Vec<(f64, f64)>,
    /// Why this value carries no error bar, when the engine's full check failed but the fixed
    /// point itself converged (shown in the status line, not as an error).
    pub warning: Option<String>,
}

impl PointData {
    /// Copies what the views need.
    pub fn from_evaluation(ev: &Evaluation) -> PointData {
        PointData {
            a_r: ev.stats.a_r,
            mean_contact_stress: ev.stats.mean_contact_stress,
            branch: branch_label(ev),
            error_estimate: ev.error_estimate,
            elapsed_s: ev.elapsed_s,
            pr: pr_points(ev),
            wall: wall_marker(ev),
            adhesionless: None,
            extra: extra_readouts(ev),
            width: ev.width,
            pressure: f64::NAN,
            pr_log: Vec::new(),
            warning: None,
        }
    }

    /// Like [`PointData::from_evaluation`] at load `p` (fills the log-grid Pr of the
    /// adhesionless case).
    pub fn at(ev: &Evaluation, p: f64) -> PointData {
        let mut pd = PointData::from_evaluation(ev);
        pd.pressure = p;
        if ev.branch == "adhesionless" && ev.width > 0.0 {
            let top = ev.stats.pr.sigma.last().copied().unwrap_or(p + 5.0 * ev.width);
            pd.pr_log = log_grid(PR_LOG_FROM, top, PR_LOG_POINTS)
                .into_iter()
                .map(|s| (s, asperity::theory::mirror::density(s, p, ev.width)))
                .collect();
        }
        pd
    }
}

/// Smallest σ* of the log–log Pr chart (\[S\] Fig. 3 reaches 10⁻³).
pub const PR_LOG_FROM: f64 = 1e-4;
/// Points of the log-spaced Pr(σ*).
pub const PR_LOG_POINTS: usize = 161;

/// `n` log-spaced values from `a` to `b` (both > 0).
pub fn log_grid(a: f64, b: f64, n: usize) -> Vec<f64> {
    let n = n.max(2);
    let (la, lb) = (a.ln(), b.max(a * 1.0001).ln());
    (0..n)
        .map(|i| (la + (lb - la) * i as f64 / (n - 1) as f64).exp())
        .collect()
}

/// a_r against t·q_r at one p* (\[S\] Fig. 7): the thickness chart.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ThicknessData {
    /// t·q_r (log-spaced).
    pub t: Vec<f64>,
    /// a_r(t) of the scene (NaN where the solver failed).
    pub a_r: Vec<f64>,
    /// a_r of the semi-infinite body (t = ∞).
    pub a_r_inf: f64,
    /// a_r(t) without adhesion (the reference curve of Fig. 7), when γ_s > 0.
    pub adhesionless: Option<Vec<f64>>,
}

/// Pr(σ*) of an evaluation as chart points.
pub fn pr_points(ev: &Evaluation) -> Vec<(f64, f64)> {
    ev.stats.pr.points()
}

/// The load curves the explorer draws.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SweepData {
    /// p*.
    pub p: Vec<f64>,
    /// a_r(p*).
    pub a_r: Vec<f64>,
    /// ū/h_rms.
    pub gap_rel: Vec<f64>,
    /// σ̄_c*(p*).
    pub mean_contact_stress: Vec<f64>,
    /// Whether each load converged.
    pub converged: Vec<bool>,
}

impl SweepData {
    /// Copies the rows of a sweep.
    pub fn from_sweep(s: &Sweep) -> SweepData {
        SweepData {
            p: s.rows.iter().map(|r| r.p).collect(),
            a_r: s.rows.iter().map(|r| r.a_r).collect(),
            gap_rel: s.rows.iter().map(|r| r.mean_gap_rel).collect(),
            mean_contact_stress: s.rows.iter().map(|r| r.mean_contact_stress).collect(),
            converged: s.rows.iter().map(|r| r.converged).collect(),
        }
    }
}

/// ū/h_rms at the current p* from a one-point sweep, or why it is unavailable (a load on
/// the way to full contact did not converge).
pub fn gap_of_sweep(s: &Sweep) -> asperity::Result<f64> {
    match s.rows.first() {
        Some(r) if r.mean_gap_rel.is_finite() => Ok(r.mean_gap_rel),
        _ => Err(asperity::Error::NotConverged {
            solver: "mean gap".into(),
            reason: s.note.clone().unwrap_or_else(|| "no load converged".into()),
        }),
    }
}

/// What the explorer shows of a finished GFMD run.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct GfmdView {
    /// p* of the run.
    pub pressure: f64,
    /// Fraction of nodes in contact.
    pub a_r: f64,
    /// σ̄_c*.
    pub mean_contact_stress: f64,
    /// ū/h_rms.
    pub gap_rel: f64,
    /// Pr(σ*) histogram (bin centres, density), ∫ = a_r.
    pub pr: Vec<(f64, f64)>,
    /// Grid side N.
    pub grid: usize,
    /// FIRE steps.
    pub iterations: usize,
    /// Wall time (s).
    pub elapsed_s: f64,
    /// The theory's a_r on the same map (its discrete spectrum), if it could be evaluated.
    pub theory_a_r: Option<f64>,
    /// GFMD load sweep on the same map (p*, a_r, ū/h_rms), warm-started; empty until run.
    pub sweep: Vec<(f64, f64, f64)>,
    /// The theory on the same map's spectrum at the sweep's loads (p*, a_r, ū/h_rms): the
    /// reduced system GFMD ran, not the full scene of the other curves.
    pub theory_sweep: Vec<(f64, f64, f64)>,
    /// Reduced against full invariants for the panel: (label, "full → run") and what could not
    /// be kept.
    pub invariants: Vec<(String, String)>,
}

impl GfmdView {
    /// Copies what the views need.
    pub fn from_result(r: &asperity::gfmd::GfmdResult) -> GfmdView {
        GfmdView {
            pressure: r.pressure,
            a_r: r.stats.a_r,
            mean_contact_stress: r.stats.mean_contact_stress,
            gap_rel: r.mean_gap_rel,
            pr: r.stats.pr.points(),
            grid: r.grid,
            iterations: r.iterations,
            elapsed_s: r.elapsed_s,
            theory_a_r: r.theory.as_ref().map(|t| t.stats.a_r),
            sweep: Vec::new(),
            theory_sweep: Vec::new(),
            invariants: r.reduction.as_ref().map_or_else(Vec::new, invariant_rows),
        }
    }

    /// Adds a GFMD sweep and the theory's sweep on the same map.
    pub fn with_sweep(mut self, sw: &asperity::gfmd::sweep::GfmdSweep) -> GfmdView {
        self.sweep = sw.rows.iter().map(|r| (r.p, r.a_r, r.mean_gap_rel)).collect();
        if let Some(t) = &sw.theory {
            self.theory_sweep = t.rows.iter().map(|r| (r.p, r.a_r, r.mean_gap_rel)).collect();
        }
        self
    }
}

/// Panel rows: γ̃_glo and μ_T of the run (and of the full system), λ_r/λ_s likewise, and a count of what was not kept.
fn invariant_rows(r: &asperity::gfmd::reduction::Reduction) -> Vec<(String, String)> {
    let mut v = vec![(
        "λr/λs".to_string(),
        format!("{} (full {})", r.reduced.bandwidth, r.full.bandwidth),
    )];
    if r.full.gamma > 0.0 {
        v.push((
            "GFMD γ̃".to_string(),
            format!("{:.3} (full {:.3})", r.reduced.gamma_glo, r.full.gamma_glo),
        ));
        v.push((
            "GFMD μT".to_string(),
            format!("{:.3} (full {:.3})", r.reduced.tabor, r.full.tabor),
        ));
    }
    let lost: Vec<&str> = r
        .not_kept
        .iter()
        .filter(|k| !k.starts_with("bandwidth"))
        .map(|k| k.split(':').next().unwrap_or(k))
        .collect();
    if !lost.is_empty() {
        v.push(("not kept".to_string(), lost.join(", ")));
    }
    v
}

/// Whether the explorer opens a preset with the preset's γ_s (true, like the CLI) or with
/// adhesion off (false).
pub const ADHESION_BY_DEFAULT: bool = true;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn point_data_copies_the_evaluation() {
        let mut scene = asperity::input::preset::Preset::resolve("system-1")
            .unwrap()
            .scene()
            .unwrap();
        scene.gamma = 0.0;
        let ev = asperity::theory::engine::evaluate(&scene, &asperity::theory::engine::Options::default()).unwrap();
        let pd = PointData::from_evaluation(&ev);
        assert_eq!(pd.a_r, ev.stats.a_r);
        assert_eq!(pd.pr.len(), ev.stats.pr.sigma.len());
        assert_eq!(pd.pr[3], (ev.stats.pr.sigma[3], ev.stats.pr.density[3]));
        assert_eq!(pd.branch, "converged");
        // adhesionless: no wall
        assert_eq!(pd.wall, None);
    }
}
