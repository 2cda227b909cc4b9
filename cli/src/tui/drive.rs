//! The update loop without a terminal or threads, for tests and deterministic rendering:
//! a message goes through [`update`], the files it asks to read are read at once and their
//! messages fed back, a GFMD run it cancels is told to stop, and the rest of its commands wait
//! in the state's queue as they would for the event loop's next frame
//! ([`App::take_commands`]); [`compute_now`] serves the computation on the calling thread.

use crate::tui::effects::worker::process;
pub use crate::tui::effects::worker::Caches;
use crate::tui::effects::{self, load};
use crate::tui::model::app::App;
use crate::tui::model::command::Command;
use crate::tui::model::msg::Msg;
pub use crate::tui::model::protocol::Reply;
use crate::tui::update::update;
use ratatui::crossterm::event::KeyEvent;
use std::collections::VecDeque;
use std::sync::atomic::AtomicBool;

/// Feeds `msg` to the update; reads what it asks to read (a preset, a tour) and feeds that
/// back; queues the other commands (files to write, GFMD runs) in the state.
pub fn send(app: &mut App, msg: Msg) {
    let mut inbox = VecDeque::from([msg]);
    while let Some(m) = inbox.pop_front() {
        for cmd in update(app, m) {
            if effects::cancel_gfmd(&cmd) {
                continue;
            }
            match load::run(&cmd) {
                Some(next) => inbox.push_back(next),
                // quitting is the state's own flag
                None if matches!(cmd, Command::Quit) => {}
                None => app.jobs.commands.push(cmd),
            }
        }
    }
}

/// A key press through [`send`].
pub fn press(app: &mut App, ev: KeyEvent) {
    send(app, Msg::Key(ev));
}

/// Serves the computation `app` asked for on the calling thread, feeding the replies back
/// (no thread, no cancellation): the last [`Command::Compute`] an update returned (queued by
/// [`send`]), or the state's own request where a test called a handler directly.
pub fn compute_now(app: &mut App, caches: &mut Caches) {
    while let Some(req) = app.take_compute() {
        let replies = std::cell::RefCell::new(Vec::new());
        process(&req, caches, &AtomicBool::new(false), &|| false, &|r| {
            replies.borrow_mut().push(r)
        });
        for r in replies.into_inner() {
            send(app, Msg::Reply(Box::new(r)));
        }
    }
}
