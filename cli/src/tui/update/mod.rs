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

/// Takes one message: the next state, and the commands it asks for, in order: the
/// computation of the current scene first where it changed, `Quit` last.
pub fn update(app: &mut App, msg: Msg) -> Vec<Command> {
    // the keys a reply is compared with: the scene's (set directly by a test or the loop)
    app.rekey();
    let asked = match msg {
        // the "terminal too small" screen shows nothing to act on: only quitting acts
        Msg::Key(ev) if app.ui.too_small() => {
            app.on_key_too_small(ev);
            None
        }
        Msg::Mouse(_) if app.ui.too_small() => None,
        Msg::Key(ev) => app.on_key(ev),
        Msg::Reply(r) => {
            app.on_reply(*r);
            None
        }
        Msg::Tick => {
            app.tick();
            None
        }
        Msg::Clock(now) => {
            app.ui.now = Some(now);
            None
        }
        Msg::Resize { cols, rows } => {
            app.ui.size = Some((cols, rows));
            None
        }
        Msg::PresetLoaded { source, result } => {
            app.preset_loaded(&source, result);
            None
        }
        Msg::TourLoaded(result) => {
            app.tour_loaded(result);
            None
        }
        Msg::Written(w) => {
            app.written(w);
            None
        }
        Msg::Mouse(p) => app.on_mouse(p),
        Msg::GfmdStarted { id, grid, at } => {
            app.gfmd_started(id, grid, at);
            None
        }
    };
    // a chart that came on screen (z, f, v, a resize, a tour step) is computed now
    app.follow_shown();
    let mut out: Vec<Command> = app.take_request().map(Command::Compute).into_iter().collect();
    // the keys the view compares with: computed once per change of scene or range
    app.rekey();
    out.extend(asked);
    if app.ui.quit {
        out.push(Command::Quit);
    }
    out
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
