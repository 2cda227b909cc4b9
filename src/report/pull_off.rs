//! The pull-off read-out, what `asperity run --pull-off` adds under `pull_off`, what
//! `asperity sweep --cycle` carries beside its cycle and Python's `pull_off()` returns: the
//! theory's pull-off p\*_c (≤ 0, in units of E\*ḡ) along GFMD's tensile path 0, −p₁, −2p₁, …
//! bisected to [`PULL_OFF_REL`] (physics.md §6.2), the two DMT routes' from the PSD alone
//! (Ciavarella's bearing-area model and the gap distribution's attraction after Persson &
//! Scaraggi, §6.3), GFMD's measured pull-off at the nearest stored case, and how far each was
//! measured from GFMD near the scene ([`crate::fit::pull_off_trust`]), and a gauged estimate of
//! GFMD's pull-off with the band it held on cases left out ([`crate::fit::pull_off_gauge`]).
//!
//! On the stored set the theory holds 0–4 % of GFMD's pull-off and the routes 6–420× of it
//! (§6.2–6.3): the read-out reports the three with those measured ratios and never as an
//! estimate with an error bar, which none of them has earned. The gauged estimate is the one
//! number with a band: an empirical correlation fitted on GFMD's pull-offs (§6.5), stated only
//! inside the range they cover.

use crate::error::Result;
use crate::fit::pull_off_gauge::{self, PullOffEstimate};
use crate::fit::pull_off_trust::{self, PullOffTrust};
use crate::fit::trust::{pull_off_reference, PullOffReference};
use crate::fit::trust_band::Place;
use crate::input::scene::Scene;
use crate::theory::adhesion::{pull_off as tensile_pull_off, AdhesionAccuracy};
use crate::theory::dmt::{pull_off_route, Route, RouteOptions};
use serde::Serialize;
use std::sync::atomic::AtomicBool;

pub use crate::theory::cycle::PULL_OFF_REL;

/// The first step of the tensile path when the caller has none: the smallest load of the
/// stored set's cycles (GFMD's tensile path starts from it).
pub const TENSILE_STEP: f64 = 1e-4;

/// The theory's pull-off as found along its tensile path.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TheoryPullOff {
    /// The most tensile p\* the contact branch held (≤ 0).
    pub pull_off_pressure: f64,
    /// (first load lost, last load held).
    pub pull_off_bracket: [f64; 2],
    /// The most tension any contact branch of the theory can hold (§6.2).
    pub tension_bound: f64,
}

/// The pull-off read-out (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PullOffReport {
    /// The theory's pull-off p\* (≤ 0; 0 where no tension is held).
    pub pull_off_pressure: f64,
    /// (first load lost, last load held) of the theory's tensile path.
    pub pull_off_bracket: [f64; 2],
    /// The most tension any contact branch of the theory can hold (p\*).
    pub tension_bound: f64,
    /// Ciavarella's bearing-area model's pull-off p\* (null where it did not converge).
    pub bam_pull_off_pressure: Option<f64>,
    /// The gap distribution's DMT pull-off p\* (null where it did not converge).
    pub gap_dmt_pull_off_pressure: Option<f64>,
    /// GFMD's measured pull-off at the nearest stored case (null where none is within reach).
    pub gfmd: Option<PullOffReference>,
    /// How far each was measured from GFMD near the scene.
    pub trust: PullOffTrust,
    /// The gauged estimate of GFMD's pull-off with its held-out band
    /// ([`crate::fit::pull_off_gauge`]; its value is null outside the measured range).
    pub estimate: PullOffEstimate,
    /// Why a route has no value, one line each.
    pub notes: Vec<String>,
}

/// The theory's pull-off of `scene` along the tensile path from `step`.
///
/// # Errors
/// As [`crate::theory::adhesion::pull_off`].
pub fn theory(scene: &Scene, step: f64, acc: &AdhesionAccuracy, cancel: Option<&AtomicBool>) -> Result<TheoryPullOff> {
    let po = tensile_pull_off(scene, step, PULL_OFF_REL, acc, cancel)?;
    Ok(TheoryPullOff {
        pull_off_pressure: po.pressure,
        pull_off_bracket: [po.lost, po.pressure],
        tension_bound: po.bound,
    })
}

/// The read-out of `scene` around the theory's pull-off `theory` (the routes are computed
/// here; a route that fails leaves its value null with a note).
pub fn read_out(scene: &Scene, theory: TheoryPullOff) -> PullOffReport {
    let mut notes = Vec::new();
    let mut route = |r: Route| {
        if !scene.is_adhesive() {
            return Some(0.0);
        }
        match pull_off_route(scene, r, &[], &RouteOptions::default()) {
            Ok(x) => Some(x.pull_off),
            Err(e) => {
                notes.push(format!("{}: {e}", r.name()));
                None
            }
        }
    };
    let bam = route(Route::BearingArea);
    let gap_dmt = route(Route::GapDistribution);
    let place = Place {
        p: scene.pressure(),
        gamma_glo: scene.gamma_glo(),
        thickness_qr: scene.thickness_qr(),
    };
    let adhesive = scene.is_adhesive();
    PullOffReport {
        pull_off_pressure: theory.pull_off_pressure,
        pull_off_bracket: theory.pull_off_bracket,
        tension_bound: theory.tension_bound,
        bam_pull_off_pressure: bam,
        gap_dmt_pull_off_pressure: gap_dmt,
        gfmd: adhesive.then(|| pull_off_reference(place)).flatten(),
        trust: pull_off_trust::assess(scene.thickness_qr(), scene.gamma_glo(), scene.model.number(), adhesive),
        estimate: pull_off_gauge::estimate(scene),
        notes,
    }
}

/// The whole read-out of `scene`: the theory's pull-off from [`TENSILE_STEP`], then
/// [`read_out`].
///
/// # Errors
/// As [`theory`].
pub fn pull_off(scene: &Scene, acc: &AdhesionAccuracy, cancel: Option<&AtomicBool>) -> Result<PullOffReport> {
    let t = theory(scene, TENSILE_STEP, acc, cancel)?;
    Ok(read_out(scene, t))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::preset::Preset;

    #[test]
    fn a_thin_adhesive_slab_reads_all_three_with_gfmds_nearest() {
        let scene = Preset::resolve("system-2")
            .unwrap()
            .scene()
            .unwrap()
            .with_thickness_qr(0.3)
            .unwrap();
        let r = pull_off(&scene, &AdhesionAccuracy::default(), None).unwrap();
        assert!(r.pull_off_pressure <= 0.0 && r.pull_off_pressure >= -r.tension_bound);
        // both DMT routes hold tension on this slab (§6.3)
        assert!(r.bam_pull_off_pressure.unwrap() < 0.0 && r.gap_dmt_pull_off_pressure.unwrap() < 0.0);
        assert!(r.gfmd.is_some() && r.trust.known, "{:?}", r.trust);
        let lines = super::super::csv::pull_off_comments(&r);
        assert!(lines.contains("# bam_pull_off_pressure: -") && lines.contains("# pull_off_trust: model"));
    }

    #[test]
    fn without_adhesion_everything_is_zero() {
        let scene = Preset::resolve("system-2")
            .unwrap()
            .scene()
            .unwrap()
            .with_surface_energy_j_m2(0.0)
            .unwrap();
        let r = pull_off(&scene, &AdhesionAccuracy::default(), None).unwrap();
        assert_eq!(r.pull_off_pressure, 0.0);
        assert_eq!(
            (r.bam_pull_off_pressure, r.gap_dmt_pull_off_pressure),
            (Some(0.0), Some(0.0))
        );
        assert!(r.gfmd.is_none() && !r.trust.known);
    }
}
