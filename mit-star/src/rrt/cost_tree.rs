//! [`CostTree`]: the tree of [`InformedRrtStar`](crate::InformedRrtStar) — an RRT tree with
//! costs-to-come, children for rewiring, resumable cost propagation, and pruning.

use mit_star_spaces::{States, Stop};

use crate::rrt::tree::{ROOT, Tree};

/// Vertices visited between two polls of the stop condition.
const POLL: usize = 1024;

/// An RRT* tree rooted at the start (vertex 0): every vertex's cost-to-come `g`, the cost of the
/// edge from its parent, and its children as intrusive sibling lists (three flat arrays, no
/// allocation per vertex; O(1) to relink a rewired vertex).
#[derive(Debug, Clone)]
pub(crate) struct CostTree {
    tree: Tree,
    /// Cost-to-come through the tree.
    costs: Vec<f64>,
    /// Cost of the edge from the parent (0 for the root).
    incoming: Vec<f64>,
    /// First child of each vertex (`ROOT`: none).
    first_child: Vec<u32>,
    /// Next and previous sibling of each vertex (`ROOT`: none).
    next_sibling: Vec<u32>,
    prev_sibling: Vec<u32>,
    /// Vertices whose children's costs still have to follow theirs (a propagation the stop
    /// interrupted).
    stale: Vec<u32>,
}

impl CostTree {
    /// A tree holding only `root`.
    pub(crate) fn new(root: &[f64]) -> Self {
        let mut tree = Self {
            tree: Tree::new(root.len()),
            costs: Vec::new(),
            incoming: Vec::new(),
            first_child: Vec::new(),
            next_sibling: Vec::new(),
            prev_sibling: Vec::new(),
            stale: Vec::new(),
        };
        tree.add(root, ROOT, 0.0);
        tree
    }

    /// Number of vertices.
    pub(crate) fn len(&self) -> usize {
        self.costs.len()
    }

    /// Adds `state` as a child of `parent` through an edge of cost `edge`.
    pub(crate) fn add(&mut self, state: &[f64], parent: u32, edge: f64) -> u32 {
        let id = self.tree.add(state, parent);
        self.first_child.push(ROOT);
        self.next_sibling.push(ROOT);
        self.prev_sibling.push(ROOT);
        let cost = if parent == ROOT {
            0.0
        } else {
            self.link(id, parent);
            self.costs[parent as usize] + edge
        };
        self.costs.push(cost);
        self.incoming.push(edge);
        id
    }

    /// Makes `child` the first child of `parent`.
    fn link(&mut self, child: u32, parent: u32) {
        let head = self.first_child[parent as usize];
        self.next_sibling[child as usize] = head;
        self.prev_sibling[child as usize] = ROOT;
        if head != ROOT {
            self.prev_sibling[head as usize] = child;
        }
        self.first_child[parent as usize] = child;
    }

    /// Takes `child` out of the child list of `parent`.
    fn unlink(&mut self, child: u32, parent: u32) {
        let (prev, next) = (
            self.prev_sibling[child as usize],
            self.next_sibling[child as usize],
        );
        if prev == ROOT {
            self.first_child[parent as usize] = next;
        } else {
            self.next_sibling[prev as usize] = next;
        }
        if next != ROOT {
            self.prev_sibling[next as usize] = prev;
        }
    }

    /// The children of `id`.
    fn children(&self, id: u32) -> impl Iterator<Item = u32> + '_ {
        let some = |c: u32| (c != ROOT).then_some(c);
        std::iter::successors(some(self.first_child[id as usize]), move |&c| {
            some(self.next_sibling[c as usize])
        })
    }

    pub(crate) fn state(&self, id: u32) -> &[f64] {
        self.tree.state(id)
    }

    pub(crate) fn cost(&self, id: u32) -> f64 {
        self.costs[id as usize]
    }

    pub(crate) fn parent(&self, id: u32) -> u32 {
        self.tree.parents[id as usize]
    }

    /// Every vertex's state, by id.
    pub(crate) fn states(&self) -> &States {
        &self.tree.states
    }

    /// The vertices from `id` up to the root, `id` first.
    pub(crate) fn branch(&self, id: u32) -> Vec<u32> {
        self.tree.branch(id)
    }

    /// `(parent, child)` pairs of every edge.
    pub(crate) fn edges(&self) -> impl Iterator<Item = (u32, u32)> + '_ {
        (0..self.len() as u32)
            .map(|id| (self.parent(id), id))
            .filter(|&(parent, _)| parent != ROOT)
    }

    /// The tree under the costs, for nearest-neighbour queries ([`Tree::nearest`]).
    pub(crate) fn search(&mut self) -> &mut Tree {
        &mut self.tree
    }

    /// Makes `parent` the parent of `child` through an edge of cost `edge` (cheaper than its
    /// current one; `parent` is not a descendant of `child`). The descendants' costs follow at
    /// the next [`propagate`](Self::propagate).
    pub(crate) fn rewire(&mut self, child: u32, parent: u32, edge: f64) {
        let old = self.tree.parents[child as usize];
        if old != ROOT {
            self.unlink(child, old);
        }
        self.tree.parents[child as usize] = parent;
        self.link(child, parent);
        self.incoming[child as usize] = edge;
        self.costs[child as usize] = self.costs[parent as usize] + edge;
        self.stale.push(child);
    }

    /// Brings the descendants of rewired vertices up to date (OMPL's `updateChildCosts`).
    /// `false` if `stop` fired first; the next call resumes.
    pub(crate) fn propagate(&mut self, stop: &dyn Stop) -> bool {
        let mut visited = 0;
        while let Some(id) = self.stale.pop() {
            let cost = self.costs[id as usize];
            let mut child = self.first_child[id as usize];
            while child != ROOT {
                self.costs[child as usize] = cost + self.incoming[child as usize];
                self.stale.push(child);
                child = self.next_sibling[child as usize];
            }
            visited += 1;
            if visited % POLL == 0 && stop.should_stop() {
                return self.stale.is_empty();
            }
        }
        true
    }

    /// Removes every vertex that neither `keep` accepts nor has a descendant `keep` accepts,
    /// and renumbers the rest (parents before children, the root staying 0), rebuilding the
    /// nearest-neighbour index. Returns the new id of every old one (`None`: removed), or
    /// `None` and no change if `stop` fired first. Call it with no propagation pending.
    pub(crate) fn prune(
        &mut self,
        mut keep: impl FnMut(u32, &[f64]) -> bool,
        stop: &dyn Stop,
    ) -> Option<Vec<Option<u32>>> {
        // Breadth-first order from the root: every parent before its children.
        let mut order = Vec::with_capacity(self.len());
        order.push(0u32);
        let mut at = 0;
        while at < order.len() {
            let id = order[at];
            order.extend(self.children(id));
            at += 1;
        }
        let mut kept = vec![false; self.len()];
        for (i, &id) in order.iter().enumerate().rev() {
            if i % POLL == 0 && stop.should_stop() {
                return None;
            }
            let keep_subtree = id == 0
                || keep(id, self.tree.state(id))
                || self.children(id).any(|c| kept[c as usize]);
            kept[id as usize] = keep_subtree;
        }
        if kept.iter().all(|&k| k) {
            return Some((0..self.len() as u32).map(Some).collect());
        }
        let mut renumbered = vec![None; self.len()];
        let root = self.tree.state(0).to_vec();
        let old = std::mem::replace(self, Self::new(&root));
        renumbered[0] = Some(0);
        for &id in order.iter().skip(1).filter(|&&id| kept[id as usize]) {
            // A kept vertex's parent is kept and comes first.
            let parent = old.parent(id);
            let new_parent = renumbered[parent as usize].unwrap_or(0);
            let new = self.add(old.state(id), new_parent, old.incoming[id as usize]);
            renumbered[id as usize] = Some(new);
        }
        Some(renumbered)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nearest::Neighbours;
    use mit_star_spaces::{Never, RealVectorSpace};

    #[test]
    fn rewiring_propagates_and_pruning_keeps_useful_branches() {
        let mut tree = CostTree::new(&[0.0, 0.0]);
        let a = tree.add(&[1.0, 0.0], 0, 1.0);
        let b = tree.add(&[2.0, 0.0], a, 1.0);
        let c = tree.add(&[3.0, 0.0], b, 1.0);
        let d = tree.add(&[0.0, 5.0], 0, 5.0);
        // Rewire b under d (a dearer edge is fine for the tree's bookkeeping).
        tree.rewire(b, d, 0.5);
        assert!(tree.propagate(&Never));
        assert_eq!(tree.cost(b), 5.5);
        assert_eq!(tree.cost(c), 6.5);
        assert_eq!(tree.branch(c), [c, b, d, 0]);
        // Keep only c: its ancestors d and b stay, a (a leaf now) goes.
        let renumbered = tree.prune(|id, _| id == c, &Never).unwrap();
        assert_eq!(renumbered[a as usize], None);
        assert_eq!(tree.len(), 4);
        let c = renumbered[c as usize].unwrap();
        assert_eq!(tree.cost(c), 6.5);
        assert_eq!(tree.state(c), &[3.0, 0.0]);
        let space = RealVectorSpace::cube(2, -10.0, 10.0).unwrap();
        let mut found = Neighbours::new();
        assert!(
            tree.search()
                .nearest(&space, &[0.4, 0.0], 2, &mut found, &Never)
        );
        let ids: Vec<u32> = found.iter().map(|&(_, id)| id).collect();
        assert_eq!(ids, [0, renumbered[b as usize].unwrap()]);
        assert_eq!(tree.edges().count(), 3);
    }
}
