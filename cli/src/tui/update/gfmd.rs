//! `g` and the GFMD job's replies → the next state: start or cancel the run, keep the
//! progress of the run shown (a reply of any other run, e.g. one cancelled before, is
//! dropped), and its outcome with the time it took; and the status line's words for the run.

use crate::tui::base::gfmd_view::GfmdView;
use crate::tui::base::progress::{format_secs, GfmdProgress};
use crate::tui::model::app::*;
use asperity::error::{Error, Result};

impl App {
    /// `g`: asks for a GFMD run of the current scene on the preset's reduced grid (with
    /// the preset and the measured map it is set up from), or cancels the running one (a
    /// run started in the same burst stops at its first check).
    pub fn toggle_gfmd(&mut self) -> Option<Command> {
        if let Some(cancel) = self.jobs.cancel_gfmd() {
            self.info("GFMD cancelled");
            return Some(Command::CancelGfmd(cancel));
        }
        let (id, cancel) = self.jobs.start_gfmd(&self.params.scene);
        let start = Command::StartGfmd {
            id,
            scene: self.params.scene.clone(),
            preset: Box::new(self.params.preset.clone()),
            map: self.shared_map_of(&self.params.scene),
            cancel,
        };
        self.info("GFMD started on the preset's reduced grid (g cancels)");
        Some(start)
    }

    /// Run `id` started at `at` (the effect built its setup and its thread): its clock starts,
    /// the status line names its grid.
    pub fn gfmd_started(&mut self, id: u64, grid: usize, at: std::time::Instant) {
        if let Some((_, started)) = self.jobs.gfmd_running(id) {
            *started = Some(at);
            self.info(format!("GFMD started on a {grid}x{grid} grid (g cancels)"));
        }
    }

    /// A progress report of run `id`: shown if it is the running one. The start message gives
    /// way to the progress in the status line.
    pub(crate) fn on_gfmd_progress(&mut self, id: u64, report: GfmdProgress) {
        if let Some((progress, _)) = self.jobs.gfmd_running(id) {
            *progress = report;
            self.ui.spinner = self.ui.spinner.wrapping_add(1);
            self.clear_gfmd_start_message();
        }
    }

    /// The end of run `id` (if it is the running one): its outcome and time, "GFMD done in
    /// X s" in the status line; a cancelled run leaves nothing.
    pub(crate) fn on_gfmd_done(&mut self, id: u64, result: Result<GfmdView>, elapsed_s: f64) {
        let Some(scene) = self.jobs.end_gfmd(id) else {
            return;
        };
        self.clear_gfmd_start_message();
        let took = if self.ui.show_timing {
            format!(" in {}", format_secs(elapsed_s))
        } else {
            String::new()
        };
        match result {
            Err(Error::Cancelled) => {}
            Ok(v) => {
                self.info(format!("GFMD done{took}"));
                self.jobs.show_gfmd(GfmdState::Done {
                    scene,
                    result: Ok(v),
                    elapsed_s,
                });
            }
            Err(e) => {
                self.fail(format!("GFMD failed{}: {e}", took.replace(" in", " after")));
                self.jobs.show_gfmd(GfmdState::Done {
                    scene,
                    result: Err(e.to_string()),
                    elapsed_s,
                });
            }
        }
    }

    /// The status line of a running job (phase, steps, residual, time and time left; the
    /// times only with [`Ui::show_timing`](crate::tui::model::ui::Ui::show_timing)).
    pub fn gfmd_status(&self) -> Option<String> {
        match self.jobs.gfmd() {
            GfmdState::Running { progress, started, .. } => {
                Some(progress.status_text(self.ui.show_timing.then(|| self.ui.elapsed_s(*started))))
            }
            _ => None,
        }
    }

    fn clear_gfmd_start_message(&mut self) {
        if self
            .ui
            .message
            .as_ref()
            .is_some_and(|m| m.text.starts_with("GFMD started"))
        {
            self.ui.message = None;
        }
    }
}

#[cfg(test)]
#[path = "gfmd_tests.rs"]
mod tests;
