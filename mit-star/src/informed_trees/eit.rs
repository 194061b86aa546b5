//! [`Eit`]: the EIT* search skeleton every configuration of the family (MIT*, EIT*, the
//! ablations) is an instance of.

use std::cmp::Reverse;
use std::time::Duration;

use mit_star_heuristics::{Euclidean, Heuristic};
use mit_star_samplers::Sampler;
use mit_star_spaces::rand::SeedableRng;
use mit_star_spaces::{SeededRng, StateSpace, States};
use mit_star_validity::{Counted, EdgeChecker, EdgeGrid, EdgeStatus, StateValidity};

use crate::graph::{NONE, RandomGeometricGraph, Vertex};
use crate::informed_trees::forward_queue::ForwardQueue;
use crate::informed_trees::guidance::{EffortInformed, Guidance};
use crate::informed_trees::lazy_successors::{Ranked, Successors};
use crate::informed_trees::neighbour_rule::{NeighbourRule, RandomGeometric};
use crate::informed_trees::reverse_queue::ReverseQueue;
use crate::informed_trees::start_reach::StartReach;
use crate::planner::validate_query;
use crate::termination::SolveStop;
use crate::{
    Counters, Observer, Outcome, Parameters, Planner, PlannerError, Solution, Termination, Trace,
    VertexId, VertexKind,
};

/// Asymmetric bidirectional lazy search on a batched random geometric graph — the EIT*
/// skeleton of Strub and Gammell (IJRR 2022) that MIT* (Zhang et al., T-ASE 2025) builds on —
/// generic over its parts:
///
/// | parameter | part | trait |
/// |---|---|---|
/// | `S` | state space | [`StateSpace`] |
/// | `V` | state validity (wrapped in [`Counted`]) | [`StateValidity`] |
/// | `Smp` | sampler (uniform, informed, adaptive, estimated informed set) | [`Sampler`] |
/// | `E` | edge checker (fixed or length-related sparse levels, dense) | [`EdgeChecker`] |
/// | `H` | admissible heuristic | [`Heuristic`] |
/// | `G` | how the forward search is led to the goals | [`Guidance`] |
/// | `N` | which vertices are neighbours (an RGG, or FCIT*'s complete graph) | [`NeighbourRule`] |
///
/// MIT*, EIT* and the paper's ablations are type aliases choosing the parts
/// ([`MitStar`](crate::MitStar), [`EitStar`](crate::EitStar), [`MitStarAs`](crate::MitStarAs),
/// [`MitStarEis`](crate::MitStarEis), [`MitStarSc`](crate::MitStarSc)).
///
/// # Algorithm
/// A lazy reverse search from the goals computes admissible cost-to-go `ĥ`, cost-to-go
/// estimates `h̃` and effort-to-go `e` over the RGG using only sparse edge checks; a forward
/// search from the start follows it, checking edges at full resolution (effort-greedy before
/// the first solution, A* after), and restarts the reverse search whenever an edge of the lazy
/// path turns out invalid. When neither search can improve, a new batch of samples is drawn
/// (under the current cost bound), samples that cannot improve the solution are pruned, and both
/// searches restart on the denser graph, the forward tree persisting.
///
/// # Arguments
/// The query (start, goals) and the parts; build with [`Eit::builder`] (parameters validated
/// once) or [`Eit::with_parts`].
///
/// # Returns
/// [`Planner::solve`] returns the best valid path so far ([`Outcome`]); repeated calls keep
/// improving it. Every edge of a returned path was checked at full resolution.
///
/// # Complexity
/// Per batch of `m` samples with `q` in total: `O(m log² q)` amortised to insert them in the
/// nearest-neighbour forest, one `O(log q + k)` neighbour query per expanded vertex, and
/// `O(log |queue|)` per queued edge; memory `O(q·k)` for the cached neighbourhoods and one
/// record per checked edge. Edge checking (state validity calls) dominates in practice.
///
/// # Example
/// ```
/// use mit_star::{EitStar, IterationLimit, Planner};
/// use mit_star_spaces::RealVectorSpace;
/// use mit_star_validity::{AxisBox, World};
///
/// let space = RealVectorSpace::cube(2, -0.5, 0.5)?;
/// let world = World::in_space(&space).with_obstacle(AxisBox::new(vec![0.0, -0.1], vec![0.1, 0.8]))?;
/// let mut planner = EitStar::builder(space, world, vec![-0.4, 0.0], vec![vec![0.4, 0.0]])
///     .resolution(1e-3)
///     .seed(7)
///     .build()?;
/// let outcome = planner.solve(&IterationLimit::new(20_000))?;
/// let solution = outcome.solution().expect("a path around the wall");
/// assert!(solution.cost >= 0.8);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct Eit<S, V, Smp, E, H = Euclidean, G = EffortInformed, N = RandomGeometric> {
    pub(crate) space: S,
    pub(crate) validity: Counted<V>,
    pub(crate) sampler: Smp,
    pub(crate) checker: E,
    pub(crate) heuristic: H,
    pub(crate) guidance: std::marker::PhantomData<fn() -> G>,
    /// Which vertices each vertex is joined to in a batch.
    pub(crate) neighbour_rule: N,
    pub(crate) parameters: Parameters,
    pub(crate) name: String,
    pub(crate) start: Vec<f64>,
    pub(crate) goals: Vec<Vec<f64>>,
    /// The sampler and checker as built, restored by `clear`.
    initial: (Smp, E),
    pub(crate) step: f64,
    pub(crate) graph: RandomGeometricGraph,
    pub(crate) forward: ForwardQueue,
    pub(crate) reverse: ReverseQueue,
    pub(crate) reverse_tag: u32,
    pub(crate) start_id: u32,
    pub(crate) goal_ids: Vec<u32>,
    pub(crate) best_cost: f64,
    pub(crate) best_goal: u32,
    /// A solution offered from outside ([`Planner::offer_solution`]) before the graph was
    /// built, with its edges' checking progress: the best one until `setup` grafts it into
    /// the forward tree ([`adopt_offer`](Self::adopt_offer)).
    pub(crate) offered: Option<(Solution, Vec<mit_star_validity::EdgeProgress>)>,
    pub(crate) lower_bound: f64,
    pub(crate) last_prune_cost: f64,
    /// The informed set is empty: no better solution exists.
    pub(crate) exhausted: bool,
    /// A batch was added when the termination condition had fired: its restart of both
    /// searches (neighbour queries over every new sample) waits for the next iteration.
    pub(crate) restart_pending: bool,
    /// Expansions asked for after the termination condition fired, as
    /// `(vertex, excluded neighbour, forward?)`: each costs a neighbour query, so they wait for
    /// the next iteration, which performs them first, in order.
    pub(crate) deferred: Vec<(u32, u32, bool)>,
    /// A reverse-search restart asked for after the termination condition fired.
    pub(crate) reverse_restart_pending: bool,
    /// The a-priori guidance's current inflation `ε` of `ĥ` in the forward order (1: none).
    pub(crate) inflation: f64,
    /// The a-priori guidance's current truncation factor (1: none).
    pub(crate) truncation: f64,
    /// The current batch's search is its final, least inflated one (ABIT*).
    pub(crate) final_search: bool,
    /// The graph holds the start and every goal, and both searches have started.
    pub(crate) ready: bool,
    /// The query was validated (by the builder, or by the first `setup`): `setup` does not
    /// check every goal again.
    query_checked: bool,
    pub(crate) trace: Trace,
    pub(crate) counters: Counters,
    pub(crate) elapsed: Duration,
    pub(crate) observer: Option<Box<dyn Observer>>,
    pub(crate) scratch: Vec<u32>,
    /// Goals reached whose solutions wait for their paths' certification
    /// (`solution_certification.rs`).
    pub(crate) solution_candidates: Vec<u32>,
    /// Scratch: a solution's path, goal first.
    pub(crate) path_scratch: Vec<u32>,
    pub(crate) extras: Vec<u32>,
    /// Scratch: the reverse-tree branch a repair invalidates.
    pub(crate) branch: Vec<u32>,
    pub(crate) batch_ids: Vec<u32>,
    pub(crate) sample: Vec<f64>,
    /// The frontier handed to the sampler (`frontier.rs`): scratch for the reverse tree's
    /// farthest vertices, and the coordinates the sampler holds (empty: none).
    pub(crate) frontier: Vec<(f64, u32)>,
    pub(crate) frontier_states: Vec<f64>,
    /// Scratch of the start's search for its side of the frontier (`start_reach.rs`).
    pub(crate) start_reach: StartReach,
    /// The random draws of the states placed along the best path (`solution_samples.rs`).
    pub(crate) path_rng: SeededRng,
    /// Scratch: the best path's states, `dimension` coordinates each.
    pub(crate) path_states: Vec<f64>,
    /// Scratch: the best path's cumulative corner weights (`solution_samples.rs`).
    pub(crate) corner_weights: Vec<f64>,
    /// Each expanded vertex's outgoing edges in the order they are queued, one at a time,
    /// where the neighbour rule asks for it (`lazy_successors.rs`; FCIT*).
    pub(crate) successors: Vec<Successors>,
    /// Scratch: an order and a heap being ranked (`lazy_successors.rs`), swapped with the
    /// vertex's once complete.
    pub(crate) ranking: (Vec<Ranked>, Vec<Reverse<Ranked>>),
}

/// The generator of the states placed along the best path, from the planner's seed (its own
/// stream: the sampler's draws do not move when it draws).
fn path_rng(seed: u64) -> SeededRng {
    SeededRng::seed_from_u64(seed ^ 0x5eed_0f5a_7a11)
}

impl<S, V, Smp, E, H, G, N> std::fmt::Debug for Eit<S, V, Smp, E, H, G, N> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Eit")
            .field("name", &self.name)
            .field("parameters", &self.parameters)
            .field("vertices", &self.graph.vertex_count())
            .field("best_cost", &self.best_cost)
            .finish_non_exhaustive()
    }
}

impl<S, V, Smp, E, H, G, N> Eit<S, V, Smp, E, H, G, N>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
    H: Heuristic<S>,
    G: Guidance,
    N: NeighbourRule + Default,
{
    /// Whether this planner's reverse search yields while the forward queue is empty when
    /// [`suspend_reverse_when_forward_empty`](Parameters::suspend_reverse_when_forward_empty)
    /// is unset (its guidance's rule).
    #[cfg(test)]
    pub(crate) const SUSPENDS: bool = G::SUSPEND_WHEN_FORWARD_EMPTY;

    /// A planner from ready-made parts. Prefer [`Eit::builder`], which builds the parts from
    /// validated [`Parameters`]; here `parameters` only sets the search's own options (batch
    /// size, η, connection, pruning, suspension rule) and is reported by
    /// [`settings`](Planner::settings).
    #[allow(clippy::too_many_arguments)]
    pub fn with_parts(
        space: S,
        validity: V,
        start: Vec<f64>,
        goals: Vec<Vec<f64>>,
        sampler: Smp,
        checker: E,
        heuristic: H,
        parameters: Parameters,
    ) -> Self {
        let step = <E as EdgeChecker<S, Counted<V>>>::step(&checker);
        let n = space.dimension();
        let graph = RandomGeometricGraph::for_space(&space);
        let parameters_seed = parameters.seed;
        Self {
            initial: (sampler.clone(), checker.clone()),
            space,
            validity: Counted::new(validity),
            sampler,
            checker,
            heuristic,
            guidance: std::marker::PhantomData,
            neighbour_rule: N::default(),
            inflation: parameters.initial_inflation.unwrap_or(1.0),
            truncation: 1.0,
            final_search: false,
            parameters,
            name: String::from("EIT*-skeleton"),
            start,
            goals,
            step,
            graph,
            forward: ForwardQueue::default(),
            reverse: ReverseQueue::default(),
            reverse_tag: 0,
            start_id: NONE,
            goal_ids: Vec::new(),
            best_cost: f64::INFINITY,
            best_goal: NONE,
            offered: None,
            lower_bound: 0.0,
            last_prune_cost: f64::INFINITY,
            exhausted: false,
            restart_pending: false,
            deferred: Vec::new(),
            reverse_restart_pending: false,
            ready: false,
            query_checked: false,
            trace: Trace::default(),
            counters: Counters::default(),
            elapsed: Duration::ZERO,
            observer: None,
            scratch: Vec::new(),
            solution_candidates: Vec::new(),
            path_scratch: Vec::new(),
            extras: Vec::new(),
            branch: Vec::new(),
            batch_ids: Vec::new(),
            sample: vec![0.0; n],
            frontier: Vec::new(),
            frontier_states: Vec::new(),
            start_reach: StartReach::default(),
            path_rng: path_rng(parameters_seed),
            path_states: Vec::new(),
            corner_weights: Vec::new(),
            successors: Vec::new(),
            ranking: (Vec::new(), Vec::new()),
        }
    }
}

impl<S, V, Smp, E, H, G, N> Eit<S, V, Smp, E, H, G, N>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
    H: Heuristic<S>,
    G: Guidance,
    N: NeighbourRule,
{
    /// Sets the name reports print.
    pub fn set_name(&mut self, name: impl Into<String>) {
        self.name = name.into();
    }

    /// Installs an observer of solutions, batches and restarts.
    pub fn set_observer(&mut self, observer: Box<dyn Observer>) {
        self.observer = Some(observer);
    }

    /// The parameters.
    pub fn parameters(&self) -> &Parameters {
        &self.parameters
    }

    /// The random geometric graph, read-only (vertices, forward tree, checked edges).
    pub fn graph(&self) -> &RandomGeometricGraph {
        &self.graph
    }

    /// The state space.
    pub fn space(&self) -> &S {
        &self.space
    }

    /// The validity checker given at construction.
    pub fn validity(&self) -> &V {
        self.validity.inner()
    }

    /// The sampler.
    pub fn sampler(&self) -> &Smp {
        &self.sampler
    }

    /// The full-resolution collision-check step `L`.
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The vertices of the best solution, start first (empty without one, or while the best
    /// solution is one offered from outside before the first solve: [`Planner::offer_solution`]
    /// grafts an offered path into the forward tree when the graph is built).
    pub fn solution_vertices(&self) -> Vec<VertexId> {
        let mut path = Vec::new();
        if self.best_goal == NONE {
            return path;
        }
        let mut v = self.best_goal;
        while v != NONE {
            path.push(VertexId(v));
            v = self.graph.vertex(v).parent;
        }
        path.reverse();
        path
    }

    /// Checks the query: at least one goal; start and goals of the space's dimension, finite,
    /// in bounds and valid.
    ///
    /// # Errors
    /// The first problem found, naming the state.
    pub fn validate_query(&self) -> Result<(), PlannerError> {
        validate_query(&self.space, self.validity.inner(), &self.start, &self.goals)
    }

    /// Marks the query as validated (by the builder), so that `setup` does not check every
    /// goal a second time.
    pub(crate) fn query_validated(mut self) -> Self {
        self.query_checked = true;
        self
    }

    /// Builds the initial graph (start and goals) and both searches, once. Goals are inserted
    /// in blocks of at most 64 KB of coordinates with the stop polled between them (20 000
    /// goals in R^32 took 55 ms unpolled): if it fires, `setup` returns with the graph
    /// partly built, not ready, and the next call goes on from the next block (each call
    /// inserts at least one).
    pub(crate) fn setup(&mut self, stop: &SolveStop<'_>) -> Result<(), PlannerError> {
        if self.ready {
            return Ok(());
        }
        if self.start_id == NONE {
            if !self.query_checked {
                self.validate_query()?;
                self.query_checked = true;
            }
            self.graph = RandomGeometricGraph::for_space(&self.space);
            // FCIT*'s expansions read the vertices outside the tree (`graph::outside_tree`).
            self.graph.outside.enabled = self.lazy_successors();
            let start = self.start.clone();
            let vertex = self.new_vertex(VertexKind::Start, &start);
            self.start_id = self.graph.add_vertex(&start, vertex);
            self.graph.vertex_mut(self.start_id).g = 0.0;
            self.goal_ids.clear();
            self.goal_ids.reserve(self.goals.len());
            self.lower_bound = self
                .heuristic
                .cost_to_go(&self.space, &self.start, &self.goals);
        }
        let block = crate::informed_trees::batch::commit_chunk(self.space.dimension());
        let mut ids = Vec::with_capacity(block.min(self.goals.len()) + 1);
        // At least one block a call, then one more for every poll that lets it go on.
        let mut first = true;
        while self.goal_ids.len() < self.goals.len() {
            if !std::mem::take(&mut first) && mit_star_spaces::Stop::should_stop(stop) {
                return Ok(());
            }
            let from = self.goal_ids.len();
            let to = (from + block).min(self.goals.len());
            ids.clear();
            for i in from..to {
                let vertex = self.goal_vertex(i);
                let id = self.graph.add_vertex(&self.goals[i], vertex);
                self.goal_ids.push(id);
                ids.push(id);
            }
            // The start is committed after the goals, in the last block (with few goals, in
            // the one commit of start and goals as before).
            if to == self.goals.len() {
                ids.push(self.start_id);
            }
            self.graph.commit(&ids);
        }
        // Thousands of goals are indexed (a polled build) rather than scanned by every query.
        self.graph.index_pending(stop);
        self.update_neighbourhood();
        self.forward.clear();
        self.ready = true;
        if let Some((solution, progress)) = self.offered.take() {
            self.adopt_offer(&solution.path, &progress);
        }
        self.restart_searches(stop);
        Ok(())
    }

    /// A vertex for `state` with its static heuristic values.
    pub(crate) fn new_vertex(&self, kind: VertexKind, state: &[f64]) -> Vertex {
        let (space, h) = (&self.space, &self.heuristic);
        let to_come = h.cost_to_come(space, &self.start, state);
        let to_go = h.cost_to_go(space, state, &self.goals);
        let effort = h.effort(space, &self.start, state, self.step);
        Vertex::new(kind, to_come, to_go, effort)
    }

    /// The vertex of goal `index`: its cost to go is the heuristic's to that goal itself (0 for
    /// an admissible one), not a minimum over every goal, so that inserting `m` goals costs
    /// `O(m)` rather than `O(m²)` (5 000 goals took 1.9 s before a 50 ms deadline was polled).
    fn goal_vertex(&self, index: usize) -> Vertex {
        let (space, h) = (&self.space, &self.heuristic);
        let goal = &self.goals[index];
        let to_come = h.cost_to_come(space, &self.start, goal);
        let to_go = h.cost_to_go(space, goal, std::slice::from_ref(goal));
        let effort = h.effort(space, &self.start, goal, self.step);
        Vertex::new(VertexKind::Goal, to_come, to_go, effort)
    }

    /// One iteration (spec §3.1).
    pub(crate) fn iterate(&mut self, stop: &SolveStop<'_>) {
        self.counters.iterations += 1;
        if self.graph.is_pruning() {
            // A pruning interrupted by the termination condition, then its batch, come first.
            self.continue_batch(stop);
        } else if self.forward.is_rekeying() {
            // A reverse restart interrupted by the termination condition comes first.
            self.continue_reverse_restart(stop);
        } else if self.reverse_restart_pending {
            // First: the restart discards the reverse expansions deferred before it.
            self.reverse_restart_pending = false;
            self.restart_reverse(stop);
        } else if !self.solution_candidates.is_empty() {
            // A solution whose certification the termination condition interrupted.
            self.settle_solutions(stop);
        } else if !self.deferred.is_empty() {
            self.run_deferred(stop);
        } else if self.restart_pending {
            self.restart_searches(stop);
        } else if self.sampler.wants_batch() {
            self.add_batch(stop);
        } else if self.continue_reverse() {
            self.reverse_step(stop);
        } else if self.continue_forward() {
            self.forward_step(stop);
        } else {
            self.search_exhausted(stop);
        }
    }

    /// Performs the expansions deferred when the termination condition fired, in order, until
    /// it fires again.
    fn run_deferred(&mut self, stop: &SolveStop<'_>) {
        let pending = std::mem::take(&mut self.deferred);
        for (i, &(v, exclude, forward)) in pending.iter().enumerate() {
            if mit_star_spaces::Stop::should_stop(stop) {
                // Keep the rest, ahead of anything deferred meanwhile.
                let mut rest = pending[i..].to_vec();
                rest.append(&mut self.deferred);
                self.deferred = rest;
                return;
            }
            if forward {
                self.expand_forward(v, exclude, stop);
            } else {
                self.expand_reverse(v, exclude, stop);
            }
        }
    }

    /// `true` once no better solution can exist.
    fn is_optimal(&self) -> bool {
        self.exhausted || self.best_cost <= self.lower_bound * (1.0 + 1e-12)
    }

    /// Records a new best solution ending at `goal`.
    pub(crate) fn record_solution(&mut self, goal: u32, stop: &SolveStop<'_>) {
        let cost = self.graph.vertex(goal).g;
        if cost >= self.best_cost {
            return;
        }
        self.best_cost = cost;
        self.best_goal = goal;
        let time = (self.elapsed + stop.elapsed()).as_secs_f64();
        self.trace.push(time, cost);
        if let Some(observer) = self.observer.as_mut() {
            observer.on_solution(&crate::SolutionEvent {
                time,
                cost,
                iteration: self.counters.iterations,
                vertices: self.graph.vertex_count(),
            });
        }
    }

    /// The best solution's path, after checking that every edge of it is whitelisted.
    fn extract_solution(&self) -> Result<Option<Solution>, PlannerError> {
        let vertices = self.solution_vertices();
        if vertices.is_empty() {
            return Ok(self.offered.as_ref().map(|(solution, _)| solution.clone()));
        }
        // The best goal must still hang from the start (a tree edge cut out under it would
        // leave a path that begins elsewhere).
        if vertices[0].0 != self.start_id {
            return Err(PlannerError::Internal(format!(
                "the best solution's path begins at vertex {}, not at the start",
                vertices[0].0
            )));
        }
        let mut path = States::with_capacity(self.space.dimension(), vertices.len());
        for (i, v) in vertices.iter().enumerate() {
            let x = self.graph.state(v.0);
            if i > 0 {
                let u = vertices[i - 1].0;
                let (a, b) = (self.graph.state(u), x);
                let grid = EdgeGrid::new(self.space.distance(a, b), self.step);
                let record = self.graph.edge(u, v.0);
                let whitelisted = grid.points() == 0
                    || record.is_some_and(|r| {
                        r.status == EdgeStatus::Valid && r.progress.tested() >= grid.points()
                    });
                if !whitelisted {
                    return Err(PlannerError::Internal(format!(
                        "solution edge {u} → {} was not fully checked",
                        v.0
                    )));
                }
                let certify = self.parameters.certification.unwrap_or(1) > 1;
                if certify && !record.is_some_and(|r| r.certified) {
                    return Err(PlannerError::Internal(format!(
                        "solution edge {u} → {} was not certified",
                        v.0
                    )));
                }
            }
            path.push(x);
        }
        Ok(Some(Solution {
            path,
            cost: self.best_cost,
        }))
    }
}

impl<S, V, Smp, E, H, G, N> Planner for Eit<S, V, Smp, E, H, G, N>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
    H: Heuristic<S>,
    G: Guidance,
    N: NeighbourRule,
{
    fn name(&self) -> &str {
        &self.name
    }

    fn solve(&mut self, termination: &dyn Termination) -> Result<Outcome, PlannerError> {
        let stop = SolveStop::new(termination);
        self.setup(&stop)?;
        let mut iterations = 0;
        // Not ready: the stop fired while the goals were being inserted; the next call goes on.
        while self.ready {
            stop.update(iterations, self.best_cost);
            if stop.should_stop_iteration(self.validity.count()) || self.is_optimal() {
                break;
            }
            self.iterate(&stop);
            iterations += 1;
        }
        self.elapsed += stop.elapsed();
        Ok(match self.extract_solution()? {
            Some(solution) => Outcome::Solved(solution),
            None => Outcome::NoSolution,
        })
    }

    fn clear(&mut self) {
        self.sampler = self.initial.0.clone();
        self.checker = self.initial.1.clone();
        self.validity.reset();
        self.graph = RandomGeometricGraph::for_space(&self.space);
        self.forward.clear();
        self.reverse.clear();
        self.reverse_tag = 0;
        self.start_id = NONE;
        self.goal_ids.clear();
        self.best_cost = f64::INFINITY;
        self.best_goal = NONE;
        self.offered = None;
        self.last_prune_cost = f64::INFINITY;
        self.exhausted = false;
        self.restart_pending = false;
        self.deferred.clear();
        self.solution_candidates.clear();
        self.reverse_restart_pending = false;
        self.inflation = self.parameters.initial_inflation.unwrap_or(1.0);
        self.truncation = 1.0;
        self.final_search = false;
        self.frontier_states.clear();
        self.ready = false;
        self.trace.clear();
        self.counters = Counters::default();
        self.elapsed = Duration::ZERO;
        self.path_rng = path_rng(self.parameters.seed);
        self.successors.clear();
    }

    fn best_cost(&self) -> f64 {
        self.best_cost
    }

    fn offer_solution(&mut self, solution: &Solution) -> bool {
        if solution.cost >= self.best_cost {
            return false;
        }
        let certification = self.parameters.certification.unwrap_or(1);
        let parts = (&self.space, &self.validity, &mut self.checker);
        let query = (self.start.as_slice(), self.goals.as_slice());
        let mut progress = Vec::with_capacity(solution.path.len());
        let path = &solution.path;
        if !crate::planner::offered_path_is_valid(parts, certification, query, path, &mut progress)
        {
            return false;
        }
        let cost = crate::planner::path_cost(&self.space, path);
        if cost >= self.best_cost {
            return false;
        }
        self.best_cost = cost;
        self.trace.push(self.elapsed.as_secs_f64(), cost);
        if self.ready {
            self.adopt_offer(path, &progress);
        } else {
            self.offered = Some((
                Solution {
                    path: path.clone(),
                    cost,
                },
                progress,
            ));
        }
        true
    }

    fn trace(&self) -> &Trace {
        &self.trace
    }

    fn counters(&self) -> Counters {
        let mut c = self.counters.with_parts(
            <E as EdgeChecker<S, Counted<V>>>::counters(&self.checker),
            self.validity.count(),
            &self.sampler.counters(),
        );
        c.neighbour_queries = self.graph.neighbour_queries();
        c.vertices = self.graph.vertex_count() as u64;
        c.edges = self.graph.edge_count() as u64;
        c.peak_vertices = c.peak_vertices.max(c.vertices);
        c.peak_edges = c.peak_edges.max(c.edges);
        c
    }

    /// The parameters this planner reads: those of its configuration when its name is one's
    /// label ([`Configuration::settings`](crate::Configuration::settings)), else every one.
    fn settings(&self) -> Vec<(String, String)> {
        match crate::Configuration::ALL
            .into_iter()
            .find(|c| c.label() == self.name)
        {
            Some(configuration) => configuration.settings(&self.parameters),
            None => self.parameters.settings(),
        }
    }

    fn snapshot(&self) -> Option<crate::Snapshot> {
        Some(self.graph_snapshot())
    }
}
