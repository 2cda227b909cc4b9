//! Inputs: the validated scene, the model variants [S-17] and the preset systems.

pub mod file;
pub mod model;
pub mod model_five;
pub mod overrides;
pub mod preset;
pub mod scene;
