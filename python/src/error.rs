//! [`BindingError`]: everything the bindings refuse, typed, and how each maps to a Python
//! exception (`ValueError`, `TypeError`, `OSError` or [`PlanningError`]).

use pyo3::PyErr;
use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyOSError, PyTypeError, PyValueError};

create_exception!(
    _native,
    PlanningError,
    PyException,
    "A query the planner refuses (start or goal in collision, out of bounds, of the wrong \
     dimension, no goal), or a planner or experiment that failed while running."
);

/// What the bindings refuse or what failed, before it becomes a Python exception.
#[derive(Debug, thiserror::Error)]
pub enum BindingError {
    /// A bad argument value (a parameter, a dimension, a budget, a name): `ValueError`.
    #[error("{0}")]
    Value(String),
    /// An argument of the wrong type: `TypeError`.
    #[error("{0}")]
    Type(String),
    /// The experiment harness refused or failed (problem, robot, experiment, results folder).
    #[error(transparent)]
    Harness(#[from] mit_star_benches::HarnessError),
    /// A planner could not be built from these parameters.
    #[error(transparent)]
    Build(#[from] mit_star::BuildError),
    /// The planner refused the query.
    #[error(transparent)]
    Planner(#[from] mit_star::PlannerError),
    /// A box world or problem could not be built.
    #[error(transparent)]
    Problem(#[from] mit_star_problems::ProblemError),
    /// An obstacle the world refused.
    #[error(transparent)]
    Validity(#[from] mit_star_validity::ValidityError),
    /// A Python exception (raised by a validity callback, or a failed conversion): passed on
    /// unchanged.
    #[error(transparent)]
    Python(#[from] PyErr),
    /// The planner is in use by another thread (a `solve` is running).
    #[error("the planner is busy: another thread is solving with it")]
    Busy,
}

impl From<BindingError> for PyErr {
    fn from(error: BindingError) -> Self {
        use mit_star_benches::HarnessError as H;
        if let BindingError::Python(error) = error {
            return error;
        }
        let message = error.to_string();
        match error {
            BindingError::Type(_) => PyTypeError::new_err(message),
            BindingError::Planner(_)
            | BindingError::Build(mit_star::BuildError::Query(_))
            | BindingError::Busy => PlanningError::new_err(message),
            BindingError::Harness(
                H::Io { .. }
                | H::OutputFolder { .. }
                | H::Database { .. }
                | H::Plot { .. }
                | H::Serialise { .. }
                | H::FolderLocked { .. },
            ) => PyOSError::new_err(message),
            BindingError::Harness(H::Planning { .. }) => PlanningError::new_err(message),
            _ => PyValueError::new_err(message),
        }
    }
}

/// A result whose error becomes a Python exception.
pub(crate) type BindingResult<T> = Result<T, BindingError>;
