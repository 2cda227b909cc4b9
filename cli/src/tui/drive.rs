//! The update loop without a terminal or threads, for tests and deterministic rendering:
//! a message goes through [`update`], the files it asks to read are read at once and their
//! messages fed back, a GFMD run it cancels is told to stop, and the rest of its commands are
//! returned to the caller; [`compute_now`] serves the last computation asked for on the
//! calling thread (kept per thread, outside the state, as the event loop keeps its commands).

pub use crate::tui::base::protocol::Reply;
use crate::tui::base::protocol::Request;
use crate::tui::effects::worker::process;
pub use crate::tui::effects::worker::Caches;
use crate::tui::effects::{self, load};
use crate::tui::model::app::App;
use crate::tui::model::command::Command;
use crate::tui::model::msg::Msg;
use crate::tui::update::update;
use ratatui::crossterm::event::KeyEvent;
use std::cell::Cell;
use std::collections::VecDeque;
use std::sync::atomic::AtomicBool;

thread_local! {
    /// The last computation an update returned through [`send`] on this thread, until
    /// [`compute_now`] serves it (a newer one supersedes it).
    static ASKED: Cell<Option<Request>> = const { Cell::new(None) };
}

/// Feeds `msg` to the update; reads what it asks to read (a preset, a tour) and feeds that
/// back, tells a cancelled GFMD run to stop; returns every command the updates asked for, in
/// order (files to write, GFMD runs, the computations, `Quit`). The last computation is also
/// kept for [`compute_now`].
pub fn send(app: &mut App, msg: Msg) -> Vec<Command> {
    let mut inbox = VecDeque::from([msg]);
    let mut out = Vec::new();
    while let Some(m) = inbox.pop_front() {
        for cmd in update(app, m) {
            effects::cancel_gfmd(&cmd);
            if let Command::Compute(req) = &cmd {
                ASKED.set(Some(req.clone()));
            }
            if let Some(next) = load::run(&cmd) {
                inbox.push_back(next);
            }
            out.push(cmd);
        }
    }
    out
}

/// A key press through [`send`]; the commands it asked for.
pub fn press(app: &mut App, ev: KeyEvent) -> Vec<Command> {
    send(app, Msg::Key(ev))
}

/// The computation [`compute_now`] would serve, taken: the state's own request where a
/// handler asked for one (the newest), else the last one [`send`] returned.
pub fn take_compute(app: &mut App) -> Option<Request> {
    let asked = ASKED.take();
    app.take_request().or(asked)
}

/// Serves the computation `app` asked for on the calling thread, feeding the replies back
/// (no thread, no cancellation): the state's own request where a test called a handler
/// directly (the newest), else the last one an update returned through [`send`].
pub fn compute_now(app: &mut App, caches: &mut Caches) {
    while let Some(req) = take_compute(app) {
        let replies = std::cell::RefCell::new(Vec::new());
        process(&req, caches, &AtomicBool::new(false), &|| false, &|r| {
            replies.borrow_mut().push(r)
        });
        for r in replies.into_inner() {
            send(app, Msg::Reply(Box::new(r)));
        }
    }
}
