//! [`PyPlanner`] (`mit_star.Planner`): a planner chosen by configuration name, with keyword
//! parameters and optionally a validity checker written in Python; `solve` plans with the GIL
//! released and stops on Ctrl-C or on an exception of the checker.

use std::sync::{Arc, Mutex};
use std::time::Instant;

use mit_star::{Configuration, Planner, build_planner_with};
use mit_star_benches::{InstanceProblem, pose_goal_planner};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::error::{BindingError, BindingResult};
use crate::interruptible::Interruptible;
use crate::parameters::planner_parameters;
use crate::problem::PyProblem;
use crate::python_validity::{CallbackFailure, PythonValidity};
use crate::solve_request::SolveRequest;
use crate::solve_result::{SolveResult, counters_dict, trace_pairs};

/// A motion planner for one problem: `Planner("eit-star", problem, seed=1, batch_size=200)`.
///
/// `configuration` is a name of `mit_star.planners()` (`mit-star`, `eit-star`, the ablations
/// `mit-star-as`, `-eis`, `-sc`, `-sr`, `rrt-connect`, `aorrtc`, `bit-star`, `abit-star`,
/// `ait-star`, `informed-rrt-star`, `fcit-star`); every other keyword is a planner parameter, as
/// `mit-star plan --set NAME=VALUE` takes it (`batch_size`, `rewire_factor`, `range`, …).
///
/// `validity`, a callable on one state (a float array of shape (d,)) returning whether it is
/// valid, and/or `vectorized`, a callable on states of shape (n, d) returning n booleans,
/// replace the problem's own checker (the problem still gives the bounds, start, goals and
/// resolution). Edge checks hand `vectorized` up to `batch` states at once (1 to 1 024; the
/// stop condition is polled between batches), and samplers draw their candidates up to eight
/// ahead and check them, with the points of their segment searches, in calls of at most
/// `batch` states: with `vectorized` (and `batch` above 1) a seed gives a search of the same
/// law as with `validity`, but not the same one.
#[pyclass(module = "mit_star._native", name = "Planner")]
pub struct PyPlanner {
    /// The planner (locked only by `&mut self` methods, which PyO3 already serialises).
    planner: Mutex<Box<dyn Planner + Send>>,
    /// Its configuration.
    configuration: Configuration,
    /// The first exception of the Python checker (or of Ctrl-C) during the current `solve`.
    failure: Arc<CallbackFailure>,
    /// The problem's identifier.
    problem_id: String,
}

impl PyPlanner {
    /// The planner, for a `&mut self` method.
    fn planner_mut(&mut self) -> &mut Box<dyn Planner + Send> {
        match self.planner.get_mut() {
            Ok(planner) => planner,
            Err(poisoned) => poisoned.into_inner(),
        }
    }

    /// The planner, for a `&self` method.
    fn with_planner<T>(&self, f: impl FnOnce(&dyn Planner) -> T) -> BindingResult<T> {
        let planner = self.planner.try_lock().map_err(|_| BindingError::Busy)?;
        Ok(f(&**planner))
    }
}

// PyO3 extracts each argument as an owned value: taking it by value is the binding's shape.
#[allow(clippy::needless_pass_by_value)]
#[pymethods]
impl PyPlanner {
    #[new]
    #[pyo3(signature = (configuration, problem, *, seed=0, validity=None, vectorized=None, batch=64, **params))]
    fn new(
        configuration: &str,
        problem: PyRef<'_, PyProblem>,
        seed: u64,
        validity: Option<Bound<'_, PyAny>>,
        vectorized: Option<Bound<'_, PyAny>>,
        batch: usize,
        params: Option<&Bound<'_, PyDict>>,
    ) -> BindingResult<Self> {
        let (configuration, parameters) = planner_parameters(configuration, seed, params)?;
        for (name, f) in [("validity", &validity), ("vectorized", &vectorized)] {
            if let Some(f) = f
                && !f.is_callable()
            {
                return Err(BindingError::Type(format!(
                    "{name} must be callable, not {}",
                    f.get_type().name()?
                )));
            }
        }
        if batch == 0 || batch > mit_star_validity::MAX_BATCH {
            return Err(BindingError::Value(format!(
                "batch must be between 1 and {}, not {batch}",
                mit_star_validity::MAX_BATCH
            )));
        }
        let failure = Arc::new(CallbackFailure::default());
        let pose = problem.pose_goal.as_ref().zip(problem.problem.as_arm());
        let planner = if let Some((spec, arm)) = pose {
            if validity.is_some() || vectorized.is_some() {
                return Err(BindingError::Value(
                    "a problem with a pose goal plans with its own checker: drop validity and vectorized"
                        .into(),
                ));
            }
            // The parameters are checked once, over the problem's own goal.
            problem
                .problem
                .effective_parameters(configuration, &parameters)?;
            let source = spec.source(arm, seed)?;
            pose_goal_planner(arm, source, configuration, parameters)
        } else if validity.is_none() && vectorized.is_none() {
            problem.problem.build_planner(configuration, &parameters)?
        } else {
            let checker = PythonValidity::new(
                validity.map(Bound::unbind),
                vectorized.map(Bound::unbind),
                batch,
                Arc::clone(&failure),
            );
            let built = match &problem.problem {
                InstanceProblem::Boxes(p) => {
                    build_planner_with(configuration, p, &parameters, checker)
                }
                InstanceProblem::Arm(p) => {
                    build_planner_with(configuration, &**p, &parameters, checker)
                }
            };
            // An exception raised while building (a checked start) is the caller's error.
            if let Some(error) = failure.take() {
                return Err(error.into());
            }
            built?
        };
        Ok(Self {
            planner: Mutex::new(planner),
            configuration,
            failure,
            problem_id: problem.id.clone(),
        })
    }

    /// Plans until one of the conditions holds — `time` seconds, the first solution, `iterations`
    /// iterations or a solution of cost at most `cost` — and returns the best solution so far.
    ///
    /// Anytime planners go on improving across calls; `clear()` starts afresh. The GIL is
    /// released while planning. Ctrl-C stops the planner and raises `KeyboardInterrupt`; an
    /// exception raised by a Python validity checker stops it and is raised here.
    ///
    /// Raises `ValueError` for no condition or a bad budget, and `PlanningError` for a query
    /// the planner refuses (a start or goal invalid or out of bounds).
    #[pyo3(signature = (time=None, *, first_solution=false, iterations=None, cost=None))]
    fn solve(
        &mut self,
        py: Python<'_>,
        time: Option<f64>,
        first_solution: bool,
        iterations: Option<u64>,
        cost: Option<f64>,
    ) -> BindingResult<SolveResult> {
        let request = SolveRequest::new(time, first_solution, iterations, cost)?;
        let failure = Arc::clone(&self.failure);
        let _ = failure.take();
        let planner = self.planner_mut();
        let (outcome, elapsed) = py.detach(|| {
            let stop = Interruptible::new(&request, failure);
            let started = Instant::now();
            let outcome = planner.solve(&stop);
            (outcome, started.elapsed().as_secs_f64())
        });
        if let Some(error) = self.failure.take() {
            return Err(error.into());
        }
        let outcome = outcome?;
        SolveResult::new(py, &outcome, &**self.planner_mut(), elapsed)
    }

    /// Forgets every sample, tree, solution and counter: the next `solve` is a fresh run.
    fn clear(&mut self) {
        self.planner_mut().clear();
    }

    /// The planner's name as reports print it (`MIT*`, `EIT*`, …).
    #[getter]
    fn name(&self) -> BindingResult<String> {
        self.with_planner(|p| p.name().to_owned())
    }

    /// The configuration's name (`mit-star`, …).
    #[getter]
    fn configuration(&self) -> &'static str {
        self.configuration.name()
    }

    /// The cost of the best solution so far (`inf` without one).
    #[getter]
    fn best_cost(&self) -> BindingResult<f64> {
        self.with_planner(|p| p.best_cost())
    }

    /// Every improvement of the best solution, `(seconds, cost)`, oldest first.
    #[getter]
    fn trace(&self) -> BindingResult<Vec<(f64, f64)>> {
        self.with_planner(trace_pairs)
    }

    /// The work counters since construction or the last `clear()`, as a `dict`.
    #[getter]
    fn counters(&self, py: Python<'_>) -> BindingResult<Py<PyDict>> {
        self.with_planner(|p| counters_dict(py, p))?
    }

    /// The planner's parameters as `(name, value)` string pairs, as benchmark logs record them.
    #[getter]
    fn settings(&self) -> BindingResult<Vec<(String, String)>> {
        self.with_planner(|p| p.settings())
    }

    fn __repr__(&self) -> String {
        format!(
            "Planner({:?}, problem={:?})",
            self.configuration.name(),
            self.problem_id
        )
    }
}
