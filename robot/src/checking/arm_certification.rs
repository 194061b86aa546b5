//! Certified motion for arms: proving every configuration of an edge collision-free, not only
//! its grid points ([`ArmChecker`]'s [`StateValidity::certify_motion`]).
//!
//! # The guarantee
//! An arm edge certified valid has **every** configuration on it collision-free: for each
//! piece of the edge, every sphere, grown by how far it can move within the piece (the
//! [`LeverArms`](crate::LeverArms) bound) and by the checker's margin for `f32` rounding, was
//! found clear of the scene and of the other links at the piece's middle configuration.
//!
//! # The walk
//! From the edge's first end, eight consecutive pieces of width `w` (a fraction of the edge)
//! are tested at once, one per `f32x8` lane, each lane's spheres grown by the margin plus how
//! far they can move within half a piece: the smaller of the lever-arm bound
//! `w/2 · Σ_j λ_j |Δq_j|` and the local bound measured at the piece's middle configuration
//! ([`LocalSweep`](crate::checking::local_sweep::LocalSweep)). If all eight are clear, the certified
//! prefix moves past them and `w` grows (by 1/16 near obstacles; doubling once four times as
//! wide as the first pieces: free space); if a piece is not, the prefix moves up to it and the next batch tests pieces
//! half as wide. The first pieces sweep about a centimetre. A piece whose growth is already below [`FLOOR`] and still
//! touches something is a contact (or within a hair of one): the edge is invalid. So free
//! space is certified in a few batches whatever the edge's length — the first batch tests
//! the whole edge as eight pieces — and the walk only refines near obstacles.
//!
//! The prefix and `w` are the whole state of the walk: a stopped certification keeps them in
//! the caller's [`MotionProgress`] and the next call goes on from there.

use spaces::{StateSpace, Stop, wrap_angle};
use validity::{EdgeStatus, MotionProgress};
use wide::f32x8;

use crate::ArmChecker;
use crate::checking::arm_checker::{Growth, Scratch, Wanted, invalid_lanes};
use crate::checking::lanes::LANES;
use crate::checking::local_sweep::EdgeTerms;

/// The smallest growth beyond the margin, in metres, at which a piece that still touches
/// something makes the edge invalid: 10 µm. An edge that passes closer than about this (plus
/// the margin) to an obstacle may be refused; none that touches one is accepted.
pub const FLOOR: f64 = 1e-5;

/// How far (metres) a sphere may sweep over half a piece of an edge's first batch: about the
/// clearance a solution edge keeps near obstacles, so that most first batches pass
/// (measured on MotionBenchMaker solution edges, `examples/certification_cost.rs`).
const FIRST_SWEEP: f64 = 0.01;

/// How much wider the pieces of the next batch are after a clear batch, while they are less
/// than four times as wide as the first pieces (near obstacles); wider, they double.
const GROWTH: f64 = 1.0625;

/// How much narrower the pieces become after a batch with a piece that is not clear.
const SHRINK: f64 = 2.0;

/// Batches between two polls of the stop condition (a batch is eight configurations: about
/// the [`STOP_POLL`](validity::STOP_POLL) state checks the grid walks poll after).
const POLL_BATCHES: u32 = 4;

/// Buffers of the walk, per clone of the checker.
#[derive(Debug, Clone)]
pub(crate) struct CertifyScratch {
    /// The middle configurations of a batch's pieces.
    chunk: Vec<f64>,
    /// The edge's joint displacements (the short way round for wrapping joints).
    delta: Vec<f64>,
    /// Per link with spheres: how far its spheres move over the whole edge.
    sweep: Vec<f64>,
    /// Per link with spheres: the growth in each lane.
    grow: Vec<f32x8>,
    /// The edge's terms of the local sweep bound.
    terms: EdgeTerms,
}

impl CertifyScratch {
    pub(crate) fn new(dimension: usize, links: usize) -> Self {
        Self {
            chunk: vec![0.0; LANES * dimension],
            delta: vec![0.0; dimension],
            sweep: vec![0.0; links],
            grow: vec![f32x8::ZERO; links],
            terms: EdgeTerms::default(),
        }
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
            chunk,
            delta,
            sweep,
            grow,
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
        let fastest = sweep.iter().copied().fold(0.0, f64::max);
        s.local.edge_terms(delta, &s.levers, terms);
        let (mut t, mut w) = (progress.certified(), progress.cursor());
        // First pieces: sweeping at most `FIRST_SWEEP` over a half piece, at most an eighth of
        // the edge.
        let first = (2.0 * FIRST_SWEEP / fastest.max(1e-12)).min(1.0 / LANES as f64);
        if !(w > 0.0 && w <= 1.0) {
            w = first;
        }
        let mut batches = 0_u32;
        loop {
            if t >= 1.0 {
                *progress = progress.advanced(1.0, w);
                return Some(EdgeStatus::Valid);
            }
            if batches % POLL_BATCHES == 0 && stop.should_stop() {
                *progress = progress.advanced(t, w);
                return Some(EdgeStatus::Unknown);
            }
            batches += 1;
            // Pieces `[t + l·w, t + (l + 1)·w]`, cut at the end of the edge; the same
            // expression gives a piece's end and the next one's start, so none is skipped.
            let mut count = 0;
            let mut halves = [0.0_f64; LANES];
            for (l, half) in halves.iter_mut().enumerate() {
                let t0 = t + l as f64 * w;
                if t0 >= 1.0 {
                    break;
                }
                let t1 = (t + (l + 1) as f64 * w).min(1.0);
                let middle = 0.5 * (t0 + t1);
                *half = 0.5 * (t1 - t0);
                let q = &mut chunk[l * n..(l + 1) * n];
                for (j, x) in q.iter_mut().enumerate() {
                    let v = a[j] + delta[j] * middle;
                    *x = if s.wraps[j] { wrap_angle(v) } else { v };
                }
                count += 1;
            }
            progress.count(count as u64);
            let place = |poses: &[_], bounds: &[_], out: &mut [f32x8]| {
                s.local
                    .grow(poses, bounds, (delta, terms), &halves, s.margin, sweep, out);
            };
            let growth = Growth::Placed(grow, &place);
            let invalid = invalid_lanes(s, lanes, (&chunk[..count * n], n), growth, Wanted::First);
            if invalid == 0 {
                t = (t + count as f64 * w).min(1.0);
                w = (if w >= 4.0 * first { 2.0 } else { GROWTH } * w).min(1.0);
                continue;
            }
            let first = invalid.trailing_zeros();
            let failed_half = halves[first as usize];
            t += f64::from(first) * w;
            if fastest * failed_half <= FLOOR {
                *progress = progress.advanced(t, w);
                return Some(EdgeStatus::Invalid);
            }
            w /= SHRINK;
        }
    }
}
