//! The pieces the RRT family shares ([`RrtConnect`](crate::RrtConnect),
//! [`InformedRrtStar`](crate::InformedRrtStar)): a tree of states with its nearest-neighbour
//! index, and steering by at most a range.

use spaces::{StateSpace, States, Stop};

use crate::kd_tree::Alive;
use crate::{NearestNeighbors, Neighbours};

/// The parent of a root.
pub(crate) const ROOT: u32 = u32::MAX;

/// One tree: states in contiguous storage, parent indices ([`ROOT`] for roots), and the
/// nearest-neighbour index over its states.
#[derive(Debug, Clone)]
pub(crate) struct Tree {
    pub(crate) states: States,
    pub(crate) parents: Vec<u32>,
    nn: NearestNeighbors,
}

impl Tree {
    pub(crate) fn new(dimension: usize) -> Self {
        Self {
            states: States::new(dimension),
            parents: Vec::new(),
            nn: NearestNeighbors::new(dimension),
        }
    }

    pub(crate) fn add(&mut self, state: &[f64], parent: u32) -> u32 {
        let id = self.parents.len() as u32;
        self.states.push(state);
        self.parents.push(parent);
        self.nn.insert([(id, state)]);
        id
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
