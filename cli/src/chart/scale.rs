//! How an axis maps data to the drawing plane: linear, or log10 (x > 0 only).

/// How an axis maps data to the drawing plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// x ↦ x.
    Linear,
    /// x ↦ log10 x (x > 0 only).
    Log10,
}

impl Scale {
    /// The scale of an axis that is logarithmic or not.
    pub fn of(log: bool) -> Scale {
        if log {
            Scale::Log10
        } else {
            Scale::Linear
        }
    }

    /// Logarithmic.
    pub fn is_log(self) -> bool {
        self == Scale::Log10
    }

    /// Data value to plane coordinate; `None` where the scale is undefined or the value is
    /// not finite.
    pub fn forward(self, x: f64) -> Option<f64> {
        match self {
            Scale::Linear => x.is_finite().then_some(x),
            Scale::Log10 => (x.is_finite() && x > 0.0).then(|| x.log10()),
        }
    }

    /// Plane coordinate back to a data value.
    pub fn inverse(self, v: f64) -> f64 {
        match self {
            Scale::Linear => v,
            Scale::Log10 => 10f64.powf(v),
        }
    }
}
