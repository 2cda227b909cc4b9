//! The allowed ranges of a surface's parameters, shared by the self-affine and the tabulated
//! spectrum (and by [`crate::limits`]).

/// Allowed lengths L, λ_r, λ_s (m): from a picometre to a kilometre, so that q and the
/// moments ∫q^k dm stay far from overflow and underflow.
pub const LENGTH_RANGE_M: (f64, f64) = (1e-12, 1e3);
/// Allowed Hurst exponents H.
pub const HURST_RANGE: (f64, f64) = (1e-3, 1.0);
/// Allowed rms gradient ḡ: the theory is small-slope; below 1e-6 C₀ underflows for short
/// wavelengths.
pub const RMS_GRADIENT_RANGE: (f64, f64) = (1e-6, 100.0);
/// Allowed rms height (m).
pub const RMS_HEIGHT_RANGE_M: (f64, f64) = (1e-15, 1e3);
