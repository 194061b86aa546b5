//! [`RrtConnect`]: Kuffner and LaValle's bidirectional RRT (2000), from the framework's parts.

use mit_star_samplers::{CostBound, Sampler, UniformSampler};
use mit_star_spaces::{StateSpace, States, Stop};
use mit_star_validity::{
    Counted, DenseChecker, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity,
};

use crate::rrt::rrt_core::{RrtCore, problem_parts};
use crate::rrt::tree::{ROOT, Tree, snapshot_of, steer};
use crate::termination::SolveStop;
use crate::{
    BuildError, Counters, Outcome, Parameters, Planner, PlannerError, Snapshot, Termination, Trace,
};

/// RRT-Connect (Kuffner & LaValle, ICRA 2000): a tree from the start and a tree from the goals
/// grow towards uniform samples in steps of at most [`range`](Self::range); after each step,
/// the other tree greedily extends towards the new state until it is reached or blocked. The
/// first connection is returned (the planner is not asymptotically optimal: later `solve` calls
/// return the same path).
///
/// Built from the framework's parts: the space's uniform sampling through [`UniformSampler`],
/// full edge checks through an [`EdgeChecker`] (batched for arms; when the problem asks for
/// certification, the edges of a connection are certified before it is returned, and an edge
/// that fails is cut from its tree with its subtree),
/// [`NearestNeighbors`](crate::NearestNeighbors) per tree (a scan with the space's metric when
/// it is not Euclidean), the shared termination conditions, trace and counters.
///
/// # Arguments
/// A query (space, validity checker, start, goals) and [`Parameters`]: `resolution` (the
/// check step), `range` (`None`: the paper's 0.3, 0.5, 1.25, 3.0 in R^2, R^4, R^8, R^16, else
/// 0.2 of the maximum extent, OMPL's default), `seed`, `certification`.
///
/// # Returns
/// From [`solve`](Planner::solve): the first path found, or no solution when the termination
/// condition fires first; trees persist across calls.
///
/// # Complexity
/// Per iteration: two nearest-neighbour queries per step (`O(log n)` expected), one motion
/// check of at most `range / step` states.
///
/// ```
/// use mit_star::{FirstSolution, Planner, RrtConnect, TerminationExt, TimeLimit};
/// let problem = mit_star_problems::DividingWalls::new(2).build()?.with_resolution(1e-4)?;
/// let mut planner = RrtConnect::for_problem(&problem, &mit_star::Parameters::default())?;
/// let outcome = planner.solve(&FirstSolution.or(TimeLimit::seconds(5.0)))?;
/// assert!(outcome.is_solved());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct RrtConnect<S, V, E = DenseChecker> {
    /// The query, parts, parameters, solution and records (AORRTC's too: it starts with this
    /// planner and keeps its parts).
    pub(super) core: RrtCore<S, V, UniformSampler, E>,
    /// The start tree (0) and the goal tree (1).
    trees: [Tree; 2],
    /// The tree that grows towards the next sample.
    growing: usize,
    phase: Phase,
    /// A motion check the stop interrupted, resumed by the next iteration.
    pending: Option<Motion>,
    /// A connection found (its state in the start tree, its state in the goal tree) whose
    /// edges are being certified; the stop interrupted the certification.
    connection: Option<(u32, u32)>,
    /// Per tree, the recent share of its draws (forced or not) that fell inside the nearest
    /// state's dynamic domain (which decides whether a forced tree redraws, see
    /// [`skips_outside_domain`]): an average over about [`LANDING_MEMORY`] draws, from 1.
    landing: [f64; 2],
}

/// What one step towards a state did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Step {
    /// Added a state `range` towards the target.
    Advanced(u32),
    /// Added the target itself.
    Reached(u32),
    /// The candidate or the motion was invalid: nothing added.
    Trapped,
    /// The stop fired; a motion check interrupted is pending.
    Stopped,
}

/// A motion being checked: from state `near` of `tree` to the planner's candidate state.
#[derive(Debug, Clone, Copy)]
struct Motion {
    tree: usize,
    near: u32,
    /// A step towards a sample (whose outcome updates the dynamic domain), not a connection.
    grows: bool,
    /// The candidate is the target itself.
    reached: bool,
    progress: EdgeProgress,
}

/// Where an iteration stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Phase {
    /// Growing a tree towards a sample.
    Grow,
    /// Tree `1 − from` steps towards state `new` of tree `from`.
    Connect { from: usize, new: u32 },
}

/// A state's dynamic-domain radius after an extension from it succeeded (`valid`) or failed:
/// a first failure sets it to [`DOMAIN_RADIUS`] ranges; later outcomes scale it by
/// `1 ± DOMAIN_RATE`, never below one range (Yershova et al., 2005, with VAMP's constants).
pub(super) fn dynamic_radius(radius: f64, valid: bool, range: f64) -> f64 {
    match (radius.is_finite(), valid) {
        (false, true) => radius,
        (false, false) => DOMAIN_RADIUS * range,
        (true, true) => radius * (1.0 + DOMAIN_RATE),
        (true, false) => (radius * (1.0 - DOMAIN_RATE)).max(range),
    }
}

/// Whether a step towards a sample outside the nearest state's dynamic domain is skipped (the
/// iteration ends): with the dynamic domain on, unless balancing forced the tree (one tree
/// has at least twice the states of the other, so the smaller grows).
///
/// A forced tree is the only one that may grow, so a skipped sample is an iteration that does
/// nothing. A tree stuck at a state whose every step fails (a goal deep in a shelf) keeps a
/// domain of at least one range, which a uniform sample in 8 dimensions hits about once in
/// 10⁴ draws; balancing then never lets the other tree grow, and the search stalls (Fetch,
/// `bookshelf_thin` #3: 13 million iterations in 1 s, three states). A forced tree instead
/// redraws a sample outside the domain up to
/// [`rrt_forced_redraws`](crate::Parameters::rrt_forced_redraws) times within the iteration,
/// and then steps towards the last draw, inside the domain or not; and it redraws only while
/// at least [`MIN_LANDING`] of the tree's recent draws fell inside (where the domain is a speck
/// of the space, as for a 14-joint robot or a stuck goal in 8 dimensions, redrawing would only
/// cost).
pub(super) fn skips_outside_domain(dynamic_domain: bool, forced: bool) -> bool {
    dynamic_domain && !forced
}

/// How many of a tree's recent draws its landing share averages over (the weight of one draw
/// is its inverse).
const LANDING_MEMORY: f64 = 32.0;

/// The least share of a tree's recent draws inside its domain with which it redraws when
/// forced.
const MIN_LANDING: f64 = 1.0 / 16.0;

/// Redraws between two polls of the stop condition while a forced tree redraws samples
/// outside its domain (a redraw is a draw and a nearest-neighbour query: well under a
/// microsecond).
const REDRAW_POLL: u32 = 64;

/// A state's first dynamic-domain radius, in ranges.
const DOMAIN_RADIUS: f64 = 4.0;

/// How much a dynamic-domain radius grows or shrinks per outcome.
const DOMAIN_RATE: f64 = 1e-4;

/// The paper's RRT-Connect range in R^`n` (for its unit-cube problems), else 0.2 of the
/// maximum extent (OMPL's default).
pub fn default_range(dimension: usize, maximum_extent: f64) -> f64 {
    match dimension {
        2 => 0.3,
        4 => 0.5,
        8 => 1.25,
        16 => 3.0,
        _ => 0.2 * maximum_extent,
    }
}

impl<S, V, E> RrtConnect<S, V, E>
where
    S: StateSpace,
    V: StateValidity,
    E: EdgeChecker<S, Counted<V>> + Clone,
{
    /// A planner for the query with ready-made checker `checker` and `parameters` (validated
    /// here: the range, the seed's sampler, the certification factor).
    ///
    /// # Errors
    /// [`BuildError::Parameter`] for a parameter out of range, [`BuildError::Query`] for a
    /// malformed query.
    pub fn with_checker(
        space: S,
        validity: V,
        query: (Vec<f64>, Vec<Vec<f64>>),
        checker: E,
        parameters: Parameters,
    ) -> Result<Self, BuildError> {
        let n = space.dimension();
        let sampler = match (parameters.rrt_halton, parameters.rrt_halton_shift) {
            (false, _) => UniformSampler::new(parameters.seed),
            (true, true) => UniformSampler::halton(parameters.seed),
            (true, false) => UniformSampler::unshifted_halton(parameters.seed),
        };
        let parts = (sampler, checker);
        let core = RrtCore::new(space, validity, query, parts, parameters, "RRT-Connect")?;
        Ok(Self {
            core,
            trees: [Tree::new(n), Tree::new(n)],
            growing: 0,
            phase: Phase::Grow,
            pending: None,
            connection: None,
            landing: [1.0; 2],
        })
    }

    /// The maximum length of one extension.
    pub fn range(&self) -> f64 {
        self.core.range
    }

    /// Sets the name reports print (default `RRT-Connect`).
    pub fn set_name(&mut self, name: impl Into<String>) {
        self.core.name = name.into();
    }

    /// Plants the roots once: the start, then the goals in blocks of at most 64 KB of
    /// coordinates with `stop` polled between them (20 000 goals in R^32 took 12 ms
    /// unpolled). `false` if the stop fired first: the next call goes on from the next block
    /// (each call plants at least one).
    pub(super) fn setup(&mut self, stop: &dyn Stop) -> bool {
        if self.trees[0].parents.is_empty() {
            self.trees[0].add(&self.core.start, ROOT);
        }
        // Only roots until every goal is planted: the goal tree grows after setup.
        let block = crate::informed_trees::batch::commit_chunk(self.core.space.dimension());
        let goals = self.core.goals.len();
        // At least one block a call, then one more for every poll that lets it go on.
        let mut first = true;
        while self.trees[1].parents.len() < goals {
            let from = self.trees[1].parents.len();
            if !std::mem::take(&mut first) && stop.should_stop() {
                return false;
            }
            for goal in &self.core.goals[from..(from + block).min(goals)] {
                self.trees[1].add(goal, ROOT);
            }
        }
        true
    }

    /// The state of tree `t` nearest to `target`, or `None` if the stop fired mid-query.
    fn nearest(&mut self, t: usize, target: &[f64], stop: &dyn Stop) -> Option<u32> {
        self.core.counters.neighbour_queries += 1;
        let complete =
            self.trees[t].nearest(&self.core.space, target, 1, &mut self.core.neighbours, stop);
        complete
            .then(|| self.core.neighbours.iter().next().map(|&(_, id)| id))
            .flatten()
    }

    /// The tree the next sample grows, and whether balancing forced it: the other one than
    /// last time, unless balancing is on and one tree has at least twice the states of the
    /// other, then the smaller (forced).
    fn tree_to_grow(&self) -> (usize, bool) {
        let [a, b] = [&self.trees[0], &self.trees[1]].map(|t| t.parents.len());
        if self.core.parameters.rrt_balance {
            if a >= 2 * b {
                return (1, true);
            }
            if b >= 2 * a {
                return (0, true);
            }
        }
        (self.growing, false)
    }

    /// Draws the next sample into `self.core.target` (a valid state with
    /// [`rrt_valid_samples`](crate::Parameters::rrt_valid_samples), else any state); `false`
    /// if the stop fired first.
    fn draw_target(&mut self, stop: &dyn Stop) -> bool {
        let mut sample = std::mem::take(&mut self.core.target);
        let drawn = if self.core.parameters.rrt_valid_samples {
            self.core.sampler.sample(
                &self.core.space,
                &self.core.validity,
                CostBound::Unbounded,
                stop,
                &mut sample,
            )
        } else {
            self.core.sampler.draw_any(&self.core.space, &mut sample)
        };
        self.core.target = sample;
        // A uniform sampler fails only when stopped (the query was validated, so the
        // dimensions agree).
        drawn.is_ok()
    }

    /// Starts a step of tree `t` from its state nearest to `self.core.target` towards it: the
    /// candidate state (at most `range` away) goes to `self.core.candidate` and the motion to
    /// it becomes the pending one ([`finish_motion`](Self::finish_motion) checks both).
    /// `Stopped` if the stop fired during the nearest-neighbour query or a redraw. A step
    /// towards a sample (`grows`) outside the nearest state's dynamic domain is skipped,
    /// unless balancing `forced` this tree: that tree redraws instead, up to
    /// [`rrt_forced_redraws`](crate::Parameters::rrt_forced_redraws) times, then steps towards
    /// the last draw (see [`skips_outside_domain`]).
    fn start_motion(
        &mut self,
        t: usize,
        grows: bool,
        forced: bool,
        stop: &dyn Stop,
    ) -> Option<Step> {
        let dynamic = grows && self.core.parameters.rrt_dynamic_domain;
        let mut redraws = 0_u32;
        loop {
            let target = std::mem::take(&mut self.core.target);
            let near = self.nearest(t, &target, stop);
            self.core.target = target;
            let Some(near) = near else {
                return Some(Step::Stopped);
            };
            let from = self.trees[t].state(near);
            let outside = dynamic
                && self.core.space.distance(from, &self.core.target)
                    > self.trees[t].radii[near as usize];
            if dynamic {
                let landed = if outside { 0.0 } else { 1.0 };
                self.landing[t] += (landed - self.landing[t]) / LANDING_MEMORY;
            }
            if outside && skips_outside_domain(dynamic, forced) {
                // Outside the nearest state's dynamic domain: skipped, nothing checked.
                return Some(Step::Trapped);
            }
            if outside
                && redraws < self.core.parameters.rrt_forced_redraws
                && self.landing[t] >= MIN_LANDING
            {
                redraws += 1;
                if redraws.is_multiple_of(REDRAW_POLL) && stop.should_stop()
                    || !self.draw_target(stop)
                {
                    return Some(Step::Stopped);
                }
                continue;
            }
            let reached = steer(
                &self.core.space,
                (from, &self.core.target),
                self.core.range,
                &mut self.core.candidate,
            );
            self.pending = Some(Motion {
                tree: t,
                near,
                grows,
                reached,
                progress: EdgeProgress::UNTESTED,
            });
            return None;
        }
    }

    /// Checks the pending motion at every grid point, then its end, and adds the end to its
    /// tree if both are valid (certification, when the problem asks for it, waits for a connection: see
    /// [`certify_connection`](Self::certify_connection)). A check the stop interrupts stays
    /// pending with its progress, and the next call resumes it.
    fn finish_motion(&mut self, stop: &dyn Stop) -> Step {
        let Some(mut motion) = self.pending.take() else {
            return Step::Trapped;
        };
        let from = self.trees[motion.tree].state(motion.near);
        // The candidate itself last, in the batch of the motion's last grid points: the grid
        // points, in bisection order and batches, reject most invalid extensions sooner than
        // one check of its end.
        let status = self
            .core
            .check_motion_and_candidate(from, &mut motion.progress, stop);
        if motion.grows && self.core.parameters.rrt_dynamic_domain && status != EdgeStatus::Unknown
        {
            let radius = &mut self.trees[motion.tree].radii[motion.near as usize];
            *radius = dynamic_radius(*radius, status == EdgeStatus::Valid, self.core.range);
        }
        match status {
            EdgeStatus::Invalid => Step::Trapped,
            EdgeStatus::Unknown => {
                self.pending = Some(motion);
                Step::Stopped
            }
            EdgeStatus::Valid => {
                let candidate = std::mem::take(&mut self.core.candidate);
                let id = self.trees[motion.tree].add(&candidate, motion.near);
                self.core.candidate = candidate;
                self.core.counters.samples += 1;
                if motion.reached {
                    Step::Reached(id)
                } else {
                    Step::Advanced(id)
                }
            }
        }
    }

    /// One iteration: grow a tree one step towards a uniform sample, then let the other tree
    /// step towards the new state until it reaches it (a solution) or is blocked. Work the
    /// stop interrupts (a motion check, the connect phase) resumes at the next call.
    pub(super) fn iterate(&mut self, stop: &SolveStop<'_>) {
        self.core.counters.iterations += 1;
        if self.connection.is_some() {
            self.certify_connection(stop);
            return;
        }
        loop {
            let step = match self.phase {
                Phase::Grow if self.pending.is_none() => {
                    if !self.draw_target(stop) {
                        return;
                    }
                    let (t, forced) = self.tree_to_grow();
                    // The trees take turns, whatever this step does.
                    self.growing = 1 - t;
                    match self.start_motion(t, true, forced, stop) {
                        Some(step) => step,
                        None => self.finish_motion(stop),
                    }
                }
                Phase::Connect { from, new } if self.pending.is_none() => {
                    let target = self.trees[from].state(new);
                    self.core.target.copy_from_slice(target);
                    match self.start_motion(1 - from, false, false, stop) {
                        Some(step) => step,
                        None => self.finish_motion(stop),
                    }
                }
                Phase::Grow | Phase::Connect { .. } => self.finish_motion(stop),
            };
            match (self.phase, step) {
                (_, Step::Stopped) => return,
                (Phase::Grow, Step::Trapped) => return,
                (Phase::Grow, Step::Advanced(id) | Step::Reached(id)) => {
                    let from = 1 - self.growing;
                    self.phase = Phase::Connect { from, new: id };
                }
                (Phase::Connect { .. }, Step::Trapped) => {
                    self.phase = Phase::Grow;
                    return;
                }
                (Phase::Connect { .. }, Step::Advanced(_)) => {}
                (Phase::Connect { from, new }, Step::Reached(joined)) => {
                    let (in_start, in_goal) = if from == 0 {
                        (new, joined)
                    } else {
                        (joined, new)
                    };
                    self.phase = Phase::Grow;
                    self.connection = Some((in_start, in_goal));
                    self.certify_connection(stop);
                    return;
                }
            }
            if stop.should_stop() {
                return;
            }
        }
    }

    /// Certifies the edges of the pending connection not yet certified (on the grid
    /// `certification` times finer than the check step), then records its path as the
    /// solution. An edge that fails is cut from its tree with everything below it, and the
    /// search goes on; a certification the stop interrupts resumes at the next call. Only the
    /// edges of a connection are certified, not every extension: most never join a path.
    fn certify_connection(&mut self, stop: &SolveStop<'_>) {
        let Some((in_start, in_goal)) = self.connection else {
            return;
        };
        for (t, end) in [(0, in_start), (1, in_goal)] {
            let mut id = end;
            while self.trees[t].parents[id as usize] != ROOT {
                let tree = &self.trees[t];
                let parent = tree.parents[id as usize];
                if !tree.certified[id as usize] {
                    // Polled between edges too: a certification on a grid of at most
                    // `STOP_POLL` new points does not poll.
                    if mit_star_spaces::Stop::should_stop(stop) {
                        return;
                    }
                    match self.core.certify(tree.state(parent), tree.state(id), stop) {
                        EdgeStatus::Valid => self.trees[t].certified[id as usize] = true,
                        EdgeStatus::Unknown => return,
                        EdgeStatus::Invalid => {
                            self.connection = None;
                            self.trees[t].prune(id);
                            return;
                        }
                    }
                }
                id = parent;
            }
        }
        self.connection = None;
        self.record_solution(in_start, in_goal, stop);
    }

    fn record_solution(&mut self, in_start_tree: u32, in_goal_tree: u32, stop: &SolveStop<'_>) {
        let mut path = States::new(self.core.space.dimension());
        let mut ids = self.trees[0].branch(in_start_tree);
        ids.reverse();
        for id in ids {
            path.push(self.trees[0].state(id));
        }
        // The meeting state is in both trees: skip its goal-tree copy.
        for id in self.trees[1].branch(in_goal_tree).into_iter().skip(1) {
            path.push(self.trees[1].state(id));
        }
        self.core.record(path, stop);
    }
}

impl<S, V, E> Planner for RrtConnect<S, V, E>
where
    S: StateSpace,
    V: StateValidity,
    E: EdgeChecker<S, Counted<V>> + Clone,
{
    fn name(&self) -> &str {
        &self.core.name
    }

    fn solve(&mut self, termination: &dyn Termination) -> Result<Outcome, PlannerError> {
        let stop = SolveStop::new(termination);
        if !self.setup(&stop) {
            return Ok(self.core.finish(&stop));
        }
        self.core.record_if_start_is_a_goal(&stop);
        let mut iterations = 0;
        while self.core.solution.is_none() {
            stop.update(iterations, self.best_cost());
            if stop.should_stop_iteration(self.core.validity.count()) {
                break;
            }
            self.iterate(&stop);
            iterations += 1;
        }
        Ok(self.core.finish(&stop))
    }

    fn clear(&mut self) {
        self.core.clear();
        let n = self.core.space.dimension();
        self.trees = [Tree::new(n), Tree::new(n)];
        self.growing = 0;
        self.phase = Phase::Grow;
        self.pending = None;
        self.connection = None;
        self.landing = [1.0; 2];
    }

    fn best_cost(&self) -> f64 {
        self.core.best_cost()
    }

    fn trace(&self) -> &Trace {
        &self.core.trace
    }

    fn counters(&self) -> Counters {
        let mut c = self.core.counters();
        c.vertices = (self.trees[0].parents.len() + self.trees[1].parents.len()) as u64;
        c.edges = c.vertices.saturating_sub(1 + self.core.goals.len() as u64);
        c.peak_vertices = c.vertices;
        c.peak_edges = c.edges;
        c
    }

    fn settings(&self) -> Vec<(String, String)> {
        self.core
            .settings(crate::Configuration::RrtConnect, Vec::new())
    }

    fn snapshot(&self) -> Option<Snapshot> {
        Some(snapshot_of(&self.trees, self.best_cost()))
    }
}

impl<S: StateSpace, V: StateValidity> RrtConnect<S, V, DenseChecker> {
    /// RRT-Connect with full checks at `parameters.resolution`
    /// ([`with_checker`](Self::with_checker) and a [`DenseChecker`]).
    ///
    /// # Errors
    /// As [`with_checker`](Self::with_checker), and [`BuildError::Validity`] for a resolution
    /// the checker refuses.
    pub fn new(
        space: S,
        validity: V,
        query: (Vec<f64>, Vec<Vec<f64>>),
        parameters: Parameters,
    ) -> Result<Self, BuildError> {
        let checker = DenseChecker::from_resolution(&space, parameters.resolution)?
            .with_acceleration(parameters.accelerated_checks);
        Self::with_checker(space, validity, query, checker, parameters)
    }
}

impl<S, V> RrtConnect<S, V, DenseChecker>
where
    S: StateSpace + Clone,
    V: StateValidity + Clone,
{
    /// RRT-Connect for `problem` with `parameters` (the problem's resolution replaces
    /// `parameters.resolution`; its certification applies unless `parameters` sets one).
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
mod tests {
    use super::*;
    use crate::{FirstSolution, TerminationExt, TimeLimit};

    #[test]
    fn goals_are_planted_in_polled_blocks_and_setup_resumes() {
        // 5 000 goals in R^4: blocks of 2 048 (64 KB of coordinates). Before blocks, every
        // goal was planted at once, the stop unread.
        let world = mit_star_validity::World::new(vec![0.0; 4], vec![1.0; 4]);
        let goals = (0..5_000)
            .map(|i| vec![0.6 + 0.3 * (f64::from(i) / 5_000.0), 0.5, 0.5, 0.5])
            .collect();
        let problem = mit_star_problems::Problem::new("goals", world, vec![0.1; 4], goals).unwrap();
        let mut planner = RrtConnect::for_problem(&problem, &Parameters::default()).unwrap();
        let expired = TimeLimit::until(std::time::Instant::now());
        let fired = SolveStop::new(&expired);
        assert!(!planner.setup(&fired));
        assert_eq!(planner.trees[1].parents.len(), 2_048);
        assert!(!planner.solve(&expired).unwrap().is_solved());
        assert_eq!(planner.trees[1].parents.len(), 4_096);
        let first = planner.solve(&FirstSolution.or(TimeLimit::seconds(10.0)));
        assert!(first.unwrap().is_solved());
        assert_eq!(planner.trees[0].parents[0], ROOT);
        assert!(planner.trees[1].parents[..5_000].iter().all(|&p| p == ROOT));
    }

    #[test]
    fn default_ranges_follow_the_paper_then_ompl() {
        assert_eq!(default_range(2, 1.0), 0.3);
        assert_eq!(default_range(4, 1.0), 0.5);
        assert_eq!(default_range(8, 1.0), 1.25);
        assert_eq!(default_range(16, 1.0), 3.0);
        assert_eq!(default_range(7, 10.0), 2.0);
    }

    #[test]
    fn steps_are_at_most_the_range_and_the_first_solution_stays() {
        let problem = mit_star_problems::DividingWalls::new(2)
            .build()
            .unwrap()
            .with_resolution(1e-4)
            .unwrap();
        let parameters = Parameters {
            range: Some(0.1),
            seed: 3,
            ..Parameters::default()
        };
        let mut planner = RrtConnect::for_problem(&problem, &parameters).unwrap();
        assert_eq!(planner.range(), 0.1);
        let stop = FirstSolution.or(TimeLimit::seconds(10.0));
        let first = planner.solve(&stop).unwrap();
        let path = &first.solution().unwrap().path;
        assert_eq!(&path[0], problem.start());
        assert_eq!(&path[path.len() - 1], &problem.goals()[0][..]);
        for (a, b) in path.iter().zip(path.iter().skip(1)) {
            assert!(problem.space().distance(a, b) <= 0.1 + 1e-12);
            assert!(problem.world().segment_verdict(a, b).is_valid());
        }
        assert_eq!(planner.trace().len(), 1);
        // Not asymptotically optimal: a later call returns the same path at once.
        let again = planner.solve(&TimeLimit::seconds(0.01)).unwrap();
        assert_eq!(again, first);
        let snapshot = planner.snapshot().unwrap();
        assert_eq!(
            snapshot.forward_edges.len() + snapshot.reverse_edges.len() + 2,
            snapshot.states.len()
        );
        planner.clear();
        assert_eq!(planner.best_cost(), f64::INFINITY);
        assert_eq!(planner.solve(&stop).unwrap(), first);
    }

    #[test]
    fn a_bad_range_is_a_typed_error() {
        let problem = mit_star_problems::DividingWalls::new(2).build().unwrap();
        for range in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let parameters = Parameters {
                range: Some(range),
                ..Parameters::default()
            };
            let error = RrtConnect::for_problem(&problem, &parameters).unwrap_err();
            assert!(error.to_string().contains("range"), "{error}");
        }
    }

    #[test]
    fn samples_are_checked_only_when_asked_and_paths_are_valid_from_any_draws() {
        let problem = mit_star_problems::DividingWalls::new(2)
            .build()
            .unwrap()
            .with_resolution(1e-4)
            .unwrap();
        for (valid_samples, halton) in [(false, false), (true, false), (false, true)] {
            let parameters = Parameters {
                range: Some(0.1),
                seed: 5,
                rrt_valid_samples: valid_samples,
                rrt_halton: halton,
                ..Parameters::default()
            };
            let mut planner = RrtConnect::for_problem(&problem, &parameters).unwrap();
            let outcome = planner
                .solve(&FirstSolution.or(TimeLimit::seconds(10.0)))
                .unwrap();
            let path = &outcome.solution().unwrap().path;
            for (a, b) in path.iter().zip(path.iter().skip(1)) {
                assert!(problem.world().segment_verdict(a, b).is_valid());
            }
            let sampler_checks = planner.counters().sampler_checks;
            assert_eq!(sampler_checks > 0, valid_samples, "{sampler_checks}");
        }
    }

    #[test]
    fn the_unshifted_halton_sequence_takes_the_same_steps_for_every_seed() {
        let problem = mit_star_problems::DividingWalls::new(2)
            .build()
            .unwrap()
            .with_resolution(1e-4)
            .unwrap();
        // The first solution and the work it took (validity: the test above).
        let first_path = |seed: u64, shift: bool| {
            let parameters = Parameters {
                range: Some(0.1),
                seed,
                rrt_halton: true,
                rrt_halton_shift: shift,
                ..Parameters::default()
            };
            let mut planner = RrtConnect::for_problem(&problem, &parameters).unwrap();
            let stop = FirstSolution.or(TimeLimit::seconds(10.0));
            let outcome = planner.solve(&stop).unwrap();
            assert!(outcome.is_solved());
            (outcome, planner.counters().iterations)
        };
        // The plain sequence: one search, whatever the seed.
        let plain = first_path(3, false);
        assert_eq!(first_path(4, false), plain);
        assert_eq!(first_path(11, false), plain);
        // Shifted by the seed (the default): other points, another search.
        assert_ne!(first_path(3, true), first_path(4, true));
    }

    /// RRT-Connect's counters after up to 4 000 iterations (or 10 s) on a goal at the
    /// centre of a hollow 0.02 wide in R^`n` whose one opening is 0.01 wide, with range 0.05:
    /// every step from the goal fails, its dynamic domain shrinks towards one range, and
    /// balancing makes the goal tree (one state against the start tree's two) the only one
    /// that may grow.
    fn enclosed_goal_counters(n: usize, redraws: u32) -> crate::Counters {
        let problem = mit_star_problems::GoalEnclosure::new(n)
            .inside(0.02)
            .gap(0.01)
            .build()
            .unwrap()
            .with_resolution(1e-3)
            .unwrap();
        let parameters = Parameters {
            range: Some(0.05),
            seed: 1,
            rrt_forced_redraws: redraws,
            ..Parameters::default()
        };
        let mut planner = RrtConnect::for_problem(&problem, &parameters).unwrap();
        planner
            .solve(&crate::IterationLimit::new(4000).or(TimeLimit::seconds(10.0)))
            .unwrap();
        planner.counters()
    }

    #[test]
    fn a_forced_tree_redraws_while_its_draws_land_in_its_domain() {
        let default = Parameters::default().rrt_forced_redraws;
        // In R^2 the goal's domain (a disc of radius 0.05 to 0.2) holds a few per cent of the
        // draws: the stuck goal tree redraws, still steps every iteration, and gets out.
        let plane = enclosed_goal_counters(2, default);
        assert!(plane.full_checks >= plane.iterations / 2, "{plane:?}");
        assert!(plane.samples_drawn > 2 * plane.iterations, "{plane:?}");
        // In R^8 it holds about one draw in 10^5: after a few dozen draws the tree stops
        // redrawing, even without a bound on the redraws, and steps towards each draw.
        for redraws in [default, u32::MAX] {
            let space = enclosed_goal_counters(8, redraws);
            assert!(space.iterations >= 4000, "{space:?}");
            assert!(space.full_checks >= space.iterations / 2, "{space:?}");
            assert!(space.samples_drawn < space.iterations + 1000, "{space:?}");
        }
        // With no redraws, one draw an iteration.
        let none = enclosed_goal_counters(2, 0);
        assert!(none.samples_drawn <= none.iterations + 1, "{none:?}");
        assert!(skips_outside_domain(true, false));
        assert!(!skips_outside_domain(true, true));
        assert!(!skips_outside_domain(false, false));
    }

    #[test]
    fn dynamic_domain_radii_start_at_four_ranges_and_stay_above_one() {
        assert_eq!(dynamic_radius(f64::INFINITY, true, 0.5), f64::INFINITY);
        assert_eq!(dynamic_radius(f64::INFINITY, false, 0.5), 2.0);
        assert!(dynamic_radius(2.0, true, 0.5) > 2.0);
        assert!(dynamic_radius(2.0, false, 0.5) < 2.0);
        assert_eq!(dynamic_radius(0.5, false, 0.5), 0.5);
    }
}
