//! `mit_star.write_view`: an interactive 3-D view of paths and trajectories on a problem, as
//! one self-contained HTML page.

use std::path::PathBuf;

use mit_star_benches::PlanView;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::error::{BindingError, BindingResult};
use crate::problem::PyProblem;

/// Writes an interactive 3-D view of `problem` to `file` (an `.html` page that opens offline in
/// a browser) and returns its size in bytes.
///
/// `path` (shape (n, d), or a list of states) is drawn as the motion "path"; `paths`, a dict
/// of label → path, adds more (each its own entry in the page's motion selector);
/// `trajectory`, the dict `time_parameterise` returns, adds the timed motion (arms only).
/// Configurations the problem's checker refuses are drawn in red. `title` heads the page.
///
/// Raises `ValueError` for a box world of more than three dimensions, a path of the wrong
/// width, a file name not ending in `.html`, or a page that cannot be written.
#[pyfunction]
#[pyo3(signature = (problem, file, path=None, *, paths=None, trajectory=None, title=None))]
#[allow(clippy::needless_pass_by_value)]
pub(crate) fn write_view(
    py: Python<'_>,
    problem: PyRef<'_, PyProblem>,
    file: PathBuf,
    path: Option<&Bound<'_, PyAny>>,
    paths: Option<&Bound<'_, PyDict>>,
    trajectory: Option<&Bound<'_, PyDict>>,
    title: Option<String>,
) -> BindingResult<u64> {
    let view = mit_star_benches::commands::ViewArgs {
        view: Some(file.clone()),
        view_search: false,
        view_package_root: Vec::new(),
    };
    view.prepare()?;
    let dimension = problem.problem.dimension();
    let states = |value: &Bound<'_, PyAny>, what: &str| -> BindingResult<Vec<Vec<f64>>> {
        let states: Vec<Vec<f64>> = value.extract().map_err(|_| {
            BindingError::Type(format!(
                "{what} must be an (n, d) array or a list of states"
            ))
        })?;
        if let Some((k, s)) = states
            .iter()
            .enumerate()
            .find(|(_, s)| s.len() != dimension)
        {
            return Err(BindingError::Value(format!(
                "{what}, state {k}: {} coordinates where the problem has {dimension}",
                s.len()
            )));
        }
        if states.iter().flatten().any(|x| !x.is_finite()) {
            return Err(BindingError::Value(format!(
                "{what}: coordinates must be finite"
            )));
        }
        Ok(states)
    };
    let mut motions = Vec::new();
    if let Some(path) = path {
        motions.push(("path".to_owned(), states(path, "path")?));
    }
    if let Some(paths) = paths {
        for (label, value) in paths.iter() {
            let label: String = label.str()?.to_string();
            let what = format!("paths[{label:?}]");
            motions.push((label, states(&value, &what)?));
        }
    }
    let timed = match trajectory {
        Some(t) => {
            let item = |key: &str| {
                t.get_item(key)?.ok_or_else(|| {
                    BindingError::Value(format!(
                        "trajectory has no {key:?}: pass the dict time_parameterise returns"
                    ))
                })
            };
            let times: Vec<f64> = item("time")?.extract().map_err(|_| {
                BindingError::Type("trajectory[\"time\"] must be a 1-D array".into())
            })?;
            let positions = states(&item("position")?, "trajectory[\"position\"]")?;
            if times.len() != positions.len() {
                return Err(BindingError::Value(format!(
                    "trajectory: {} times for {} positions",
                    times.len(),
                    positions.len()
                )));
            }
            Some((times, positions))
        }
        None => None,
    };
    let title = title.unwrap_or_else(|| problem.id.clone());
    let meshes = &problem.meshes;
    let problem = &problem.problem;
    py.detach(|| {
        let mut page = PlanView::new(problem, title, None)?;
        if let Some(resolver) = meshes {
            page.meshes(resolver);
        }
        for (label, states) in &motions {
            page.path(label.clone(), states);
        }
        if let Some((times, positions)) = timed {
            page.samples("trajectory", times, positions);
        }
        page.write(&file)
    })
    .map_err(BindingError::from)
}
