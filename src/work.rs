//! A count of the computations started in this process (theory evaluations, load sweeps,
//! GFMD relaxations, PSD analyses, generated surfaces, fits), so that a front end can show
//! that input it refused started none: its checks run before any work, not after.
//!
//! The count is a relaxed atomic: it orders nothing and changes no result. A front end's
//! test mode may [`forbid`] work: a computation that starts then panics at once, naming
//! itself, instead of running (a check that came too late shows as that panic).

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

static STARTED: AtomicUsize = AtomicUsize::new(0);
static FORBIDDEN: AtomicBool = AtomicBool::new(false);

/// Records that a computation starts.
///
/// # Panics
/// After [`forbid`]: the input should have been refused before any work.
pub fn start() {
    STARTED.fetch_add(1, Ordering::Relaxed);
    assert!(
        !FORBIDDEN.load(Ordering::Relaxed),
        "a computation started although work was forbidden (input checked too late)"
    );
}

/// Makes every later [`start`] panic (a test mode: input must be refused before work).
pub fn forbid() {
    FORBIDDEN.store(true, Ordering::Relaxed);
}

/// How many computations have started in this process.
///
/// # Examples
/// ```
/// let before = asperity::work::started();
/// asperity::work::start();
/// assert!(asperity::work::started() > before);
/// ```
pub fn started() -> usize {
    STARTED.load(Ordering::Relaxed)
}
