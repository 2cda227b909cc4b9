//! The numerical methods an [`Error::NotConverged`](super::Error::NotConverged) names.

use std::fmt;

/// The numerical method behind an [`Error::NotConverged`](super::Error::NotConverged); displayed as the name a message
/// gives it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Solver {
    /// The adaptive ODE of the adhesionless variance (Dormand–Prince).
    VarianceOde,
    /// The adhesionless theory as a whole.
    AdhesionlessTheory,
    /// The adhesive theory as a whole (root search over branches).
    AdhesiveTheory,
    /// One march of the adhesive propagator through the resolution.
    AdhesiveMarch,
    /// The adhesive propagator with a prescribed wall.
    AdhesivePropagation,
    /// The self-consistency of γ(q) at q_s [S-14].
    AdhesiveSelfConsistency,
    /// The theory evaluated for a fit or a comparison.
    Theory,
    /// The mean gap.
    MeanGap,
    /// The energy route of the mean gap [S-12].
    MeanGapEnergyRoute,
    /// A load sweep.
    LoadSweep,
    /// A thickness sweep.
    ThicknessSweep,
    /// GFMD's FIRE relaxation.
    Gfmd,
    /// GFMD's Polonsky–Keer conjugate gradients.
    GfmdPolonskyKeer,
    /// A least-squares fit.
    Gauge,
    /// The Levenberg–Marquardt iteration of a fit.
    GaugeLevenbergMarquardt,
    /// The scale-by-scale snapshots of the march (the explorer's scale view).
    ScaleSnapshots,
    /// A benchmark's reference.
    Bench,
}

impl fmt::Display for Solver {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Solver::VarianceOde => "variance ODE (Dormand-Prince)",
            Solver::AdhesionlessTheory => "adhesionless theory",
            Solver::AdhesiveTheory => "adhesive theory",
            Solver::AdhesiveMarch => "adhesive march",
            Solver::AdhesivePropagation => "adhesive propagation",
            Solver::AdhesiveSelfConsistency => "adhesive self-consistency",
            Solver::Theory => "theory",
            Solver::MeanGap => "mean gap",
            Solver::MeanGapEnergyRoute => "mean gap (energy route)",
            Solver::LoadSweep => "load sweep",
            Solver::ThicknessSweep => "thickness sweep",
            Solver::Gfmd => "GFMD",
            Solver::GfmdPolonskyKeer => "GFMD (Polonsky-Keer)",
            Solver::Gauge => "gauge",
            Solver::GaugeLevenbergMarquardt => "gauge (Levenberg-Marquardt)",
            Solver::ScaleSnapshots => "scale snapshots",
            Solver::Bench => "bench",
        })
    }
}
