//! The library's typed errors as Python exceptions (the classes live in
//! `asperity/_errors.py`, so that they are plain Python classes with documented attributes).
//!
//! - [`Error::Invalid`] and [`Error::InvalidField`] → `InputError(ValueError)` with `.field`
//!   (the Python argument's name: the last segment of the library's canonical key, `model` for
//!   the variant), `.key` (the canonical key), `.value` and `.allowed` (the range in words);
//! - [`Error::Unsupported`] and [`Error::Preset`] → `InputError` with the field where there is one;
//! - [`Error::NotConverged`] → `NotConverged(RuntimeError)` with `.solver` and `.reason`;
//! - [`Error::Io`] → `OSError` (`FileNotFoundError` for a missing file);
//! - [`Error::Cancelled`] → `KeyboardInterrupt` (a cancel without a pending Python exception);
//! - a Rust panic → `InternalError(RuntimeError)` with the panic's message.

use asperity::error::{Error, Field};
use pyo3::exceptions::{PyFileNotFoundError, PyKeyboardInterrupt, PyOSError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The Python argument name of a library field: the key's last segment (`load.thickness_qr`
/// → `thickness_qr`), `model` for the variant, `from_` for a sweep's first load (`from` is a
/// Python keyword).
pub fn python_name(field: &Field) -> String {
    match field {
        Field::Model => "model".into(),
        Field::HeightMap => "heights".into(),
        Field::SystemSize => "system_size_m".into(),
        Field::SweepFrom => "from_".into(),
        Field::Other(k) => {
            let k = k.trim_start_matches('-').replace('-', "_");
            k.rsplit('.').next().unwrap_or(&k).to_string()
        }
        f => f.short().to_string(),
    }
}

/// Builds an exception of class `name` from `asperity._errors` with `message` and keyword
/// attributes.
fn raise(py: Python<'_>, name: &str, message: String, attrs: &[(&str, Option<String>)]) -> PyErr {
    let build = || -> PyResult<PyErr> {
        let cls = py.import("asperity._errors")?.getattr(name)?;
        let kw = PyDict::new(py);
        for (k, v) in attrs {
            kw.set_item(*k, v.clone())?;
        }
        let obj = cls.call((message.clone(),), Some(&kw))?;
        Ok(PyErr::from_value(obj))
    };
    build().unwrap_or_else(|e| e)
}

/// The Python exception of a library error.
pub fn to_py(py: Python<'_>, e: Error) -> PyErr {
    match &e {
        Error::Invalid { field, value, allowed } => {
            let name = python_name(field);
            invalid(py, &name, field.key(), value, &allowed.describe(&name))
        }
        Error::InvalidField { field, value, allowed } => {
            let name = field.trim_start_matches('-').replace('-', "_");
            invalid(py, &name, field, value, &allowed.describe(&name))
        }
        Error::Unsupported(_) => raise(py, "InputError", e.to_string(), &[("field", Some("model".into()))]),
        Error::Preset { source, .. } => raise(
            py,
            "InputError",
            e.to_string(),
            &[("field", Some("preset".into())), ("value", Some(source.clone()))],
        ),
        Error::NotConverged { solver, reason } => raise(
            py,
            "NotConverged",
            e.to_string(),
            &[("solver", Some(solver.to_string())), ("reason", Some(reason.clone()))],
        ),
        Error::Io { kind, .. } if *kind == std::io::ErrorKind::NotFound => PyFileNotFoundError::new_err(e.to_string()),
        Error::Io { .. } => PyOSError::new_err(e.to_string()),
        Error::Cancelled => PyKeyboardInterrupt::new_err("cancelled"),
        _ => raise(py, "InputError", e.to_string(), &[]),
    }
}

/// An `InputError` about the argument `name` (the library's key `key`): its value and the
/// allowed range in words.
fn invalid(py: Python<'_>, name: &str, key: &str, value: &str, allowed: &str) -> PyErr {
    raise(
        py,
        "InputError",
        format!("invalid {name} = {value}: allowed {allowed}"),
        &[
            ("field", Some(name.to_string())),
            ("key", Some(key.to_string())),
            ("value", Some(value.to_string())),
            ("allowed", Some(allowed.to_string())),
        ],
    )
}

/// An `InputError` about a Python argument that the library never sees (a type, a shape).
pub fn input(py: Python<'_>, field: &str, value: &str, allowed: &str) -> PyErr {
    invalid(py, field, field, value, allowed)
}

/// The `InternalError` of a Rust panic (its payload's message).
pub fn panic(py: Python<'_>, payload: Box<dyn std::any::Any + Send>) -> PyErr {
    let msg = payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic without a message".into());
    raise(
        py,
        "InternalError",
        format!("internal error (a Rust panic): {msg}"),
        &[],
    )
}

/// Runs `f`, turning a library error into its exception and a panic into `InternalError`.
pub fn guard<T>(py: Python<'_>, f: impl FnOnce() -> asperity::Result<T>) -> PyResult<T> {
    settle(py, std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)))
}

/// [`guard`] with the GIL released while `f` runs, so that other Python threads run beside a
/// call that reads, generates or analyses a map (work too short for a worker thread and its
/// cancel flag, [`crate::work::run`], but long enough to stall a notebook's other threads).
pub fn detached<T, F>(py: Python<'_>, f: F) -> PyResult<T>
where
    T: Send,
    F: FnOnce() -> asperity::Result<T> + Send,
{
    let r = py.detach(move || std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)));
    settle(py, r)
}

/// The value, or the exception of a library error or a panic.
fn settle<T>(py: Python<'_>, r: std::thread::Result<asperity::Result<T>>) -> PyResult<T> {
    match r {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(e)) => Err(to_py(py, e)),
        Err(p) => Err(panic(py, p)),
    }
}
