//! The reverse search's frontier: the states it reached farthest from the goals, handed to the
//! sampler at the end of a batch without a solution
//! ([`Sampler::observe_frontier`](samplers::Sampler::observe_frontier)).

use std::cmp::Ordering;

use heuristics::Heuristic;
use samplers::Sampler;
use spaces::{StateSpace, Stop};
use validity::{Counted, EdgeChecker, StateValidity};

use crate::informed_trees::eit::Eit;
use crate::informed_trees::guidance::{Guidance, ReverseSearch};

/// Vertices of the reverse tree walked between two polls of the stop condition.
const FRONTIER_POLL: usize = 4096;

/// Farthest first (largest `ĥ`), ties by id, so the frontier does not depend on the walk's
/// order.
fn farther(a: &(f64, u32), b: &(f64, u32)) -> Ordering {
    b.0.total_cmp(&a.0).then(a.1.cmp(&b.1))
}

impl<S, V, Smp, E, H, G> Eit<S, V, Smp, E, H, G>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
    H: Heuristic<S>,
    G: Guidance,
{
    /// Hands the sampler the frontier of the reverse search that just ended: without a
    /// solution, the [`near_frontier`](crate::Parameters::near_frontier) samples of the reverse
    /// tree with the largest cost-to-go `ĥ`, farthest first; with one (or with the count 0, or
    /// without a reverse search), nothing, once, so that the sampler drops what it kept.
    ///
    /// Walks the reverse tree from the goals through its child lists, keeping the best
    /// `near_frontier` in a small sorted buffer. Allocates nothing once the buffers have grown.
    /// Polls `stop` every [`FRONTIER_POLL`] vertices; if it fires, the walk is abandoned and
    /// the sampler keeps the frontier it had (`frontier_states` is always what it holds).
    ///
    /// Complexity: O(t · f) for a reverse tree of `t` vertices and a frontier of `f` states
    /// (the search that built the tree touched each of them already).
    pub(crate) fn send_frontier(&mut self, solved: bool, stop: &dyn Stop) {
        let wanted = self.parameters.near_frontier;
        let held = !self.frontier_states.is_empty();
        if solved || wanted == 0 || G::REVERSE == ReverseSearch::None {
            if held {
                self.frontier_states.clear();
                self.sampler.observe_frontier(&[]);
            }
            return;
        }
        let tag = self.reverse_tag;
        let mut best = std::mem::take(&mut self.frontier);
        best.clear();
        let mut walk = std::mem::take(&mut self.branch);
        walk.clear();
        walk.extend(
            self.goal_ids
                .iter()
                .copied()
                .filter(|&g| self.graph.vertex(g).h(tag).is_finite()),
        );
        let mut walked = 0_usize;
        let mut stopped = false;
        while let Some(v) = walk.pop() {
            walked += 1;
            if walked % FRONTIER_POLL == 0 && stop.should_stop() {
                stopped = true;
                break;
            }
            self.push_reverse_children(v, &mut walk);
            let vertex = self.graph.vertex(v);
            let h = vertex.h(tag);
            if vertex.is_terminal() || !h.is_finite() {
                continue;
            }
            let entry = (h, v);
            if best.len() == wanted && farther(&entry, &best[wanted - 1]) != Ordering::Less {
                continue;
            }
            let at = best.partition_point(|kept| farther(kept, &entry) == Ordering::Less);
            if best.len() == wanted {
                best.pop();
            }
            best.insert(at, entry);
        }
        self.branch = walk;
        if !stopped {
            self.frontier_states.clear();
            for &(_, v) in &best {
                self.frontier_states.extend_from_slice(self.graph.state(v));
            }
            if held || !best.is_empty() {
                self.sampler.observe_frontier(&self.frontier_states);
            }
        }
        self.frontier = best;
    }
}
