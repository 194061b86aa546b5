//! The [`EdgeChecker`] trait: sparse and full checks of an edge with per-edge memory.

use mit_star_spaces::{StateSpace, Stop};

use crate::{
    EdgeCounters, EdgeGrid, EdgeProgress, EdgeStatus, GridWalker, StateValidity, canonical_ends,
};

/// Decides edge validity at a sparse (current level) or full resolution, on the canonical grid
/// of spec §2, remembering work in the caller's [`EdgeProgress`].
///
/// Implementations differ only in how many grid points a sparse check tests
/// ([`sparse_budget`](Self::sparse_budget)) and how that number changes with the level; the
/// walking is shared ([`GridWalker`]). Object safe for fixed `S`, `V`:
/// `Box<dyn EdgeChecker<RealVectorSpace, World>>` works.
///
/// # One canonical direction
/// An edge is undirected: callers may name its ends in either order, check by check, and keep
/// one [`EdgeProgress`] per unordered pair (the planner's reverse search sparse-checks `u → v`,
/// its forward search fully checks `v → u`). Every method computes the edge's length, grid,
/// sparse budget and [`remaining`](Self::remaining) work from its
/// [canonical end](canonical_ends), and every walk starts there, so the answers and the points
/// tested do not depend on the order the caller chose.
///
/// # Guarantees (pinned by `tests/edge_checkers.rs` and `tests/edge_direction.rs`)
/// - a finer check never turns an invalid edge valid;
/// - no grid point of an edge is tested twice across its sparse and full checks, whichever
///   end each check names (every walk starts from the [canonical end](canonical_ends));
/// - a full check that returns [`EdgeStatus::Valid`] has tested every grid point;
/// - an edge with a NaN or infinite coordinate in an end, or whose length is not finite, is
///   [`EdgeStatus::Invalid`] for every check and certification (and its progress says so):
///   it has no grid to test (`tests/non_finite_ends.rs`).
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
        if !is_checkable(a, b, length) {
            *progress = EdgeProgress::FOUND_INVALID;
            return EdgeStatus::Invalid;
        }
        let grid = EdgeGrid::new(length, walker.step());
        let before = walker.counters().points_tested;
        let status = walker.advance(space, validity, (a, b, grid), budget, progress, stop);
        let counters = walker.counters_mut();
        let tested = counters.points_tested - before;
        counters.by_length.count_sparse(grid.points(), tested);
        status
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
        full_check(
            self.walker_mut(),
            space,
            (a, b),
            progress,
            |walker, grid, progress| {
                walker.advance(space, validity, (a, b, grid), u64::MAX, progress, stop)
            },
        )
    }

    /// Full check of the motion `from → to` and of its end `to` itself
    /// ([`GridWalker::advance_with_end`]): what a tree planner asks before it adds `to`. A
    /// batched checker tests the end with the motion's last grid points. `progress` belongs to
    /// this check (it counts the end as one more position), and is kept when `stop` fires
    /// first ([`EdgeStatus::Unknown`]), so a later call resumes.
    fn check_full_and_end(
        &mut self,
        space: &S,
        validity: &V,
        from: &[f64],
        to: &[f64],
        progress: &mut EdgeProgress,
        stop: &dyn Stop,
    ) -> EdgeStatus {
        let ends = (from, to);
        full_check(
            self.walker_mut(),
            space,
            ends,
            progress,
            |walker, grid, progress| {
                walker.advance_with_end(space, validity, (from, to, grid), progress, stop)
            },
        )
    }

    /// Certifies a whitelisted edge on a grid `factor` times finer than its own
    /// ([`GridWalker::certify`]): [`EdgeStatus::Invalid`] if a point between its grid points
    /// is invalid, [`EdgeStatus::Unknown`] if `stop` fired first.
    fn certify(
        &mut self,
        space: &S,
        validity: &V,
        a: &[f64],
        b: &[f64],
        factor: u32,
        stop: &dyn Stop,
    ) -> EdgeStatus {
        if factor > 1 && !is_checkable(a, b, space.distance(a, b)) {
            return EdgeStatus::Invalid;
        }
        self.walker_mut()
            .certify(space, validity, (a, b), factor, stop)
    }

    /// Grid points a full check of `a → b` would still test (the effort of the edge).
    fn remaining(&self, space: &S, a: &[f64], b: &[f64], progress: EdgeProgress) -> u64 {
        progress.remaining(&self.walker().grid(space, a, b))
    }
}

/// What a full check does around its walk (`walk`, given the walker, the edge's canonical grid
/// and the progress): counts the check, refuses an edge without a grid (see [`is_checkable`]),
/// and records the points the walk tested by the grid's length.
fn full_check<S: StateSpace + ?Sized>(
    walker: &mut GridWalker,
    space: &S,
    (a, b): (&[f64], &[f64]),
    progress: &mut EdgeProgress,
    walk: impl FnOnce(&mut GridWalker, EdgeGrid, &mut EdgeProgress) -> EdgeStatus,
) -> EdgeStatus {
    walker.counters_mut().full_checks += 1;
    // The walker's own grid, from the canonical end, with the length kept for the guard.
    let (u, v) = canonical_ends(a, b);
    let length = space.distance(u, v);
    if !is_checkable(u, v, length) {
        *progress = EdgeProgress::FOUND_INVALID;
        return EdgeStatus::Invalid;
    }
    let grid = EdgeGrid::new(length, walker.step());
    let before = walker.counters().points_tested;
    let status = walk(walker, grid, progress);
    let counters = walker.counters_mut();
    let tested = counters.points_tested - before;
    counters.by_length.count_full(grid.points(), tested);
    status
}

/// `true` if the edge `a — b` of length `length` has a grid to check: every coordinate of
/// both ends finite, and the length too (finite ends so far apart that it overflows have no
/// grid). Otherwise no check may call it valid — an edge with a NaN end has a one-interval
/// grid with no point to test, and would pass untested — so every check answers
/// [`EdgeStatus::Invalid`]. One pass over the ends per check, none per point.
#[inline]
fn is_checkable(a: &[f64], b: &[f64], length: f64) -> bool {
    length.is_finite() && a.iter().chain(b).all(|x| x.is_finite())
}
