//! The only place the explorer reads [`Evaluation`] and [`Sweep`] fields: everything the
//! views show is copied into the small structs below. When the engine grows fields (the
//! adhesive solver's σ_a*, branch, iterations, residual, detached fraction), wire them in
//! [`wall_marker`], [`branch_label`] and [`PointData::from_evaluation`]; nothing else in
//! `tui` needs to change.
//!
//! Branches (hysteresis): at a load inside a hysteresis window the adhesive theory has several
//! self-consistent solutions ([`Evaluation::branches`], lowest a_r first): the loading branch
//! (what a loading history reaches), the unloading branch (what an unloading history keeps)
//! and unstable ones between them. The point panel lists them ([`BranchRow`]); the a_r(p*)
//! chart draws the unloading curve beside the loading one and marks the jump-in load (above
//! which the loading branch no longer exists) and the pull-off load (below which the
//! unloading branch no longer exists), see [`SweepData::with_branches`].

use asperity::theory::adhesion::{Branch, BranchState};
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
    if ev.branch == Branch::Adhesionless {
        return "converged".into();
    }
    let mut s = format!("{} ({} it)", ev.branch, ev.iterations);
    if ev.branches.len() > 1 {
        s.push_str(&format!(", {} branches", ev.branches.len()));
    }
    s
}

/// One branch of the adhesive solution at the current load, as the point panel lists it.
#[derive(Debug, Clone, PartialEq)]
pub struct BranchRow {
    /// "loading", "unloading" or "unstable".
    pub name: String,
    /// a_r(q_s) of the branch.
    pub a_r: f64,
    /// Whether it is stable (H rises through its root).
    pub stable: bool,
    /// Whether it is the branch the rest of the panel and the Pr chart show.
    pub shown: bool,
}

/// The branches of an evaluation (empty without adhesion, or with a single branch: nothing to
/// choose between).
pub fn branch_rows(ev: &Evaluation) -> Vec<BranchRow> {
    if ev.branches.len() < 2 {
        return Vec::new();
    }
    // the shown branch: the evaluation's own (its a_r is the closest)
    let shown = ev
        .branches
        .iter()
        .enumerate()
        .filter(|(_, b)| b.branch == ev.branch)
        .min_by(|x, y| {
            let dx = (x.1.a_r - ev.stats.a_r).abs();
            let dy = (y.1.a_r - ev.stats.a_r).abs();
            dx.total_cmp(&dy)
        })
        .map(|(i, _)| i);
    ev.branches
        .iter()
        .enumerate()
        .map(|(i, b)| BranchRow {
            name: b.branch.as_str().into(),
            a_r: b.a_r,
            stable: b.stable,
            shown: Some(i) == shown,
        })
        .collect()
}

/// Extra read-outs (label, value) shown under "state" in the panel, in this order.
pub fn extra_readouts(ev: &Evaluation) -> Vec<(String, String)> {
    if ev.branch == Branch::Adhesionless {
        return Vec::new();
    }
    let mut v = vec![
        ("σ_a*".into(), crate::numfmt::sig(ev.sigma_a, 4)),
        ("tensile".into(), tensile_share(ev.tensile_area, ev.stats.a_r)),
        ("residual".into(), crate::numfmt::sig(ev.residual, 2)),
    ];
    if ev.branches.len() < 2 {
        if let Some(u) = ev.unloading_a_r {
            v.push(("unload a_r".into(), crate::numfmt::sig(u, 4)));
        }
    }
    v
}

/// The contact under tension as the captions say it: its share of the contact area a_r
/// (∫_{−σ_a}^0 Pr dσ* / a_r), e.g. `12.1% of contact`.
pub fn tensile_share(tensile_area: f64, a_r: f64) -> String {
    if a_r > 0.0 && tensile_area.is_finite() {
        format!("{}% of contact", crate::numfmt::sig(100.0 * tensile_area / a_r, 3))
    } else {
        "–".into()
    }
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
    /// Every branch at this load (empty with fewer than two), see [`branch_rows`].
    pub branches: Vec<BranchRow>,
    /// A quick first answer at chart accuracy (no error bar); the full-accuracy point follows.
    pub preview: bool,
    /// Inside a hysteresis window: the same load on the unloading branch, evaluated whole
    /// (its Pr, σ̄_c*, tensile area, wall, state and error bar), which the panel and the charts
    /// show where the load history is on that branch; None outside a window.
    pub unloading: Option<Box<PointData>>,
    /// On [`PointData::unloading`]: the branch's ū/h_rms and its bracket (the adhesionless gap
    /// at the load with its a_r … at the same load, docs/physics.md §5.1); None elsewhere or
    /// where the gap could not be had.
    pub gap: Option<BranchGapView>,
    /// The panel's `trust` row, computed with the point (empty until then).
    pub trust: String,
    /// The pull-off read-out in one line for the a_r(p*) chart (adhesive scenes; None
    /// without adhesion or until computed with the trust).
    pub pull_off: Option<String>,
}

/// Where the gauged pull-off estimate starts in [`PointData::pull_off`] (the view drops it
/// first where a chart's border is short).
pub const PULL_OFF_EST_SEGMENT: &str = " · est. ";

/// ū/h_rms of one branch with its bracket.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BranchGapView {
    /// ū/h_rms.
    pub relative: f64,
    /// The bracket's lower end (the adhesionless gap at the load with the branch's a_r).
    pub lower: f64,
    /// The bracket's upper end (the adhesionless gap at the same load).
    pub upper: f64,
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
            branches: branch_rows(ev),
            preview: false,
            unloading: None,
            gap: None,
            trust: String::new(),
            pull_off: None,
        }
    }

    /// Like [`PointData::from_evaluation`] at load `p` (fills the log-grid Pr of the
    /// adhesionless case).
    pub fn at(ev: &Evaluation, p: f64) -> PointData {
        let mut pd = PointData::from_evaluation(ev);
        pd.pressure = p;
        if ev.branch == Branch::Adhesionless && ev.width > 0.0 {
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
    /// a_r of the unloading branch where p* lies inside a hysteresis window at that t (NaN
    /// elsewhere; empty: no window). `a_r` is then the loading branch's, as on the a_r(p*)
    /// chart.
    pub a_r_unloading: Vec<f64>,
    /// t·q_r of the windows' edges where the loading branch (small contact) ends: thinner,
    /// only the large contact is left (a jump into contact).
    pub jump_in: Vec<f64>,
    /// t·q_r of the windows' edges where the unloading branch (large contact) ends: thicker,
    /// only the small contact is left (pull-off).
    pub pull_off: Vec<f64>,
}

/// One frame of the scale view: Pr(σ*, q) at one resolution of the march.
#[derive(Debug, Clone, PartialEq)]
pub struct ScaleFrame {
    /// q/q_L.
    pub q_rel: f64,
    /// a_r(q).
    pub a_r: f64,
    /// σ_a*(q) (0 without adhesion): the wall sits at σ* = −σ_a*.
    pub sigma_a: f64,
    /// Pr(σ*, q) as (σ*, density), on the σ* range shared by every frame.
    pub pr: Vec<(f64, f64)>,
}

/// The scale view of a scene ([`asperity::theory::adhesion::scales`]): frames coarse to
/// fine (the last at q_s) and a_r(q), σ_a*(q) at every node of the march.
#[derive(Debug, Clone, PartialEq)]
pub struct ScalesData {
    /// The frames.
    pub frames: Vec<ScaleFrame>,
    /// (q/q_L, a_r(q)) at the march's nodes.
    pub area: Vec<(f64, f64)>,
    /// (q/q_L, σ_a*(q)) at the march's nodes.
    pub wall: Vec<(f64, f64)>,
}

impl ScalesData {
    /// Copies what the scale charts need.
    pub fn from_scales(s: &asperity::theory::adhesion::scales::Scales) -> ScalesData {
        let q_l = s.q.first().copied().unwrap_or(1.0);
        ScalesData {
            frames: s
                .frames
                .iter()
                .map(|f| {
                    // the march's round-off far from the distribution (|Pr| < 1e-12 of the
                    // peak) is drawn as the zero it is
                    let peak = f.density.iter().fold(0.0f64, |m, d| m.max(d.abs()));
                    let pr = s
                        .sigma
                        .iter()
                        .zip(&f.density)
                        .map(|(&x, &d)| (x, if d.abs() < 1e-12 * peak { 0.0 } else { d }))
                        .collect();
                    ScaleFrame {
                        q_rel: f.q / q_l,
                        a_r: f.a_r,
                        sigma_a: f.sigma_a,
                        pr,
                    }
                })
                .collect(),
            area: s.q.iter().zip(&s.a_q).map(|(q, a)| (q / q_l, *a)).collect(),
            wall: s.q.iter().zip(&s.sigma_a_q).map(|(q, w)| (q / q_l, *w)).collect(),
        }
    }
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
    /// ū/h_rms (the loading branch's).
    pub gap_rel: Vec<f64>,
    /// The bracket of ū/h_rms on the loading branch: the adhesionless gap at the load with the
    /// same a_r (lower) and at the same load (upper), docs/physics.md §5.1; empty without
    /// adhesion (the bracket is the value itself).
    pub gap_lower: Vec<f64>,
    /// Upper end of the bracket (see [`SweepData::gap_lower`]).
    pub gap_upper: Vec<f64>,
    /// ū/h_rms of the unloading branch inside a hysteresis window (NaN elsewhere; empty: no
    /// hysteresis).
    pub gap_unloading: Vec<f64>,
    /// σ̄_c*(p*).
    pub mean_contact_stress: Vec<f64>,
    /// Whether each load converged.
    pub converged: Vec<bool>,
    /// a_r of the unloading branch (NaN where there is no distinct one; empty: no hysteresis).
    pub a_r_unloading: Vec<f64>,
    /// p* above which the loading branch no longer exists (the jump into contact), when it
    /// lies in the swept range.
    pub jump_in: Option<f64>,
    /// p* below which the unloading branch no longer exists (pull-off), when it lies in the
    /// swept range.
    pub pull_off: Option<f64>,
    /// The quick first sweep of an adhesive scene (fewer loads, see
    /// `worker::PREVIEW_POINTS`), drawn while the full one runs.
    pub preview: bool,
    /// Why loads with a_r have no ū/h_rms (the mean gap failed on its own), if so.
    pub gap_note: Option<String>,
}

impl SweepData {
    /// The bracket of the loading branch's ū/h_rms at `p` (interpolated in ln p* like the gap
    /// itself), where the sweep has one.
    pub fn gap_bracket_at(&self, p: f64) -> Option<(f64, f64)> {
        if self.gap_lower.len() != self.p.len() || self.gap_upper.len() != self.p.len() {
            return None;
        }
        let lo = asperity::theory::sweep::interpolate_in_ln_p(&self.p, &self.gap_lower, p)?;
        let hi = asperity::theory::sweep::interpolate_in_ln_p(&self.p, &self.gap_upper, p)?;
        (lo.is_finite() && hi.is_finite()).then_some((lo.min(hi), hi.max(lo)))
    }

    /// Copies the rows of a sweep: the loading branch with ū and σ̄_c*, the unloading branch
    /// where a hysteresis window makes it distinct, and the window's edges (the library refines
    /// them by bisection, [`asperity::theory::hysteresis`]).
    pub fn from_sweep(s: &Sweep) -> SweepData {
        let bracket = s.rows.iter().any(|r| r.mean_gap_upper_rel > r.mean_gap_lower_rel);
        let col = |f: &dyn Fn(&asperity::theory::sweep::SweepRow) -> f64| -> Vec<f64> {
            if bracket {
                s.rows.iter().map(f).collect()
            } else {
                Vec::new()
            }
        };
        SweepData {
            p: s.rows.iter().map(|r| r.p).collect(),
            a_r: s.rows.iter().map(|r| r.a_r).collect(),
            gap_rel: s.rows.iter().map(|r| r.mean_gap_rel).collect(),
            // a bracket only where it is one (with adhesion the ends differ)
            gap_lower: col(&|r| r.mean_gap_lower_rel),
            gap_upper: col(&|r| r.mean_gap_upper_rel),
            gap_unloading: if s.rows.iter().any(|r| r.mean_gap_unloading_rel.is_finite()) {
                s.rows.iter().map(|r| r.mean_gap_unloading_rel).collect()
            } else {
                Vec::new()
            },
            mean_contact_stress: s.rows.iter().map(|r| r.mean_contact_stress).collect(),
            converged: s.rows.iter().map(|r| r.converged).collect(),
            // empty without a hysteresis (nothing to draw)
            a_r_unloading: if s.rows.iter().any(|r| r.a_r_unloading.is_finite()) {
                s.rows.iter().map(|r| r.a_r_unloading).collect()
            } else {
                Vec::new()
            },
            jump_in: s.jump_in_pressure,
            pull_off: s.pull_off_pressure,
            preview: false,
            gap_note: s.gap_note.clone(),
        }
    }

    /// Adds the unloading curve and the jump from the branches found at each load
    /// (`branches[k]` at `p[k]`; an empty list where the load failed), see
    /// [`unloading_curve`] (for loads evaluated one by one; a sweep carries its own).
    pub fn with_branches(mut self, branches: &[Vec<BranchState>]) -> SweepData {
        let (u, jump, pull) = unloading_curve(&self.p, branches);
        self.a_r_unloading = u;
        self.jump_in = jump;
        self.pull_off = pull;
        self
    }

    /// Whether there is anything of a second branch to draw.
    pub fn has_hysteresis(&self) -> bool {
        self.a_r_unloading.iter().any(|a| a.is_finite()) || self.jump_in.is_some() || self.pull_off.is_some()
    }
}

/// From the branches at each load `p[k]` (ascending): a_r of the unloading branch (NaN where
/// there is none distinct from the loading one), the jump-in load and the pull-off load.
///
/// The hysteresis window is the run of loads with a distinct unloading branch. The jump-in
/// load is the window's top: the last load where the loading branch still exists (its
/// midpoint with the next load in ln p*, where the next load converged without hysteresis).
/// The pull-off load is the window's bottom likewise. An edge at the end of the swept range
/// (the window continues beyond it) is not a jump: `None`. With several windows the first
/// jump-in and the last pull-off are reported.
pub fn unloading_curve(p: &[f64], branches: &[Vec<BranchState>]) -> (Vec<f64>, Option<f64>, Option<f64>) {
    let n = p.len().min(branches.len());
    let unloading: Vec<f64> = (0..n)
        .map(|k| {
            branches[k]
                .iter()
                .find(|b| b.branch == Branch::Unloading && b.a_r.is_finite())
                .map_or(f64::NAN, |b| b.a_r)
        })
        .collect();
    // a load with numbers but without a distinct unloading branch (a single branch)
    let single = |k: usize| !branches[k].is_empty() && unloading[k].is_nan();
    let mid = |a: f64, b: f64| (a.ln() + 0.5 * (b.ln() - a.ln())).exp();
    let mut jump = None;
    let mut pull = None;
    for k in 0..n.saturating_sub(1) {
        let (here, next) = (unloading[k].is_finite(), unloading[k + 1].is_finite());
        if jump.is_none() && here && single(k + 1) {
            jump = Some(mid(p[k], p[k + 1]));
        }
        if next && single(k) {
            pull = Some(mid(p[k], p[k + 1]));
        }
    }
    (unloading, jump, pull)
}

/// Whether the explorer opens a preset with the preset's γ_s (true, like the CLI) or with
/// adhesion off (false).
pub const ADHESION_BY_DEFAULT: bool = true;

/// a_r(p*) of eq. (18) of \[S\] (the closed form the area charts draw dashed).
pub fn eq18_area(p: f64) -> f64 {
    asperity::theory::closed_form::eq18_area(p)
}

/// The small-stress asymptote of the adhesionless Pr(σ*) (\[S\] Fig. 3).
pub fn pr_small_stress(sigma: f64, p: f64, delta: f64) -> f64 {
    asperity::theory::closed_form::pr_small_stress(sigma, p, delta)
}

/// The large-stress asymptote of the adhesionless Pr(σ*) (\[S\] Fig. 3).
pub fn pr_large_stress(sigma: f64, p: f64, delta: f64) -> f64 {
    asperity::theory::closed_form::pr_large_stress(sigma, p, delta)
}

#[cfg(test)]
#[path = "data_tests.rs"]
mod tests;
