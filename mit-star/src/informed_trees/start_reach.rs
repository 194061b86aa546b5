//! The start's side of the frontier: how far the start reaches through edges that pass the
//! sparse checks, for a start in a pocket
//! ([`Parameters::start_frontier`](crate::Parameters::start_frontier)).

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use heuristics::Heuristic;
use samplers::Sampler;
use spaces::{StateSpace, Stop};
use validity::{Counted, EdgeChecker, EdgeStatus, StateValidity};

use crate::informed_trees::eit::Eit;
use crate::informed_trees::guidance::Guidance;

/// Vertices settled between two polls of the stop condition.
const REACH_POLL: usize = 256;

/// A vertex waiting in the start's search with its cost from the start: the cheapest first,
/// ties by id.
#[derive(Debug, Clone, Copy)]
struct Tentative(f64, u32);

impl PartialEq for Tentative {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Tentative {}

impl PartialOrd for Tentative {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Tentative {
    // Reversed: `BinaryHeap` pops the largest.
    fn cmp(&self, other: &Self) -> Ordering {
        other.0.total_cmp(&self.0).then(other.1.cmp(&self.1))
    }
}

/// Scratch of the start's search, kept between batches so it allocates nothing once grown.
#[derive(Debug, Default)]
pub(crate) struct StartReach {
    /// Best cost from the start found so far, per vertex id (∞: not reached).
    cost: Vec<f64>,
    heap: BinaryHeap<Tentative>,
    /// The farthest vertices reached, farthest first, as `(cost from the start, id)`.
    pub(crate) farthest: Vec<(f64, u32)>,
}

/// Keeps `entry` in `best`, the at most `wanted` entries with the largest cost, farthest
/// first, ties by id (so the result does not depend on the order entries come in).
pub(crate) fn keep_farthest(best: &mut Vec<(f64, u32)>, wanted: usize, entry: (f64, u32)) {
    let farther = |a: &(f64, u32), b: &(f64, u32)| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1));
    if best.len() == wanted && farther(&entry, &best[wanted - 1]) != Ordering::Less {
        return;
    }
    let at = best.partition_point(|kept| farther(kept, &entry) == Ordering::Less);
    if best.len() == wanted {
        best.pop();
    }
    best.insert(at, entry);
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
    /// Searches from the start, cheapest first, over the current neighbour lists and the
    /// edges that pass the sparse checks of the current level (storing what the checks
    /// learn, as the reverse search does), and keeps in `self.start_reach.farthest` the
    /// `wanted` vertices it reached at the largest cost, farthest first.
    ///
    /// Returns `false` if it settles more than `cap` vertices (the start's side is not the
    /// smaller one) or the stop condition fires (polled every [`REACH_POLL`] vertices and
    /// inside neighbour queries and checks).
    ///
    /// Complexity: O(c · k) edge lookups and at most as many sparse checks, plus
    /// O(c · k · log c) for the queue, for `c ≤ cap + 1` settled vertices with `k` neighbours
    /// each, and O(n) to reset the costs of the graph's `n` vertex slots.
    pub(crate) fn reach_from_start(&mut self, cap: usize, wanted: usize, stop: &dyn Stop) -> bool {
        let mut reach = std::mem::take(&mut self.start_reach);
        let mut best = std::mem::take(&mut reach.farthest);
        best.clear();
        reach.heap.clear();
        reach.cost.clear();
        reach.cost.resize(self.graph.id_bound(), f64::INFINITY);
        reach.cost[self.start_id as usize] = 0.0;
        reach.heap.push(Tentative(0.0, self.start_id));
        let mut settled = 0_usize;
        let mut complete = true;
        'search: while let Some(Tentative(cost, v)) = reach.heap.pop() {
            if cost > reach.cost[v as usize] {
                continue;
            }
            settled += 1;
            if settled > cap || (settled % REACH_POLL == 0 && stop.should_stop()) {
                complete = false;
                break;
            }
            if v != self.start_id {
                keep_farthest(&mut best, wanted, (cost, v));
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
                match self.sparse_check(v, n.id, true, stop).0 {
                    EdgeStatus::Invalid => {}
                    EdgeStatus::Unknown if stop.should_stop() => {
                        complete = false;
                        break 'search;
                    }
                    _ => {
                        reach.cost[n.id as usize] = through;
                        reach.heap.push(Tentative(through, n.id));
                    }
                }
            }
        }
        reach.farthest = best;
        self.start_reach = reach;
        complete
    }
}
