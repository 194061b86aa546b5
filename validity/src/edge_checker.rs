//! The [`EdgeChecker`] trait, per-edge memory ([`EdgeProgress`]) and the shared grid walker.

use spaces::{StateSpace, Stop};

use crate::{EdgeGrid, StateValidity, ValidityError};

/// What is known about an edge after a check.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EdgeStatus {
    /// Every grid point has been tested valid: the edge is whitelisted.
    Valid,
    /// Some grid points remain untested and none tested so far was invalid.
    Unknown,
    /// A grid point was invalid: the edge is blacklisted (both directions).
    Invalid,
}

/// Per-edge memory of checking work: how many positions of the edge's bisection order have been
/// tested (all valid), or that the edge is known invalid. Eight bytes; the planner stores one per
/// edge it has touched. `Default` is "nothing tested yet".
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct EdgeProgress(u64);

impl EdgeProgress {
    const INVALID: u64 = u64::MAX;

    /// Nothing tested yet.
    pub const UNTESTED: Self = Self(0);

    /// Number of grid points tested valid so far (0 if the edge is known invalid).
    #[inline]
    pub fn tested(&self) -> u64 {
        if self.is_invalid() { 0 } else { self.0 }
    }

    /// `true` once a tested grid point was invalid.
    #[inline]
    pub fn is_invalid(&self) -> bool {
        self.0 == Self::INVALID
    }

    /// The status of an edge with this progress on `grid`.
    #[inline]
    pub fn status(&self, grid: &EdgeGrid) -> EdgeStatus {
        if self.is_invalid() {
            EdgeStatus::Invalid
        } else if self.0 >= grid.points() {
            EdgeStatus::Valid
        } else {
            EdgeStatus::Unknown
        }
    }

    /// Grid points still to test on `grid` before the edge is whitelisted (0 if invalid: nothing
    /// more will be tested).
    #[inline]
    pub fn remaining(&self, grid: &EdgeGrid) -> u64 {
        if self.is_invalid() {
            0
        } else {
            grid.points().saturating_sub(self.0)
        }
    }
}

/// Counters of edge-checking work, for benchmarks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct EdgeCounters {
    /// Sparse checks requested.
    pub sparse_checks: u64,
    /// Full checks requested.
    pub full_checks: u64,
    /// Grid points tested (state validity calls made by edge checks).
    pub points_tested: u64,
}

/// Walks an edge's canonical grid in bisection order, testing states; shared by every checker.
///
/// Owns the one scratch state the walk needs (allocated once, on first use), so checking an edge
/// never allocates. Polls the stop condition every [`STOP_POLL`] points.
#[derive(Debug, Clone)]
pub struct GridWalker {
    step: f64,
    scratch: Vec<f64>,
    counters: EdgeCounters,
}

/// How many grid points a walk tests between two polls of the stop condition: small enough that
/// a slow validity checker (an arm with meshes, 100 µs a state) stops within a few
/// milliseconds, large enough that reading the clock costs little next to 32 state checks.
pub const STOP_POLL: u64 = 32;

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
/// assert_eq!(validity::canonical_ends(&a, &b), (&b[..], &a[..]));
/// assert_eq!(validity::canonical_ends(&b, &a), (&b[..], &a[..]));
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
            counters: EdgeCounters::default(),
        })
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
    /// of `a` and `b`, so progress made from either end continues the same order.
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
        self.scratch.resize(space.dimension(), 0.0);
        let mut position = progress.0;
        for index in grid.order(position, target) {
            if (position - progress.0) % STOP_POLL == STOP_POLL - 1 && stop.should_stop() {
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
}

/// Decides edge validity at a sparse (current level) or full resolution, on the canonical grid
/// of spec §2, remembering work in the caller's [`EdgeProgress`].
///
/// Implementations differ only in how many grid points a sparse check tests
/// ([`sparse_budget`](Self::sparse_budget)) and how that number changes with the level; the
/// walking is shared ([`GridWalker`]). Object safe for fixed `S`, `V`:
/// `Box<dyn EdgeChecker<RealVectorSpace, World>>` works.
///
/// # Guarantees (pinned by `tests/edge_checkers.rs` and `tests/edge_direction.rs`)
/// - a finer check never turns an invalid edge valid;
/// - no grid point of an edge is tested twice across its sparse and full checks, whichever
///   end each check names (every walk starts from the [canonical end](canonical_ends));
/// - a full check that returns [`EdgeStatus::Valid`] has tested every grid point.
pub trait EdgeChecker<S: StateSpace + ?Sized, V: StateValidity + ?Sized> {
    /// Grid points a sparse check at the current level tests on an edge of `length` (before
    /// capping at the grid's size).
    fn sparse_budget(&self, length: f64) -> u64;

    /// Current sparse level `k` (0 after [`reset`](Self::reset)).
    fn level(&self) -> u32;

    /// Moves to the next, finer sparse level (called when a lazy path turns out invalid).
    fn refine(&mut self);

    /// Returns to sparse level 0 (called with every new batch).
    fn reset(&mut self);

    /// The shared grid walker.
    fn walker(&self) -> &GridWalker;

    /// The shared grid walker, mutably.
    fn walker_mut(&mut self) -> &mut GridWalker;

    /// The full-resolution step `L`.
    fn step(&self) -> f64 {
        self.walker().step()
    }

    /// Work counters so far.
    fn counters(&self) -> EdgeCounters {
        self.walker().counters()
    }

    /// Sparse check of `a → b` at the current level: tests the first
    /// [`sparse_budget`](Self::sparse_budget) positions of the bisection order not yet tested.
    fn check_sparse(
        &mut self,
        space: &S,
        validity: &V,
        a: &[f64],
        b: &[f64],
        progress: &mut EdgeProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus {
        // One distance per check, from the canonical end: it gives both the sparse budget and
        // the grid, identical from either end.
        let (a, b) = canonical_ends(a, b);
        let length = space.distance(a, b);
        let budget = self.sparse_budget(length);
        let walker = self.walker_mut();
        walker.counters_mut().sparse_checks += 1;
        let grid = EdgeGrid::new(length, walker.step());
        walker.advance(space, validity, (a, b, grid), budget, progress, stop)
    }

    /// Full check of `a → b`: tests every grid point not yet tested. Returns
    /// [`EdgeStatus::Unknown`] only if `stop` fired first (progress is kept, so a later call
    /// resumes).
    fn check_full(
        &mut self,
        space: &S,
        validity: &V,
        a: &[f64],
        b: &[f64],
        progress: &mut EdgeProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus {
        let walker = self.walker_mut();
        walker.counters_mut().full_checks += 1;
        let grid = walker.grid(space, a, b);
        walker.advance(space, validity, (a, b, grid), u64::MAX, progress, stop)
    }

    /// Grid points a full check of `a → b` would still test (the effort of the edge).
    fn remaining(&self, space: &S, a: &[f64], b: &[f64], progress: EdgeProgress) -> u64 {
        progress.remaining(&self.walker().grid(space, a, b))
    }
}
