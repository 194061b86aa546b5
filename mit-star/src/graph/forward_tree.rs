//! The forward tree's links inside the [`RandomGeometricGraph`], and pruning.

use mit_star_spaces::Stop;

use crate::graph::random_geometric_graph::RandomGeometricGraph;
use crate::graph::vertex::NONE;

/// Vertices the pruning scan visits between two polls of the stop condition (a few tens of
/// microseconds of work).
const PRUNE_POLL: usize = 4096;

/// Vertices the pruning removes between two polls (each loses its stored edges).
const REMOVE_POLL: usize = 64;

/// What a call to [`RandomGeometricGraph::prune`] or
/// [`continue_pruning`](RandomGeometricGraph::continue_pruning) achieved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Pruning {
    /// Complete: this many vertices were removed.
    Done(usize),
    /// The stop condition fired during the scan: nothing was removed.
    Abandoned,
    /// The stop condition fired during the removal: the pruning must be continued.
    Interrupted,
}

impl RandomGeometricGraph {
    /// Removes `child` from its forward parent's child list (keeps its own subtree).
    pub(crate) fn unlink_child(&mut self, child: u32) {
        let (parent, prev, next) = {
            let c = self.vertex(child);
            (c.parent, c.prev_sibling, c.next_sibling)
        };
        if parent == NONE {
            return;
        }
        if prev == NONE {
            self.vertex_mut(parent).first_child = next;
        } else {
            self.vertex_mut(prev).next_sibling = next;
        }
        if next != NONE {
            self.vertex_mut(next).prev_sibling = prev;
        }
        let c = self.vertex_mut(child);
        c.parent = NONE;
        c.prev_sibling = NONE;
        c.next_sibling = NONE;
    }

    /// Makes `parent` the forward parent of `child` through an edge of cost `cost`, and sets
    /// `g(child) = g(parent) + cost` (descendants are not updated here).
    pub(crate) fn set_forward_parent(&mut self, child: u32, parent: u32, cost: f64) {
        self.unlink_child(child);
        let first = self.vertex(parent).first_child;
        let g = self.vertex(parent).g + cost;
        if first != NONE {
            self.vertex_mut(first).prev_sibling = child;
        }
        self.vertex_mut(parent).first_child = child;
        let c = self.vertex_mut(child);
        c.parent = parent;
        c.parent_cost = cost;
        c.next_sibling = first;
        c.prev_sibling = NONE;
        c.g = g;
    }

    /// Sets `g` of every vertex below `root` to its parent's `g` plus its edge's cost, from the
    /// top down (after links above have changed); `stack` is scratch.
    pub(crate) fn refresh_costs_below(&mut self, root: u32, stack: &mut Vec<u32>) {
        stack.clear();
        stack.push(root);
        while let Some(v) = stack.pop() {
            let g = self.vertex(v).g;
            let mut child = self.vertex(v).first_child;
            while child != NONE {
                let c = self.vertex_mut(child);
                c.g = g + c.parent_cost;
                stack.push(child);
                child = c.next_sibling;
            }
        }
    }

    /// Cuts `root` and its forward subtree out of the forward tree: every vertex in it gets
    /// `g = ∞` and no tree links.
    pub(crate) fn detach_subtree(&mut self, root: u32, stack: &mut Vec<u32>) {
        self.unlink_child(root);
        stack.clear();
        stack.push(root);
        while let Some(v) = stack.pop() {
            let mut child = self.vertex(v).first_child;
            while child != NONE {
                stack.push(child);
                child = self.vertex(child).next_sibling;
            }
            self.note_detached(v);
            let x = self.vertex_mut(v);
            x.g = f64::INFINITY;
            x.parent = NONE;
            x.parent_cost = f64::INFINITY;
            x.first_child = NONE;
            x.next_sibling = NONE;
            x.prev_sibling = NONE;
        }
    }

    /// Removes every sample whose admissible solution cost `ĉ(start, x) + ĉ(x, goals)` exceeds
    /// `bound`, except those in `protected` (start and goals are never removed). Forward
    /// subtrees hanging from removed vertices are detached (their vertices stay as samples with
    /// `g = ∞`). Starts a new batch once done; `pruned` (in tests) then lists the removed
    /// ids in ascending order.
    ///
    /// Both phases poll `stop`. If it fires during the scan for prunable vertices, nothing is
    /// removed ([`Pruning::Abandoned`]: the caller prunes at a later batch). If it fires during
    /// the removal, the graph is left mid-way ([`Pruning::Interrupted`]) and
    /// [`continue_pruning`](Self::continue_pruning) must finish the job before the graph is
    /// used otherwise.
    pub(crate) fn prune(&mut self, bound: f64, protected: &[u32], stop: &dyn Stop) -> Pruning {
        debug_assert!(!self.is_pruning(), "a pruning is already under way");
        let mut removed = std::mem::take(&mut self.prune_ids);
        removed.clear();
        for (scanned, node) in self.graph.node_indices().enumerate() {
            if scanned % PRUNE_POLL == PRUNE_POLL - 1 && stop.should_stop() {
                removed.clear();
                self.prune_ids = removed;
                return Pruning::Abandoned;
            }
            let id = node.index() as u32;
            let v = self.vertex(id);
            if !v.is_terminal()
                && v.cost_to_come_bound + v.cost_to_go_bound > bound
                && !protected.contains(&id)
            {
                removed.push(id);
            }
        }
        self.prune_ids = removed;
        self.prune_next = Some(0);
        self.continue_pruning(stop)
    }

    /// `true` while a pruning interrupted during its removal phase is unfinished.
    pub(crate) fn is_pruning(&self) -> bool {
        self.prune_next.is_some()
    }

    /// The ids the last completed pruning removed, in ascending order.
    #[cfg(test)]
    pub(crate) fn pruned(&self) -> &[u32] {
        &self.prune_ids
    }

    /// Continues the removal phase of an interrupted [`prune`](Self::prune), polling `stop`
    /// every [`REMOVE_POLL`] vertices: [`Pruning::Done`] with the number of vertices removed once
    /// it completes (at once if no pruning is under way), [`Pruning::Interrupted`] if `stop`
    /// fired first.
    pub(crate) fn continue_pruning(&mut self, stop: &dyn Stop) -> Pruning {
        let Some(mut next) = self.prune_next else {
            return Pruning::Done(0);
        };
        let removed = std::mem::take(&mut self.prune_ids);
        // `removed` is in ascending id order, so membership is a binary search. Each vertex is
        // unlinked and removed in turn: its vertex data outlive the removal, so later vertices
        // may still read the links of earlier ones.
        let mut stack = Vec::new();
        while next < removed.len() {
            let id = removed[next];
            next += 1;
            self.unlink_child(id);
            let mut child = self.vertex(id).first_child;
            while child != NONE {
                let following = self.vertex(child).next_sibling;
                if removed.binary_search(&child).is_ok() {
                    // Removed as well: its own children are handled in its turn.
                    let c = self.vertex_mut(child);
                    c.parent = NONE;
                    c.prev_sibling = NONE;
                    c.next_sibling = NONE;
                } else {
                    self.detach_subtree(child, &mut stack);
                }
                child = following;
            }
            self.vertex_mut(id).first_child = NONE;
            self.remove_vertex(id);
            // Polled after a removal, so that every call makes progress.
            if next % REMOVE_POLL == 0 && next < removed.len() && stop.should_stop() {
                self.prune_ids = removed;
                self.prune_next = Some(next);
                return Pruning::Interrupted;
            }
        }
        // The trees forget them lazily (their birth stamps are dead).
        self.nn.note_removed(removed.len());
        self.new_batch();
        let count = removed.len();
        self.prune_ids = removed;
        self.prune_next = None;
        Pruning::Done(count)
    }
}

#[cfg(test)]
mod tests {
    use super::Pruning;
    use crate::graph::random_geometric_graph::RandomGeometricGraph;
    use crate::graph::vertex::{NONE, Vertex, VertexKind};

    /// A chain start → a → b → c with a sibling d under a.
    fn tree() -> (RandomGeometricGraph, [u32; 5]) {
        let mut g = RandomGeometricGraph::new(1, true);
        let mut ids = [0; 5];
        for (i, x) in [0.0, 1.0, 2.0, 3.0, 1.5].into_iter().enumerate() {
            let kind = if i == 0 {
                VertexKind::Start
            } else {
                VertexKind::Sample
            };
            // ĝ + ĥ = x + (3 − x)·0 … give each sample a distinct admissible cost x.
            ids[i] = g.add_vertex(&[x], Vertex::new(kind, x, x, 0));
        }
        g.vertex_mut(ids[0]).g = 0.0;
        g.set_forward_parent(ids[1], ids[0], 1.0);
        g.set_forward_parent(ids[2], ids[1], 1.0);
        g.set_forward_parent(ids[3], ids[2], 1.0);
        g.set_forward_parent(ids[4], ids[1], 0.5);
        g.commit(&ids);
        (g, ids)
    }

    #[test]
    fn rewiring_moves_a_subtree() {
        let (mut g, [s, a, b, c, d]) = tree();
        assert_eq!(g.vertex(c).g, 3.0);
        g.set_forward_parent(b, s, 2.0);
        assert_eq!(g.vertex(b).g, 2.0);
        assert_eq!(g.vertex(a).first_child, d);
        assert_eq!(g.vertex(d).next_sibling, NONE);
        assert_eq!(g.vertex(c).parent, b);
    }

    #[test]
    fn pruning_detaches_orphans_and_keeps_protected_vertices() {
        let (mut g, [s, a, b, c, d]) = tree();
        // Admissible costs: a 2, b 4, c 6, d 3. Bound 3.5 removes b and c, keeps a and d.
        assert_eq!(g.prune(3.5, &[], &mit_star_spaces::Never), Pruning::Done(2));
        assert_eq!(g.pruned(), [b, c]);
        assert_eq!(g.vertex_count(), 3);
        assert_eq!(g.vertex(a).first_child, d);
        // Protection keeps a vertex whatever its bound; detached subtrees lose their g.
        let (mut g, [_, a, b, c, _]) = tree();
        assert_eq!(
            g.prune(1.0, &[b], &mit_star_spaces::Never),
            Pruning::Done(3)
        );
        assert_eq!(g.pruned(), [a, c, 4]);
        assert_eq!(g.vertex(b).g, f64::INFINITY);
        assert_eq!(g.vertex(b).parent, NONE);
        assert_eq!(g.vertex(s).first_child, NONE);
    }

    /// Fires on every poll.
    struct Fired;
    impl mit_star_spaces::Stop for Fired {
        fn should_stop(&self) -> bool {
            true
        }
    }

    #[test]
    fn a_stop_during_the_scan_removes_nothing() {
        let mut g = RandomGeometricGraph::new(1, true);
        let start = g.add_vertex(&[0.0], Vertex::new(VertexKind::Start, 0.0, 0.0, 0));
        g.vertex_mut(start).g = 0.0;
        for i in 0..2 * super::PRUNE_POLL {
            let x = 1.0 + i as f64;
            g.add_vertex(&[x], Vertex::new(VertexKind::Sample, x, x, 0));
        }
        let count = g.vertex_count();
        assert_eq!(g.prune(0.5, &[], &Fired), Pruning::Abandoned);
        assert!(g.pruned().is_empty() && !g.is_pruning());
        assert_eq!(g.vertex_count(), count);
        // Without the stop, every sample goes.
        assert_eq!(
            g.prune(0.5, &[], &mit_star_spaces::Never),
            Pruning::Done(count - 1)
        );
    }

    /// Fires from its `after`-th poll on.
    struct FiresAfter(std::cell::Cell<u32>);
    impl mit_star_spaces::Stop for FiresAfter {
        fn should_stop(&self) -> bool {
            let left = self.0.get();
            self.0.set(left.saturating_sub(1));
            left == 0
        }
    }

    /// A random forest over `count` samples: each sample's parent is an earlier vertex.
    fn forest(count: usize, seed: u64) -> RandomGeometricGraph {
        let mut g = RandomGeometricGraph::new(1, true);
        let start = g.add_vertex(&[0.0], Vertex::new(VertexKind::Start, 0.0, 0.0, 0));
        g.vertex_mut(start).g = 0.0;
        let mut state = seed;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 33) as usize
        };
        for i in 1..count as u32 {
            let x = (next() % 1000) as f64 / 100.0;
            let id = g.add_vertex(&[x], Vertex::new(VertexKind::Sample, x, x, 0));
            assert_eq!(id, i);
            let parent = (next() % i as usize) as u32;
            if g.vertex(parent).g.is_finite() {
                g.set_forward_parent(id, parent, 0.1);
            }
        }
        g
    }

    /// The forward links and liveness of every id, to compare two graphs.
    fn links(g: &RandomGeometricGraph, count: usize) -> Vec<(bool, u32, u32, u32, u64)> {
        (0..count as u32)
            .map(|v| {
                let x = g.vertex(v);
                let live = g.state_of(crate::graph::vertex::VertexId(v)).is_some();
                (live, x.parent, x.first_child, x.next_sibling, x.g.to_bits())
            })
            .collect()
    }

    #[test]
    fn an_interrupted_removal_continues_to_the_uninterrupted_result() {
        let count = 3000;
        for seed in 0..4 {
            let mut whole = forest(count, seed);
            let Pruning::Done(removed) = whole.prune(5.0, &[7], &mit_star_spaces::Never) else {
                panic!("an unstoppable pruning completes");
            };
            assert!(removed > 1000);
            let mut pieces = forest(count, seed);
            // The scan polls twice (never firing), then the removal is cut every few polls.
            let mut outcome = pieces.prune(5.0, &[7], &FiresAfter(std::cell::Cell::new(4)));
            let mut calls = 1;
            while outcome == Pruning::Interrupted {
                assert!(pieces.is_pruning());
                outcome = pieces.continue_pruning(&FiresAfter(std::cell::Cell::new(3)));
                calls += 1;
            }
            assert!(calls > 3, "seed {seed}: the removal was interrupted");
            assert_eq!(outcome, Pruning::Done(removed));
            assert!(!pieces.is_pruning());
            assert_eq!(pieces.pruned(), whole.pruned());
            assert_eq!(pieces.vertex_count(), whole.vertex_count());
            assert_eq!(links(&pieces, count), links(&whole, count));
        }
    }
}
