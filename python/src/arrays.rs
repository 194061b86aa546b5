//! [`vector`] and [`matrix`]: the float arrays the bindings take, from whatever a user has at
//! hand — a `float64` numpy array as it is (no copy), or anything numpy can turn into one
//! (lists, tuples, integer or `float32` arrays), converted once by `numpy.asarray`.

use numpy::{PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::error::{BindingError, BindingResult};

/// `value` as a `float64` numpy array: itself if it is one, else `numpy.asarray(value,
/// dtype="float64")`.
fn as_float64<'py>(name: &str, value: &Bound<'py, PyAny>) -> BindingResult<Bound<'py, PyAny>> {
    let py = value.py();
    let numpy = py.import("numpy")?;
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", "float64")?;
    numpy
        .call_method("asarray", (value,), Some(&kwargs))
        .map_err(|e| {
            BindingError::Type(format!(
                "{name} must be an array of numbers (a numpy array or a list), not {}: {e}",
                type_name(value)
            ))
        })
}

/// The name of `value`'s type, for messages.
fn type_name(value: &Bound<'_, PyAny>) -> String {
    value
        .get_type()
        .name()
        .map_or_else(|_| "an unknown type".to_owned(), |n| n.to_string())
}

/// `value` as a 1-D `float64` array (`name` in messages).
///
/// # Errors
/// [`BindingError::Type`] if numpy cannot make numbers of it, [`BindingError::Value`] if it
/// is not one-dimensional.
pub(crate) fn vector<'py>(
    name: &str,
    value: &Bound<'py, PyAny>,
) -> BindingResult<PyReadonlyArray1<'py, f64>> {
    if let Ok(a) = value.extract::<PyReadonlyArray1<'py, f64>>() {
        return Ok(a);
    }
    let converted = as_float64(name, value)?;
    converted
        .extract::<PyReadonlyArray1<'py, f64>>()
        .map_err(|_| shape_error(name, &converted, "(d,)"))
}

/// `value` as a 2-D `float64` array (`name` in messages).
///
/// # Errors
/// As [`vector`], for two dimensions.
pub(crate) fn matrix<'py>(
    name: &str,
    value: &Bound<'py, PyAny>,
) -> BindingResult<PyReadonlyArray2<'py, f64>> {
    if let Ok(a) = value.extract::<PyReadonlyArray2<'py, f64>>() {
        return Ok(a);
    }
    let converted = as_float64(name, value)?;
    converted
        .extract::<PyReadonlyArray2<'py, f64>>()
        .map_err(|_| shape_error(name, &converted, "(m, d)"))
}

/// `name` has another number of dimensions than `wanted`.
fn shape_error(name: &str, converted: &Bound<'_, PyAny>, wanted: &str) -> BindingError {
    let shape = converted
        .cast::<numpy::PyUntypedArray>()
        .map_or_else(|_| "?".to_owned(), |a| format!("{:?}", a.shape()));
    BindingError::Value(format!("{name} must have shape {wanted}, not {shape}"))
}
