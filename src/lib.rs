//! # asperity
//!
//! Persson's contact-mechanics theory of randomly rough, adhesive, elastic contacts, as
//! amended and gauged in Wang & Müser, "Gauging Persson theory on adhesion" (Tribol. Lett. 65,
//! 2017), cited [S-n] for its equation n, and a Green's-function molecular-dynamics (GFMD)
//! brute-force reference to check it against. This crate is the physics only: no terminal, no
//! command line. The `asperity` binary (crate `asperity-cli`) is one front end on it.
//!
//! The physics reference (conventions, errata, decisions, reference values, the preset
//! systems) is in the repository's `docs/` folder.
//!
//! ## Units and reduced variables
//!
//! Inputs are in SI units and carry the unit in their name where they are not reduced
//! (`contact_modulus_pa`, `range_m`, `gamma_j_m2`, …). Stresses are reduced by E*ḡ, with E* the
//! contact modulus and ḡ the rms gradient of the surface: σ* = σ/(E*ḡ), p* = p/(E*ḡ). Slab
//! thickness is reduced by the roll-off wave number, t·q_r (∞ for a semi-infinite body).
//! Pr(σ*) is normalised so that ∫Pr dσ* = a_r, the relative contact area.
//!
//! ## Layout
//!
//! - [`input`]: the validated [`input::scene::Scene`] (built once, changed by validating
//!   setters or [`input::overrides::Overrides`]), models [S-17], presets.
//! - [`surface`]: the height spectrum C(q) and its moments; random height maps.
//! - [`elastic`]: the slab factor f(qt) [S-4].
//! - [`numerics`]: FFTs, the adaptive ODE integrator.
//! - [`theory`]: the mirror Gaussian [S-7, S-22], the adhesionless
//!   theory, adhesion [S-5..S-9, S-14], energy and mean gap [S-11, S-12], sweeps, and the
//!   [`theory::engine`] that evaluates one scene.
//! - [`gfmd`]: the brute-force reference solver.
//! - [`report`]: what a front end shows of one scene ([`report::point()`]: branches, window,
//!   per-branch gap with its bracket, error bars, timings).
//! - [`fit`]: gauging model coefficients on reference data (weighted least squares).
//! - [`contact`]: [`contact::ContactStats`], the statistics every result carries.
//! - [`error`]: typed errors ([`Error`], [`Field`]); [`tolerances`]: every numerical tolerance.
//!
//! ## Example
//!
//! ```
//! use asperity::input::preset::Preset;
//! use asperity::theory::engine::{self, Options};
//!
//! // System I of [S] (the contact-mechanics challenge), without adhesion, model 3, p* = 0.01.
//! let preset = Preset::resolve("system-1").unwrap();
//! let scene = preset
//!     .scene()
//!     .unwrap()
//!     .without_adhesion()
//!     .with_model(asperity::input::model::Model::named(3).unwrap())
//!     .unwrap();
//! let eval = engine::evaluate(&scene, &Options::default()).unwrap();
//! // Table 1 of [S]: a_r = p*/σ̄_c* = 0.01/0.4670 = 0.0214.
//! assert!((eval.stats.a_r - 0.0214).abs() < 2e-4);
//! ```

pub mod contact;
pub mod elastic;
pub mod error;
pub mod fit;
pub mod gfmd;
pub mod input;
pub mod limits;
pub mod numerics;
pub mod report;
pub mod surface;
pub mod theory;
pub mod tolerances;
pub mod work;

pub use error::{Error, Field, Result};
