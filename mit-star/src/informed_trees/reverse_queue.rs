//! [`ReverseQueue`]: the lazy reverse search's edge queue, ordered by `(k1, k2, k3)` (spec §3.2).

use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// A queued reverse edge `u → v` (`u` in the reverse tree) with its keys.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct ReverseEdge {
    /// `k1 = ĥ(u) + ĉ(u,v) + ĉ(start, v)`, `k2 = ĥ(u) + ĉ(u,v)` as order-preserving bits, and
    /// `k3 = e(u) + remaining(u,v) + effort(start, v)`.
    key: [u64; 3],
    pub(crate) source: u32,
    pub(crate) target: u32,
    /// Position of `target` in `source`'s cached neighbour list, or `NONE`.
    pub(crate) hint: u32,
    /// The source's reverse-expansion version when the edge was queued.
    pub(crate) version: u32,
}

impl ReverseEdge {
    /// An edge with its keys.
    pub(crate) fn new(
        k1: f64,
        k2: f64,
        k3: u64,
        source: u32,
        target: u32,
        hint: u32,
        version: u32,
    ) -> Self {
        debug_assert!(k1 >= 0.0 && k2 >= 0.0, "reverse keys are non-negative");
        Self {
            key: [k1.to_bits(), k2.to_bits(), k3],
            source,
            target,
            hint,
            version,
        }
    }

    /// `k1`: the admissible cost of a solution through the edge.
    pub(crate) fn k1(&self) -> f64 {
        f64::from_bits(self.key[0])
    }
}

/// A binary min-heap of reverse edges. Stale entries (queued before their source was expanded
/// again) are recognised by their version and skipped by the caller's `is_current` test, so an
/// edge never needs to be found inside the heap.
#[derive(Debug, Clone, Default)]
pub(crate) struct ReverseQueue {
    heap: BinaryHeap<Reverse<ReverseEdge>>,
}

impl ReverseQueue {
    /// Removes every edge, keeping the allocation.
    pub(crate) fn clear(&mut self) {
        self.heap.clear();
    }

    /// Queues an edge.
    pub(crate) fn push(&mut self, edge: ReverseEdge) {
        self.heap.push(Reverse(edge));
    }

    /// The best current edge, after dropping stale ones from the top.
    pub(crate) fn peek(
        &mut self,
        mut is_current: impl FnMut(&ReverseEdge) -> bool,
    ) -> Option<ReverseEdge> {
        while let Some(top) = self.heap.peek() {
            if is_current(&top.0) {
                return Some(top.0);
            }
            self.heap.pop();
        }
        None
    }

    /// Removes and returns the best current edge.
    pub(crate) fn pop(
        &mut self,
        is_current: impl FnMut(&ReverseEdge) -> bool,
    ) -> Option<ReverseEdge> {
        let edge = self.peek(is_current)?;
        self.heap.pop();
        Some(edge)
    }

    /// Number of entries, stale ones included.
    #[cfg(test)]
    pub(crate) fn len(&self) -> usize {
        self.heap.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_order_lexicographically_then_by_ids() {
        let mut q = ReverseQueue::default();
        q.push(ReverseEdge::new(1.0, 0.5, 9, 3, 4, 0, 0));
        q.push(ReverseEdge::new(1.0, 0.4, 9, 8, 9, 0, 0));
        q.push(ReverseEdge::new(1.0, 0.4, 2, 7, 1, 0, 0));
        q.push(ReverseEdge::new(0.9, 0.9, 99, 6, 2, 0, 1));
        q.push(ReverseEdge::new(1.0, 0.4, 2, 5, 1, 0, 0));
        // The 0.9 entry is stale (version 1 is not current).
        let current = |e: &ReverseEdge| e.version == 0;
        let order: Vec<u32> = std::iter::from_fn(|| q.pop(current))
            .map(|e| e.source)
            .collect();
        assert_eq!(order, [5, 7, 8, 3]);
        assert_eq!(q.len(), 0);
        assert_eq!(ReverseEdge::new(0.25, 0.0, 0, 0, 0, 0, 0).k1(), 0.25);
    }
}
