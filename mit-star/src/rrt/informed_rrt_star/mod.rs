//! [`InformedRrtStar`]: Gammell, Srinivasa and Barfoot's Informed RRT* (IROS 2014), from the
//! framework's parts.

#[cfg(doc)]
use mit_star_samplers::CostBound;
use mit_star_samplers::{InformedSampler, Sampler};
use mit_star_spaces::rand::SeedableRng;
use mit_star_spaces::{SeededRng, StateSpace};
use mit_star_validity::{Counted, DenseChecker, EdgeChecker, StateValidity};

use crate::rrt::cost_tree::CostTree;
use crate::rrt::rrt_core::{RrtCore, checked_range, problem_parts};
use crate::termination::SolveStop;
use crate::{
    BuildError, Counters, Outcome, Parameters, Planner, PlannerError, Snapshot, Termination, Trace,
    VertexKind,
};

mod iteration;

use iteration::{Candidate, Phase};

/// OMPL's `prune_threshold`: the tree is pruned once the best cost has improved by more than
/// this fraction since the last prune.
const PRUNE_THRESHOLD: f64 = 0.05;

/// Mixed into the seed of the goal-bias coin so that it does not repeat the sampler's stream.
const COIN_STREAM: u64 = 0x9E37_79B9_7F4A_7C15;

/// Informed RRT* (Gammell, Srinivasa & Barfoot, IROS 2014) as OMPL's `InformedRRTstar` runs
/// it: k-nearest RRT* (Karaman & Frazzoli, IJRR 2011) whose samples, once a solution of cost
/// `c_best` exists, are drawn directly from the informed set of `c_best` (the prolate
/// hyperspheroid of states that could lie on a cheaper path), and whose tree is pruned of
/// vertices that cannot improve the solution.
///
/// Each iteration draws a goal with probability `goal_bias` (while a goal is not yet in the
/// tree), else the sampler's state under [`CostBound::Unbounded`] or
/// [`CostBound::Solution`]`(c_best)`; steers from the nearest vertex by at most
/// [`range`](Self::range) and fully checks that motion; takes the
/// `k = k_nearest(vertices + 1, n, rrt_rewire_factor)` nearest vertices closer than the range,
/// checks their edges cheapest cost-to-come first until one is valid (OMPL's delayed collision
/// checking) and adds the new vertex under it; then rewires every neighbour through the new
/// vertex where that is cheaper (edge verdicts of the first pass reused: edges are undirected),
/// propagating costs to descendants. A goal is reached when the new vertex is a goal state;
/// every improvement of the best goal vertex is a solution recorded in the [`Trace`].
///
/// Pruning (`parameters.pruning`, OMPL's `pruneTree`): once the best cost has improved by more
/// than 5 % since the last prune, every vertex whose admissible estimate
/// `‖start − x‖ + min_goal ‖x − goal‖` exceeds `c_best` is removed unless one of its
/// descendants is kept (OMPL's leaf-and-chain rule: a vertex goes exactly when it and its whole
/// subtree fail the test); the best goal vertex is always kept, and the nearest-neighbour index
/// is rebuilt.
///
/// Deviations from OMPL, all small: (1) a neighbour whose cost through it is not below the cost
/// through the nearest vertex is never checked as a parent (OMPL checks it when the nearest
/// vertex is not among the neighbours, and may then pick a dearer parent); (2) goal-biased
/// draws cycle through the goals not yet in the tree (OMPL cycles through every goal while
/// fewer goal vertices than goals exist); (3) rewiring visits the neighbours cheapest first,
/// not nearest first; (4) solutions are exact only (no approximate solution); (5) edges are
/// fully checked at the problem's resolution and certified on a finer grid when the problem
/// asks, and whatever the termination condition interrupts (an edge check with its progress,
/// a neighbour query, a cost propagation) resumes at the next `solve`; a prune it interrupts is
/// abandoned and retried after the next iteration; (6) `k` is
/// [`k_nearest`](crate::k_nearest)'s, whose `e · (1 + 1/n)` is not truncated.
///
/// # Arguments
/// A query (space, validity checker, start, goals), a [`Sampler`] (by default
/// [`InformedSampler`], direct informed sampling), an [`EdgeChecker`] (by default
/// [`DenseChecker`]) and [`Parameters`]: `range` (`None`: [`default_range`](crate::default_range)), `goal_bias`,
/// `rrt_rewire_factor`, `pruning`, `resolution`, `seed`, `certification`.
///
/// # Returns
/// From [`solve`](Planner::solve): the best solution so far (every edge fully checked, and
/// certified when asked), or no solution; the tree persists, so repeated calls keep improving
/// it (asymptotically optimal). A call returns early once the informed set is empty (the
/// solution is the straight line).
///
/// # Complexity
/// Per iteration: one nearest and one k-nearest query (`O(log n)` expected, `k = O(log n)`),
/// up to `k` edge checks of at most `range / step` states each, and the cost propagation of
/// rewired subtrees. A prune is `O(n)` and happens at most once per 5 % improvement.
///
/// ```
/// use mit_star::{InformedRrtStar, IterationLimit, Planner};
/// let problem = mit_star_problems::DividingWalls::new(2).build()?.with_resolution(1e-4)?;
/// let mut planner = InformedRrtStar::for_problem(&problem, &mit_star::Parameters::default())?;
/// let first = planner.solve(&IterationLimit::new(3000))?;
/// let later = planner.solve(&IterationLimit::new(3000))?;
/// // Anytime: a later call never returns a dearer path.
/// assert!(later.cost() <= first.cost());
/// if let Some(solution) = later.solution() {
///     assert!(solution.cost >= problem.optimum().unwrap() - 1e-9);
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct InformedRrtStar<S, V, Smp = InformedSampler, E = DenseChecker> {
    /// The query, parts, parameters, solution and records; its `candidate` is the state being
    /// added (`range` at most from its nearest vertex towards the state drawn, `target`).
    core: RrtCore<S, V, Smp, E>,
    /// The goal-bias coin.
    coin: SeededRng,
    tree: CostTree,
    /// The vertex of each goal in the tree, if it is there.
    goal_vertices: Vec<Option<u32>>,
    /// Where the goal-biased draws resume their cycle through the goals.
    next_goal: usize,
    /// The goal vertex of the recorded solution and its cost-to-come then.
    best_goal: Option<(u32, f64)>,
    phase: Phase,
    /// The neighbourhood of the state being added, cheapest first.
    candidates: Vec<Candidate>,
    /// The best cost at the last prune (∞: never pruned).
    pruned_cost: f64,
    peak_vertices: usize,
}

impl<S, V, Smp, E> InformedRrtStar<S, V, Smp, E>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
{
    /// A planner for the query with a ready-made sampler and checker, and `parameters`
    /// (validated here).
    ///
    /// # Errors
    /// [`BuildError::Parameter`] for a parameter out of range (a `goal_bias` outside `[0, 1]`,
    /// a non-positive range or rewire factor, …), [`BuildError::Query`] for a malformed query.
    pub fn with_parts(
        space: S,
        validity: V,
        query: (Vec<f64>, Vec<Vec<f64>>),
        sampler: Smp,
        checker: E,
        parameters: Parameters,
    ) -> Result<Self, BuildError> {
        let coin = SeededRng::seed_from_u64(parameters.seed ^ COIN_STREAM);
        let parts = (sampler, checker);
        let core = RrtCore::new(space, validity, query, parts, parameters, "Informed RRT*")?;
        Ok(Self {
            coin,
            tree: CostTree::new(&core.start),
            goal_vertices: vec![None; core.goals.len()],
            next_goal: 0,
            best_goal: None,
            phase: Phase::Sample,
            candidates: Vec::new(),
            pruned_cost: f64::INFINITY,
            peak_vertices: 1,
            core,
        })
    }

    /// The maximum length of one extension.
    pub fn range(&self) -> f64 {
        self.core.range
    }

    /// Sets the name reports print (default `Informed RRT*`).
    pub fn set_name(&mut self, name: impl Into<String>) {
        self.core.name = name.into();
    }
}

impl<S, V, Smp, E> Planner for InformedRrtStar<S, V, Smp, E>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
{
    fn name(&self) -> &str {
        &self.core.name
    }

    fn solve(&mut self, termination: &dyn Termination) -> Result<Outcome, PlannerError> {
        let stop = SolveStop::new(termination);
        if self.core.record_if_start_is_a_goal(&stop) {
            return Ok(self.core.finish(&stop));
        }
        let mut iterations = 0;
        loop {
            stop.update(iterations, self.best_cost());
            if stop.should_stop_iteration(self.core.validity.count()) || !self.iterate(&stop) {
                break;
            }
            iterations += 1;
        }
        Ok(self.core.finish(&stop))
    }

    fn clear(&mut self) {
        self.core.clear();
        self.coin = SeededRng::seed_from_u64(self.core.parameters.seed ^ COIN_STREAM);
        self.tree = CostTree::new(&self.core.start);
        self.goal_vertices.fill(None);
        self.next_goal = 0;
        self.best_goal = None;
        self.phase = Phase::Sample;
        self.candidates.clear();
        self.pruned_cost = f64::INFINITY;
        self.peak_vertices = 1;
    }

    fn offer_solution(&mut self, solution: &crate::Solution) -> bool {
        self.core.offer(solution)
    }

    fn best_cost(&self) -> f64 {
        self.core.best_cost()
    }

    fn trace(&self) -> &Trace {
        &self.core.trace
    }

    fn counters(&self) -> Counters {
        let mut c = self.core.counters();
        c.vertices = self.tree.len() as u64;
        c.edges = c.vertices - 1;
        c.peak_vertices = self.peak_vertices as u64;
        c.peak_edges = c.peak_vertices - 1;
        c
    }

    fn settings(&self) -> Vec<(String, String)> {
        self.core
            .settings(crate::Configuration::InformedRrtStar, Vec::new())
    }

    fn snapshot(&self) -> Option<Snapshot> {
        let mut kinds = vec![VertexKind::Sample; self.tree.len()];
        kinds[0] = VertexKind::Start;
        for &id in self.goal_vertices.iter().flatten() {
            kinds[id as usize] = VertexKind::Goal;
        }
        let forward_edges = self
            .tree
            .edges()
            .map(|(parent, child)| (parent as usize, child as usize))
            .collect();
        let mut solution: Vec<usize> = match self.best_goal {
            Some((goal, _)) => self
                .tree
                .branch(goal)
                .iter()
                .map(|&id| id as usize)
                .collect(),
            None => Vec::new(),
        };
        solution.reverse();
        Some(Snapshot {
            states: self.tree.states().clone(),
            origins: vec![mit_star_samplers::SampleOrigin::Drawn; kinds.len()],
            kinds,
            forward_edges,
            reverse_edges: Vec::new(),
            solution,
            best_cost: self.best_cost(),
            estimated_informed_cost: None,
        })
    }
}

impl<S: StateSpace, V: StateValidity> InformedRrtStar<S, V, InformedSampler, DenseChecker> {
    /// Informed RRT* with direct informed sampling seeded with `parameters.seed` and full
    /// checks at `parameters.resolution` ([`with_parts`](Self::with_parts) with an
    /// [`InformedSampler`] and a [`DenseChecker`]).
    ///
    /// # Errors
    /// As [`with_parts`](Self::with_parts), and [`BuildError::Validity`] for a resolution the
    /// checker refuses.
    pub fn new(
        space: S,
        validity: V,
        (start, goals): (Vec<f64>, Vec<Vec<f64>>),
        parameters: Parameters,
    ) -> Result<Self, BuildError> {
        checked_range(&space, &validity, (&start, &goals), &parameters)?;
        let checker = DenseChecker::from_resolution(&space, parameters.resolution)?
            .with_acceleration(parameters.accelerated_checks);
        let sampler = InformedSampler::new(&space, &start, &goals, parameters.seed)?;
        Self::with_parts(
            space,
            validity,
            (start, goals),
            sampler,
            checker,
            parameters,
        )
    }

    /// Informed RRT* for `problem` ([`new`](Self::new) with copies of its space, validity
    /// checker and query); the problem's resolution replaces `parameters.resolution`, and its
    /// certification applies unless `parameters` sets one.
    ///
    /// # Errors
    /// [`BuildError::Problem`] if the problem refuses its check step, else as
    /// [`new`](Self::new).
    pub fn for_problem<P>(problem: &P, parameters: &Parameters) -> Result<Self, BuildError>
    where
        P: mit_star_problems::PlanningProblem<Space = S, Validity = V>,
    {
        let (space, validity, query, parameters) = problem_parts(problem, parameters)?;
        Self::new(space, validity, query, parameters)
    }
}

#[cfg(test)]
mod tests;
