//! The rough surface: its height spectrum C(q) and random height maps drawn from it.

pub mod heightmap;
pub mod spectrum;
