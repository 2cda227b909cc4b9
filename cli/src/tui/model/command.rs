//! The work an update asks for, as data: everything that leaves the explorer's state (the
//! worker's computation, a GFMD thread, a preset or tour file to read, files to write, the end
//! of the program) is one [`Command`]. [`crate::tui::update::update`] returns them; the event
//! loop ([`crate::tui::run_app`]) runs them through [`crate::tui::effects`], and what an effect
//! finds comes back to the update as a [`crate::tui::model::msg::Msg`]. A test runs them
//! itself ([`crate::tui::drive`]).

use crate::tui::model::protocol::Request;
use asperity::input::scene::Scene;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// One piece of work for the event loop.
#[derive(Debug, Clone)]
pub enum Command {
    /// Compute what the visible charts need for the current scene (the worker; a newer
    /// request supersedes an older one): returned by an update that changed the scene or the
    /// charts shown; the loop submits the last of a burst, so a held key makes one request.
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
    /// Stop the GFMD run whose flag this is (`g` while it runs, Esc).
    CancelGfmd(Arc<AtomicBool>),
    /// `e`: write the curves (CSV) and the scene (TOML).
    Export,
    /// `s`: save the visible charts as SVG and PNG.
    SaveCharts,
    /// Resolve a preset by name or path (the picker, the preset knob, a typed name); the
    /// answer is [`crate::tui::model::msg::Msg::PresetLoaded`].
    LoadPreset(String),
    /// Resolve a tour by name or path (`t`); the answer is
    /// [`crate::tui::model::msg::Msg::TourLoaded`].
    LoadTour(String),
    /// Leave the explorer.
    Quit,
}
