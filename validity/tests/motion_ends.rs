//! `EdgeChecker::check_full_and_end`: a full check of a motion and of its end state.
//!
//! Random box worlds and motions whose end may be invalid, checked one by one, in batches of
//! any width, and through the world's prepared segments: the answer is that of a full check
//! followed by a check of the end (valid exactly when every grid point and the end are), the
//! end is tested once (never twice, also across stops), walks stopped at any poll resume to the
//! same answer, and a motion checked from either end tests the state it was asked about.

use std::cell::{Cell, RefCell};

use mit_star_spaces::{Never, RealVectorSpace, Stop};
use mit_star_validity::{
    AxisBox, DenseChecker, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity, World,
};
use proptest::prelude::*;

/// A world tested in batches of `width` points (through `first_invalid`'s default, one by
/// one), recording every state asked about.
struct Recording<'a> {
    world: &'a World,
    width: usize,
    seen: RefCell<Vec<Vec<f64>>>,
}

impl StateValidity for Recording<'_> {
    fn is_valid(&self, state: &[f64]) -> bool {
        self.seen.borrow_mut().push(state.to_vec());
        self.world.is_valid(state)
    }

    fn batch_width(&self) -> usize {
        self.width
    }
}

/// Fires at every `every`-th poll (every second poll at most: a walk that polls before its
/// first point makes progress only between two polls that let it run).
struct Every {
    polls: Cell<u64>,
    every: u64,
}

impl Stop for Every {
    fn should_stop(&self) -> bool {
        self.polls.set(self.polls.get() + 1);
        self.polls.get().is_multiple_of(self.every)
    }
}

/// A world, a valid start and an end that may be invalid.
fn world_and_motion() -> impl Strategy<Value = (World, Vec<f64>, Vec<f64>)> {
    (1usize..=3).prop_flat_map(|n| {
        let boxes = prop::collection::vec(
            (
                prop::collection::vec(-0.5f64..0.5, n),
                prop::collection::vec(0.002f64..0.3, n),
            ),
            0..6,
        );
        let point = || prop::collection::vec(-0.5f64..0.5, n);
        (boxes, point(), point()).prop_filter_map("a valid start", move |(boxes, a, b)| {
            let mut world = World::new(vec![-0.5; n], vec![0.5; n]);
            for (center, widths) in boxes {
                world.add_obstacle(AxisBox::new(center, widths)).ok()?;
            }
            world.is_valid(&a).then_some((world, a, b))
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn the_end_is_checked_with_the_motion(
        (world, a, b) in world_and_motion(),
        step in 0.002f64..0.05,
        width in 1usize..=16,
        every in 2u64..5,
    ) {
        let space = RealVectorSpace::cube(a.len(), -0.5, 0.5).unwrap();
        let mut plain = DenseChecker::new(step).unwrap();
        let mut progress = EdgeProgress::default();
        let grid = plain.check_full(&space, &world, &a, &b, &mut progress, &Never);
        let expected = match grid {
            EdgeStatus::Valid if world.is_valid(&b) => EdgeStatus::Valid,
            _ => EdgeStatus::Invalid,
        };
        for reversed in [false, true] {
            // The motion `from → to`: its end `to` is the state checked.
            let (from, to) = if reversed { (&b, &a) } else { (&a, &b) };
            let expected = if reversed {
                let mut progress = EdgeProgress::default();
                match plain.check_full(&space, &world, from, to, &mut progress, &Never) {
                    EdgeStatus::Valid => EdgeStatus::Valid,
                    _ => EdgeStatus::Invalid,
                }
            } else {
                expected
            };
            // Batches of `width` (unprepared), and the world's own prepared segments.
            let recording = Recording { world: &world, width, seen: RefCell::new(Vec::new()) };
            let mut checker = DenseChecker::new(step).unwrap();
            let mut progress = EdgeProgress::default();
            let stop = Every { polls: Cell::new(0), every };
            let mut status = EdgeStatus::Unknown;
            for _ in 0..10_000 {
                status = checker.check_full_and_end(&space, &recording, from, to, &mut progress, &stop);
                if status != EdgeStatus::Unknown {
                    break;
                }
            }
            prop_assert_eq!(status, expected, "width {} reversed {}", width, reversed);
            let seen = recording.seen.into_inner();
            for (i, s) in seen.iter().enumerate() {
                prop_assert!(!seen[..i].contains(s), "{:?} tested twice", s);
            }
            // The end is among the states tested, unless a grid point failed first.
            let end_seen = seen.iter().any(|s| s.iter().zip(to.iter()).all(|(x, y)| (x - y).abs() <= 1e-12));
            let grid_failed = plain.check_full(&space, &world, from, to, &mut EdgeProgress::default(), &Never) == EdgeStatus::Invalid;
            prop_assert!(end_seen || grid_failed, "the end was not tested");
            let mut prepared: DenseChecker = DenseChecker::new(step).unwrap();
            let mut progress = EdgeProgress::default();
            let status = prepared.check_full_and_end(&space, &world, from, to, &mut progress, &Never);
            prop_assert_eq!(status, expected, "prepared, reversed {}", reversed);
            if status == EdgeStatus::Valid {
                // Checked again: nothing left to test.
                let before = EdgeChecker::<RealVectorSpace, World>::counters(&prepared).points_tested;
                let again = prepared.check_full_and_end(&space, &world, from, to, &mut progress, &Never);
                prop_assert_eq!(again, EdgeStatus::Valid);
                prop_assert_eq!(EdgeChecker::<RealVectorSpace, World>::counters(&prepared).points_tested, before);
            }
        }
    }
}
