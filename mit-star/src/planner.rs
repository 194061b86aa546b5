//! The [`Planner`] trait every planner of the framework implements, and what `solve` returns.

use mit_star_spaces::{StateSpace, States};
use mit_star_validity::StateValidity;

use crate::{Counters, Endpoint, PlannerError, Snapshot, Termination, Trace};

/// A valid path from the start to a goal.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// The path's states, start first, goal last. Every edge between consecutive states was
    /// checked at full resolution.
    pub path: States,
    /// The path's cost (length).
    pub cost: f64,
}

/// What [`Planner::solve`] found.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// The best solution found so far.
    Solved(Solution),
    /// No solution within the termination condition (not an error).
    NoSolution,
}

impl Outcome {
    /// The solution, if any.
    pub fn solution(&self) -> Option<&Solution> {
        match self {
            Self::Solved(s) => Some(s),
            Self::NoSolution => None,
        }
    }

    /// `true` if a solution was found.
    pub fn is_solved(&self) -> bool {
        matches!(self, Self::Solved(_))
    }

    /// The solution's cost, `∞` without one.
    pub fn cost(&self) -> f64 {
        self.solution().map_or(f64::INFINITY, |s| s.cost)
    }
}

/// A motion planner: OMPL's `Planner`, reduced to what benchmarks and applications use.
///
/// Anytime planners improve their solution across repeated [`solve`](Self::solve) calls;
/// [`clear`](Self::clear) forgets everything so the planner can be reused for a fresh run with
/// no state leaking between queries. Object safe: run-time configurations are
/// `Box<dyn Planner + Send>` ([`build_planner`](crate::build_planner)).
pub trait Planner {
    /// The planner's name, as benchmark reports print it (e.g. `MIT*`).
    fn name(&self) -> &str;

    /// Plans until `termination` fires (or the solution is provably optimal) and returns the
    /// best solution so far. A returned path is always valid at full resolution.
    ///
    /// # Errors
    /// [`PlannerError`] if the query is malformed: no goal, a start or goal of the wrong
    /// dimension, not finite, out of bounds, or in collision.
    fn solve(&mut self, termination: &dyn Termination) -> Result<Outcome, PlannerError>;

    /// Forgets every sample, tree, solution, counter and random state: the next `solve` behaves
    /// exactly like the first `solve` of a freshly built planner with the same parameters.
    fn clear(&mut self);

    /// Cost of the best solution so far (`∞` if none).
    fn best_cost(&self) -> f64;

    /// Every improvement of the best solution, `(time, cost)`, oldest first.
    fn trace(&self) -> &Trace;

    /// Work counters since construction or the last `clear`.
    fn counters(&self) -> Counters;

    /// The planner's parameters as `(name, value)` pairs, for benchmark logs.
    fn settings(&self) -> Vec<(String, String)>;

    /// A read-only copy of the planner's samples, trees and cost bounds (for pictures of runs),
    /// if the planner offers one. The default offers none.
    fn snapshot(&self) -> Option<Snapshot> {
        None
    }

    /// Offers the planner a solution found outside its search — a shortened copy of its own
    /// path ([`Simplifying`](crate::Simplifying)), or another planner's — between two `solve`
    /// calls. A planner that can use it checks it as its own edges (every edge at full
    /// resolution, then certified when the problem asks; the path must join its start to one of
    /// its goals) and, if it is valid and cheaper than its best, makes it its best solution, so
    /// its cost bound, informed set and pruning follow from then on; it then returns `true`.
    /// The EIT* family also grafts the path into its forward tree (its corners become
    /// vertices, its edges known valid), so later batches can improve on it locally.
    /// The default ignores the offer and returns `false` (planners that return their first
    /// solution, and wrappers that cannot pass it on).
    fn offer_solution(&mut self, solution: &Solution) -> bool {
        let _ = solution;
        false
    }
}

/// A boxed planner is a planner (so wrappers such as [`Simplifying`](crate::Simplifying) take
/// run-time configurations).
impl<P: Planner + ?Sized> Planner for Box<P> {
    fn name(&self) -> &str {
        (**self).name()
    }

    fn solve(&mut self, termination: &dyn Termination) -> Result<Outcome, PlannerError> {
        (**self).solve(termination)
    }

    fn clear(&mut self) {
        (**self).clear();
    }

    fn best_cost(&self) -> f64 {
        (**self).best_cost()
    }

    fn trace(&self) -> &Trace {
        (**self).trace()
    }

    fn counters(&self) -> Counters {
        (**self).counters()
    }

    fn settings(&self) -> Vec<(String, String)> {
        (**self).settings()
    }

    fn snapshot(&self) -> Option<Snapshot> {
        (**self).snapshot()
    }

    fn offer_solution(&mut self, solution: &Solution) -> bool {
        (**self).offer_solution(solution)
    }
}

/// Makes `solution` the `best` one, with a point at `time` (planning time) in `trace`, if it
/// is cheaper: how a planner or wrapper that keeps its own best solution records one.
pub(crate) fn keep_if_cheaper(
    (best, trace): (&mut Option<Solution>, &mut Trace),
    time: std::time::Duration,
    solution: Solution,
) {
    if best.as_ref().is_none_or(|b| solution.cost < b.cost) {
        trace.push(time.as_secs_f64(), solution.cost);
        *best = Some(solution);
    }
}

/// The length of `path` in `space` (the sum of its edges).
pub(crate) fn path_cost<S: StateSpace>(space: &S, path: &States) -> f64 {
    path.iter()
        .zip(path.iter().skip(1))
        .map(|(a, b)| space.distance(a, b))
        .sum()
}

/// Whether `path` joins `start` to one of `goals` with every state finite and of the space's
/// dimension, and every edge valid at full resolution on `checker`'s grid and, when
/// `certification > 1`, certified: the test an offered solution passes before a planner takes
/// it ([`Planner::offer_solution`]). `progress` receives each edge's checking progress (all of
/// its grid tested when the path passes), for a planner that keeps the edges. Runs to the end
/// (no stop): an offer is bounded work.
pub(crate) fn offered_path_is_valid<S, V, E>(
    (space, validity, checker): (&S, &V, &mut E),
    certification: u32,
    (start, goals): (&[f64], &[Vec<f64>]),
    path: &States,
    progress: &mut Vec<mit_star_validity::EdgeProgress>,
) -> bool
where
    S: StateSpace,
    V: StateValidity,
    E: mit_star_validity::EdgeChecker<S, V>,
{
    progress.clear();
    let n = space.dimension();
    if path.len() < 2 || path.dimension() != n || path[0] != *start {
        return false;
    }
    let end = &path[path.len() - 1];
    if !goals.iter().any(|g| g.as_slice() == end) {
        return false;
    }
    if path
        .iter()
        .any(|x| space.check_state(x).is_err() || !validity.is_valid(x))
    {
        return false;
    }
    path.iter().zip(path.iter().skip(1)).all(|(a, b)| {
        let mut tested = mit_star_validity::EdgeProgress::UNTESTED;
        let never = &mit_star_spaces::Never;
        let valid = checker.check_full(space, validity, a, b, &mut tested, never)
            == mit_star_validity::EdgeStatus::Valid
            && (certification <= 1
                || checker.certify(space, validity, a, b, certification, never)
                    == mit_star_validity::EdgeStatus::Valid);
        progress.push(tested);
        valid
    })
}

/// Checks a query against a space and a validity checker.
pub(crate) fn validate_query<S, V>(
    space: &S,
    validity: &V,
    start: &[f64],
    goals: &[Vec<f64>],
) -> Result<(), PlannerError>
where
    S: StateSpace + ?Sized,
    V: StateValidity + ?Sized,
{
    if goals.is_empty() {
        return Err(PlannerError::NoGoals);
    }
    let endpoints = || {
        std::iter::once((Endpoint::Start, start)).chain(
            goals
                .iter()
                .enumerate()
                .map(|(i, g)| (Endpoint::Goal(i), g.as_slice())),
        )
    };
    for (endpoint, state) in endpoints() {
        space
            .check_state(state)
            .map_err(|source| PlannerError::State { endpoint, source })?;
    }
    // Endpoints in blocks: a batched checker decides a block's states in one pass of its
    // lanes instead of one pass each, and thousands of goals are not copied into one array
    // (20 000 goals in R^32 are 5 MB). The first in collision is reported.
    const BLOCK: usize = 256;
    let n = space.dimension();
    let mut states = Vec::with_capacity(BLOCK.min(1 + goals.len()) * n);
    let mut valid = Vec::with_capacity(BLOCK.min(1 + goals.len()));
    let mut block = Vec::with_capacity(BLOCK.min(1 + goals.len()));
    let mut all = endpoints().peekable();
    while all.peek().is_some() {
        states.clear();
        block.clear();
        for (endpoint, state) in all.by_ref().take(BLOCK) {
            states.extend_from_slice(state);
            block.push((endpoint, state));
        }
        valid.clear();
        valid.resize(block.len(), false);
        validity.are_valid(&states, n, &mut valid);
        if let Some(((endpoint, state), _)) = block.iter().zip(&valid).find(|(_, valid)| !**valid) {
            return Err(PlannerError::InCollision {
                endpoint: *endpoint,
                state: state.to_vec(),
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outcome_accessors() {
        let mut path = States::new(2);
        path.push(&[0.0, 0.0]);
        path.push(&[1.0, 0.0]);
        let solved = Outcome::Solved(Solution { path, cost: 1.0 });
        assert!(solved.is_solved());
        assert_eq!(solved.cost(), 1.0);
        assert_eq!(solved.solution().map(|s| s.path.len()), Some(2));
        assert!(!Outcome::NoSolution.is_solved());
        assert_eq!(Outcome::NoSolution.cost(), f64::INFINITY);
    }
}
