//! What the screen shows and how: the knob selected, the charts, overlays, the tour, the status line.

use crate::tui::base::kinds::ChartKind;
use crate::tui::base::tour::Tour;
use crate::tui::base::wrap::MIN_SIZE;

/// Whether a terminal of `cols`×`rows` is smaller than [`MIN_SIZE`]: the view then shows
/// only the "terminal too small" screen, and the update takes only the keys that quit.
pub fn too_small(cols: u16, rows: u16) -> bool {
    cols < MIN_SIZE.0 || rows < MIN_SIZE.1
}

/// What covers the main view.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Overlay {
    /// Nothing.
    None,
    /// The key help.
    Help,
    /// The preset picker, with its cursor.
    Presets(usize),
}

/// The tour being walked (`t`, `asperity tour`).
#[derive(Debug, Clone, PartialEq)]
pub struct TourState {
    /// The tour.
    pub tour: Tour,
    /// The current step.
    pub step: usize,
}

/// A line for the status bar.
#[derive(Debug, Clone, PartialEq)]
pub struct Message {
    /// Text.
    pub text: String,
    /// Whether it reports a problem.
    pub error: bool,
}

/// What the screen shows and how.
#[derive(Debug)]
pub struct Ui {
    /// Selected row of [`App::knob_rows`](crate::tui::model::app::App::knob_rows).
    pub selected: usize,
    /// The value being typed, if any.
    pub edit: Option<String>,
    /// Overlay.
    pub overlay: Overlay,
    /// The charts of the big panel, the lower-left and the lower-right panel.
    pub charts: [ChartKind; 3],
    /// First row of the help shown (the help scrolls where the terminal is short).
    pub help_scroll: usize,
    /// First line of the tour's caption shown (it scrolls where the terminal is short).
    pub caption_scroll: usize,
    /// The panel the chart selector (`v`) changes.
    pub focus: usize,
    /// The focused chart fills the screen (`z`).
    pub zoom: bool,
    /// The linear Pr chart has a log density axis (`y`).
    pub log_pr: bool,
    /// Overlay every model on the charts (`M`).
    pub all_models: bool,
    /// Show the adhesionless comparison in the Pr chart.
    pub compare: bool,
    /// Status-bar message (cleared by the next key).
    pub message: Option<Message>,
    /// The scale view's frame (None: the last, at q_s).
    pub frame: Option<usize>,
    /// The scale view plays (one frame per tick).
    pub playing: bool,
    /// The tour, when one is being walked.
    pub tour: Option<TourState>,
    /// Set when the user quits.
    pub quit: bool,
    /// Show compute times (off in snapshot tests: they vary from run to run).
    pub show_timing: bool,
    /// The mouse is captured (`--mouse`): a click focuses a chart or picks a knob, the wheel
    /// steps the selected knob.
    pub mouse: bool,
    /// Use colour (off under `NO_COLOR`).
    pub color: bool,
    /// Spinner phase (advanced by ticks while busy).
    pub spinner: usize,
    /// The loop's clock as of its last [`Msg::Clock`]: update and view read no clock of their
    /// own, they take the time from here (`None` until the first).
    ///
    /// [`Msg::Clock`]: crate::tui::model::msg::Msg::Clock
    pub now: Option<std::time::Instant>,
    /// The terminal's size (columns, rows) as last reported ([`Msg::Resize`]); `None` until
    /// known.
    ///
    /// [`Msg::Resize`]: crate::tui::model::msg::Msg::Resize
    pub size: Option<(u16, u16)>,
}

impl Ui {
    /// Seconds from `since` to the loop's clock ([`Ui::now`]); 0 when either is unknown.
    pub fn elapsed_s(&self, since: Option<std::time::Instant>) -> f64 {
        match (self.now, since) {
            (Some(now), Some(t)) => now.saturating_duration_since(t).as_secs_f64(),
            _ => 0.0,
        }
    }

    /// Whether the terminal, as last reported, is too small ([`too_small`]); not while its
    /// size is unknown.
    pub fn too_small(&self) -> bool {
        self.size.is_some_and(|(cols, rows)| too_small(cols, rows))
    }
}
