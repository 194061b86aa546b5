//! [`RrtCore`]: what every RRT planner of the crate ([`RrtConnect`](crate::RrtConnect),
//! [`InformedRrtStar`](crate::InformedRrtStar)) holds besides its trees — the query, the parts,
//! the parameters, the best solution and the records — and how it is built.

use std::time::Duration;

use mit_star_samplers::Sampler;
use mit_star_spaces::{StateSpace, States, Stop};
use mit_star_validity::{Counted, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity};

use crate::planner::validate_query;
use crate::termination::SolveStop;
use crate::{
    BuildError, Counters, Neighbours, Outcome, Parameters, Solution, Trace, default_range,
};

/// The query, parts, parameters, best solution and records of an RRT planner, with the two
/// state buffers of an extension: the state drawn (`target`) and the state steered to
/// (`candidate`).
#[derive(Debug, Clone)]
pub(crate) struct RrtCore<S, V, Smp, E> {
    pub(crate) space: S,
    pub(crate) validity: Counted<V>,
    pub(crate) sampler: Smp,
    pub(crate) checker: E,
    /// The parts as built, restored by [`clear`](Self::clear).
    initial: (Smp, E),
    pub(crate) parameters: Parameters,
    /// The maximum length of one extension.
    pub(crate) range: f64,
    pub(crate) name: String,
    pub(crate) start: Vec<f64>,
    pub(crate) goals: Vec<Vec<f64>>,
    pub(crate) solution: Option<Solution>,
    pub(crate) trace: Trace,
    pub(crate) counters: Counters,
    /// Planning time of the finished `solve` calls.
    pub(crate) elapsed: Duration,
    pub(crate) neighbours: Neighbours,
    pub(crate) target: Vec<f64>,
    pub(crate) candidate: Vec<f64>,
}

/// What an RRT planner's `for_problem` builds from: the space, the validity checker, the query
/// and the parameters for the problem.
pub(crate) type ProblemParts<S, V> = (S, V, (Vec<f64>, Vec<Vec<f64>>), Parameters);

/// The parts of `problem` with `parameters` for it ([`Parameters::for_problem`]: its resolution,
/// and its certification unless `parameters` sets one).
///
/// # Errors
/// [`BuildError::Problem`] if the problem refuses its check step.
pub(crate) fn problem_parts<P>(
    problem: &P,
    parameters: &Parameters,
) -> Result<ProblemParts<P::Space, P::Validity>, BuildError>
where
    P: mit_star_problems::PlanningProblem,
{
    Ok((
        problem.space().clone(),
        problem.validity().clone(),
        (problem.start().to_vec(), problem.goals().to_vec()),
        parameters.for_problem(problem)?,
    ))
}

/// Validates `parameters` and the query, and returns the range the planner steps by
/// (`parameters.range`, else [`default_range`]).
///
/// # Errors
/// [`BuildError::Parameter`] for a parameter out of range, [`BuildError::Query`] for a
/// malformed query.
pub(crate) fn checked_range<S: StateSpace, V: StateValidity>(
    space: &S,
    validity: &V,
    (start, goals): (&[f64], &[Vec<f64>]),
    parameters: &Parameters,
) -> Result<f64, BuildError> {
    parameters.validate()?;
    validate_query(space, validity, start, goals)?;
    let extent = space.maximum_extent();
    Ok(parameters
        .range
        .unwrap_or_else(|| default_range(space.dimension(), extent)))
}

impl<S, V, Smp, E> RrtCore<S, V, Smp, E>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
{
    /// The core of a planner called `name` for the query, with its parts and `parameters`
    /// (validated here, with the query).
    ///
    /// # Errors
    /// As [`checked_range`].
    pub(crate) fn new(
        space: S,
        validity: V,
        (start, goals): (Vec<f64>, Vec<Vec<f64>>),
        (sampler, checker): (Smp, E),
        parameters: Parameters,
        name: &str,
    ) -> Result<Self, BuildError> {
        let range = checked_range(&space, &validity, (&start, &goals), &parameters)?;
        let n = space.dimension();
        Ok(Self {
            initial: (sampler.clone(), checker.clone()),
            sampler,
            checker,
            validity: Counted::new(validity),
            range,
            name: name.into(),
            solution: None,
            trace: Trace::default(),
            counters: Counters::default(),
            elapsed: Duration::ZERO,
            neighbours: Neighbours::new(),
            target: vec![0.0; n],
            candidate: vec![0.0; n],
            space,
            parameters,
            start,
            goals,
        })
    }

    /// Checks the motion `from → candidate` at full resolution (every grid point not yet
    /// tested), then on the certification grid when the parameters ask for one. `Unknown` if
    /// the stop fired first: `progress` keeps what the full check tested, and the next call
    /// resumes.
    pub(crate) fn check_to_candidate(
        &mut self,
        from: &[f64],
        progress: &mut EdgeProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus {
        let (space, validity, to) = (&self.space, &self.validity, &self.candidate);
        let status = self
            .checker
            .check_full(space, validity, from, to, progress, stop);
        if status != EdgeStatus::Valid {
            return status;
        }
        let to = std::mem::take(&mut self.candidate);
        let status = self.certify(from, &to, stop);
        self.candidate = to;
        status
    }

    /// Checks the motion `from → candidate` at full resolution and the candidate itself
    /// ([`EdgeChecker::check_full_and_end`]: a batched checker tests the candidate with the
    /// motion's last grid points), without certification. `progress` belongs to this check.
    pub(crate) fn check_motion_and_candidate(
        &mut self,
        from: &[f64],
        progress: &mut EdgeProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus {
        let (space, validity, to) = (&self.space, &self.validity, &self.candidate);
        self.checker
            .check_full_and_end(space, validity, from, to, progress, stop)
    }

    /// How many times finer than the check step edges are certified (1: not at all).
    pub(crate) fn certification(&self) -> u32 {
        self.parameters.certification.unwrap_or(1)
    }

    /// Certifies the motion `from → to`, already checked at full resolution, on the grid
    /// [`certification`](Self::certification) times finer (`Valid` at once when that is 1).
    pub(crate) fn certify(&mut self, from: &[f64], to: &[f64], stop: &dyn Stop) -> EdgeStatus {
        let factor = self.certification();
        if factor > 1 {
            let (space, validity) = (&self.space, &self.validity);
            self.checker
                .certify(space, validity, from, to, factor, stop)
        } else {
            EdgeStatus::Valid
        }
    }

    /// Records `path` as the solution if it is cheaper than the best one (its cost the sum of
    /// its edges), with the planning time in the trace.
    pub(crate) fn record(&mut self, path: States, stop: &SolveStop<'_>) {
        let cost = crate::planner::path_cost(&self.space, &path);
        let best = (&mut self.solution, &mut self.trace);
        crate::planner::keep_if_cheaper(
            best,
            self.elapsed + stop.elapsed(),
            Solution { path, cost },
        );
    }

    /// Records the trivial path `(start, goal)` of cost 0 if the start is one of the goals
    /// (at distance 0 from it) and nothing cheaper is known; `true` if the best solution is
    /// then that trivial one — nothing can improve on it, and no tree need grow.
    pub(crate) fn record_if_start_is_a_goal(&mut self, stop: &SolveStop<'_>) -> bool {
        if self.best_cost() <= 0.0 {
            return true;
        }
        let Some(goal) = self
            .goals
            .iter()
            .position(|g| self.space.distance(&self.start, g) == 0.0)
        else {
            return false;
        };
        let mut path = States::new(self.space.dimension());
        path.push(&self.start);
        path.push(&self.goals[goal]);
        self.record(path, stop);
        true
    }

    /// Takes `solution`, offered from outside ([`Planner::offer_solution`](crate::Planner)), as
    /// the best one if it is valid (checked and certified as the planner's edges) and cheaper,
    /// with a trace point at the planning time so far.
    pub(crate) fn offer(&mut self, solution: &Solution) -> bool {
        if solution.cost >= self.best_cost() {
            return false;
        }
        let certification = self.certification();
        let parts = (&self.space, &self.validity, &mut self.checker);
        let query = (self.start.as_slice(), self.goals.as_slice());
        let progress = &mut Vec::new();
        let path = &solution.path;
        if !crate::planner::offered_path_is_valid(parts, certification, query, path, progress) {
            return false;
        }
        let cost = crate::planner::path_cost(&self.space, &solution.path);
        if cost >= self.best_cost() {
            return false;
        }
        self.trace.push(self.elapsed.as_secs_f64(), cost);
        self.solution = Some(Solution {
            path: solution.path.clone(),
            cost,
        });
        true
    }

    /// Cost of the best solution (`∞` if none).
    pub(crate) fn best_cost(&self) -> f64 {
        self.solution.as_ref().map_or(f64::INFINITY, |s| s.cost)
    }

    /// Ends a `solve` call: adds its time and returns the best solution.
    pub(crate) fn finish(&mut self, stop: &SolveStop<'_>) -> Outcome {
        self.elapsed += stop.elapsed();
        match &self.solution {
            Some(solution) => Outcome::Solved(solution.clone()),
            None => Outcome::NoSolution,
        }
    }

    /// Restores the parts as built and forgets the solution and the records.
    pub(crate) fn clear(&mut self) {
        self.sampler = self.initial.0.clone();
        self.checker = self.initial.1.clone();
        self.validity.reset();
        self.solution = None;
        self.trace.clear();
        self.counters = Counters::default();
        self.elapsed = Duration::ZERO;
    }

    /// The counters with the parts' work filled in (the planner fills the graph sizes).
    pub(crate) fn counters(&self) -> Counters {
        self.counters.with_parts(
            <E as EdgeChecker<S, Counted<V>>>::counters(&self.checker),
            self.validity.count(),
            &self.sampler.counters(),
        )
    }

    /// The settings of the planner of `configuration` built on this core: the parameters it
    /// reads ([`Configuration::settings`](crate::Configuration::settings)), with the range and
    /// certification as they run, then `extra` (the planner's own counts).
    pub(crate) fn settings(
        &self,
        configuration: crate::Configuration,
        extra: Vec<(&str, String)>,
    ) -> Vec<(String, String)> {
        let mut settings = configuration.settings(&self.parameters);
        for (name, value) in &mut settings {
            match name.as_str() {
                "range" => *value = self.range.to_string(),
                "certification" => *value = self.certification().to_string(),
                _ => {}
            }
        }
        settings.extend(extra.into_iter().map(|(k, v)| (k.to_owned(), v)));
        settings
    }
}
