//! The front ends of asperity: the `asperity` command line ([`cli`]), the terminal explorer
//! ([`tui`]) and the speed-against-error report ([`benchmark`]). They render the library's
//! typed results and errors in their own words; the physics lives in the `asperity` crate.

pub mod benchmark;
pub mod chart;
pub mod cli;
pub mod figure;
pub mod looks;
pub mod numfmt;
pub mod outfile;
pub mod report;
pub mod tui;
