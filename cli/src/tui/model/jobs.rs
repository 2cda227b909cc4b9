//! The work under way: the worker's requests, the GFMD run, the files written.

use crate::tui::base::progress::{GfmdProgress, GfmdState};
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
    /// A request is being served: set with the request
    /// ([`crate::tui::model::app::App::take_request`]), cleared when the worker has served the
    /// newest one ([`Jobs::served`]); read it with [`Jobs::busy`].
    pub(in crate::tui::model) busy: bool,
    /// When the current request was made (while busy; read it with [`Jobs::busy_since`]).
    pub(in crate::tui::model) busy_since: Option<std::time::Instant>,
    /// The background GFMD run (started with `g`; read it with [`Jobs::gfmd`]).
    gfmd: GfmdState,
    /// The flag that stops the running GFMD run: Some exactly while one runs (set by
    /// [`Jobs::start_gfmd`], taken by [`Jobs::cancel_gfmd`] and [`Jobs::end_gfmd`]).
    gfmd_cancel: Option<Arc<AtomicBool>>,
    /// The id of the last GFMD run started (strictly increasing, so a reply of an earlier run is
    /// told apart).
    gfmd_next: u64,
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
    /// No work under way, exports to `export_dir`.
    pub fn new(export_dir: PathBuf) -> Jobs {
        Jobs {
            gen: 0,
            load_range: None,
            busy: false,
            busy_since: None,
            gfmd: GfmdState::Idle,
            gfmd_cancel: None,
            gfmd_next: 0,
            pending: true,
            asked: crate::tui::base::kinds::Needs::default(),
            last_export: None,
            export_dir,
        }
    }

    /// Generation of the newest request.
    pub fn gen(&self) -> u64 {
        self.gen
    }

    /// Whether a request is being served.
    pub fn busy(&self) -> bool {
        self.busy
    }

    /// When the request being served was made.
    pub fn busy_since(&self) -> Option<std::time::Instant> {
        self.busy_since
    }

    /// The worker has sent everything of request `gen` (or failed on it): nothing is being
    /// served any more when it is the newest (an older request's end changes nothing).
    pub fn served(&mut self, gen: u64) {
        if gen == self.gen {
            self.busy = false;
            self.busy_since = None;
        }
    }

    /// A new GFMD run on `scene`: its id (the next one) and the flag that stops it; the run is
    /// the running one from now on.
    pub fn start_gfmd(&mut self, scene: &Scene) -> (u64, Arc<AtomicBool>) {
        self.gfmd_next += 1;
        let cancel = Arc::new(AtomicBool::new(false));
        self.gfmd_cancel = Some(cancel.clone());
        self.gfmd = GfmdState::Running {
            id: self.gfmd_next,
            scene: scene.clone(),
            progress: GfmdProgress::starting(scene.pressure()),
            started: None,
        };
        (self.gfmd_next, cancel)
    }

    /// Cancels the running GFMD run: nothing runs any more, and the returned flag is to be
    /// raised (None when no run was running).
    pub fn cancel_gfmd(&mut self) -> Option<Arc<AtomicBool>> {
        if !matches!(self.gfmd, GfmdState::Running { .. }) {
            return None;
        }
        self.gfmd = GfmdState::Idle;
        self.gfmd_cancel.take()
    }

    /// The end of GFMD run `id`: when it is the running one, its scene (its flag is dropped,
    /// nothing runs any more; the caller shows the outcome with [`Jobs::show_gfmd`]); None for
    /// any other run.
    pub fn end_gfmd(&mut self, id: u64) -> Option<Scene> {
        match &self.gfmd {
            GfmdState::Running { id: cur, scene, .. } if *cur == id => {
                let scene = scene.clone();
                self.gfmd_cancel = None;
                self.gfmd = GfmdState::Idle;
                Some(scene)
            }
            _ => None,
        }
    }

    /// The GFMD run: idle, running (with its progress) or done.
    pub fn gfmd(&self) -> &GfmdState {
        &self.gfmd
    }

    /// The progress and start time of run `id`, when it is the running one (to update them).
    pub fn gfmd_running(&mut self, id: u64) -> Option<(&mut GfmdProgress, &mut Option<std::time::Instant>)> {
        match &mut self.gfmd {
            GfmdState::Running {
                id: cur,
                progress,
                started,
                ..
            } if *cur == id => Some((progress, started)),
            _ => None,
        }
    }

    /// Shows a finished run's outcome, or nothing (`Idle`). A running run is not a state to
    /// show: it starts with [`Jobs::start_gfmd`], so a `Running` state here is taken as `Idle`.
    /// Whatever ran is stopped: its flag is returned, to be raised.
    pub fn show_gfmd(&mut self, state: GfmdState) -> Option<Arc<AtomicBool>> {
        self.gfmd = match state {
            GfmdState::Running { .. } => GfmdState::Idle,
            s => s,
        };
        self.gfmd_cancel.take()
    }
}
