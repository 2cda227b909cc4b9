//! Runs the explorer's commands in the calling thread, for tests and headless use: the
//! computation the state asks for, its replies fed back through the update.

use crate::tui::effects::worker::process;
pub use crate::tui::effects::worker::Caches;
use crate::tui::model::app::App;
pub use crate::tui::model::protocol::Reply;
use std::sync::atomic::AtomicBool;

/// Serves every pending request of `app` on the calling thread, feeding the replies back
/// (no thread, no cancellation): for tests and deterministic rendering.
pub fn compute_now(app: &mut App, caches: &mut Caches) {
    while let Some(req) = app.take_request() {
        let replies = std::cell::RefCell::new(Vec::new());
        process(&req, caches, &AtomicBool::new(false), &|| false, &|r| {
            replies.borrow_mut().push(r)
        });
        for r in replies.into_inner() {
            app.on_reply(r);
        }
    }
}
