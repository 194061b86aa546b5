//! Exact certification of a straight motion against a box [`World`] that polls its stop
//! condition in proportion to its work and goes on where a stop left it
//! ([`World::certify_exact`]).
//!
//! [`World::segment_verdict`] decides a segment in one go: two passes (the computed points
//! `a + (b − a)·t`, then `b + (a − b)·s`), each over every box of the world — the bounds, the
//! anti-obstacles (their intervals of fractions, merged), the obstacles (each interval covered
//! by the anti-obstacles' or not) and the lattices (one coordinate at a time). In a world of
//! 10⁵ boxes that is milliseconds, far more than one poll period, and a planner certifying an
//! edge could not stop in time. A certification does the same work in steps, counts it in
//! units (a box compared with the segment's reach is one, an exact crossing
//! [`CROSSING_UNITS`], a lattice slab [`SLAB_UNITS`]) and polls the stop every
//! [`POLL_UNITS`]. Where the walk stands (the pass, the stage, the next box) and what it found
//! so far (the anti-obstacles' intervals, a lattice's intersection) stay in the scratch
//! [`Segment`] the caller keeps, and the units done in the progress's cursor, so a stopped
//! certification of the same motion with the same scratch goes on where it stopped.
//!
//! The answer is the verdict's whatever the stops: the same intervals and the same coverage
//! tests, in the same passes (only the first invalid fraction is not sought). Once the
//! scratch's buffers have grown to the world, a certification allocates nothing.

use mit_star_spaces::Stop;

use crate::box_world::segment_validation::{
    FRACTIONS, Interval, crossed_interval, intersect_into, lattice_cubes, lattice_slab,
    leaves_bounds, meets_reach, merge_in_place, uncovered,
};
use crate::{EdgeStatus, MotionProgress, Segment, World};

/// Work units a certification does between two polls of the stop condition. A unit is one box
/// compared with the segment's reach (at most `2n` comparisons, a few nanoseconds), so this is
/// a few microseconds of work: about the time of [`STOP_POLL`](crate::STOP_POLL) state checks,
/// as [`StateValidity::certify_motion`](crate::StateValidity::certify_motion) asks, and far
/// more than one read of the clock.
pub(crate) const POLL_UNITS: u64 = 512;

/// Units of one exact crossing of a box (a slab test and a search of the floats along every
/// coordinate).
pub(crate) const CROSSING_UNITS: u64 = 32;

/// Units of one lattice slab (a slab test and a search along one coordinate).
pub(crate) const SLAB_UNITS: u64 = 8;

/// Where an exact certification stands, kept in the caller's scratch [`Segment`] between the
/// calls that certify one motion.
#[derive(Debug, Clone, Default)]
pub(crate) struct ExactCertification {
    /// The motion's ends, `a` then `b` (empty: no certification under way).
    ends: Vec<f64>,
    /// Units done so far: the cursor the progress of a resumed call carries.
    done: u64,
    /// `false`: the points `a + (b − a)·t`; `true`: the points `b + (a − b)·s`.
    second_pass: bool,
    /// The step of the pass.
    stage: Stage,
    /// The world's bounds as a row.
    bounds: Vec<f64>,
    /// The anti-obstacles' intervals of this pass (merged once all are found).
    free: Vec<Interval>,
    /// A lattice's intervals: the intersection over the coordinates done so far.
    lattice: Vec<Interval>,
    /// The slabs of the current coordinate of a lattice.
    slabs: Vec<Interval>,
    /// Room for the next intersection.
    spare: Vec<Interval>,
}

/// The steps of one pass, in order.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
enum Stage {
    /// The bounds.
    #[default]
    Bounds,
    /// The anti-obstacles, from this index on.
    Anti(usize),
    /// The obstacles, from this index on.
    Obstacles(usize),
    /// Lattice `index`, coordinate `d`, from cube `next` on (`None`: the coordinate is not
    /// begun).
    Lattice {
        index: usize,
        d: usize,
        next: Option<f64>,
    },
}

/// How a run of steps ended.
enum Steps {
    /// The budget is spent; this many units were done.
    Worked(u64),
    /// Both passes are done: every computed point is valid.
    Valid,
    /// A computed point is invalid.
    Invalid,
}

impl ExactCertification {
    /// `true` if this scratch holds a certification of `a → b` stopped where `progress` says.
    fn resumes(&self, (a, b): (&[f64], &[f64]), progress: &MotionProgress) -> bool {
        self.done > 0
            && progress.cursor() == self.done as f64
            && self.ends.len() == a.len() + b.len()
            && self
                .ends
                .iter()
                .zip(a.iter().chain(b))
                .all(|(x, y)| x.to_bits() == y.to_bits())
    }

    /// Begins a certification of `a → b`.
    fn begin(&mut self, (a, b): (&[f64], &[f64])) {
        self.ends.clear();
        self.ends.extend(a.iter().chain(b));
        self.done = 0;
        self.second_pass = false;
        self.stage = Stage::Bounds;
        self.free.clear();
    }

    /// Forgets the certification (it is decided).
    fn finish(&mut self) {
        self.ends.clear();
        self.done = 0;
    }
}

impl World {
    /// Certifies the straight motion `a → b` exactly (every computed point of both
    /// parametrizations valid: [`segment_verdict`](Self::segment_verdict)'s answer), polling
    /// `stop` before any work and after every [`POLL_UNITS`] units of it.
    ///
    /// `Unknown` if the stop fired: `scratch` keeps where the certification stands and
    /// `progress` its cursor, and a later call with the same motion, scratch and progress goes
    /// on from there (any other call starts over). Counts one evaluation per certification
    /// begun.
    pub(crate) fn certify_exact(
        &self,
        ends: (&[f64], &[f64]),
        scratch: &mut Segment,
        progress: &mut MotionProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus {
        if progress.is_complete() {
            return EdgeStatus::Valid;
        }
        if stop.should_stop() {
            return EdgeStatus::Unknown;
        }
        let mut exact = std::mem::take(&mut scratch.exact);
        let status = self.certify_in_steps(ends, scratch, &mut exact, progress, stop);
        scratch.exact = exact;
        status
    }

    fn certify_in_steps(
        &self,
        (a, b): (&[f64], &[f64]),
        segment: &mut Segment,
        exact: &mut ExactCertification,
        progress: &mut MotionProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus {
        if !exact.resumes((a, b), progress) {
            progress.count(1);
            let n = self.dimension();
            if a.len() != n || b.len() != n || a.iter().chain(b).any(|x| !x.is_finite()) {
                exact.finish();
                return EdgeStatus::Invalid;
            }
            exact.begin((a, b));
            self.bounds_row(&mut exact.bounds);
        }
        if exact.second_pass {
            segment.set(b, a);
        } else {
            segment.set(a, b);
        }
        if !segment.is_finite() {
            exact.finish();
            return EdgeStatus::Invalid;
        }
        loop {
            match self.steps(segment, exact, (a, b), POLL_UNITS) {
                Steps::Valid => {
                    exact.finish();
                    *progress = progress.advanced(1.0, 0.0);
                    return EdgeStatus::Valid;
                }
                Steps::Invalid => {
                    exact.finish();
                    return EdgeStatus::Invalid;
                }
                Steps::Worked(units) => {
                    exact.done += units;
                    if stop.should_stop() {
                        *progress = progress.advanced(0.0, exact.done as f64);
                        return EdgeStatus::Unknown;
                    }
                }
            }
        }
    }

    /// Goes on with the certification in `exact` (its pass set in `segment`) until it is
    /// decided or at least `budget` units are done.
    fn steps(
        &self,
        segment: &mut Segment,
        exact: &mut ExactCertification,
        (a, b): (&[f64], &[f64]),
        budget: u64,
    ) -> Steps {
        let width = 2 * self.dimension();
        let mut units = 0;
        loop {
            if units >= budget {
                return Steps::Worked(units);
            }
            match exact.stage {
                Stage::Bounds => {
                    units += CROSSING_UNITS;
                    if leaves_bounds(segment, &exact.bounds).is_some() {
                        return Steps::Invalid;
                    }
                    exact.free.clear();
                    exact.stage = Stage::Anti(0);
                }
                Stage::Anti(first) => {
                    let rows = self.anti_obstacles.rows();
                    let count = rows.len().checked_div(width).unwrap_or(0);
                    let mut i = first;
                    while i < count && units < budget {
                        let row = &rows[i * width..(i + 1) * width];
                        units += 1;
                        if meets_reach(segment, row) {
                            units += CROSSING_UNITS;
                            exact.free.extend(crossed_interval(segment, row));
                        }
                        i += 1;
                    }
                    if i < count {
                        exact.stage = Stage::Anti(i);
                        continue;
                    }
                    units += exact.free.len() as u64;
                    merge_in_place(&mut exact.free);
                    exact.stage = Stage::Obstacles(0);
                }
                Stage::Obstacles(first) => {
                    let rows = self.obstacles.rows();
                    let count = rows.len().checked_div(width).unwrap_or(0);
                    let mut i = first;
                    while i < count && units < budget {
                        let row = &rows[i * width..(i + 1) * width];
                        units += 1;
                        if meets_reach(segment, row) {
                            units += CROSSING_UNITS;
                            if let Some(interval) = crossed_interval(segment, row)
                                && uncovered(interval, &exact.free).is_some()
                            {
                                return Steps::Invalid;
                            }
                        }
                        i += 1;
                    }
                    exact.stage = if i < count {
                        Stage::Obstacles(i)
                    } else {
                        Stage::Lattice {
                            index: 0,
                            d: 0,
                            next: None,
                        }
                    };
                }
                Stage::Lattice { index, d, next } => {
                    let Some(lattice) = self.lattices.get(index) else {
                        // The pass is over.
                        if exact.second_pass {
                            return Steps::Valid;
                        }
                        exact.second_pass = true;
                        segment.set(b, a);
                        exact.stage = Stage::Bounds;
                        continue;
                    };
                    let following = Stage::Lattice {
                        index: index + 1,
                        d: 0,
                        next: None,
                    };
                    if lattice.count == 0 {
                        exact.stage = following;
                        continue;
                    }
                    if d == 0 && next.is_none() {
                        exact.lattice.clear();
                        exact.lattice.push((FRACTIONS[0], FRACTIONS[1]));
                    }
                    if d == self.dimension() {
                        units += exact.lattice.len() as u64;
                        let free = &exact.free;
                        if exact.lattice.iter().any(|&i| uncovered(i, free).is_some()) {
                            return Steps::Invalid;
                        }
                        exact.stage = following;
                        continue;
                    }
                    let (first, last) = lattice_cubes(self, lattice, segment, d);
                    let mut j = next.unwrap_or_else(|| {
                        exact.slabs.clear();
                        first
                    });
                    while j <= last && units < budget {
                        units += SLAB_UNITS;
                        exact
                            .slabs
                            .extend(lattice_slab(self, lattice, segment, d, j));
                        j += 1.0;
                    }
                    if j <= last {
                        exact.stage = Stage::Lattice {
                            index,
                            d,
                            next: Some(j),
                        };
                        continue;
                    }
                    units += exact.slabs.len() as u64;
                    merge_in_place(&mut exact.slabs);
                    intersect_into(&exact.lattice, &exact.slabs, &mut exact.spare);
                    std::mem::swap(&mut exact.lattice, &mut exact.spare);
                    exact.stage = if exact.lattice.is_empty() {
                        following
                    } else {
                        Stage::Lattice {
                            index,
                            d: d + 1,
                            next: None,
                        }
                    };
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use mit_star_spaces::{Never, RealVectorSpace};

    use super::*;
    use crate::{AxisBox, GridWalker, Lattice, StateValidity};

    /// The scratch's buffers, by address and capacity.
    fn buffers(e: &ExactCertification) -> Vec<(usize, usize)> {
        let lists = [&e.free, &e.lattice, &e.slabs, &e.spare];
        let mut out: Vec<(usize, usize)> = lists
            .iter()
            .map(|v| (v.as_ptr() as usize, v.capacity()))
            .collect();
        out.push((e.ends.as_ptr() as usize, e.ends.capacity()));
        out.push((e.bounds.as_ptr() as usize, e.bounds.capacity()));
        // `lattice` and `spare` swap places: compare them as a set.
        out.sort_unstable();
        out
    }

    #[test]
    fn certifying_reuses_the_scratch_once_it_has_grown() {
        let mut world = World::new(vec![-0.5; 3], vec![0.5; 3]);
        let mut seed = 11_u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (seed >> 11) as f64 / (1_u64 << 53) as f64 - 0.5
        };
        for k in 0..600 {
            let c = vec![next(), next(), next()];
            let b = AxisBox::cube(c, 0.05 + 0.05 * (next() + 0.5));
            if k % 10 == 0 {
                world.add_anti_obstacle(b).unwrap();
            } else {
                world.add_obstacle(b).unwrap();
            }
        }
        let world = world
            .with_lattice(Lattice {
                count: 30,
                spacing: 1.0 / 31.0,
                side: 0.004,
            })
            .unwrap();
        let space = RealVectorSpace::cube(3, -0.5, 0.5).unwrap();
        let edges: Vec<[f64; 6]> = (0..300)
            .map(|_| [next(), next(), next(), next(), next(), next()])
            .collect();
        let mut walker = GridWalker::new(0.01).unwrap();
        let mut scratch = Segment::default();
        let mut certify = |scratch: &mut Segment| {
            let mut valid = 0;
            for e in &edges {
                let mut progress = MotionProgress::default();
                let status = world
                    .certify_motion_in(&space, (&e[..3], &e[3..]), scratch, &mut progress, &Never)
                    .unwrap();
                // The walker's answer is the same.
                let walked = walker.certify(&space, &world, (&e[..3], &e[3..]), 2, &Never);
                assert_eq!(status, walked);
                valid += u32::from(status == EdgeStatus::Valid);
            }
            valid
        };
        let valid = certify(&mut scratch);
        assert!(valid > 0 && valid < 300, "{valid}");
        let grown = buffers(&scratch.exact);
        certify(&mut scratch);
        assert_eq!(
            buffers(&scratch.exact),
            grown,
            "the scratch was reallocated"
        );
    }
}
