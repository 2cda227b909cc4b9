//! Reports: what a front end shows of a computation, as plain typed data.
//!
//! A report gathers the results of several library calls (the evaluation of a scene, its
//! hysteresis window, the mean gap of each branch, the time each took) into one value that a
//! front end renders in its own words: the `asperity` binary writes it as JSON or a table, a
//! script or another program reads the fields. Values that may be absent are `Option`s (never
//! NaN), and an absent value comes with the reason where there is one.
//!
//! - [`mod@point`]: one scene at one load, everything `asperity run` prints.
//! - [`mod@sweep`]: a sweep over the load, t·q_r or γ_s with its hysteresis windows,
//!   everything `asperity sweep` prints.
//! - [`mod@cycle`]: the theory's path along a load cycle, what `asperity sweep --cycle`
//!   prints.
//! - [`mod@compare`]: every model against one reference, everything `asperity compare`
//!   prints.
//! - [`mod@gauge`]: the custom model fitted to a reference, and the reference assembled,
//!   everything `asperity gauge` prints.
//! - [`mod@gfmd`]: a GFMD run's spec with its defaults and ranges, its study (ladder,
//!   seeds) and the rows of its sweeps and cycles, everything `asperity gfmd` prints.
//! - [`mod@psd`]: a height map's PSD with its moments and self-affine fit, everything
//!   `asperity psd` prints.
//! - [`mod@pull_off`]: the theory's pull-off, the DMT routes', GFMD's nearest and how far
//!   each was measured from GFMD: what `asperity run --pull-off` and `sweep --cycle` add.
//! - [`mod@figure`]: the figures and Table 1 of \[S\] as data (their files, curves refined
//!   where they bend, closed forms, the values \[S\] states, GFMD points), everything
//!   `asperity figure` prints.
//! - [`mod@csv`]: the reports as CSV, as every front end writes them.
//! - [`mod@names`]: the public names kept as aliases of a preferred one.
//! - [`mod@numfmt`]: numbers as every front end writes them (tick labels, legends, panel
//!   values, durations).

pub mod compare;
pub mod csv;
pub mod cycle;
pub mod figure;
pub mod gauge;
pub mod gfmd;
pub mod names;
pub mod numfmt;
pub mod point;
pub mod psd;
pub mod pull_off;
pub mod sweep;

pub use point::{point, BranchReport, PointReport, ResolutionTable};
pub use psd::PsdReport;
pub use sweep::{Over, SweepReport};
