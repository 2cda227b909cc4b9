//! The work an update asks for, as data: everything that leaves the explorer's state (the
//! worker's computation, a GFMD thread, a preset or tour file to read, files to write, the end
//! of the program) is one [`Command`]. [`crate::tui::update::update`] returns them; the event
//! loop ([`crate::tui::run_app`]) runs them through [`crate::tui::effects`], and what an effect
//! finds comes back to the update as a [`crate::tui::model::msg::Msg`]. A test runs them
//! itself ([`crate::tui::drive`]).

use crate::chart::Chart;
use crate::tui::base::data::{ScalesData, SweepData, ThicknessData};
use crate::tui::base::gfmd_view::GfmdView;
use crate::tui::base::kinds::ChartKind;
use crate::tui::base::protocol::Request;
use crate::tui::model::pins::Pin;
use asperity::input::preset::{MeasuredSpec, Preset};
use asperity::input::scene::Scene;
use asperity::surface::heightmap::Surface;
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// One piece of work for the event loop.
#[derive(Debug, Clone)]
pub enum Command {
    /// Compute what the visible charts need for the current scene (the worker; a newer
    /// request supersedes an older one): returned by an update that changed the scene or the
    /// charts shown; the loop submits the last of a burst, so a held key makes one request.
    Compute(Request),
    /// Start GFMD run `id` on `scene` in its own thread; `cancel` stops it (`g` again). It
    /// carries everything the run is set up from: the effect reads no state.
    StartGfmd {
        /// The run's id (replies of other runs are dropped).
        id: u64,
        /// The scene it runs on.
        scene: Scene,
        /// The preset, whose grid the run uses.
        preset: Box<Preset>,
        /// The measured map it runs on (None: a surface generated from the scene's spectrum).
        map: Option<Arc<Surface>>,
        /// Set to stop the run.
        cancel: Arc<AtomicBool>,
    },
    /// Stop the GFMD run whose flag this is (`g` while it runs, Esc).
    CancelGfmd(Arc<AtomicBool>),
    /// `e` (the curves as CSV and the scene as TOML) or `s` (the visible charts as SVG and
    /// PNG): what the files hold, taken from the state when the key was pressed.
    Export(Box<ExportJob>),
    /// Resolve a preset by name or path (the picker, the preset knob, a typed name); the
    /// answer is [`crate::tui::model::msg::Msg::PresetLoaded`].
    LoadPreset(String),
    /// Resolve a tour by name or path (`t`); the answer is
    /// [`crate::tui::model::msg::Msg::TourLoaded`].
    LoadTour(String),
    /// Leave the explorer.
    Quit,
}

/// The files of one `e` or `s`: where they go, under which name and number, and their data
/// as the screen showed it when the key was pressed (the effect writes it and reads no state).
#[derive(Debug, Clone)]
pub struct ExportJob {
    /// `s` (the charts as SVG and PNG) rather than `e` (CSV and TOML).
    pub charts: bool,
    /// The export directory.
    pub dir: PathBuf,
    /// The scene's name in file names (`asperity-NAME-N…`).
    pub name: String,
    /// The number to write under (the other key's, on the same scene); None: the next free one.
    pub reuse: Option<u32>,
    /// The scene.
    pub scene: Scene,
    /// The preset the scene came from.
    pub preset: Preset,
    /// The preset's name or path.
    pub source: String,
    /// The measured surface's file, side and periodicity (None on a preset's surface).
    pub measured: Option<MeasuredSpec>,
    /// The screen shows the unloading branch.
    pub unloading: bool,
    /// Pr(σ*) of the branch shown.
    pub pr: Option<Vec<(f64, f64)>>,
    /// The load curves.
    pub sweep: Option<SweepData>,
    /// a_r(t·q_r), where the thickness chart is shown.
    pub thickness: Option<ThicknessData>,
    /// The GFMD result of this scene.
    pub gfmd: Option<GfmdView>,
    /// The pinned curves.
    pub pins: Vec<Pin>,
    /// The scale view's frames, where it is shown.
    pub scales: Option<ScalesData>,
    /// The visible charts (each once), for `s`.
    pub figures: Vec<(ChartKind, Chart)>,
}
