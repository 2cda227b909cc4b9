//! Long work off the interpreter: the computation runs on a worker thread without the GIL
//! while the calling thread wakes every [`POLL`] to deliver progress to the Python callback
//! and to check for signals. Ctrl-C (a KeyboardInterrupt from `check_signals`), an exception
//! raised by the progress callback, or any other pending Python exception sets the library's
//! cancel flag; the solvers see it within one step (GFMD) or one march (the adhesive solver),
//! and the exception is raised once the worker has stopped, or after [`GRACE`] at the latest
//! (the worker then stops at its next check, in the background). A panic on the worker
//! becomes `InternalError`.

use crate::errors;
use asperity::Result;
use pyo3::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// How often the calling thread checks for Ctrl-C and delivers progress.
pub const POLL: Duration = Duration::from_millis(50);

/// One progress report: the stage and its numbers (a dict on the Python side).
#[derive(Debug, Clone, Default, serde::Serialize)]
pub struct Info {
    /// "relax" (GFMD relaxation), "theory" (the theory on a GFMD map), "sweep" (values done).
    pub stage: &'static str,
    /// Relaxation steps, or values done.
    pub done: usize,
    /// Values in all (sweeps; 0 where unknown).
    pub total: usize,
    /// GFMD's relative force residual (NaN for sweeps).
    pub residual: f64,
    /// GFMD's contact fraction (NaN for sweeps).
    pub contact_fraction: f64,
}

impl Info {
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(pythonize::pythonize(py, self)?)
    }
}

/// What the work gets: the cancel flag and a way to report progress.
pub struct Ctx {
    /// Set when the caller wants the work to stop.
    pub cancel: Arc<AtomicBool>,
    tx: mpsc::Sender<Info>,
}

impl Ctx {
    /// Sends a progress report (dropped if the caller has gone).
    pub fn report(&self, info: Info) {
        let _ = self.tx.send(info);
    }
}

/// How long a cancelled call waits for the worker to stop before it raises anyway: the
/// solvers stop within one step, but a phase that watches no flag (preparing a GFMD map, one
/// evaluation of the theory) finishes in the background, its result dropped.
pub const GRACE: Duration = Duration::from_millis(250);

/// Runs `work` on a worker thread with the GIL released (see the module docs).
pub fn run<T, F>(py: Python<'_>, progress: Option<&Bound<'_, PyAny>>, work: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce(&Ctx) -> Result<T> + Send + 'static,
{
    let cancel = Arc::new(AtomicBool::new(false));
    let (tx, rx) = mpsc::channel::<Info>();
    let ctx = Ctx {
        cancel: Arc::clone(&cancel),
        tx,
    };
    let handle = std::thread::Builder::new()
        .name("asperity-work".into())
        .spawn(move || work(&ctx))
        .map_err(|e| errors::to_py(py, asperity::Error::io("start the worker thread", e)))?;
    let mut pending: Option<PyErr> = None;
    let mut deadline: Option<Instant> = None;
    let mut rx = rx;
    loop {
        let (first, back) = py.detach(move || (rx.recv_timeout(POLL), rx));
        rx = back;
        let mut latest = match first {
            Ok(i) => Some(i),
            Err(RecvTimeoutError::Timeout) => None,
            Err(RecvTimeoutError::Disconnected) => break,
        };
        // deliver only the newest report of a burst
        while let Ok(i) = rx.try_recv() {
            latest = Some(i);
        }
        if pending.is_none() {
            if let (Some(info), Some(cb)) = (latest, progress) {
                if let Err(e) = info.to_dict(py).and_then(|d| cb.call1((d,))) {
                    pending = Some(e);
                }
            }
        }
        if pending.is_none() {
            if let Err(e) = py.check_signals() {
                pending = Some(e);
            }
        }
        if pending.is_some() {
            cancel.store(true, Ordering::Relaxed);
            let d = *deadline.get_or_insert_with(|| Instant::now() + GRACE);
            if Instant::now() >= d {
                // the worker stops at its next check of the flag, its result dropped
                return Err(pending.take().expect("pending"));
            }
        }
    }
    let joined = py.detach(move || handle.join());
    match (pending, joined) {
        (Some(e), _) => Err(e),
        (None, Ok(Ok(v))) => Ok(v),
        (None, Ok(Err(e))) => Err(errors::to_py(py, e)),
        (None, Err(p)) => Err(errors::panic(py, p)),
    }
}
