//! Planner parameters from Python keyword arguments: each `name=value` is a
//! `--set name=value` of the command line, checked by the same rules.

use mit_star::{Configuration, Parameters};
use mit_star_benches::{ParameterOverrides, PlannerSpec, parse_configuration};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyString};

use crate::error::{BindingError, BindingResult};

/// The configuration named `name` (`mit-star`, `eit-star`, …; `_` may stand for `-`) and its
/// parameters: the defaults with `params` applied and `seed` set.
///
/// # Errors
/// [`BindingError::Harness`] for an unknown configuration or a refused parameter (naming it),
/// [`BindingError::Type`] for a value that is not a bool, int, float or str.
pub(crate) fn planner_parameters(
    name: &str,
    seed: u64,
    params: Option<&Bound<'_, PyDict>>,
) -> BindingResult<(Configuration, Parameters)> {
    let configuration = parse_configuration(&name.replace('_', "-"))?;
    let overrides = overrides(params)?;
    let spec = PlannerSpec::new(configuration, None, &overrides)?;
    spec.refuse_unread()?;
    Ok((configuration, spec.parameters_for_seed(seed)))
}

/// `params` as parameter overrides (`None` values are skipped: the default stands).
pub(crate) fn overrides(params: Option<&Bound<'_, PyDict>>) -> BindingResult<ParameterOverrides> {
    let mut overrides = ParameterOverrides::default();
    for (key, value) in params.into_iter().flat_map(|d| d.iter()) {
        let key: String = key.extract()?;
        if value.is_none() {
            continue;
        }
        overrides.push(key.clone(), toml_value(&key, &value)?)?;
    }
    Ok(overrides)
}

/// A Python value as the TOML value the parameter table takes.
fn toml_value(key: &str, value: &Bound<'_, PyAny>) -> BindingResult<toml::Value> {
    if value.is_instance_of::<PyBool>() {
        Ok(toml::Value::Boolean(value.extract()?))
    } else if value.is_instance_of::<PyInt>() {
        let i: i64 = value
            .extract()
            .map_err(|_| BindingError::Value(format!("parameter `{key}`: {value} is too large")))?;
        Ok(toml::Value::Integer(i))
    } else if value.is_instance_of::<PyFloat>() {
        Ok(toml::Value::Float(value.extract()?))
    } else if value.is_instance_of::<PyString>() {
        Ok(toml::Value::String(value.extract()?))
    } else if let Ok(i) = value.extract::<i64>() {
        Ok(toml::Value::Integer(i)) // numpy integers
    } else if let Ok(x) = value.extract::<f64>() {
        Ok(toml::Value::Float(x)) // numpy floats
    } else {
        Err(BindingError::Type(format!(
            "parameter `{key}` must be a bool, int, float or str, not {}",
            value.get_type().name()?
        )))
    }
}
