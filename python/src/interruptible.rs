//! [`Interruptible`]: a termination condition that also stops the planner when Python asks —
//! Ctrl-C (a pending signal, polled with the GIL taken briefly every [`SIGNAL_POLL`]) or an
//! exception raised by a Python validity checker.

use std::cell::Cell;
use std::sync::Arc;
use std::time::{Duration, Instant};

use mit_star::{Progress, Termination};
use pyo3::prelude::*;

use crate::python_validity::CallbackFailure;

/// How often pending signals (Ctrl-C) are checked while planning: a stopped planner returns
/// within this plus its own stop latency, and taking the GIL this rarely costs nothing
/// measurable (about a microsecond per poll).
pub(crate) const SIGNAL_POLL: Duration = Duration::from_millis(5);

/// `inner`, or a Python signal handler that raised (Ctrl-C: `KeyboardInterrupt`), or an
/// exception of a Python validity checker — whichever comes first.
pub(crate) struct Interruptible<'a> {
    /// The condition the caller asked for (time, first solution, iterations, cost).
    inner: &'a dyn Termination,
    /// Where callback exceptions and the signal handler's exception are kept.
    failure: Arc<CallbackFailure>,
    /// When signals were last checked.
    last_poll: Cell<Instant>,
}

impl<'a> Interruptible<'a> {
    /// `inner`, interruptible from Python, with exceptions kept in `failure`.
    pub(crate) fn new(inner: &'a dyn Termination, failure: Arc<CallbackFailure>) -> Self {
        Self {
            inner,
            failure,
            last_poll: Cell::new(Instant::now()),
        }
    }
}

impl Termination for Interruptible<'_> {
    fn should_terminate(&self, progress: &Progress) -> bool {
        if self.failure.has_failed() {
            return true;
        }
        if progress.now.saturating_duration_since(self.last_poll.get()) >= SIGNAL_POLL {
            self.last_poll.set(progress.now);
            if let Err(error) = Python::attach(|py| py.check_signals()) {
                self.failure.store(error);
                return true;
            }
        }
        self.inner.should_terminate(progress)
    }
}
