//! The update: a message ([`Msg`]: a key, a reply, a tick, what an effect found) → the next
//! state ([`App`]) plus the [`Command`]s it asks for (a GFMD run to start or a preset, tour or
//! file to read or write, quitting). [`update`] is pure: no terminal, no threads, no clock
//! read (the instants it keeps come in messages), no file read or written, so every message is unit-tested
//! (`update_tests.rs`). The computation of the current scene is one of the commands: an
//! update that changed the scene or the charts shown returns [`Command::Compute`] first (the
//! event loop submits the last of a burst, the worker drops superseded ones).
//!
//! The handlers each change one part of the state, one idea per file: [`key`] (keys, the
//! overlays, typing), [`action`] (the key table's actions), [`turn`] (a knob stepped or
//! typed), [`models`] (the model cycle), [`scene`] (a new scene or preset, the load
//! history), [`tour`] (walking a tour), [`reply`] (the worker's replies), [`gfmd`] (`g` and
//! the GFMD run), [`mouse`] (`--mouse`), [`pin`] (`P`), [`scales`] (the scale view's frames), [`files`] (what `e`
//! and `s` wrote).

pub mod action;
pub mod files;
pub mod gfmd;
pub mod key;
pub mod models;
pub mod mouse;
pub mod pin;
pub mod reply;
pub mod scales;
pub mod scene;
pub mod tour;
pub mod turn;

use crate::tui::model::app::{App, Command};
use crate::tui::model::msg::Msg;
use asperity::input::scene::Scene;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// Takes one message: the next state, and the commands it asks for, in order (`Quit` last).
pub fn update(app: &mut App, msg: Msg) -> Vec<Command> {
    match msg {
        // the "terminal too small" screen shows nothing to act on: only quitting acts
        Msg::Key(ev) if app.ui.too_small() => app.on_key_too_small(ev),
        Msg::Mouse(_) if app.ui.too_small() => {}
        Msg::Key(ev) => app.on_key(ev),
        Msg::Reply(r) => app.on_reply(*r),
        Msg::Tick => app.tick(),
        Msg::Clock(now) => app.ui.now = Some(now),
        Msg::Resize { cols, rows } => app.ui.size = Some((cols, rows)),
        Msg::PresetLoaded { source, result } => app.preset_loaded(&source, result),
        Msg::TourLoaded(result) => app.tour_loaded(result),
        Msg::Written(w) => app.written(w),
        Msg::Mouse(p) => app.on_mouse(p),
        Msg::GfmdStarted { id, grid, at } => app.gfmd_started(id, grid, at),
    }
    // a chart that came on screen (z, f, v, a resize, a tour step) is computed now
    app.follow_shown();
    app.take_commands()
}

impl App {
    /// The commands the handlers asked for since the last call, `Quit` last when asked.
    fn take_asked(&mut self) -> Vec<Command> {
        let mut out = std::mem::take(&mut self.jobs.commands);
        if self.ui.quit {
            out.push(Command::Quit);
        }
        out
    }

    /// Every command queued since the last call (by [`crate::tui::drive`], or by handlers
    /// called directly), the computation of the current scene first when it changed (the last
    /// one asked for: it supersedes the others): what the event loop would run before the
    /// next frame.
    pub fn take_commands(&mut self) -> Vec<Command> {
        let mut out: Vec<Command> = self.take_compute().map(Command::Compute).into_iter().collect();
        out.append(&mut self.take_asked());
        out
    }

    /// The computation to run now: the state's own request where the scene changed since the
    /// last one, else the last [`Command::Compute`] queued by [`crate::tui::drive::send`]
    /// (the queued ones are removed: the last supersedes the others).
    pub fn take_compute(&mut self) -> Option<crate::tui::model::protocol::Request> {
        let mut queued = None;
        self.jobs.commands.retain(|c| match c {
            Command::Compute(r) => {
                queued = Some(r.clone());
                false
            }
            _ => true,
        });
        self.take_request().or(queued)
    }

    /// The GFMD run to start, if `g` asked for one: its id, scene and cancel flag.
    pub fn take_gfmd_request(&mut self) -> Option<(u64, Scene, Arc<AtomicBool>)> {
        let i = self
            .jobs
            .commands
            .iter()
            .position(|c| matches!(c, Command::StartGfmd { .. }))?;
        match self.jobs.commands.remove(i) {
            Command::StartGfmd { id, scene, cancel } => Some((id, scene, cancel)),
            _ => None,
        }
    }
}

#[cfg(test)]
#[path = "update_tests.rs"]
mod tests;

#[cfg(test)]
#[path = "keys_tests.rs"]
mod keys_tests;

#[cfg(test)]
#[path = "msg_tests.rs"]
mod msg_tests;
