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
//! # Floating point
//! Interval ends are computed with the same box bounds (`c ± (w/2 + ε)`) the point test uses,
//! so an anti-obstacle exactly aligned with its obstacle (a slot as wide as the wall) yields
//! bit-identical intervals and covers it; a slot shifted by `1e-7` leaves an uncovered sliver,
//! found. Decisions are exact up to the rounding of the slab parameters (a relative `~1e-16`
//! of the segment): a contact that deep — a segment grazing a corner by less than that — may be
//! decided either way, as the point test itself would be at that scale.

use crate::World;

/// Why a segment is invalid.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SegmentCause {
    /// A coordinate of an end is NaN or infinite, or the ends differ in dimension.
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
    /// The point at parameter `t` (`x(t) = a + t (b − a)`) is invalid, for `cause`; `t` is the
    /// first such parameter the slab tests found.
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
type Interval = (f64, f64);

impl World {
    /// Decides exactly whether every point of the straight segment `a → b` is valid (module
    /// docs: slab tests against every box, anti-obstacle coverage, bounds; no grid).
    ///
    /// ```
    /// use validity::{AxisBox, SegmentCause, SegmentVerdict, World};
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
    /// # Ok::<(), validity::ValidityError>(())
    /// ```
    pub fn segment_verdict(&self, a: &[f64], b: &[f64]) -> SegmentVerdict {
        let n = self.dimension();
        if a.len() != n || b.len() != n || a.iter().chain(b).any(|x| !x.is_finite()) {
            return SegmentVerdict::Invalid {
                t: 0.0,
                cause: SegmentCause::Malformed,
            };
        }
        if let Some(t) = self.leaves_bounds(a, b) {
            return SegmentVerdict::Invalid {
                t,
                cause: SegmentCause::OutOfBounds,
            };
        }
        let mut free = Vec::new();
        for anti in self.anti_obstacles() {
            if let Some(interval) = box_interval(&anti.center, &anti.widths, a, b) {
                free.push(interval);
            }
        }
        let free = merged(free);
        let mut first: Option<(f64, SegmentCause)> = None;
        let mut note = |t: f64, cause: SegmentCause| {
            if first.is_none_or(|(best, _)| t < best) {
                first = Some((t, cause));
            }
        };
        for (index, obstacle) in self.obstacles().iter().enumerate() {
            if let Some(interval) = box_interval(&obstacle.center, &obstacle.widths, a, b)
                && let Some(t) = uncovered(interval, &free)
            {
                note(t, SegmentCause::Obstacle(index));
            }
        }
        for index in 0..self.lattices().len() {
            for interval in lattice_intervals(self, index, a, b) {
                if let Some(t) = uncovered(interval, &free) {
                    note(t, SegmentCause::Lattice(index));
                    break;
                }
            }
        }
        match first {
            Some((t, cause)) => SegmentVerdict::Invalid { t, cause },
            None => SegmentVerdict::Valid,
        }
    }

    /// The first parameter where the segment is outside the bounds, if any (the box is convex:
    /// the segment stays inside iff both ends do).
    fn leaves_bounds(&self, a: &[f64], b: &[f64]) -> Option<f64> {
        let inside = |x: &[f64]| {
            x.iter()
                .zip(self.lower().iter().zip(self.upper()))
                .all(|(&v, (&lo, &hi))| v >= lo && v <= hi)
        };
        if !inside(a) {
            return Some(0.0);
        }
        if inside(b) {
            return None;
        }
        // Leaves at the smallest exit parameter over the coordinates.
        let mut exit = 1.0_f64;
        for (d, (&lo, &hi)) in self.lower().iter().zip(self.upper()).enumerate() {
            let delta = b[d] - a[d];
            if b[d] > hi && delta > 0.0 {
                exit = exit.min((hi - a[d]) / delta);
            } else if b[d] < lo && delta < 0.0 {
                exit = exit.min((lo - a[d]) / delta);
            }
        }
        Some(exit.clamp(0.0, 1.0))
    }
}

/// The closed parameter interval where `x(t)` lies in `[lo, hi]` along one coordinate, within
/// `[0, 1]` (`None` if empty).
#[inline]
fn slab(a: f64, b: f64, lo: f64, hi: f64) -> Option<Interval> {
    let delta = b - a;
    if delta == 0.0 {
        return (a >= lo && a <= hi).then_some((0.0, 1.0));
    }
    let (mut t0, mut t1) = ((lo - a) / delta, (hi - a) / delta);
    if t0 > t1 {
        std::mem::swap(&mut t0, &mut t1);
    }
    let (t0, t1) = (t0.max(0.0), t1.min(1.0));
    (t0 <= t1).then_some((t0, t1))
}

/// The closed parameter interval inside the box `center ± (widths/2 + ε)` (the world's
/// membership rule), `None` if the segment misses it.
fn box_interval(center: &[f64], widths: &[f64], a: &[f64], b: &[f64]) -> Option<Interval> {
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (d, (&c, &w)) in center.iter().zip(widths).enumerate() {
        let half = 0.5 * w + f64::EPSILON;
        let (s0, s1) = slab(a[d], b[d], c - half, c + half)?;
        t0 = t0.max(s0);
        t1 = t1.min(s1);
        if t0 > t1 {
            return None;
        }
    }
    Some((t0, t1))
}

/// Sorts closed intervals and merges those that overlap or touch.
fn merged(mut intervals: Vec<Interval>) -> Vec<Interval> {
    intervals.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut out: Vec<Interval> = Vec::with_capacity(intervals.len());
    for (s, e) in intervals {
        match out.last_mut() {
            Some(last) if s <= last.1 => last.1 = last.1.max(e),
            _ => out.push((s, e)),
        }
    }
    out
}

/// The first parameter of `interval` that no interval of `free` (merged, disjoint, sorted)
/// covers, if any. Closed intervals: `[0.2, 0.5]` covers `[0.2, 0.5]`.
fn uncovered((s, e): Interval, free: &[Interval]) -> Option<f64> {
    // Merged intervals are disjoint with gaps between them, so one of them must cover it all.
    let covering = free.iter().find(|(u0, u1)| *u0 <= s && s <= *u1);
    match covering {
        Some(&(_, u1)) if u1 >= e => None,
        // Covered up to u1, then a gap: the sliver just after u1 is in the obstacle.
        Some(&(_, u1)) => Some(u1),
        None => Some(s),
    }
}

/// The parameter intervals where the segment is inside some cube of lattice `index`: the
/// lattice is a product `∏_d S_d` of unions of slabs, so the set is `∩_d T_d` with
/// `T_d = {t : x_d(t) ∈ S_d}`.
fn lattice_intervals(world: &World, index: usize, a: &[f64], b: &[f64]) -> Vec<Interval> {
    let lattice = &world.lattices()[index];
    if lattice.count == 0 {
        return Vec::new();
    }
    let half = 0.5 * lattice.side + f64::EPSILON;
    let mut result = vec![(0.0, 1.0)];
    for (d, &lower) in world.lower().iter().enumerate() {
        let (lo, hi) = (a[d].min(b[d]), a[d].max(b[d]));
        // Cubes j whose slab [c_j − h, c_j + h], c_j = lower + (j + 1)·spacing, meets [lo, hi].
        let first = ((lo - half - lower) / lattice.spacing - 1.0)
            .floor()
            .max(0.0);
        let last = ((hi + half - lower) / lattice.spacing - 1.0)
            .ceil()
            .min(lattice.count as f64 - 1.0);
        let mut slabs = Vec::new();
        let mut j = first;
        while j <= last {
            let c = lower + (j + 1.0) * lattice.spacing;
            if let Some(interval) = slab(a[d], b[d], c - half, c + half) {
                slabs.push(interval);
            }
            j += 1.0;
        }
        let slabs = merged(slabs);
        result = intersection(&result, &slabs);
        if result.is_empty() {
            break;
        }
    }
    result
}

/// The intersection of two sorted lists of disjoint closed intervals.
fn intersection(x: &[Interval], y: &[Interval]) -> Vec<Interval> {
    let (mut i, mut j, mut out) = (0, 0, Vec::new());
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
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{AxisBox, Lattice};

    fn square() -> World {
        World::new(vec![-0.5; 2], vec![0.5; 2])
    }

    #[test]
    fn covered_intervals_and_slivers() {
        let free = merged(vec![(0.4, 0.6), (0.1, 0.2), (0.2, 0.3)]);
        assert_eq!(free, vec![(0.1, 0.3), (0.4, 0.6)]);
        assert_eq!(uncovered((0.15, 0.3), &free), None);
        assert_eq!(uncovered((0.15, 0.35), &free), Some(0.3));
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
        assert_eq!(
            w.segment_verdict(&[0.0, 0.0], &[1.0, 0.0]),
            SegmentVerdict::Invalid {
                t: 0.5,
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
