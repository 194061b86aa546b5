//! [`VertexId`], [`VertexKind`] and the per-vertex search data the graph keeps for the planner.

/// "No vertex": the parent of a root, an empty child list.
pub(crate) const NONE: u32 = u32::MAX;

/// Effort-to-go of a vertex the reverse search has not reached.
pub(crate) const NO_EFFORT: u64 = u64::MAX;

/// Identifies a vertex (a sample) of the [`RandomGeometricGraph`](crate::graph::random_geometric_graph::RandomGeometricGraph).
///
/// Ids are stable while the vertex lives; the id of a pruned vertex may be reused by a later
/// sample.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct VertexId(pub(crate) u32);

impl VertexId {
    /// The id as an index (the vertex's slot in the graph's storage).
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// What a vertex stands for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VertexKind {
    /// The start state (root of the forward tree).
    Start,
    /// A goal state (a root of the reverse tree).
    Goal,
    /// A sample drawn by the sampler.
    Sample,
}

/// Everything the planner keeps per vertex, stored as the graph's node weight (one contiguous
/// array). The reverse-search fields are valid only while `reverse_tag` equals the current
/// reverse search's tag, so restarting the reverse search is O(1): bump the tag.
#[derive(Debug, Clone)]
pub(crate) struct Vertex {
    pub(crate) kind: VertexKind,
    /// Which step of the sampler produced the state (pictures).
    pub(crate) origin: mit_star_samplers::SampleOrigin,
    /// `ĝ(x) = ĉ(start, x)`, the admissible cost-to-come bound.
    pub(crate) cost_to_come_bound: f64,
    /// `ĉ(x, goals)`, the admissible cost-to-go bound.
    pub(crate) cost_to_go_bound: f64,
    /// Effort lower bound from the start to `x` (grid points of the straight edge).
    pub(crate) effort_from_start: u64,

    /// Batch tag at which the cached neighbour list was last brought up to date, how many of
    /// its entries are used this batch, how many nearest neighbours it holds exactly (k-nearest)
    /// or the radius it covers (r-disc), and the position in the graph's insertion log it
    /// covers.
    pub(crate) neighbours_tag: u32,
    pub(crate) neighbours_len: u32,
    pub(crate) neighbours_wanted: u32,
    pub(crate) neighbours_radius: f64,
    pub(crate) neighbours_log: u32,
    /// The graph's removal count when the list was last brought up to date: while it is
    /// unchanged, no neighbour can have died.
    pub(crate) neighbours_removals: u64,

    /// Forward tree: cost-to-come `g`, parent, cost of the parent edge, intrusive child list.
    pub(crate) g: f64,
    pub(crate) parent: u32,
    pub(crate) parent_cost: f64,
    pub(crate) first_child: u32,
    pub(crate) next_sibling: u32,
    pub(crate) prev_sibling: u32,
    /// Batch tag of the vertex's last forward expansion.
    pub(crate) forward_expanded: u32,
    /// A forward expansion of the vertex has queued rewirings (edges to other tree vertices);
    /// without cascading rewirings (BIT*) no later expansion does.
    pub(crate) rewiring_expanded: bool,

    /// Reverse search: tag of validity, `ĥ`, `h̃`, `e`, reverse parent, closed tag, expansion
    /// version (stamps reverse-queue entries; older entries are stale).
    pub(crate) reverse_tag: u32,
    pub(crate) h: f64,
    pub(crate) h_estimate: f64,
    pub(crate) effort: u64,
    pub(crate) reverse_parent: u32,
    pub(crate) closed_tag: u32,
    pub(crate) reverse_version: u32,
    /// Reverse tree: intrusive child list (first child; previous and next sibling under the
    /// same reverse parent), so a repair finds a branch in the branch's size.
    pub(crate) reverse_first_child: u32,
    pub(crate) reverse_next_sibling: u32,
    pub(crate) reverse_prev_sibling: u32,
}

impl Vertex {
    /// A fresh vertex, in neither tree.
    pub(crate) fn new(
        kind: VertexKind,
        cost_to_come_bound: f64,
        cost_to_go_bound: f64,
        effort_from_start: u64,
    ) -> Self {
        Self {
            kind,
            origin: mit_star_samplers::SampleOrigin::Drawn,
            cost_to_come_bound,
            cost_to_go_bound,
            effort_from_start,
            neighbours_tag: 0,
            neighbours_len: 0,
            neighbours_wanted: 0,
            neighbours_radius: 0.0,
            neighbours_log: 0,
            neighbours_removals: 0,
            g: f64::INFINITY,
            parent: NONE,
            parent_cost: f64::INFINITY,
            first_child: NONE,
            next_sibling: NONE,
            prev_sibling: NONE,
            forward_expanded: 0,
            rewiring_expanded: false,
            reverse_tag: 0,
            h: f64::INFINITY,
            h_estimate: f64::INFINITY,
            effort: NO_EFFORT,
            reverse_parent: NONE,
            closed_tag: 0,
            reverse_version: 0,
            reverse_first_child: NONE,
            reverse_next_sibling: NONE,
            reverse_prev_sibling: NONE,
        }
    }

    /// `ĥ(x)` in the reverse search tagged `tag` (∞ if not reached).
    #[inline]
    pub(crate) fn h(&self, tag: u32) -> f64 {
        if self.reverse_tag == tag {
            self.h
        } else {
            f64::INFINITY
        }
    }

    /// `h̃(x)` in the reverse search tagged `tag` (∞ if not reached).
    #[inline]
    pub(crate) fn h_estimate(&self, tag: u32) -> f64 {
        if self.reverse_tag == tag {
            self.h_estimate
        } else {
            f64::INFINITY
        }
    }

    /// `e(x)` in the reverse search tagged `tag` (saturated if not reached).
    #[inline]
    pub(crate) fn effort(&self, tag: u32) -> u64 {
        if self.reverse_tag == tag {
            self.effort
        } else {
            NO_EFFORT
        }
    }

    /// Reverse-tree parent in the reverse search tagged `tag`.
    #[inline]
    pub(crate) fn reverse_parent(&self, tag: u32) -> u32 {
        if self.reverse_tag == tag {
            self.reverse_parent
        } else {
            NONE
        }
    }

    /// `true` if the vertex is in the reverse tree of the search tagged `tag`.
    #[inline]
    pub(crate) fn in_reverse_tree(&self, tag: u32) -> bool {
        self.reverse_tag == tag && self.h.is_finite()
    }

    /// `true` if the vertex was expanded (closed) by the reverse search tagged `tag`.
    #[inline]
    pub(crate) fn is_closed(&self, tag: u32) -> bool {
        self.closed_tag == tag
    }

    /// Makes the reverse data current for search `tag`, reset to "not reached" (child list
    /// included).
    #[inline]
    pub(crate) fn touch_reverse(&mut self, tag: u32) {
        if self.reverse_tag != tag {
            self.reverse_tag = tag;
            self.forget_reverse();
        }
    }

    /// Resets the reverse data to "not reached" (`ĥ`, `h̃`, `e`, reverse parent and child
    /// links), keeping the search tag.
    #[inline]
    pub(crate) fn forget_reverse(&mut self) {
        self.h = f64::INFINITY;
        self.h_estimate = f64::INFINITY;
        self.effort = NO_EFFORT;
        self.reverse_parent = NONE;
        self.reverse_first_child = NONE;
        self.reverse_next_sibling = NONE;
        self.reverse_prev_sibling = NONE;
    }

    /// `true` if an edge from `v` into this vertex would rewire the forward tree: the vertex is
    /// in it, and not as a child of `v`.
    #[inline]
    pub(crate) fn rewired_from(&self, v: u32) -> bool {
        self.g.is_finite() && self.parent != v
    }

    /// `true` for the start and goal vertices (never pruned).
    #[inline]
    pub(crate) fn is_terminal(&self) -> bool {
        self.kind != VertexKind::Sample
    }

    /// `true` for a goal vertex.
    #[inline]
    pub(crate) fn is_goal(&self) -> bool {
        self.kind == VertexKind::Goal
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reverse_data_is_invalidated_by_the_tag() {
        let mut v = Vertex::new(VertexKind::Sample, 0.1, 0.2, 3);
        assert_eq!(v.h(1), f64::INFINITY);
        v.touch_reverse(1);
        v.h = 0.5;
        v.h_estimate = 0.5;
        v.effort = 10;
        v.reverse_parent = 4;
        assert!(v.in_reverse_tree(1));
        assert_eq!((v.h(1), v.effort(1), v.reverse_parent(1)), (0.5, 10, 4));
        // A restart bumps the tag: everything reads as unreached without touching the vertex.
        assert_eq!(
            (v.h(2), v.effort(2), v.reverse_parent(2)),
            (f64::INFINITY, NO_EFFORT, NONE)
        );
        assert!(!v.in_reverse_tree(2));
        v.touch_reverse(2);
        assert_eq!(v.h, f64::INFINITY);
    }
}
