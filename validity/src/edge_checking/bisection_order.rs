//! The canonical grid of an edge and its bisection order (spec §2).
//!
//! An edge of length `d` checked at step `L` has `N = max(1, ceil(d / L))` intervals and the
//! interior grid points `i / N` for `i = 1 … N-1` (the endpoints are vertices, already known
//! valid). Every check of the edge — sparse or full, by any checker — tests points of this one
//! grid, in one fixed order, so the only memory an edge needs is *how many* points of the order
//! have been tested ([`EdgeProgress`](crate::EdgeProgress)).
//!
//! # The order
//! Let `D = ⌊log₂ N⌋`. Level `d = 1 … D` contains the points `⌊m·N / 2^d⌋` for odd
//! `m = 1, 3, …, 2^d − 1`, left to right: level 1 is the midpoint, level 2 the quarter points, and
//! so on — the breadth-first bisection OMPL's discrete motion validator uses. Because
//! `N ≥ 2^D`, the `2^D − 1` points of levels `1 … D` are distinct. The remaining `N − 2^D` grid
//! points (none when `N` is a power of two) follow in ascending order; by then no untested gap is
//! wider than two grid steps. Any position of the order can be computed in `O(log N)` without
//! allocation, so a check can resume where an earlier one stopped.

use std::sync::OnceLock;

/// Grids of at most this many intervals read their order from a table, written once by the
/// computed order: an arm's extension edges have 16 at most, and walking the computed order,
/// about 20 instructions a point, was 4 % of RRT-Connect's instructions on the Panda; the
/// table takes 1.4 % off (callgrind of `arm_profile target 20 rrt-connect 1` on four scenes:
/// 111.8 M → 110.3 M).
const TABLED: u64 = 64;

/// The order of the grid of `n ∈ 2 … TABLED` intervals, each index in a byte: the orders of
/// every such grid are written one after the other, grid `n`'s from `Σ_{m < n} (m − 1)` on.
fn table(n: u64) -> &'static [u8] {
    static TABLES: OnceLock<Vec<u8>> = OnceLock::new();
    let tables = TABLES.get_or_init(|| {
        (2..=TABLED)
            .flat_map(|n| {
                let grid = EdgeGrid::with_intervals(n);
                grid.computed_order(0, grid.points()).map(|i| i as u8)
            })
            .collect()
    });
    let start = ((n - 1) * (n - 2) / 2) as usize;
    &tables[start..start + (n - 1) as usize]
}

/// The canonical grid of one edge: `intervals` equal steps, interior points `1 … intervals-1`.
#[derive(Debug, Clone, Copy)]
pub struct EdgeGrid {
    intervals: u64,
    /// `2^D`, the largest power of two not above `intervals`.
    dyadic: u64,
    /// `1 / N`, so that a grid fraction is one multiplication.
    inverse: f64,
}

impl EdgeGrid {
    /// The grid of an edge of `length` checked at `step` (`N = max(1, ceil(length / step))`).
    ///
    /// A non-finite or non-positive step, or a non-finite length, gives the one-interval grid;
    /// edge checkers validate their step once at construction so this never happens in practice.
    #[inline]
    pub fn new(length: f64, step: f64) -> Self {
        let ratio = length / step;
        let intervals = if ratio.is_finite() && ratio > 1.0 {
            // Saturates at u64::MAX for absurd ratios; `as` on f64 saturates.
            (ratio.ceil() as u64).max(1)
        } else {
            1
        };
        Self::with_intervals(intervals)
    }

    /// The grid with exactly `intervals ≥ 1` intervals.
    #[inline]
    pub fn with_intervals(intervals: u64) -> Self {
        let intervals = intervals.max(1);
        let dyadic = 1u64 << (63 - intervals.leading_zeros());
        Self {
            intervals,
            dyadic,
            inverse: 1.0 / intervals as f64,
        }
    }

    /// Number of intervals `N`.
    #[inline]
    pub fn intervals(&self) -> u64 {
        self.intervals
    }

    /// Number of interior points, `N − 1`: the work of a full check.
    #[inline]
    pub fn points(&self) -> u64 {
        self.intervals - 1
    }

    /// Fraction along the edge of grid index `i`.
    #[inline]
    pub fn fraction(&self, index: u64) -> f64 {
        index as f64 * self.inverse
    }

    /// Grid index (in `1 … N-1`) of position `j` (0-based) of the bisection order.
    ///
    /// # Panics
    /// In debug builds, if `j ≥ points()`.
    pub fn point(&self, j: u64) -> u64 {
        debug_assert!(
            j < self.points(),
            "position {j} beyond {} points",
            self.points()
        );
        let leveled = self.dyadic - 1;
        if j < leveled {
            let depth = 64 - (j + 1).leading_zeros(); // level d: positions 2^(d-1)-1 … 2^d-2
            let k = j + 1 - (1u64 << (depth - 1));
            self.level_point(2 * k + 1, depth)
        } else {
            self.nth_leftover(j - leveled)
        }
    }

    /// `⌊m·N / 2^depth⌋`, exact in 128-bit arithmetic.
    #[inline]
    fn level_point(&self, m: u64, depth: u32) -> u64 {
        ((u128::from(m) * u128::from(self.intervals)) >> depth) as u64
    }

    /// Number of level points (levels `1 … D`) with index `≤ i`.
    #[inline]
    fn leveled_up_to(&self, i: u64) -> u64 {
        // #{m ≥ 1 : ⌊m N / 2^D⌋ ≤ i} = #{m ≥ 1 : m < (i+1)·2^D / N} = ⌈(i+1)·2^D / N⌉ − 1.
        let num = u128::from(i + 1) * u128::from(self.dyadic);
        let count = num.div_ceil(u128::from(self.intervals)) as u64 - 1;
        count.min(self.dyadic - 1)
    }

    /// The `r`-th (0-based) grid index, ascending, that is not a level point.
    fn nth_leftover(&self, r: u64) -> u64 {
        // Smallest i with i − leveled_up_to(i) ≥ r + 1; the left side is non-decreasing in i.
        let (mut lo, mut hi) = (1, self.intervals - 1);
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if mid - self.leveled_up_to(mid) > r {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        lo
    }

    /// Iterates over the grid indices of bisection-order positions `from .. to`.
    ///
    /// Starting costs `O(log N)`; each further step a few additions and one 128-bit multiply —
    /// no division — so walking a whole grid costs about as much as counting it.
    /// Grids of up to 64 intervals read the order from a table the computed order wrote once.
    pub fn order(&self, from: u64, to: u64) -> BisectionOrder {
        let end = to.min(self.points());
        if from < end && self.intervals <= TABLED {
            // An empty walk from `from` (nothing computed), extended over the table.
            let mut order = self.computed_order(from, from);
            (order.end, order.table) = (end, table(self.intervals));
            return order;
        }
        self.computed_order(from, to)
    }

    /// [`order`](Self::order) computed step by step, without the table.
    fn computed_order(&self, from: u64, to: u64) -> BisectionOrder {
        let to = to.min(self.points());
        let leveled = self.dyadic - 1;
        let mut order = BisectionOrder {
            grid: *self,
            position: from,
            end: to,
            depth: 1,
            m: 1,
            cursor: 0,
            next_level_m: 0,
            table: &[],
        };
        if from >= to {
            return order;
        }
        if from < leveled {
            let depth = 64 - (from + 1).leading_zeros();
            order.depth = depth;
            order.m = 2 * (from + 1 - (1u64 << (depth - 1))) + 1;
        } else {
            order.enter_leftovers(from - leveled);
        }
        order
    }
}

/// Grids are equal when their interval counts are (everything else derives from it).
impl PartialEq for EdgeGrid {
    fn eq(&self, other: &Self) -> bool {
        self.intervals == other.intervals
    }
}

impl Eq for EdgeGrid {}

/// Iterator over positions of an edge's bisection order; see [`EdgeGrid::order`].
#[derive(Debug, Clone)]
pub struct BisectionOrder {
    grid: EdgeGrid,
    position: u64,
    end: u64,
    /// Level phase: current depth `d` and odd numerator `m` of the next point `⌊m·N / 2^d⌋`.
    depth: u32,
    m: u64,
    /// Leftover phase: next candidate grid index, and the numerator `m` (over `2^D`) of the
    /// first level point not below it — a merge of two ascending sequences.
    cursor: u64,
    next_level_m: u64,
    /// The whole order of a grid of at most [`TABLED`] intervals (empty: computed).
    table: &'static [u8],
}

impl BisectionOrder {
    /// Positions the leftover phase at its `r`-th index.
    fn enter_leftovers(&mut self, r: u64) {
        self.cursor = self.grid.nth_leftover(r);
        self.next_level_m = self.grid.leveled_up_to(self.cursor - 1) + 1;
    }

    /// The level point with numerator `m` over `2^D`, or `u64::MAX` past the last one.
    #[inline]
    fn level_point_at_full_depth(&self, m: u64) -> u64 {
        if m < self.grid.dyadic {
            let depth = 63 - self.grid.dyadic.leading_zeros();
            self.grid.level_point(m, depth)
        } else {
            u64::MAX
        }
    }
}

impl Iterator for BisectionOrder {
    type Item = u64;

    #[inline]
    fn next(&mut self) -> Option<u64> {
        if self.position >= self.end {
            return None;
        }
        let j = self.position;
        self.position += 1;
        if !self.table.is_empty() {
            return Some(u64::from(self.table[j as usize]));
        }
        let leveled = self.grid.dyadic - 1;
        if j < leveled {
            let index = self.grid.level_point(self.m, self.depth);
            self.m += 2;
            if self.m >= 1u64 << self.depth {
                self.depth += 1;
                self.m = 1;
            }
            if self.position == leveled && self.position < self.end {
                self.enter_leftovers(0);
            }
            return Some(index);
        }
        // Skip the level points: both sequences ascend, so this is a merge.
        let mut level = self.level_point_at_full_depth(self.next_level_m);
        while self.cursor == level {
            self.cursor += 1;
            self.next_level_m += 1;
            level = self.level_point_at_full_depth(self.next_level_m);
        }
        let index = self.cursor;
        self.cursor += 1;
        Some(index)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = usize::try_from(self.end - self.position).unwrap_or(usize::MAX);
        (n, Some(n))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_of_two_grid_is_breadth_first_bisection() {
        let grid = EdgeGrid::with_intervals(8);
        let order: Vec<u64> = grid.order(0, 7).collect();
        assert_eq!(order, vec![4, 2, 6, 1, 3, 5, 7]);
    }

    #[test]
    fn every_grid_visits_each_point_exactly_once() {
        for n in 1..300 {
            let grid = EdgeGrid::with_intervals(n);
            let mut seen = vec![false; n as usize];
            for (j, i) in grid.order(0, grid.points()).enumerate() {
                assert!((1..n).contains(&i), "n={n}: index {i} out of range");
                assert!(!seen[i as usize], "n={n}: index {i} twice");
                seen[i as usize] = true;
                assert_eq!(
                    grid.point(j as u64),
                    i,
                    "n={n}: random access differs at {j}"
                );
            }
            assert_eq!(seen.iter().filter(|&&s| s).count() as u64, grid.points());
        }
    }

    #[test]
    fn tabled_orders_are_the_computed_ones() {
        for n in 2..=TABLED {
            let grid = EdgeGrid::with_intervals(n);
            let computed: Vec<u64> = grid.computed_order(0, grid.points()).collect();
            let tabled: Vec<u64> = grid.order(0, grid.points()).collect();
            assert_eq!(tabled, computed, "n={n}");
            assert_eq!(table(n).len() as u64, grid.points());
        }
    }

    #[test]
    fn resuming_matches_the_full_order() {
        for n in [5u64, 12, 64, 65, 100, 1000, 1023, 1025] {
            let grid = EdgeGrid::with_intervals(n);
            let full: Vec<u64> = grid.order(0, grid.points()).collect();
            for from in [0, 1, 3, 7, 500, 1020] {
                let from = from.min(grid.points());
                let rest: Vec<u64> = grid.order(from, grid.points()).collect();
                assert_eq!(rest, full[from as usize..], "n={n} from={from}");
            }
        }
    }

    #[test]
    fn grid_from_length_and_step() {
        assert_eq!(EdgeGrid::new(1.0, 0.25).intervals(), 4);
        assert_eq!(EdgeGrid::new(1.0, 0.3).intervals(), 4);
        assert_eq!(EdgeGrid::new(0.1, 0.3).points(), 0);
        assert_eq!(EdgeGrid::new(f64::NAN, 0.3).points(), 0);
    }
}
