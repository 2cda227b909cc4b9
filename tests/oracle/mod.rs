//! An independent slow oracle for the adhesive theory, like RustFFT's naive
//! DFT beside its FFT: the same equations as `asperity::theory::adhesion` ([S-5..S-9, S-14],
//! docs/physics.md §4) solved the plain way, sharing no code with the fast path. Only the
//! scene's input parameters are read from the library.
//!
//! - `physics`: PSD, measure, ḡ, slab factor, W, Griffith wall, quadrature.
//! - `march`: extrapolated backward Euler / finite differences with a Shortley–Weller
//!   absorbing wall.
//! - `solve`: self-consistency as a scalar equation H(C) = 0 in C = γ(q_L), all roots.
#![allow(dead_code)]

pub mod march;
pub mod physics;
pub mod solve;
