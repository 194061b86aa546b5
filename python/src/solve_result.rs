//! [`SolveResult`] (`mit_star.SolveResult`): what one `solve` returned, as plain Python
//! objects — the path as an `(n, d)` numpy array, its cost, the anytime trace, the counters.

use mit_star::{Outcome, Planner};
use numpy::PyArray2;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::error::{BindingError, BindingResult};
use crate::json_value::to_python;

/// The result of `Planner.solve`.
///
/// `path` is `None` without a solution; `cost` is then `inf`. `trace` is every improvement of
/// the best solution since the planner was built or cleared, as `(seconds, cost)` pairs;
/// `counters` is a `dict` of the planner's work counters; `elapsed` is the wall-clock time of
/// this `solve` call in seconds.
#[pyclass(module = "mit_star._native", name = "SolveResult", frozen, get_all)]
#[derive(Debug)]
pub struct SolveResult {
    /// `True` if a solution was found.
    solved: bool,
    /// The path, shape (n, d), start first, goal last; `None` without a solution.
    path: Option<Py<PyArray2<f64>>>,
    /// The path's cost (length); `inf` without a solution.
    cost: f64,
    /// `(seconds, cost)` of every improvement, oldest first.
    trace: Vec<(f64, f64)>,
    /// The work counters (`iterations`, `samples`, `validity_checks`, …).
    counters: Py<PyDict>,
    /// Wall-clock seconds of this `solve` call.
    elapsed: f64,
    /// The planner's name (`MIT*`, …).
    planner: String,
}

impl SolveResult {
    /// The result of `outcome` from `planner` after `elapsed` seconds.
    ///
    /// # Errors
    /// Only if Python cannot allocate the objects.
    pub(crate) fn new(
        py: Python<'_>,
        outcome: &Outcome,
        planner: &dyn Planner,
        elapsed: f64,
    ) -> BindingResult<Self> {
        let path = match outcome.solution() {
            Some(solution) => {
                let rows: Vec<Vec<f64>> = solution.path.iter().map(<[f64]>::to_vec).collect();
                let array = PyArray2::from_vec2(py, &rows)
                    .map_err(|e| BindingError::Value(e.to_string()))?;
                Some(array.unbind())
            }
            None => None,
        };
        Ok(Self {
            solved: outcome.is_solved(),
            path,
            cost: outcome.cost(),
            trace: trace_pairs(planner),
            counters: counters_dict(py, planner)?,
            elapsed,
            planner: planner.name().to_owned(),
        })
    }
}

#[pymethods]
impl SolveResult {
    fn __repr__(&self) -> String {
        format!(
            "SolveResult(planner={:?}, solved={}, cost={}, elapsed={:.4})",
            self.planner,
            if self.solved { "True" } else { "False" },
            self.cost,
            self.elapsed
        )
    }
}

/// The planner's anytime trace as `(seconds, cost)` pairs.
pub(crate) fn trace_pairs(planner: &dyn Planner) -> Vec<(f64, f64)> {
    planner
        .trace()
        .points()
        .iter()
        .map(|p| (p.time, p.cost))
        .collect()
}

/// The planner's counters as a `dict`.
///
/// # Errors
/// Only if Python cannot allocate the objects.
pub(crate) fn counters_dict(py: Python<'_>, planner: &dyn Planner) -> BindingResult<Py<PyDict>> {
    let value = to_python(py, &planner.counters())?;
    Ok(value
        .cast_into::<PyDict>()
        .map_err(|e| BindingError::Value(e.to_string()))?
        .unbind())
}
