//! The iteration of [`InformedRrtStar`]: drawing and steering, the motion check, the
//! neighbourhood, choosing the parent, rewiring, recording solutions and pruning. Every phase
//! but drawing can be interrupted by the stop and resumes at the next call.

use mit_star_samplers::{CostBound, SampleError, Sampler};
use mit_star_spaces::rand::RngExt;
use mit_star_spaces::{StateSpace, States, Stop};
use mit_star_validity::{Counted, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity};

use super::{InformedRrtStar, PRUNE_THRESHOLD};
use crate::rrt::tree::steer;
use crate::termination::SolveStop;
use crate::{Planner, k_nearest};

/// What is known of a candidate's edge to the new state.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Known {
    Unchecked,
    Valid,
    Invalid,
}

/// A neighbour of the new state: its id, its distance, its cost-to-come plus that distance.
#[derive(Debug, Clone, Copy)]
pub(super) struct Candidate {
    id: u32,
    distance: f64,
    cost: f64,
    known: Known,
}

/// Where an iteration stands; the stop may interrupt any phase but `Sample`, and the next call
/// resumes it.
#[derive(Debug, Clone, Copy)]
pub(super) enum Phase {
    /// Drawing a state and steering towards it.
    Sample,
    /// Checking the motion from vertex `near` to the new state (a goal's if `goal`).
    Extend {
        near: u32,
        goal: Option<usize>,
        progress: EdgeProgress,
    },
    /// The motion is valid: querying the new state's neighbours.
    Neighbourhood { near: u32, goal: Option<usize> },
    /// Checking candidate parents cheapest first; `next` is the one being checked.
    ChooseParent {
        near: u32,
        goal: Option<usize>,
        next: usize,
        progress: EdgeProgress,
    },
    /// Vertex `new` is in the tree: rewiring the candidates from `next` on through it.
    Rewire {
        new: u32,
        next: usize,
        progress: EdgeProgress,
    },
}

impl<S, V, Smp, E> InformedRrtStar<S, V, Smp, E>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
{
    /// Fully checks (and certifies when asked) the edge from `vertex` to the new state.
    fn check_edge(
        &mut self,
        vertex: u32,
        progress: &mut EdgeProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus {
        let from = self.tree.state(vertex);
        self.core.check_to_candidate(from, progress, stop)
    }

    /// With probability `goal_bias`, the next goal not yet in the tree (none once all are).
    fn goal_target(&mut self) -> Option<usize> {
        let n = self.core.goals.len();
        let g = (0..n)
            .map(|i| (self.next_goal + i) % n)
            .find(|&g| self.goal_vertices[g].is_none())?;
        if self.coin.random::<f64>() >= self.core.parameters.goal_bias {
            return None;
        }
        self.next_goal = (g + 1) % n;
        Some(g)
    }

    /// Draws a target, steers from its nearest vertex and, if the new state is valid, moves to
    /// [`Phase::Extend`] (`Ok(true)`). `Ok(false)`: nothing to extend this iteration (stopped,
    /// or the new state is invalid). An error: the sampler can draw nothing more.
    fn draw(&mut self, stop: &dyn Stop) -> Result<bool, SampleError> {
        let goal = self.goal_target();
        if let Some(g) = goal {
            self.core.target.copy_from_slice(&self.core.goals[g]);
        } else {
            let bound = self
                .core
                .solution
                .as_ref()
                .map_or(CostBound::Unbounded, |s| CostBound::Solution(s.cost));
            let drawn = self.core.sampler.sample(
                &self.core.space,
                &self.core.validity,
                bound,
                stop,
                &mut self.core.target,
            );
            match drawn {
                Ok(()) => {}
                Err(SampleError::Stopped) => return Ok(false),
                Err(error) => return Err(error),
            }
        }
        self.core.counters.neighbour_queries += 1;
        if !self.tree.search().nearest(
            &self.core.space,
            &self.core.target,
            1,
            &mut self.core.neighbours,
            stop,
        ) {
            return Ok(false);
        }
        let Some(&(distance, near)) = self.core.neighbours.iter().next() else {
            return Ok(false);
        };
        if distance == 0.0 {
            return Ok(false);
        }
        let from = self.tree.state(near);
        let reached = steer(
            &self.core.space,
            (from, &self.core.target),
            self.core.range,
            &mut self.core.candidate,
        );
        if !self.core.validity.is_valid(&self.core.candidate) {
            return Ok(false);
        }
        let goal = goal.filter(|_| reached);
        let progress = EdgeProgress::UNTESTED;
        self.phase = Phase::Extend {
            near,
            goal,
            progress,
        };
        Ok(true)
    }

    /// The neighbours of the new state closer than the range (and `near`), cheapest first;
    /// `false` if the stop interrupted the query.
    fn find_neighbourhood(&mut self, near: u32, stop: &dyn Stop) -> bool {
        let (n, eta) = (
            self.core.space.dimension(),
            self.core.parameters.rrt_rewire_factor,
        );
        let k = k_nearest(self.tree.len() + 1, n, eta);
        self.core.counters.neighbour_queries += 1;
        if !self.tree.search().nearest(
            &self.core.space,
            &self.core.candidate,
            k,
            &mut self.core.neighbours,
            stop,
        ) {
            return false;
        }
        self.candidates.clear();
        for &(_, id) in self.core.neighbours.iter() {
            let distance = self
                .core
                .space
                .distance(self.tree.state(id), &self.core.candidate);
            // OMPL's k-nearest RRT* connects only neighbours closer than the range.
            if id == near || distance < self.core.range {
                let cost = self.tree.cost(id) + distance;
                let known = Known::Unchecked;
                self.candidates.push(Candidate {
                    id,
                    distance,
                    cost,
                    known,
                });
            }
        }
        self.candidates
            .sort_unstable_by(|a, b| a.cost.total_cmp(&b.cost).then(a.id.cmp(&b.id)));
        true
    }

    /// Checks candidate parents cheapest first until one's edge is valid, never one dearer
    /// than `near` (whose edge is valid), and adds the new state under it. `None` if the stop
    /// interrupted a check (the phase keeps its progress).
    fn choose_parent(
        &mut self,
        (near, goal): (u32, Option<usize>),
        mut next: usize,
        mut progress: EdgeProgress,
        stop: &dyn Stop,
    ) -> Option<u32> {
        let near_edge = self
            .core
            .space
            .distance(self.tree.state(near), &self.core.candidate);
        let through_near = self.tree.cost(near) + near_edge;
        let (parent, edge) = loop {
            let Some(&c) = self.candidates.get(next) else {
                break (near, near_edge);
            };
            if c.id == near || c.cost >= through_near {
                break (near, near_edge);
            }
            match self.check_edge(c.id, &mut progress, stop) {
                EdgeStatus::Unknown => {
                    self.phase = Phase::ChooseParent {
                        near,
                        goal,
                        next,
                        progress,
                    };
                    return None;
                }
                EdgeStatus::Invalid => {
                    self.candidates[next].known = Known::Invalid;
                    next += 1;
                    progress = EdgeProgress::UNTESTED;
                }
                EdgeStatus::Valid => break (c.id, c.distance),
            }
        };
        if let Some(c) = self.candidates.iter_mut().find(|c| c.id == parent) {
            c.known = Known::Valid;
        }
        let new = self.tree.add(&self.core.candidate, parent, edge);
        if let Some(g) = goal {
            self.goal_vertices[g] = Some(new);
        }
        self.core.counters.samples += 1;
        self.peak_vertices = self.peak_vertices.max(self.tree.len());
        Some(new)
    }

    /// Rewires the candidates from `next` on through `new` where that is cheaper and the edge
    /// valid, finishing each cost propagation and recording improved solutions as it goes.
    /// `false` if the stop interrupted (the phase keeps its place).
    fn rewire(
        &mut self,
        new: u32,
        mut next: usize,
        mut progress: EdgeProgress,
        stop: &SolveStop<'_>,
    ) -> bool {
        loop {
            if !self.tree.propagate(stop) {
                self.phase = Phase::Rewire {
                    new,
                    next,
                    progress,
                };
                return false;
            }
            self.update_solution(stop);
            let Some(&c) = self.candidates.get(next) else {
                return true;
            };
            let cheaper = self.tree.cost(new) + c.distance < self.tree.cost(c.id);
            if cheaper && c.id != self.tree.parent(new) && c.known != Known::Invalid {
                let valid = c.known == Known::Valid
                    || match self.check_edge(c.id, &mut progress, stop) {
                        EdgeStatus::Unknown => {
                            self.phase = Phase::Rewire {
                                new,
                                next,
                                progress,
                            };
                            return false;
                        }
                        status => status == EdgeStatus::Valid,
                    };
                if valid {
                    self.tree.rewire(c.id, new, c.distance);
                }
            }
            next += 1;
            progress = EdgeProgress::UNTESTED;
        }
    }

    /// Records the cheapest goal vertex's path if it improves on the best solution.
    fn update_solution(&mut self, stop: &SolveStop<'_>) {
        let tree = &self.tree;
        let cheapest = self
            .goal_vertices
            .iter()
            .flatten()
            .copied()
            .min_by(|&a, &b| tree.cost(a).total_cmp(&tree.cost(b)));
        let Some(goal) = cheapest else { return };
        let cost_to_come = tree.cost(goal);
        if self.best_goal.is_some_and(|(_, c)| cost_to_come >= c) {
            return;
        }
        let mut path = States::new(self.core.space.dimension());
        for &id in tree.branch(goal).iter().rev() {
            path.push(tree.state(id));
        }
        self.best_goal = Some((goal, cost_to_come));
        self.core.record(path, stop);
    }

    /// OMPL's `pruneTree`, once the best cost improved by more than 5 % since the last prune
    /// (abandoned, to be retried, if the stop fires).
    fn prune(&mut self, stop: &dyn Stop) {
        let best = self.best_cost();
        let pruned = self.pruned_cost;
        let improved = !pruned.is_finite() || (pruned - best).abs() / pruned > PRUNE_THRESHOLD;
        if !self.core.parameters.pruning || !best.is_finite() || !improved {
            return;
        }
        let (space, start, goals) = (&self.core.space, &self.core.start, &self.core.goals);
        let best_goal = self.best_goal.map(|(id, _)| id);
        let keep = |id: u32, x: &[f64]| {
            let to_goal = goals
                .iter()
                .map(|g| space.distance(x, g))
                .fold(f64::INFINITY, f64::min);
            Some(id) == best_goal || space.distance(start, x) + to_goal <= best
        };
        let before = self.tree.len();
        let Some(renumbered) = self.tree.prune(keep, stop) else {
            return;
        };
        self.core.counters.pruned += (before - self.tree.len()) as u64;
        for vertex in &mut self.goal_vertices {
            *vertex = vertex.and_then(|id| renumbered[id as usize]);
        }
        self.best_goal = self
            .best_goal
            .and_then(|(id, c)| Some((renumbered[id as usize]?, c)));
        self.pruned_cost = best;
    }

    /// One RRT* iteration, or the rest of one the stop interrupted. `false` if the sampler
    /// can draw nothing more (the informed set is empty: the solution is optimal).
    pub(super) fn iterate(&mut self, stop: &SolveStop<'_>) -> bool {
        loop {
            match self.phase {
                Phase::Sample => {
                    self.core.counters.iterations += 1;
                    match self.draw(stop) {
                        Ok(true) => {}
                        Ok(false) => return true,
                        Err(_) => return false,
                    }
                }
                Phase::Extend {
                    near,
                    goal,
                    mut progress,
                } => match self.check_edge(near, &mut progress, stop) {
                    EdgeStatus::Unknown => {
                        self.phase = Phase::Extend {
                            near,
                            goal,
                            progress,
                        };
                        return true;
                    }
                    EdgeStatus::Invalid => {
                        self.phase = Phase::Sample;
                        return true;
                    }
                    EdgeStatus::Valid => self.phase = Phase::Neighbourhood { near, goal },
                },
                Phase::Neighbourhood { near, goal } => {
                    if !self.find_neighbourhood(near, stop) {
                        return true;
                    }
                    let progress = EdgeProgress::UNTESTED;
                    self.phase = Phase::ChooseParent {
                        near,
                        goal,
                        next: 0,
                        progress,
                    };
                }
                Phase::ChooseParent {
                    near,
                    goal,
                    next,
                    progress,
                } => {
                    let Some(new) = self.choose_parent((near, goal), next, progress, stop) else {
                        return true;
                    };
                    let progress = EdgeProgress::UNTESTED;
                    self.phase = Phase::Rewire {
                        new,
                        next: 0,
                        progress,
                    };
                }
                Phase::Rewire {
                    new,
                    next,
                    progress,
                } => {
                    if self.rewire(new, next, progress, stop) {
                        self.phase = Phase::Sample;
                        self.prune(stop);
                    }
                    return true;
                }
            }
        }
    }
}
