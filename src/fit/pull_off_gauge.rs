//! A gauged estimate of GFMD's pull-off: an empirical correlation fitted at run time on the
//! stored pull-offs of system II's 21 adhesive cases (`data/reference/pull-off-theory-256.csv`,
//! [`super::pull_off_trust::table`]), with the error it was measured to have on cases it was
//! not fitted to (docs/physics.md §6.5).
//!
//! **The form.** ln(−p\*_c) = a + b·ln γ̃_glo + c/(t·q_r), the last term 0 for the half-space:
//! the pull-off grows as a power b of the global adhesion measure γ̃_glo = γ_s/u_ela^(f) [S-24]
//! and a thin slab, at equal γ̃_glo, holds less by e^{c/(t·q_r)} (c < 0 as fitted). The three
//! coefficients are the least-squares solution of the 3×3 normal equations over the cases
//! given (ordinary least squares in ln p\*_c). It is a correlation gauged on GFMD, not a
//! derivation, and it gives the theory no unloading branch.
//!
//! **Its error.** Each case is left out in turn, the form fitted on the others and the case's
//! held-out error e = ln(p\*_c estimate / p\*_c GFMD) recorded. The stated band is the
//! ⌈[`BAND_COVERAGE`]·(n+1)⌉-th smallest |e| of the n cases (the jackknife quantile, which
//! holds a further exchangeable case with probability ≥ [`BAND_COVERAGE`]): the estimate is
//! stated as p\*_c ×/÷ e^{that}.
//!
//! **Where it says nothing.** Outside the cases' domain it extrapolates nothing and says
//! "outside the measured range: no estimate": another spectrum shape than system II's (a
//! measured or discrete spectrum, another Hurst exponent or L/λ_r, a bandwidth λ_r/λ_s more
//! than 1.5× outside the 16…128 where system II was measured), t·q_r thinner than the set's,
//! γ̃_glo outside the range the set holds at the scene's thickness (interpolated in 1/(t·q_r)
//! between the set's thicknesses), or a Tabor parameter outside the set's.

use super::pull_off_trust::{table, PullOffCase};
use crate::input::model_five::{BANDWIDTH_MEASURED, SET_BANDWIDTH};
use crate::input::preset::Preset;
use crate::input::scene::Scene;
use crate::surface::spectrum::Spectrum;
use serde::Serialize;
use std::sync::OnceLock;

/// The share of held-out cases the stated band is built to hold (module docs).
pub const BAND_COVERAGE: f64 = 0.9;
/// The factor the held-out summary counts cases within (the target).
pub const WITHIN_FACTOR: f64 = 1.5;
/// Slack on the edges of the measured ranges (relative; the set's own cases lie inside).
const EDGE_SLACK: f64 = 0.02;
/// How close a scene's Hurst exponent and q_r/q_L must be to system II's (relative).
const SHAPE_REL: f64 = 0.01;

/// The coefficients (a, b, c) of the form (module docs).
pub type Coefficients = [f64; 3];

/// The regressors (1, ln γ̃_glo, 1/(t·q_r)) of a case or scene (1/(t·q_r) = 0 for a half-space).
pub fn regressors(gamma_glo: f64, thickness_qr: f64) -> [f64; 3] {
    let thin = if thickness_qr.is_finite() {
        1.0 / thickness_qr
    } else {
        0.0
    };
    [1.0, gamma_glo.ln(), thin]
}

/// The form's pull-off p\* (< 0) at (γ̃_glo, t·q_r) with coefficients `c`.
pub fn evaluate(c: &Coefficients, gamma_glo: f64, thickness_qr: f64) -> f64 {
    let x = regressors(gamma_glo, thickness_qr);
    -(c[0] * x[0] + c[1] * x[1] + c[2] * x[2]).exp()
}

/// Whether a case carries a pull-off the form can be fitted to (GFMD held tension).
fn usable(c: &PullOffCase) -> bool {
    c.gfmd.0 < 0.0 && c.gamma_glo > 0.0 && c.gamma_glo.is_finite()
}

/// The least-squares coefficients over the usable cases of `cases` (None with fewer than 3 or
/// where the normal equations are singular).
pub fn fit(cases: &[PullOffCase]) -> Option<Coefficients> {
    let mut m = [[0.0; 3]; 3];
    let mut v = [0.0; 3];
    let mut n = 0;
    for c in cases.iter().filter(|c| usable(c)) {
        let x = regressors(c.gamma_glo, c.thickness_qr);
        let y = (-c.gfmd.0).ln();
        for ((mi, vi), xi) in m.iter_mut().zip(v.iter_mut()).zip(x) {
            *vi += xi * y;
            for (mij, xj) in mi.iter_mut().zip(x) {
                *mij += xi * xj;
            }
        }
        n += 1;
    }
    if n < 3 {
        return None;
    }
    solve3(m, v)
}

/// Solves m·x = v by Cramer's rule (None where m is singular to round-off).
fn solve3(m: [[f64; 3]; 3], v: [f64; 3]) -> Option<[f64; 3]> {
    let det = |a: [[f64; 3]; 3]| {
        a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
    };
    let d = det(m);
    let scale: f64 = m.iter().flatten().map(|x| x.abs()).fold(0.0, f64::max);
    if !d.is_finite() || d.abs() <= 1e-12 * scale.powi(3) {
        return None;
    }
    let mut x = [0.0; 3];
    for (k, xk) in x.iter_mut().enumerate() {
        let mut a = m;
        for (row, vr) in a.iter_mut().zip(v) {
            row[k] = vr;
        }
        *xk = det(a) / d;
    }
    Some(x)
}

/// Each case's estimate from the form fitted on the cases not left out with it: `left_out(i, j)`
/// says whether case j is left out when case i is estimated (it must hold for j = i). None for
/// a case that is not usable or whose fit has too few cases.
pub fn held_out_estimates(cases: &[PullOffCase], left_out: impl Fn(usize, usize) -> bool) -> Vec<Option<f64>> {
    (0..cases.len())
        .map(|i| {
            if !usable(&cases[i]) {
                return None;
            }
            let rest: Vec<PullOffCase> = (0..cases.len())
                .filter(|&j| j != i && !left_out(i, j))
                .map(|j| cases[j])
                .collect();
            fit(&rest).map(|c| evaluate(&c, cases[i].gamma_glo, cases[i].thickness_qr))
        })
        .collect()
}

/// ln(estimate/GFMD) of each case left out on its own (None where it has no estimate).
pub fn leave_one_out(cases: &[PullOffCase]) -> Vec<Option<f64>> {
    errors(cases, &held_out_estimates(cases, |i, j| i == j))
}

/// ln(estimate/GFMD) of each case with every case of its thickness left out.
pub fn leave_thickness_out(cases: &[PullOffCase]) -> Vec<Option<f64>> {
    let same = |i: usize, j: usize| cases[i].thickness_qr == cases[j].thickness_qr;
    errors(cases, &held_out_estimates(cases, same))
}

fn errors(cases: &[PullOffCase], est: &[Option<f64>]) -> Vec<Option<f64>> {
    cases
        .iter()
        .zip(est)
        .map(|(c, e)| e.map(|e| (e / c.gfmd.0).ln()))
        .collect()
}

/// The band's half-width in ln p\*_c from held-out errors: the ⌈[`BAND_COVERAGE`]·(n+1)⌉-th
/// smallest |e| (None where that exceeds n: too few cases to state it).
pub fn band_half_width(errors: &[f64]) -> Option<f64> {
    let mut a: Vec<f64> = errors.iter().map(|e| e.abs()).collect();
    a.sort_by(f64::total_cmp);
    let k = (BAND_COVERAGE * (a.len() + 1) as f64).ceil() as usize;
    (1..=a.len()).contains(&k).then(|| a[k - 1])
}

/// The band's measured coverage: each usable case left out, the form fitted and its band
/// stated from the others alone (their own held-out errors), whether the band held the case's
/// GFMD pull-off; (held, cases).
pub fn band_held(cases: &[PullOffCase]) -> [usize; 2] {
    let mut held = [0, 0];
    for (i, c) in cases.iter().enumerate().filter(|(_, c)| usable(c)) {
        let rest: Vec<PullOffCase> = cases
            .iter()
            .enumerate()
            .filter(|(j, _)| *j != i)
            .map(|(_, c)| *c)
            .collect();
        let e: Vec<f64> = leave_one_out(&rest).into_iter().flatten().collect();
        let (Some(k), Some(b)) = (fit(&rest), band_half_width(&e)) else {
            continue;
        };
        held[1] += 1;
        let r = (evaluate(&k, c.gamma_glo, c.thickness_qr) / c.gfmd.0).ln();
        held[0] += usize::from(r.abs() <= b);
    }
    held
}

/// How the form did on cases it was not fitted to.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HeldOut {
    /// Cases estimated.
    pub cases: usize,
    /// Mean |ln(estimate/GFMD)|.
    pub mean_abs_ln: f64,
    /// The largest factor between estimate and GFMD.
    pub worst_factor: f64,
    /// Cases within [`WITHIN_FACTOR`] of GFMD.
    pub within_1_5: usize,
}

impl HeldOut {
    /// The summary of held-out errors `e` (ln ratios; None entries skipped).
    pub fn of(e: &[Option<f64>]) -> HeldOut {
        let e: Vec<f64> = e.iter().flatten().map(|x| x.abs()).collect();
        HeldOut {
            cases: e.len(),
            mean_abs_ln: e.iter().sum::<f64>() / e.len().max(1) as f64,
            worst_factor: e.iter().copied().fold(0.0, f64::max).exp(),
            within_1_5: e.iter().filter(|&&x| x <= WITHIN_FACTOR.ln()).count(),
        }
    }
}

/// The measured domain: at each thickness of the set (by 1/(t·q_r), ascending) the range of
/// ln γ̃_glo its cases hold, and the range of their Tabor parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct Domain {
    /// (1/(t·q_r), ln γ̃_glo smallest, largest), ascending in 1/(t·q_r).
    pub thickness: Vec<(f64, f64, f64)>,
    /// Smallest and largest μ_T of the cases (None where system II's preset did not resolve).
    pub tabor: Option<[f64; 2]>,
}

/// μ_T of system II's preset at its own γ_s (the cases keep it, ∝ γ_s^{2/3}).
fn preset_tabor() -> Option<f64> {
    static T: OnceLock<Option<f64>> = OnceLock::new();
    *T.get_or_init(|| Some(Preset::resolve("system-2").ok()?.scene().ok()?.tabor()))
}

impl Domain {
    /// The domain of the usable cases of `cases`.
    pub fn of(cases: &[PullOffCase]) -> Domain {
        let mut thickness: Vec<(f64, f64, f64)> = Vec::new();
        for c in cases.iter().filter(|c| usable(c)) {
            let (x, g) = (regressors(c.gamma_glo, c.thickness_qr)[2], c.gamma_glo.ln());
            match thickness.iter_mut().find(|e| e.0 == x) {
                Some(e) => (e.1, e.2) = (e.1.min(g), e.2.max(g)),
                None => thickness.push((x, g, g)),
            }
        }
        thickness.sort_by(|a, b| a.0.total_cmp(&b.0));
        let tabor = preset_tabor().and_then(|t0| {
            let mu: Vec<f64> = cases
                .iter()
                .filter(|c| usable(c))
                .map(|c| t0 * c.gamma_factor.powf(2.0 / 3.0))
                .collect();
            let lo = mu.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = mu.iter().copied().fold(0.0, f64::max);
            (lo <= hi).then_some([lo, hi])
        });
        Domain { thickness, tabor }
    }

    /// Each way (γ̃_glo, t·q_r, μ_T) lies outside the domain, in words (empty inside).
    pub fn outside(&self, gamma_glo: f64, thickness_qr: f64, tabor: Option<f64>) -> Vec<String> {
        let mut out = Vec::new();
        let x = regressors(gamma_glo, thickness_qr)[2];
        let (Some(first), Some(last)) = (self.thickness.first(), self.thickness.last()) else {
            return vec!["no measured case".into()];
        };
        if x > last.0 * (1.0 + EDGE_SLACK) || x < first.0 - EDGE_SLACK * last.0 {
            out.push(format!(
                "t·q_r {thickness_qr:.3} is outside the measured {:.3}…{}",
                1.0 / last.0,
                if first.0 == 0.0 {
                    "∞".to_string()
                } else {
                    format!("{:.3}", 1.0 / first.0)
                }
            ));
        } else {
            let (lo, hi) = self.glo_range_at(x);
            let g = gamma_glo.ln();
            if !(lo - EDGE_SLACK..=hi + EDGE_SLACK).contains(&g) {
                out.push(format!(
                    "γ̃_glo {gamma_glo:.3} is outside the measured {:.3}…{:.3} at this thickness",
                    lo.exp(),
                    hi.exp()
                ));
            }
        }
        if let (Some([lo, hi]), Some(mu)) = (self.tabor, tabor) {
            if !(lo * (1.0 - EDGE_SLACK)..=hi * (1.0 + EDGE_SLACK)).contains(&mu) {
                out.push(format!("μ_T {mu:.3} is outside the measured {lo:.3}…{hi:.3}"));
            }
        }
        out
    }

    /// The ln γ̃_glo range at 1/(t·q_r) = x, linear in x between the bracketing thicknesses.
    fn glo_range_at(&self, x: f64) -> (f64, f64) {
        let t = &self.thickness;
        let k = t.partition_point(|e| e.0 < x).clamp(1, t.len().max(2) - 1);
        if t.len() < 2 {
            return (t[0].1, t[0].2);
        }
        let (a, b) = (t[k - 1], t[k]);
        let w = ((x - a.0) / (b.0 - a.0)).clamp(0.0, 1.0);
        (a.1 + w * (b.1 - a.1), a.2 + w * (b.2 - a.2))
    }
}

/// The form fitted on a set of cases, with its held-out error and domain.
#[derive(Debug, Clone, PartialEq)]
pub struct Gauge {
    /// (a, b, c) fitted on every usable case.
    pub coefficients: Coefficients,
    /// The band's half-width in ln p\*_c (module docs).
    pub band_half_width: f64,
    /// Each case left out on its own.
    pub leave_one_out: HeldOut,
    /// Each thickness left out with all its cases.
    pub leave_thickness_out: HeldOut,
    /// (held, cases) of [`band_held`].
    pub band_held: [usize; 2],
    /// Where it was measured.
    pub domain: Domain,
}

impl Gauge {
    /// The gauge on `cases` (None with too few usable cases to fit and state a band).
    pub fn on(cases: &[PullOffCase]) -> Option<Gauge> {
        let loo = leave_one_out(cases);
        let e: Vec<f64> = loo.iter().flatten().copied().collect();
        Some(Gauge {
            coefficients: fit(cases)?,
            band_half_width: band_half_width(&e)?,
            leave_one_out: HeldOut::of(&loo),
            leave_thickness_out: HeldOut::of(&leave_thickness_out(cases)),
            band_held: band_held(cases),
            domain: Domain::of(cases),
        })
    }
}

/// The gauge on the stored table, fitted once.
pub fn gauge() -> Option<&'static Gauge> {
    static G: OnceLock<Option<Gauge>> = OnceLock::new();
    G.get_or_init(|| Gauge::on(table())).as_ref()
}

/// The gauged estimate of a scene's pull-off (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PullOffEstimate {
    /// The estimated pull-off p\* (≤ 0; null outside the measured range).
    pub pull_off_pressure: Option<f64>,
    /// The stated band [most tensile, least tensile] p\* (null outside or without adhesion).
    pub band: Option<[f64; 2]>,
    /// The band as a factor ×/÷ about the estimate.
    pub band_factor: Option<f64>,
    /// The share of held-out cases the band is built to hold.
    pub band_coverage: f64,
    /// (held, cases): how many stored cases, each left out, the band stated without them held.
    pub band_held: Option<[usize; 2]>,
    /// (a, b, c) of ln(−p\*) = a + b·ln γ̃_glo + c/(t·q_r), fitted on the stored cases.
    pub coefficients: Option<Coefficients>,
    /// How the form did on the stored cases each left out.
    pub held_out: Option<HeldOut>,
    /// Each way the scene lies outside the measured range (empty inside).
    pub outside: Vec<String>,
    /// One line for a table.
    pub summary: String,
}

/// Each way `scene`'s spectrum differs from system II's, in words (empty where it is the same
/// shape).
pub fn shape_outside(scene: &Scene) -> Vec<String> {
    let Spectrum::SelfAffine(s) = scene.spectrum() else {
        return vec![format!(
            "a {} spectrum, not system II's self-affine one",
            scene.spectrum().kind()
        )];
    };
    let Some(pre) = Preset::resolve("system-2").ok().and_then(|p| p.scene().ok()) else {
        return vec!["system II's preset did not resolve".into()];
    };
    let sp = pre.spectrum();
    let mut out = Vec::new();
    if let Spectrum::SelfAffine(p) = sp {
        if ((s.hurst - p.hurst) / p.hurst).abs() > SHAPE_REL {
            out.push(format!("Hurst exponent {:.3}, system II's is {:.3}", s.hurst, p.hurst));
        }
    }
    let (rl, rl0) = (scene.spectrum().q_r() / scene.spectrum().q_l(), sp.q_r() / sp.q_l());
    if (rl / rl0 - 1.0).abs() > SHAPE_REL {
        out.push(format!("L/λ_r {rl:.3}, system II's is {rl0:.3}"));
    }
    let bw = scene.spectrum().q_s() / scene.spectrum().q_r();
    if !(SET_BANDWIDTH / 1.5..=BANDWIDTH_MEASURED * 1.5).contains(&bw) {
        out.push(format!(
            "λ_r/λ_s {bw:.0}, system II was measured at {SET_BANDWIDTH:.0}…{BANDWIDTH_MEASURED:.0}"
        ));
    }
    out
}

/// The estimate of `scene`'s pull-off from the stored gauge.
pub fn estimate(scene: &Scene) -> PullOffEstimate {
    if !scene.is_adhesive() {
        return PullOffEstimate {
            pull_off_pressure: Some(0.0),
            band: None,
            band_factor: None,
            band_coverage: BAND_COVERAGE,
            band_held: None,
            coefficients: None,
            held_out: None,
            outside: Vec::new(),
            summary: "without adhesion no tension is held: pull-off 0".into(),
        };
    }
    let mut outside = shape_outside(scene);
    let Some(g) = gauge() else {
        outside.push("the stored cases give no gauge".into());
        return estimate_with(None, scene.gamma_glo(), scene.thickness_qr(), outside);
    };
    outside.extend(
        g.domain
            .outside(scene.gamma_glo(), scene.thickness_qr(), Some(scene.tabor())),
    );
    estimate_with(Some(g), scene.gamma_glo(), scene.thickness_qr(), outside)
}

/// The estimate at (γ̃_glo, t·q_r) from gauge `g`, with `outside` the ways the scene lies
/// outside its domain (a test builds `g` on cases with some left out).
pub fn estimate_with(g: Option<&Gauge>, gamma_glo: f64, thickness_qr: f64, outside: Vec<String>) -> PullOffEstimate {
    let coefficients = g.map(|g| g.coefficients);
    let held_out = g.map(|g| g.leave_one_out);
    let inside = outside.is_empty();
    let Some(g) = g.filter(|_| inside) else {
        return PullOffEstimate {
            pull_off_pressure: None,
            band: None,
            band_factor: None,
            band_coverage: BAND_COVERAGE,
            band_held: g.map(|g| g.band_held),
            coefficients,
            held_out,
            summary: format!("outside the measured range: no estimate ({})", outside.join("; ")),
            outside,
        };
    };
    let p = evaluate(&g.coefficients, gamma_glo, thickness_qr);
    let f = g.band_half_width.exp();
    let h = g.leave_one_out;
    PullOffEstimate {
        pull_off_pressure: Some(p),
        band: Some([p * f, p / f]),
        band_factor: Some(f),
        band_coverage: BAND_COVERAGE,
        band_held: Some(g.band_held),
        coefficients,
        held_out,
        outside,
        summary: format!(
            "gauged estimate {p:.2e} ×/÷ {f:.2} (a band that held {} of {} of GFMD's pull-offs left out); an empirical correlation in γ̃_glo and t·q_r fitted on GFMD's pull-offs of system II, each left out: mean |ln| {:.2}, {} of {} within 1.5×, worst {:.2}×",
            g.band_held[0],
            g.band_held[1],
            h.mean_abs_ln,
            h.within_1_5,
            h.cases,
            h.worst_factor
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_normal_equations_recover_an_exact_form() {
        // cases made from known coefficients: the fit returns them to round-off
        let want = [-3.0, 2.5, -0.2];
        let cases: Vec<PullOffCase> = table()
            .iter()
            .map(|c| PullOffCase {
                gfmd: (evaluate(&want, c.gamma_glo, c.thickness_qr), 0.0),
                ..*c
            })
            .collect();
        let got = fit(&cases).unwrap();
        for (g, w) in got.iter().zip(want) {
            assert!((g - w).abs() < 1e-9, "{got:?}");
        }
        assert!(fit(&cases[..2]).is_none());
    }

    #[test]
    fn the_band_is_the_jackknife_quantile() {
        // n = 9: ⌈0.9·10⌉ = 9, the largest; n = 8: ⌈8.1⌉ = 9 > 8, none
        let e: Vec<f64> = (1..=9).map(|i| -0.1 * i as f64).collect();
        assert_eq!(band_half_width(&e), Some(0.9));
        assert_eq!(band_half_width(&e[..8]), None);
    }
}
