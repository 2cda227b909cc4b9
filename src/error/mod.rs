//! Typed errors for the whole library.
//!
//! Bad input is [`Error::Invalid`]: the [`Field`] it concerns, the value (formatted compactly,
//! never as a 300-digit decimal) and the allowed range in words. The library names a field by
//! its canonical key ([`Field::key`], the preset's dotted path where there is one); each front
//! end renders the field in its own words (the CLI as its flag, a preset as its key, the
//! explorer as its label), so no front end's vocabulary appears here. A computation that does
//! not reach its tolerance is [`Error::NotConverged`], naming the solver and the reason.

mod range;
mod solver;

pub use range::{Allowed, Bound, Range};
pub use solver::Solver;

use std::fmt;

/// Result alias used throughout the crate.
pub type Result<T> = std::result::Result<T, Error>;

/// A user-settable quantity, named independently of any front end.
///
/// [`Field::key`] gives the canonical key (the preset path for preset fields). Front ends map
/// fields to their own names (e.g. [`Field::Thickness`] is `--thickness` on the command line,
/// `load.thickness_qr` in a preset, `t·q_r` in the explorer).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Field {
    /// L, the side of the periodic square (m).
    SystemSize,
    /// λ_r, the roll-off wavelength (m).
    RolloffWavelength,
    /// λ_s, the short-wavelength cut-off (m).
    ShortWavelength,
    /// H, the Hurst exponent.
    Hurst,
    /// ḡ, the rms gradient.
    RmsGradient,
    /// h_rms (m).
    RmsHeight,
    /// A height map (its values or its shape).
    HeightMap,
    /// E*, the contact modulus (Pa).
    ContactModulus,
    /// γ_s, the surface energy (J/m²).
    SurfaceEnergy,
    /// ρ, the range of the adhesive interaction (m).
    Range,
    /// p* = p/(E*ḡ), the reduced nominal pressure.
    Pressure,
    /// p, the nominal pressure in Pa (GFMD).
    PressurePa,
    /// t·q_r, the reduced slab thickness (∞ = semi-infinite).
    Thickness,
    /// The model variant (1–4 or custom).
    Model,
    /// c₁ of W(a) [S-17].
    C1,
    /// c₂ of W(a) [S-17].
    C2,
    /// α, the exponent of W in the stress broadening [S-15].
    Alpha,
    /// k_G, the Griffith prefactor [S-8].
    KGriffith,
    /// The pair (c₁, c₂) together (W must stay positive on [0, 1]).
    WeightCoefficients,
    /// Relative tolerance of the adhesionless variance ODE.
    Rtol,
    /// Resolution steps per decade of the adhesive solver.
    AdhesionSteps,
    /// Stress grid points per standard deviation of the adhesive solver.
    AdhesionPoints,
    /// Self-consistency tolerance |γ(q_s)/γ_s − 1| of the adhesive solver.
    AdhesionTol,
    /// Upper end σ*_max of the tabulated Pr(σ*).
    SigmaMax,
    /// Number of points of the tabulated Pr(σ*).
    SigmaPoints,
    /// Lower end of a load sweep (p*).
    SweepFrom,
    /// Upper end of a load sweep (p*).
    SweepTo,
    /// Number of loads in a sweep.
    SweepPoints,
    /// Largest ln p* step of a sweep's energy table.
    SweepStep,
    /// Relative precision of a sweep's hysteresis-window edges.
    EdgeRel,
    /// GFMD grid side N.
    Grid,
    /// GFMD relative force residual.
    GfmdTolerance,
    /// GFMD iteration limit.
    MaxIterations,
    /// Number of histogram bins of a GFMD Pr(σ*).
    Bins,
    /// Initial contact gap of a GFMD run (m).
    ContactGap,
    /// L/λ_r of a reduced GFMD system.
    GfmdSizeRatio,
    /// λ_r/λ_s of a reduced GFMD system.
    GfmdBandwidth,
    /// λ_s/Δa of a reduced GFMD system.
    GfmdPointsPerShortWavelength,
    /// Number of GFMD realisations (seeds) of an ensemble.
    Seeds,
    /// λ_s/Δa of the rungs of a GFMD resolution ladder.
    Ladder,
    /// The seed of a GFMD surface realisation (the first of an ensemble).
    Seed,
    /// γ_f, the fitting parameter of the literature variants YP08 and Xu24.
    FudgeGamma,
    /// Lower cut-off q_min of a measured spectrum (1/m).
    QMin,
    /// Upper cut-off q_max of a measured spectrum (1/m).
    QMax,
    /// Radial bins per decade of q of a measured map's PSD.
    BinsPerDecade,
    /// Loads of a figure's curves.
    FigurePoints,
    /// Width of a text chart (characters).
    ChartWidth,
    /// Height of a text chart (lines).
    ChartHeight,
    /// The step of a tour to start at (1 = the first).
    TourStep,
    /// Any other field, by its canonical key (e.g. `reference[2].pressure`).
    Other(String),
}

impl Field {
    /// The canonical key: the preset path where the field lives in a preset (e.g.
    /// `load.thickness_qr`), otherwise a dotted name in the same style.
    pub fn key(&self) -> &str {
        match self {
            Field::SystemSize => "surface.system_size_m",
            Field::RolloffWavelength => "surface.rolloff_wavelength_m",
            Field::ShortWavelength => "surface.short_wavelength_m",
            Field::Hurst => "surface.hurst",
            Field::RmsGradient => "surface.rms_gradient",
            Field::RmsHeight => "surface.rms_height_m",
            Field::HeightMap => "surface.height_map",
            Field::ContactModulus => "material.contact_modulus_pa",
            Field::SurfaceEnergy => "adhesion.surface_energy_j_m2",
            Field::Range => "adhesion.range_m",
            Field::Pressure => "load.pressure",
            Field::PressurePa => "load.pressure_pa",
            Field::Thickness => "load.thickness_qr",
            Field::Model => "model.variant",
            Field::C1 => "model.c1",
            Field::C2 => "model.c2",
            Field::Alpha => "model.alpha",
            Field::KGriffith => "model.k_griffith",
            Field::WeightCoefficients => "model.c1/c2",
            Field::Rtol => "accuracy.rtol",
            Field::AdhesionSteps => "accuracy.adhesion_steps",
            Field::AdhesionPoints => "accuracy.adhesion_points",
            Field::AdhesionTol => "accuracy.adhesion_tol",
            Field::SigmaMax => "accuracy.sigma_max",
            Field::SigmaPoints => "accuracy.sigma_points",
            Field::SweepFrom => "sweep.from",
            Field::SweepTo => "sweep.to",
            Field::SweepPoints => "sweep.points",
            Field::SweepStep => "sweep.step_ln",
            Field::EdgeRel => "sweep.edge_rel",
            Field::Grid => "gfmd.grid",
            Field::GfmdTolerance => "gfmd.tolerance",
            Field::MaxIterations => "gfmd.max_iterations",
            Field::Bins => "gfmd.bins",
            Field::ContactGap => "gfmd.contact_gap_m",
            Field::GfmdSizeRatio => "gfmd.system_size_ratio",
            Field::GfmdBandwidth => "gfmd.bandwidth",
            Field::GfmdPointsPerShortWavelength => "gfmd.points_per_short_wavelength",
            Field::Seeds => "gfmd.seeds",
            Field::Ladder => "gfmd.ladder",
            Field::Seed => "gfmd.seed",
            Field::FudgeGamma => "model.fudge_gamma",
            Field::QMin => "measured.q_min_per_m",
            Field::QMax => "measured.q_max_per_m",
            Field::BinsPerDecade => "psd.bins_per_decade",
            Field::FigurePoints => "figure.points",
            Field::ChartWidth => "chart.width",
            Field::ChartHeight => "chart.height",
            Field::TourStep => "tour.step",
            Field::Other(k) => k,
        }
    }
}

impl Field {
    /// The short name used inside range descriptions: the last segment of the key (e.g.
    /// `hurst`, `thickness_qr`).
    pub fn short(&self) -> &str {
        let k = self.key();
        k.rsplit('.').next().unwrap_or(k)
    }
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// Everything that can go wrong in asperity.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A field has a value outside its allowed range (or NaN).
    Invalid {
        /// Which field.
        field: Field,
        /// The offending value, compactly formatted (see [`fmt_value`]).
        value: String,
        /// What the field accepts (a range, a list of choices, or a condition in words).
        allowed: Allowed,
    },
    /// A field has a value outside its allowed range (or NaN), named by a free-form string.
    ///
    /// Kept while the code base moves to [`Error::Invalid`]; new code uses [`Error::invalid`].
    InvalidField {
        /// Name of the field.
        field: String,
        /// The offending value, as the user gave it.
        value: String,
        /// What the field accepts.
        allowed: Allowed,
    },
    /// A preset (or tour, or other TOML input) could not be read or parsed.
    Preset {
        /// The file (or preset name).
        source: String,
        /// What the parser said.
        message: String,
    },
    /// A numerical method did not reach its tolerance.
    NotConverged {
        /// Which solver.
        solver: Solver,
        /// Why, with the numbers (iterations, residual).
        reason: String,
    },
    /// The requested combination is not (yet) supported.
    Unsupported(String),
    /// I/O failure: what was being done (with the file where there is one) and why.
    Io {
        /// What was being done, e.g. "read preset presets/x.toml" or "start the worker thread".
        action: String,
        /// The system's error kind (`Other` where there is none).
        kind: std::io::ErrorKind,
        /// The system's message.
        message: String,
    },
    /// The caller cancelled a long computation (e.g. a sweep the explorer no longer needs).
    Cancelled,
}

impl Error {
    /// An [`Error::Io`] of a file operation: `verb` ("read", "write") `what` ("preset",
    /// "surface", "" for a plain file) at `path`, failing with `e`.
    pub fn io_file(verb: &str, what: &str, path: &std::path::Path, e: &std::io::Error) -> Self {
        let sep = if what.is_empty() { "" } else { " " };
        Error::Io {
            action: format!("{verb} {what}{sep}{}", path.display()),
            kind: e.kind(),
            message: e.to_string(),
        }
    }

    /// An [`Error::Io`] of something other than a file (a thread, the terminal, an encoder).
    pub fn io(action: impl Into<String>, message: impl fmt::Display) -> Self {
        Error::Io {
            action: action.into(),
            kind: std::io::ErrorKind::Other,
            message: message.to_string(),
        }
    }

    /// An [`Error::Invalid`] for `field`: `value` is formatted with [`fmt_value`] when it is a
    /// number (use [`Error::invalid_text`] for non-numeric values).
    pub fn invalid(field: Field, value: f64, allowed: impl Into<Allowed>) -> Self {
        Error::Invalid {
            field,
            value: fmt_value(value),
            allowed: allowed.into(),
        }
    }

    /// An [`Error::Invalid`] whose value is text (a model name, a path, a shape).
    pub fn invalid_text(field: Field, value: impl fmt::Display, allowed: impl Into<Allowed>) -> Self {
        Error::Invalid {
            field,
            value: fmt_text(&value.to_string()),
            allowed: allowed.into(),
        }
    }

    /// Shorthand for [`Error::InvalidField`] (free-form field name).
    pub fn field(field: impl Into<String>, value: impl fmt::Display, allowed: impl Into<Allowed>) -> Self {
        Error::InvalidField {
            field: field.into(),
            value: fmt_text(&value.to_string()),
            allowed: allowed.into(),
        }
    }

    /// The field this error is about, if it is an [`Error::Invalid`].
    pub fn invalid_field(&self) -> Option<&Field> {
        match self {
            Error::Invalid { field, .. } => Some(field),
            _ => None,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Invalid { field, value, allowed } => {
                write!(
                    f,
                    "invalid {field} = {value}: allowed {}",
                    allowed.describe(field.short())
                )
            }
            Error::InvalidField { field, value, allowed } => {
                let name = field.trim_start_matches('-');
                write!(f, "invalid {field} = {value}: allowed {}", allowed.describe(name))
            }
            Error::Preset { source, message } => {
                let one_line = message.split_whitespace().collect::<Vec<_>>().join(" ");
                write!(f, "preset {source}: {one_line}")
            }
            Error::NotConverged { solver, reason } => write!(f, "{solver} did not converge: {reason}"),
            Error::Unsupported(what) => write!(f, "not supported: {what}"),
            Error::Io { action, message, .. } => write!(f, "i/o error: cannot {action}: {message}"),
            Error::Cancelled => write!(f, "cancelled"),
        }
    }
}

impl std::error::Error for Error {}

/// Formats a number for a message: plain for moderate magnitudes, scientific otherwise, so
/// that 1e300 prints as `1e300`, not as 301 digits; `NaN`, `inf`, `-inf` as such.
pub fn fmt_value(x: f64) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    let a = x.abs();
    if a == 0.0 || (1e-4..1e6).contains(&a) {
        // shortest representation that round-trips
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// The longest value text an error shows; longer texts (a 300-character file name) are cut
/// in the middle with `…`, so an error stays one short line.
pub const MAX_SHOWN_CHARS: usize = 80;

/// Formats user text for a message: a number as [`fmt_value`] does (so `1e300` typed as 301
/// digits prints as `1e300`), anything else as given, cut in the middle to
/// [`MAX_SHOWN_CHARS`] (its start and its end: a file name's beginning, and the line number
/// and what is wrong with it).
pub fn fmt_text(s: &str) -> String {
    let t = s.trim();
    if t.is_empty() {
        return "\"\" (empty)".into();
    }
    if let Ok(x) = t.parse::<f64>() {
        if t.len() > 12 {
            return fmt_value(x);
        }
    }
    let n = t.chars().count();
    if n > MAX_SHOWN_CHARS {
        let head = MAX_SHOWN_CHARS / 4;
        let tail = MAX_SHOWN_CHARS - head - 1;
        let start: String = t.chars().take(head).collect();
        let end: String = t.chars().skip(n - tail).collect();
        return format!("{start}…{end}");
    }
    t.to_string()
}

/// Checks that `value` is not NaN and lies in `[lo, hi]` (bounds may be infinite); the error
/// states the range as `lo <= value <= hi`.
pub fn check_in(field: Field, value: f64, lo: f64, hi: f64) -> Result<f64> {
    if value.is_nan() || value < lo || value > hi {
        return Err(Error::invalid(field, value, Range::closed(lo, hi)));
    }
    Ok(value)
}

/// Checks that `value` is finite and strictly positive.
pub fn check_finite_positive(field: Field, value: f64) -> Result<f64> {
    if !(value.is_finite() && value > 0.0) {
        return Err(Error::invalid(field, value, Range::above(0.0)));
    }
    Ok(value)
}

/// Checks that `value` is finite and lies in `[lo, hi]` (bounds may be infinite).
pub fn check_range(field: &str, value: f64, lo: f64, hi: f64, allowed: &str) -> Result<f64> {
    if value.is_nan() || value < lo || value > hi {
        return Err(Error::field(field, fmt_value(value), allowed));
    }
    Ok(value)
}

/// Checks that `value` is finite and strictly positive.
pub fn check_positive(field: &str, value: f64) -> Result<f64> {
    if !(value.is_finite() && value > 0.0) {
        return Err(Error::field(field, fmt_value(value), Range::above(0.0)));
    }
    Ok(value)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_print_compactly() {
        assert_eq!(fmt_value(1e300), "1e300");
        assert_eq!(fmt_value(-1e-300), "-1e-300");
        assert_eq!(fmt_value(0.005), "0.005");
        assert_eq!(fmt_value(0.0), "0");
        assert_eq!(fmt_value(f64::NEG_INFINITY), "-inf");
        assert_eq!(fmt_value(f64::NAN), "NaN");
    }

    #[test]
    fn invalid_names_the_field_by_its_key() {
        let e = check_in(Field::Pressure, 1e300, 1e-12, 1e3).unwrap_err();
        assert_eq!(e.invalid_field(), Some(&Field::Pressure));
        assert_eq!(
            e.to_string(),
            "invalid load.pressure = 1e300: allowed 1e-12 <= pressure <= 1000"
        );
    }
}
