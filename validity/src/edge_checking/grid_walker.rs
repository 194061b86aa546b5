//! The walk over an edge's canonical grid shared by every checker ([`GridWalker`]), the end it
//! starts from ([`canonical_ends`]) and how often it polls the stop condition ([`STOP_POLL`]).

use mit_star_spaces::{StateSpace, Stop};

use crate::{
    EdgeGrid, EdgeProgress, EdgeStatus, LengthBuckets, MotionProgress, Preparation, Segment,
    StateValidity, ValidityError,
};

/// Counters of edge-checking work, for benchmarks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct EdgeCounters {
    /// Sparse checks requested.
    pub sparse_checks: u64,
    /// Full checks requested.
    pub full_checks: u64,
    /// Grid points tested (state validity calls made by edge checks, certification included),
    /// counted up to and including the first invalid one, and counting the points the broad
    /// phase decided without a test ([`points_culled`](Self::points_culled)): the same number
    /// with acceleration on or off.
    pub points_tested: u64,
    /// Of those, the points decided valid without a test, because the validity checker's
    /// per-edge broad phase found nothing near the edge ([`Preparation::AllValid`]).
    pub points_culled: u64,
    /// Edges certified on a finer grid ([`GridWalker::certify`]), passed or not.
    pub certifications: u64,
    /// Certifications that found an invalid point the edge's own grid had missed.
    pub certification_failures: u64,
    /// Configurations evaluated by certifications: the finer grid's points, or the grown
    /// configurations of a motion certification ([`StateValidity::certify_motion`]).
    pub certification_points: u64,
    /// Sparse and full checks and their points, by edge length.
    pub by_length: LengthBuckets,
}

/// Walks an edge's canonical grid in bisection order, testing states; shared by every checker.
///
/// Owns the scratch the walk needs (allocated once, on first use), so checking an edge never
/// allocates. Polls the stop condition every [`STOP_POLL`] points, and before the first point
/// of a walk longer than that (see [`advance`](Self::advance)).
///
/// # Acceleration
/// Unless [turned off](Self::set_accelerated), a walk in a space whose edges are straight
/// lines first lets the validity checker [prepare](StateValidity::prepare_segment) the edge (a
/// box world keeps only the boxes near it; an arm's checker fills its lanes from the segment),
/// then hands it the fractions of up to [`STOP_POLL`] points at a time, or of one batch for a
/// checker with batches ([`StateValidity::any_invalid_on`]); an edge the checker
/// proves free is decided without testing a point. The answers, the progress and the points
/// counted are those of the one-by-one walk; off, every point is interpolated and tested on
/// its own, as OMPL's discrete motion validator does.
#[derive(Debug, Clone)]
pub struct GridWalker {
    step: f64,
    scratch: Vec<f64>,
    /// The fractions of one batch of points.
    batch: Vec<f64>,
    segment: Segment,
    accelerated: bool,
    /// An interrupted scan: the edge's ends (`a` then `b`, canonical order) and the first grid
    /// index not yet scanned (0: none). Every index below it was valid, so a later full check
    /// of the same edge resumes there instead of starting over (a scan longer than the time
    /// slices a planner is given would otherwise never finish).
    scan_edge: Vec<f64>,
    scan_next: u64,
    /// An interrupted certification: the edge's ends (canonical order; empty: none), how far
    /// a motion certification came, and how many new points a grid certification walked.
    certifying: Vec<f64>,
    certified_motion: MotionProgress,
    certified_points: u64,
    /// The scratch of motion certifications ([`StateValidity::certify_motion_in`]), apart
    /// from `segment` (which every walk resets): it keeps what an interrupted certification
    /// found until the same edge is certified again.
    motion_scratch: Segment,
    counters: EdgeCounters,
}

/// How many grid points a walk tests between two polls of the stop condition: small enough that
/// a slow validity checker (an arm with meshes, 100 µs a state) stops within a few
/// milliseconds, large enough that reading the clock costs little next to 32 state checks.
///
/// A walk of more than `STOP_POLL` points polls before its first point and after every
/// `STOP_POLL` points tested, so a walk begun after the stop fired tests nothing and a running
/// walk tests at most `STOP_POLL` points after it fires. A walk of at most `STOP_POLL` points
/// never polls (it is over before a poll would be due). A poll only ends a walk when the stop
/// has fired: a walk the stop lets run always tests at least one point.
///
/// A checker whose [`batch_width`](crate::StateValidity::batch_width) is wider than
/// `STOP_POLL` (a vectorised checker written in another language, where each call costs far
/// more than a state) is handed whole batches instead: the poll period is then its batch
/// width rounded up to a multiple of `STOP_POLL` (at most [`MAX_BATCH`]), and the rules above
/// hold with that period.
pub const STOP_POLL: u64 = 32;

/// The widest batch a walk hands a checker in one call, and so the longest poll period.
pub const MAX_BATCH: usize = 1024;

/// The poll period of a walk handing batches of `width` points: `width` rounded up to a
/// multiple of [`STOP_POLL`].
fn poll_period(width: usize) -> u64 {
    (width.clamp(1, MAX_BATCH) as u64).div_ceil(STOP_POLL) * STOP_POLL
}

/// The fraction, on the canonical grid whose far end is `v`, of the motion's end `b`: 1 if
/// `b` is that far end, else 0 (`b` is the canonical start).
fn end_fraction(v: &[f64], b: &[f64]) -> f64 {
    if std::ptr::eq(v, b) { 1.0 } else { 0.0 }
}

/// How many fractions of a prepared edge go to one call for a checker of batch `width`: its
/// batches when it has any (an arm's eight lanes: a call is then one batch, and a counting
/// wrapper counts the points the checker was handed, no more), else [`STOP_POLL`].
fn prepared_width(width: usize) -> usize {
    if width > 1 { width } else { STOP_POLL as usize }
}

/// Full checks of prepared edges with at least this many points left scan the grid in
/// ascending order after a head of bisection positions (see `GridWalker::advance_scanning`).
const SCAN_MIN: u64 = 512;

/// Bisection positions a scanning full check walks first: levels 1–8, which find any obstacle
/// wider than 1/256 of the edge.
const SCAN_HEAD: u64 = 255;

/// Points a scan tests between two polls of the stop condition: a prepared point costs a
/// nanosecond or two, so this keeps the clock reads rare and the polls microseconds apart.
const SCAN_POLL: u64 = 1024;

/// The edge `a — b` with its ends in canonical order: the lexicographically smaller state first
/// (coordinates compared with `f64::total_cmp`).
///
/// Every walk of an edge starts from this end, whichever end the caller named, so that a sparse
/// check from one end and a full check from the other test disjoint prefixes of *one* order of
/// *one* grid. (The bisection order is not symmetric under `i → N − i` unless `2^D` divides `N`:
/// walking from the other end would skip points never tested and repeat others.)
///
/// ```
/// let (a, b) = ([0.5, 0.0], [0.1, 0.9]);
/// assert_eq!(mit_star_validity::canonical_ends(&a, &b), (&b[..], &a[..]));
/// assert_eq!(mit_star_validity::canonical_ends(&b, &a), (&b[..], &a[..]));
/// ```
#[inline]
pub fn canonical_ends<'a>(a: &'a [f64], b: &'a [f64]) -> (&'a [f64], &'a [f64]) {
    for (x, y) in a.iter().zip(b) {
        match x.total_cmp(y) {
            std::cmp::Ordering::Less => return (a, b),
            std::cmp::Ordering::Greater => return (b, a),
            std::cmp::Ordering::Equal => {}
        }
    }
    (a, b)
}

impl GridWalker {
    /// A walker for grids of step `step` (the full-resolution check length `L`).
    ///
    /// # Errors
    /// [`ValidityError::NotPositive`] if `step` is not finite and positive.
    pub fn new(step: f64) -> Result<Self, ValidityError> {
        if !(step.is_finite() && step > 0.0) {
            return Err(ValidityError::NotPositive {
                name: "edge-check step",
                value: step,
            });
        }
        Ok(Self {
            step,
            scratch: Vec::new(),
            batch: Vec::new(),
            segment: Segment::default(),
            accelerated: true,
            scan_edge: Vec::new(),
            scan_next: 0,
            certifying: Vec::new(),
            certified_motion: MotionProgress::default(),
            certified_points: 0,
            motion_scratch: Segment::default(),
            counters: EdgeCounters::default(),
        })
    }

    /// Turns [acceleration](Self#acceleration) on (the default) or off.
    pub fn set_accelerated(&mut self, accelerated: bool) {
        self.accelerated = accelerated;
    }

    /// `true` if walks are [accelerated](Self#acceleration).
    pub fn is_accelerated(&self) -> bool {
        self.accelerated
    }

    /// The full-resolution step `L`.
    #[inline]
    pub fn step(&self) -> f64 {
        self.step
    }

    /// Work counters so far.
    pub fn counters(&self) -> EdgeCounters {
        self.counters
    }

    /// Mutable access to the counters (to count checks and to reset).
    pub fn counters_mut(&mut self) -> &mut EdgeCounters {
        &mut self.counters
    }

    /// The canonical grid of the edge `a — b` (its length measured from the
    /// [canonical end](canonical_ends), so both directions give the same grid).
    #[inline]
    pub fn grid<S: StateSpace + ?Sized>(&self, space: &S, a: &[f64], b: &[f64]) -> EdgeGrid {
        let (a, b) = canonical_ends(a, b);
        EdgeGrid::new(space.distance(a, b), self.step)
    }

    /// Tests the positions of the bisection order of edge `(a, b)` on its canonical `grid`
    /// (from [`grid`](Self::grid)) up to `target` (exclusive) that `progress` has not covered
    /// yet, stopping at the first invalid point. Updates `progress`.
    ///
    /// The walk starts from the [canonical end](canonical_ends) of the edge whatever the order
    /// of `a` and `b`: the grid's fractions are measured from that end, so `progress` made from
    /// either end continues the same order of the same points. The stop condition is polled as
    /// [`STOP_POLL`] describes; a stopped walk keeps the progress made, so a later call resumes.
    pub fn advance<S, V>(
        &mut self,
        space: &S,
        validity: &V,
        (a, b, grid): (&[f64], &[f64], EdgeGrid),
        target: u64,
        progress: &mut EdgeProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        if progress.is_invalid() {
            return EdgeStatus::Invalid;
        }
        let (a, b) = canonical_ends(a, b);
        let target = target.min(grid.points());
        if progress.0 >= target {
            return progress.status(&grid);
        }
        let start = progress.0;
        let mut width = validity.batch_width().clamp(1, MAX_BATCH);
        let mut prepared = false;
        if self.accelerated && space.is_euclidean() {
            self.segment.set(a, b);
            match validity.prepare_segment(&mut self.segment) {
                Preparation::AllValid => {
                    let decided = target - start;
                    self.counters.points_tested += decided;
                    self.counters.points_culled += decided;
                    *progress = EdgeProgress(target);
                    return progress.status(&grid);
                }
                Preparation::Prepared if target == grid.points() && target - start >= SCAN_MIN => {
                    return self.advance_scanning(space, validity, (a, b, grid), progress, stop);
                }
                Preparation::Prepared => (prepared, width) = (true, prepared_width(width)),
                Preparation::Unprepared => {}
            }
        }
        // A walk longer than one poll period polls before its first point too (a walk begun
        // after the deadline tests nothing); a shorter walk never polls: it ends within a
        // period anyway, and one clock read would cost as much as a few of its points.
        let polls_first = target - start > poll_period(width);
        if width > 1 {
            return self.advance_batched(
                space,
                validity,
                (a, b, grid),
                (target, width, polls_first, prepared),
                progress,
                stop,
            );
        }
        self.scratch.resize(space.dimension(), 0.0);
        let mut position = start;
        for index in grid.order(start, target) {
            let walked = position - start;
            if walked.is_multiple_of(STOP_POLL) && (walked > 0 || polls_first) && stop.should_stop()
            {
                break;
            }
            space.interpolate(a, b, grid.fraction(index), &mut self.scratch);
            self.counters.points_tested += 1;
            if !validity.is_valid(&self.scratch) {
                *progress = EdgeProgress(EdgeProgress::INVALID);
                return EdgeStatus::Invalid;
            }
            position += 1;
        }
        *progress = EdgeProgress(position);
        progress.status(&grid)
    }

    /// A full check of the motion `a → b` (in the caller's order) on its canonical `grid`,
    /// then of the motion's end `b` itself, as one more position after the grid's: a batched
    /// checker tests the end in the batch of the last grid points instead of in a call of its
    /// own (a planner that adds `b` to a tree needs both). `progress` counts the end as
    /// position `grid.points()`, so the motion is [`EdgeStatus::Valid`] once `progress` has
    /// passed it; keep a progress of this walk apart from those of [`advance`](Self::advance).
    /// The end is tested as the space's interpolation reaches it (`a + (b − a)·1` on a straight
    /// line: `b`, up to one rounding). Polls as [`advance`](Self::advance) does; a stopped walk
    /// keeps its progress.
    pub fn advance_with_end<S, V>(
        &mut self,
        space: &S,
        validity: &V,
        (a, b, grid): (&[f64], &[f64], EdgeGrid),
        progress: &mut EdgeProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        let points = grid.points();
        if progress.is_invalid() {
            return EdgeStatus::Invalid;
        }
        if progress.0 > points {
            return EdgeStatus::Valid;
        }
        let (u, v) = canonical_ends(a, b);
        let end = end_fraction(v, b);
        let start = progress.0;
        let width = validity.batch_width().clamp(1, MAX_BATCH);
        let mut prepared = false;
        if self.accelerated && space.is_euclidean() {
            self.segment.set(u, v);
            match validity.prepare_segment(&mut self.segment) {
                Preparation::AllValid => {
                    let decided = points + 1 - start;
                    self.counters.points_tested += decided;
                    self.counters.points_culled += decided;
                    *progress = EdgeProgress(points + 1);
                    return EdgeStatus::Valid;
                }
                Preparation::Prepared if points - start < SCAN_MIN => prepared = true,
                Preparation::Prepared => {
                    return self.grid_then_end(space, validity, (a, b, grid), progress, stop);
                }
                Preparation::Unprepared => {}
            }
        }
        if !prepared && width == 1 {
            return self.grid_then_end(space, validity, (a, b, grid), progress, stop);
        }
        let width = if prepared {
            prepared_width(width)
        } else {
            width
        };
        let fractions = grid
            .order(start, points)
            .map(|index| grid.fraction(index))
            .chain(std::iter::once(end));
        let batches = Batches {
            width,
            polls_first: points + 1 - start > poll_period(width),
            prepared,
        };
        match self.walk_batches(space, validity, (u, v), fractions, batches, stop) {
            Walked::Invalid => {
                *progress = EdgeProgress(EdgeProgress::INVALID);
                EdgeStatus::Invalid
            }
            Walked::Done(walked) | Walked::Stopped(walked) => {
                *progress = EdgeProgress(start + walked);
                if progress.0 > points {
                    EdgeStatus::Valid
                } else {
                    EdgeStatus::Unknown
                }
            }
        }
    }

    /// [`advance_with_end`](Self::advance_with_end) as two walks: the grid's
    /// ([`advance`](Self::advance)), then the end alone (checkers without batches, and long
    /// prepared edges, which the grid's walk scans).
    fn grid_then_end<S, V>(
        &mut self,
        space: &S,
        validity: &V,
        (a, b, grid): (&[f64], &[f64], EdgeGrid),
        progress: &mut EdgeProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        let status = self.advance(space, validity, (a, b, grid), u64::MAX, progress, stop);
        if status != EdgeStatus::Valid {
            return status;
        }
        let (u, v) = canonical_ends(a, b);
        let end = end_fraction(v, b);
        self.scratch.resize(space.dimension(), 0.0);
        space.interpolate(u, v, end, &mut self.scratch);
        self.counters.points_tested += 1;
        if validity.is_valid(&self.scratch) {
            *progress = EdgeProgress(grid.points() + 1);
            EdgeStatus::Valid
        } else {
            *progress = EdgeProgress(EdgeProgress::INVALID);
            EdgeStatus::Invalid
        }
    }

    /// A full check of a long prepared edge: the first [`SCAN_HEAD`] positions of the
    /// bisection order (where a wide obstacle shows at once), then every grid point in
    /// ascending order, [`STOP_POLL`] fractions per call — cheap to generate, and the order
    /// does not matter when every point turns out valid. If one is invalid, the walk goes on
    /// in bisection order from where the head stopped and finds the first invalid position
    /// (an invalid point exists among the untested ones: the tested ones were valid), so the
    /// status, the progress and the points counted are exactly the walk's. Polls before the
    /// scan and every [`SCAN_POLL`] points of it; a stopped scan keeps the head's progress, and
    /// the walker remembers where the scan of this edge stopped, so that the next full check of
    /// the same edge goes on from there.
    fn advance_scanning<S, V>(
        &mut self,
        space: &S,
        validity: &V,
        (a, b, grid): (&[f64], &[f64], EdgeGrid),
        progress: &mut EdgeProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        let target = grid.points();
        let walk = |walker: &mut Self, to: u64, progress: &mut EdgeProgress| {
            let polls_first = to - progress.0 > STOP_POLL;
            let batches = (to, STOP_POLL as usize, polls_first, true);
            walker.advance_batched(space, validity, (a, b, grid), batches, progress, stop)
        };
        if progress.0 < SCAN_HEAD {
            let status = walk(self, SCAN_HEAD.min(target), progress);
            if status != EdgeStatus::Unknown || progress.0 < SCAN_HEAD.min(target) {
                return status;
            }
        }
        let mut fractions = [0.0; STOP_POLL as usize];
        let resumes = self.scan_next > 0
            && self.scan_edge.len() == a.len() + b.len()
            && self
                .scan_edge
                .iter()
                .zip(a.iter().chain(b))
                .all(|(x, y)| x.to_bits() == y.to_bits());
        let mut index = if resumes { self.scan_next } else { 1 };
        self.scan_next = 0;
        let mut since_poll = SCAN_POLL;
        while index <= target {
            if since_poll >= SCAN_POLL {
                if stop.should_stop() {
                    self.scan_edge.clear();
                    self.scan_edge.extend(a.iter().chain(b));
                    self.scan_next = index;
                    return progress.status(&grid);
                }
                since_poll = 0;
            }
            let n = STOP_POLL.min(target + 1 - index);
            for (k, t) in (0..n).zip(&mut fractions) {
                *t = grid.fraction(index + k);
            }
            let found = validity.first_invalid_on(&mut self.segment, &fractions[..n as usize]);
            if found.is_some() {
                return walk(self, target, progress);
            }
            index += n;
            since_poll += n;
        }
        self.counters.points_tested += target - progress.0;
        *progress = EdgeProgress(target);
        EdgeStatus::Valid
    }

    /// [`advance`](Self::advance) for a checker with batches: the next `width` points of the
    /// bisection order (fewer at the end of the walk or of a poll period) go to
    /// [`StateValidity::any_invalid`] in one call. Each point of the order is drawn from
    /// the order once, so no point is tested twice; polls fall on the same positions as in
    /// the one-by-one walk, because a batch never straddles a poll.
    #[inline(never)]
    fn advance_batched<S, V>(
        &mut self,
        space: &S,
        validity: &V,
        (a, b, grid): (&[f64], &[f64], EdgeGrid),
        (target, width, polls_first, prepared): (u64, usize, bool, bool),
        progress: &mut EdgeProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        let start = progress.0;
        let fractions = grid.order(start, target).map(|index| grid.fraction(index));
        let batches = Batches {
            width,
            polls_first,
            prepared,
        };
        match self.walk_batches(space, validity, (a, b), fractions, batches, stop) {
            Walked::Invalid => {
                *progress = EdgeProgress(EdgeProgress::INVALID);
                EdgeStatus::Invalid
            }
            Walked::Done(walked) | Walked::Stopped(walked) => {
                *progress = EdgeProgress(start + walked);
                progress.status(&grid)
            }
        }
    }

    /// Tests the states at `fractions` of the edge `a → b` in order, `batches.width` to a call
    /// — [`StateValidity::any_invalid_on`] with the fractions if the walker's segment is
    /// prepared, [`StateValidity::any_invalid`] with interpolated states otherwise — polling
    /// `stop` every poll period ([`STOP_POLL`] points, or the batch width rounded up to a
    /// multiple of it) and before the first point if `batches.polls_first`, so that no batch
    /// straddles a poll. Counts the points tested up to and including the invalid
    /// one found.
    fn walk_batches<S, V>(
        &mut self,
        space: &S,
        validity: &V,
        (a, b): (&[f64], &[f64]),
        fractions: impl Iterator<Item = f64>,
        batches: Batches,
        stop: &dyn Stop,
    ) -> Walked
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        let dimension = space.dimension();
        let width = batches.width.clamp(1, MAX_BATCH);
        let period = poll_period(width);
        if !batches.prepared {
            self.scratch.resize(dimension * width, 0.0);
        }
        self.batch.resize(width, 0.0);
        let ts = &mut self.batch;
        let mut fractions = fractions;
        let mut walked = 0_u64;
        loop {
            // The batch is drawn before the poll, which it does not depend on: a walk with
            // nothing left ends without polling, and a stopped walk drops what it drew.
            let n = (width as u64).min(period - walked % period) as usize;
            let mut filled = 0;
            for (slot, t) in ts.iter_mut().take(n).zip(&mut fractions) {
                *slot = t;
                filled += 1;
            }
            if filled == 0 {
                break;
            }
            if walked.is_multiple_of(period)
                && (walked > 0 || batches.polls_first)
                && stop.should_stop()
            {
                return Walked::Stopped(walked);
            }
            let found = if batches.prepared {
                validity.any_invalid_on(&mut self.segment, &ts[..filled])
            } else {
                for (slot, &t) in self.scratch.chunks_exact_mut(dimension).zip(&ts[..filled]) {
                    space.interpolate(a, b, t, slot);
                }
                validity.any_invalid(&self.scratch[..filled * dimension], dimension)
            };
            if let Some(index) = found {
                self.counters.points_tested += index.min(filled - 1) as u64 + 1;
                return Walked::Invalid;
            }
            self.counters.points_tested += filled as u64;
            walked += filled as u64;
        }
        Walked::Done(walked)
    }

    /// Certifies the edge `a — b`: proves every state of it valid, not only the points of its
    /// grid, stopping at the first state found invalid.
    ///
    /// A checker that certifies motions ([`StateValidity::certify_motion_in`]: a box
    /// [`World`](crate::World) exactly, by slab tests; the `robot` crate's arm checker by
    /// spheres grown by how far they can move) certifies the whole edge, whatever the step.
    /// Any other checker is certified on a grid `factor` times finer than the edge's own: every
    /// point of the grid of step `step / factor` that is not a point of the edge's own grid
    /// (those were tested by the checks that whitelisted it), in order from the
    /// [canonical end](canonical_ends), [`StateValidity::batch_width`] points per call.
    ///
    /// A planner certifies the edges it is about to build its solution from. Returns
    /// [`EdgeStatus::Valid`] at once for `factor ≤ 1` (certification off), and
    /// [`EdgeStatus::Unknown`] if `stop` fired first (polled as in [`advance`](Self::advance)):
    /// the walker remembers how far the certification of that edge came, and the next
    /// certification of the same edge goes on from there, so that a planner driven by short
    /// time slices still finishes it.
    pub fn certify<S, V>(
        &mut self,
        space: &S,
        validity: &V,
        (a, b): (&[f64], &[f64]),
        factor: u32,
        stop: &dyn Stop,
    ) -> EdgeStatus
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        if factor <= 1 {
            return EdgeStatus::Valid;
        }
        let (a, b) = canonical_ends(a, b);
        let resumes = self.certifying.len() == a.len() + b.len()
            && self
                .certifying
                .iter()
                .zip(a.iter().chain(b))
                .all(|(x, y)| x.to_bits() == y.to_bits());
        let (mut motion, walked) = if resumes {
            (self.certified_motion, self.certified_points)
        } else {
            (MotionProgress::default(), 0)
        };
        self.certifying.clear();
        let before = motion.evaluations();
        let scratch = &mut self.motion_scratch;
        let status = match validity.certify_motion_in(&space, (a, b), scratch, &mut motion, stop) {
            Some(status) => {
                let evaluated = motion.evaluations() - before;
                self.counters.certification_points += evaluated;
                if status == EdgeStatus::Unknown {
                    self.certified_motion = motion;
                }
                status
            }
            None => {
                let (status, walked) =
                    self.certify_on_grid(space, validity, (a, b), factor, walked, stop);
                self.certified_points = walked;
                status
            }
        };
        match status {
            EdgeStatus::Unknown => self.certifying.extend(a.iter().chain(b)),
            EdgeStatus::Valid => self.counters.certifications += 1,
            EdgeStatus::Invalid => {
                self.counters.certifications += 1;
                self.counters.certification_failures += 1;
            }
        }
        status
    }

    /// [`certify`](Self::certify) on a grid `factor` times finer than the edge's own, from
    /// the `walked`-th new point on; returns the status and the new points walked so far.
    fn certify_on_grid<S, V>(
        &mut self,
        space: &S,
        validity: &V,
        (a, b): (&[f64], &[f64]),
        factor: u32,
        walked: u64,
        stop: &dyn Stop,
    ) -> (EdgeStatus, u64)
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        let length = space.distance(a, b);
        let coarse = EdgeGrid::new(length, self.step).intervals();
        let fine = EdgeGrid::new(length, self.step / f64::from(factor));
        let (intervals, points) = (fine.intervals(), fine.points());
        // Fine index `i` lies on the coarse grid when `i · coarse` is a multiple of `intervals`;
        // those are the multiples of `intervals / gcd`, `gcd − 1` of them.
        let on_coarse = |i: u64| u128::from(i) * u128::from(coarse) % u128::from(intervals) == 0;
        let new_points = points - (gcd(coarse, intervals) - 1);
        let width = validity.batch_width().clamp(1, MAX_BATCH);
        let fractions = (1..=points)
            .filter(|&i| !on_coarse(i))
            .skip(walked as usize)
            .map(|i| fine.fraction(i));
        let batches = Batches {
            width,
            polls_first: new_points - walked.min(new_points) > poll_period(width),
            prepared: false,
        };
        let before = self.counters.points_tested;
        let outcome = self.walk_batches(space, validity, (a, b), fractions, batches, stop);
        self.counters.certification_points += self.counters.points_tested - before;
        match outcome {
            Walked::Done(_) => (EdgeStatus::Valid, 0),
            Walked::Stopped(more) => (EdgeStatus::Unknown, walked + more),
            Walked::Invalid => (EdgeStatus::Invalid, 0),
        }
    }
}

/// How [`GridWalker::walk_batches`] groups its points: up to `width` per call, on a prepared
/// segment or as interpolated states, polling before the first point if `polls_first`.
#[derive(Debug, Clone, Copy)]
struct Batches {
    width: usize,
    polls_first: bool,
    prepared: bool,
}

/// How a [`GridWalker::walk_batches`] walk ended, with the points it tested valid.
enum Walked {
    /// Every point valid.
    Done(u64),
    /// The stop fired before the rest.
    Stopped(u64),
    /// A point was invalid.
    Invalid,
}

fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

#[cfg(test)]
mod tests {
    use std::cell::Cell;

    use mit_star_spaces::{Never, RealVectorSpace};

    use super::*;
    use crate::{AllValid, Counted};

    /// Counts its polls and fires from poll number `fires_at` (1-based) on.
    struct Polls {
        polls: Cell<u64>,
        fires_at: u64,
    }

    impl Polls {
        fn firing_at(fires_at: u64) -> Self {
            Self {
                polls: Cell::new(0),
                fires_at,
            }
        }
    }

    impl Stop for Polls {
        fn should_stop(&self) -> bool {
            self.polls.set(self.polls.get() + 1);
            self.polls.get() >= self.fires_at
        }
    }

    /// Walks the whole grid of `intervals` intervals on `[0, 1]` from fresh progress.
    fn walk(intervals: u64, stop: &dyn Stop) -> (EdgeStatus, EdgeProgress, u64) {
        let space = RealVectorSpace::cube(1, 0.0, 1.0).unwrap();
        let mut walker = GridWalker::new(1.0 / intervals as f64).unwrap();
        let validity = Counted::new(AllValid);
        let mut progress = EdgeProgress::default();
        let grid = EdgeGrid::with_intervals(intervals);
        let status = walker.advance(
            &space,
            &validity,
            (&[0.0], &[1.0], grid),
            u64::MAX,
            &mut progress,
            stop,
        );
        (status, progress, validity.count())
    }

    #[test]
    fn a_walk_begun_after_the_stop_tests_nothing_unless_it_is_short() {
        let fired = Polls::firing_at(1);
        // 33 points: longer than one poll period, polled before the first point.
        let (status, progress, tested) = walk(34, &fired);
        assert_eq!(
            (status, progress.tested(), tested),
            (EdgeStatus::Unknown, 0, 0)
        );
        assert_eq!(fired.polls.get(), 1);
        // 32 points: never polled, finished.
        let fired = Polls::firing_at(1);
        let (status, progress, tested) = walk(33, &fired);
        assert_eq!(
            (status, progress.tested(), tested),
            (EdgeStatus::Valid, 32, 32)
        );
        assert_eq!(fired.polls.get(), 0);
    }

    #[test]
    fn polls_come_every_stop_poll_points() {
        for fires_at in 1..6 {
            let stop = Polls::firing_at(fires_at);
            let (status, progress, tested) = walk(1000, &stop);
            assert_eq!(status, EdgeStatus::Unknown);
            assert_eq!(progress.tested(), STOP_POLL * (fires_at - 1));
            assert_eq!(tested, progress.tested());
            assert_eq!(stop.polls.get(), fires_at);
        }
        for intervals in [2_u64, 33, 34, 65, 66, 1000] {
            let stop = Polls::firing_at(u64::MAX);
            let (status, progress, _) = walk(intervals, &stop);
            let points = intervals - 1;
            assert_eq!((status, progress.tested()), (EdgeStatus::Valid, points));
            let expected = if points > STOP_POLL {
                points.div_ceil(STOP_POLL)
            } else {
                0
            };
            assert_eq!(stop.polls.get(), expected, "{points} points");
        }
    }

    /// Valid everywhere, `width` states per call, recording how many it is handed each call.
    struct Wide {
        width: usize,
        calls: std::cell::RefCell<Vec<usize>>,
    }

    impl StateValidity for Wide {
        fn is_valid(&self, _: &[f64]) -> bool {
            true
        }

        fn batch_width(&self) -> usize {
            self.width
        }

        fn any_invalid(&self, states: &[f64], dimension: usize) -> Option<usize> {
            self.calls.borrow_mut().push(states.len() / dimension);
            None
        }
    }

    #[test]
    fn a_checker_wider_than_stop_poll_gets_its_whole_batches_and_a_longer_poll_period() {
        let space = RealVectorSpace::cube(1, 0.0, 1.0).unwrap();
        let walk = |stop: &Polls| {
            let mut walker = GridWalker::new(1e-3).unwrap();
            let validity = Wide {
                width: 100,
                calls: Default::default(),
            };
            let mut progress = EdgeProgress::default();
            let grid = EdgeGrid::with_intervals(1000);
            let ends = (&[0.0][..], &[1.0][..], grid);
            let status = walker.advance(&space, &validity, ends, u64::MAX, &mut progress, stop);
            (status, progress.tested(), validity.calls.into_inner())
        };
        // 999 points, polled every 128 (100 rounded up to a multiple of 32): before the first
        // point and after 128, 256, …, 896; each period is a batch of 100 and one of 28.
        let stop = Polls::firing_at(u64::MAX);
        let (status, tested, calls) = walk(&stop);
        assert_eq!((status, tested), (EdgeStatus::Valid, 999));
        assert_eq!(stop.polls.get(), 8);
        assert_eq!(calls.iter().sum::<usize>(), 999);
        assert_eq!(calls.iter().filter(|&&n| n == 100).count(), 8);
        assert!(calls.iter().all(|&n| n <= 100), "{calls:?}");
        // Fired at the second poll: one period tested.
        let (status, tested, calls) = walk(&Polls::firing_at(2));
        assert_eq!(
            (status, tested, calls),
            (EdgeStatus::Unknown, 128, vec![100, 28])
        );
    }

    #[test]
    fn a_stopped_walk_resumes_where_it_stopped() {
        let (_, mut progress, _) = walk(1000, &Polls::firing_at(3));
        assert_eq!(progress.tested(), 2 * STOP_POLL);
        let space = RealVectorSpace::cube(1, 0.0, 1.0).unwrap();
        let mut walker = GridWalker::new(1e-3).unwrap();
        let validity = Counted::new(AllValid);
        // Resumed from the other end: the same order continues.
        let status = walker.advance(
            &space,
            &validity,
            (&[1.0], &[0.0], EdgeGrid::with_intervals(1000)),
            u64::MAX,
            &mut progress,
            &Never,
        );
        assert_eq!(status, EdgeStatus::Valid);
        assert_eq!(validity.count(), 999 - 2 * STOP_POLL);
    }

    /// Valid everywhere except in `(lo, hi)` on the first coordinate; records every state.
    struct Gap {
        lo: f64,
        hi: f64,
        seen: std::cell::RefCell<Vec<f64>>,
    }

    impl StateValidity for Gap {
        fn is_valid(&self, s: &[f64]) -> bool {
            self.seen.borrow_mut().push(s[0]);
            !(s[0] > self.lo && s[0] < self.hi)
        }
    }

    fn gap(lo: f64, hi: f64) -> Gap {
        Gap {
            lo,
            hi,
            seen: std::cell::RefCell::new(Vec::new()),
        }
    }

    #[test]
    fn certification_finds_what_falls_between_grid_points() {
        let space = RealVectorSpace::cube(1, 0.0, 1.0).unwrap();
        let never = Never;
        // Grid of 10 intervals: points at 0.1, 0.2, …; the gap (0.12, 0.13) lies between two.
        let mut walker = GridWalker::new(0.1).unwrap();
        let thin = gap(0.12, 0.13);
        let mut progress = EdgeProgress::default();
        let grid = walker.grid(&space, &[0.0], &[1.0]);
        let status = walker.advance(
            &space,
            &thin,
            (&[0.0], &[1.0], grid),
            u64::MAX,
            &mut progress,
            &never,
        );
        assert_eq!(status, EdgeStatus::Valid);
        // Four times finer: 0.125 is a point, and it is in the gap.
        let status = walker.certify(&space, &thin, (&[1.0], &[0.0]), 4, &never);
        assert_eq!(status, EdgeStatus::Invalid);
        assert_eq!(walker.counters().certification_failures, 1);
        // Twice finer misses it (0.15 is the nearest point): the factor is what it says.
        let status = walker.certify(&space, &gap(0.12, 0.13), (&[0.0], &[1.0]), 2, &never);
        assert_eq!(status, EdgeStatus::Valid);
        assert_eq!(walker.counters().certifications, 2);
    }

    #[test]
    fn certification_skips_the_edges_own_points() {
        let space = RealVectorSpace::cube(1, 0.0, 1.0).unwrap();
        for (length, step, factor) in [
            (1.0, 0.1, 4),
            (0.95, 0.1, 4),
            (0.37, 0.1, 3),
            (0.05, 0.1, 4),
        ] {
            let mut walker = GridWalker::new(step).unwrap();
            let free = gap(2.0, 3.0);
            let coarse = EdgeGrid::new(length, step);
            let fine = EdgeGrid::new(length, step / f64::from(factor));
            let status = walker.certify(&space, &free, (&[0.0], &[length]), factor, &Never);
            assert_eq!(status, EdgeStatus::Valid);
            let seen = free.seen.into_inner();
            // Every fine point not on the coarse grid, once, in order.
            let expected: Vec<f64> = (1..fine.intervals())
                .map(|i| length * fine.fraction(i))
                .filter(|x| {
                    (1..coarse.intervals()).all(|j| (length * coarse.fraction(j) - x).abs() > 1e-12)
                })
                .collect();
            assert_eq!(seen.len(), expected.len(), "{length} {step} {factor}");
            for (a, b) in seen.iter().zip(&expected) {
                assert!((a - b).abs() < 1e-12);
            }
            assert_eq!(walker.counters().points_tested, expected.len() as u64);
        }
    }

    #[test]
    fn certification_polls_and_factor_one_is_free() {
        let space = RealVectorSpace::cube(1, 0.0, 1.0).unwrap();
        let mut walker = GridWalker::new(1e-3).unwrap();
        let free = gap(2.0, 3.0);
        let stop = Polls::firing_at(1);
        assert_eq!(
            walker.certify(&space, &free, (&[0.0], &[1.0]), 4, &stop),
            EdgeStatus::Unknown
        );
        assert_eq!(walker.counters().points_tested, 0);
        assert_eq!(
            walker.certify(&space, &free, (&[0.0], &[1.0]), 1, &stop),
            EdgeStatus::Valid
        );
        // Neither a stopped certification nor factor 1 is a finished one.
        assert_eq!(walker.counters().certifications, 0);
    }

    #[test]
    fn a_stopped_certification_goes_on_where_it_stopped() {
        let space = RealVectorSpace::cube(1, 0.0, 1.0).unwrap();
        let mut walker = GridWalker::new(1e-2).unwrap();
        let free = Counted::new(gap(2.0, 3.0));
        // 300 new points; each call's stop fires on its third poll.
        let mut calls = 0;
        let status = loop {
            calls += 1;
            let fires = Polls::firing_at(3);
            let status = walker.certify(&space, &free, (&[1.0], &[0.0]), 4, &fires);
            if status != EdgeStatus::Unknown {
                break status;
            }
        };
        assert_eq!(status, EdgeStatus::Valid);
        assert!(calls > 2, "{calls}");
        // Every new point once: resumed, not started over.
        assert_eq!(free.count(), 300);
        assert_eq!(walker.counters().certification_points, 300);
        assert_eq!(walker.counters().certifications, 1);
        // Another edge starts afresh.
        let status = walker.certify(&space, &free, (&[0.0], &[0.5]), 4, &Never);
        assert_eq!(status, EdgeStatus::Valid);
        assert_eq!(free.count(), 450);
    }
}
