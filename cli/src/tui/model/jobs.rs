//! The work under way: the worker's requests, the GFMD run, the files written.

use crate::tui::base::progress::GfmdState;
use asperity::input::scene::Scene;
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// The work under way.
#[derive(Debug)]
pub struct Jobs {
    /// Generation of the newest request (strictly increasing: set by
    /// [`crate::tui::model::app::App::take_request`] only; read it with [`Jobs::gen`]).
    pub(in crate::tui::model) gen: u64,
    /// The load charts' p* range of the last request (see [`crate::tui::model::knobs::sticky_range`]).
    pub(in crate::tui::model) load_range: Option<(f64, f64)>,
    /// A request is being served.
    pub busy: bool,
    /// When the current request was made (while busy).
    pub busy_since: Option<std::time::Instant>,
    /// The background GFMD run (started with `g`).
    pub gfmd: GfmdState,
    pub gfmd_cancel: Option<Arc<AtomicBool>>,
    pub gfmd_next: u64,
    /// The scene or the charts changed since the last request (set by
    /// [`crate::tui::model::app::App::refresh`], cleared by the request).
    pub(in crate::tui::model) pending: bool,
    /// What the last request asked for (the charts then shown).
    pub(in crate::tui::model) asked: crate::tui::base::kinds::Needs,
    /// The last `e`/`s`: its scene, file name, number, and whether `e` and `s` were done
    /// under that number.
    pub last_export: Option<(Scene, String, u32, [bool; 2])>,
    /// Where `e` writes.
    pub export_dir: PathBuf,
}

impl Jobs {
    /// Generation of the newest request.
    pub fn gen(&self) -> u64 {
        self.gen
    }
}
