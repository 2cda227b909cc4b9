//! The work an update asks for, as data: everything that leaves the explorer's state (the
//! worker's computation, a GFMD thread, files, the end of the program) is one [`Command`],
//! queued by the update ([`crate::tui::model::app::App::take_commands`] drains the queue) and run by the
//! event loop ([`super::run_app`]); a test runs them itself ([`crate::tui::drive::compute_now`],
//! [`crate::tui::effects::files::run`]). The update does no I/O of its own beyond resolving a preset or
//! tour name.

use crate::tui::model::protocol::Request;
use asperity::input::scene::Scene;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// One piece of work for the event loop.
#[derive(Debug, Clone)]
pub enum Command {
    /// Compute what the visible charts need for the current scene (the worker; a newer
    /// request supersedes an older one).
    Compute(Request),
    /// Start GFMD run `id` on `scene` in its own thread; `cancel` stops it (`g` again).
    StartGfmd {
        /// The run's id (replies of other runs are dropped).
        id: u64,
        /// The scene it runs on.
        scene: Scene,
        /// Set to stop the run.
        cancel: Arc<AtomicBool>,
    },
    /// `e`: write the curves (CSV) and the scene (TOML).
    Export,
    /// `s`: save the visible charts as SVG and PNG.
    SaveCharts,
    /// Leave the explorer.
    Quit,
}
