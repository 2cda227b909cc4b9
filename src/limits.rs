//! The allowed values of every user-settable field in one place: what a front end states when
//! it refuses a value (a flag that does not parse, a preset key out of range), built from the
//! same constants the library's own checks use.
//!
//! [`allowed`] gives the range of a field on its own. Some checks relate fields to each other
//! (W(a) ≥ 0 needs c₁ and c₂ together; a sweep's last value above its first; a GFMD grid that
//! keeps λ_r > λ_s); those are made where the fields meet and name the field the user set.

use crate::error::{Allowed, Field, Range};
use crate::gfmd::problem::{BINS_RANGE, CONTACT_GAP_RANGE, MAX_ITERATIONS_RANGE, TOLERANCE_RANGE};
use crate::input::model::{ALPHA_RANGE, C_RANGE, K_GRIFFITH_RANGE, MODEL_CHOICES};
use crate::input::scene::{thickness_allowed, MODULUS_RANGE_PA, PRESSURE_RANGE, RANGE_RANGE_M, SURFACE_ENERGY_RANGE};
use crate::surface::heightmap::MAX_GRID;
use crate::surface::spectrum::{HURST_RANGE, LENGTH_RANGE_M, RMS_GRADIENT_RANGE, RMS_HEIGHT_RANGE_M};
use crate::theory::adhesion::{ADHESION_POINTS_RANGE, ADHESION_STEPS_RANGE, ADHESION_TOL_RANGE};
use crate::theory::engine::{EDGE_REL_RANGE, RTOL_RANGE, SIGMA_MAX_RANGE, SIGMA_POINTS_RANGE, SWEEP_STEP_RANGE};

fn closed((lo, hi): (f64, f64)) -> Allowed {
    Allowed::Range(Range::closed(lo, hi))
}

fn whole((lo, hi): (usize, usize)) -> Allowed {
    Allowed::Range(Range::whole(lo as f64, hi as f64))
}

/// The values `field` accepts on its own, or `None` where they depend on another field (a
/// sweep's ends depend on the swept knob) or are not numbers (a height map).
///
/// # Examples
/// ```
/// use asperity::error::Field;
/// let a = asperity::limits::allowed(&Field::Pressure).unwrap();
/// assert_eq!(a.describe("p*"), "1e-12 <= p* <= 1000");
/// assert!(a.range().unwrap().contains(0.01));
/// ```
pub fn allowed(field: &Field) -> Option<Allowed> {
    Some(match field {
        Field::SystemSize | Field::RolloffWavelength | Field::ShortWavelength => closed(LENGTH_RANGE_M),
        Field::Hurst => closed(HURST_RANGE),
        Field::RmsGradient => closed(RMS_GRADIENT_RANGE),
        Field::RmsHeight => closed(RMS_HEIGHT_RANGE_M),
        Field::ContactModulus => closed(MODULUS_RANGE_PA),
        Field::SurfaceEnergy => closed(SURFACE_ENERGY_RANGE),
        Field::Range => closed(RANGE_RANGE_M),
        Field::Pressure => closed(PRESSURE_RANGE),
        Field::PressurePa => Allowed::Range(Range::above(0.0)),
        Field::Thickness => thickness_allowed(),
        Field::Model => Allowed::choices(MODEL_CHOICES),
        Field::C1 | Field::C2 => Allowed::Range(C_RANGE),
        Field::Alpha => Allowed::Range(ALPHA_RANGE),
        Field::KGriffith => Allowed::Range(K_GRIFFITH_RANGE),
        Field::Rtol => closed(RTOL_RANGE),
        Field::AdhesionSteps => closed(ADHESION_STEPS_RANGE),
        Field::AdhesionPoints => closed(ADHESION_POINTS_RANGE),
        Field::AdhesionTol => closed(ADHESION_TOL_RANGE),
        Field::SigmaMax => closed(SIGMA_MAX_RANGE),
        Field::SigmaPoints => Allowed::Range(Range::whole(SIGMA_POINTS_RANGE.0 as f64, SIGMA_POINTS_RANGE.1 as f64)),
        Field::SweepStep => closed(SWEEP_STEP_RANGE),
        Field::EdgeRel => closed(EDGE_REL_RANGE),
        Field::Grid => Allowed::Range(Range::whole(4.0, MAX_GRID as f64)),
        Field::SweepPoints => Allowed::Range(Range::whole(
            crate::theory::sweep::SWEEP_POINTS_RANGE.0 as f64,
            crate::theory::sweep::SWEEP_POINTS_RANGE.1 as f64,
        )),
        Field::GfmdTolerance => Allowed::Range(TOLERANCE_RANGE),
        Field::MaxIterations => Allowed::Range(MAX_ITERATIONS_RANGE),
        Field::Bins => Allowed::Range(BINS_RANGE),
        Field::ContactGap => Allowed::Range(CONTACT_GAP_RANGE),
        Field::Seeds => Allowed::Range(Range::whole(1.0, MAX_SEEDS as f64)),
        Field::Ladder => closed(LADDER_RANGE),
        Field::Seed => Allowed::Range(Range::whole(0.0, u64::MAX as f64)),
        Field::FudgeGamma => Allowed::Range(Range::open_closed(
            crate::input::model::FUDGE_GAMMA_RANGE.0,
            crate::input::model::FUDGE_GAMMA_RANGE.1,
        )),
        Field::QMin | Field::QMax => Allowed::Range(Range::above(0.0)),
        Field::BinsPerDecade => closed(crate::surface::psd::BINS_PER_DECADE_RANGE),
        Field::FigurePoints => whole(FIGURE_POINTS_RANGE),
        Field::ChartWidth => whole(CHART_WIDTH_RANGE),
        Field::ChartHeight => whole(CHART_HEIGHT_RANGE),
        Field::GfmdSizeRatio | Field::GfmdBandwidth | Field::GfmdPointsPerShortWavelength => {
            whole(GFMD_REDUCTION_RANGE)
        }
        Field::TourStep => Allowed::Range(Range {
            lo: crate::error::Bound::Inclusive(1.0),
            hi: crate::error::Bound::Unbounded,
            whole: true,
        }),
        _ => return None,
    })
}

/// Checks `value` of `field` against its range in the table ([`allowed`]); a field without a
/// range of its own passes.
///
/// # Errors
/// [`crate::error::Error::Invalid`] for `field`, stating its range, when `value` lies outside it.
pub fn check(field: Field, value: f64) -> crate::error::Result<f64> {
    match allowed(&field).as_ref().and_then(Allowed::range) {
        Some(r) if !r.contains(value) => Err(crate::error::Error::invalid(field, value, *r)),
        _ => Ok(value),
    }
}

/// Largest number of GFMD realisations (seeds) of an ensemble.
pub const MAX_SEEDS: usize = 1000;
/// Allowed λ_s/Δa of a rung of a GFMD resolution ladder.
pub const LADDER_RANGE: (f64, f64) = (2.0, 256.0);
/// L/λ_r, λ_r/λ_s and λ_s/Δa of a preset's reduced GFMD grid (`[gfmd]`).
pub const GFMD_REDUCTION_RANGE: (usize, usize) = (1, 4096);
/// Loads of a figure's curves (`figure --points`).
pub const FIGURE_POINTS_RANGE: (usize, usize) = (2, 100_000);
/// Width of a text chart in characters.
pub const CHART_WIDTH_RANGE: (usize, usize) = (20, 1000);
/// Height of a text chart in lines.
pub const CHART_HEIGHT_RANGE: (usize, usize) = (10, 1000);

/// Every user-settable number with a range of its own in [`allowed`]: the table each front
/// end's flags, keys and keywords are checked against (`cli/tests/range_table.rs` enumerates
/// the command line's flags and the presets' keys against it; a front end adds its side by
/// naming these fields).
pub const FIELDS: &[Field] = &[
    Field::SystemSize,
    Field::RolloffWavelength,
    Field::ShortWavelength,
    Field::Hurst,
    Field::RmsGradient,
    Field::RmsHeight,
    Field::ContactModulus,
    Field::SurfaceEnergy,
    Field::Range,
    Field::Pressure,
    Field::PressurePa,
    Field::Thickness,
    Field::Model,
    Field::C1,
    Field::C2,
    Field::Alpha,
    Field::KGriffith,
    Field::Rtol,
    Field::AdhesionSteps,
    Field::AdhesionPoints,
    Field::AdhesionTol,
    Field::SigmaMax,
    Field::SigmaPoints,
    Field::SweepStep,
    Field::EdgeRel,
    Field::Grid,
    Field::SweepPoints,
    Field::GfmdTolerance,
    Field::MaxIterations,
    Field::Bins,
    Field::ContactGap,
    Field::GfmdSizeRatio,
    Field::GfmdBandwidth,
    Field::GfmdPointsPerShortWavelength,
    Field::Seeds,
    Field::Ladder,
    Field::Seed,
    Field::FudgeGamma,
    Field::QMin,
    Field::QMax,
    Field::BinsPerDecade,
    Field::FigurePoints,
    Field::ChartWidth,
    Field::ChartHeight,
    Field::TourStep,
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_range_holds_its_default() {
        // the defaults of the accuracy knobs lie inside their ranges
        let o = crate::theory::engine::Options::default();
        for (f, v) in [
            (Field::Rtol, o.accuracy.rtol),
            (Field::AdhesionSteps, o.adhesion.steps_per_ln_q),
            (Field::AdhesionPoints, o.adhesion.points_per_width),
            (Field::AdhesionTol, o.adhesion.tol),
            (Field::SigmaPoints, o.sigma_points as f64),
            (Field::SweepStep, o.sweep_step_ln),
            (Field::EdgeRel, o.edge_rel),
        ] {
            let a = allowed(&f).unwrap();
            assert!(a.range().unwrap().contains(v), "{f}: {v}");
        }
        assert!(!allowed(&Field::Grid).unwrap().range().unwrap().contains(4.5));
        assert_eq!(
            allowed(&Field::Model).unwrap().describe("model"),
            "1, 2, 3, 4, 5, custom, yp08 or xu24"
        );
    }

    #[test]
    fn every_field_of_the_table_has_a_range() {
        for f in FIELDS {
            assert!(allowed(f).is_some(), "{f}: no range");
        }
    }
}
