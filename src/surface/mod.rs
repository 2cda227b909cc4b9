//! The rough surface: its height spectrum C(q) and random height maps drawn from it.

pub mod fit;
pub mod generate;
pub mod heightmap;
pub mod psd;
pub mod ranges;
pub mod readers;
pub mod shells;
pub mod spectrum;
pub mod tabulated;
pub mod writers;
