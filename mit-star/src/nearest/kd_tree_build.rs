//! Building a [`KdTree`]: median splits along the widest coordinate, points partitioned in
//! place, the stop condition polled as work accumulates.

use mit_star_spaces::Stop;

use crate::nearest::kd_tree::{BUCKET, KdTree, LEAF, Node};
use crate::nearest::lanes::{GROUP, push_point};

/// Cells larger than this take their split value from an evenly spaced sample of this size.
const SAMPLED_MEDIAN: usize = 1023;

/// Work between two polls of the stop condition while building, in coordinates (points
/// partitioned × dimension): tens of microseconds in any dimension.
pub(crate) const POLL_WORK: usize = 32_768;

/// The stop condition of a build, the work done since it was last polled, and scratch space.
struct Budget<'a> {
    stop: &'a dyn Stop,
    work: usize,
    scratch: Scratch,
}

/// The arrays of a build the stop condition abandoned, kept rather than freed and reused by
/// the next build.
///
/// Returning tens of megabytes to the system takes milliseconds (page-table teardown): freed on
/// the way out of an abandoned build, they made `solve` return 3–5 ms after its deadline
/// (`examples/poll_gaps.rs` found it). Kept, they cost at most one extra copy of the points,
/// and the next build writes into memory that is already mapped.
#[derive(Debug, Clone, Default)]
pub(crate) struct Spare {
    ids: Vec<u32>,
    births: Vec<u32>,
    coordinates: Vec<f64>,
    lanes: Vec<[f64; GROUP]>,
}

impl Spare {
    /// The spare arrays, emptied (their capacity kept), for a new build.
    pub(crate) fn take(&mut self) -> (Vec<u32>, Vec<u32>, Vec<f64>) {
        let (mut ids, mut births, mut coordinates) = (
            std::mem::take(&mut self.ids),
            std::mem::take(&mut self.births),
            std::mem::take(&mut self.coordinates),
        );
        ids.clear();
        births.clear();
        coordinates.clear();
        (ids, births, coordinates)
    }

    /// The spare lanes (`KdTree::lanes`), emptied, with room for `capacity` rows.
    pub(crate) fn take_lanes(&mut self, capacity: usize) -> Vec<[f64; GROUP]> {
        let mut lanes = std::mem::take(&mut self.lanes);
        fresh(&mut lanes, capacity);
        lanes
    }

    /// Keeps the lanes of an abandoned build (the larger array, as [`keep`](Self::keep) does).
    pub(crate) fn keep_lanes(&mut self, lanes: Vec<[f64; GROUP]>) {
        if lanes.capacity() >= self.lanes.capacity() {
            self.lanes = lanes;
        }
    }

    /// Keeps the arrays of an abandoned build (the larger of each pair, should the spare still
    /// hold some: the smaller one is freed, so keep the spare empty while building).
    pub(crate) fn keep(&mut self, ids: Vec<u32>, births: Vec<u32>, coordinates: Vec<f64>) {
        if ids.capacity() >= self.ids.capacity() {
            self.ids = ids;
        }
        if births.capacity() >= self.births.capacity() {
            self.births = births;
        }
        if coordinates.capacity() >= self.coordinates.capacity() {
            self.coordinates = coordinates;
        }
    }
}

/// Buffers reused by every split of a build.
#[derive(Default)]
struct Scratch {
    column: Vec<f64>,
    select: Vec<f64>,
}

impl KdTree {
    /// Builds a tree from `parts` of ids, birth stamps and coordinates (row after row); `None`
    /// if `stop` fired first (it is polled every few thousand points of work, copying
    /// included). The copies are made in `spare`'s arrays, and an abandoned build leaves them
    /// there.
    pub(crate) fn from_parts(
        dimension: usize,
        parts: &[Parts<'_>],
        stop: &dyn Stop,
        spare: &mut Spare,
    ) -> Option<Self> {
        let (own_ids, own_births, buffer) = spare.take();
        match polled_concat(parts, stop, (own_ids, own_births, buffer)) {
            Ok(owned) => Self::from_owned(dimension, owned, stop, spare),
            Err((ids, births, buffer)) => {
                spare.keep(ids, births, buffer);
                None
            }
        }
    }

    /// [`from_parts`](Self::from_parts) taking the arrays it partitions in place; an
    /// abandoned build hands them to `spare`.
    pub(crate) fn from_owned(
        dimension: usize,
        (ids, births, coordinates): (Vec<u32>, Vec<u32>, Vec<f64>),
        stop: &dyn Stop,
        spare: &mut Spare,
    ) -> Option<Self> {
        let count = ids.len();
        let mut tree = Self::empty(dimension);
        if count == 0 || dimension == 0 {
            return Some(tree);
        }
        // The tree's own arrays, partitioned in place level by level: every pass over a cell is
        // sequential, and the points end in leaf order with no final gather.
        tree.ids = ids;
        tree.births = births;
        tree.coordinates = coordinates;
        // The leaves' lanes are written as the split emits them, in storage order.
        tree.lanes = spare.take_lanes(count.div_ceil(GROUP) * dimension);
        tree.nodes.reserve(2 * count / BUCKET + 1);
        let mut stopped = false;
        for chunk in tree
            .coordinates
            .chunks((POLL_WORK / dimension).max(1) * dimension)
        {
            for row in chunk.chunks_exact(dimension) {
                for (d, &x) in row.iter().enumerate() {
                    tree.lower[d] = tree.lower[d].min(x);
                    tree.upper[d] = tree.upper[d].max(x);
                }
            }
            if stop.should_stop() {
                stopped = true;
                break;
            }
        }
        if !stopped {
            let (mut lo, mut hi) = (tree.lower.clone(), tree.upper.clone());
            let mut budget = Budget {
                stop,
                work: 0,
                scratch: Scratch::default(),
            };
            if tree
                .split(0, count, &mut lo, &mut hi, &mut budget)
                .is_some()
            {
                return Some(tree);
            }
        }
        spare.keep(tree.ids, tree.births, tree.coordinates);
        spare.keep_lanes(tree.lanes);
        None
    }

    /// Swaps points `a` and `b` (rows, ids, stamps).
    #[inline]
    fn swap_points(&mut self, a: usize, b: usize) {
        if a == b {
            return;
        }
        let n = self.dimension;
        let (first, second) = (a.min(b), a.max(b));
        let (head, tail) = self.coordinates.split_at_mut(second * n);
        head[first * n..(first + 1) * n].swap_with_slice(&mut tail[..n]);
        self.ids.swap(a, b);
        self.births.swap(a, b);
    }

    /// Recursively builds the subtree over points `start..end`, whose bounding box is
    /// `lo..hi`; returns the node index.
    fn split(
        &mut self,
        start: usize,
        end: usize,
        lo: &mut [f64],
        hi: &mut [f64],
        budget: &mut Budget<'_>,
    ) -> Option<u32> {
        let m = end - start;
        // Each point of the cell is read once and moved once below.
        budget.work += 2 * m * self.dimension.max(1);
        if budget.work >= POLL_WORK {
            budget.work = 0;
            if budget.stop.should_stop() {
                return None;
            }
        }
        let n = self.dimension;
        let index = self.nodes.len() as u32;
        // Widest coordinate of the cell.
        let (dim, spread) =
            (0..n)
                .map(|d| (d, hi[d] - lo[d]))
                .fold(
                    (0, f64::NEG_INFINITY),
                    |best, c| if c.1 > best.1 { c } else { best },
                );
        let leaf = Node {
            start: start as u32,
            end: end as u32,
            dim: LEAF,
            low: 0.0,
            high: 0.0,
            left: 0,
            right: 0,
        };
        if m <= BUCKET || spread <= 0.0 {
            // Leaves come in storage order (left subtrees first), and their points are final.
            debug_assert_eq!(self.lanes.len(), start.div_ceil(GROUP) * n);
            for p in start..end {
                push_point(&mut self.lanes, p, &self.coordinates[p * n..(p + 1) * n]);
            }
            self.nodes.push(leaf);
            return Some(index);
        }
        // Median along `dim`, then a three-way partition of the points around it (less,
        // equal, greater); the median position falls among the equal ones.
        // Large cells poll while their points are read and moved (below): near the root that
        // is millions of coordinates, milliseconds of work. An abandoned build discards the
        // half-partitioned arrays.
        let poll_every = (POLL_WORK / n.max(1)).max(1);
        let scratch = &mut budget.scratch;
        scratch.column.clear();
        let mut from = start;
        while from < end {
            let to = (from + poll_every).min(end);
            scratch
                .column
                .extend((from..to).map(|p| self.coordinates[p * n + dim]));
            #[cfg(test)]
            crate::nearest::kd_tree_build_tests::visited(to - from);
            from = to;
            if from < end && budget.stop.should_stop() {
                return None;
            }
        }
        // The split value: the exact median of small cells, the median of an evenly spaced
        // sample of large ones (the tree stays balanced to within a few percent).
        scratch.select.clear();
        if m <= SAMPLED_MEDIAN {
            scratch.select.extend_from_slice(&scratch.column);
        } else {
            let stride = m / SAMPLED_MEDIAN;
            scratch
                .select
                .extend(scratch.column.iter().step_by(stride).take(SAMPLED_MEDIAN));
        }
        let half = scratch.select.len() / 2;
        let median = *scratch
            .select
            .select_nth_unstable_by(half, f64::total_cmp)
            .1;
        let mut column = std::mem::take(&mut budget.scratch.column);
        let (mut less, mut i, mut greater) = (0, 0, m);
        let mut next_poll = poll_every;
        while i < greater {
            if (i + (m - greater)) >= next_poll {
                next_poll += poll_every;
                if budget.stop.should_stop() {
                    budget.scratch.column = column;
                    return None;
                }
            }
            #[cfg(test)]
            crate::nearest::kd_tree_build_tests::visited(1);
            if column[i] < median {
                column.swap(less, i);
                self.swap_points(start + less, start + i);
                less += 1;
                i += 1;
            } else if column[i] > median {
                greater -= 1;
                column.swap(i, greater);
                self.swap_points(start + i, start + greater);
            } else {
                i += 1;
            }
        }
        // Split at the middle, moved into the run of points equal to the split value when the
        // sampled median is off (both halves stay non-empty: the median is a cell point).
        let mid = (m / 2).clamp(less.max(1), greater.min(m - 1).max(less.max(1)));
        let low = if mid > less {
            median
        } else {
            column[..mid]
                .iter()
                .copied()
                .fold(f64::NEG_INFINITY, f64::max)
        };
        let high = if greater > mid {
            median
        } else {
            column[mid..].iter().copied().fold(f64::INFINITY, f64::min)
        };
        budget.scratch.column = column;
        self.nodes.push(Node {
            dim: dim as u32,
            low,
            high,
            ..leaf
        });
        let saved_hi = hi[dim];
        hi[dim] = low;
        let l = self.split(start, start + mid, lo, hi, budget)?;
        hi[dim] = saved_hi;
        let saved_lo = lo[dim];
        lo[dim] = high;
        let r = self.split(start + mid, end, lo, hi, budget)?;
        lo[dim] = saved_lo;
        let node = &mut self.nodes[index as usize];
        node.left = l;
        node.right = r;
        Some(index)
    }
}

/// Ids, birth stamps and coordinates (row after row) of some points.
pub(crate) type Parts<'a> = (&'a [u32], &'a [u32], &'a [f64]);

/// Ids, birth stamps and coordinates, owned.
pub(crate) type Owned = (Vec<u32>, Vec<u32>, Vec<f64>);

/// The concatenation of `parts` in `out`'s arrays (emptied first; their capacity reused),
/// copied [`POLL_WORK`] coordinates at a time with `stop` polled in between: copying millions
/// of coordinates takes tens of milliseconds, page faults included. `Err(out)` if it fired, so
/// that the caller keeps the arrays rather than free them on the deadline path.
pub(crate) fn polled_concat(
    parts: &[Parts<'_>],
    stop: &dyn Stop,
    (mut ids, mut births, mut out): Owned,
) -> Result<Owned, Owned> {
    let count = parts.iter().map(|p| p.0.len()).sum();
    let total = parts.iter().map(|p| p.2.len()).sum();
    // An array too small is replaced, not grown: growing copies its whole old buffer (the
    // allocator does not know it is empty).
    fresh(&mut ids, count);
    fresh(&mut births, count);
    fresh(&mut out, total);
    for &(i, b, x) in parts {
        ids.extend_from_slice(i);
        births.extend_from_slice(b);
        for chunk in x.chunks(POLL_WORK) {
            out.extend_from_slice(chunk);
            if stop.should_stop() {
                return Err((ids, births, out));
            }
        }
    }
    Ok((ids, births, out))
}

/// Empties `v` and makes room for `capacity` items without copying its old contents.
pub(crate) fn fresh<T>(v: &mut Vec<T>, capacity: usize) {
    v.clear();
    if v.capacity() < capacity {
        *v = Vec::with_capacity(capacity);
    }
}
