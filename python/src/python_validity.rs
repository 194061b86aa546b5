//! [`PythonValidity`]: a validity checker written in Python — a callable on one state and,
//! optionally, a vectorised callable on an `(n, d)` array — that any planner uses through
//! [`mit_star_validity::StateValidity`].
//!
//! The planner runs with the GIL released; each call takes the GIL only while the Python code
//! runs. An exception raised by the callable is kept in the shared [`CallbackFailure`] (the
//! first one), the state is answered invalid, and the planner's termination condition fires at
//! its next poll, so the planner stops cleanly and the exception is raised from `solve`.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

use mit_star_validity::StateValidity;
use numpy::ndarray::ArrayView2;
use numpy::{PyArray1, PyReadonlyArray1, ToPyArray};
use pyo3::prelude::*;

/// The first Python exception raised while planning, shared by the checker that caught it and
/// the termination condition that stops the planner.
#[derive(Debug, Default)]
pub(crate) struct CallbackFailure {
    /// Set once an exception is stored: read at every termination poll, without a lock.
    failed: AtomicBool,
    /// The exception.
    error: Mutex<Option<PyErr>>,
}

impl CallbackFailure {
    /// Keeps `error` unless one is kept already.
    pub(crate) fn store(&self, error: PyErr) {
        if let Ok(mut slot) = self.error.lock()
            && slot.is_none()
        {
            *slot = Some(error);
        }
        self.failed.store(true, Ordering::Release);
    }

    /// `true` once an exception was stored.
    pub(crate) fn has_failed(&self) -> bool {
        self.failed.load(Ordering::Acquire)
    }

    /// The stored exception, taken (the failure is cleared for the next `solve`).
    pub(crate) fn take(&self) -> Option<PyErr> {
        self.failed.store(false, Ordering::Release);
        self.error.lock().ok().and_then(|mut slot| slot.take())
    }
}

/// A validity checker calling Python: `scalar(state) -> bool` on a state of shape (d,), and
/// `vectorised(states) -> array of bool` on states of shape (n, d), if given (then edge checks
/// hand it up to `batch` grid points at once).
#[derive(Debug, Clone)]
pub(crate) struct PythonValidity {
    /// The callable on one state (`None`: the vectorised one on a (1, d) array).
    scalar: Option<Arc<Py<PyAny>>>,
    /// The callable on an (n, d) array.
    vectorised: Option<Arc<Py<PyAny>>>,
    /// How many states the vectorised callable receives at most.
    batch: usize,
    /// Where an exception goes.
    failure: Arc<CallbackFailure>,
}

impl PythonValidity {
    /// A checker calling `scalar` and/or `vectorised` (at least one), batches of at most
    /// `batch` states, exceptions kept in `failure`.
    pub(crate) fn new(
        scalar: Option<Py<PyAny>>,
        vectorised: Option<Py<PyAny>>,
        batch: usize,
        failure: Arc<CallbackFailure>,
    ) -> Self {
        Self {
            scalar: scalar.map(Arc::new),
            vectorised: vectorised.map(Arc::new),
            batch: batch.max(1),
            failure,
        }
    }

    /// `vectorised(states)` as booleans, or `None` after an exception (kept) or a reply of
    /// the wrong shape (kept as a `ValueError`/`TypeError`).
    fn call_vectorised(
        &self,
        py: Python<'_>,
        f: &Py<PyAny>,
        states: &ArrayView2<'_, f64>,
    ) -> Option<Vec<bool>> {
        let n = states.nrows();
        let reply = f
            .call1(py, (states.to_pyarray(py),))
            .and_then(|r| booleans(py, r.bind(py), n));
        match reply {
            Ok(bools) => Some(bools),
            Err(error) => {
                self.failure.store(error);
                None
            }
        }
    }
}

impl StateValidity for PythonValidity {
    fn is_valid(&self, state: &[f64]) -> bool {
        if self.failure.has_failed() {
            return false;
        }
        Python::attach(|py| match (&self.scalar, &self.vectorised) {
            (Some(f), _) => {
                let reply = f
                    .call1(py, (PyArray1::from_slice(py, state),))
                    .and_then(|r| r.is_truthy(py));
                reply.unwrap_or_else(|error| {
                    self.failure.store(error);
                    false
                })
            }
            (None, Some(f)) => {
                let Ok(view) = ArrayView2::from_shape((1, state.len()), state) else {
                    return false;
                };
                self.call_vectorised(py, f, &view)
                    .is_some_and(|answers| answers[0])
            }
            (None, None) => true,
        })
    }

    fn batch_width(&self) -> usize {
        if self.vectorised.is_some() {
            self.batch
        } else {
            1
        }
    }

    fn first_invalid(&self, states: &[f64], dimension: usize) -> Option<usize> {
        let Some(f) = &self.vectorised else {
            return states
                .chunks_exact(dimension.max(1))
                .position(|s| !self.is_valid(s));
        };
        if self.failure.has_failed() {
            return Some(0);
        }
        let n = states.len() / dimension.max(1);
        let Ok(view) = ArrayView2::from_shape((n, dimension), &states[..n * dimension]) else {
            return Some(0);
        };
        Python::attach(|py| match self.call_vectorised(py, f, &view) {
            Some(answers) => answers.iter().position(|&valid| !valid),
            None => Some(0),
        })
    }

    /// One call of the vectorised checker per `batch` states (a sampler may hand more at once:
    /// the points of several segment searches, packed into one call); a failed
    /// call answers "invalid" for every state of its batch, as
    /// [`first_invalid`](Self::first_invalid) does.
    fn are_valid(&self, states: &[f64], dimension: usize, valid: &mut [bool]) {
        let Some(f) = &self.vectorised else {
            for (state, answer) in states.chunks_exact(dimension.max(1)).zip(valid) {
                *answer = self.is_valid(state);
            }
            return;
        };
        let n = (states.len() / dimension.max(1)).min(valid.len());
        let batches = states[..n * dimension].chunks(self.batch * dimension.max(1));
        for (batch, answers) in batches.zip(valid[..n].chunks_mut(self.batch)) {
            let count = answers.len();
            let replies = if self.failure.has_failed() {
                None
            } else {
                ArrayView2::from_shape((count, dimension), batch)
                    .ok()
                    .and_then(|view| Python::attach(|py| self.call_vectorised(py, f, &view)))
            };
            match replies {
                Some(replies) => answers.copy_from_slice(&replies),
                None => answers.fill(false),
            }
        }
    }
}

/// `reply` as `n` booleans: a numpy bool array as it is, anything else through
/// `numpy.asarray(reply, dtype=bool)`.
fn booleans(py: Python<'_>, reply: &Bound<'_, PyAny>, n: usize) -> PyResult<Vec<bool>> {
    let answers = match reply.extract::<PyReadonlyArray1<'_, bool>>() {
        Ok(array) => array.as_array().to_vec(),
        Err(_) => {
            let array = py
                .import("numpy")?
                .call_method1("asarray", (reply, "bool"))?
                .call_method0("ravel")?;
            array
                .extract::<PyReadonlyArray1<'_, bool>>()?
                .as_array()
                .to_vec()
        }
    };
    if answers.len() == n {
        Ok(answers)
    } else {
        Err(pyo3::exceptions::PyValueError::new_err(format!(
            "the vectorised validity checker returned {} answers for {n} states",
            answers.len()
        )))
    }
}
