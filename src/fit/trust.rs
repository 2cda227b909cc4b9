//! How far to trust the theory for a scene: where the scene lies relative to asperity's GFMD
//! reference set ([`super::reference_set`]) and how far the theory was measured from brute
//! force at the scene's own load, at the stored cases nearest it ([`super::trust_band`]).
//!
//! Inside the set means p* and t·q_r inside the ranges the set covers and γ̃_glo at most its
//! largest; outside, each excess is named ("p* 1e-06 is 2.0 decades below the set's 1e-5").
//!
//! The error read-out is the band of [`super::trust_band`]: each of the nearest cases'
//! ln(a_r theory / a_r GFMD) interpolated in log p* to the scene's load (never a point more
//! than [`super::trust_band::LOAD_REACH`] decades away), GFMD's own standard error added, and
//! GFMD's finite-size error where the finite-size study measured it. Where fewer than
//! [`super::trust_band::MIN_CASES`] cases have a value at the load, the read-out says
//! "no error known" (`known` false, the error fields NaN: null in JSON) instead.
//!
//! The theory columns are those of the scene's model where the set holds them (model 5 on
//! system II has its own), else the set's (the preset's model: 4 for system II, 3 for system
//! I), labelled with the model they were measured for.
//!
//! An adhesive model 5 scene whose bandwidth λ_r/λ_s is nearer the full system's 128 than the
//! set's 16 (above √(16·128) ≈ 45) reads its error from the bandwidth set instead: model 5 on
//! the full system II against the widest GFMD of each case (1024², λ_r/λ_s = 64; 2048² for the
//! half-space at the preset's γ_s), a_r only, at p* = 10⁻³…10⁻². Below those loads it falls back
//! to the set's 256² columns and says at which bandwidth they were measured.

use super::reference_set::{bandwidth_set, combined_set, reference_set, ReferencePoint, MODELS, SET_GRID};
use super::trust_band::{band, CaseError, Place, TheoryOf, LOAD_REACH, MIN_CASES};
use crate::input::scene::Scene;
use crate::theory::cycle::PathBranch;
use serde::Serialize;
use std::sync::OnceLock;

/// Cases the error read-out averages over.
pub const NEAREST: usize = super::trust_band::NEAREST;

/// The ranges the reference set covers.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SetRange {
    /// Smallest and largest positive p* stored.
    pub pressure: [f64; 2],
    /// Thinnest slab stored (t·q_r); the set also holds the half-space.
    pub thickness_qr_min: f64,
    /// Largest γ̃_glo stored.
    pub gamma_glo_max: f64,
    /// Grid side of the stored maps.
    pub grid: usize,
}

/// One stored case near the scene, with the theory's error there, at the scene's load.
pub type NearPoint = CaseError;

/// Where a scene lies relative to the reference set and the theory's measured error near it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Trust {
    /// Inside the set's ranges.
    pub inside: bool,
    /// Each way the scene lies outside, in words (empty inside).
    pub outside: Vec<String>,
    /// The set's ranges.
    pub set: SetRange,
    /// Whether an error is known at the scene's load (see the module docs).
    pub known: bool,
    /// The cases the error is read from, nearest first, at the scene's load.
    pub nearest: Vec<NearPoint>,
    /// The model whose error was measured there.
    pub measured_model: u8,
    /// Whether that is the scene's model.
    pub same_model: bool,
    /// Mean |ln(theory/GFMD)| of a_r over the cases (NaN where unknown).
    pub a_r_log_error: f64,
    /// Largest theory/GFMD (or GFMD/theory) ratio of a_r among them (NaN where unknown).
    pub a_r_worst_ratio: f64,
    /// The band: GFMD's a_r lies within this factor of the theory's, as far as the cases tell
    /// (their worst error, GFMD's standard error and, where measured, its finite-size error;
    /// NaN where unknown).
    pub a_r_band_ratio: f64,
    /// GFMD's finite-size error in ln a_r at this load (null where not measured).
    pub finite_size_log_error: Option<f64>,
    /// Where the error is read off the set's narrower maps for a wider scene: the error of
    /// that transfer added to the band ([`bandwidth_transfer_error`]; null where not added).
    pub bandwidth_log_error: Option<f64>,
    /// Mean |ln(theory/GFMD)| of ū/h_rms (null where no case has a theory gap).
    pub mean_gap_log_error: Option<f64>,
    /// GFMD's pull-off at the measured case nearest an adhesive scene (null without adhesion
    /// or where no case is within reach): the number to hold the theory's pull-off against.
    pub pull_off: Option<PullOffReference>,
    /// One line for a table.
    pub summary: String,
}

/// The ranges of the stored set.
pub fn set_range() -> SetRange {
    let set = combined_set();
    let pos = set.iter().filter(|r| r.p > 0.0);
    let (lo, hi) = pos
        .clone()
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), r| (lo.min(r.p), hi.max(r.p)));
    SetRange {
        pressure: [lo, hi],
        thickness_qr_min: set.iter().map(|r| r.thickness_qr).fold(f64::INFINITY, f64::min),
        gamma_glo_max: set
            .iter()
            .map(|r| r.gamma_glo)
            .filter(|g| g.is_finite())
            .fold(0.0, f64::max),
        grid: SET_GRID,
    }
}

/// Each way `scene` lies outside the set's ranges, in words.
fn outside_lines(scene: &Scene, set: &SetRange) -> Vec<String> {
    let (p, t, glo) = (scene.pressure(), scene.thickness_qr(), scene.gamma_glo());
    let mut outside = Vec::new();
    if p < set.pressure[0] {
        outside.push(format!(
            "p* {p:.3e} is {:.1} decades below the set's {:.0e}",
            (set.pressure[0] / p).log10(),
            set.pressure[0]
        ));
    } else if p > set.pressure[1] {
        outside.push(format!(
            "p* {p:.3e} is {:.1} decades above the set's {:.0e}",
            (p / set.pressure[1]).log10(),
            set.pressure[1]
        ));
    }
    if t < set.thickness_qr_min {
        outside.push(format!(
            "t·q_r {t:.3} is thinner than the set's {}",
            set.thickness_qr_min
        ));
    }
    if glo > set.gamma_glo_max {
        outside.push(format!(
            "γ̃_glo {glo:.3} is above the set's largest {:.3}",
            set.gamma_glo_max
        ));
    }
    if let Some(line) = model_five_bandwidth(scene) {
        outside.push(line);
    }
    outside
}

/// The theory column a scene's model reads at a stored point: the model's own where the point
/// has it (the small-load set holds models 1–5; the 256² set model 5's), else the set's.
pub fn theory_column(model: Option<u8>) -> impl Fn(&ReferencePoint) -> Option<(f64, f64, u8)> {
    let five = model == Some(5);
    move |r: &ReferencePoint| {
        let own = model
            .filter(|m| (1..=MODELS as u8).contains(m))
            .map(|m| (m, r.theory_models[m as usize - 1]))
            .filter(|(_, (a, _))| *a > 0.0);
        if let Some((m, (a, u))) = own {
            Some((a, u, m))
        } else if five && r.theory5_a_r > 0.0 {
            Some((r.theory5_a_r, r.theory5_mean_gap_rel, 5))
        } else {
            (r.theory_a_r > 0.0).then_some((r.theory_a_r, r.theory_mean_gap_rel, r.theory_model))
        }
    }
}

/// The trust read-out of `scene` (see the module docs).
pub fn assess(scene: &Scene) -> Trust {
    let set = set_range();
    let outside = outside_lines(scene, &set);
    let place = Place {
        p: scene.pressure(),
        gamma_glo: scene.gamma_glo(),
        thickness_qr: scene.thickness_qr(),
    };
    let five = scene.model().kind == crate::input::model::ModelKind::Five;
    let theory = theory_column(scene.model.number());
    let bw = scene.spectrum().q_s() / scene.spectrum().q_r();
    let wide_scene = five && scene.is_adhesive() && bw.is_finite() && bw > WIDE_BANDWIDTH;
    let set_points: Vec<&ReferencePoint> = combined_set().iter().collect();
    let mut wide = false;
    let (mut band, finite_size_log_error) = stated_band(&set_points, place, scene.model.number());
    if wide_scene {
        let mut widest = band_of_widest(place, &theory);
        if widest.known {
            widest.half_width += finite_size_log_error.unwrap_or(0.0);
            band = widest;
            wide = true;
        }
    }
    // read off the set's narrower maps: add the error of that transfer, measured where both exist
    let narrow_read = !wide && bw.is_finite() && bw > 1.5 * SET_BANDWIDTH;
    let bandwidth_log_error = (band.known && narrow_read).then(|| bandwidth_transfer_error(five));
    band.half_width += bandwidth_log_error.unwrap_or(0.0);
    let logs: Vec<f64> = band.cases.iter().map(|c| c.log_error().abs()).collect();
    let nan_unless = |x: f64| if band.known { x } else { f64::NAN };
    let a_r_log_error = nan_unless(logs.iter().sum::<f64>() / logs.len().max(1) as f64);
    let a_r_worst_ratio = nan_unless(logs.iter().cloned().fold(0.0, f64::max).exp());
    let a_r_band_ratio = nan_unless(band.half_width.exp());
    let gaps: Vec<f64> = band
        .cases
        .iter()
        .filter_map(|n| n.mean_gap_rel_theory.map(|g| (g / n.mean_gap_rel_gfmd).ln().abs()))
        .collect();
    let mean_gap_log_error = (band.known && !gaps.is_empty()).then(|| gaps.iter().sum::<f64>() / gaps.len() as f64);
    let default_model = if five { 5 } else { 4 };
    let measured_model = band.cases.first().map_or(default_model, |c| c.model);
    let same_model = scene.model.number() == Some(measured_model);
    let error = Error {
        known: band.known,
        p: place.p,
        model: measured_model,
        same_model,
        mean: a_r_log_error,
        band: a_r_band_ratio,
        finite_size: finite_size_log_error.is_some(),
        gap: mean_gap_log_error,
    };
    let mut summary = summary(&outside, &error);
    // the set's maps are narrower than most scenes: say at which bandwidth it was measured
    if band.known && wide {
        summary += " (model 5 on the full system II against GFMD at λ_r/λ_s = 64–128)";
    } else if let Some(b) = bandwidth_log_error {
        summary += &format!(
            " (measured on the set's maps, λ_r/λ_s = {SET_BANDWIDTH:.0}; this scene has {bw:.0}: the band adds ×/÷ {:.2} for that)",
            b.exp()
        );
    }
    Trust {
        inside: outside.is_empty(),
        outside,
        set,
        known: band.known,
        nearest: band.cases,
        measured_model,
        same_model,
        a_r_log_error,
        a_r_worst_ratio,
        a_r_band_ratio,
        finite_size_log_error,
        bandwidth_log_error,
        mean_gap_log_error,
        pull_off: scene.is_adhesive().then(|| pull_off_reference(place)).flatten(),
        summary,
    }
}

/// GFMD's measured pull-off near a scene.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PullOffReference {
    /// t·q_r of the case (null: a half-space).
    pub thickness_qr: Option<f64>,
    /// γ_s of the case over the preset's.
    pub gamma_factor: f64,
    /// γ̃_glo of the case.
    pub gamma_glo: f64,
    /// GFMD's pull-off p* (mean over the maps, ≤ 0).
    pub pull_off_pressure: f64,
    /// Its standard error over the maps (null with one map).
    pub pull_off_pressure_err: Option<f64>,
    /// Maps averaged.
    pub seeds: usize,
    /// Distance of the case from the scene (units of [`super::trust_band`]).
    pub distance: f64,
}

/// The measured case nearest `place` within [`super::trust_band::CASE_REACH`], from the
/// small-load set's cycles where it holds the case, else the 256² set's.
pub fn pull_off_reference(place: Place) -> Option<PullOffReference> {
    use super::reference_set::{pull_offs, small_load_holds, small_load_pull_offs};
    use super::trust_band::{case_distance, CASE_REACH};
    small_load_pull_offs()
        .iter()
        .chain(
            pull_offs()
                .iter()
                .filter(|r| !small_load_holds(r.system, r.thickness_qr, r.gamma_factor)),
        )
        .filter(|r| r.gamma_factor > 0.0 && r.pressure.0.is_finite())
        .map(|r| (case_distance(place, r.thickness_qr, r.gamma_glo), r))
        .filter(|(d, _)| *d <= CASE_REACH)
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(distance, r)| PullOffReference {
            thickness_qr: r.thickness_qr.is_finite().then_some(r.thickness_qr),
            gamma_factor: r.gamma_factor,
            gamma_glo: r.gamma_glo,
            pull_off_pressure: r.pressure.0,
            pull_off_pressure_err: r.pressure.1.is_finite().then_some(r.pressure.1),
            seeds: r.seeds,
            distance,
        })
}

/// Quantile of the transfer errors taken as the band's bandwidth term.
pub const TRANSFER_QUANTILE: f64 = 0.9;

/// The error of reading a wider scene's error off the set's λ_r/λ_s = 16 maps: over the
/// bandwidth set's widest rows that the 256² set also holds (adhesive system II, loading,
/// p* = 10⁻³…10⁻²), the [`TRANSFER_QUANTILE`] quantile of |e_wide − e_16|, e = ln(theory/GFMD):
/// for model 5 its full-system column against the widest GFMD; for the other models model 4's
/// columns on each map (the only other model the bandwidth set holds).
pub fn bandwidth_transfer_error(five: bool) -> f64 {
    static CACHE: OnceLock<[f64; 2]> = OnceLock::new();
    CACHE.get_or_init(|| [transfer_quantile(false), transfer_quantile(true)])[usize::from(five)]
}

fn transfer_quantile(five: bool) -> f64 {
    let narrow = reference_set();
    let column = |r: &ReferencePoint| if five { r.theory5_a_r } else { r.theory_a_r };
    let mut d: Vec<f64> = widest_rows(bandwidth_set())
        .into_iter()
        .filter(|w| w.branch == PathBranch::Loading && column(w) > 0.0)
        .filter_map(|w| {
            let n = narrow.iter().find(|n| {
                n.system == w.system
                    && n.branch == PathBranch::Loading
                    && n.thickness_qr == w.thickness_qr
                    && n.gamma_factor == w.gamma_factor
                    && (n.p / w.p - 1.0).abs() < 1e-6
            })?;
            let e16 = (column(n) / n.a_r.0).ln();
            let ewide = (column(w) / w.a_r.0).ln();
            (e16.is_finite() && ewide.is_finite()).then_some((ewide - e16).abs())
        })
        .collect();
    d.sort_by(f64::total_cmp);
    d.get(((d.len() as f64 * TRANSFER_QUANTILE) as usize).min(d.len().saturating_sub(1)))
        .copied()
        .unwrap_or(0.0)
}

/// The band the read-out states at `place` from `points` for `model`'s columns: the
/// neighbouring cases' band ([`super::trust_band::band`]) widened by GFMD's finite-size error
/// where it was measured (returned beside it).
pub fn stated_band(
    points: &[&ReferencePoint],
    place: Place,
    model: Option<u8>,
) -> (super::trust_band::Band, Option<f64>) {
    let theory = theory_column(model);
    let mut b = band(points, place, &theory);
    let finite = finite_size_error(place);
    if b.known {
        b.half_width += finite.unwrap_or(0.0);
    }
    (b, finite)
}

/// The band over the bandwidth set's widest rows (model 5 on the full system).
fn band_of_widest(place: Place, theory: &TheoryOf) -> super::trust_band::Band {
    let widest = widest_rows(bandwidth_set());
    band(&widest, place, theory)
}

/// GFMD's finite-size error in ln a_r at the place, where the finite-size study measured it.
fn finite_size_error(place: Place) -> Option<f64> {
    super::finite_size::log_error(place)
}

/// Above this λ_r/λ_s an adhesive model 5 scene reads its error from the bandwidth set (see
/// the module docs): √(16·128), the midpoint in octaves of the set's and the full system's.
pub const WIDE_BANDWIDTH: f64 = 45.254_833_995_939_04;

/// The rows of each case's widest grid.
fn widest_rows(rows: &[ReferencePoint]) -> Vec<&ReferencePoint> {
    let widest = |r: &ReferencePoint| {
        rows.iter()
            .filter(|o| o.thickness_qr == r.thickness_qr && o.gamma_factor == r.gamma_factor)
            .map(|o| o.grid)
            .max()
            .unwrap_or(0)
    };
    rows.iter().filter(|r| r.grid == widest(r)).collect()
}

/// The bandwidth λ_r/λ_s of the set's grid (256² at L/λ_r = 2, λ_s/Δa = 8).
pub const SET_BANDWIDTH: f64 = crate::input::model_five::SET_BANDWIDTH;

/// Model 5's gauge was measured over λ_r/λ_s from [`SET_BANDWIDTH`] to
/// [`crate::input::model_five::BANDWIDTH_MEASURED`] (physics.md §3.6); on a scene whose
/// bandwidth q_s/q_r is more than 1.5× outside that range, one line saying so (the gauge is
/// held at its value at the nearer end).
fn model_five_bandwidth(scene: &Scene) -> Option<String> {
    use crate::input::model_five::BANDWIDTH_MEASURED;
    if scene.model().kind != crate::input::model::ModelKind::Five || !scene.is_adhesive() {
        return None;
    }
    let bw = scene.spectrum().q_s() / scene.spectrum().q_r();
    let outside = !(SET_BANDWIDTH / 1.5..=BANDWIDTH_MEASURED * 1.5).contains(&bw);
    (outside && bw.is_finite()).then(|| {
        format!(
            "model 5 was gauged against GFMD at λ_r/λ_s = {SET_BANDWIDTH:.0} to {BANDWIDTH_MEASURED:.0}, this scene has {bw:.0}: its gauge is held at the nearer end and was not checked there"
        )
    })
}

/// What the summary line says of the error.
struct Error {
    known: bool,
    p: f64,
    model: u8,
    same_model: bool,
    mean: f64,
    band: f64,
    finite_size: bool,
    gap: Option<f64>,
}

fn summary(outside: &[String], e: &Error) -> String {
    let place = if outside.is_empty() {
        "inside the GFMD reference set".to_string()
    } else {
        format!("outside the GFMD reference set: {}", outside.join("; "))
    };
    if !e.known {
        return format!(
            "{place}; outside the measured range: no error known (fewer than {MIN_CASES} reference cases within reach have GFMD within {LOAD_REACH} decades of p* = {:.3e})",
            e.p
        );
    }
    let gap = e.gap.map_or(String::new(), |g| {
        format!(", mean gap off by {:.0} %", 100.0 * (g.exp() - 1.0))
    });
    let whose = if e.same_model {
        format!("model {}", e.model)
    } else {
        format!("model {} (not this scene's model)", e.model)
    };
    let parts = if e.finite_size {
        "their worst error, GFMD's standard error and finite size"
    } else {
        "their worst error and GFMD's standard error"
    };
    format!(
        "{place}; {whose} vs GFMD at this load at the {} nearest cases: a_r off by {:.0} % on average, within ×/÷ {:.2} ({parts}){gap}",
        NEAREST,
        100.0 * (e.mean.exp() - 1.0),
        e.band
    )
}
