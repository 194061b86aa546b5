//! Conformance of every edge checker on random worlds and edges.
//!
//! Pins the guarantees of spec §2: all checks use one canonical grid; a sparse check's work is
//! reused (no grid point tested twice); a finer check never turns an invalid edge valid; a full
//! check agrees with a from-scratch dense check.

use std::cell::RefCell;

use mit_star_spaces::{Never, RealVectorSpace, StateSpace};
use mit_star_validity::{
    AxisBox, DenseChecker, EdgeChecker, EdgeGrid, EdgeProgress, EdgeStatus, FixedSparseChecker,
    LengthAdaptiveChecker, StateValidity, World,
};
use proptest::prelude::*;

/// Records every state it is asked about, delegating to a world.
struct Recorder<'a> {
    world: &'a World,
    seen: RefCell<Vec<Vec<f64>>>,
}

impl StateValidity for Recorder<'_> {
    fn is_valid(&self, state: &[f64]) -> bool {
        self.seen.borrow_mut().push(state.to_vec());
        self.world.is_valid(state)
    }
}

/// A random world in `[-0.5, 0.5]^n` and a random edge between two of its valid states.
fn world_and_edge() -> impl Strategy<Value = (World, Vec<f64>, Vec<f64>)> {
    (2usize..=6).prop_flat_map(|n| {
        let boxes = prop::collection::vec(
            (
                prop::collection::vec(-0.5f64..0.5, n),
                prop::collection::vec(0.01f64..0.3, n),
            ),
            0..6,
        );
        let point = || prop::collection::vec(-0.5f64..0.5, n);
        (boxes, point(), point()).prop_filter_map(
            "endpoints must be valid",
            move |(boxes, a, b)| {
                let mut world = World::new(vec![-0.5; n], vec![0.5; n]);
                for (center, widths) in boxes {
                    world.add_obstacle(AxisBox::new(center, widths)).ok()?;
                }
                (world.is_valid(&a) && world.is_valid(&b)).then_some((world, a, b))
            },
        )
    })
}

/// The checkers under test, all at `step`, each at some sparse level.
fn checkers(
    step: f64,
    level: u32,
) -> Vec<Box<dyn EdgeChecker<RealVectorSpace, Recorder<'static>>>> {
    let mut fixed = FixedSparseChecker::new(step).unwrap();
    let mut adaptive =
        LengthAdaptiveChecker::with_parameters(step, 40.0 * step, 0.5, 2.0 * step).unwrap();
    for _ in 0..level {
        EdgeChecker::<RealVectorSpace, Recorder<'static>>::refine(&mut fixed);
        EdgeChecker::<RealVectorSpace, Recorder<'static>>::refine(&mut adaptive);
    }
    vec![
        Box::new(DenseChecker::new(step).unwrap()),
        Box::new(fixed),
        Box::new(adaptive),
    ]
}

/// Ground truth: is any canonical grid point of `a → b` invalid?
fn truth(space: &RealVectorSpace, world: &World, a: &[f64], b: &[f64], step: f64) -> EdgeStatus {
    let grid = EdgeGrid::new(space.distance(a, b), step);
    let mut x = vec![0.0; a.len()];
    for i in 1..grid.intervals() {
        space.interpolate(a, b, grid.fraction(i), &mut x);
        if !world.is_valid(&x) {
            return EdgeStatus::Invalid;
        }
    }
    EdgeStatus::Valid
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn sparse_then_full_tests_each_point_once_and_agrees_with_truth(
        (world, a, b) in world_and_edge(),
        step in 0.002f64..0.05,
        levels in prop::collection::vec(0u32..6, 1..4),
    ) {
        let n = a.len();
        let space = RealVectorSpace::cube(n, -0.5, 0.5).unwrap();
        let expected = truth(&space, &world, &a, &b, step);
        // 'static needed by the boxed trait objects; leak the tiny world for the test's lifetime.
        let world: &'static World = Box::leak(Box::new(world));
        for checker_index in 0..3 {
            let recorder = Recorder { world, seen: RefCell::new(Vec::new()) };
            let mut progress = EdgeProgress::default();
            let mut saw_invalid = false;
            for &level in &levels {
                let mut checker = checkers(step, level).swap_remove(checker_index);
                let status = checker.check_sparse(&space, &recorder, &a, &b, &mut progress, &Never);
                if status == EdgeStatus::Invalid {
                    saw_invalid = true;
                    // A sparse check only reports invalid when a grid point is invalid.
                    prop_assert_eq!(expected, EdgeStatus::Invalid);
                }
            }
            let mut checker = checkers(step, 0).swap_remove(checker_index);
            let full = checker.check_full(&space, &recorder, &a, &b, &mut progress, &Never);
            // A finer check never turns an invalid edge valid, and the full check is exact.
            if saw_invalid {
                prop_assert_eq!(full, EdgeStatus::Invalid);
            }
            prop_assert_eq!(full, expected);
            // No grid point tested twice across all checks of the edge.
            let seen = recorder.seen.borrow();
            for (i, x) in seen.iter().enumerate() {
                for y in &seen[..i] {
                    prop_assert!(x != y, "grid point {:?} tested twice", x);
                }
            }
            // A valid edge has had every grid point tested, exactly once.
            if full == EdgeStatus::Valid {
                let grid = EdgeGrid::new(space.distance(&a, &b), step);
                prop_assert_eq!(seen.len() as u64, grid.points());
                prop_assert_eq!(progress.tested(), grid.points());
            }
        }
    }

    #[test]
    fn sparse_budgets_grow_with_level_and_length(
        step in 1e-5f64..1e-2,
        short in 0.0f64..1.0,
        extra in 0.0f64..1.0,
        level in 0u32..20,
    ) {
        type C = dyn EdgeChecker<RealVectorSpace, World>;
        let long = short + extra;
        let mut adaptive = LengthAdaptiveChecker::new(step).unwrap();
        let mut fixed = FixedSparseChecker::new(step).unwrap();
        for _ in 0..level {
            <LengthAdaptiveChecker as EdgeChecker<RealVectorSpace, World>>::refine(&mut adaptive);
            <FixedSparseChecker as EdgeChecker<RealVectorSpace, World>>::refine(&mut fixed);
        }
        let (a, f): (&C, &C) = (&adaptive, &fixed);
        // Every edge gets at least its midpoint; longer edges get at least as many checks.
        prop_assert!(a.sparse_budget(short) >= 1);
        prop_assert!(a.sparse_budget(long) >= a.sparse_budget(short));
        prop_assert_eq!(f.sparse_budget(short), (1u64 << (level + 1)) - 1);
        // The adaptive spacing never goes below its floor of 10 L.
        prop_assert!(adaptive.spacing() >= 10.0 * step * (1.0 - 1e-12));
        let mut next = adaptive.clone();
        <LengthAdaptiveChecker as EdgeChecker<RealVectorSpace, World>>::refine(&mut next);
        let n: &C = &next;
        prop_assert!(n.sparse_budget(long) >= a.sparse_budget(long));
    }
}

#[test]
fn reset_returns_to_level_zero() {
    let mut checker = LengthAdaptiveChecker::new(1e-4).unwrap();
    let c: &mut dyn EdgeChecker<RealVectorSpace, World> = &mut checker;
    let initial = c.sparse_budget(1.0);
    c.refine();
    c.refine();
    assert_eq!(c.level(), 2);
    assert!(c.sparse_budget(1.0) > initial);
    c.reset();
    assert_eq!((c.level(), c.sparse_budget(1.0)), (0, initial));
}

#[test]
fn full_check_stops_when_told_and_resumes() {
    let space = RealVectorSpace::cube(2, -0.5, 0.5).unwrap();
    let world = World::in_space(&space);
    // One state at a time: the walk itself is stopped.
    let mut checker = DenseChecker::new(1e-5).unwrap().with_acceleration(false);
    let (a, b) = ([-0.4, 0.0], [0.4, 0.0]);
    let mut progress = EdgeProgress::default();
    let stopped = checker.check_full(&space, &world, &a, &b, &mut progress, &|| true);
    assert_eq!(stopped, EdgeStatus::Unknown);
    assert!(
        progress.tested() < 1000,
        "stopped after {} points",
        progress.tested()
    );
    let done = checker.check_full(&space, &world, &a, &b, &mut progress, &Never);
    assert_eq!(done, EdgeStatus::Valid);
    assert_eq!(progress.tested(), 79_999);
    // Accelerated, the empty world's broad phase decides the edge without a test: at once,
    // stop or not.
    let mut checker = DenseChecker::new(1e-5).unwrap();
    let mut progress = EdgeProgress::default();
    let done = checker.check_full(&space, &world, &a, &b, &mut progress, &|| true);
    assert_eq!((done, progress.tested()), (EdgeStatus::Valid, 79_999));
    let counters = <DenseChecker as EdgeChecker<RealVectorSpace, World>>::counters(&checker);
    assert_eq!(
        (counters.points_tested, counters.points_culled),
        (79_999, 79_999)
    );
}
