//! [`ForwardQueue`]: the forward search's edge queue with EIT*'s three keys and its
//! effort-greedy / A* front selection (spec §3.3).

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap};

use crate::graph::{BuildEdgeHasher, edge_key};

/// The three keys of a queued forward edge `u → v`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ForwardKeys {
    /// `g(u) + ĉ(u,v) + ĥ(v)`: admissible cost of a solution through the edge.
    pub(crate) lower: f64,
    /// `g(u) + ĉ(u,v) + h̃(v)`: estimated cost of a solution through the edge.
    pub(crate) estimated: f64,
    /// `remaining_checks(u,v) + e(v)`: estimated state checks to a solution through the edge.
    pub(crate) effort: u64,
}

/// A queued forward edge and what the planner cached about it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ForwardEdge {
    pub(crate) source: u32,
    pub(crate) target: u32,
    /// Position of `target` in `source`'s cached neighbour list, or `NONE`.
    pub(crate) hint: u32,
    /// `ĉ(source, target)`.
    pub(crate) cost: f64,
    /// Metric distance (sizes the edge's check grid).
    pub(crate) distance: f64,
}

/// The suboptimality factor `ε` of the front selection.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Front {
    /// `ε = ∞` (no solution yet): greedy on effort.
    Greedy,
    /// `ε = 1` (a solution exists): A* on the admissible key.
    Optimal,
    /// BIT*'s order: the least `estimated` key (`g + ĉ + ε·ĥ`, `ε` the inflation).
    Estimated,
}

#[derive(Debug, Clone, Copy)]
struct Slot {
    edge: ForwardEdge,
    keys: ForwardKeys,
    version: u32,
    live: bool,
    /// The target is open (not yet expanded by the current reverse search).
    open: bool,
}

/// A heap entry: keys in one order, as order-preserving bits, then ids for determinism.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Item {
    key: [u64; 3],
    source: u32,
    target: u32,
    slot: u32,
    version: u32,
}

impl Item {
    /// The entries of `slot` (number `id`) in the three heaps: by lower, effort, estimate.
    #[inline]
    fn of(s: &Slot, id: usize) -> [Reverse<Self>; 3] {
        let (k, e) = (s.keys, s.edge);
        let (l, est, eff) = (bits(k.lower), bits(k.estimated), k.effort);
        let item = |key| {
            Reverse(Self {
                key,
                source: e.source,
                target: e.target,
                slot: id as u32,
                version: s.version,
            })
        };
        [
            item([l, est, eff]),
            item([eff, l, est]),
            item([est, eff, l]),
        ]
    }
}

/// Order-preserving bits of a non-negative cost (`+∞` included).
#[inline]
pub(crate) fn bits(cost: f64) -> u64 {
    debug_assert!(cost >= 0.0, "queue keys are non-negative, got {cost}");
    cost.to_bits()
}

/// The forward queue: each edge at most once (a map from the vertex pair to its slot), three
/// binary heaps with lazy deletion ordered by `lower`, `effort` and `estimated` (ties broken by
/// the other keys, then the vertex ids), and per-target lists so the keys of edges into a vertex
/// can be refreshed when the reverse search improves it.
#[derive(Debug, Clone, Default)]
pub(crate) struct ForwardQueue {
    slots: Vec<Slot>,
    free: Vec<u32>,
    index: HashMap<u64, u32, BuildEdgeHasher>,
    by_lower: BinaryHeap<Reverse<Item>>,
    by_effort: BinaryHeap<Reverse<Item>>,
    by_estimate: BinaryHeap<Reverse<Item>>,
    live: usize,
    open: usize,
    incoming: Vec<Vec<u32>>,
    touched: Vec<u32>,
    /// A re-key in progress: the next slot to re-key and the heaps' items gathered so far.
    rekeying: Option<Rekey>,
}

/// The state of a re-key interrupted by the termination condition.
#[derive(Debug, Clone, Default)]
struct Rekey {
    next: usize,
    lower: Vec<Reverse<Item>>,
    effort: Vec<Reverse<Item>>,
    estimate: Vec<Reverse<Item>>,
}

/// Slots re-keyed between two polls of the termination condition.
const REKEY_POLL: usize = 1024;

impl ForwardQueue {
    /// Removes every edge, keeping allocations.
    pub(crate) fn clear(&mut self) {
        self.slots.clear();
        self.free.clear();
        self.index.clear();
        self.by_lower.clear();
        self.by_effort.clear();
        self.by_estimate.clear();
        self.live = 0;
        self.open = 0;
        self.rekeying = None;
        for &t in &self.touched {
            if let Some(list) = self.incoming.get_mut(t as usize) {
                list.clear();
            }
        }
        self.touched.clear();
    }

    /// Number of queued edges.
    #[cfg(test)]
    pub(crate) fn len(&self) -> usize {
        self.live
    }

    /// `true` if `source → target` is queued.
    #[cfg(test)]
    pub(crate) fn contains(&self, source: u32, target: u32) -> bool {
        self.index.contains_key(&edge_key(source, target))
    }

    /// `true` if no edge is queued.
    pub(crate) fn is_empty(&self) -> bool {
        self.live == 0
    }

    /// `true` if some queued edge has an open target.
    pub(crate) fn has_open_targets(&self) -> bool {
        self.open > 0
    }

    /// Inserts `edge` with `keys`, or updates its keys if it is queued already.
    pub(crate) fn insert_or_update(&mut self, edge: ForwardEdge, keys: ForwardKeys, open: bool) {
        let key = edge_key(edge.source, edge.target);
        if let Some(&slot) = self.index.get(&key) {
            self.rekey(slot, keys);
            return;
        }
        let slot = Slot {
            edge,
            keys,
            version: 0,
            live: true,
            open,
        };
        let id = match self.free.pop() {
            Some(id) => {
                // A new version: the heaps may still hold entries of the slot's last edge.
                let version = self.slots[id as usize].version.wrapping_add(1);
                self.slots[id as usize] = Slot { version, ..slot };
                id
            }
            None => {
                self.slots.push(slot);
                (self.slots.len() - 1) as u32
            }
        };
        self.index.insert(key, id);
        self.live += 1;
        self.open += usize::from(open);
        let t = edge.target as usize;
        if self.incoming.len() <= t {
            self.incoming.resize_with(t + 1, Vec::new);
        }
        if self.incoming[t].is_empty() {
            self.touched.push(edge.target);
        }
        self.incoming[t].push(id);
        self.push(id);
    }

    /// Updates the keys of `source → target` if it is queued; returns whether it was.
    pub(crate) fn update(&mut self, source: u32, target: u32, keys: ForwardKeys) -> bool {
        match self.index.get(&edge_key(source, target)) {
            Some(&slot) => {
                self.rekey(slot, keys);
                true
            }
            None => false,
        }
    }

    /// Recomputes with `keys_of` the keys of every queued edge into `target`.
    pub(crate) fn update_incoming(
        &mut self,
        target: u32,
        mut keys_of: impl FnMut(&ForwardEdge) -> ForwardKeys,
    ) {
        let Some(list) = self.incoming.get(target as usize) else {
            return;
        };
        // Index loop: `rekey` needs `&mut self` while the list is read.
        for i in 0..list.len() {
            let slot = self.incoming[target as usize][i];
            let s = self.slots[slot as usize];
            if s.live && s.edge.target == target {
                let keys = keys_of(&s.edge);
                self.rekey(slot, keys);
            }
        }
    }

    /// Marks `target` closed: edges into it no longer count as having an open target.
    pub(crate) fn close_target(&mut self, target: u32) {
        let Some(list) = self.incoming.get(target as usize) else {
            return;
        };
        for &slot in list {
            let s = &mut self.slots[slot as usize];
            if s.live && s.open && s.edge.target == target {
                s.open = false;
                self.open -= 1;
            }
        }
    }

    /// Marks `target` open again (the inverse of [`close_target`](Self::close_target)): a
    /// repair of the reverse search made it unexpanded.
    pub(crate) fn reopen_target(&mut self, target: u32) {
        let Some(list) = self.incoming.get(target as usize) else {
            return;
        };
        for &slot in list {
            let s = &mut self.slots[slot as usize];
            if s.live && !s.open && s.edge.target == target {
                s.open = true;
                self.open += 1;
            }
        }
    }

    /// Starts recomputing every key and marking every target open (after the reverse search
    /// restarts); [`rekey_all`](Self::rekey_all) does the work. Until it completes, the queue
    /// must not be used otherwise.
    pub(crate) fn begin_rekey_all(&mut self) {
        let take = |heap: &mut BinaryHeap<Reverse<Item>>| {
            let mut items = std::mem::take(heap).into_vec();
            items.clear();
            items
        };
        self.rekeying = Some(Rekey {
            next: 0,
            lower: take(&mut self.by_lower),
            effort: take(&mut self.by_effort),
            estimate: take(&mut self.by_estimate),
        });
        self.open = 0;
    }

    /// `true` while a re-key begun by [`begin_rekey_all`](Self::begin_rekey_all) is unfinished.
    pub(crate) fn is_rekeying(&self) -> bool {
        self.rekeying.is_some()
    }

    /// Continues the re-key with `keys_of`, polling `stop` every [`REKEY_POLL`] slots; `true`
    /// once it is complete (at once if none is in progress), `false` if `stop` fired first (the
    /// next call resumes where this one stopped; keys do not change while the planner is idle).
    pub(crate) fn rekey_all(
        &mut self,
        mut keys_of: impl FnMut(&ForwardEdge) -> ForwardKeys,
        stop: &dyn mit_star_spaces::Stop,
    ) -> bool {
        let Some(mut r) = self.rekeying.take() else {
            return true;
        };
        while r.next < self.slots.len() {
            let id = r.next;
            r.next += 1;
            let s = &mut self.slots[id];
            if s.live {
                s.keys = keys_of(&s.edge);
                s.open = true;
                self.open += 1;
                let [lower, effort, estimate] = Item::of(s, id);
                r.lower.push(lower);
                r.effort.push(effort);
                r.estimate.push(estimate);
            }
            if r.next % REKEY_POLL == 0 && r.next < self.slots.len() && stop.should_stop() {
                self.rekeying = Some(r);
                return false;
            }
        }
        self.by_lower = BinaryHeap::from(r.lower);
        self.by_effort = BinaryHeap::from(r.effort);
        self.by_estimate = BinaryHeap::from(r.estimate);
        true
    }

    /// The edge the front selection would pop, with its keys.
    pub(crate) fn peek(&mut self, front: Front) -> Option<(ForwardEdge, ForwardKeys)> {
        let slot = self.select(front)?;
        let s = &self.slots[slot as usize];
        Some((s.edge, s.keys))
    }

    /// Removes and returns the edge the front selection picks.
    pub(crate) fn pop(&mut self, front: Front) -> Option<(ForwardEdge, ForwardKeys)> {
        let slot = self.select(front)?;
        let s = self.slots[slot as usize];
        self.remove(slot);
        Some((s.edge, s.keys))
    }

    /// The least admissible key `min lower` (∞ if empty).
    pub(crate) fn min_lower(&mut self) -> f64 {
        Self::clean(&mut self.by_lower, &self.slots);
        self.by_lower
            .peek()
            .map_or(f64::INFINITY, |i| self.slots[i.0.slot as usize].keys.lower)
    }

    /// Front selection (spec §3.3): with `ε = ∞` the least-effort edge if its estimated cost is
    /// finite, else the least-estimated edge if finite, else the least-lower edge; with `ε = 1`
    /// the least-estimated edge (ties: least effort) if its estimate is below `min lower`, else
    /// the least-lower edge.
    fn select(&mut self, front: Front) -> Option<u32> {
        Self::clean(&mut self.by_lower, &self.slots);
        Self::clean(&mut self.by_effort, &self.slots);
        Self::clean(&mut self.by_estimate, &self.slots);
        let lower = self.by_lower.peek()?.0.slot;
        let estimate = self.by_estimate.peek()?.0.slot;
        let keys = |slot: u32| self.slots[slot as usize].keys;
        match front {
            Front::Greedy => {
                let effort = self.by_effort.peek()?.0.slot;
                if keys(effort).estimated < f64::INFINITY {
                    Some(effort)
                } else if keys(estimate).estimated < f64::INFINITY {
                    Some(estimate)
                } else {
                    Some(lower)
                }
            }
            Front::Estimated => Some(estimate),
            Front::Optimal => {
                if keys(estimate).estimated < keys(lower).lower {
                    Some(estimate)
                } else {
                    Some(lower)
                }
            }
        }
    }

    /// Pops stale entries off the top of `heap`.
    fn clean(heap: &mut BinaryHeap<Reverse<Item>>, slots: &[Slot]) {
        while let Some(top) = heap.peek() {
            let s = &slots[top.0.slot as usize];
            if s.live && s.version == top.0.version {
                return;
            }
            heap.pop();
        }
    }

    fn remove(&mut self, slot: u32) {
        let s = &mut self.slots[slot as usize];
        s.live = false;
        self.live -= 1;
        if s.open {
            self.open -= 1;
        }
        self.index.remove(&edge_key(s.edge.source, s.edge.target));
        self.free.push(slot);
    }

    fn rekey(&mut self, slot: u32, keys: ForwardKeys) {
        let s = &mut self.slots[slot as usize];
        if s.keys == keys {
            return;
        }
        s.keys = keys;
        s.version = s.version.wrapping_add(1);
        self.push(slot);
    }

    fn push(&mut self, slot: u32) {
        let [lower, effort, estimate] = Item::of(&self.slots[slot as usize], slot as usize);
        self.by_lower.push(lower);
        self.by_effort.push(effort);
        self.by_estimate.push(estimate);
        // Keep stale entries from piling up.
        if self.by_lower.len() > 4 * self.live + 4096 {
            self.reheap();
        }
    }

    /// Rebuilds the heaps from the live slots.
    fn reheap(&mut self) {
        let mut lower = std::mem::take(&mut self.by_lower).into_vec();
        let mut effort = std::mem::take(&mut self.by_effort).into_vec();
        let mut estimate = std::mem::take(&mut self.by_estimate).into_vec();
        lower.clear();
        effort.clear();
        estimate.clear();
        for (id, s) in self.slots.iter().enumerate() {
            if s.live {
                let [l, f, e] = Item::of(s, id);
                lower.push(l);
                effort.push(f);
                estimate.push(e);
            }
        }
        self.by_lower = BinaryHeap::from(lower);
        self.by_effort = BinaryHeap::from(effort);
        self.by_estimate = BinaryHeap::from(estimate);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn edge(source: u32, target: u32) -> ForwardEdge {
        ForwardEdge {
            source,
            target,
            hint: u32::MAX,
            cost: 0.1,
            distance: 0.1,
        }
    }

    fn keys(lower: f64, estimated: f64, effort: u64) -> ForwardKeys {
        ForwardKeys {
            lower,
            estimated,
            effort,
        }
    }

    #[test]
    fn greedy_front_takes_least_effort_then_astar_takes_least_lower() {
        let mut q = ForwardQueue::default();
        q.insert_or_update(edge(0, 1), keys(1.0, 1.0, 50), true);
        q.insert_or_update(edge(0, 2), keys(2.0, 2.0, 5), true);
        q.insert_or_update(
            edge(0, 3),
            keys(f64::INFINITY, f64::INFINITY, u64::MAX),
            true,
        );
        assert_eq!(q.peek(Front::Greedy).unwrap().0.target, 2);
        assert_eq!(q.peek(Front::Optimal).unwrap().0.target, 1);
        assert_eq!(q.min_lower(), 1.0);
        // Updating a key reorders; the stale entry is skipped.
        q.insert_or_update(edge(0, 1), keys(1.0, 1.0, 1), true);
        assert_eq!(q.len(), 3);
        assert_eq!(q.pop(Front::Greedy).unwrap().0.target, 1);
        assert_eq!(q.pop(Front::Greedy).unwrap().0.target, 2);
        // Only the unreached target is left: its lower key is infinite.
        assert_eq!(q.pop(Front::Greedy).unwrap().0.target, 3);
        assert!(q.is_empty() && q.pop(Front::Greedy).is_none());
    }

    #[test]
    fn a_reused_slot_is_not_taken_for_its_last_edge() {
        // The popped edge's entries stay in the heaps; the next edge inserted takes its slot
        // and must be ordered by its own keys, not the popped edge's.
        let mut q = ForwardQueue::default();
        q.insert_or_update(edge(0, 1), keys(1.0, 1.0, 1), true);
        q.insert_or_update(edge(0, 2), keys(2.0, 2.0, 2), true);
        assert_eq!(q.pop(Front::Estimated).unwrap().0.target, 1);
        q.insert_or_update(edge(1, 3), keys(3.0, 3.0, 3), true);
        for front in [Front::Estimated, Front::Optimal, Front::Greedy] {
            assert_eq!(q.peek(front).unwrap().0.target, 2, "{front:?}");
        }
        assert_eq!(q.min_lower(), 2.0);
    }

    #[test]
    fn ties_break_by_vertex_ids() {
        let mut q = ForwardQueue::default();
        for (s, t) in [(4, 9), (2, 7), (2, 3), (5, 1)] {
            q.insert_or_update(edge(s, t), keys(1.0, 1.0, 3), true);
        }
        let order: Vec<(u32, u32)> = std::iter::from_fn(|| q.pop(Front::Greedy))
            .map(|(e, _)| (e.source, e.target))
            .collect();
        assert_eq!(order, [(2, 3), (2, 7), (4, 9), (5, 1)]);
    }

    #[test]
    fn open_targets_and_incoming_updates() {
        let mut q = ForwardQueue::default();
        q.insert_or_update(edge(0, 5), keys(3.0, 3.0, 9), true);
        q.insert_or_update(edge(1, 5), keys(4.0, 4.0, 9), true);
        q.insert_or_update(edge(1, 6), keys(5.0, 5.0, 9), false);
        assert!(q.has_open_targets());
        q.close_target(5);
        assert!(!q.has_open_targets());
        // Reopening counts each live edge into the target once, however often it is called.
        q.reopen_target(5);
        q.reopen_target(5);
        q.close_target(6);
        assert_eq!(q.open, 2);
        q.close_target(5);
        assert!(!q.has_open_targets());
        q.update_incoming(5, |e| keys(0.5 + f64::from(e.source), 0.5, 1));
        assert_eq!(q.peek(Front::Optimal).unwrap().0.source, 0);
        assert_eq!(q.min_lower(), 0.5);
        assert!(q.update(1, 6, keys(0.1, 0.1, 0)));
        assert!(!q.update(2, 6, keys(0.1, 0.1, 0)));
        assert_eq!(q.pop(Front::Optimal).unwrap().0.target, 6);
        q.begin_rekey_all();
        assert!(q.is_rekeying());
        assert!(q.rekey_all(|_| keys(1.0, 1.0, 1), &mit_star_spaces::Never));
        assert!(!q.is_rekeying());
        assert!(q.has_open_targets());
        assert_eq!(q.len(), 2);
        q.clear();
        assert!(q.is_empty() && !q.has_open_targets());
    }

    /// Fires on every poll.
    struct Fired;
    impl mit_star_spaces::Stop for Fired {
        fn should_stop(&self) -> bool {
            true
        }
    }

    #[test]
    fn an_interrupted_rekey_resumes_to_the_same_queue() {
        let fill = |q: &mut ForwardQueue| {
            for i in 0..5000_u32 {
                let k = f64::from((i * 7919) % 1000);
                q.insert_or_update(
                    edge(i, i + 1),
                    keys(k, k + 1.0, u64::from(i % 13)),
                    i % 3 == 0,
                );
            }
            // Some removed slots and a closed target on the way.
            for _ in 0..100 {
                q.pop(Front::Optimal);
            }
            q.close_target(4001);
        };
        let new_keys = |e: &ForwardEdge| {
            let k = f64::from((e.source * 104_729) % 997);
            keys(k, k + 0.5, u64::from(e.target % 5))
        };
        let mut whole = ForwardQueue::default();
        fill(&mut whole);
        whole.begin_rekey_all();
        assert!(whole.rekey_all(new_keys, &mit_star_spaces::Never));
        let mut pieces = ForwardQueue::default();
        fill(&mut pieces);
        pieces.begin_rekey_all();
        let mut calls = 1;
        while !pieces.rekey_all(new_keys, &Fired) {
            calls += 1;
            assert!(pieces.is_rekeying());
        }
        assert!(calls >= 4, "the re-key was interrupted ({calls} calls)");
        assert!(pieces.has_open_targets() && whole.has_open_targets());
        for front in [Front::Greedy, Front::Optimal, Front::Estimated] {
            let (mut a, mut b) = (whole.clone(), pieces.clone());
            while let Some(x) = a.pop(front) {
                assert_eq!(Some(x), b.pop(front));
            }
            assert!(b.pop(front).is_none());
        }
    }
}
