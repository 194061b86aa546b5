//! [`SolveRequest`]: when a `solve` called from Python should return — a time budget, the
//! first solution, an iteration count, a cost — checked before the planner starts.

use mit_star::{CostThreshold, FirstSolution, IterationLimit, Progress, Termination, TimeLimit};
use mit_star_benches::{HarnessError, budget_duration};

use crate::error::{BindingError, BindingResult};

/// The conditions `solve(time=…, first_solution=…, iterations=…, cost=…)` asked for; the
/// planner stops at the first that holds.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SolveRequest {
    /// A wall-clock budget from the start of `solve`.
    time: Option<TimeLimit>,
    /// Stop at the first solution.
    first_solution: bool,
    /// Stop after this many iterations of this `solve`.
    iterations: Option<IterationLimit>,
    /// Stop once a solution costs at most this much.
    cost: Option<CostThreshold>,
}

impl SolveRequest {
    /// The request, checked: at least one condition, a usable time budget, a finite cost.
    ///
    /// # Errors
    /// [`BindingError::Value`] for no condition at all (the planner would never return), a
    /// budget that is not a positive number of seconds, or a cost that is not a number.
    pub(crate) fn new(
        time: Option<f64>,
        first_solution: bool,
        iterations: Option<u64>,
        cost: Option<f64>,
    ) -> BindingResult<Self> {
        if time.is_none() && !first_solution && iterations.is_none() && cost.is_none() {
            return Err(BindingError::Value(
                "give time=SECONDS, first_solution=True, iterations=N or cost=C: \
                 otherwise the planner never returns"
                    .into(),
            ));
        }
        let time = time
            .map(|seconds| {
                budget_duration(seconds)
                    .map(TimeLimit::new)
                    .map_err(|source| HarnessError::Budget {
                        what: "time".into(),
                        source,
                    })
            })
            .transpose()
            .map_err(BindingError::Harness)?;
        if let Some(c) = cost
            && c.is_nan()
        {
            return Err(BindingError::Value("cost must be a number, not NaN".into()));
        }
        Ok(Self {
            time,
            first_solution,
            iterations: iterations.map(IterationLimit::new),
            cost: cost.map(CostThreshold::new),
        })
    }
}

impl Termination for SolveRequest {
    fn should_terminate(&self, progress: &Progress) -> bool {
        self.time.is_some_and(|t| t.should_terminate(progress))
            || (self.first_solution && FirstSolution.should_terminate(progress))
            || self
                .iterations
                .is_some_and(|i| i.should_terminate(progress))
            || self.cost.is_some_and(|c| c.should_terminate(progress))
    }
}
