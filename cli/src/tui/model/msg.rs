//! What the update takes: a key, a reply of the worker or of a GFMD thread, a tick of the
//! clock, or what an effect found (a preset or a tour read, files written, a GFMD run
//! started). Every message is plain data, so [`crate::tui::update::update`] is a function of
//! the state and the message and is unit-tested message by message.

use crate::tui::base::protocol::Reply;
use crate::tui::base::tour::Tour;
use asperity::error::Result;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use ratatui::crossterm::event::KeyEvent;

/// One message for the update.
#[derive(Debug)]
pub enum Msg {
    /// A key pressed (or repeated).
    Key(KeyEvent),
    /// A reply of the worker or of a GFMD thread.
    Reply(Box<Reply>),
    /// Time passed with nothing else happening (the spinner; a playing scale view).
    Tick,
    /// The loop's clock, read once per batch of messages (before them) and per tick: the only
    /// way time enters the state.
    Clock(std::time::Instant),
    /// The terminal's size, at the start and whenever it changes.
    Resize {
        /// Columns.
        cols: u16,
        /// Rows.
        rows: u16,
    },
    /// The preset asked for by [`crate::tui::model::command::Command::LoadPreset`].
    PresetLoaded {
        /// The name or path it was asked by.
        source: String,
        /// The preset, or why it could not be read.
        result: Result<Preset>,
    },
    /// The tour asked for by [`crate::tui::model::command::Command::LoadTour`].
    TourLoaded(Result<Tour>),
    /// The files of `e` or `s` were written (or not).
    Written(Written),
    /// The mouse (captured only with `--mouse`), placed on the screen by the view's layout.
    Mouse(Pointer),
    /// GFMD run `id` started on a `grid`×`grid` grid.
    GfmdStarted {
        /// The run.
        id: u64,
        /// Its grid's side.
        grid: usize,
        /// When its thread started.
        at: std::time::Instant,
    },
}

/// What `e` or `s` wrote: the scene, the file name and number it wrote under, and the paths.
#[derive(Debug)]
pub struct Written {
    /// `s` (the charts) rather than `e` (curves and scene).
    pub charts: bool,
    /// The scene written.
    pub scene: Scene,
    /// The scene's file name (`asperity-NAME-N…`).
    pub name: String,
    /// The file number.
    pub number: u32,
    /// The paths written, or why not.
    pub result: Result<Vec<String>>,
}

/// What lies under the mouse pointer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// Chart panel `0..3` (big, lower left, lower right).
    Chart(usize),
    /// A knob's row of the parameter panel (an index into
    /// [`crate::tui::model::app::App::knob_rows`]).
    Knob(usize),
    /// Anything else.
    Elsewhere,
}

/// What the mouse did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pointer {
    /// A left click on a target.
    Click(Target),
    /// The wheel turned up (away from the user).
    WheelUp,
    /// The wheel turned down.
    WheelDown,
}
