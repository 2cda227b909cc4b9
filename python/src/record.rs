//! Result objects built once, in Rust, from the library's serialisable values (the keys and
//! numbers of the CLI's JSON):
//!
//! - [`Record`]: a frozen object whose attributes are a value's keys, each converted once when
//!   the record is made: an object becomes a record, a list of objects a list of records, a
//!   list of numbers a read-only float64 numpy array (null as NaN), anything else the plain
//!   value (`r.x is r.x`);
//! - `record_methods!`: the dict-like methods every result class shares: `to_dict()` (a
//!   fresh plain dict, JSON types only, unavailable values None), `keys()`, `r["key"]`,
//!   `"key" in r`, iteration over the keys and a short `repr`.
//!
//! A non-finite number, which JSON writes as null, is None in `to_dict()` as in the CLI's
//! output.

use crate::value;
use numpy::PyArray1;
use pyo3::exceptions::{PyAttributeError, PyKeyError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde_json::Value;
use std::sync::Arc;

/// `v` as a read-only float64 numpy array (a caller cannot change the one the result keeps;
/// `np.array(a)` gives a copy to write to).
pub fn array(py: Python<'_>, v: Vec<f64>) -> PyResult<Py<PyArray1<f64>>> {
    let a = PyArray1::from_vec(py, v);
    a.getattr("flags")?.setattr("writeable", false)?;
    Ok(a.unbind())
}

/// The numbers of a JSON list (null as NaN); None where an item is anything else.
fn numbers(items: &[Value]) -> Option<Vec<f64>> {
    items
        .iter()
        .map(|x| match x {
            Value::Null => Some(f64::NAN),
            Value::Number(n) => n.as_f64(),
            _ => None,
        })
        .collect()
}

/// A JSON value as an attribute (module docs).
pub fn attr(py: Python<'_>, v: &Value) -> PyResult<Py<PyAny>> {
    Ok(match v {
        Value::Object(_) => Py::new(py, Record::new(py, Arc::new(v.clone()))?)?.into_any(),
        Value::Array(items) if !items.is_empty() && items.iter().all(Value::is_object) => {
            let records = items.iter().map(|x| attr(py, x)).collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, records)?.into_any().unbind()
        }
        Value::Array(items) => match numbers(items) {
            Some(xs) => array(py, xs)?.into_any(),
            None => value::to_py(py, v)?.unbind(),
        },
        _ => value::to_py(py, v)?.unbind(),
    })
}

/// The keys of an object value (none for anything else).
pub fn keys(data: &Value) -> Vec<String> {
    data.as_object()
        .map(|m| m.keys().cloned().collect())
        .unwrap_or_default()
}

/// `data[key]` as a plain Python value; KeyError where it has no such key.
pub fn item<'py>(py: Python<'py>, data: &Value, key: &str) -> PyResult<Bound<'py, PyAny>> {
    match data.get(key) {
        Some(v) => value::to_py(py, v),
        None => Err(PyKeyError::new_err(key.to_string())),
    }
}

/// Whether `key` is a string and one of `data`'s keys.
pub fn contains(data: &Value, key: &Bound<'_, PyAny>) -> bool {
    key.extract::<String>().is_ok_and(|k| data.get(&k).is_some())
}

/// `Class(k=v, ..., ...)` of the keys `shown` (None: the first eight keys with a scalar value),
/// the class's name read from the object (a Python subclass shows its own).
pub fn repr(obj: &Bound<'_, PyAny>, data: &Value, shown: Option<&[&str]>) -> PyResult<String> {
    let py = obj.py();
    let name = obj.get_type().name()?.to_string();
    let scalar = |v: &Value| !(v.is_object() || v.is_array());
    let picked: Vec<(&str, &Value)> = match (shown, data.as_object()) {
        (_, None) => Vec::new(),
        (Some(keys), Some(m)) => keys.iter().map(|k| (*k, m.get(*k).unwrap_or(&Value::Null))).collect(),
        (None, Some(m)) => m
            .iter()
            .filter(|(_, v)| scalar(v))
            .take(8)
            .map(|(k, v)| (k.as_str(), v))
            .collect(),
    };
    let mut parts = Vec::with_capacity(picked.len() + 1);
    for (k, v) in picked {
        parts.push(format!("{k}={}", value::to_py(py, v)?.repr()?));
    }
    parts.push("...".into());
    Ok(format!("{name}({})", parts.join(", ")))
}

/// The dict-like methods of a result class with a field `data: Arc<Value>` (module docs), and
/// the class's own methods after them (one `#[pymethods]` block per class).
macro_rules! record_methods {
    ($ty:ident, $shown:expr, { $($extra:tt)* }) => {
        #[pymethods]
        impl $ty {
            /// A fresh plain dict: the keys and numbers of the CLI's JSON, JSON types only,
            /// unavailable values None.
            fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                $crate::value::to_py(py, &self.data)
            }

            /// The field names (the JSON keys).
            fn keys(&self) -> Vec<String> {
                $crate::record::keys(&self.data)
            }

            fn __getitem__<'py>(&self, py: Python<'py>, key: &str) -> PyResult<Bound<'py, PyAny>> {
                $crate::record::item(py, &self.data, key)
            }

            fn __contains__(&self, key: &Bound<'_, PyAny>) -> bool {
                $crate::record::contains(&self.data, key)
            }

            fn __iter__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyIterator>> {
                pyo3::types::PyList::new(py, $crate::record::keys(&self.data))?.try_iter()
            }

            fn __repr__(slf: &Bound<'_, Self>) -> PyResult<String> {
                $crate::record::repr(slf.as_any(), &slf.get().data, $shown)
            }

            $($extra)*
        }
    };
}
pub(crate) use record_methods;

/// A column of `rows` as a read-only array: bools as bool, strings as str, numbers as float64
/// (null as NaN); anything else as a plain list.
fn column(py: Python<'_>, rows: &[Value], key: &str) -> PyResult<Py<PyAny>> {
    let col: Vec<Value> = rows
        .iter()
        .map(|r| r.get(key).cloned().unwrap_or(Value::Null))
        .collect();
    if let Some(xs) = numbers(&col) {
        return Ok(array(py, xs)?.into_any());
    }
    let typed = if col.iter().all(Value::is_boolean) {
        let bools: Vec<bool> = col.iter().map(|v| v.as_bool().unwrap_or(false)).collect();
        PyArray1::from_vec(py, bools).into_any()
    } else if col.iter().all(Value::is_string) {
        let kw = PyDict::new(py);
        kw.set_item("dtype", "str")?;
        let list = value::to_py(py, &Value::Array(col))?;
        py.import("numpy")?.call_method("array", (list,), Some(&kw))?
    } else {
        return Ok(value::to_py(py, &Value::Array(col))?.unbind());
    };
    typed.getattr("flags")?.setattr("writeable", false)?;
    Ok(typed.unbind())
}

/// A result part read as attributes: the keys of a library value, each converted once (module
/// docs), and where it has `rows` (a list of objects) each row key not among its own as a
/// column array (`res.a_r`); `to_dict()` gives the plain dict. `Record(d)` makes one from a
/// plain dict (or shares another's), so that a Python subclass (`SweepResult`) wraps one.
#[pyclass(module = "asperity._native", frozen, subclass)]
pub struct Record {
    /// The attributes by key, built once.
    attrs: Arc<Py<PyDict>>,
    /// The value, for `to_dict()` and `r["key"]`.
    data: Arc<Value>,
}

impl Record {
    /// The record of an object value (no attributes for anything else).
    pub fn new(py: Python<'_>, data: Arc<Value>) -> PyResult<Record> {
        let attrs = PyDict::new(py);
        if let Value::Object(m) = &*data {
            for (k, v) in m {
                attrs.set_item(k, attr(py, v)?)?;
            }
            if let Some(Value::Array(rows)) = m.get("rows") {
                if let Some(Value::Object(first)) = rows.first() {
                    for k in first.keys().filter(|k| !m.contains_key(*k)) {
                        attrs.set_item(k, column(py, rows, k)?)?;
                    }
                }
            }
        }
        Ok(Record {
            attrs: Arc::new(attrs.unbind()),
            data,
        })
    }

    /// Adds (or replaces) the attribute `name`, one that is not a key of the value.
    pub fn with_attr(self, py: Python<'_>, name: &str, v: Py<PyAny>) -> PyResult<Record> {
        self.attrs.bind(py).set_item(name, v)?;
        Ok(self)
    }
}

record_methods!(Record, None, {
    /// `Record(d)`: the record of a plain dict `d` (JSON types), or one sharing the record `d`.
    #[new]
    fn py_new(py: Python<'_>, source: &Bound<'_, PyAny>) -> PyResult<Record> {
        if let Ok(r) = source.cast::<Record>() {
            let r = r.get();
            return Ok(Record {
                attrs: Arc::clone(&r.attrs),
                data: Arc::clone(&r.data),
            });
        }
        let text: String = py.import("json")?.call_method1("dumps", (source,))?.extract()?;
        let data: Value = serde_json::from_str(&text).map_err(|e| PyValueError::new_err(e.to_string()))?;
        Record::new(py, Arc::new(data))
    }

    fn __getattr__(slf: &Bound<'_, Self>, name: &str) -> PyResult<Py<PyAny>> {
        let me = slf.get();
        match me.attrs.bind(slf.py()).get_item(name)? {
            Some(v) => Ok(v.unbind()),
            None => Err(PyAttributeError::new_err(format!(
                "{} has no field or column '{name}' (fields: {})",
                slf.get_type().name()?,
                keys(&me.data).join(", ")
            ))),
        }
    }

    fn __dir__(slf: &Bound<'_, Self>) -> PyResult<Vec<String>> {
        let own: Vec<String> = slf
            .py()
            .get_type::<pyo3::types::PyAny>()
            .getattr("__dir__")?
            .call1((slf,))?
            .extract()?;
        let attrs: Vec<String> = slf.get().attrs.bind(slf.py()).keys().extract()?;
        let mut all: Vec<String> = own.into_iter().chain(attrs).collect();
        all.sort();
        all.dedup();
        Ok(all)
    }
});
