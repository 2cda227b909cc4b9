//! The error band of the trust read-out ([`super::trust`]): how far the theory was measured
//! from GFMD at a scene's own load, at the stored cases nearest the scene, and whether that is
//! known at all.
//!
//! **Where.** A scene is placed by p\* and, for the case, by two numbers that carry its
//! thickness and surface energy: the thinness τ = log₁₀(1 + 1/(t·q_r)) (0 for a half-space,
//! 1.04 at t·q_r = 0.1) and the adhesion ℓ = log₂(γ̃_glo + γ̃₀) with γ̃₀ = [`GLO_FLOOR`]
//! (γ̃_glo [S-24]; one unit per doubling, smooth through γ̃_glo = 0). A case's distance from the
//! scene is √(Δτ² + Δℓ²): one step of the set (a thickness, γ_s × 2) is 0.1–1 unit.
//!
//! **At the scene's load.** Each case's stored loading points are interpolated in log p\*:
//! ln a_r of GFMD and of the theory, and GFMD's relative standard error, linearly in log₁₀p\*
//! between the two stored loads that bracket p\*. Beyond a case's first or last stored load
//! by at most [`LOAD_REACH`] decades the end point is used; farther, the case says nothing
//! about the scene (it is not used, rather than quoted a decade away).
//!
//! **The band.** Over the [`NEAREST`] nearest cases within [`CASE_REACH`] that have a value
//! at the load: e_c = ln(a_r theory / a_r GFMD) and s_c GFMD's relative standard error. The
//! band's half-width in ln a_r is
//!
//! ```text
//! B = max_c (|e_c| + SE_WEIGHT·s_c) + f,
//! ```
//!
//! ([`SE_WEIGHT`]), f the finite-size error of GFMD's reduced maps where it was measured (0 where not; the
//! caller adds it). The theory's a_r is then within a factor e^B of GFMD's, as far as the
//! neighbours tell. With fewer than [`MIN_CASES`] cases no error is known: the read-out says
//! so instead of quoting far points.

use super::reference_set::ReferencePoint;
use crate::theory::cycle::PathBranch;
use serde::Serialize;
use std::collections::BTreeMap;

/// Cases the band takes at most.
pub const NEAREST: usize = 4;
/// Cases needed for an error to be known.
pub const MIN_CASES: usize = 2;
/// Largest case distance used (units of the module docs).
pub const CASE_REACH: f64 = 1.5;
/// How far beyond a case's stored loads (decades of p\*) its end point still stands for it:
/// below one step of the set's loads (⅓ decade).
pub const LOAD_REACH: f64 = 0.25;
/// Standard errors of GFMD's mean added to the band (two: a 95 % interval of the mean).
pub const SE_WEIGHT: f64 = 2.0;
/// γ̃₀ of the adhesion coordinate: below it γ̃_glo hardly moves the theory's error (system I's
/// γ̃_glo is 0.024, system II's half-space 0.1).
pub const GLO_FLOOR: f64 = 0.025;

/// Where the band is asked: the scene's p\* and its case coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Place {
    /// p\* (positive).
    pub p: f64,
    /// γ̃_glo of the scene.
    pub gamma_glo: f64,
    /// t·q_r (∞ for a half-space).
    pub thickness_qr: f64,
}

impl Place {
    fn coords(&self) -> (f64, f64) {
        coords(self.thickness_qr, self.gamma_glo)
    }
}

/// Distance of a case (t·q_r, γ̃_glo) from `place` in the coordinates of the module docs.
pub(crate) fn case_distance(place: Place, t: f64, glo: f64) -> f64 {
    let ((tau, ell), (ct, cl)) = (place.coords(), coords(t, glo));
    ((ct - tau).powi(2) + (cl - ell).powi(2)).sqrt()
}

pub(crate) fn coords(t: f64, glo: f64) -> (f64, f64) {
    let glo = if glo.is_finite() { glo.max(0.0) } else { 0.0 };
    ((1.0 + 1.0 / t).log10(), (glo + GLO_FLOOR).log2())
}

/// One case's measured error at the place's load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CaseError {
    /// System of \[S\] (1 or 2).
    pub system: u8,
    /// t·q_r (null: a half-space).
    pub thickness_qr: Option<f64>,
    /// γ_s of the case over the preset's.
    pub gamma_factor: f64,
    /// γ̃_glo of the case.
    pub gamma_glo: f64,
    /// The load the values are at: the scene's p\*, or the case's nearest stored load when
    /// the scene's lies just beyond the case's range (within [`LOAD_REACH`]).
    pub p: f64,
    /// GFMD's a_r there (interpolated in log p\*).
    pub a_r_gfmd: f64,
    /// The theory's a_r on the same maps there.
    pub a_r_theory: f64,
    /// GFMD's ū/h_rms there.
    pub mean_gap_rel_gfmd: f64,
    /// The theory's ū/h_rms there (null where it has none).
    pub mean_gap_rel_theory: Option<f64>,
    /// GFMD's relative standard error of a_r there (0 where one seed).
    pub a_r_rel_se: f64,
    /// Distance of the case from the scene.
    pub distance: f64,
    /// The model whose error this is.
    pub model: u8,
}

impl CaseError {
    /// ln(theory/GFMD) of a_r.
    pub fn log_error(&self) -> f64 {
        (self.a_r_theory / self.a_r_gfmd).ln()
    }
}

/// The band at a place.
#[derive(Debug, Clone, PartialEq)]
pub struct Band {
    /// The cases used, nearest first.
    pub cases: Vec<CaseError>,
    /// Whether at least [`MIN_CASES`] cases had a value at the load.
    pub known: bool,
    /// B without the finite-size term (see the module docs); 0 where unknown.
    pub half_width: f64,
}

/// The theory's value at a stored point for the model asked: (a_r, ū/h_rms, model), or None
/// where the point has no theory value for it.
pub type TheoryOf<'a> = dyn Fn(&ReferencePoint) -> Option<(f64, f64, u8)> + 'a;

/// The band at `place` from `points` (any subset of the stored sets), reading the theory with
/// `theory`.
pub fn band(points: &[&ReferencePoint], place: Place, theory: &TheoryOf) -> Band {
    let mut cases: Vec<CaseError> = group(points)
        .into_values()
        .filter_map(|rows| {
            let distance = case_distance(place, rows[0].thickness_qr, rows[0].gamma_glo);
            if distance > CASE_REACH {
                return None;
            }
            at_load(&rows, place.p, theory).map(|mut c| {
                c.distance = distance;
                c
            })
        })
        .collect();
    cases.sort_by(|a, b| a.distance.total_cmp(&b.distance));
    cases.truncate(NEAREST);
    let known = cases.len() >= MIN_CASES;
    let half_width = if known {
        cases
            .iter()
            .map(|c| c.log_error().abs() + SE_WEIGHT * c.a_r_rel_se)
            .fold(0.0, f64::max)
    } else {
        0.0
    };
    Band {
        cases,
        known,
        half_width,
    }
}

fn positive(x: f64) -> bool {
    x > 0.0
}

/// The loading points of each case, sorted by p\*.
fn group<'a>(points: &[&'a ReferencePoint]) -> BTreeMap<(u8, u64, u64, usize), Vec<&'a ReferencePoint>> {
    let mut cases: BTreeMap<_, Vec<&ReferencePoint>> = BTreeMap::new();
    for r in points {
        if r.branch != PathBranch::Loading || !positive(r.p) || !positive(r.a_r.0) {
            continue;
        }
        let key = (r.system, r.thickness_qr.to_bits(), r.gamma_factor.to_bits(), r.grid);
        cases.entry(key).or_default().push(r);
    }
    for rows in cases.values_mut() {
        rows.sort_by(|a, b| a.p.total_cmp(&b.p));
    }
    cases
}

/// One case's values at load `p` (see the module docs), None where it has none there.
/// A stored point with the theory's (a_r, ū/h_rms, model) there.
type WithTheory<'a> = (&'a ReferencePoint, (f64, f64, u8));

fn at_load(rows: &[&ReferencePoint], p: f64, theory: &TheoryOf) -> Option<CaseError> {
    let rows: Vec<WithTheory> = rows
        .iter()
        .filter_map(|r| theory(r).filter(|t| t.0 > 0.0).map(|t| (*r, t)))
        .collect();
    let (first, last) = (rows.first()?, rows.last()?);
    let x = p.log10();
    let (lo, hi, w, at) = if p <= first.0.p {
        ((first.0.p / p).log10() <= LOAD_REACH).then_some((first, first, 0.0, first.0.p))?
    } else if p >= last.0.p {
        ((p / last.0.p).log10() <= LOAD_REACH).then_some((last, last, 0.0, last.0.p))?
    } else {
        let i = rows.iter().position(|r| r.0.p >= p)?;
        let (a, b) = (&rows[i - 1], &rows[i]);
        let w = (x - a.0.p.log10()) / (b.0.p.log10() - a.0.p.log10());
        (a, b, w, p)
    };
    let lerp = |f: &dyn Fn(&WithTheory) -> f64| (1.0 - w) * f(lo) + w * f(hi);
    let rel_se = |r: &ReferencePoint| {
        let s = r.a_r.1 / r.a_r.0;
        if s.is_finite() {
            s
        } else {
            0.0
        }
    };
    let gap_theory = lerp(&|r| r.1 .1.ln());
    Some(CaseError {
        system: lo.0.system,
        thickness_qr: lo.0.thickness_qr.is_finite().then_some(lo.0.thickness_qr),
        gamma_factor: lo.0.gamma_factor,
        gamma_glo: lo.0.gamma_glo,
        p: at,
        a_r_gfmd: lerp(&|r| r.0.a_r.0.ln()).exp(),
        a_r_theory: lerp(&|r| r.1 .0.ln()).exp(),
        mean_gap_rel_gfmd: lerp(&|r| r.0.mean_gap_rel.0.ln()).exp(),
        mean_gap_rel_theory: gap_theory.is_finite().then(|| gap_theory.exp()),
        a_r_rel_se: lerp(&|r| rel_se(r.0)),
        distance: 0.0,
        model: lo.1 .2,
    })
}
