//! Batched point checks of a box [`World`] along one prepared [`Segment`]: the per-edge broad
//! phase (keep only the boxes the edge crosses, each with the exact interval of fractions whose
//! points lie in it) and four points per SIMD step against those intervals (`wide`'s `f64x4`,
//! safe code).
//!
//! # Why the answers are unchanged
//! A point of the segment is computed as `a + (b − a)·t`, exactly as the space interpolates,
//! and every coordinate of every such point lies within the segment's reach (the interval
//! between the ends, widened by a bound on the rounding error; see [`Segment::set`]). A box
//! whose bounds do not meet the reach along some coordinate therefore contains no point of the
//! segment; dropping it changes no answer. A kept box's span (a slab test against the box
//! widened by that bound) contains every fraction whose point is in it, and within the span
//! the exact interval is found by searching the floats: each computed coordinate is monotone
//! in `t`, so the fractions inside the box are exactly `[τ₀, τ₁]`, and a lane's point is in
//! the box iff `τ₀ ≤ t ≤ τ₁`. A coordinate whose reach lies inside the world's bounds cannot
//! leave them; the others are tested with the scalar test's comparisons.
//! `validity/tests/world_segments.rs` checks this point by point for random worlds and edges,
//! at grid fractions and at the very floats where the answer changes.

use wide::f64x4;

use crate::box_world::box_set::BoxSet;
use crate::{Preparation, Segment, StateValidity, World};

/// Points per SIMD step.
const LANES: usize = 4;

/// Most boxes of each kind a prepared segment keeps: an edge that meets more (a long edge
/// through a dense world of thousands of boxes) is tested point by point through the
/// hierarchy instead.
const MOST_KEPT: usize = 64;

impl World {
    /// The per-edge broad phase: records in `segment` the coordinates along which it may leave
    /// the bounds and the crossings of the obstacles and anti-obstacles it crosses (candidates:
    /// the boxes whose bounds meet its reach). [`Preparation::AllValid`] if nothing is left
    /// that could make a point invalid.
    ///
    /// Costs one pass over the boxes, or a query of the hierarchy in worlds of more than
    /// [`TREE_THRESHOLD`](crate::TREE_THRESHOLD) boxes. Segments with non-finite coordinates,
    /// and segments that meet more than 64 boxes of a kind, are not prepared: their points are
    /// tested one by one.
    pub(crate) fn prepare(&self, segment: &mut Segment) -> Preparation {
        let n = self.dimension();
        if n == 0 || segment.dimension() != n || !segment.is_finite() {
            return Preparation::Unprepared;
        }
        for d in 0..n {
            let (lo, hi) = segment.reach(d);
            if lo < self.lower[d] || hi > self.upper[d] {
                segment.bound_coordinates.push(d);
            }
        }
        segment.lattices = self.lattices.iter().any(|l| l.count > 0);
        for anti in [false, true] {
            let set = if anti {
                &self.anti_obstacles
            } else {
                &self.obstacles
            };
            let Segment {
                reach, candidates, ..
            } = segment;
            if !keep_meeting(set, reach, candidates) {
                return Preparation::Unprepared;
            }
            segment.cross(anti);
            if !anti && segment.obstacle_crossings.is_empty() && !segment.lattices {
                // No obstacle to carve from: anti-obstacles cannot change an answer.
                return if segment.bound_coordinates.is_empty() {
                    Preparation::AllValid
                } else {
                    Preparation::Prepared
                };
            }
        }
        Preparation::Prepared
    }

    /// The first invalid point among the points at `fractions` of a segment this world
    /// prepared, four points per step: bounds along the coordinates the segment may leave, then
    /// the crossings of the kept obstacles, then — only for lanes inside an obstacle — those
    /// of the kept anti-obstacles.
    pub(crate) fn first_invalid_on_segment(
        &self,
        segment: &mut Segment,
        fractions: &[f64],
    ) -> Option<usize> {
        if segment.lattices {
            return segment.first_invalid_by(fractions, |state| self.is_valid(state));
        }
        let segment = &*segment;
        for (step, chunk) in fractions.chunks(LANES).enumerate() {
            let mut ts = [chunk[chunk.len() - 1]; LANES];
            ts[..chunk.len()].copy_from_slice(chunk);
            let t = f64x4::from(ts);
            let lanes = [
                ts.iter().copied().fold(f64::INFINITY, f64::min),
                ts.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            ];
            let mut invalid = f64x4::ZERO;
            for &d in &segment.bound_coordinates {
                let x = segment.lanes(d, t);
                let inside =
                    x.simd_ge(f64x4::splat(self.lower[d])) & x.simd_le(f64x4::splat(self.upper[d]));
                invalid |= !inside;
            }
            let hit = in_crossings(&segment.obstacle_crossings, t, lanes);
            if hit.any() {
                invalid |= hit & !in_crossings(&segment.anti_crossings, t, lanes);
            }
            let lanes = invalid.to_bitmask() & ((1 << chunk.len()) - 1);
            if lanes != 0 {
                return Some(step * LANES + lanes.trailing_zeros() as usize);
            }
        }
        None
    }
}

/// Lanes whose point lies in some box, given the boxes' crossings (exact fraction intervals):
/// all ones where inside, zero elsewhere. Crossings that miss the lanes' fractions (`[min,
/// max]` in `lanes`) are skipped.
#[inline]
fn in_crossings(crossings: &[[f64; 2]], t: f64x4, lanes: [f64; 2]) -> f64x4 {
    let mut inside_any = f64x4::ZERO;
    for &[t0, t1] in crossings {
        if t0 <= lanes[1] && t1 >= lanes[0] {
            inside_any |= t.simd_ge(f64x4::splat(t0)) & t.simd_le(f64x4::splat(t1));
        }
    }
    inside_any
}

/// Appends to `kept` the rows of `set` (`[lo, hi]` per coordinate) that meet `reach` (same
/// layout) along every coordinate: the slab index where it serves, else the hierarchy above
/// [`TREE_THRESHOLD`](crate::TREE_THRESHOLD) boxes, else a scan. `false` if more than [`MOST_KEPT`] boxes meet it.
fn keep_meeting(set: &BoxSet, reach: &[f64], kept: &mut Vec<f64>) -> bool {
    let width = reach.len();
    if let Some(slabs) = set.slabs(width / 2) {
        return slabs.collect_meeting(set.rows(), reach, kept, MOST_KEPT);
    }
    if let Some(tree) = set.hierarchy(width / 2) {
        return tree.collect_meeting(reach, kept, MOST_KEPT);
    }
    for row in set.rows().chunks_exact(width) {
        let meets = row
            .chunks_exact(2)
            .zip(reach.chunks_exact(2))
            .all(|(b, r)| b[0] <= r[1] && b[1] >= r[0]);
        if meets {
            kept.extend_from_slice(row);
        }
    }
    true
}
