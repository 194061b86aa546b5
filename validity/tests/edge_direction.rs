//! Checks of one edge from either end share one grid and one order: whatever the sequence of
//! sparse checks (each from a random end, at random levels, by any checker) and the end of the
//! final full check, every grid point is tested exactly once.
//!
//! The planner stores one progress per unordered vertex pair, while its reverse search
//! sparse-checks `u → v` and its forward search fully checks `v → u`. The bisection order is
//! not symmetric unless `2^D` divides `N`, so without a canonical end, `N = 701` with 15 sparse
//! points left 15 grid points untested — and the edge came back `Valid`.

use std::cell::RefCell;

use mit_star_spaces::{Never, RealVectorSpace, StateSpace};
use mit_star_validity::{
    DenseChecker, EdgeChecker, EdgeGrid, EdgeProgress, EdgeStatus, FixedSparseChecker,
    LengthAdaptiveChecker, StateValidity, canonical_ends,
};
use proptest::prelude::*;

/// Records the grid index of every state it is asked about (fraction along the canonical
/// direction, times `N`), answering valid except at one forbidden index.
struct Indexer<'a> {
    a: &'a [f64],
    length: f64,
    intervals: u64,
    forbidden: Option<u64>,
    seen: RefCell<Vec<u64>>,
}

impl StateValidity for Indexer<'_> {
    fn is_valid(&self, state: &[f64]) -> bool {
        let t = mit_star_spaces::euclidean_distance(self.a, state) / self.length;
        let index = (t * self.intervals as f64).round() as u64;
        self.seen.borrow_mut().push(index);
        Some(index) != self.forbidden
    }
}

/// A checker of `kind` (dense, fixed sparse, length-adaptive) at sparse level `level`.
fn checker<'r>(
    kind: u8,
    step: f64,
    level: u32,
) -> Box<dyn EdgeChecker<RealVectorSpace, Indexer<'r>>> {
    let mut checker: Box<dyn EdgeChecker<RealVectorSpace, Indexer<'r>>> = match kind % 3 {
        0 => Box::new(DenseChecker::new(step).unwrap()),
        1 => Box::new(FixedSparseChecker::new(step).unwrap()),
        _ => Box::new(
            LengthAdaptiveChecker::with_parameters(step, 40.0 * step, 0.5, 2.0 * step).unwrap(),
        ),
    };
    for _ in 0..level {
        checker.refine();
    }
    checker
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn every_index_is_tested_exactly_once_whatever_the_ends(
        n in 1usize..=6,
        raw_a in prop::collection::vec(-0.5f64..0.5, 6),
        raw_b in prop::collection::vec(-0.5f64..0.5, 6),
        intervals in 2u64..5000,
        sparse in prop::collection::vec((any::<bool>(), 0u8..3, 0u32..8), 0..6),
        full_from_b in any::<bool>(),
        final_kind in 0u8..3,
    ) {
        let (a, b) = (&raw_a[..n], &raw_b[..n]);
        let space = RealVectorSpace::cube(n, -0.5, 0.5).unwrap();
        let length = space.distance(a, b);
        prop_assume!(length > 1e-6);
        // A step giving exactly `intervals` intervals (up to rounding of the ratio).
        let step = length / (intervals as f64 - 0.5);
        let grid = EdgeGrid::new(length, step);
        let (ca, _) = canonical_ends(a, b);
        let recorder = &Indexer {
            a: ca,
            length,
            intervals: grid.intervals(),
            forbidden: None,
            seen: RefCell::new(Vec::new()),
        };
        let mut progress = EdgeProgress::default();
        for (from_b, kind, level) in sparse {
            let mut c = checker(kind, step, level);
            let (x, y) = if from_b { (b, a) } else { (a, b) };
            let status = c.check_sparse(&space, recorder, x, y, &mut progress, &Never);
            prop_assert_ne!(status, EdgeStatus::Invalid);
        }
        let mut c = checker(final_kind, step, 0);
        // The remaining work is the same from either end, and is what the full check will do.
        let remaining = c.remaining(&space, a, b, progress);
        prop_assert_eq!(remaining, c.remaining(&space, b, a, progress));
        prop_assert_eq!(remaining, grid.points() - recorder.seen.borrow().len() as u64);
        let (x, y) = if full_from_b { (b, a) } else { (a, b) };
        let status = c.check_full(&space, recorder, x, y, &mut progress, &Never);
        prop_assert_eq!(status, EdgeStatus::Valid);
        let mut seen = recorder.seen.borrow().clone();
        prop_assert_eq!(seen.len() as u64, grid.points(), "each point once");
        seen.sort_unstable();
        let expected: Vec<u64> = (1..grid.intervals()).collect();
        prop_assert_eq!(seen, expected, "every interior index");
    }

    #[test]
    fn an_invalid_point_is_found_from_either_end(
        n in 1usize..=4,
        raw_a in prop::collection::vec(-0.5f64..0.5, 4),
        raw_b in prop::collection::vec(-0.5f64..0.5, 4),
        intervals in 2u64..3000,
        forbidden_at in 0.0f64..1.0,
        sparse_from_b in any::<bool>(),
        full_from_b in any::<bool>(),
    ) {
        let (a, b) = (&raw_a[..n], &raw_b[..n]);
        let space = RealVectorSpace::cube(n, -0.5, 0.5).unwrap();
        let length = space.distance(a, b);
        prop_assume!(length > 1e-6);
        let step = length / (intervals as f64 - 0.5);
        let grid = EdgeGrid::new(length, step);
        let forbidden = 1 + ((grid.points() - 1) as f64 * forbidden_at) as u64;
        let (ca, _) = canonical_ends(a, b);
        let recorder = &Indexer {
            a: ca,
            length,
            intervals: grid.intervals(),
            forbidden: Some(forbidden),
            seen: RefCell::new(Vec::new()),
        };
        let mut progress = EdgeProgress::default();
        let mut c = checker(1, step, 0);
        let (x, y) = if sparse_from_b { (b, a) } else { (a, b) };
        let _ = c.check_sparse(&space, recorder, x, y, &mut progress, &Never);
        let (x, y) = if full_from_b { (b, a) } else { (a, b) };
        let status = c.check_full(&space, recorder, x, y, &mut progress, &Never);
        prop_assert_eq!(status, EdgeStatus::Invalid);
        let seen = recorder.seen.borrow();
        let mut unique = seen.clone();
        unique.sort_unstable();
        unique.dedup();
        prop_assert_eq!(unique.len(), seen.len(), "no point twice");
    }
}

#[test]
fn the_issues_examples_are_fully_covered() {
    // N = 701 with 15 sparse points and N = 1000 with 160, sparse from one end, full from the
    // other: every index once.
    for (intervals, sparse) in [(701_u64, 15_u64), (1000, 160)] {
        let space = RealVectorSpace::cube(1, 0.0, 1.0).unwrap();
        let (a, b) = ([0.0], [1.0]);
        let step = 1.0 / intervals as f64;
        let grid = EdgeGrid::new(1.0, step);
        assert_eq!(grid.intervals(), intervals);
        let recorder = Indexer {
            a: &a,
            length: 1.0,
            intervals,
            forbidden: None,
            seen: RefCell::new(Vec::new()),
        };
        let mut walker = mit_star_validity::GridWalker::new(step).unwrap();
        let mut progress = EdgeProgress::default();
        walker.advance(
            &space,
            &recorder,
            (&a, &b, grid),
            sparse,
            &mut progress,
            &Never,
        );
        walker.advance(
            &space,
            &recorder,
            (&b, &a, grid),
            u64::MAX,
            &mut progress,
            &Never,
        );
        let mut seen = recorder.seen.borrow().clone();
        seen.sort_unstable();
        assert_eq!(seen, (1..intervals).collect::<Vec<_>>(), "N = {intervals}");
    }
}
