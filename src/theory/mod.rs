//! Persson theory as amended in \[S\]: the mirror Gaussian [S-7, S-22],
//! the adhesionless variance ODE [S-2, S-15], adhesion [S-5..S-9, S-14], the elastic energy
//! [S-11] and mean gap [S-12], load sweeps,
//! sweeps over the thickness or the surface energy, and the engine that evaluates one scene.

pub mod adhesion;
pub mod closed_form;
pub mod cycle;
pub mod dmt;
pub mod energy;
pub mod engine;
pub mod gap;
pub mod hysteresis;
pub mod knob;
pub mod loads;
pub mod mirror;
pub mod persson;
pub mod sweep;
pub mod unloading;
pub mod window;

/// The slab factor moved to [`crate::elastic::slab`] (below inputs and theory alike); this
/// path stays for code written against it.
pub use crate::elastic::slab;
