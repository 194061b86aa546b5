//! `mit_star._native`: the Rust half of the `mit_star` Python package (PyO3, built by
//! maturin). The Python half (`mit_star/__init__.py`) re-exports it with per-configuration
//! constructors (`MitStar`, `EitStar`, …) and type stubs.
//!
//! | file | what it holds |
//! |---|---|
//! | `problem.rs`, `box_world.rs` | `Problem`: PDT families, problem files, MotionBenchMaker folders and robots, box worlds from numpy arrays |
//! | `planner.rs`, `parameters.rs` | `Planner`: a configuration by name with keyword parameters; `solve` with the GIL released |
//! | `solve_request.rs`, `interruptible.rs` | when `solve` returns: the caller's conditions, Ctrl-C, a checker's exception |
//! | `python_validity.rs` | a validity checker written in Python (scalar and vectorised) |
//! | `solve_result.rs`, `json_value.rs` | what `solve` returns, as plain Python objects |
//! | `experiment.rs` | running shipped or file experiments and reading results folders |
//! | `error.rs` | `BindingError` and its Python exceptions (`PlanningError`) |

mod arrays;
mod box_world;
mod error;
mod experiment;
mod interruptible;
mod json_value;
mod parameters;
mod planner;
mod problem;
mod python_validity;
mod solve_request;
mod solve_result;
mod trajectory;
mod view;

use pyo3::prelude::*;

/// The configuration names (`mit-star`, `eit-star`, …), MIT* first.
#[pyfunction]
fn planners() -> Vec<&'static str> {
    mit_star::Configuration::ALL
        .iter()
        .map(|c| c.name())
        .collect()
}

/// The parameters the planner of configuration `name` reads, with their defaults as text, in
/// the order `planners` lists them (`mit-star planners` prints the same).
///
/// Raises `ValueError` for an unknown configuration.
#[pyfunction]
fn planner_parameters(name: &str) -> PyResult<Vec<(String, String)>> {
    let configuration = mit_star_benches::parse_configuration(&name.replace('_', "-"))
        .map_err(|e| pyo3::exceptions::PyValueError::new_err(e.to_string()))?;
    Ok(configuration.settings(&mit_star::Parameters::default()))
}

/// The built-in problem families (PDT's benchmark problems), as `(name, description)`.
#[pyfunction]
fn problem_families() -> Vec<(&'static str, &'static str)> {
    mit_star_problems::catalogue()
        .iter()
        .map(|f| (f.name(), f.description()))
        .collect()
}

/// The shipped robots (`panda`, `ur5`, `fetch`).
#[pyfunction]
fn robots() -> Vec<&'static str> {
    mit_star_robot::ShippedRobot::all()
        .iter()
        .map(|r| r.name)
        .collect()
}

/// The module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<problem::PyProblem>()?;
    m.add_class::<planner::PyPlanner>()?;
    m.add_class::<solve_result::SolveResult>()?;
    m.add_class::<experiment::PyExperimentResults>()?;
    m.add_function(wrap_pyfunction!(planners, m)?)?;
    m.add_function(wrap_pyfunction!(planner_parameters, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(problem_families, m)?)?;
    m.add_function(wrap_pyfunction!(robots, m)?)?;
    m.add_function(wrap_pyfunction!(experiment::experiments, m)?)?;
    m.add_function(wrap_pyfunction!(experiment::run_experiment, m)?)?;
    m.add_function(wrap_pyfunction!(experiment::read_results, m)?)?;
    m.add_function(wrap_pyfunction!(trajectory::time_parameterise, m)?)?;
    m.add_function(wrap_pyfunction!(view::write_view, m)?)?;
    m.add("PlanningError", m.py().get_type::<error::PlanningError>())?;
    Ok(())
}
