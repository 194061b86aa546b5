//! [`PendingPoints`]: the nearest-neighbour structure's buffer of points not yet in a tree, in
//! blocks of bounded size so that it grows without copying more than one block's half.

use crate::nearest::kd_tree::Poll;
use crate::nearest::lanes::{GROUP, distances_any, distances_fixed, push_point};

/// Points per block: also how many points a scan of the buffer checks between two polls.
const BLOCK: usize = 4096;

/// Points a new block has room for before it grows (by doubling, up to [`BLOCK`]). A block
/// allocated at full size (230 kB for the Panda's seven coordinates, twice over) came from the
/// top of the heap on every solve and went back to the system when the solve ended, so each
/// RRT-Connect solve paid fresh zeroed pages for it: starting small took RRT-Connect's Panda
/// solves from 220 to 170 µs (pooled medians, 30 alternated runs of `arm_profile target 20
/// rrt-connect 3`), with the same instructions.
const FIRST: usize = 64;

/// One block: up to [`BLOCK`] points, its arrays doubling from room for [`FIRST`].
#[derive(Debug, Clone)]
struct Block {
    ids: Vec<u32>,
    births: Vec<u32>,
    /// By point: the coordinates of point `i` at `i · dimension ..`, for builds.
    coordinates: Vec<f64>,
    /// The same coordinates by group of [`GROUP`] points, one row per coordinate (row
    /// `g · dimension + c` holds coordinate `c` of points `4g .. 4g + 4`), for scans that
    /// compute four distances at once; the unused places of the last group hold NaN.
    lanes: Vec<[f64; GROUP]>,
}

/// Points waiting to be built into a kd-tree, scanned linearly by queries meanwhile.
///
/// The buffer holds up to a quarter of the indexed points, megabytes in high dimensions. As one
/// `Vec` it doubled as it grew, copying itself in one step no termination condition can
/// interrupt (milliseconds past a deadline in `R^32`; `docs/guide/src/reference/reliability.md`). A block
/// doubles only up to [`BLOCK`] points (one copy of at most half a block: 0.5 MB in `R^32`),
/// then never moves; emptied, blocks are kept for the points that follow.
#[derive(Debug, Clone)]
pub(crate) struct PendingPoints {
    dimension: usize,
    blocks: Vec<Block>,
    /// Blocks in use: every block before the last in use is full.
    used: usize,
    len: usize,
}

impl PendingPoints {
    /// An empty buffer of points of `dimension` coordinates.
    pub(crate) fn new(dimension: usize) -> Self {
        Self {
            dimension,
            blocks: Vec::new(),
            used: 0,
            len: 0,
        }
    }

    /// Number of points.
    #[inline]
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// `true` if no point waits.
    #[inline]
    pub(crate) fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Appends a point with its id and birth stamp.
    pub(crate) fn push(&mut self, id: u32, birth: u32, point: &[f64]) {
        debug_assert_eq!(point.len(), self.dimension);
        if self.used == 0 || self.blocks[self.used - 1].ids.len() == BLOCK {
            if self.used == self.blocks.len() {
                self.blocks.push(Block {
                    ids: Vec::with_capacity(FIRST),
                    births: Vec::with_capacity(FIRST),
                    coordinates: Vec::with_capacity(FIRST * self.dimension),
                    lanes: Vec::with_capacity(FIRST / GROUP * self.dimension),
                });
            }
            self.used += 1;
        }
        let block = &mut self.blocks[self.used - 1];
        push_point(&mut block.lanes, block.ids.len(), point);
        block.ids.push(id);
        block.births.push(birth);
        block.coordinates.extend_from_slice(point);
        self.len += 1;
    }

    /// Makes room for `additional` more points in the list of blocks (blocks themselves are
    /// allocated as points arrive).
    pub(crate) fn reserve(&mut self, additional: usize) {
        let blocks = (self.len + additional).div_ceil(BLOCK);
        self.blocks
            .reserve(blocks.saturating_sub(self.blocks.len()));
    }

    /// Removes every point (the blocks are kept for reuse).
    pub(crate) fn clear(&mut self) {
        for block in &mut self.blocks[..self.used] {
            block.ids.clear();
            block.births.clear();
            block.coordinates.clear();
            block.lanes.clear();
        }
        self.used = 0;
        self.len = 0;
    }

    /// The blocks in use, in insertion order, as `(ids, births, coordinates)`.
    pub(crate) fn blocks(&self) -> impl Iterator<Item = (&[u32], &[u32], &[f64])> + '_ {
        self.blocks[..self.used]
            .iter()
            .map(|b| (&b.ids[..], &b.births[..], &b.coordinates[..]))
    }
}

impl PendingPoints {
    /// Visits the points a group of up to [`GROUP`] at a time, in insertion order: their ids,
    /// births and squared Euclidean distances to `query` (unused places: NaN, which compares
    /// false with everything). Each distance is the one
    /// [`squared_distance`](crate::nearest::kd_tree::squared_distance) returns, bit for bit:
    /// coordinate `c` adds to partial sum `c mod 4`, in order, and the sums are added pairwise.
    /// Polls `poll` once per block; `false` if it fired (the visit is then incomplete).
    pub(crate) fn scan(
        &self,
        query: &[f64],
        poll: &mut Poll<'_>,
        visit: impl FnMut(&[u32], &[u32], [f64; GROUP]),
    ) -> bool {
        debug_assert_eq!(query.len(), self.dimension);
        // Common dimensions get a kernel whose loops unroll completely.
        macro_rules! fixed {
            ($($n:literal)*) => {
                match self.dimension {
                    $($n => match <&[f64; $n]>::try_from(query) {
                        Ok(query) => self.scan_fixed(query, poll, visit),
                        Err(_) => self.scan_any(query, poll, visit),
                    },)*
                    _ => self.scan_any(query, poll, visit),
                }
            };
        }
        fixed!(2 3 4 5 6 7 8 9 10 11 12 13 14 15 16)
    }

    /// [`scan`](Self::scan) for points of `N` coordinates: the loops unroll and every sum
    /// stays in a register.
    fn scan_fixed<const N: usize>(
        &self,
        query: &[f64; N],
        poll: &mut Poll<'_>,
        visit: impl FnMut(&[u32], &[u32], [f64; GROUP]),
    ) -> bool {
        self.scan_groups(N, poll, visit, |rows| distances_fixed(rows, query))
    }

    /// [`scan`](Self::scan) for any number of coordinates.
    fn scan_any(
        &self,
        query: &[f64],
        poll: &mut Poll<'_>,
        visit: impl FnMut(&[u32], &[u32], [f64; GROUP]),
    ) -> bool {
        self.scan_groups(self.dimension.max(1), poll, visit, |rows| {
            distances_any(rows, query)
        })
    }

    /// The walk of [`scan`](Self::scan): per group, its `rows` (one per coordinate, `width` of
    /// them) to `distances`, then the answer to `visit`; a poll per block.
    #[inline(always)]
    fn scan_groups(
        &self,
        width: usize,
        poll: &mut Poll<'_>,
        mut visit: impl FnMut(&[u32], &[u32], [f64; GROUP]),
        distances: impl Fn(&[[f64; GROUP]]) -> [f64; GROUP],
    ) -> bool {
        for block in &self.blocks[..self.used] {
            if poll.tick(block.ids.len() as u32) {
                return false;
            }
            for ((ids, births), rows) in block
                .ids
                .chunks(GROUP)
                .zip(block.births.chunks(GROUP))
                .zip(block.lanes.chunks_exact(width))
            {
                visit(ids, births, distances(rows));
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_come_back_in_order_across_blocks_and_clears() {
        let mut p = PendingPoints::new(2);
        for round in 0..3_u32 {
            let count = [10_000_u32, 3, 8192][round as usize];
            for i in 0..count {
                p.push(i, round, &[f64::from(i), -f64::from(i)]);
            }
            assert_eq!(p.len(), count as usize);
            let mut next = 0;
            for (ids, births, xs) in p.blocks() {
                assert!(ids.len() <= BLOCK && !ids.is_empty());
                assert_eq!(xs.len(), 2 * ids.len());
                for (j, &id) in ids.iter().enumerate() {
                    assert_eq!(id, next);
                    assert_eq!(births[j], round);
                    assert_eq!(xs[2 * j..2 * j + 2], [f64::from(next), -f64::from(next)]);
                    next += 1;
                }
            }
            assert_eq!(next, count);
            p.clear();
            assert!(p.is_empty());
            assert_eq!(p.blocks().count(), 0);
        }
        // The first round's three blocks were kept and reused; none grew beyond a block, and
        // the full ones reached it.
        assert_eq!(p.blocks.len(), 3);
        assert!(
            p.blocks
                .iter()
                .all(|b| b.coordinates.capacity() <= 2 * BLOCK)
        );
        assert!(
            p.blocks[..2]
                .iter()
                .all(|b| b.coordinates.capacity() == 2 * BLOCK)
        );
    }
}
