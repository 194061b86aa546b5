//! [`SlabIndex`]: which boxes can hold a point, coordinate by coordinate, for worlds of many
//! large boxes in many dimensions, where a bounding-volume hierarchy cannot prune.
//!
//! In 32 dimensions a hierarchy splits each coordinate at most once or twice, and boxes whose
//! sides span a quarter of the range or more make every child's bounds overlap its sibling's:
//! a point near the middle of the space enters nearly every node (up to 2.2 ms a check with 10⁵
//! boxes in R^32, measured). The slabs answer the same question with a few thousand word
//! operations (about 20 µs there).

/// Slabs per coordinate, at most.
const SLABS: usize = 32;

/// The index's size at most, in bits (2²⁸ bits = 32 MiB): fewer slabs per coordinate above it.
const MAX_BITS: usize = 1 << 28;

/// Coordinates the index serves, at most (the query keeps one slab offset per coordinate on
/// the stack); worlds of more dimensions use the hierarchy.
pub(crate) const MAX_DIMENSION: usize = 64;

/// Per coordinate, the range of the boxes cut into equal slabs; per slab, a bitset of the boxes
/// whose side on that coordinate meets it. A point is in a box only if the box's bit is set in
/// the point's slab of every coordinate: a query ANDs the point's bitsets 64 boxes at a time,
/// stops a word as soon as it is zero, and checks the few surviving boxes exactly.
///
/// Exact: a point's slab and a side's first and last slabs come from one monotone map, so a box
/// holding the point has its bit set in every slab the point falls in; candidates are then
/// tested against the rows themselves. Built in `O(N · n · slabs / 64)`; a query costs about
/// `N / 64 · k` word operations, `k` the coordinates it takes for 64 boxes to all miss.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SlabIndex {
    dimension: usize,
    slabs: usize,
    /// Words per bitset: `⌈N / 64⌉`.
    words: usize,
    /// Per coordinate, the smallest lower bound of any box, and slabs per unit length.
    origin: Vec<f64>,
    scale: Vec<f64>,
    /// Coordinates, most selective first (fewest boxes per slab on average).
    order: Vec<usize>,
    /// Bitsets, `[coordinate][slab][word]`.
    bits: Vec<u64>,
}

impl SlabIndex {
    /// The index over `rows` (each box `2 · dimension` values), or `None` for a dimension the
    /// index does not serve (0, or above [`MAX_DIMENSION`]).
    pub(crate) fn build(rows: &[f64], dimension: usize) -> Option<Self> {
        if dimension == 0 || dimension > MAX_DIMENSION {
            return None;
        }
        let width = 2 * dimension;
        let count = rows.len() / width;
        let words = count.div_ceil(64).max(1);
        let slabs = (MAX_BITS / (dimension * words * 64)).clamp(1, SLABS);
        let mut origin = vec![f64::INFINITY; dimension];
        let mut end = vec![f64::NEG_INFINITY; dimension];
        for row in rows.chunks_exact(width) {
            for d in 0..dimension {
                origin[d] = origin[d].min(row[2 * d]);
                end[d] = end[d].max(row[2 * d + 1]);
            }
        }
        let scale: Vec<f64> = origin
            .iter()
            .zip(&end)
            .map(|(&lo, &hi)| {
                let span = hi - lo;
                if span.is_finite() && span > 0.0 {
                    slabs as f64 / span
                } else {
                    0.0
                }
            })
            .collect();
        let mut index = Self {
            dimension,
            slabs,
            words,
            origin,
            scale,
            order: (0..dimension).collect(),
            bits: vec![0; dimension * slabs * words],
        };
        let mut filled = vec![0_usize; dimension];
        for (b, row) in rows.chunks_exact(width).enumerate() {
            for (d, filled) in filled.iter_mut().enumerate() {
                let (first, last) = (index.slab(d, row[2 * d]), index.slab(d, row[2 * d + 1]));
                *filled += last + 1 - first;
                for s in first..=last {
                    index.bits[(d * slabs + s) * words + b / 64] |= 1 << (b % 64);
                }
            }
        }
        index.order.sort_by_key(|&d| filled[d]);
        Some(index)
    }

    /// `true` if checks of `count` boxes in `dimension` dimensions, whose sides span on
    /// average `side` of the boxes' extent along their coordinate, should use the slabs rather
    /// than a hierarchy: when the boxes are large (`side` ≥ 0.1) and a hierarchy over them
    /// (`log₂(count / 8)` levels, 8 boxes per leaf) would cut each coordinate fewer than 1.5
    /// times on a path from its root. Siblings' bounds then overlap along most coordinates and a
    /// point near the middle enters most nodes: with 10⁵ such boxes the hierarchy's worst check
    /// is 0.5 ms in R^12 and 2.2 ms in R^32, the slabs' 15–20 µs. Small boxes the hierarchy
    /// separates in any dimension (10⁵ boxes of side 0.015 in R^16: 0.5 µs a check, the slabs
    /// 5 µs), and with 10⁵ large boxes in R^4 or R^8 it is 3–7× faster on average (its worst
    /// check about 0.1 ms).
    ///
    /// Measured with `cargo test --release -p mit-star-validity --lib slab_index -- --ignored
    /// --nocapture` (the mean over uniform points, and the worst of free points among many
    /// boxes, a start state's place) and `cargo run --release -p mit-star-validity --example
    /// large_world`.
    pub(crate) fn serves(count: usize, dimension: usize, side: f64) -> bool {
        Self::hierarchy_is_shallow(count, dimension) && side >= 0.1
    }

    /// The first half of [`serves`](Self::serves), which needs no pass over the boxes: a
    /// dimension the index serves, with a hierarchy over `count` boxes cutting each coordinate
    /// fewer than 1.5 times.
    fn hierarchy_is_shallow(count: usize, dimension: usize) -> bool {
        let depth = (count as f64 / 8.0).log2();
        (1..=MAX_DIMENSION).contains(&dimension) && count > 8 && 1.5 * dimension as f64 >= depth
    }

    /// The index over `rows` if it [serves](Self::serves) them better than a hierarchy.
    pub(crate) fn if_it_serves(rows: &[f64], dimension: usize) -> Option<Self> {
        let width = 2 * dimension;
        let count = rows.len().checked_div(width)?;
        if !Self::hierarchy_is_shallow(count, dimension) {
            return None;
        }
        let mut extent = vec![(f64::INFINITY, f64::NEG_INFINITY); dimension];
        let mut sides = vec![0.0; dimension];
        for row in rows.chunks_exact(width) {
            for (d, ((lo, hi), sum)) in extent.iter_mut().zip(&mut sides).enumerate() {
                *lo = row[2 * d].min(*lo);
                *hi = row[2 * d + 1].max(*hi);
                *sum += row[2 * d + 1] - row[2 * d];
            }
        }
        let side = extent
            .iter()
            .zip(&sides)
            .map(|(&(lo, hi), &sum)| (sum / count as f64 / (hi - lo)).min(1.0))
            .filter(|f| f.is_finite())
            .sum::<f64>()
            / dimension as f64;
        Self::serves(count, dimension, side)
            .then(|| Self::build(rows, dimension))
            .flatten()
    }

    /// The slab of value `x` on coordinate `d`: monotone in `x`, clamped to the slabs.
    #[inline]
    fn slab(&self, d: usize, x: f64) -> usize {
        // `as` saturates: below the origin (and NaN) go to slab 0.
        (((x - self.origin[d]) * self.scale[d]).floor() as usize).min(self.slabs - 1)
    }

    /// `true` if `point` lies in one of `rows` (closed), the rows the index was built over.
    #[inline]
    pub(crate) fn contains(&self, rows: &[f64], point: &[f64]) -> bool {
        let width = 2 * self.dimension;
        let mut offsets = [0_usize; MAX_DIMENSION];
        for (offset, &d) in offsets.iter_mut().zip(&self.order) {
            *offset = (d * self.slabs + self.slab(d, point[d])) * self.words;
        }
        let offsets = &offsets[..self.dimension];
        for w in 0..self.words {
            let mut mask = u64::MAX;
            for &offset in offsets {
                mask &= self.bits[offset + w];
                if mask == 0 {
                    break;
                }
            }
            while mask != 0 {
                let b = 64 * w + mask.trailing_zeros() as usize;
                mask &= mask - 1;
                let row = &rows[b * width..(b + 1) * width];
                if row
                    .chunks_exact(2)
                    .zip(point)
                    .all(|(r, &x)| x >= r[0] && x <= r[1])
                {
                    return true;
                }
            }
        }
        false
    }

    /// Appends to `kept` the rows of every box of `rows` that meets `reach` (`[lo, hi]` per
    /// coordinate, closed) and returns `true` — or returns `false`, with `kept` holding a
    /// partial list, as soon as more than `cap` boxes meet it (as the hierarchy's
    /// `collect_meeting`). A coordinate's candidates are the union of the slabs the reach
    /// spans on it.
    pub(crate) fn collect_meeting(
        &self,
        rows: &[f64],
        reach: &[f64],
        kept: &mut Vec<f64>,
        cap: usize,
    ) -> bool {
        let width = 2 * self.dimension;
        let mut spans = [(0_usize, 0_usize); MAX_DIMENSION];
        for (span, &d) in spans.iter_mut().zip(&self.order) {
            let (first, last) = (self.slab(d, reach[2 * d]), self.slab(d, reach[2 * d + 1]));
            let base = d * self.slabs;
            *span = (
                (base + first) * self.words,
                (base + last.max(first)) * self.words,
            );
        }
        let spans = &spans[..self.dimension];
        let mut count = 0;
        for w in 0..self.words {
            let mut mask = u64::MAX;
            for &(first, last) in spans {
                let mut union = 0;
                let mut at = first + w;
                while at <= last + w {
                    union |= self.bits[at];
                    at += self.words;
                }
                mask &= union;
                if mask == 0 {
                    break;
                }
            }
            while mask != 0 {
                let b = 64 * w + mask.trailing_zeros() as usize;
                mask &= mask - 1;
                let row = &rows[b * width..(b + 1) * width];
                let meets = row
                    .chunks_exact(2)
                    .zip(reach.chunks_exact(2))
                    .all(|(r, e)| r[0] <= e[1] && r[1] >= e[0]);
                if meets {
                    count += 1;
                    if count > cap {
                        return false;
                    }
                    kept.extend_from_slice(row);
                }
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scan(rows: &[f64], n: usize, p: &[f64]) -> bool {
        rows.chunks_exact(2 * n).any(|r| {
            r.chunks_exact(2)
                .zip(p)
                .all(|(b, &x)| x >= b[0] && x <= b[1])
        })
    }

    #[test]
    fn agrees_with_a_scan_on_points_inside_outside_and_on_faces() {
        let mut seed = 11_u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for (n, count) in [(1, 3), (3, 500), (16, 130), (40, 70)] {
            let mut rows = Vec::new();
            for _ in 0..count {
                for _ in 0..n {
                    let (c, w) = (next() - 0.5, 0.4 * next());
                    rows.extend([c - w, c + w]);
                }
            }
            let index = SlabIndex::build(&rows, n).unwrap();
            for i in 0..4000 {
                let mut p: Vec<f64> = (0..n).map(|_| 1.4 * (next() - 0.5)).collect();
                if i % 4 == 0 {
                    // On a face of some box: the closed sides count.
                    let b = i % count;
                    let d = i % n;
                    p[d] = rows[b * 2 * n + 2 * d + (i / 4) % 2];
                }
                assert_eq!(index.contains(&rows, &p), scan(&rows, n, &p), "{p:?}");
            }
            let nan = vec![f64::NAN; n];
            assert!(!index.contains(&rows, &nan));
        }
        assert!(SlabIndex::build(&[], 0).is_none());
        assert!(SlabIndex::build(&[0.0; 130], 65).is_none());
        let empty = SlabIndex::build(&[], 2).unwrap();
        assert!(!empty.contains(&[], &[0.0, 0.0]));
    }

    /// Not a test: prints the time per point check of the hierarchy and of the slabs, for
    /// the rule of [`SlabIndex::serves`].
    #[test]
    #[ignore = "a measurement; run in release with --ignored --nocapture"]
    fn measure_against_the_hierarchy() {
        use crate::box_world::box_tree::BoxTree;
        use std::hint::black_box;
        use std::time::Instant;
        let mut seed = 5_u64;
        let mut next = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        println!(
            "| boxes | n | slabs serve | hierarchy mean / worst (µs) | slabs mean / worst (µs) |"
        );
        println!("|---|---|---|---|---|");
        for (count, n) in [(1000, 4), (1000, 8), (1000, 16), (100_000, 4), (100_000, 8)]
            .into_iter()
            .chain([(100_000, 12), (100_000, 16), (100_000, 32), (10_000, 32)])
        {
            let side = (0.3 / count as f64).powf(1.0 / n as f64).min(0.5);
            let mut rows = Vec::with_capacity(2 * n * count);
            for _ in 0..count {
                for _ in 0..n {
                    let (c, h) = (next() - 0.5, 0.5 * side * (0.5 + 0.5 * next()));
                    rows.extend([c - h, c + h]);
                }
            }
            let points: Vec<Vec<f64>> = (0..2000)
                .map(|_| (0..n).map(|_| next() - 0.5).collect())
                .collect();
            // Free points near the middle, where most boxes' sides hold most coordinates.
            let free: Vec<Vec<f64>> = (0..200_000)
                .map(|_| (0..n).map(|_| 0.2 * (next() - 0.5)).collect::<Vec<f64>>())
                .filter(|p| !scan(&rows, n, p))
                .take(20)
                .collect();
            let tree = BoxTree::build(&rows, n);
            let slabs = SlabIndex::build(&rows, n).unwrap();
            let time = |check: &dyn Fn(&[f64]) -> bool| {
                let started = Instant::now();
                for p in &points {
                    black_box(check(black_box(p)));
                }
                let mean = started.elapsed().as_secs_f64() / points.len() as f64;
                let worst = free
                    .iter()
                    .map(|p| {
                        let started = Instant::now();
                        black_box(check(black_box(p)));
                        started.elapsed().as_secs_f64()
                    })
                    .fold(0.0, f64::max);
                (mean * 1e6, worst * 1e6)
            };
            let (tm, tw) = time(&|p| tree.contains(p));
            let (sm, sw) = time(&|p| slabs.contains(&rows, p));
            println!(
                "| {count} | {n} | {} | {tm:.2} / {tw:.1} | {sm:.2} / {sw:.1} |",
                SlabIndex::if_it_serves(&rows, n).is_some()
            );
        }
    }

    #[test]
    fn collects_the_boxes_a_reach_meets_as_a_scan_does() {
        let mut seed = 3_u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for (n, count) in [(2, 300), (12, 200), (32, 150)] {
            let mut rows = Vec::new();
            for _ in 0..count {
                for _ in 0..n {
                    let (c, w) = (next() - 0.5, 0.3 * next());
                    rows.extend([c - w, c + w]);
                }
            }
            let index = SlabIndex::build(&rows, n).unwrap();
            for i in 0..500 {
                let reach: Vec<f64> = (0..n)
                    .flat_map(|_| {
                        let (c, w) = (1.2 * (next() - 0.5), 0.5 * next() * next());
                        [c - w, c + w]
                    })
                    .collect();
                let expected: Vec<f64> = rows
                    .chunks_exact(2 * n)
                    .filter(|r| {
                        r.chunks_exact(2)
                            .zip(reach.chunks_exact(2))
                            .all(|(b, e)| b[0] <= e[1] && b[1] >= e[0])
                    })
                    .flatten()
                    .copied()
                    .collect();
                let cap = if i % 2 == 0 { count } else { 3 };
                let mut kept = Vec::new();
                let complete = index.collect_meeting(&rows, &reach, &mut kept, cap);
                assert_eq!(complete, expected.len() <= cap * 2 * n, "{reach:?}");
                if complete {
                    assert_eq!(kept, expected);
                }
            }
        }
    }

    #[test]
    fn a_box_of_zero_width_on_a_coordinate_is_found() {
        // All boxes share one value on coordinate 0: that coordinate has no span.
        let rows = [0.2, 0.2, -1.0, 1.0, 0.2, 0.2, 2.0, 3.0];
        let index = SlabIndex::build(&rows, 2).unwrap();
        assert!(index.contains(&rows, &[0.2, 0.5]));
        assert!(index.contains(&rows, &[0.2, 3.0]));
        assert!(!index.contains(&rows, &[0.2, 1.5]));
        assert!(!index.contains(&rows, &[0.3, 0.5]));
    }
}
