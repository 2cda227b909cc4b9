//! Speed against error: ladders of accuracy settings for each solver, timed (median of several
//! runs) and compared with a converged reference (a much finer solution, and closed forms
//! where they exist). `asperity bench` prints the tables; the full run writes BENCHMARKS.md.
//!
//! Every rung that is the solver's default carries an error bound; `--quick` fails (non-zero
//! exit) if any default rung exceeds its bound, so CI guards the accuracy of what users see.

mod gfmd;
mod ladder;
mod report;
mod theory;

pub use gfmd::gfmd;
pub use ladder::{median_time, HardCase, Report, Rung};
pub use report::{document, fmt_time, machine, markdown, DEFAULTS, HAND_WRITTEN};
pub use theory::{adhesionless, adhesive, sweeps};
