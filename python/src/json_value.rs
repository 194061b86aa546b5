//! Plain Python objects (`dict`, `list`, `float`, `int`, `str`, `bool`, `None`) from anything
//! serde can serialise: counters, run records, trace points.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde_json::Value;

use crate::error::{BindingError, BindingResult};

/// `value` as plain Python objects.
///
/// # Errors
/// [`BindingError::Value`] if serde cannot represent it (never for the library's types).
pub(crate) fn to_python<'py, T: serde::Serialize>(
    py: Python<'py>,
    value: &T,
) -> BindingResult<Bound<'py, PyAny>> {
    let json = serde_json::to_value(value).map_err(|e| BindingError::Value(e.to_string()))?;
    json_to_python(py, &json)
}

/// A JSON value as plain Python objects (objects keep their key order).
pub(crate) fn json_to_python<'py>(
    py: Python<'py>,
    value: &Value,
) -> BindingResult<Bound<'py, PyAny>> {
    Ok(match value {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => pyo3::types::PyBool::new(py, *b).to_owned().into_any(),
        Value::Number(n) => {
            if let Some(i) = &n.as_i64() {
                pyo3::types::PyInt::new(py, *i).into_any()
            } else if let Some(u) = &n.as_u64() {
                pyo3::types::PyInt::new(py, *u).into_any()
            } else {
                pyo3::types::PyFloat::new(py, n.as_f64().unwrap_or(f64::NAN)).into_any()
            }
        }
        Value::String(s) => pyo3::types::PyString::new(py, s).into_any(),
        Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(json_to_python(py, item)?)?;
            }
            list.into_any()
        }
        Value::Object(map) => {
            let dict = PyDict::new(py);
            for (key, item) in map {
                dict.set_item(key, json_to_python(py, item)?)?;
            }
            dict.into_any()
        }
    })
}
