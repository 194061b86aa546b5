//! The vertices that may lie outside the forward tree, for FCIT*'s expansions.
//!
//! On a complete graph a vertex's list holds every other vertex, and an expansion that may no
//! longer rewire ranks only the edges out of the tree (and to its children). In a batch
//! without a solution the tree holds most vertices, so reading the whole list to find those
//! few was most of an expansion's time (and most of the memory traffic: a list is 24 bytes
//! per vertex). This keeps a superset of the vertices outside the tree — every vertex
//! committed since the last compaction (when a batch's searches restart), and every vertex
//! cut out of the tree since — so that
//! such an expansion reads only those, and the vertex's children through the tree's links.

use crate::graph::random_geometric_graph::{DEAD, RandomGeometricGraph};
use crate::nearest::Chunked;

/// A vertex that may be outside the forward tree, as committed: its id, its position in the
/// graph's log and its birth stamp (another stamp now: it was removed since).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Outside {
    pub(crate) id: u32,
    pub(crate) position: u32,
    pub(crate) birth: u32,
}

/// The candidates and what is needed to keep them without duplicates.
#[derive(Debug, Clone, Default)]
pub(crate) struct OutsideTree {
    /// Kept only when set (FCIT*'s lazy successors); otherwise nothing is recorded.
    pub(crate) enabled: bool,
    /// The candidates, in no particular order. Readers test the tree themselves (`g`).
    pub(crate) entries: Vec<Outside>,
    /// Per id: the birth stamp of its entry in `entries`, `DEAD` if it has none.
    listed: Chunked<u32>,
    /// Per id: its position in the log at its last commit (`DEAD` if never committed).
    positions: Chunked<u32>,
}

impl OutsideTree {
    /// Sizes the per-id arrays to hold `id`.
    fn make_room(&mut self, id: u32) {
        while self.listed.len() <= id as usize {
            self.listed.push(DEAD);
            self.positions.push(DEAD);
        }
    }

    /// Adds `entry` unless it is there already.
    fn offer(&mut self, entry: Outside) {
        self.make_room(entry.id);
        let listed = &mut self.listed[entry.id as usize];
        if *listed != entry.birth {
            *listed = entry.birth;
            self.entries.push(entry);
        }
    }
}

impl RandomGeometricGraph {
    /// Drops the candidates that were removed or have joined the tree: once per batch, when
    /// its searches restart, the first time the list is read after the batch's commits. Not
    /// per commit: a large batch commits in hundreds of chunks, and each pass over the whole
    /// list is unpolled.
    pub(crate) fn compact_outside(&mut self) {
        if !self.outside.enabled {
            return;
        }
        let mut entries = std::mem::take(&mut self.outside.entries);
        entries.retain(|c| {
            let keep = self.births[c.id as usize] == c.birth && !self.vertex(c.id).g.is_finite();
            if !keep && self.outside.listed[c.id as usize] == c.birth {
                self.outside.listed[c.id as usize] = DEAD;
            }
            keep
        });
        self.outside.entries = entries;
    }

    /// `ids` are committed at log positions `first..`: they are candidates.
    pub(crate) fn note_committed(&mut self, first: usize, ids: &[u32]) {
        if !self.outside.enabled {
            return;
        }
        for (position, &id) in (first as u32..).zip(ids) {
            self.outside.make_room(id);
            self.outside.positions[id as usize] = position;
            let birth = self.births[id as usize];
            self.outside.offer(Outside {
                id,
                position,
                birth,
            });
        }
    }

    /// `v` was cut out of the forward tree: it is a candidate again (if committed).
    pub(crate) fn note_detached(&mut self, v: u32) {
        if !self.outside.enabled {
            return;
        }
        if let Some(position) = self.log_position(v) {
            let birth = self.births[v as usize];
            self.outside.offer(Outside {
                id: v,
                position,
                birth,
            });
        }
    }

    /// Where `v` was committed in the log (`None` if it has not been, as itself).
    pub(crate) fn log_position(&self, v: u32) -> Option<u32> {
        let position = *self.outside.positions.get(v as usize)?;
        let birth = self.births[v as usize];
        (position != DEAD && self.log[position as usize] == (v, birth)).then_some(position)
    }
}
