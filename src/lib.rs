//! # asperity
//!
//! Persson's contact-mechanics theory of randomly rough, adhesive, elastic contacts, as
//! amended and gauged in Wang & Müser, "Gauging Persson theory on adhesion" (Tribol. Lett. 65,
//! 2017), cited [S-n] for its equation n. The physics modules have no terminal dependency.
//!
//! - [`spectrum`]: self-affine PSD with roll-off, moments, quadrature; discrete spectra.
//! - [`slab`]: slab factor f(qt) [S-4].
//! - [`model`]: weight function W(a) [S-17] and the four model variants.
//! - [`mirror`]: mirror-Gaussian distribution and moments [S-7, S-22].
//! - [`persson`]: the adhesionless theory, the W-coupled variance ODE [S-2, S-15, S-22].
//! - [`adhesion`]: the adhesive theory: moving absorbing wall, γ(q), σ_a(q), fixed point
//!   [S-5..S-9, S-14].
//! - [`energy`]: elastic energy U [S-11, S-14].
//! - [`gap`]: mean gap ū(p₀) [S-12] by the energy route, and the Yang–Persson closed form.
//! - [`sweep`]: a_r, ū, σ̄_c, U over a log-spaced load range (parallel; shared U table).
//! - [`scene`], [`preset`]: inputs and preset systems.
//! - [`engine`]: one evaluation of a scene, whatever it needs (the front ends call this).
//! - [`surface`], [`gfmd`]: seeded random height maps; the GFMD brute-force reference solver.
//! - [`benchmark`]: speed-against-error ladders (`asperity bench`).
//! - [`cli`]: the headless commands.
//! - [`tui`]: the terminal explorer (the only module that uses ratatui).

pub mod adhesion;
pub mod benchmark;
pub mod cli;
pub mod energy;
pub mod engine;
pub mod error;
pub mod fft2;
pub mod gap;
pub mod gfmd;
pub mod mirror;
pub mod model;
pub mod ode;
pub mod persson;
pub mod preset;
pub mod scene;
pub mod slab;
pub mod spectrum;
pub mod surface;
pub mod sweep;
pub mod tolerances;
pub mod tui;

pub use error::{Error, Result};
