//! Termination conditions (OMPL's `PlannerTerminationCondition`): when
//! [`Planner::solve`](crate::Planner::solve) should return.

use std::cell::Cell;
use std::time::{Duration, Instant};

use mit_star_spaces::Stop;

/// What a termination condition may look at: the state of the current `solve` call.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// The moment this progress was taken (read once per check, so conditions need not read
    /// the clock again).
    pub now: Instant,
    /// Wall-clock time since this `solve` call started.
    pub elapsed: Duration,
    /// Iterations done in this `solve` call.
    pub iterations: u64,
    /// Cost of the best solution so far (`∞` if none).
    pub best_cost: f64,
}

impl Progress {
    /// Progress taken now, for a `solve` call that has run `elapsed`.
    pub fn new(elapsed: Duration, iterations: u64, best_cost: f64) -> Self {
        Self {
            now: Instant::now(),
            elapsed,
            iterations,
            best_cost,
        }
    }
}

/// Decides when a planner stops.
///
/// Planners check it before every iteration; the building blocks (samplers, edge checkers)
/// poll it in their inner loops through a [`Stop`] view, so a time limit is honoured even in the
/// middle of an iteration. Implementations must be cheap and side-effect free. Combine
/// conditions with [`TerminationExt::or`] and [`TerminationExt::and`].
///
/// ```
/// use std::time::Duration;
/// use mit_star::{CostThreshold, IterationLimit, Progress, Termination, TerminationExt, TimeLimit};
///
/// let condition = TimeLimit::new(Duration::from_millis(50)).or(CostThreshold::new(1.2));
/// let progress = Progress::new(Duration::from_millis(10), 3, 1.1);
/// assert!(condition.should_terminate(&progress)); // cost reached
/// let both = IterationLimit::new(10).and(CostThreshold::new(1.2));
/// assert!(!both.should_terminate(&progress)); // only 3 iterations
/// ```
pub trait Termination {
    /// `true` once the planner should stop.
    fn should_terminate(&self, progress: &Progress) -> bool;
}

impl<T: Termination + ?Sized> Termination for &T {
    fn should_terminate(&self, progress: &Progress) -> bool {
        (**self).should_terminate(progress)
    }
}

impl<T: Termination + ?Sized> Termination for Box<T> {
    fn should_terminate(&self, progress: &Progress) -> bool {
        (**self).should_terminate(progress)
    }
}

/// Stops after a wall-clock budget measured from the start of `solve`, or at a fixed instant.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TimeLimit {
    limit: Limit,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Limit {
    Budget(Duration),
    Until(Instant),
}

impl TimeLimit {
    /// A budget of `budget` from the start of each `solve` call.
    pub fn new(budget: Duration) -> Self {
        Self {
            limit: Limit::Budget(budget),
        }
    }

    /// A budget in seconds (negative or NaN budgets stop at once).
    pub fn seconds(seconds: f64) -> Self {
        Self::new(Duration::try_from_secs_f64(seconds.max(0.0)).unwrap_or(Duration::MAX))
    }

    /// Stops at a fixed instant — e.g. one taken before building the planner, so construction
    /// counts against the budget as in PDT's protocol.
    pub fn until(instant: Instant) -> Self {
        Self {
            limit: Limit::Until(instant),
        }
    }
}

impl Termination for TimeLimit {
    #[inline]
    fn should_terminate(&self, progress: &Progress) -> bool {
        match self.limit {
            Limit::Budget(budget) => progress.elapsed >= budget,
            Limit::Until(instant) => progress.now >= instant,
        }
    }
}

/// Stops after a number of iterations of the current `solve` call.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IterationLimit(u64);

impl IterationLimit {
    /// At most `iterations` iterations.
    pub fn new(iterations: u64) -> Self {
        Self(iterations)
    }
}

impl Termination for IterationLimit {
    #[inline]
    fn should_terminate(&self, progress: &Progress) -> bool {
        progress.iterations >= self.0
    }
}

/// Stops once the best solution costs at most the threshold.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CostThreshold(f64);

impl CostThreshold {
    /// Stop when `c_best ≤ threshold`.
    pub fn new(threshold: f64) -> Self {
        Self(threshold)
    }
}

impl Termination for CostThreshold {
    #[inline]
    fn should_terminate(&self, progress: &Progress) -> bool {
        progress.best_cost <= self.0
    }
}

/// Stops as soon as any solution exists (OMPL's exact-solution condition).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FirstSolution;

impl Termination for FirstSolution {
    #[inline]
    fn should_terminate(&self, progress: &Progress) -> bool {
        progress.best_cost.is_finite()
    }
}

/// Stops when either condition does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Or<A, B>(pub A, pub B);

impl<A: Termination, B: Termination> Termination for Or<A, B> {
    #[inline]
    fn should_terminate(&self, progress: &Progress) -> bool {
        self.0.should_terminate(progress) || self.1.should_terminate(progress)
    }
}

/// Stops when both conditions do.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct And<A, B>(pub A, pub B);

impl<A: Termination, B: Termination> Termination for And<A, B> {
    #[inline]
    fn should_terminate(&self, progress: &Progress) -> bool {
        self.0.should_terminate(progress) && self.1.should_terminate(progress)
    }
}

/// Combinators for termination conditions.
pub trait TerminationExt: Termination + Sized {
    /// Stop when `self` or `other` does.
    fn or<B: Termination>(self, other: B) -> Or<Self, B> {
        Or(self, other)
    }

    /// Stop when `self` and `other` both do.
    fn and<B: Termination>(self, other: B) -> And<Self, B> {
        And(self, other)
    }
}

impl<T: Termination> TerminationExt for T {}

/// A caller's termination seen by a planner that a wrapper runs (as
/// [`Simplifying`](crate::Simplifying) and [`WarmStarted`](crate::WarmStarted) do): time
/// counts from the wrapper's `solve` call, and the best cost is the better of the wrapped
/// planner's and the wrapper's own.
pub(crate) struct Wrapped<'a> {
    pub(crate) termination: &'a dyn Termination,
    pub(crate) started: Instant,
    pub(crate) best: f64,
}

impl Termination for Wrapped<'_> {
    fn should_terminate(&self, progress: &Progress) -> bool {
        let progress = Progress {
            elapsed: progress.now.saturating_duration_since(self.started),
            best_cost: progress.best_cost.min(self.best),
            ..*progress
        };
        self.termination.should_terminate(&progress)
    }
}

/// The [`Stop`] view of a termination condition that building blocks poll during one
/// iteration: time moves on, the iteration count and best cost are those of the iteration.
///
/// Every poll through [`Stop`] reads the clock. A planner's main loop polls once per
/// iteration through [`should_stop_iteration`](Self::should_stop_iteration) instead, which
/// reads it on every [`ITERATION_CLOCK_PERIOD`]-th call (counted from the last reading by any
/// poll), or once the validity checks since the last reading an iteration poll made reach
/// [`CHECKS_PER_READING`], and otherwise judges the condition at the instant last read: the iteration count, best cost and interruptions are
/// always current, and a deadline is noticed at most that many cheap iterations late. On the
/// Panda's cage the readings were 3 % of MIT*'s time, five sixths of it at these polls; the
/// same work now takes 0.96 of the time (the arm-planning reference, "Where MIT*'s time
/// goes after its first path").
pub(crate) struct SolveStop<'a> {
    termination: &'a dyn Termination,
    started: Instant,
    iterations: Cell<u64>,
    best_cost: Cell<f64>,
    /// The clock's last reading, by any poll.
    read_at: Cell<Instant>,
    /// Iteration polls since that reading.
    polls_since_reading: Cell<u32>,
    /// The validity checks counted when an iteration poll last read the clock.
    checks_at_reading: Cell<u64>,
}

/// An iteration poll reads the clock at least this often ([`SolveStop::should_stop_iteration`]).
pub(crate) const ITERATION_CLOCK_PERIOD: u32 = 8;

/// An iteration poll reads the clock once this many validity checks were made since an
/// iteration poll last read it: an iteration's costly part is its checks.
pub(crate) const CHECKS_PER_READING: u64 = 64;

impl<'a> SolveStop<'a> {
    /// Starts the clock of a `solve` call.
    pub(crate) fn new(termination: &'a dyn Termination) -> Self {
        let started = Instant::now();
        Self {
            termination,
            started,
            iterations: Cell::new(0),
            best_cost: Cell::new(f64::INFINITY),
            read_at: Cell::new(started),
            polls_since_reading: Cell::new(0),
            checks_at_reading: Cell::new(0),
        }
    }

    /// Records the iteration count and best cost the next polls report.
    pub(crate) fn update(&self, iterations: u64, best_cost: f64) {
        self.iterations.set(iterations);
        self.best_cost.set(best_cost);
    }

    /// Time since the `solve` call started.
    pub(crate) fn elapsed(&self) -> Duration {
        self.read_clock().saturating_duration_since(self.started)
    }

    /// The poll of a planner's main loop, once per iteration; `checks` is the planner's
    /// validity-check count so far. Reads the clock as described on [`SolveStop`].
    pub(crate) fn should_stop_iteration(&self, checks: u64) -> bool {
        let polls = self.polls_since_reading.get() + 1;
        let checked = checks.saturating_sub(self.checks_at_reading.get());
        if polls >= ITERATION_CLOCK_PERIOD || checked >= CHECKS_PER_READING {
            self.checks_at_reading.set(checks);
            return Stop::should_stop(self);
        }
        self.polls_since_reading.set(polls);
        self.judge(self.read_at.get())
    }

    /// Reads the clock, keeping the reading for the iteration polls.
    fn read_clock(&self) -> Instant {
        let now = Instant::now();
        self.read_at.set(now);
        self.polls_since_reading.set(0);
        now
    }

    /// The condition at `now`, with the iteration's count and best cost.
    fn judge(&self, now: Instant) -> bool {
        self.termination.should_terminate(&Progress {
            now,
            elapsed: now.saturating_duration_since(self.started),
            iterations: self.iterations.get(),
            best_cost: self.best_cost.get(),
        })
    }
}

impl Stop for SolveStop<'_> {
    #[inline]
    fn should_stop(&self) -> bool {
        let now = self.read_clock();
        self.judge(now)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(ms: u64, iterations: u64, best_cost: f64) -> Progress {
        Progress {
            now: Instant::now(),
            elapsed: Duration::from_millis(ms),
            iterations,
            best_cost,
        }
    }

    #[test]
    fn each_condition_fires_when_it_should() {
        let time = TimeLimit::new(Duration::from_millis(20));
        assert!(!time.should_terminate(&at(19, 0, 1.0)));
        assert!(time.should_terminate(&at(20, 0, 1.0)));
        assert!(TimeLimit::seconds(-1.0).should_terminate(&at(0, 0, 1.0)));
        assert!(TimeLimit::until(Instant::now()).should_terminate(&at(0, 0, 1.0)));
        assert!(IterationLimit::new(5).should_terminate(&at(0, 5, 1.0)));
        assert!(!IterationLimit::new(5).should_terminate(&at(0, 4, 1.0)));
        assert!(CostThreshold::new(1.0).should_terminate(&at(0, 0, 1.0)));
        assert!(!CostThreshold::new(1.0).should_terminate(&at(0, 0, f64::INFINITY)));
        assert!(FirstSolution.should_terminate(&at(0, 0, 3.0)));
        assert!(!FirstSolution.should_terminate(&at(0, 0, f64::INFINITY)));
    }

    #[test]
    fn combinators_and_the_stop_view() {
        let c = IterationLimit::new(2)
            .or(FirstSolution)
            .and(TimeLimit::new(Duration::ZERO));
        assert!(c.should_terminate(&at(0, 2, f64::INFINITY)));
        assert!(!c.should_terminate(&at(0, 1, f64::INFINITY)));
        let boxed: Box<dyn Termination> = Box::new(c);
        let stop = SolveStop::new(&boxed);
        assert!(!stop.should_stop());
        stop.update(1, 0.5);
        assert!(stop.should_stop());
    }

    #[test]
    fn iteration_polls_read_the_clock_every_period_or_after_enough_checks() {
        // A limit long enough that a busy machine does not pass it before the first poll.
        let limit = TimeLimit::new(Duration::from_millis(200));
        let past = Duration::from_millis(250);
        let stop = SolveStop::new(&limit);
        assert!(!stop.should_stop());
        std::thread::sleep(past);
        // The deadline passed after the last reading: the next polls judge at that reading,
        // until the period's last one reads the clock.
        for _ in 1..ITERATION_CLOCK_PERIOD {
            assert!(!stop.should_stop_iteration(0));
        }
        assert!(stop.should_stop_iteration(0));
        // Enough validity checks since the last reading read it at once.
        let stop = SolveStop::new(&limit);
        assert!(!stop.should_stop_iteration(0));
        std::thread::sleep(past);
        assert!(!stop.should_stop_iteration(CHECKS_PER_READING - 1));
        assert!(stop.should_stop_iteration(CHECKS_PER_READING));
        // A poll through `Stop` always reads it.
        let stop = SolveStop::new(&limit);
        std::thread::sleep(past);
        assert!(Stop::should_stop(&stop));
    }

    #[test]
    fn iteration_polls_see_the_iteration_count_and_cost_at_once() {
        let limit = IterationLimit::new(3).or(FirstSolution);
        let stop = SolveStop::new(&limit);
        assert!(!stop.should_stop_iteration(0));
        stop.update(3, f64::INFINITY);
        assert!(stop.should_stop_iteration(0));
        stop.update(0, 1.0);
        assert!(stop.should_stop_iteration(0));
    }
}
