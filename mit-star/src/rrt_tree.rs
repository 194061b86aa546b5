//! The pieces the RRT family shares ([`RrtConnect`](crate::RrtConnect),
//! [`InformedRrtStar`](crate::InformedRrtStar)): a tree of states with its nearest-neighbour
//! index, steering by at most a range, and the full (optionally certified) motion check.

use spaces::{StateSpace, States, Stop};
use validity::{Counted, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity};

use crate::eit::validate_query;
use crate::kd_tree::Alive;
use crate::{BuildError, NearestNeighbors, Neighbours, Parameters, default_range};

/// The parent of a root.
pub(crate) const ROOT: u32 = u32::MAX;

/// One tree: states in contiguous storage, parent indices ([`ROOT`] for roots), and the
/// nearest-neighbour index over its states.
#[derive(Debug, Clone)]
pub(crate) struct Tree {
    pub(crate) states: States,
    pub(crate) parents: Vec<u32>,
    nn: NearestNeighbors,
}

impl Tree {
    pub(crate) fn new(dimension: usize) -> Self {
        Self {
            states: States::new(dimension),
            parents: Vec::new(),
            nn: NearestNeighbors::new(dimension),
        }
    }

    pub(crate) fn add(&mut self, state: &[f64], parent: u32) -> u32 {
        let id = self.parents.len() as u32;
        self.states.push(state);
        self.parents.push(parent);
        self.nn.insert([(id, state)]);
        id
    }

    pub(crate) fn state(&self, id: u32) -> &[f64] {
        &self.states[id as usize]
    }

    /// The path from `id` up to its root, `id` first.
    pub(crate) fn branch(&self, mut id: u32) -> Vec<u32> {
        let mut ids = vec![id];
        while self.parents[id as usize] != ROOT {
            id = self.parents[id as usize];
            ids.push(id);
        }
        ids
    }

    /// The `k` states nearest to `target` in `found` (`(squared distance, id)`, nearest first,
    /// ties by id), by the kd-trees in a Euclidean space, else by a scan with the space's
    /// metric. `false` (and `found` incomplete) if `stop` fired first.
    pub(crate) fn nearest<S: StateSpace>(
        &mut self,
        space: &S,
        target: &[f64],
        k: usize,
        found: &mut Neighbours,
        stop: &dyn Stop,
    ) -> bool {
        if space.is_euclidean() {
            return self.nn.nearest_alive(target, k, found, Alive::All, stop);
        }
        found.reset(k);
        for (id, state) in self.states.iter().enumerate() {
            if id % 4096 == 4095 && stop.should_stop() {
                return false;
            }
            let d = space.distance(state, target);
            found.offer(d * d, id as u32);
        }
        true
    }
}

/// Writes to `out` the state at most `range` from `from` towards `target` (`target` itself when
/// it is that close) and returns whether it is `target`.
pub(crate) fn steer<S: StateSpace>(
    space: &S,
    (from, target): (&[f64], &[f64]),
    range: f64,
    out: &mut [f64],
) -> bool {
    let distance = space.distance(from, target);
    let reached = distance <= range;
    if reached {
        out.copy_from_slice(target);
    } else {
        space.interpolate(from, target, range / distance, out);
    }
    reached
}

/// The edge checks of one planner: its checker, and the certification factor it applies (1:
/// none).
pub(crate) struct MotionCheck<'a, S, V, E> {
    pub(crate) checker: &'a mut E,
    pub(crate) space: &'a S,
    pub(crate) validity: &'a Counted<V>,
    pub(crate) certification: u32,
}

impl<S, V, E> MotionCheck<'_, S, V, E>
where
    S: StateSpace,
    V: StateValidity,
    E: EdgeChecker<S, Counted<V>>,
{
    /// Checks the motion `from → to` at full resolution (every grid point not yet tested, then
    /// the certification grid when the factor is above 1). `Unknown` if the stop fired first:
    /// `progress` keeps what was tested and the next call resumes.
    pub(crate) fn run(
        self,
        (from, to): (&[f64], &[f64]),
        progress: &mut EdgeProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus {
        let status = self
            .checker
            .check_full(self.space, self.validity, from, to, progress, stop);
        if status == EdgeStatus::Valid && self.certification > 1 {
            return self.checker.certify(
                self.space,
                self.validity,
                from,
                to,
                self.certification,
                stop,
            );
        }
        status
    }
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
    P: problems::PlanningProblem,
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
