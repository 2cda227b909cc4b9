//! Typed errors for the whole engine.
//!
//! Every error names what went wrong in one line: the field, the value and the allowed range
//! for bad input; the solver and the reason for a non-converged computation. The CLI prints
//! the `Display` form to stderr and exits non-zero; the TUI shows it in the status line.

use std::fmt;

/// Result alias used throughout the crate.
pub type Result<T> = std::result::Result<T, Error>;

/// Everything that can go wrong in asperity.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// A field has a value outside its allowed range (or NaN).
    InvalidField {
        /// Dotted path of the field, e.g. `surface.hurst` or `--pressure`.
        field: String,
        /// The offending value, as the user gave it.
        value: String,
        /// The allowed range, in words, e.g. `0 < hurst <= 1`.
        allowed: String,
    },
    /// A preset file could not be read or parsed.
    Preset {
        /// The file (or preset name).
        source: String,
        /// What the parser said.
        message: String,
    },
    /// A numerical method did not reach its tolerance.
    NotConverged {
        /// Which solver.
        solver: String,
        /// Why, with the numbers (iterations, residual).
        reason: String,
    },
    /// The requested combination is not (yet) supported.
    Unsupported(String),
    /// I/O failure (file not found, cannot write), with the path.
    Io(String),
    /// The caller cancelled a long computation (e.g. a sweep the TUI no longer needs).
    Cancelled,
}

impl Error {
    /// Shorthand for [`Error::InvalidField`].
    pub fn field(field: impl Into<String>, value: impl fmt::Display, allowed: impl Into<String>) -> Self {
        Error::InvalidField {
            field: field.into(),
            value: value.to_string(),
            allowed: allowed.into(),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::InvalidField { field, value, allowed } => {
                write!(f, "invalid {field} = {value}: allowed {allowed}")
            }
            Error::Preset { source, message } => {
                let one_line = message.split_whitespace().collect::<Vec<_>>().join(" ");
                write!(f, "preset {source}: {one_line}")
            }
            Error::NotConverged { solver, reason } => write!(f, "{solver} did not converge: {reason}"),
            Error::Unsupported(what) => write!(f, "not supported: {what}"),
            Error::Io(what) => write!(f, "i/o error: {what}"),
            Error::Cancelled => write!(f, "cancelled"),
        }
    }
}

impl std::error::Error for Error {}

/// Checks that `value` is finite and lies in `[lo, hi]` (bounds may be infinite).
pub fn check_range(field: &str, value: f64, lo: f64, hi: f64, allowed: &str) -> Result<f64> {
    if value.is_nan() || value < lo || value > hi {
        return Err(Error::field(field, value, allowed));
    }
    Ok(value)
}

/// Checks that `value` is finite and strictly positive.
pub fn check_positive(field: &str, value: f64) -> Result<f64> {
    if !(value.is_finite() && value > 0.0) {
        return Err(Error::field(field, value, "a finite number > 0"));
    }
    Ok(value)
}
