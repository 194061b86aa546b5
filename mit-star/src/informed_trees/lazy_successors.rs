//! Lazy successors: FCIT*'s way of keeping the forward queue small on a fully connected graph.
//! Instead of queueing all `q − 1` outgoing edges of an expanded vertex, its neighbours are
//! sorted once by `ĉ(v, w) + ĥ(w)` and only the best edge not yet tried is queued; when that
//! edge leaves the queue, the next one takes its place. With the a-priori heuristic
//! ([`APriori`](crate::APriori)) the keys of `v`'s edges are `g(v)` plus these values, so the
//! queue hands out edges in the same order as if all were queued, with at most one queued edge
//! per expanded vertex (plus the few tree edges queued beside the lists).

use mit_star_heuristics::Heuristic;
use mit_star_samplers::Sampler;
use mit_star_spaces::StateSpace;
use mit_star_validity::{Counted, EdgeChecker, StateValidity};

use crate::graph::NONE;
use crate::informed_trees::NeighbourRule;
use crate::informed_trees::eit::Eit;
use crate::informed_trees::forward_queue::ForwardEdge;
use crate::informed_trees::guidance::{Guidance, ReverseSearch};
use crate::informed_trees::reverse_search::forward_keys;

/// One vertex's outgoing edges in the order they are tried in the current batch.
#[derive(Debug, Clone, Default)]
pub(crate) struct Successors {
    /// Positions in the vertex's neighbour list, best `ĉ + ĥ` first.
    pub(crate) order: Vec<u32>,
    /// The next position of `order` to try.
    next: u32,
    /// The batch tag the order was made in (another: the order is stale).
    pub(crate) tag: u32,
    /// The neighbour left out of this expansion (the tree parent it was reached from).
    exclude: u32,
    /// The target of the edge queued from `order`, or `NONE`.
    pub(crate) queued: u32,
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
    /// `true` if forward expansions queue their edges one at a time: the neighbour rule asks
    /// for it and the guidance's heuristic is the a-priori one (with a reverse search, `ĥ`
    /// changes under the queued edges and the order of a list would go stale).
    pub(crate) fn lazy_successors(&self) -> bool {
        G::REVERSE == ReverseSearch::None && self.neighbour_rule.queues_successors_lazily()
    }

    /// Sorts the first `len` neighbours of `v` by `ĉ + ĥ` and queues the best edge that passes
    /// the expansion's rules (not to `exclude`, not blacklisted, a rewiring only where allowed).
    ///
    /// Where `v` may not rewire (every expansion after its first in BIT*'s default), the edges
    /// into the forward tree other than to `v`'s children are left out of the order: the scan
    /// of [`queue_next_successor`](Self::queue_next_successor) would skip them anyway, and on a
    /// complete graph whose tree holds most vertices (a batch without a solution) sorting and
    /// scanning them was most of a re-expansion's time. The order of the edges kept is the
    /// same.
    pub(crate) fn expand_forward_lazily(&mut self, v: u32, len: usize, exclude: u32) {
        let index = v as usize;
        if self.successors.len() <= index {
            self.successors.resize_with(index + 1, Successors::default);
        }
        let rewirings = self.may_rewire(v);
        let mut keyed = std::mem::take(&mut self.successor_keys);
        keyed.clear();
        keyed.reserve(len);
        // One pass over the list, reading each neighbour's vertex once.
        for (i, n) in (0u32..).zip(self.graph.neighbour_slice(v, len)) {
            let target = self.graph.vertex(n.id);
            if !rewirings && target.rewired_from(v) {
                continue;
            }
            keyed.push((order_bits(n.cost + target.cost_to_go_bound), i));
        }
        // Integer keys order as `total_cmp` would, and compare faster.
        keyed.sort_unstable();
        let tag = self.graph.tag;
        let successors = &mut self.successors[index];
        successors.order.clear();
        successors.order.extend(keyed.iter().map(|&(_, i)| i));
        successors.next = 0;
        successors.tag = tag;
        successors.exclude = exclude;
        successors.queued = NONE;
        self.successor_keys = keyed;
        self.queue_next_successor(v);
    }

    /// Queues `v`'s next edge in its order, if one passes the rules and could still improve
    /// the solution. An edge that cannot (`g(v) + ĉ + ĥ ≥ c_best`) stays next: every later one
    /// is as expensive, and a lower `g(v)` ([`refresh_successor`](Self::refresh_successor))
    /// may let it through.
    pub(crate) fn queue_next_successor(&mut self, v: u32) {
        let index = v as usize;
        let Some(successors) = self.successors.get(index) else {
            return;
        };
        if successors.tag != self.graph.tag {
            return;
        }
        let exclude = successors.exclude;
        let mut next = successors.next as usize;
        let g = self.graph.vertex(v).g;
        let rewirings = self.may_rewire(v);
        let mut queued = None;
        while let Some(&i) = self.successors[index].order.get(next) {
            let n = self.graph.neighbour(v, i as usize);
            let target = self.graph.vertex(n.id);
            if g + n.cost + target.cost_to_go_bound >= self.best_cost {
                break;
            }
            next += 1;
            // The cheap tests first: `is_blacklisted` looks the edge up.
            let rewiring = self.is_rewiring(v, n.id);
            if n.id == exclude || (rewiring && !rewirings) || self.is_blacklisted(v, n.id) {
                continue;
            }
            if rewiring {
                self.graph.vertex_mut(v).rewiring_expanded = true;
            }
            queued = Some(ForwardEdge {
                source: v,
                target: n.id,
                hint: i,
                cost: n.cost,
                distance: n.distance,
            });
            break;
        }
        let successors = &mut self.successors[index];
        successors.next = next as u32;
        successors.queued = queued.map_or(NONE, |edge| edge.target);
        if let Some(edge) = queued {
            self.queue_forward(edge);
        }
    }

    /// `true` if an expansion of `v` may queue edges that rewire the forward tree: with
    /// cascading rewirings, or until one of `v`'s expansions has queued such an edge.
    fn may_rewire(&self, v: u32) -> bool {
        self.parameters.cascading_rewirings.unwrap_or(false)
            || !self.graph.vertex(v).rewiring_expanded
    }

    /// After the edge `u → v` left the queue: if it was `u`'s queued successor, queue the next.
    pub(crate) fn advance_successors(&mut self, u: u32, v: u32) {
        if self
            .successors
            .get(u as usize)
            .is_some_and(|s| s.queued == v && s.tag == self.graph.tag)
        {
            self.queue_next_successor(u);
        }
    }

    /// `g(d)` decreased: re-keys `d`'s queued successor, or queues one if its order had stopped
    /// at an edge the old `g(d)` could not afford.
    pub(crate) fn refresh_successor(&mut self, d: u32) {
        let Some(successors) = self.successors.get(d as usize) else {
            return;
        };
        if successors.tag != self.graph.tag {
            return;
        }
        let queued = successors.queued;
        if queued == NONE {
            self.queue_next_successor(d);
            return;
        }
        let i = successors.order[successors.next as usize - 1];
        let n = self.graph.neighbour(d, i as usize);
        let edge = ForwardEdge {
            source: d,
            target: queued,
            hint: i,
            cost: n.cost,
            distance: n.distance,
        };
        let keys = forward_keys(&self.graph, self.key_rule(), &edge);
        self.forward.update(d, queued, keys);
    }
}

/// `x`'s bits, ordered as [`f64::total_cmp`] orders the numbers.
#[inline]
fn order_bits(x: f64) -> u64 {
    let bits = x.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | 1 << 63
    }
}

#[cfg(test)]
mod tests {
    use super::order_bits;

    #[test]
    fn order_bits_orders_as_total_cmp() {
        let xs = [
            f64::NEG_INFINITY,
            -3.5,
            -1e-300,
            -0.0,
            0.0,
            1e-300,
            0.25,
            0.25 + f64::EPSILON,
            7.0,
            f64::INFINITY,
        ];
        for a in xs {
            for b in xs {
                assert_eq!(
                    order_bits(a).cmp(&order_bits(b)),
                    a.total_cmp(&b),
                    "{a} {b}"
                );
            }
        }
    }
}
