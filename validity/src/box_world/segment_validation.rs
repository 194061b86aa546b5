//! Exact validation of a straight segment against a [`World`]: slab tests, no grid.
//!
//! A planner checks an edge at grid points a step `L` apart, so a path can cross an obstacle
//! thinner than `L` between two of them. Validating the returned path on the same kind of grid
//! would miss exactly what the planner missed. This module decides the segment itself: for
//! `x(t) = a + t (b − a)`, `t ∈ [0, 1]`, it computes the closed `t`-intervals inside every
//! obstacle (and lattice cube) and inside every anti-obstacle, and the segment is valid iff it
//! stays in the bounds and every obstacle interval is covered by the union of the anti-obstacle
//! intervals — the [`World`]'s point semantics (closed boxes widened by `f64::EPSILON`, "valid
//! iff in bounds and in some anti-obstacle or in no obstacle") applied to every point of the
//! segment at once.
//!
//! # Floating point: the computed points, exactly
//! A planner never meets the real segment, only its *computed* points: `a + (b − a)·t` in
//! floating point, at float fractions `t`, from one end or the other — the ends themselves,
//! every grid point a walk or a certification tests, every state an interpolation returns. Far
//! from the origin those lie on a lattice of ulps (1e-7 apart at 1e9), so a computed point can
//! fall into a box the real segment misses by less than that, or out of an anti-obstacle it
//! stays in. The verdict is therefore taken on exactly those points: for both
//! parametrizations, `a + (b − a)·t` and `b + (a − b)·t`, and every float `t ∈ [0, 1)`, the
//! [`World`]'s own comparisons against its own box bounds (`c ± (w/2 + ε)`). Each computed
//! coordinate is monotone in `t`, so the fractions inside a box (or a lattice slab, or the
//! bounds) form one interval of floats, found exactly by searching the floats
//! ([`Segment::crossing`]) within a slab test's loose span. So the verdict is one-sided — a
//! computed point the point test rejects makes the segment invalid — and exact: an
//! anti-obstacle exactly aligned with its obstacle (a slot as wide as the wall) yields the
//! same intervals and covers it, while a slot shifted by `1e-7` leaves an uncovered sliver,
//! found. What lies *between* two computed points of the real segment (a corner clipped by
//! less than an ulp of the coordinates) is decided as the nearest computed points are.

use crate::box_world::segment::ROUNDING;
use crate::{Lattice, Segment, World};

/// Why a segment is invalid.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SegmentCause {
    /// A coordinate of an end is NaN or infinite, their difference overflows, or the ends
    /// differ in dimension.
    Malformed,
    /// The segment leaves the world's bounds.
    OutOfBounds,
    /// The segment enters obstacle `index` (of [`World::obstacles`]) outside every
    /// anti-obstacle.
    Obstacle(usize),
    /// The segment enters a cube of lattice `index` (of [`World::lattices`]) outside every
    /// anti-obstacle.
    Lattice(usize),
}

/// The verdict of [`World::segment_verdict`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SegmentVerdict {
    /// Every point of the segment is valid.
    Valid,
    /// A computed point near parameter `t` is invalid, for `cause`: the point `a + (b − a)·t`
    /// itself, at the first such float `t`, if there is one; otherwise `t` is `1 − s` for the
    /// first float `s` at which `b + (a − b)·s` is invalid.
    Invalid {
        /// Where along the segment, in `[0, 1]`.
        t: f64,
        /// Why.
        cause: SegmentCause,
    },
}

impl SegmentVerdict {
    /// `true` for [`SegmentVerdict::Valid`].
    pub fn is_valid(&self) -> bool {
        matches!(self, Self::Valid)
    }
}

/// A closed interval of the segment's parameter.
pub(crate) type Interval = (f64, f64);

impl World {
    /// Decides exactly whether every point of the straight segment `a → b` is valid (module
    /// docs: slab tests against every box, anti-obstacle coverage, bounds; no grid).
    ///
    /// ```
    /// use mit_star_validity::{AxisBox, SegmentCause, SegmentVerdict, World};
    /// // A wall 1e-6 thick across the square: no grid at step 5e-6 sees it; this does.
    /// let world = World::new(vec![-0.5; 2], vec![0.5; 2])
    ///     .with_obstacle(AxisBox::new(vec![0.0, 0.0], vec![1e-6, 1.0]))?;
    /// match world.segment_verdict(&[-0.3, 0.0], &[0.3, 0.0]) {
    ///     SegmentVerdict::Invalid { t, cause } => {
    ///         assert_eq!(cause, SegmentCause::Obstacle(0));
    ///         assert!((t - 0.5).abs() < 1e-5);
    ///     }
    ///     SegmentVerdict::Valid => unreachable!(),
    /// }
    /// assert!(world.segment_verdict(&[-0.3, 0.0], &[-0.1, 0.2]).is_valid());
    /// # Ok::<(), mit_star_validity::ValidityError>(())
    /// ```
    pub fn segment_verdict(&self, a: &[f64], b: &[f64]) -> SegmentVerdict {
        let n = self.dimension();
        let malformed = SegmentVerdict::Invalid {
            t: 0.0,
            cause: SegmentCause::Malformed,
        };
        if a.len() != n || b.len() != n || a.iter().chain(b).any(|x| !x.is_finite()) {
            return malformed;
        }
        let mut segment = Segment::default();
        segment.set(a, b);
        if !segment.is_finite() {
            return malformed;
        }
        if let Some((t, cause)) = self.first_invalid_computed(&segment) {
            return SegmentVerdict::Invalid { t, cause };
        }
        segment.set(b, a);
        match self.first_invalid_computed(&segment) {
            Some((s, cause)) => SegmentVerdict::Invalid { t: 1.0 - s, cause },
            None => SegmentVerdict::Valid,
        }
    }

    /// The first float fraction `t ∈ [0, 1)` whose computed point `segment.point(t)` the world
    /// rejects, and why (`None` if every one is valid): the bounds, then the obstacles and
    /// lattices not covered by anti-obstacles, each as an exact interval of floats.
    fn first_invalid_computed(&self, segment: &Segment) -> Option<(f64, SegmentCause)> {
        let mut first: Option<(f64, SegmentCause)> = None;
        let mut note = |t: f64, cause: SegmentCause| {
            if first.is_none_or(|(best, _)| t < best) {
                first = Some((t, cause));
            }
        };
        let mut bounds = Vec::new();
        self.bounds_row(&mut bounds);
        if let Some(t) = leaves_bounds(segment, &bounds) {
            note(t, SegmentCause::OutOfBounds);
        }
        let width = 2 * self.dimension();
        let free = merged(
            self.anti_obstacles
                .rows()
                .chunks_exact(width)
                .filter_map(|row| exact_interval(segment, row))
                .collect(),
        );
        for (index, row) in self.obstacles.rows().chunks_exact(width).enumerate() {
            if let Some(interval) = exact_interval(segment, row)
                && let Some(t) = uncovered(interval, &free)
            {
                note(t, SegmentCause::Obstacle(index));
            }
        }
        for index in 0..self.lattices.len() {
            for interval in lattice_intervals(self, index, segment) {
                if let Some(t) = uncovered(interval, &free) {
                    note(t, SegmentCause::Lattice(index));
                    break;
                }
            }
        }
        first
    }

    /// The world's bounds as one row, `[lo₀, hi₀, lo₁, hi₁, …]`, written into `row`.
    pub(crate) fn bounds_row(&self, row: &mut Vec<f64>) {
        row.clear();
        row.extend(
            self.lower
                .iter()
                .zip(&self.upper)
                .flat_map(|(&lo, &hi)| [lo, hi]),
        );
    }
}

/// The first float fraction whose computed point lies outside the bounds `row` (as
/// [`World::bounds_row`] writes them), `None` if every one lies inside.
pub(crate) fn leaves_bounds(segment: &Segment, row: &[f64]) -> Option<f64> {
    match exact_interval(segment, row) {
        Some((s, _)) if s > 0.0 => Some(0.0),
        Some((_, e)) if e < BELOW_ONE => Some(next_float(e)),
        Some(_) => None,
        None => Some(0.0),
    }
}

/// The largest float below 1: fractions run over `[0, 1)`, so the point at 1 is the other end
/// itself (the other parametrization's `t = 0`), not `a + (b − a)·1`, which may differ from it
/// by rounding.
pub(crate) const BELOW_ONE: f64 = 1.0 - f64::EPSILON / 2.0;

/// The fractions of `[0, 1)`, as a span.
pub(crate) const FRACTIONS: [f64; 2] = [0.0, BELOW_ONE];

/// The float just above a non-negative `t`.
pub(crate) fn next_float(t: f64) -> f64 {
    f64::from_bits(t.to_bits() + 1)
}

/// The exact interval of float fractions `t ∈ [0, 1)` whose computed point lies in the closed
/// box `row` (`[lo, hi]` per coordinate, as the world stores it), `None` if none does: boxes
/// away from the segment's reach are dismissed at once, the others by a slab test's loose span,
/// then searched.
pub(crate) fn exact_interval(segment: &Segment, row: &[f64]) -> Option<Interval> {
    if !meets_reach(segment, row) {
        return None;
    }
    crossed_interval(segment, row)
}

/// `true` if the box `row` meets the segment's reach along every coordinate (a box that does
/// not holds no computed point).
#[inline]
pub(crate) fn meets_reach(segment: &Segment, row: &[f64]) -> bool {
    row.chunks_exact(2)
        .zip(segment.reach.chunks_exact(2))
        .all(|(b, r)| b[0] <= r[1] && b[1] >= r[0])
}

/// [`exact_interval`] for a box known to meet the segment's reach: the slab test's span, then
/// the search of the floats within it.
pub(crate) fn crossed_interval(segment: &Segment, row: &[f64]) -> Option<Interval> {
    let [s0, s1] = segment.span(row)?;
    let [t0, t1] = segment.crossing(row, [s0, s1.min(BELOW_ONE)])?;
    Some((t0, t1))
}

/// Sorts closed intervals of non-negative floats and merges those that overlap or are
/// adjacent (no float between them).
fn merged(mut intervals: Vec<Interval>) -> Vec<Interval> {
    merge_in_place(&mut intervals);
    intervals
}

/// [`merged`] in place: sorts `intervals` and merges those that overlap or are adjacent,
/// keeping the buffer.
pub(crate) fn merge_in_place(intervals: &mut Vec<Interval>) {
    intervals.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut kept = 0;
    for i in 0..intervals.len() {
        let (s, e) = intervals[i];
        if kept > 0 && s <= next_float(intervals[kept - 1].1) {
            let last = &mut intervals[kept - 1];
            last.1 = last.1.max(e);
        } else {
            intervals[kept] = (s, e);
            kept += 1;
        }
    }
    intervals.truncate(kept);
}

/// The first float of `interval` that no interval of `free` (merged, sorted, with floats
/// between them) covers, if any. Closed intervals: `[0.2, 0.5]` covers `[0.2, 0.5]`.
pub(crate) fn uncovered((s, e): Interval, free: &[Interval]) -> Option<f64> {
    // Merged intervals are disjoint with gaps between them, so one of them must cover it all:
    // the last one starting at or before `s`, if it reaches `s` (a binary search, so that a
    // world of many anti-obstacles costs a logarithm per obstacle crossed).
    let before = free.partition_point(|(u0, _)| *u0 <= s);
    let covering = before
        .checked_sub(1)
        .map(|i| &free[i])
        .filter(|(_, u1)| s <= *u1);
    match covering {
        Some(&(_, u1)) if u1 >= e => None,
        // Covered up to u1, then a gap: the float just after u1 is in the obstacle.
        Some(&(_, u1)) => Some(next_float(u1)),
        None => Some(s),
    }
}

/// The float fractions where the computed point lies in some cube of lattice `index`: the
/// lattice is a product `∏_d S_d` of unions of slabs, so the set is `∩_d T_d` with
/// `T_d = {t : x_d(t) ∈ S_d}`, each slab's floats found exactly with the world's own test
/// `|x − c| ≤ side/2 + ε` (which tests only the nearest centre: the union over every centre
/// holds all it accepts).
fn lattice_intervals(world: &World, index: usize, segment: &Segment) -> Vec<Interval> {
    let lattice = &world.lattices[index];
    if lattice.count == 0 {
        return Vec::new();
    }
    let mut result = vec![(FRACTIONS[0], FRACTIONS[1])];
    for d in 0..world.dimension() {
        let (first, last) = lattice_cubes(world, lattice, segment, d);
        let mut slabs = Vec::new();
        let mut j = first;
        while j <= last {
            slabs.extend(lattice_slab(world, lattice, segment, d, j));
            j += 1.0;
        }
        let mut next = Vec::new();
        intersect_into(&result, &merged(slabs), &mut next);
        result = next;
        if result.is_empty() {
            break;
        }
    }
    result
}

/// The first and last index `j` (as floats) of the cubes of `lattice` along coordinate `d`
/// whose slab `[c_j − h, c_j + h]`, `c_j = lower + (j + 1)·spacing`, may meet the segment's
/// reach, one more each side for the rounding of this estimate.
pub(crate) fn lattice_cubes(
    world: &World,
    lattice: &Lattice,
    segment: &Segment,
    d: usize,
) -> (f64, f64) {
    let half = 0.5 * lattice.side + f64::EPSILON;
    let last_cube = lattice.count as f64 - 1.0;
    let (lower, (lo, hi)) = (world.lower[d], segment.reach(d));
    let first = ((lo - half - lower) / lattice.spacing - 2.0)
        .floor()
        .max(0.0);
    let last = ((hi + half - lower) / lattice.spacing)
        .ceil()
        .min(last_cube);
    (first, last)
}

/// The exact float fractions whose computed coordinate `d` lies in the slab of cube `j` of
/// `lattice` (the world's own test `|x − c| ≤ side/2 + ε`), if any.
#[inline]
pub(crate) fn lattice_slab(
    world: &World,
    lattice: &Lattice,
    segment: &Segment,
    d: usize,
    j: f64,
) -> Option<Interval> {
    let half = 0.5 * lattice.side + f64::EPSILON;
    let c = world.lower[d] + (j + 1.0) * lattice.spacing;
    // The span of the slab widened by the rounding of `x − c`.
    let widen = ROUNDING * (c.abs() + half);
    let slab = [c - half - widen, c + half + widen];
    let span = segment.slab_span(d, slab, FRACTIONS)?;
    let [t0, t1] = segment.coordinate_crossing(d, span, |v| v - c >= -half, |v| v - c <= half)?;
    Some((t0, t1))
}

/// The intersection of two sorted lists of disjoint closed intervals, written into `out`.
pub(crate) fn intersect_into(x: &[Interval], y: &[Interval], out: &mut Vec<Interval>) {
    out.clear();
    let (mut i, mut j) = (0, 0);
    while i < x.len() && j < y.len() {
        let (s, e) = (x[i].0.max(y[j].0), x[i].1.min(y[j].1));
        if s <= e {
            out.push((s, e));
        }
        if x[i].1 < y[j].1 {
            i += 1;
        } else {
            j += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::AxisBox;

    fn square() -> World {
        World::new(vec![-0.5; 2], vec![0.5; 2])
    }

    #[test]
    fn covered_intervals_and_slivers() {
        let free = merged(vec![(0.4, 0.6), (0.1, 0.2), (0.2, 0.3)]);
        assert_eq!(free, vec![(0.1, 0.3), (0.4, 0.6)]);
        assert_eq!(uncovered((0.15, 0.3), &free), None);
        assert_eq!(uncovered((0.15, 0.35), &free), Some(next_float(0.3)));
        assert_eq!(uncovered((0.35, 0.5), &free), Some(0.35));
        assert_eq!(uncovered((0.4, 0.6), &free), None);
    }

    #[test]
    fn an_aligned_slot_is_free_and_a_shifted_one_leaves_a_sliver() {
        let wall = AxisBox::new(vec![0.0, 0.0], vec![0.1, 1.0]);
        let slot = |dx: f64| AxisBox::new(vec![dx, 0.0], vec![0.1, 0.04]);
        let aligned = square()
            .with_obstacle(wall.clone())
            .unwrap()
            .with_anti_obstacle(slot(0.0))
            .unwrap();
        assert!(
            aligned
                .segment_verdict(&[-0.3, 0.0], &[0.3, 0.0])
                .is_valid()
        );
        let shifted = square()
            .with_obstacle(wall)
            .unwrap()
            .with_anti_obstacle(slot(1.2e-7))
            .unwrap();
        assert!(matches!(
            shifted.segment_verdict(&[-0.3, 0.0], &[0.3, 0.0]),
            SegmentVerdict::Invalid {
                cause: SegmentCause::Obstacle(0),
                ..
            }
        ));
    }

    #[test]
    fn bounds_and_malformed_ends() {
        let w = square();
        // The first computed point beyond the bound is at the float after 0.5.
        assert_eq!(
            w.segment_verdict(&[0.0, 0.0], &[1.0, 0.0]),
            SegmentVerdict::Invalid {
                t: next_float(0.5),
                cause: SegmentCause::OutOfBounds
            }
        );
        assert!(matches!(
            w.segment_verdict(&[f64::NAN, 0.0], &[0.0, 0.0]),
            SegmentVerdict::Invalid {
                cause: SegmentCause::Malformed,
                ..
            }
        ));
        assert!(matches!(
            w.segment_verdict(&[0.0], &[0.0, 0.0]),
            SegmentVerdict::Invalid {
                cause: SegmentCause::Malformed,
                ..
            }
        ));
        assert!(w.segment_verdict(&[0.1, 0.1], &[0.1, 0.1]).is_valid());
    }

    #[test]
    fn lattices_are_crossed_exactly() {
        let lattice = Lattice {
            count: 4,
            spacing: 0.2,
            side: 0.05,
        };
        let w = square().with_lattice(lattice).unwrap();
        // Cube centres at -0.3, -0.1, 0.1, 0.3 per axis; y = 0.0 runs between the rows.
        assert!(w.segment_verdict(&[-0.45, 0.0], &[0.45, 0.0]).is_valid());
        // y = -0.1 runs through a row of cubes.
        assert!(matches!(
            w.segment_verdict(&[-0.45, -0.1], &[0.45, -0.1]),
            SegmentVerdict::Invalid {
                cause: SegmentCause::Lattice(0),
                ..
            }
        ));
        // Diagonals x + y = −0.7 (misses the cube at (−0.3, −0.3)) and x + y = −0.6 (cuts it).
        assert!(
            w.segment_verdict(&[-0.45, -0.25], &[-0.25, -0.45])
                .is_valid()
        );
        assert!(
            !w.segment_verdict(&[-0.45, -0.15], &[-0.15, -0.45])
                .is_valid()
        );
    }
}
