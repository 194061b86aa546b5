//! Certification of a solution's path before it is recorded
//! ([`Parameters::lazy_certification`](crate::Parameters::lazy_certification)).
//!
//! With certification on (arms: a grid four times finer than the check step), every edge of a
//! returned path must be certified. Certifying each edge as it joins the forward tree spends
//! most of that work on edges no solution ever uses: on the Panda's MotionBenchMaker problems
//! MIT* certified about twice as many edges as its first solution has on the easy scenes, and
//! ten times as many on `cage`. So an edge that brings a *new* vertex into the tree joins it
//! uncertified, and a solution is recorded only once every edge of its path is certified.
//!
//! The best solution's path stays certified at every moment. Its edges were certified when it
//! was recorded. A vertex joining the tree fresh has no subtree, so its uncertified edge is on
//! no recorded path. A vertex already in the tree moves to a new parent only once the new
//! parent's path and the edge are certified (`forward_step`), so a certified path stays
//! certified under it. Hence every vertex of the best path has a certified path to the start,
//! and the subtree below an uncertified edge never holds one. (Certifying only the edge is not
//! enough: the new parent's own path may hold an uncertified edge, and its failure would cut
//! the best goal out of the tree.) A failed certification blacklists the edge, cuts its
//! child's subtree out of the tree and restarts both searches (edges into the cut vertices
//! may have been dropped from the forward queue while those vertices were cheaper to reach):
//! rare, as failures are — an edge valid at every check point and invalid between them.

use mit_star_heuristics::Heuristic;
use mit_star_samplers::Sampler;
use mit_star_spaces::StateSpace;
use mit_star_validity::{Counted, EdgeChecker, EdgeStatus, StateValidity};

use crate::graph::NONE;
use crate::informed_trees::NeighbourRule;
use crate::informed_trees::eit::Eit;
use crate::informed_trees::guidance::Guidance;
use crate::termination::SolveStop;

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
    /// `true` if edges join the forward tree uncertified and solutions' paths are certified
    /// before they are recorded.
    pub(crate) fn certifies_lazily(&self) -> bool {
        self.parameters.lazy_certification && self.parameters.certification.unwrap_or(1) > 1
    }

    /// Records the goals reached since the last call (`solution_candidates`, in the order they
    /// were reached) whose paths are better than the best solution and certify. A candidate
    /// whose certification the termination condition interrupts stays, with those after it,
    /// for the next iteration.
    pub(crate) fn settle_solutions(&mut self, stop: &SolveStop<'_>) {
        let mut candidates = std::mem::take(&mut self.solution_candidates);
        let mut settled = 0;
        for &goal in &candidates {
            if self.graph.vertex(goal).g < self.best_cost {
                match self.certify_path(goal, stop) {
                    EdgeStatus::Valid => self.record_solution(goal, stop),
                    EdgeStatus::Invalid => {}
                    EdgeStatus::Unknown => break,
                }
            }
            settled += 1;
        }
        candidates.drain(..settled);
        self.solution_candidates = candidates;
    }

    /// Certifies the uncertified edges of the forward-tree path from the start to `end`, from
    /// the start on (at once `Valid` without lazy certification; [`certify`](Self::certify)
    /// passes over an edge certified before). `Invalid` once one fails:
    /// that edge is blacklisted, its child's subtree (with `end`) cut out of the forward tree
    /// and both searches restart at the next iteration. `Unknown` if the termination condition
    /// fired first.
    pub(crate) fn certify_path(&mut self, end: u32, stop: &SolveStop<'_>) -> EdgeStatus {
        if !self.certifies_lazily() {
            return EdgeStatus::Valid;
        }
        let mut path = std::mem::take(&mut self.path_scratch);
        path.clear();
        let mut v = end;
        while v != NONE {
            path.push(v);
            v = self.graph.vertex(v).parent;
        }
        let mut status = EdgeStatus::Valid;
        for pair in path.windows(2).rev() {
            let (child, parent) = (pair[0], pair[1]);
            status = self.certify(parent, child, stop);
            match status {
                EdgeStatus::Valid => {}
                EdgeStatus::Invalid => {
                    let mut stack = std::mem::take(&mut self.scratch);
                    self.graph.detach_subtree(child, &mut stack);
                    self.scratch = stack;
                    self.restart_pending = true;
                    break;
                }
                EdgeStatus::Unknown => break,
            }
        }
        self.path_scratch = path;
        status
    }
}
