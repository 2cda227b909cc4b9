//! The latency trace of `ASPERITY_TRACE=FILE` (see [`crate::tui`]): per generation, the time
//! from the key press to the frames that show the point, the load charts and everything.

use crate::tui::model::app::{App, Slot};
use std::io::Write;
use std::time::Instant;

/// Latency trace (see the module docs).
pub struct Trace {
    pub file: Option<std::fs::File>,
    pub started: Option<(u64, Instant)>,
    point_logged: bool,
    charts_logged: bool,
    final_logged: bool,
}

impl Trace {
    /// The trace `ASPERITY_TRACE` asks for (none without it).
    pub fn from_env() -> Trace {
        let file = std::env::var_os("ASPERITY_TRACE")
            .and_then(|p| std::fs::OpenOptions::new().create(true).append(true).open(p).ok());
        Trace {
            file,
            started: None,
            point_logged: false,
            charts_logged: false,
            final_logged: false,
        }
    }

    pub fn after_draw(&mut self, app: &App) {
        let (Some(f), Some((gen, t0))) = (self.file.as_mut(), self.started) else {
            return;
        };
        if gen != app.jobs.gen() {
            return;
        }
        let ms = t0.elapsed().as_secs_f64() * 1e3;
        if !self.point_logged && app.results.point().is_some() && app.results.point_gen >= gen {
            let _ = writeln!(f, "gen {gen} point_drawn_ms {ms:.2}");
            self.point_logged = true;
        }
        let shown = app.results.point_gen >= gen && app.results.is_current(Slot::Sweep);
        if !self.charts_logged && shown {
            let _ = writeln!(f, "gen {gen} charts_drawn_ms {ms:.2}");
            self.charts_logged = true;
        }
        let preview = app.results.sweep().is_some_and(|s| s.as_ref().is_ok_and(|s| s.preview));
        if !self.final_logged && shown && !preview {
            let _ = writeln!(f, "gen {gen} charts_final_ms {ms:.2}");
            self.final_logged = true;
        }
        if !app.jobs.busy() {
            let _ = writeln!(f, "gen {gen} all_drawn_ms {ms:.2}");
            self.started = None;
        }
    }

    /// Starts timing generation `gen` from `t0` (a key press, or the request).
    pub fn start(&mut self, gen: u64, t0: Instant) {
        self.started = Some((gen, t0));
        self.point_logged = false;
        self.charts_logged = false;
        self.final_logged = false;
    }
}
