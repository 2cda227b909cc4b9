//! serde values as Python objects: the library's serialisable results (the same values the
//! CLI writes as JSON) become dicts, lists, floats, ints, strings, bools and None, so that a
//! result compares key by key with `asperity ... --format json`. A non-finite number, which
//! JSON writes as null, is None here too.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde_json::Value;

/// `v` as a Python object.
pub fn to_py<'py>(py: Python<'py>, v: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
        Value::Number(n) => {
            if let Some(u) = n.as_u64() {
                u.into_pyobject(py)?.into_any()
            } else if let Some(i) = n.as_i64() {
                i.into_pyobject(py)?.into_any()
            } else {
                n.as_f64().unwrap_or(f64::NAN).into_pyobject(py)?.into_any()
            }
        }
        Value::String(s) => s.into_pyobject(py)?.into_any(),
        Value::Array(a) => {
            let items = a.iter().map(|x| to_py(py, x)).collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, items)?.into_any()
        }
        Value::Object(m) => {
            let d = PyDict::new(py);
            for (k, x) in m {
                d.set_item(k, to_py(py, x)?)?;
            }
            d.into_any()
        }
    })
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
