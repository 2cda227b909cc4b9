//! The work that leaves the explorer's state: the compute worker, the engine jobs, the files
//! of `e` and `s`.

pub mod engine;
pub mod export;
pub mod files;
pub mod worker;
