//! The report of one scene at one load: the contact statistics [S-3, S-9], every branch of
//! the adhesive solution [S-14] with its mean gap (docs/physics.md §5.1), the hysteresis
//! window around the load, the error bars and the time each part took.
//!
//! Units as everywhere in the library: stresses reduced by E*ḡ (σ* = σ/(E*ḡ)), gaps relative
//! to h_rms (`*_rel`) or in metres (`mean_gap`), energies in J/m², times in seconds of wall
//! time. The serialised field names are those of `asperity run --format json` (a public
//! interface).

use crate::contact::ContactStats;
use crate::error::Result;
use crate::input::scene::{Scene, SceneSummary};
use crate::theory::adhesion::{Branch, BranchState};
use crate::theory::engine::{self, Evaluation, Options};
use crate::theory::gap::{self, BranchGap, MeanGap};
use crate::theory::window::{self, Window};
use serde::Serialize;
use std::time::Instant;

/// a_r(q) along the resolution q_L → q_s.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct ResolutionTable {
    /// q (1/m).
    pub q: Vec<f64>,
    /// a_r(q).
    pub a_r: Vec<f64>,
}

/// Everything known about one scene at its load p*.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[non_exhaustive]
pub struct PointReport {
    /// `a_r`, `mean_contact_stress` (reduced by E*ḡ), `contact_stress_variance` (by (E*ḡ)²)
    /// and `pr` = {`sigma`, `density`}, ∫density dσ* = a_r.
    #[serde(flatten)]
    pub stats: ContactStats,
    /// Width Δ* of the stress distribution.
    pub width: f64,
    /// Whether the result meets the requested accuracy: a finite error bar, a_r in [0, 1],
    /// and with adhesion every stable branch's self-consistency residual within the
    /// adhesive tolerance.
    pub converged: bool,
    /// Why `converged` is false, in one line (which check failed, with its numbers); absent
    /// when it is true.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub converged_note: Option<String>,
    /// Estimated absolute error of a_r.
    pub error_estimate: f64,
    /// Mean gap ū (m) of the reported branch (`branch`: the loading one unless the options
    /// follow the unloading branch): the adhesionless gap [S-12] at the load the
    /// branch's contact carries (without adhesion: the energy route itself; docs/physics.md
    /// §5.1); None when unavailable (see `mean_gap_note`).
    pub mean_gap: Option<f64>,
    /// ū/h_rms; None when unavailable.
    pub mean_gap_rel: Option<f64>,
    /// Lower end of ū/h_rms's bracket: the adhesionless gap at the load that gives the same
    /// a_r (no higher than `mean_gap_rel`); equal to `mean_gap_rel` without adhesion; None
    /// when the gap is.
    pub mean_gap_lower_rel: Option<f64>,
    /// Upper end of the bracket: the adhesionless gap at the same load; None when the gap is.
    pub mean_gap_upper_rel: Option<f64>,
    /// Estimated absolute error of `mean_gap_rel` (quadrature and interpolation); None when
    /// the gap is.
    pub mean_gap_error: Option<f64>,
    /// p_c*: the net force the reported branch's contact carries per nominal area, ∫σ*Pr dσ*
    /// (p* plus the tension of the contact edges; p* without adhesion); None when the gap is.
    pub contact_load: Option<f64>,
    /// One line saying what `mean_gap_rel` is ([`mean_gap_about`]).
    pub mean_gap_about: String,
    /// Why the mean gap is None; absent when it is given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mean_gap_note: Option<String>,
    /// Elastic energy U per nominal area (J/m²) [S-11].
    pub elastic_energy: f64,
    /// σ_a*(q_s): the adhesive wall at σ* = −σ_a* (0 without adhesion).
    pub sigma_a: f64,
    /// Contact area under tension, ∫_{−σ_a}^0 Pr dσ*.
    pub tensile_area: f64,
    /// 1 − a_r: the fraction that left the contact through the wall.
    pub detached_fraction: f64,
    /// Marches of the adhesive solver (0 without adhesion).
    pub iterations: usize,
    /// Self-consistency residual |γ(q_s)/γ_s − 1| (0 without adhesion).
    pub residual: f64,
    /// "adhesionless"; "loading": the branch a loading history reaches; or "unloading" where
    /// the options follow the unloading branch
    /// ([`crate::theory::adhesion::AdhesionAccuracy::follow_unloading`], a preset's
    /// `[load] branch = "unloading"`) and the load lies inside a hysteresis window. The
    /// distribution, moments, tensile area, wall and gap fields are this branch's.
    pub branch: Branch,
    /// a_r of a distinct unloading branch (the highest stable one), None if none: the name a
    /// sweep's row gives it ([`crate::theory::sweep::SweepRow::a_r_unloading`]; the preferred
    /// name, see [`crate::report::names`]).
    pub a_r_unloading: Option<f64>,
    /// The same number as `a_r_unloading`, under its older name (an alias kept for readers of
    /// earlier output).
    pub unloading_a_r: Option<f64>,
    /// Every branch at this load, lowest a_r first, with its gap. Empty without adhesion.
    pub branches: Vec<BranchReport>,
    /// Inside a hysteresis window (two stable branches at this load): p* above which the
    /// loading branch no longer exists (jump into contact); None outside a window or when
    /// the window runs past the allowed range of p*.
    pub jump_in_pressure: Option<f64>,
    /// Inside a hysteresis window: p* below which the unloading branch no longer exists
    /// (pull-off); None outside a window or when it runs past the allowed range.
    pub pull_off_pressure: Option<f64>,
    /// Where the scene lies relative to asperity's GFMD reference set and how far the theory
    /// was measured from GFMD at the nearest stored points ([`crate::fit::trust`]).
    pub trust: crate::fit::trust::Trust,
    /// The pull-off read-out where asked for ([`point_with_pull_off`]; absent otherwise): the
    /// theory's pull-off in tension, the DMT routes', GFMD's nearest and their trust.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pull_off: Option<super::pull_off::PullOffReport>,
    /// γ(q)/γ_s along `resolution.q` (empty without adhesion).
    pub gamma_q: Vec<f64>,
    /// σ_a*(q) along `resolution.q` (empty without adhesion).
    pub sigma_a_q: Vec<f64>,
    /// Wall time of the whole computation (s): the solve with its error estimate, the
    /// hysteresis window and the mean gap (the parts follow).
    pub elapsed_s: f64,
    /// Wall time of the solve at p* with its error estimate (s).
    pub elapsed_solve_s: f64,
    /// Wall time of the hysteresis window's edges (s; 0 outside a window).
    pub elapsed_window_s: f64,
    /// Wall time of the mean gap (s).
    pub elapsed_gap_s: f64,
    /// Resolved inputs.
    pub scene: SceneSummary,
    /// a_r(q) along the resolution.
    pub resolution: ResolutionTable,
}

/// One branch of [`PointReport::branches`]: its state and its mean gap.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[non_exhaustive]
pub struct BranchReport {
    /// branch, stable, a_r, sigma_a, gamma_coarse, elastic_energy, residual.
    #[serde(flatten)]
    pub state: BranchState,
    /// ū/h_rms of this branch: the adhesionless gap at the load its contact carries
    /// (docs/physics.md §5.1); None for an unstable branch (no quasi-static path follows it)
    /// or when unavailable.
    pub mean_gap_rel: Option<f64>,
    /// The adhesionless gap at the same load (the bracket's upper end, the same for every
    /// branch: the dissipation-free route [S-12] of the scene without adhesion); None as
    /// `mean_gap_rel`.
    pub mean_gap_reversible_rel: Option<f64>,
    /// The bracket's lower end: the adhesionless gap at the load with this branch's a_r;
    /// None as `mean_gap_rel`.
    pub mean_gap_lower_rel: Option<f64>,
    /// The bracket's upper end (= `mean_gap_reversible_rel`); None as `mean_gap_rel`.
    pub mean_gap_upper_rel: Option<f64>,
    /// Estimated absolute error of `mean_gap_rel`; None as `mean_gap_rel`.
    pub mean_gap_error: Option<f64>,
    /// The net force the branch's contact carries per nominal area, ∫σ*Pr dσ*; None as
    /// `mean_gap_rel`.
    pub contact_load: Option<f64>,
}

/// What `mean_gap_rel` is, in one line.
pub fn mean_gap_about(adhesive: bool) -> String {
    if adhesive {
        "mean_gap_rel: the adhesionless gap at the load the branch's contact carries (p* + the pull of its edges) \
         (docs/physics.md 5.1), bracketed by the adhesionless gap at the load with the same a_r \
         (lower) and at the same load (upper)"
            .into()
    } else {
        "mean_gap_rel: the energy route of Persson theory, integral of dU/p from p* to full contact [S-12]".into()
    }
}

/// Evaluates `scene` at its load and gathers the report: the evaluation with its error
/// estimate ([`engine::evaluate`]), inside a hysteresis window its edges
/// ([`window::window_around_from`], from the evaluation's own branches), and the mean gap of
/// each stable branch ([`gap::mean_gap_of`], from the same branches: nothing adhesive is
/// solved twice).
///
/// A mean gap that cannot be had does not fail the report: the gap fields are None and
/// `mean_gap_note` says why.
///
/// # Errors
/// [`crate::Error::Invalid`] for a scene or options out of range; what
/// [`engine::evaluate`] and [`window::window_around_from`] return when the solve or the
/// window's edges cannot be resolved ([`crate::Error::NotConverged`] with the reason).
///
/// # Examples
/// ```
/// use asperity::input::preset::Preset;
/// use asperity::report;
/// use asperity::theory::engine::Options;
///
/// // System II of [S] with its surface energy, model 3, semi-infinite, p* = 0.01.
/// let scene = Preset::resolve("system-2").unwrap().scene().unwrap();
/// let r = report::point(&scene, &Options::default()).unwrap();
/// assert!(r.converged && r.stats.a_r > 0.0 && r.stats.a_r < 1.0);
/// // the loading branch's gap lies in its bracket
/// let (lo, g, hi) = (r.mean_gap_lower_rel.unwrap(), r.mean_gap_rel.unwrap(), r.mean_gap_upper_rel.unwrap());
/// assert!(lo <= g && g <= hi);
/// ```
pub fn point(scene: &Scene, opts: &Options) -> Result<PointReport> {
    opts.validate()?;
    let t0 = Instant::now();
    let ev = engine::evaluate(scene, opts)?;
    let t_solve = t0.elapsed().as_secs_f64();
    let window = match ev.adhesive.as_deref() {
        Some(sol) if ev.branches.iter().filter(|b| b.stable).count() >= 2 => {
            window::window_around_from(scene, sol, &opts.adhesion, None)?
        }
        _ => None,
    };
    let t_window = t0.elapsed().as_secs_f64();
    let (gap, mean_gap_note) = match gap::mean_gap_of(scene, &ev, opts) {
        Ok(g) => (Some(g), None),
        Err(e) => (None, Some(format!("mean gap unavailable: {e}"))),
    };
    let elapsed_s = t0.elapsed().as_secs_f64();
    Ok(assemble(
        scene,
        opts,
        &ev,
        window,
        gap,
        mean_gap_note,
        [elapsed_s, t_solve, t_window],
    ))
}

/// Whether an evaluation meets the accuracy `opts` asked for (see [`PointReport::converged`]):
/// None when it does, else the reason in one line.
fn unconverged_reason(scene: &Scene, ev: &Evaluation, opts: &Options) -> Option<String> {
    use crate::error::fmt_value;
    if !(ev.error_estimate.is_finite() && ev.error_estimate >= 0.0) {
        return Some(format!(
            "the error estimate of a_r is {} (not a finite bar)",
            fmt_value(ev.error_estimate)
        ));
    }
    if !(0.0..=1.0).contains(&ev.stats.a_r) {
        return Some(format!("a_r = {} lies outside [0, 1]", fmt_value(ev.stats.a_r)));
    }
    if !scene.is_adhesive() {
        return None;
    }
    let tol = opts.adhesion.tol;
    if ev.residual > tol {
        return Some(format!(
            "the adhesive self-consistency residual |gamma(q_s)/gamma_s - 1| = {} is above the tolerance {} \
             (accuracy.adhesion_tol; finer adhesion steps or points may reach it)",
            fmt_value(ev.residual),
            fmt_value(tol)
        ));
    }
    ev.branches.iter().find(|b| b.stable && b.residual > tol).map(|b| {
        format!(
            "the stable {} branch (a_r = {}) has self-consistency residual {} above the tolerance {} \
                 (accuracy.adhesion_tol)",
            b.branch,
            fmt_value(b.a_r),
            fmt_value(b.residual),
            fmt_value(tol)
        )
    })
}

fn assemble(
    scene: &Scene,
    opts: &Options,
    ev: &Evaluation,
    window: Option<Window>,
    gap: Option<MeanGap>,
    mean_gap_note: Option<String>,
    [elapsed_s, t_solve, t_window]: [f64; 3],
) -> PointReport {
    let note = unconverged_reason(scene, ev, opts);
    // the top-level gap is the reported branch's: the loading one's, or the unloading one's
    // where the evaluation follows it (`AdhesionAccuracy::follow_unloading`)
    let shown: Option<BranchGap> = gap.as_ref().and_then(|g| {
        if ev.branch == Branch::Unloading {
            g.unloading
        } else {
            Some(BranchGap {
                relative: g.relative,
                error: g.error,
                lower: g.lower,
                upper: g.upper,
                contact_load: g.contact_load,
            })
        }
    });
    let h_rms = scene.spectrum.rms_height();
    PointReport {
        stats: ev.stats.clone(),
        width: ev.width,
        converged: note.is_none(),
        converged_note: note,
        error_estimate: ev.error_estimate,
        mean_gap: shown.map(|g| g.relative * h_rms),
        mean_gap_rel: shown.map(|g| g.relative),
        mean_gap_lower_rel: shown.map(|g| g.lower),
        mean_gap_upper_rel: shown.map(|g| g.upper),
        mean_gap_error: shown.map(|g| g.error),
        contact_load: shown.map(|g| g.contact_load),
        mean_gap_about: mean_gap_about(scene.is_adhesive()),
        mean_gap_note,
        elastic_energy: ev.elastic_energy,
        sigma_a: ev.sigma_a,
        tensile_area: ev.tensile_area,
        detached_fraction: ev.detached_fraction,
        iterations: ev.iterations,
        residual: ev.residual,
        branch: ev.branch,
        a_r_unloading: ev.unloading_a_r,
        unloading_a_r: ev.unloading_a_r,
        branches: branches(ev, gap.as_ref()),
        jump_in_pressure: window.and_then(|w| w.jump_in_pressure),
        pull_off_pressure: window.and_then(|w| w.pull_off_pressure),
        trust: crate::fit::trust::assess(scene),
        pull_off: None,
        gamma_q: ev.gamma_q.clone(),
        sigma_a_q: ev.sigma_a_q.clone(),
        elapsed_s,
        elapsed_solve_s: t_solve,
        elapsed_window_s: t_window - t_solve,
        elapsed_gap_s: elapsed_s - t_window,
        scene: scene.summary(),
        resolution: ResolutionTable {
            q: ev.resolution.iter().map(|r| r.q).collect(),
            a_r: ev.resolution.iter().map(|r| r.a_r).collect(),
        },
    }
}

/// [`point()`] with the pull-off read-out ([`super::pull_off::pull_off`]) in `pull_off`: the
/// theory's path into tension and the two routes, 0.1–3 s more on system II.
///
/// # Errors
/// As [`point()`] and [`super::pull_off::pull_off`].
pub fn point_with_pull_off(scene: &Scene, opts: &Options) -> Result<PointReport> {
    let mut r = point(scene, opts)?;
    r.pull_off = Some(super::pull_off::pull_off(scene, &opts.adhesion, None)?);
    Ok(r)
}

/// The branches of an evaluation with their gaps (`gap` holds the loading branch's and,
/// inside a hysteresis window, the unloading branch's).
fn branches(ev: &Evaluation, gap: Option<&MeanGap>) -> Vec<BranchReport> {
    ev.branches
        .iter()
        .map(|b| {
            let g: Option<BranchGap> = match (b.branch, gap) {
                (Branch::Loading, Some(g)) if b.stable => Some(BranchGap {
                    relative: g.relative,
                    error: g.error,
                    lower: g.lower,
                    upper: g.upper,
                    contact_load: g.contact_load,
                }),
                (Branch::Unloading, Some(g)) => g.unloading,
                _ => None,
            };
            BranchReport {
                state: b.clone(),
                mean_gap_rel: g.map(|g| g.relative),
                mean_gap_reversible_rel: g.map(|g| g.upper),
                mean_gap_lower_rel: g.map(|g| g.lower),
                mean_gap_upper_rel: g.map(|g| g.upper),
                mean_gap_error: g.map(|g| g.error),
                contact_load: g.map(|g| g.contact_load),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::preset::Preset;

    /// Following the unloading branch reports the root the loading evaluation lists as
    /// `unloading` (the same a_r and gap), with its own distribution: system II, model 3,
    /// t·q_r = 0.1, γ_s = 0.1256 J/m², p* = 1e-4, inside its hysteresis window.
    #[test]
    fn the_unloading_branch_is_the_listed_unloading_root() {
        let scene = crate::report::sweep::tests::jump_scene()
            .with_thickness_qr(0.1)
            .unwrap();
        let loading = point(&scene, &Options::default()).unwrap();
        let mut o = Options::default();
        o.adhesion.follow_unloading = true;
        let unloading = point(&scene, &o).unwrap();
        assert_eq!((loading.branch, unloading.branch), (Branch::Loading, Branch::Unloading));
        let listed = loading
            .branches
            .iter()
            .find(|b| b.state.branch == Branch::Unloading)
            .expect("two stable branches at this load");
        assert!((unloading.stats.a_r / listed.state.a_r - 1.0).abs() < 1e-6);
        assert!(unloading.stats.a_r > 5.0 * loading.stats.a_r);
        let (g, want) = (unloading.mean_gap_rel.unwrap(), listed.mean_gap_rel.unwrap());
        assert!((g / want - 1.0).abs() < 1e-3, "{g} vs {want}");
        // its own distribution: ∫Pr dσ* = a_r of the branch (trapezoid on the sampled grid)
        let pr = &unloading.stats.pr;
        let mass: f64 = pr
            .sigma
            .windows(2)
            .zip(pr.density.windows(2))
            .map(|(s, d)| 0.5 * (d[0] + d[1]) * (s[1] - s[0]))
            .sum();
        assert!(
            (mass / unloading.stats.a_r - 1.0).abs() < 2e-2,
            "{mass} vs {}",
            unloading.stats.a_r
        );
    }

    #[test]
    fn an_unconverged_evaluation_says_which_check_failed() {
        let scene = Preset::resolve("system-2").unwrap().scene().unwrap();
        let opts = Options::default();
        let ev = engine::evaluate(&scene, &opts).unwrap();
        assert_eq!(unconverged_reason(&scene, &ev, &opts), None);
        let mut off = ev.clone();
        off.residual = 10.0 * opts.adhesion.tol;
        let why = unconverged_reason(&scene, &off, &opts).unwrap();
        assert!(
            why.contains("residual") && why.contains("tolerance") && !why.contains('\n'),
            "{why}"
        );
        let mut bar = ev.clone();
        bar.error_estimate = f64::NAN;
        assert!(unconverged_reason(&scene, &bar, &opts)
            .unwrap()
            .contains("error estimate"));
        let mut area = ev;
        area.stats.a_r = 1.5;
        assert!(unconverged_reason(&scene, &area, &opts)
            .unwrap()
            .contains("outside [0, 1]"));
    }
}
