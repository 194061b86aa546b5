//! The start's side of the frontier: how far the start reaches through edges that pass the
//! sparse checks, for a start in a pocket
//! ([`Parameters::start_frontier`](crate::Parameters::start_frontier)).

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use mit_star_heuristics::Heuristic;
use mit_star_samplers::Sampler;
use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::{Counted, EdgeChecker, EdgeStatus, StateValidity};

use crate::informed_trees::NeighbourRule;
use crate::informed_trees::eit::Eit;
use crate::informed_trees::forward_queue::bits;
use crate::informed_trees::frontier::keep_farthest;
use crate::informed_trees::guidance::Guidance;

/// Vertices settled between two polls of the stop condition.
const REACH_POLL: usize = 256;

/// Scratch of the start's search, kept between batches so it allocates nothing once grown.
#[derive(Debug, Default)]
pub(crate) struct StartReach {
    /// Best cost from the start found so far, per vertex id (∞: not reached).
    cost: Vec<f64>,
    /// Vertices waiting, cheapest first (costs as order-preserving bits), ties by id. Also the
    /// scratch of the confirmed frontier's walk (`frontier.rs`), which never runs at once.
    pub(crate) heap: BinaryHeap<Reverse<(u64, u32)>>,
    /// The farthest vertices reached, farthest first, as `(cost from the start, id)`.
    pub(crate) farthest: Vec<(f64, u32)>,
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
    /// Searches from the start, cheapest first, over the current neighbour lists and the
    /// edges that pass the sparse checks of the current level (storing what the checks
    /// learn, as the reverse search does), and keeps in `self.start_reach.farthest` the
    /// `wanted` vertices it reached at the largest cost, farthest first.
    ///
    /// Returns `false` if it settles more than `cap` vertices (the start's side is not the
    /// smaller one) or the stop condition fires (polled every [`REACH_POLL`] vertices and
    /// inside neighbour queries). An edge whose check the stop interrupted counts as passed,
    /// as in the reverse search.
    ///
    /// Complexity: O(c · k) edge lookups and at most as many sparse checks, plus
    /// O(c · k · log c) for the queue, for `c ≤ cap + 1` settled vertices with `k` neighbours
    /// each, and O(n) to reset the costs of the graph's `n` vertex slots.
    pub(crate) fn reach_from_start(&mut self, cap: usize, wanted: usize, stop: &dyn Stop) -> bool {
        let mut reach = std::mem::take(&mut self.start_reach);
        reach.farthest.clear();
        reach.heap.clear();
        reach.cost.clear();
        reach.cost.resize(self.graph.id_bound(), f64::INFINITY);
        reach.cost[self.start_id as usize] = 0.0;
        reach.heap.push(Reverse((bits(0.0), self.start_id)));
        let mut settled = 0_usize;
        let mut complete = true;
        while let Some(Reverse((key, v))) = reach.heap.pop() {
            let cost = f64::from_bits(key);
            if cost > reach.cost[v as usize] {
                continue;
            }
            settled += 1;
            if settled > cap || (settled.is_multiple_of(REACH_POLL) && stop.should_stop()) {
                complete = false;
                break;
            }
            if v != self.start_id {
                keep_farthest(&mut reach.farthest, wanted, (cost, v));
            }
            let Some(len) = self.graph.neighbours(v, &self.space, &self.heuristic, stop) else {
                complete = false;
                break;
            };
            for i in 0..len {
                let n = self.graph.neighbour(v, i);
                let through = cost + n.cost;
                if through >= reach.cost[n.id as usize] || self.graph.vertex(n.id).is_terminal() {
                    continue;
                }
                if self.sparse_check(v, n.id, true, stop).0 != EdgeStatus::Invalid {
                    reach.cost[n.id as usize] = through;
                    reach.heap.push(Reverse((bits(through), n.id)));
                }
            }
        }
        self.start_reach = reach;
        complete
    }
}
