//! [`WarmStarted`]: an anytime planner whose first solution comes from a fast feasibility
//! planner.

use std::time::{Duration, Instant};

use crate::termination::Wrapped;
use crate::{
    Counters, Outcome, Planner, PlannerError, Progress, Snapshot, Solution, Termination, Trace,
};

/// Wraps an asymptotically optimal planner `P` so that its first solution comes from a
/// feasibility planner `F` (RRT-Connect in [`build_planner`](crate::build_planner)'s
/// `warm_start`): `F` plans until its first solution, which is reported at once and then
/// offered to `P` ([`Planner::offer_solution`]); `P` takes it as its best solution, so its cost
/// bound, informed set and pruning start from it, and plans on to improve it. Removing the
/// wrapper is the ablation (`warm_start` in [`Parameters`](crate::Parameters)): the paper's
/// planners find their own first solution.
///
/// Why: on a robot arm the EIT* family needs many batches to cross a narrow passage in 7-D
/// (tens of milliseconds on MotionBenchMaker's `cage`), where RRT-Connect's trees take about a
/// millisecond; once a solution exists, the informed set of its cost is where the batches of
/// `P` go. OMPL reaches the same composition with its anytime path shortening over several
/// planners; AORRTC is RRT-Connect followed by cost-bounded searches.
///
/// # Arguments
/// `inner`, the planner that improves; `front`, the planner whose first solution starts it.
/// Both must plan the same query (space, validity checker, start, goals): the offer is checked
/// by `inner` as its own edges (full resolution, then certified when the problem asks), so a
/// front planning another query only wastes its time.
///
/// # Returns
/// From [`solve`](Planner::solve): the best path so far. The trace has the front's solution
/// as its first point (at the time the front found it), then the inner planner's improvements
/// at their times since the first `solve` call. Time limits and cost thresholds apply to the
/// whole call; an [`IterationLimit`](crate::IterationLimit) counts the iterations of each of
/// the two planners separately.
///
/// # Complexity
/// The front's first solve, one check of its path by `inner` (every edge, at the start of the
/// next stretch of improvement, not before the first solution is returned), then `inner`'s.
///
/// ```
/// use mit_star::{build_planner, Configuration, Parameters, Planner, TimeLimit};
/// let problem = mit_star_problems::DividingWalls::new(2).build()?.with_resolution(1e-4)?;
/// let parameters = Parameters { warm_start: true, ..Parameters::default() };
/// let mut planner = build_planner(Configuration::MitStar, &problem, &parameters)?;
/// let outcome = planner.solve(&TimeLimit::seconds(0.1))?;
/// // RRT-Connect's first path, then MIT*'s improvements of it.
/// assert!(planner.trace().len() > 1);
/// assert!(outcome.cost() < planner.trace().points()[0].cost);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct WarmStarted<P, F> {
    inner: P,
    front: F,
    /// The front's solution, until it is offered to `inner`.
    pending: Option<Solution>,
    solution: Option<Solution>,
    trace: Trace,
    /// Planning time of the finished `solve` calls.
    elapsed: Duration,
    /// Time the front planned.
    front_time: Duration,
    /// Time the inner planner planned, as this wrapper measured it.
    inner_time: Duration,
    /// `inner` took the front's solution.
    taken: bool,
    /// Trace points of `inner` already merged into this trace.
    merged: usize,
}

impl<P: Planner, F: Planner> WarmStarted<P, F> {
    /// `inner` started from the first solution of `front`.
    pub fn new(inner: P, front: F) -> Self {
        Self {
            inner,
            front,
            pending: None,
            solution: None,
            trace: Trace::default(),
            elapsed: Duration::ZERO,
            front_time: Duration::ZERO,
            inner_time: Duration::ZERO,
            taken: false,
            merged: 0,
        }
    }

    /// The planner that improves the first solution.
    pub fn inner(&self) -> &P {
        &self.inner
    }

    /// The planner that finds the first solution.
    pub fn front(&self) -> &F {
        &self.front
    }

    /// Makes `solution` the best one, with a trace point at `time` (seconds since the first
    /// `solve`), if it is cheaper.
    fn keep(&mut self, solution: &Solution, time: f64) {
        if solution.cost < self.best_cost() {
            self.trace.push(time, solution.cost);
            self.solution = Some(solution.clone());
        }
    }

    /// Runs the front until its first solution or `termination`.
    fn run_front(
        &mut self,
        termination: &dyn Termination,
        started: Instant,
    ) -> Result<(), PlannerError> {
        let outer = Wrapped {
            termination,
            started,
            best: self.best_cost(),
        };
        let front_started = Instant::now();
        let outcome = self.front.solve(&outer)?;
        self.front_time += front_started.elapsed();
        if let Outcome::Solved(solution) = outcome {
            let time = (self.elapsed + started.elapsed()).as_secs_f64();
            self.keep(&solution, time);
            self.pending = Some(solution);
        }
        Ok(())
    }

    /// Appends the inner planner's new trace points, its times (its own planning time) moved
    /// `shift` seconds on.
    fn merge_inner_trace(&mut self, shift: f64) {
        while let Some(&point) = self.inner.trace().points().get(self.merged) {
            self.merged += 1;
            if point.cost < self.best_cost() {
                self.trace.push(point.time + shift, point.cost);
            }
        }
    }
}

impl<P: Planner, F: Planner> Planner for WarmStarted<P, F> {
    fn name(&self) -> &str {
        self.inner.name()
    }

    fn solve(&mut self, termination: &dyn Termination) -> Result<Outcome, PlannerError> {
        let started = Instant::now();
        if self.solution.is_none() {
            self.run_front(termination, started)?;
        }
        let progress = Progress::new(started.elapsed(), 0, self.best_cost());
        if self.solution.is_some() && !termination.should_terminate(&progress) {
            if let Some(first) = self.pending.take() {
                self.taken = self.inner.offer_solution(&first);
            }
            self.merged = self.inner.trace().len();
            let outer = Wrapped {
                termination,
                started,
                best: self.best_cost(),
            };
            // The inner planner's clock counts only its own solves: its times move on by the
            // time spent before this call reached it.
            let shift =
                (self.elapsed + started.elapsed()).as_secs_f64() - self.inner_time.as_secs_f64();
            let inner_started = Instant::now();
            let outcome = self.inner.solve(&outer)?;
            self.inner_time += inner_started.elapsed();
            self.merge_inner_trace(shift);
            if let Outcome::Solved(solution) = outcome
                && solution.cost < self.best_cost()
            {
                self.solution = Some(solution);
            }
        }
        self.elapsed += started.elapsed();
        Ok(match &self.solution {
            Some(solution) => Outcome::Solved(solution.clone()),
            None => Outcome::NoSolution,
        })
    }

    fn clear(&mut self) {
        self.inner.clear();
        self.front.clear();
        self.pending = None;
        self.solution = None;
        self.trace.clear();
        self.elapsed = Duration::ZERO;
        self.front_time = Duration::ZERO;
        self.inner_time = Duration::ZERO;
        self.taken = false;
        self.merged = 0;
    }

    fn best_cost(&self) -> f64 {
        self.solution.as_ref().map_or(f64::INFINITY, |s| s.cost)
    }

    fn trace(&self) -> &Trace {
        &self.trace
    }

    /// The work of both planners, summed ([`Counters::merged`]).
    fn counters(&self) -> Counters {
        self.inner.counters().merged(&self.front.counters())
    }

    fn settings(&self) -> Vec<(String, String)> {
        let mut settings = self.inner.settings();
        settings.push(("warm_start_planner".into(), self.front.name().to_owned()));
        settings.push((
            "warm_start_time".into(),
            self.front_time.as_secs_f64().to_string(),
        ));
        settings.push(("warm_start_taken_by_planner".into(), self.taken.to_string()));
        settings
    }

    fn snapshot(&self) -> Option<Snapshot> {
        self.inner.snapshot().or_else(|| self.front.snapshot())
    }

    fn offer_solution(&mut self, solution: &Solution) -> bool {
        if !self.inner.offer_solution(solution) {
            return false;
        }
        self.merged = self.inner.trace().len();
        let time = self.elapsed.as_secs_f64();
        self.keep(solution, time);
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{
        Configuration, FirstSolution, IterationLimit, Parameters, build_planner, build_planner_with,
    };

    fn problem() -> mit_star_problems::Problem {
        mit_star_problems::DividingWalls::new(2)
            .build()
            .and_then(|p| p.with_resolution(1e-4))
            .expect("a valid problem")
    }

    fn warm(seed: u64) -> Box<dyn Planner + Send> {
        let parameters = Parameters {
            warm_start: true,
            seed,
            ..Parameters::default()
        };
        build_planner(Configuration::MitStar, &problem(), &parameters).expect("builds")
    }

    #[test]
    fn the_first_solution_is_the_fronts_and_the_inner_planner_takes_it() {
        let problem = problem();
        let parameters = Parameters {
            seed: 7,
            ..Parameters::default()
        };
        let mut alone =
            build_planner(Configuration::RrtConnect, &problem, &parameters).expect("builds");
        let front_cost = alone.solve(&FirstSolution).expect("solves").cost();
        let mut planner = warm(7);
        let first = planner.solve(&FirstSolution).expect("solves");
        assert_eq!(first.cost(), front_cost);
        assert_eq!(planner.trace().len(), 1);
        // The inner planner has not run yet: no batch drawn.
        assert_eq!(planner.counters().batches, 0);
        let settings = planner.settings();
        let taken = settings
            .iter()
            .find(|(k, _)| k == "warm_start_taken_by_planner");
        assert_eq!(taken.map(|(_, v)| v.as_str()), Some("false"));
        // Planning on: the offer is taken, and the inner planner improves from there.
        let later = planner.solve(&IterationLimit::new(5000)).expect("solves");
        assert!(
            later.cost() < front_cost,
            "{} !< {front_cost}",
            later.cost()
        );
        let settings = planner.settings();
        let taken = settings
            .iter()
            .find(|(k, _)| k == "warm_start_taken_by_planner");
        assert_eq!(taken.map(|(_, v)| v.as_str()), Some("true"));
        assert!(planner.counters().batches > 0);
        let points = planner.trace().points();
        assert!(points.len() > 1);
        for pair in points.windows(2) {
            assert!(pair[1].time >= pair[0].time && pair[1].cost < pair[0].cost);
        }
        assert_eq!(points.last().map(|p| p.cost), Some(later.cost()));
    }

    #[test]
    fn clear_forgets_both_planners() {
        let mut planner = warm(3);
        let first = planner.solve(&FirstSolution).expect("solves");
        planner.solve(&IterationLimit::new(50)).expect("solves");
        planner.clear();
        assert!(planner.trace().is_empty());
        assert_eq!(planner.best_cost(), f64::INFINITY);
        assert_eq!(planner.counters(), Counters::default());
        assert_eq!(planner.solve(&FirstSolution).expect("solves"), first);
    }

    #[test]
    fn an_offer_before_the_first_solve_skips_the_front() {
        let problem = problem();
        let parameters = Parameters::default();
        let mut donor =
            build_planner(Configuration::RrtConnect, &problem, &parameters).expect("builds");
        let donated = donor.solve(&FirstSolution).expect("solves");
        let solution = donated.solution().expect("a path").clone();
        let inner = build_planner_with(
            Configuration::EitStar,
            &problem,
            &parameters,
            problem.world().clone(),
        )
        .expect("builds");
        let front =
            build_planner(Configuration::RrtConnect, &problem, &parameters).expect("builds");
        let mut planner = WarmStarted::new(inner, front);
        assert!(planner.offer_solution(&solution));
        assert_eq!(planner.best_cost(), solution.cost);
        let outcome = planner.solve(&IterationLimit::new(20)).expect("solves");
        assert!(outcome.cost() <= solution.cost);
        assert_eq!(planner.front().counters(), Counters::default());
    }
}
