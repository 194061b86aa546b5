//! The in-place repair of the reverse search (AIT*'s LPA*-style update): when the forward
//! search finds an edge of the reverse tree invalid, only the branch below that edge loses its
//! cost-to-go, and the search resumes from the branch's neighbours that kept theirs.
//!
//! The reverse tree keeps intrusive child lists ([`Vertex`](crate::graph::Vertex)'s
//! `reverse_first_child`, …), so a repair costs the branch's size, not the graph's.

use mit_star_heuristics::Heuristic;
use mit_star_samplers::Sampler;
use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::{Counted, EdgeChecker, StateValidity};

use crate::graph::NONE;
use crate::informed_trees::NeighbourRule;
use crate::informed_trees::eit::Eit;
use crate::informed_trees::guidance::{Guidance, ReverseSearch};
use crate::informed_trees::reverse_search::forward_keys;

/// Branch vertices invalidated or re-seeded between two polls of the termination condition.
const REPAIR_POLL: usize = 32;

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
    /// `true` if an invalid reverse-tree edge is repaired in place rather than restarting the
    /// reverse search ([`Parameters::repair_reverse_search`](crate::Parameters)).
    pub(crate) fn repairs_reverse(&self) -> bool {
        G::REVERSE != ReverseSearch::None && self.parameters.repair_reverse_search == Some(true)
    }

    /// Makes `parent` the reverse parent of `v` (both current in this reverse search), moving
    /// `v` between child lists.
    pub(crate) fn link_reverse(&mut self, v: u32, parent: u32) {
        if self.graph.vertex(v).reverse_parent == parent {
            return;
        }
        self.unlink_reverse(v);
        let first = self.graph.vertex(parent).reverse_first_child;
        if first != NONE {
            self.graph.vertex_mut(first).reverse_prev_sibling = v;
        }
        self.graph.vertex_mut(parent).reverse_first_child = v;
        let x = self.graph.vertex_mut(v);
        x.reverse_parent = parent;
        x.reverse_next_sibling = first;
        x.reverse_prev_sibling = NONE;
    }

    /// Appends `v`'s children in the reverse tree to `out` (a vertex current in this reverse
    /// search has only current children: a new search's first touch empties the lists).
    pub(crate) fn push_reverse_children(&self, v: u32, out: &mut Vec<u32>) {
        let mut child = self.graph.vertex(v).reverse_first_child;
        while child != NONE {
            out.push(child);
            child = self.graph.vertex(child).reverse_next_sibling;
        }
    }

    /// Takes `v` out of its reverse parent's child list (if it has a parent).
    fn unlink_reverse(&mut self, v: u32) {
        let (parent, prev, next) = {
            let x = self.graph.vertex(v);
            (
                x.reverse_parent,
                x.reverse_prev_sibling,
                x.reverse_next_sibling,
            )
        };
        if parent == NONE {
            return;
        }
        if prev == NONE {
            self.graph.vertex_mut(parent).reverse_first_child = next;
        } else {
            self.graph.vertex_mut(prev).reverse_next_sibling = next;
        }
        if next != NONE {
            self.graph.vertex_mut(next).reverse_prev_sibling = prev;
        }
        let x = self.graph.vertex_mut(v);
        x.reverse_parent = NONE;
        x.reverse_prev_sibling = NONE;
        x.reverse_next_sibling = NONE;
    }

    /// The edge from `root` to its reverse parent is invalid: `root` and every vertex below it
    /// in the reverse tree lose `ĥ`, `h̃`, `e` and their reverse parent and become unexpanded
    /// (their queued reverse edges go stale, the forward edges into them are re-keyed and count
    /// as open again); then every edge into the branch from a vertex still in the reverse tree
    /// is queued, so the reverse search finds the branch's new cost-to-go (or none) as it
    /// continues — LPA*'s update of the inconsistent vertices, on the edge queue.
    ///
    /// The edges into a branch vertex `x` are taken from `x`'s own neighbours and tree
    /// neighbours, as OMPL's AIT* does; with k-nearest neighbours (not symmetric) a vertex
    /// that has `x` among its neighbours but is not among `x`'s can thus not offer `x` a path,
    /// where a restart's expansion of it would.
    ///
    /// Polls `stop`; if it fires, the reverse search restarts in the next iteration instead.
    ///
    /// Complexity: O(b (k + d)) for a branch of `b` vertices, `k` neighbours and `d` queued
    /// forward edges per vertex, plus the neighbour queries of branch vertices never expanded.
    pub(crate) fn repair_reverse_branch(&mut self, root: u32, stop: &dyn Stop) {
        let tag = self.reverse_tag;
        self.unlink_reverse(root);
        let mut branch = std::mem::take(&mut self.branch);
        branch.clear();
        branch.push(root);
        let mut i = 0;
        while i < branch.len() {
            self.push_reverse_children(branch[i], &mut branch);
            i += 1;
        }
        let completed = self.invalidate(&branch, tag, stop) && self.reseed(&branch, tag, stop);
        if !completed {
            self.reverse_restart_pending = true;
        }
        self.branch = branch;
    }

    /// Step 1 of a repair: `branch` forgets its reverse-search data. `false` if `stop` fired.
    fn invalidate(&mut self, branch: &[u32], tag: u32, stop: &dyn Stop) -> bool {
        for (j, &x) in branch.iter().enumerate() {
            if j % REPAIR_POLL == REPAIR_POLL - 1 && stop.should_stop() {
                return false;
            }
            let was_closed = {
                let v = self.graph.vertex_mut(x);
                v.forget_reverse();
                // Its queued reverse edges carried the old ĥ: stale now.
                v.reverse_version = v.reverse_version.wrapping_add(1);
                let was_closed = v.closed_tag == tag;
                if was_closed {
                    v.closed_tag = 0;
                }
                was_closed
            };
            if was_closed {
                self.forward.reopen_target(x);
            }
            let (graph, rule) = (&self.graph, self.key_rule());
            self.forward
                .update_incoming(x, |e| forward_keys(graph, rule, e));
        }
        // Deferred expansions of branch vertices would expand them with ĥ = ∞.
        let graph = &self.graph;
        self.deferred
            .retain(|&(v, _, forward)| forward || graph.vertex(v).in_reverse_tree(tag));
        true
    }

    /// Step 2 of a repair: queues every edge into `branch` from a vertex still in the reverse
    /// tree. `false` if `stop` fired.
    fn reseed(&mut self, branch: &[u32], tag: u32, stop: &dyn Stop) -> bool {
        for (j, &x) in branch.iter().enumerate() {
            if j % REPAIR_POLL == REPAIR_POLL - 1 && stop.should_stop() {
                return false;
            }
            let Some(len) = self.graph.neighbours(x, &self.space, &self.heuristic, stop) else {
                return false;
            };
            for i in 0..len {
                let n = self.graph.neighbour(x, i);
                self.offer_reverse(n.id, x, n.cost, n.distance, tag);
            }
            self.collect_tree_extras(x, len, false);
            for k in 0..self.extras.len() {
                let w = self.extras[k];
                let (cost, distance) = self.edge_geometry(x, w, NONE);
                self.offer_reverse(w, x, cost, distance, tag);
            }
        }
        true
    }

    /// Queues the reverse edge `w → x` if `w` is in the reverse tree (and the edge is not
    /// known invalid, could improve `x` and a solution: [`queue_reverse`](Self::queue_reverse)).
    fn offer_reverse(&mut self, w: u32, x: u32, cost: f64, distance: f64, tag: u32) {
        let source = self.graph.vertex(w);
        if !source.in_reverse_tree(tag) {
            return;
        }
        let (h, effort, version) = (source.h, source.effort, source.reverse_version);
        self.queue_reverse((w, x, NONE, cost, distance), h, effort, version, NONE, tag);
    }
}

#[cfg(test)]
mod tests;
