//! Result objects built once, in Rust, from the library's serialisable values (the keys and
//! numbers of the CLI's JSON):
//!
//! - [`Record`]: a frozen object whose attributes are a value's keys, each converted once when
//!   the record is made: an object becomes a record, a list of objects a list of records, a
//!   list of numbers a read-only float64 numpy array (null as NaN), anything else the plain
//!   value (`r.x is r.x`); the keys of its `rows` (or a PSD's `table`) as column arrays; a GFMD
//!   result's map as `heights`, outside `to_dict()`; a Python subclass's `_parts` (its typed
//!   parts) made once when it is made;
//! - `record_methods!`: the dict-like methods every result class shares: `to_dict()` (a
//!   fresh plain dict, JSON types only, unavailable values None), `keys()`, `r["key"]`,
//!   `"key" in r`, iteration over the keys, a short `repr`, `Class(d)` and pickling.
//!
//! Values cross with pythonize. A non-finite number, which JSON writes as null, is None in
//! `to_dict()` as in the CLI's output.

use crate::value;
use numpy::PyArray1;
use pyo3::exceptions::{PyAttributeError, PyKeyError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyType};
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

/// A plain Python value (JSON types: None, bools, ints, floats, strings, lists, tuples and
/// dicts with string keys) as a JSON value, every float exactly; a non-finite float as null,
/// as `to_dict()` has it.
fn plain(source: &Bound<'_, PyAny>) -> PyResult<Value> {
    pythonize::depythonize(source).map_err(|e| {
        PyValueError::new_err(format!(
            "not a plain value (None, bool, int, float, str, list or dict): {e}"
        ))
    })
}

/// A result class made from its value (the CLI's JSON object).
pub trait FromValue: Sized {
    /// The result of `data`.
    ///
    /// # Errors
    /// A Python error while its arrays or parts are made.
    fn from_value(py: Python<'_>, data: Arc<Value>) -> PyResult<Self>;

    /// The result of a plain dict (JSON types, as `to_dict()` gives them).
    ///
    /// # Errors
    /// `ValueError` for anything JSON cannot hold.
    fn from_source(py: Python<'_>, source: &Bound<'_, PyAny>) -> PyResult<Self> {
        Self::from_value(py, Arc::new(plain(source)?))
    }

    /// `cls(source)`: the result of `source` for the class `cls` (a Python subclass included).
    ///
    /// # Errors
    /// As [`FromValue::from_source`].
    fn from_class(cls: &Bound<'_, PyType>, source: &Bound<'_, PyAny>) -> PyResult<Self> {
        Self::from_source(cls.py(), source)
    }
}

/// The dict-like methods of a result class with a field `data: Arc<Value>` (module docs),
/// `Class(d)` from a plain dict ([`FromValue`]), pickling through it, and the class's own
/// methods after them (one `#[pymethods]` block per class).
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

            /// `Class(d)`: the result of a plain dict `d` with the keys of `to_dict()` (how a
            /// pickled result returns).
            #[new]
            #[classmethod]
            fn py_new(cls: &Bound<'_, pyo3::types::PyType>, source: &Bound<'_, PyAny>) -> PyResult<Self> {
                <Self as $crate::record::FromValue>::from_class(cls, source)
            }

            fn __reduce__<'py>(
                slf: &Bound<'py, Self>,
            ) -> PyResult<(Bound<'py, pyo3::types::PyType>, (Bound<'py, PyAny>,))> {
                let d = $crate::value::to_py(slf.py(), &slf.get().data)?;
                Ok((slf.get_type(), ($crate::record::with_map(slf.as_any(), d)?,)))
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

/// A sweep's values (its `over`: "pressure", "thickness" or "gamma"): the rows' p*, t·q_r (∞
/// where null: a half-space) or γ_s; None for anything that is not a sweep.
fn swept(over: Option<&Value>, rows: &[Value]) -> Option<Vec<f64>> {
    let key = match over?.as_str()? {
        "pressure" => "p",
        "thickness" => "thickness_qr",
        "gamma" => "gamma",
        _ => return None,
    };
    Some(rows.iter().map(|r| r[key].as_f64().unwrap_or(f64::INFINITY)).collect())
}

/// The attribute of a GFMD result that holds the map it ran on (m, rows along y): not a key
/// of its value (the CLI's JSON has no map), kept through pickling.
const MAP: &str = "heights";

/// A result part read as attributes: the keys of a library value, each converted once (module
/// docs), and where it has `rows` or `table` (a list of objects) each of their keys not among
/// its own as a column array (`res.a_r`, `psd.q`), for a sweep also `values` (the swept
/// knob's); `to_dict()` gives the plain dict. `Record(d)` makes one from a plain dict (or
/// shares another's), so that a Python subclass (`SweepResult`) wraps one; a subclass's
/// `_parts` (name → function of the attribute, None where absent) makes its typed parts once,
/// when it is made (`CycleResult` of `cycle`, a tuple of a bracket).
#[pyclass(module = "asperity._native", frozen, subclass, dict)]
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
            for list in ["rows", "table"] {
                if let Some(Value::Array(rows)) = m.get(list) {
                    if let Some(Value::Object(first)) = rows.first() {
                        for k in first.keys().filter(|k| !m.contains_key(*k)) {
                            attrs.set_item(k, column(py, rows, k)?)?;
                        }
                    }
                    if let Some(values) = swept(m.get("over"), rows) {
                        attrs.set_item("values", array(py, values)?)?;
                    }
                }
            }
        }
        Ok(Record {
            attrs: Arc::new(attrs.unbind()),
            data,
        })
    }

    /// The record of a library result (its serde value, the CLI's JSON object).
    pub fn of<T: serde::Serialize>(py: Python<'_>, x: &T) -> PyResult<Record> {
        Record::new(py, Arc::new(value::json(x)?))
    }

    /// The record of a GFMD result with `heights`, the map it ran on (an array), where it
    /// has one.
    pub fn on_map<T: serde::Serialize>(py: Python<'_>, x: &T, heights: Option<Bound<'_, PyAny>>) -> PyResult<Record> {
        let r = Record::of(py, x)?;
        if let Some(h) = heights {
            r.attrs.bind(py).set_item(MAP, h)?;
        }
        Ok(r)
    }
}

/// `d`, the plain dict of the result `obj`, with the map of a record that has one (what
/// `Record(d)` takes back).
pub fn with_map<'py>(obj: &Bound<'py, PyAny>, d: Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    if let Ok(r) = obj.cast::<Record>() {
        if let Some(m) = r.get().attrs.bind(obj.py()).get_item(MAP)? {
            d.set_item(MAP, m)?;
        }
    }
    Ok(d)
}

impl FromValue for Record {
    fn from_value(py: Python<'_>, data: Arc<Value>) -> PyResult<Record> {
        Record::new(py, data)
    }

    /// A record sharing the record `source` (how a Python subclass wraps one), else the
    /// record of a plain dict (with the map under `heights`, as pickling passes it).
    fn from_source(py: Python<'_>, source: &Bound<'_, PyAny>) -> PyResult<Record> {
        if let Ok(r) = source.cast::<Record>() {
            let r = r.get();
            return Ok(Record {
                attrs: Arc::clone(&r.attrs),
                data: Arc::clone(&r.data),
            });
        }
        let map = match source.cast::<PyDict>() {
            Ok(d) => d.get_item(MAP)?.filter(|m| !m.is_instance_of::<PyList>()),
            Err(_) => None,
        };
        let Some(map) = map else {
            return Record::new(py, Arc::new(plain(source)?));
        };
        let rest = source.cast::<PyDict>()?.copy()?;
        rest.del_item(MAP)?;
        let r = Record::new(py, Arc::new(plain(rest.as_any())?))?;
        r.attrs.bind(py).set_item(MAP, map)?;
        Ok(r)
    }

    /// The record of `source` with the class's `_parts` made.
    fn from_class(cls: &Bound<'_, PyType>, source: &Bound<'_, PyAny>) -> PyResult<Record> {
        let py = cls.py();
        let r = Record::from_source(py, source)?;
        let Ok(parts) = cls.getattr("_parts") else {
            return Ok(r);
        };
        let attrs = r.attrs.bind(py).copy()?;
        for (k, make) in parts.cast::<PyDict>()?.iter() {
            let v = attrs.get_item(&k)?.unwrap_or_else(|| py.None().into_bound(py));
            attrs.set_item(k, make.call1((v,))?)?;
        }
        Ok(Record {
            attrs: Arc::new(attrs.unbind()),
            data: r.data,
        })
    }
}

record_methods!(Record, None, {
    /// An attribute that Python's own lookup did not find: on the first such reading the
    /// record's attributes move into the instance's `__dict__`, where the lookup finds them
    /// from then on at the speed of a plain attribute (a property of a subclass still wins).
    fn __getattr__(slf: &Bound<'_, Self>, name: &str) -> PyResult<Py<PyAny>> {
        let me = slf.get();
        let attrs = me.attrs.bind(slf.py());
        let own = slf.getattr("__dict__")?;
        if own.len()? == 0 {
            own.call_method1("update", (attrs,))?;
        }
        match attrs.get_item(name)? {
            Some(v) => Ok(v.unbind()),
            None => Err(PyAttributeError::new_err(format!(
                "{} has no field or column '{name}' (fields: {})",
                slf.get_type().name()?,
                keys(&me.data).join(", ")
            ))),
        }
    }

    /// Frozen: no attribute is set or deleted.
    fn __setattr__(slf: &Bound<'_, Self>, name: &str, _value: &Bound<'_, PyAny>) -> PyResult<()> {
        Err(PyAttributeError::new_err(format!(
            "{} is frozen: '{name}' cannot be set",
            slf.get_type().name()?
        )))
    }

    fn __delattr__(slf: &Bound<'_, Self>, name: &str) -> PyResult<()> {
        Err(PyAttributeError::new_err(format!(
            "{} is frozen: '{name}' cannot be deleted",
            slf.get_type().name()?
        )))
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
