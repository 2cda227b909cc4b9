//! serde values as Python objects: the library's serialisable results (the same values the
//! CLI writes as JSON) become dicts, lists, floats, ints, strings, bools and None, so that a
//! result compares key by key with `asperity ... --format json`. A non-finite number, which
//! JSON writes as null, is None here too.

use pyo3::prelude::*;
use serde_json::Value;

/// `v` as a Python object.
pub fn to_py<'py>(py: Python<'py>, v: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(pythonize::pythonize(py, v)?)
}

/// A serialisable value as a JSON value (the CLI's JSON of it).
pub fn json<T: serde::Serialize>(x: &T) -> PyResult<Value> {
    serde_json::to_value(x).map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))
}

/// A serialisable value as a Python object (through [`json`]).
pub fn ser<'py, T: serde::Serialize>(py: Python<'py>, x: &T) -> PyResult<Bound<'py, PyAny>> {
    to_py(py, &json(x)?)
}

/// An object value with `preset` first (as the CLI writes `run`'s JSON).
pub fn with_preset(preset: &str, v: Value) -> Value {
    let mut m = serde_json::Map::new();
    m.insert("preset".into(), Value::String(preset.to_string()));
    if let Value::Object(o) = v {
        m.extend(o);
    }
    Value::Object(m)
}
