//! The forward tree's links inside the [`RandomGeometricGraph`], and pruning.

use crate::graph::RandomGeometricGraph;
use crate::vertex::NONE;

/// Vertices the pruning scan visits between two polls of the stop condition (a few tens of
/// microseconds of work).
const PRUNE_POLL: usize = 4096;

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
    /// `g = ∞`). Starts a new batch. Returns the number of vertices removed.
    ///
    /// The scan for prunable vertices polls `stop` every [`PRUNE_POLL`] vertices; if it fires,
    /// nothing is removed and `None` is returned (the caller prunes at a later batch). The
    /// removal itself, proportional to the vertices removed, runs to the end.
    pub(crate) fn prune(
        &mut self,
        bound: f64,
        protected: &[u32],
        removed: &mut Vec<u32>,
        stop: &dyn spaces::Stop,
    ) -> Option<usize> {
        removed.clear();
        for (scanned, node) in self.graph.node_indices().enumerate() {
            if scanned % PRUNE_POLL == PRUNE_POLL - 1 && stop.should_stop() {
                removed.clear();
                return None;
            }
            let v = &self.graph[node];
            let id = node.index() as u32;
            if !v.is_terminal()
                && v.cost_to_come_bound + v.cost_to_go_bound > bound
                && !protected.contains(&id)
            {
                removed.push(id);
            }
        }
        // `removed` is in ascending id order, so membership is a binary search.
        let mut stack = Vec::new();
        for i in 0..removed.len() {
            let id = removed[i];
            self.unlink_child(id);
            let mut child = self.vertex(id).first_child;
            while child != NONE {
                let next = self.vertex(child).next_sibling;
                if removed.binary_search(&child).is_ok() {
                    // Removed as well: its own children are handled in its turn.
                    let c = self.vertex_mut(child);
                    c.parent = NONE;
                    c.prev_sibling = NONE;
                    c.next_sibling = NONE;
                } else {
                    self.detach_subtree(child, &mut stack);
                }
                child = next;
            }
            self.vertex_mut(id).first_child = NONE;
        }
        for &id in removed.iter() {
            self.remove_vertex(id);
        }
        // The trees forget them lazily (their birth stamps are dead).
        self.nn.note_removed(removed.len());
        self.new_batch();
        Some(removed.len())
    }
}

#[cfg(test)]
mod tests {
    use crate::VertexKind;
    use crate::graph::RandomGeometricGraph;
    use crate::vertex::{NONE, Vertex};

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
        let mut removed = Vec::new();
        assert_eq!(g.prune(3.5, &[], &mut removed, &spaces::Never), Some(2));
        assert_eq!(removed, [b, c]);
        assert_eq!(g.vertex_count(), 3);
        assert_eq!(g.vertex(a).first_child, d);
        // Protection keeps a vertex whatever its bound; detached subtrees lose their g.
        let (mut g, [_, a, b, c, _]) = tree();
        assert_eq!(g.prune(1.0, &[b], &mut removed, &spaces::Never), Some(3));
        assert_eq!(removed, [a, c, 4]);
        assert_eq!(g.vertex(b).g, f64::INFINITY);
        assert_eq!(g.vertex(b).parent, NONE);
        assert_eq!(g.vertex(s).first_child, NONE);
    }

    /// Fires on every poll.
    struct Fired;
    impl spaces::Stop for Fired {
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
        let mut removed = Vec::new();
        assert_eq!(g.prune(0.5, &[], &mut removed, &Fired), None);
        assert!(removed.is_empty());
        assert_eq!(g.vertex_count(), count);
        // Without the stop, every sample goes.
        assert_eq!(
            g.prune(0.5, &[], &mut removed, &spaces::Never),
            Some(count - 1)
        );
    }
}
