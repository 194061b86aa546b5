//! The pieces the RRT family shares ([`RrtConnect`](crate::RrtConnect),
//! [`InformedRrtStar`](crate::InformedRrtStar)): a tree of states with its nearest-neighbour
//! index, and steering by at most a range.

use mit_star_spaces::{StateSpace, States, Stop};

use crate::nearest::{Alive, NearestNeighbors, Neighbours};

/// The parent of a root.
pub(crate) const ROOT: u32 = u32::MAX;

/// One tree: states in contiguous storage, parent indices ([`ROOT`] for roots), whether each
/// state's edge from its parent is certified, and the nearest-neighbour index over its states.
/// A parent's index is always below its children's.
#[derive(Debug, Clone)]
pub(crate) struct Tree {
    pub(crate) states: States,
    pub(crate) parents: Vec<u32>,
    /// The edge from the parent passed certification (roots: `true`). Planners that certify
    /// lazily (only a solution's edges) read and set it.
    pub(crate) certified: Vec<bool>,
    /// Per state: its dynamic-domain radius (RRT-Connect; `∞` until an extension from it
    /// fails).
    pub(crate) radii: Vec<f64>,
    nn: NearestNeighbors,
}

/// States a tree has room for when it is built: most arm solves of RRT-Connect end with
/// trees of a few dozen states (a median of 8 on the Panda's MotionBenchMaker problems), so
/// room reserved with the planner spares a solve the buffers' growth (about 2 % of a median
/// solve's instructions there); a larger tree grows as usual.
const ROOM: usize = 64;

impl Tree {
    pub(crate) fn new(dimension: usize) -> Self {
        Self {
            states: States::with_capacity(dimension, ROOM),
            parents: Vec::with_capacity(ROOM),
            certified: Vec::with_capacity(ROOM),
            radii: Vec::with_capacity(ROOM),
            nn: NearestNeighbors::new(dimension),
        }
    }

    pub(crate) fn add(&mut self, state: &[f64], parent: u32) -> u32 {
        let id = self.parents.len() as u32;
        self.states.push(state);
        self.parents.push(parent);
        self.certified.push(parent == ROOT);
        self.radii.push(f64::INFINITY);
        self.nn.insert([(id, state)]);
        id
    }

    /// Removes state `id` (not a root) and every state below it, and renumbers the rest in
    /// their order: the tree an edge that failed certification leaves. Linear in the tree's
    /// size; it runs once per failed certification, which is rare.
    pub(crate) fn prune(&mut self, id: u32) {
        debug_assert_ne!(self.parents[id as usize], ROOT, "a root is never pruned");
        let n = self.parents.len();
        // Children come after their parents, so one pass in order marks every descendant.
        let mut renumbered = vec![ROOT; n];
        let mut kept = Tree::new(self.states.dimension());
        for old in 0..n {
            let parent = self.parents[old];
            let orphaned = parent != ROOT && renumbered[parent as usize] == ROOT;
            if old == id as usize || orphaned {
                continue;
            }
            let new_parent = if parent == ROOT {
                ROOT
            } else {
                renumbered[parent as usize]
            };
            renumbered[old] = kept.add(&self.states[old], new_parent);
            kept.certified[renumbered[old] as usize] = self.certified[old];
            kept.radii[renumbered[old] as usize] = self.radii[old];
        }
        *self = kept;
    }

    pub(crate) fn state(&self, id: u32) -> &[f64] {
        &self.states[id as usize]
    }

    /// The path from `id` up to its root, `id` first.
    pub(crate) fn branch(&self, mut id: u32) -> Vec<u32> {
        let mut ids = vec![id];
        while self.parents[id as usize] != ROOT {
            id = self.parents[id as usize];
            ids.push(id);
        }
        ids
    }

    /// The `k` states nearest to `target` in `found` (`(squared distance, id)`, nearest first,
    /// ties by id), by the kd-trees in a Euclidean space, else by a scan with the space's
    /// metric. `false` (and `found` incomplete) if `stop` fired first.
    pub(crate) fn nearest<S: StateSpace>(
        &mut self,
        space: &S,
        target: &[f64],
        k: usize,
        found: &mut Neighbours,
        stop: &dyn Stop,
    ) -> bool {
        if space.is_euclidean() {
            return self.nn.nearest_alive(target, k, found, Alive::All, stop);
        }
        found.reset(k);
        for (id, state) in self.states.iter().enumerate() {
            if id % 4096 == 4095 && stop.should_stop() {
                return false;
            }
            let d = space.distance(state, target);
            found.offer(d * d, id as u32);
        }
        true
    }
}

/// A [`Snapshot`](crate::Snapshot) of a start tree (0) and a goal tree (1): their states, the
/// start tree's edges as forward edges and the goal tree's as reverse ones.
pub(crate) fn snapshot_of(trees: &[Tree; 2], best_cost: f64) -> crate::Snapshot {
    let mut states = States::new(trees[0].states.dimension());
    let mut kinds = Vec::new();
    let mut edges = [Vec::new(), Vec::new()];
    for (t, tree) in trees.iter().enumerate() {
        let offset = states.len();
        for (id, state) in tree.states.iter().enumerate() {
            states.push(state);
            let parent = tree.parents[id];
            kinds.push(match (t, parent) {
                (0, ROOT) => crate::VertexKind::Start,
                (_, ROOT) => crate::VertexKind::Goal,
                _ => crate::VertexKind::Sample,
            });
            if parent != ROOT {
                edges[t].push((offset + parent as usize, offset + id));
            }
        }
    }
    let [forward_edges, reverse_edges] = edges;
    crate::Snapshot {
        states,
        origins: vec![mit_star_samplers::SampleOrigin::Drawn; kinds.len()],
        kinds,
        forward_edges,
        reverse_edges,
        solution: Vec::new(),
        best_cost,
        estimated_informed_cost: None,
    }
}

/// Writes to `out` the state at most `range` from `from` towards `target` (`target` itself when
/// it is that close) and returns whether it is `target`.
pub(crate) fn steer<S: StateSpace>(
    space: &S,
    (from, target): (&[f64], &[f64]),
    range: f64,
    out: &mut [f64],
) -> bool {
    let distance = space.distance(from, target);
    let reached = distance <= range;
    if reached {
        out.copy_from_slice(target);
    } else {
        space.interpolate(from, target, range / distance, out);
    }
    reached
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pruning_removes_the_subtree_and_keeps_the_rest_in_order() {
        // 0 ─ 1 ─ 2 ─ 4
        //  └─ 3    └─ 5
        let mut tree = Tree::new(1);
        for (x, parent) in [
            (0.0, ROOT),
            (1.0, 0),
            (2.0, 1),
            (3.0, 0),
            (4.0, 2),
            (5.0, 2),
        ] {
            tree.add(&[x], parent);
        }
        tree.certified[3] = true;
        tree.prune(2);
        let states: Vec<f64> = tree.states.iter().map(|s| s[0]).collect();
        assert_eq!(states, [0.0, 1.0, 3.0]);
        assert_eq!(tree.parents, [ROOT, 0, 0]);
        assert_eq!(tree.certified, [true, false, true]);
        // The index knows only the states kept, under their new numbers.
        let space = mit_star_spaces::RealVectorSpace::cube(1, 0.0, 10.0).unwrap();
        let mut found = Neighbours::new();
        assert!(tree.nearest(&space, &[4.6], 1, &mut found, &mit_star_spaces::Never));
        assert_eq!(found.iter().next().map(|&(_, id)| id), Some(2));
    }
}
