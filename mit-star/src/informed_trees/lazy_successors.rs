//! Lazy successors: FCIT*'s way of keeping the forward queue small on a fully connected graph.
//! Instead of queueing all `q − 1` outgoing edges of an expanded vertex, its edges are ranked
//! once by `ĉ(v, w) + ĥ(w)` and only the best edge not yet tried is queued; when that edge
//! leaves the queue, the next one takes its place. With the a-priori heuristic
//! ([`APriori`](crate::APriori)) the keys of `v`'s edges are `g(v)` plus these values, so the
//! queue hands out edges in the order queueing all of them would, with at most one queued edge
//! per expanded vertex (plus the few tree edges queued beside them). One rule differs from
//! queueing all at once: without cascading rewirings a vertex queues at most one rewiring
//! (an edge into the tree other than to its children), since the first one queued marks it
//! as having rewired; queued all at once, its first expansion that meets any would queue
//! them all.
//!
//! On a complete, uncapped graph ([`listless`](Eit::listless)) no neighbour list is kept: a
//! vertex's list would be every other live vertex of the graph's log, in log order, so an
//! expansion that may still rewire ranks the log itself, and one that may not ranks only the
//! vertices outside the tree (`graph/outside_tree.rs`) and its children. Either way each edge
//! is measured as a list entry would be, and ties are broken by log position, which orders as
//! a list position would.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use mit_star_heuristics::Heuristic;
use mit_star_samplers::Sampler;
use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::{Counted, EdgeChecker, StateValidity};

use crate::graph::NONE;
use crate::graph::Neighbourhood;
use crate::informed_trees::NeighbourRule;
use crate::informed_trees::eit::Eit;
use crate::informed_trees::forward_queue::ForwardEdge;
use crate::informed_trees::guidance::{Guidance, ReverseSearch};
use crate::informed_trees::reverse_search::forward_keys;
use crate::nearest::Poll;

/// An edge of an order: its sort key ([`order_bits`] of `ĉ + ĥ`), its target's position in
/// the neighbour list or in the log (which order alike on a complete graph), its target.
/// Tuples order by key, then position.
pub(crate) type Ranked = (u64, u32, u32);

/// One vertex's outgoing edges in the order they are tried in the current batch.
#[derive(Debug, Clone, Default)]
pub(crate) struct Successors {
    /// The edges out of the tree (and to the vertex's children), best `ĉ + ĥ` first; with
    /// cascading rewirings, every edge.
    pub(crate) order: Vec<Ranked>,
    /// The next position of `order` to try.
    next: u32,
    /// While the vertex may still queue its one rewiring: its edges into the tree, a min-heap
    /// merged into `order` as the walk goes. Emptied once a rewiring is queued, since every
    /// edge left in it would be passed over.
    pub(crate) rewirings: BinaryHeap<Reverse<Ranked>>,
    /// The batch tag the order was made in (another: the order is stale).
    pub(crate) tag: u32,
    /// The neighbour left out of this expansion (the tree parent it was reached from).
    exclude: u32,
    /// The target of the edge queued from the order, or `NONE`.
    pub(crate) queued: u32,
}

impl Successors {
    /// The next edge to try: the least of `order`'s next and the rewirings' least.
    fn peek(&self) -> Option<Ranked> {
        let listed = self.order.get(self.next as usize).copied();
        let rewiring = self.rewirings.peek().map(|r| r.0);
        match (listed, rewiring) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// Passes over `edge`, the one [`peek`](Self::peek) returned.
    fn advance(&mut self, edge: Ranked) {
        if self.rewirings.peek().is_some_and(|r| r.0 == edge) {
            self.rewirings.pop();
        } else {
            self.next += 1;
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
    /// `true` if forward expansions queue their edges one at a time: the neighbour rule asks
    /// for it and the guidance's heuristic is the a-priori one (with a reverse search, `ĥ`
    /// changes under the queued edges and the order of a list would go stale).
    pub(crate) fn lazy_successors(&self) -> bool {
        G::REVERSE == ReverseSearch::None && self.neighbour_rule.queues_successors_lazily()
    }

    /// Sorts the first `len` neighbours of `v` by `ĉ + ĥ` and queues the best edge that passes
    /// the expansion's rules (not to `exclude`, not blacklisted, a rewiring only where allowed).
    ///
    /// A vertex queues at most one rewiring, in the first expansion that meets one it may
    /// queue (BIT*'s rule without cascading rewirings, one edge at a time). So the edges into
    /// the forward tree other than to `v`'s children are not sorted: where `v` may no longer
    /// rewire they are left out (the walk of
    /// [`queue_next_successor`](Self::queue_next_successor) would pass over them), and where
    /// it may they go to a heap, which hands them out in order until one is queued and is
    /// then emptied. On a complete graph whose tree holds most vertices (a batch without a
    /// solution) those edges were most of each order: sorting them and walking past them
    /// took a third of a run. The edges are tried in the order a full sort gives.
    pub(crate) fn expand_forward_lazily(
        &mut self,
        v: u32,
        len: usize,
        exclude: u32,
        stop: &dyn Stop,
    ) -> bool {
        let index = v as usize;
        if self.successors.len() <= index {
            self.successors.resize_with(index + 1, Successors::default);
        }
        let rewirings = self.may_rewire(v);
        // With cascading rewirings every edge into the tree may be queued: all are sorted.
        let apart = rewirings && !self.parameters.cascading_rewirings.unwrap_or(false);
        let (mut order, mut heap) = std::mem::take(&mut self.ranking);
        order.clear();
        heap.clear();
        let ranked = if !self.listless() {
            self.rank_list(v, len, rewirings, apart, (&mut order, &mut heap));
            true
        } else if rewirings {
            self.rank_log(v, apart, (&mut order, &mut heap), stop)
        } else {
            self.rank_outside(v, &mut order);
            true
        };
        if !ranked {
            // Interrupted: the vertex's order stays as it was, and the expansion is retried.
            self.ranking = (order, heap);
            return false;
        }
        // Integer keys order as `total_cmp` would, and compare faster.
        order.sort_unstable();
        let tag = self.graph.tag;
        let successors = &mut self.successors[index];
        let order = std::mem::replace(&mut successors.order, order);
        let heap = std::mem::replace(&mut successors.rewirings, BinaryHeap::from(heap));
        self.ranking = (order, heap.into_vec());
        let successors = &mut self.successors[index];
        successors.next = 0;
        successors.tag = tag;
        successors.exclude = exclude;
        successors.queued = NONE;
        self.queue_next_successor(v);
        true
    }

    /// Ranks the first `len` entries of `v`'s list: into `order`, or, for the edges into the
    /// tree, into `heap` (`apart`) or nowhere (without `rewirings`).
    fn rank_list(
        &self,
        v: u32,
        len: usize,
        rewirings: bool,
        apart: bool,
        (order, heap): (&mut Vec<Ranked>, &mut Vec<Reverse<Ranked>>),
    ) {
        order.reserve(len);
        let hopeless = self.hopeless(v);
        // One pass over the list, reading each neighbour's vertex once.
        for (i, n) in (0u32..).zip(self.graph.neighbour_slice(v, len)) {
            let target = self.graph.vertex(n.id);
            if !hopeless(n.cost, target.cost_to_go_bound) {
                let into_tree = target.rewired_from(v);
                let edge = (order_bits(n.cost + target.cost_to_go_bound), i, n.id);
                file(edge, into_tree, rewirings, apart, (order, heap));
            }
        }
    }

    /// Ranks every other live vertex of the log, as `v`'s complete list would hold it: the
    /// edges into the tree into `heap` if `apart`, the others into `order`. `false` if `stop`
    /// fired.
    fn rank_log(
        &self,
        v: u32,
        apart: bool,
        (order, heap): (&mut Vec<Ranked>, &mut Vec<Reverse<Ranked>>),
        stop: &dyn Stop,
    ) -> bool {
        let graph = &self.graph;
        let a = graph.state(v);
        let hopeless = self.hopeless(v);
        let mut poll = Poll::new(stop, a.len());
        for (position, &(w, birth)) in (0u32..).zip(graph.log.iter_from(0)) {
            if poll.tick(1) {
                return false;
            }
            if w == v || graph.births[w as usize] != birth {
                continue;
            }
            let target = graph.vertex(w);
            let (cost, _) = graph.measure(a, w, &self.space, &self.heuristic);
            if !hopeless(cost, target.cost_to_go_bound) {
                let into_tree = target.rewired_from(v);
                let edge = (order_bits(cost + target.cost_to_go_bound), position, w);
                file(edge, into_tree, true, apart, (&mut *order, &mut *heap));
            }
        }
        true
    }

    /// A test of the edges out of `v` that can never be queued: with a solution of cost
    /// `c_best`, an edge whose `ĝ(v) + ĉ + ĥ` reaches it fails the walk's test `g(v) + ĉ + ĥ ≥
    /// c_best` now and after any later improvement of `g(v)` (never below `ĝ(v)`) or of
    /// `c_best` (which only falls), so it is left out of the order. Without a solution,
    /// nothing is.
    fn hopeless(&self, v: u32) -> impl Fn(f64, f64) -> bool + use<S, V, Smp, E, H, G, N> {
        let (bound, best) = (self.graph.vertex(v).cost_to_come_bound, self.best_cost);
        move |cost: f64, h: f64| best.is_finite() && bound + cost + h >= best
    }

    /// `true` if FCIT*'s expansions need no neighbour lists: on a complete, uncapped graph a
    /// vertex's list would hold every other live vertex of the log, in log order (a list
    /// position orders as a log position does), so an expansion reads the log itself, or,
    /// once it may no longer rewire, the vertices outside the tree (`graph::outside_tree`,
    /// kept only for the lazy successors).
    pub(crate) fn listless(&self) -> bool {
        let graph = &self.graph;
        graph.outside.enabled
            && graph.neighbourhood == Neighbourhood::Radius(f64::INFINITY)
            && graph.neighbour_cap == usize::MAX
    }

    /// Appends to `order` the edges of `v`'s complete list that do not rewire the tree: to the
    /// logged vertices outside the tree, and to `v`'s logged children; each ranked by its key
    /// and then its target's log position (the list's order), measured as a list entry is.
    fn rank_outside(&self, v: u32, order: &mut Vec<Ranked>) {
        let graph = &self.graph;
        let x = graph.vertex(v);
        // Its list would hold the live vertices other than `v` in the log.
        let limit = graph.log.len() as u32;
        let a = graph.state(v);
        let hopeless = self.hopeless(v);
        let mut rank = |w: u32, position: u32, bound: f64| {
            let (cost, _) = graph.measure(a, w, &self.space, &self.heuristic);
            if !hopeless(cost, bound) {
                order.push((order_bits(cost + bound), position, w));
            }
        };
        for c in &graph.outside.entries {
            if c.position >= limit || c.id == v || graph.births[c.id as usize] != c.birth {
                continue;
            }
            let target = graph.vertex(c.id);
            // In the tree: a child of `v` is ranked below, any other vertex is a rewiring.
            if !target.g.is_finite() {
                rank(c.id, c.position, target.cost_to_go_bound);
            }
        }
        let mut child = x.first_child;
        while child != NONE {
            let target = graph.vertex(child);
            if let Some(position) = graph.log_position(child)
                && position < limit
            {
                rank(child, position, target.cost_to_go_bound);
            }
            child = target.next_sibling;
        }
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
        let g = self.graph.vertex(v).g;
        let rewirings = self.may_rewire(v);
        // Without a solution the test `g + ĉ + ĥ ≥ c_best` fails for every finite key, and
        // the edge is not measured for it.
        let bounded = self.best_cost.is_finite() || !g.is_finite();
        let mut queued = None;
        while let Some(edge @ (key, _, id)) = self.successors[index].peek() {
            let target = self.graph.vertex(id);
            let mut measured = None;
            if bounded || key >= order_bits(f64::INFINITY) {
                let a = self.graph.state(v);
                let (cost, distance) = self.graph.measure(a, id, &self.space, &self.heuristic);
                if g + cost + target.cost_to_go_bound >= self.best_cost {
                    break;
                }
                measured = Some((cost, distance));
            }
            self.successors[index].advance(edge);
            // The cheap tests first: `is_blacklisted` looks the edge up.
            let rewiring = target.rewired_from(v);
            if id == exclude || (rewiring && !rewirings) || self.is_blacklisted(v, id) {
                continue;
            }
            if rewiring {
                self.graph.vertex_mut(v).rewiring_expanded = true;
                // Every edge left in the heap leads into the tree (with cascading rewirings
                // the heap is empty).
                self.successors[index].rewirings = BinaryHeap::new();
            }
            let (cost, distance) = measured.unwrap_or_else(|| {
                let a = self.graph.state(v);
                self.graph.measure(a, id, &self.space, &self.heuristic)
            });
            queued = Some(ForwardEdge {
                source: v,
                target: id,
                hint: NONE,
                cost,
                distance,
            });
            break;
        }
        let successors = &mut self.successors[index];
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
        let a = self.graph.state(d);
        let (cost, distance) = self.graph.measure(a, queued, &self.space, &self.heuristic);
        let edge = ForwardEdge {
            source: d,
            target: queued,
            hint: NONE,
            cost,
            distance,
        };
        let keys = forward_keys(&self.graph, self.key_rule(), &edge);
        self.forward.update(d, queued, keys);
    }
}

/// Files a ranked edge: one into the tree (`into_tree`) is left out without `rewirings`, and
/// goes to the heap when those edges are kept `apart`; any other goes to the order.
fn file(
    edge: Ranked,
    into_tree: bool,
    rewirings: bool,
    apart: bool,
    (order, heap): (&mut Vec<Ranked>, &mut Vec<Reverse<Ranked>>),
) {
    match (into_tree, rewirings, apart) {
        (true, false, _) => {}
        (true, true, true) => heap.push(Reverse(edge)),
        _ => order.push(edge),
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
