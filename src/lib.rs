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
//! - [`energy`]: elastic energy U [S-11, S-14].
//! - [`scene`], [`preset`]: inputs and preset systems.
//! - [`engine`]: one evaluation of a scene, whatever it needs (the front ends call this).
//! - [`surface`], [`gfmd`]: seeded random height maps; the GFMD brute-force reference solver.
//! - [`benchmark`]: speed-against-error ladders (`asperity bench`).
//! - [`cli`]: the headless commands.

pub mod benchmark;
pub mod cli;
pub mod energy;
pub mod engine;
pub mod error;
pub mod fft2;
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
pub mod tolerances;

pub use error::{Error, Result};
