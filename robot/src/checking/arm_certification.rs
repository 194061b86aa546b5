//! Certified motion for arms: proving every configuration of an edge collision-free, not only
//! its grid points ([`ArmChecker`]'s
//! [`StateValidity::certify_motion`](mit_star_validity::StateValidity::certify_motion)).
//!
//! # The guarantee
//! An arm edge certified valid has **every** configuration on it collision-free: the edge is
//! covered by pieces, and for each piece every sphere, grown by how far it can move within the
//! piece (the local sweep and [`LeverArms`](crate::LeverArms) bounds) and by the checker's
//! margin for `f32` rounding, is clear of the scene and of the other links at the piece's
//! middle configuration — and, grown by the user's [padding](crate::Padding) too, clear of
//! the scene: a padded checker's certified edges keep the padding at every configuration.
//!
//! # The walk
//! Conservative advancement along the edge from its first end. Each batch evaluates a lane's worth
//! ([`LANES`]: eight, or sixteen with AVX-512) of configurations ahead of the certified prefix `t`,
//! spaced `2w` apart (`t + w`, `t + 3w`, …); each lane's clearance gives its *certified radius*
//! (`clearance.rs`): how far along the edge the configuration can move before any sphere could
//! reach an obstacle or another link. The prefix then runs on through every lane whose piece
//! touches it, and the next spacing is the smallest radius seen up to the first gap — so free
//! space is crossed in one or two batches whatever the edge's length, and the pieces shrink only
//! where the edge passes close to something. A configuration whose clearance is below [`FLOOR`]
//! (in contact, or within a hair of it) makes the edge invalid.
//!
//! The pieces beyond a gap are kept: the next batches fill the gap and step over them. Where an
//! edge passes close to something in one place, the batch that finds the narrow place has
//! certified most of the rest of the edge already; walking over those pieces again was most of
//! certification's work among point clouds (the figures are in the guide's point-clouds page).
//!
//! A stopped certification keeps the prefix and `w` in the caller's [`MotionProgress`], and
//! the pieces beyond in the checker's scratch: the next call for the same motion and progress
//! goes on from there (another checker, or a call for another motion in between, recomputes
//! the pieces beyond the prefix).

use mit_star_spaces::{StateSpace, Stop, wrap_angle};
use mit_star_validity::{EdgeStatus, MotionProgress};

use crate::ArmChecker;
use crate::checking::arm_checker::{Coordinate, Scratch, fill_on_line};
use crate::checking::clearance::{EdgeBounds, certified_radii};
use crate::checking::lanes::LANES;
use crate::checking::local_sweep::EdgeTerms;

/// The smallest clearance beyond the margin, in metres, of a configuration of a valid edge:
/// 10 µm. An edge that passes closer than this (plus the margin) to an obstacle or to another
/// link is refused; none that touches one is accepted.
pub const FLOOR: f64 = 1e-5;

/// How far (metres) the fastest sphere may sweep over half a piece of an edge's first batch:
/// 10 cm, so that on most edges the first batch's pieces spread over the whole edge (they are
/// never wider than `1 / LANES` of it): a clear edge is certified in a batch or two, and an
/// edge near obstacles learns its clearances all along it at once. Measured on the Panda's
/// MotionBenchMaker problems against 1 and 3 cm (callgrind instruction counts of RRT-Connect's
/// and MIT*'s solves: 2–3 % fewer for RRT-Connect, a fifth fewer per certified edge for MIT*).
const FIRST_SWEEP: f64 = 0.1;

/// The widest piece a batch seeks, in spacings `w`: limits how far clearances are sought, and
/// so how much of the scene each batch looks at. A wide piece lets the next spacing grow.
/// With [`SPACING`], chosen with the pieces beyond gaps kept by callgrind counts of
/// RRT-Connect's solves among the Panda's point clouds (a scan of both; the guide's
/// point-clouds page has the counts of the change as a whole).
const USEFUL: f64 = 2.0;

/// The widest piece sought by a batch whose pieces reach the edge's end, in spacings `w`.
/// Such a batch finishes the edge if every piece is at least `w` wide, and if one is not, the
/// next spacing is set by that narrower piece: a piece wider than `w` only helps where it
/// covers for a narrow neighbour, so clearances are sought only a little beyond `w` (the
/// margin is for the radii's rounding down). Every edge ends with such a batch, and many are
/// certified by it alone. On the Panda's problems this takes 16 % of certification's
/// instructions off RRT-Connect and 12 % off MIT*, for 0.7 % more batches (callgrind, measured
/// with the commit that brought this rule; the arm-planning reference, "Certified arm motion",
/// describes the batches).
const FINAL_USEFUL: f64 = 1.1;

/// The next spacing's share of the smallest radius met.
const SPACING: f64 = 0.7;

// A batch's radii are at most `USEFUL · w`, and the next spacing is `SPACING` times the
// smallest: with a product near 1 the spacing would shrink batch after batch on a clear edge
// (0.6 and 1.5 took thirteen times the instructions).
const _: () = assert!(SPACING * USEFUL >= 1.25);

/// Batches between two polls of the stop condition (a batch is eight or sixteen
/// configurations: about the [`STOP_POLL`](mit_star_validity::STOP_POLL) state checks the grid walks poll
/// after, or twice that).
const POLL_BATCHES: u32 = 4;

/// Buffers of the walk, per clone of the checker.
#[derive(Debug, Default)]
pub(crate) struct CertifyScratch {
    /// The edge's joint displacements (the short way round for wrapping joints).
    delta: Vec<f64>,
    /// Per link with spheres: how far its spheres move over the whole edge.
    sweep: Vec<f64>,
    /// Per self-collision pair: how far its links move relative to each other over the
    /// whole edge.
    pair_sweep: Vec<f64>,
    /// The edge's terms of the local sweep bound.
    terms: EdgeTerms,
    /// Pieces certified beyond the prefix, `(start, end)` as fractions of the edge: sorted,
    /// disjoint, none reaching the prefix.
    ahead: Vec<(f64, f64)>,
    /// After a stop: the ends of the motion (`a` then `b`) whose pieces `ahead` holds.
    stopped_ends: Vec<f64>,
    /// After a stop: the prefix and spacing it left in the caller's progress, so that the
    /// next call for the same motion and progress goes on with `ahead` (and repeats no work).
    stopped_at: Option<(f64, f64)>,
}

impl CertifyScratch {
    pub(crate) fn new(dimension: usize, links: usize, pairs: usize) -> Self {
        Self {
            delta: vec![0.0; dimension],
            sweep: vec![0.0; links],
            pair_sweep: vec![0.0; pairs],
            terms: EdgeTerms::default(),
            ahead: Vec::with_capacity(2 * LANES),
            stopped_ends: vec![0.0; 2 * dimension],
            stopped_at: None,
        }
    }

    /// Forgets a stopped walk, so that no later call resumes it.
    pub(crate) fn forget_stop(&mut self) {
        self.stopped_at = None;
    }

    /// Marks a walk as stopped at `at` (tests).
    #[cfg(test)]
    pub(crate) fn stop_at_for_tests(&mut self, at: (f64, f64)) {
        self.stopped_at = Some(at);
    }

    /// Whether no buffer has room for anything (tests).
    #[cfg(test)]
    pub(crate) fn holds_nothing_for_tests(&self) -> bool {
        self.delta.capacity() == 0
            && self.sweep.capacity() == 0
            && self.pair_sweep.capacity() == 0
            && self.ahead.capacity() == 0
            && self.stopped_ends.capacity() == 0
    }

    /// Whether a stopped walk is kept (tests).
    #[cfg(test)]
    pub(crate) fn stopped_for_tests(&self) -> bool {
        self.stopped_at.is_some()
    }
}

impl ArmChecker {
    /// The walk of the [module docs](self): `None` for a space this checker's motions are
    /// not the motions of (another dimension, or straight lines where the robot has wrapping
    /// joints).
    pub(crate) fn certify(
        &self,
        space: &dyn StateSpace,
        (a, b): (&[f64], &[f64]),
        progress: &mut MotionProgress,
        stop: &dyn Stop,
    ) -> Option<EdgeStatus> {
        let s = &*self.shared;
        let n = s.lower.len();
        if space.dimension() != n || (space.is_euclidean() && s.wraps.iter().any(|&w| w)) {
            return None;
        }
        if a.len() != n || b.len() != n || a.iter().chain(b).any(|x| !x.is_finite()) {
            return Some(EdgeStatus::Invalid);
        }
        if progress.is_complete() {
            return Some(EdgeStatus::Valid);
        }
        let mut guard = self.scratch.lock();
        let Scratch { lanes, certify, .. } = &mut *guard;
        let CertifyScratch {
            delta,
            sweep,
            pair_sweep,
            terms,
            ahead,
            stopped_ends,
            stopped_at,
        } = certify;
        let resumes = stopped_at.take() == Some((progress.certified(), progress.cursor()))
            && stopped_ends[..n] == *a
            && stopped_ends[n..] == *b;
        if !resumes {
            ahead.clear();
        }
        for (j, d) in delta.iter_mut().enumerate() {
            *d = if s.wraps[j] {
                wrap_angle(b[j] - a[j])
            } else {
                b[j] - a[j]
            };
        }
        for (k, out) in sweep.iter_mut().enumerate() {
            let levers = &s.levers[k * n..(k + 1) * n];
            *out = levers.iter().zip(&*delta).map(|(l, d)| l * d.abs()).sum();
        }
        for (p, out) in pair_sweep.iter_mut().enumerate() {
            let levers = &s.pair_levers[p * n..(p + 1) * n];
            *out = levers.iter().zip(&*delta).map(|(l, d)| l * d.abs()).sum();
        }
        let fastest = sweep.iter().copied().fold(0.0, f64::max);
        // Each link's terms of the local sweep bound are computed when a batch first needs
        // them (a link far from everything never does).
        terms.reset(s.links.len());
        let edge = EdgeBounds {
            delta,
            sweep,
            pair_sweep,
        };
        let (mut t, mut w) = (progress.certified(), progress.cursor());
        // First pieces: the fastest sphere sweeping at most `FIRST_SWEEP` over a half piece,
        // a batch of them spanning at most the edge.
        if !(w > 0.0 && w <= 1.0) {
            w = (FIRST_SWEEP / fastest.max(1e-12)).min(0.5 / LANES as f64);
        }
        let mut batches = 0_u32;
        loop {
            if t >= 1.0 {
                *progress = progress.advanced(1.0, w);
                return Some(EdgeStatus::Valid);
            }
            if batches.is_multiple_of(POLL_BATCHES) && stop.should_stop() {
                *progress = progress.advanced(t, w);
                *stopped_at = Some((progress.certified(), progress.cursor()));
                stopped_ends[..n].copy_from_slice(a);
                stopped_ends[n..].copy_from_slice(b);
                return Some(EdgeStatus::Unknown);
            }
            batches += 1;
            // Configurations at `t + w`, `t + 3w`, …, over the pieces already certified, the
            // last one at the edge's end at the latest.
            let (middles, count, reaches_end) = place_batch(t, w, ahead);
            progress.count(count as u64);
            // Their joint values, kept between the ends, which rounding could leave by an ulp
            // (past a joint limit that an end sits on), or wrapped for a wrapping joint.
            let keep = |j: usize| {
                if s.wraps[j] {
                    Coordinate::Wrapped
                } else {
                    Coordinate::Between(a[j].min(b[j]), a[j].max(b[j]))
                }
            };
            let outside = fill_on_line(s, &mut lanes.lane_q, (a, delta), &middles[..count], keep);
            // No piece needs to reach further than the edge, and a batch's pieces need not be
            // more than `USEFUL` spacings wide, or `FINAL_USEFUL` if they reach its end.
            let useful = (if reaches_end { FINAL_USEFUL } else { USEFUL } * w).min(1.0);
            let (radii, refused) =
                certified_radii(s, lanes, (count, outside), &edge, terms, (FLOOR, useful));
            if refused != 0 {
                *progress = progress.advanced(t, w);
                return Some(EdgeStatus::Invalid);
            }
            // The prefix runs on through every piece that reaches it, the others are kept; the
            // next spacing is the smallest radius met up to the first gap.
            let pieces = middles.iter().zip(&radii).take(count);
            ahead.extend(pieces.clone().map(|(&m, &r)| (m - r, m + r)));
            t = absorb(t, ahead);
            let mut next = 1.0_f64;
            for (&middle, &radius) in pieces {
                next = next.min(radius);
                if middle - radius > t {
                    break;
                }
            }
            // A little less, so that the next batch's first piece reaches the prefix even
            // where the clearance stays as it is (an equal spacing can miss it by rounding).
            w = next * SPACING;
        }
    }
}

/// The middles of a batch's configurations after the prefix `t`, spaced `2w` apart and stepping
/// over the pieces `ahead` (sorted, none reaching `t`): each configuration's piece is assumed
/// `w` wide on either side. Returns them, their count (at least one, at most [`LANES`]) and
/// whether the assumed pieces and `ahead` reach the edge's end.
fn place_batch(t: f64, w: f64, ahead: &[(f64, f64)]) -> ([f64; LANES], usize, bool) {
    let mut middles = [0.0_f64; LANES];
    let (mut count, mut x, mut kept) = (0, t, ahead.iter().peekable());
    while count < LANES {
        while let Some(&&(start, end)) = kept.peek() {
            if start > x {
                break;
            }
            x = x.max(end);
            kept.next();
        }
        if x >= 1.0 && count > 0 {
            break;
        }
        let middle = (x + w).min(1.0);
        middles[count] = middle;
        count += 1;
        x = middle + w;
        if x >= 1.0 {
            break;
        }
    }
    (middles, count, x >= 1.0)
}

/// Sorts the pieces `ahead`, runs the prefix `t` on through every one that reaches it, merges
/// the overlapping ones among the rest and keeps those; returns the new prefix. Every
/// configuration up to the new prefix, and in every piece kept, lies in a piece given.
fn absorb(mut t: f64, ahead: &mut Vec<(f64, f64)>) -> f64 {
    ahead.sort_unstable_by(|p, q| p.0.total_cmp(&q.0));
    let mut kept = 0;
    for i in 0..ahead.len() {
        let (start, end) = ahead[i];
        // Once a piece is kept, none after it reaches the prefix: they start no earlier, and
        // the prefix has stopped growing.
        if kept == 0 && start <= t {
            t = t.max(end);
        } else if kept > 0 && start <= ahead[kept - 1].1 {
            ahead[kept - 1].1 = ahead[kept - 1].1.max(end);
        } else {
            ahead[kept] = (start, end);
            kept += 1;
        }
    }
    ahead.truncate(kept);
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_batch_steps_over_the_pieces_already_certified() {
        let (middles, count, end) = place_batch(0.0, 0.1, &[(0.15, 0.5)]);
        assert_eq!((count, end), (4, true));
        for (m, want) in middles.iter().zip([0.1, 0.6, 0.8, 1.0]) {
            assert!((m - want).abs() < 1e-12, "{middles:?}");
        }
        // Without pieces: equally spaced, the last at the end at the latest.
        let (middles, count, end) = place_batch(0.5, 0.1, &[]);
        assert_eq!((count, end), (3, true));
        assert!((middles[2] - 1.0).abs() < 1e-12);
        // Too far to reach the end in one batch.
        let (_, count, end) = place_batch(0.0, 0.001, &[]);
        assert_eq!((count, end), (LANES, false));
        // Pieces reaching the end leave one configuration to place.
        let (middles, count, end) = place_batch(0.2, 0.05, &[(0.22, 1.0)]);
        assert_eq!((count, end, middles[0]), (1, true, 0.25));
    }

    #[test]
    fn the_prefix_runs_through_the_pieces_that_reach_it_and_keeps_the_rest() {
        let mut ahead = vec![
            (0.6, 0.7),
            (0.05, 0.2),
            (0.65, 0.8),
            (0.3, 0.4),
            (0.15, 0.25),
        ];
        assert_eq!(absorb(0.1, &mut ahead), 0.25);
        assert_eq!(ahead, [(0.3, 0.4), (0.6, 0.8)]);
        // A gap filled joins everything after it.
        ahead.push((0.2, 0.35));
        ahead.push((0.38, 0.62));
        assert_eq!(absorb(0.25, &mut ahead), 0.8);
        assert!(ahead.is_empty());
    }
}
