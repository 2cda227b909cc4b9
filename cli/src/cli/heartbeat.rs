//! Progress of a long headless command on stderr: after [`FIRST_S`] seconds, and then every
//! [`EVERY_S`] seconds, one updated line (`asperity sweep: working, 12 s, 40 computations
//! started`) counted by [`asperity::work::started`], for the commands that print no progress
//! of their own. Only on a terminal (a script reading stderr gets its lines unchanged) and
//! without `--quiet`; the line is cleared when the command ends. Work counted in steps shows
//! [`super::progress`]'s bar instead.

use std::io::{IsTerminal, Write};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Seconds before the first progress line.
pub const FIRST_S: f64 = 3.0;
/// Seconds between updates.
pub const EVERY_S: f64 = 2.0;

/// A running heartbeat; dropping it stops the thread and clears its line.
pub struct Heartbeat {
    done: Arc<AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

/// Starts the heartbeat of command `name` (None off a terminal).
pub fn start(name: &'static str) -> Option<Heartbeat> {
    if !std::io::stderr().is_terminal() || super::progress::is_quiet() {
        return None;
    }
    let done = Arc::new(AtomicBool::new(false));
    let flag = done.clone();
    let thread = std::thread::spawn(move || {
        let t0 = Instant::now();
        let mut next = FIRST_S;
        let mut shown = false;
        while !flag.load(Ordering::Relaxed) {
            std::thread::sleep(Duration::from_millis(100));
            let s = t0.elapsed().as_secs_f64();
            if s >= next {
                let n = asperity::work::started();
                eprint!("\rasperity {name}: working, {s:.0} s, {n} computations started ");
                let _ = std::io::stderr().flush();
                shown = true;
                next += EVERY_S;
            }
        }
        if shown {
            eprint!("\r\x1b[K");
        }
    });
    Some(Heartbeat {
        done,
        thread: Some(thread),
    })
}

impl Drop for Heartbeat {
    fn drop(&mut self) {
        self.done.store(true, Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}
