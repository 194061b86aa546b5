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
//! touches it, and the next spacing is the smallest radius seen — so free space is crossed in one
//! or two batches whatever the edge's length, and the pieces shrink only where the edge passes
//! close to something. A configuration whose clearance is below [`FLOOR`] (in contact, or within a
//! hair of it) makes the edge invalid.
//!
//! The prefix and `w` are the whole state of the walk: a stopped certification keeps them in
//! the caller's [`MotionProgress`] and the next call goes on from there.

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
const USEFUL: f64 = 2.5;

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
const SPACING: f64 = 0.9;

/// Batches between two polls of the stop condition (a batch is eight or sixteen
/// configurations: about the [`STOP_POLL`](mit_star_validity::STOP_POLL) state checks the grid walks poll
/// after, or twice that).
const POLL_BATCHES: u32 = 4;

/// Buffers of the walk, per clone of the checker.
#[derive(Debug)]
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
}

impl CertifyScratch {
    pub(crate) fn new(dimension: usize, links: usize, pairs: usize) -> Self {
        Self {
            delta: vec![0.0; dimension],
            sweep: vec![0.0; links],
            pair_sweep: vec![0.0; pairs],
            terms: EdgeTerms::default(),
        }
    }
}

impl Clone for CertifyScratch {
    /// New buffers of the same sizes, as [`new`](Self::new) makes them: every walk writes
    /// what it reads, so the contents are not worth copying.
    fn clone(&self) -> Self {
        Self::new(self.delta.len(), self.sweep.len(), self.pair_sweep.len())
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
        let Scratch { lanes, certify } = &mut *guard;
        let CertifyScratch {
            delta,
            sweep,
            pair_sweep,
            terms,
        } = certify;
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
                return Some(EdgeStatus::Unknown);
            }
            batches += 1;
            // Configurations at `t + w`, `t + 3w`, …, the last one at the edge's end at the
            // latest.
            let mut count = 0;
            let mut middles = [0.0_f64; LANES];
            for (l, middle) in middles.iter_mut().enumerate() {
                *middle = (t + (2 * l + 1) as f64 * w).min(1.0);
                count += 1;
                if *middle + w >= 1.0 {
                    break;
                }
            }
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
            let reaches_end = middles[count - 1] + w >= 1.0;
            let useful = (if reaches_end { FINAL_USEFUL } else { USEFUL } * w).min(1.0);
            let (radii, refused) =
                certified_radii(s, lanes, (count, outside), &edge, terms, (FLOOR, useful));
            if refused != 0 {
                *progress = progress.advanced(t, w);
                return Some(EdgeStatus::Invalid);
            }
            // The prefix runs on through every piece that reaches it; the next spacing is the
            // smallest radius met on the way.
            let mut next = 1.0_f64;
            for (&middle, &radius) in middles.iter().zip(&radii).take(count) {
                next = next.min(radius);
                if middle - radius > t {
                    break;
                }
                t = t.max(middle + radius);
            }
            // A little less, so that the next batch's first piece reaches the prefix even
            // where the clearance stays as it is (an equal spacing can miss it by rounding).
            w = next * SPACING;
        }
    }
}
