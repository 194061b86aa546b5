//! One cost-bounded bidirectional search of [`Aorrtc`]: two trees with costs-to-come, grown
//! toward informed samples under a drawn cost bound per sample (the AO-x meta-algorithm's cost
//! dimension), joined under the best solution's cost.

use mit_star_samplers::{CostBound, SampleError, Sampler};
use mit_star_spaces::rand::RngExt;
use mit_star_spaces::{StateSpace, States, Stop};
use mit_star_validity::{AllValid, Counted, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity};

use super::Aorrtc;
use crate::rrt::rrt_core::RrtCore;
use crate::rrt::tree::{ROOT, Tree, steer};
use crate::termination::SolveStop;

/// The trees of one search: the start tree (0) and the goal tree (1), each state's cost-to-come
/// from its root, and the solution cost the search must beat.
#[derive(Debug, Clone)]
pub(super) struct AoxTrees {
    pub(super) trees: [Tree; 2],
    pub(super) costs: [Vec<f64>; 2],
    /// The tree the next sample grows.
    growing: usize,
    /// The cost every path of this search must beat (`∞`: no search yet).
    pub(super) bound: f64,
    /// A connection found (its state in the start tree, its state in the goal tree) whose edges
    /// are being certified; the stop interrupted the certification.
    connection: Option<(u32, u32)>,
}

/// What one iteration of a search did.
#[derive(Debug, Clone)]
pub(super) enum Found {
    /// Nothing to report (a state added, or not).
    Nothing,
    /// A certified path cheaper than the search's bound.
    Path(States),
    /// The informed set of the bound is empty: the best solution is optimal.
    Optimal,
}

impl AoxTrees {
    pub(super) fn new(dimension: usize) -> Self {
        Self {
            trees: [Tree::new(dimension), Tree::new(dimension)],
            costs: [Vec::new(), Vec::new()],
            growing: 0,
            bound: f64::INFINITY,
            connection: None,
        }
    }

    /// Starts a search that must beat `bound`: the trees hold only the start and the goals.
    pub(super) fn restart(&mut self, start: &[f64], goals: &[Vec<f64>], bound: f64) {
        let dimension = start.len();
        self.trees = [Tree::new(dimension), Tree::new(dimension)];
        self.trees[0].add(start, ROOT);
        for goal in goals {
            self.trees[1].add(goal, ROOT);
        }
        self.costs = [vec![0.0], vec![0.0; goals.len()]];
        self.bound = bound;
        self.connection = None;
    }

    /// States in both trees.
    pub(super) fn size(&self) -> usize {
        self.costs[0].len() + self.costs[1].len()
    }

    fn add(&mut self, t: usize, state: &[f64], parent: u32, cost: f64) -> u32 {
        self.costs[t].push(cost);
        self.trees[t].add(state, parent)
    }

    /// The tree the next sample grows, and whether balancing forced it: alternating, unless
    /// one tree has at least twice the states of the other (then the smaller, forced), as
    /// RRT-Connect with `rrt_balance`.
    fn tree_to_grow(&mut self, balance: bool) -> (usize, bool) {
        let [a, b] = [&self.trees[0], &self.trees[1]].map(|t| t.parents.len());
        let (t, forced) = match (balance, a >= 2 * b, b >= 2 * a) {
            (true, true, _) => (1, true),
            (true, _, true) => (0, true),
            _ => (self.growing, false),
        };
        self.growing = 1 - t;
        (t, forced)
    }

    /// The root of tree `t` nearest to `x` (the start, or the nearest goal) and its distance.
    fn root_for<S: StateSpace>(&self, space: &S, t: usize, x: &[f64]) -> (u32, f64) {
        let tree = &self.trees[t];
        (0..tree.parents.len() as u32)
            .take_while(|&id| tree.parents[id as usize] == ROOT)
            .map(|id| (id, space.distance(tree.state(id), x)))
            .fold(
                (0, f64::INFINITY),
                |best, c| if c.1 < best.1 { c } else { best },
            )
    }
}

/// A uniform draw in `[0, 1)` from the planner's own generator.
fn unit(rng: &mut mit_star_spaces::SeededRng) -> f64 {
    rng.random::<f64>()
}

impl<S, V, E> Aorrtc<S, V, E>
where
    S: StateSpace,
    V: StateValidity,
    E: EdgeChecker<S, Counted<V>> + Clone,
{
    /// One iteration of the cost-bounded search under the best cost `bound`: certify a
    /// pending connection, or draw an informed sample, grow a tree toward it from the nearest
    /// state that can reach it within a drawn cost, and try to join the other tree within what
    /// the bound leaves. Work the stop interrupts is dropped (a state joins a tree only once its
    /// motion is valid), except a connection's certification, which resumes.
    pub(super) fn search_iteration(&mut self, stop: &SolveStop<'_>) -> Found {
        if self.search.connection.is_some() {
            return self.certify_connection(stop);
        }
        let bound = self.search.bound;
        let core = &mut self.connect.core;
        let mut x = std::mem::take(&mut core.target);
        // Any state of the informed set: the motion toward it is what gets checked.
        let drawn = self.informed.sample(
            &core.space,
            &AllValid,
            CostBound::Solution(bound),
            stop,
            &mut x,
        );
        core.target = x;
        match drawn {
            Ok(()) => {}
            Err(SampleError::EmptySet { .. }) => return Found::Optimal,
            Err(_) => return Found::Nothing,
        }
        let (t, forced) = self.search.tree_to_grow(core.parameters.rrt_balance);
        let Some((new, new_cost)) = self.grow(t, forced, stop) else {
            return Found::Nothing;
        };
        self.join(t, new, new_cost, stop)
    }

    /// Grows tree `t` toward the sample in `core.target`; the new state and its cost, or `None`
    /// if nothing was added. A sample outside the nearest state's dynamic domain is skipped
    /// unless balancing `forced` the tree, as in RRT-Connect.
    fn grow(&mut self, t: usize, forced: bool, stop: &SolveStop<'_>) -> Option<(u32, f64)> {
        let bound = self.search.bound;
        let core = &mut self.connect.core;
        let space = &core.space;
        let x = &core.target;
        let (root, g_hat) = self.search.root_for(space, t, x);
        let (_, h_hat) = self.search.root_for(space, 1 - t, x);
        // The sample's cost-to-come bound, drawn between the least it could be and the most
        // the solution bound allows.
        let c_rand = g_hat + unit(&mut self.rng) * (bound - g_hat - h_hat).max(0.0);
        let (mut near, distance) =
            nearest_within_cost(&mut self.search, core, t, root, c_rand, stop)?;
        let dynamic = core.parameters.rrt_dynamic_domain;
        let skips = crate::rrt::rrt_connect::skips_outside_domain(dynamic, forced);
        if skips && distance > self.search.trees[t].radii[near as usize] {
            return None;
        }
        let from = self.search.trees[t].state(near);
        steer(
            &core.space,
            (from, &core.target),
            core.range,
            &mut core.candidate,
        );
        let status = motion_status(core, from, stop);
        if dynamic && status != EdgeStatus::Unknown {
            let radius = &mut self.search.trees[t].radii[near as usize];
            *radius = crate::rrt::rrt_connect::dynamic_radius(
                *radius,
                status == EdgeStatus::Valid,
                core.range,
            );
        }
        if status != EdgeStatus::Valid {
            return None;
        }
        let from = self.search.trees[t].state(near);
        let mut cost =
            self.search.costs[t][near as usize] + core.space.distance(from, &core.candidate);
        // Cost-bound resampling: look for a cheaper parent under redrawn bounds until one fails.
        let g_new = core
            .space
            .distance(self.search.trees[t].state(root), &core.candidate);
        for _ in 0..core.parameters.aorrtc_resamples {
            let range = (cost - g_new).max(0.0);
            if range == 0.0 {
                break;
            }
            let c_rand = g_new + unit(&mut self.rng) * range;
            // The query is the new state: swapped into the target for the search, then back.
            std::mem::swap(&mut core.target, &mut core.candidate);
            let better = nearest_within_cost(&mut self.search, core, t, root, c_rand, stop);
            std::mem::swap(&mut core.target, &mut core.candidate);
            let (other, d) = better?;
            let other_cost = self.search.costs[t][other as usize] + d;
            if other == near || other_cost >= cost {
                break;
            }
            match motion_status(core, self.search.trees[t].state(other), stop) {
                EdgeStatus::Valid => (near, cost) = (other, other_cost),
                EdgeStatus::Invalid => break,
                EdgeStatus::Unknown => return None,
            }
        }
        core.counters.samples += 1;
        Some((self.search.add(t, &core.candidate, near, cost), cost))
    }

    /// Steps from state `new` of tree `t` (cost `new_cost`) toward the other tree's state that
    /// can be reached within the bound, adding each step to tree `t`; a path if all are valid.
    fn join(&mut self, t: usize, new: u32, new_cost: f64, stop: &SolveStop<'_>) -> Found {
        let bound = self.search.bound;
        let core = &mut self.connect.core;
        let b = 1 - t;
        core.target.copy_from_slice(self.search.trees[t].state(new));
        let (root, _) = self.search.root_for(&core.space, b, &core.target);
        let Some((other, distance)) =
            nearest_within_cost(&mut self.search, core, b, root, bound - new_cost, stop)
        else {
            return Found::Nothing;
        };
        if new_cost + distance + self.search.costs[b][other as usize] >= bound {
            return Found::Nothing;
        }
        let steps = (distance / core.range).ceil().max(1.0);
        let length = distance / steps;
        let (from_state, to_state) = &mut self.ends;
        from_state.copy_from_slice(&core.target);
        to_state.copy_from_slice(self.search.trees[b].state(other));
        let (mut last, mut cost) = (new, new_cost);
        for i in 1..=steps as usize {
            if i == steps as usize {
                core.candidate.copy_from_slice(to_state);
            } else {
                let fraction = i as f64 / steps;
                core.space
                    .interpolate(from_state, to_state, fraction, &mut core.candidate);
            }
            if motion_status(core, self.search.trees[t].state(last), stop) != EdgeStatus::Valid {
                return Found::Nothing;
            }
            cost += length;
            last = self.search.add(t, &core.candidate, last, cost);
        }
        self.search.connection = Some(if t == 0 { (last, other) } else { (other, last) });
        self.certify_connection(stop)
    }

    /// Certifies the edges of the pending connection, then returns its path. An edge that
    /// fails certification ends the search (the next starts afresh under the same bound).
    fn certify_connection(&mut self, stop: &SolveStop<'_>) -> Found {
        let Some((in_start, in_goal)) = self.search.connection else {
            return Found::Nothing;
        };
        let core = &mut self.connect.core;
        for (t, end) in [(0, in_start), (1, in_goal)] {
            let mut id = end;
            while self.search.trees[t].parents[id as usize] != ROOT {
                let tree = &self.search.trees[t];
                let parent = tree.parents[id as usize];
                if !tree.certified[id as usize] {
                    if Stop::should_stop(stop) {
                        return Found::Nothing;
                    }
                    match core.certify(tree.state(parent), tree.state(id), stop) {
                        EdgeStatus::Valid => self.search.trees[t].certified[id as usize] = true,
                        EdgeStatus::Unknown => return Found::Nothing,
                        EdgeStatus::Invalid => {
                            let bound = self.search.bound;
                            self.search.restart(&core.start, &core.goals, bound);
                            return Found::Nothing;
                        }
                    }
                }
                id = parent;
            }
        }
        self.search.connection = None;
        let mut path = States::new(core.space.dimension());
        let mut ids = self.search.trees[0].branch(in_start);
        ids.reverse();
        for id in ids {
            path.push(self.search.trees[0].state(id));
        }
        // The meeting state is in both trees: skip the second copy.
        for id in self.search.trees[1].branch(in_goal).into_iter().skip(1) {
            path.push(self.search.trees[1].state(id));
        }
        Found::Path(path)
    }
}

/// The nearest states [`nearest_within_cost`] looks at first; it looks at four times as many
/// each round, up to [`MAX_CANDIDATES`].
const FIRST_CANDIDATES: usize = 8;

/// The most states [`nearest_within_cost`] looks at before it takes the root.
const MAX_CANDIDATES: usize = 32;

/// The state of tree `t` nearest to `core.target` among those that reach it within cost
/// `c_rand` (cost-to-come plus distance), else `root` (whose cost is 0 and which always does),
/// with its distance to the target. Only states nearer than the root are candidates, and only
/// the [`MAX_CANDIDATES`] nearest: past them the root is taken (VAMP's AORRTC looks at every
/// state within the root's distance, which costs time linear in the tree per query once a search
/// near the optimum grows large). The nearest states are fetched in rounds of growing size, so
/// the usual query, whose nearest state qualifies, costs one small k-nearest search. `None` if
/// the stop fired.
fn nearest_within_cost<S, V, Smp, E>(
    search: &mut AoxTrees,
    core: &mut RrtCore<S, V, Smp, E>,
    t: usize,
    root: u32,
    c_rand: f64,
    stop: &dyn Stop,
) -> Option<(u32, f64)>
where
    S: StateSpace,
{
    core.counters.neighbour_queries += 1;
    let tree = &mut search.trees[t];
    let size = tree.parents.len();
    let radius = core.space.distance(tree.state(root), &core.target);
    let costs = &search.costs[t];
    let mut k = FIRST_CANDIDATES;
    let mut seen = 0;
    loop {
        if !tree.nearest(&core.space, &core.target, k, &mut core.neighbours, stop) {
            return None;
        }
        for &(d2, id) in core.neighbours.iter().skip(seen) {
            let d = d2.sqrt();
            if d >= radius {
                return Some((root, radius));
            }
            if tree.parents[id as usize] == ROOT || costs[id as usize] + d <= c_rand {
                return Some((id, d));
            }
        }
        seen = core.neighbours.len();
        if seen >= size || k >= MAX_CANDIDATES {
            return Some((root, radius));
        }
        k *= 4;
    }
}

/// Checks the motion `from → core.candidate` at full resolution and the candidate itself (in
/// the batch of the motion's last grid points).
fn motion_status<S, V, Smp, E>(
    core: &mut RrtCore<S, V, Smp, E>,
    from: &[f64],
    stop: &dyn Stop,
) -> EdgeStatus
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
{
    let mut progress = EdgeProgress::UNTESTED;
    core.check_motion_and_candidate(from, &mut progress, stop)
}
