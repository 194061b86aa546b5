//! Batched edge checks against the one-by-one path.
//!
//! A checker with [`StateValidity::batch_width`] `> 1` receives grid points in batches. For
//! every edge checker, random worlds, edges, batch widths and sequences of sparse and full
//! checks: the statuses and progress equal those of the one-by-one walk, no grid point is
//! tested twice, the batched walk tests exactly the one-by-one walk's points up to its first
//! invalid point plus at most the rest of that batch, and polls of the stop condition fall on
//! the same positions.

use std::cell::{Cell, RefCell};

use mit_star_spaces::{Never, RealVectorSpace, Stop};
use mit_star_validity::{
    AxisBox, DenseChecker, EdgeChecker, EdgeProgress, EdgeStatus, FixedSparseChecker,
    LengthAdaptiveChecker, STOP_POLL, StateValidity, World,
};
use proptest::prelude::*;

/// A world checked in batches of `width` (every state of a batch is tested, as SIMD lanes
/// would be), recording each state asked about and each batch's size.
struct Batched<'a> {
    world: &'a World,
    width: usize,
    seen: RefCell<Vec<Vec<f64>>>,
    batches: RefCell<Vec<usize>>,
}

impl<'a> Batched<'a> {
    fn new(world: &'a World, width: usize) -> Self {
        Self {
            world,
            width,
            seen: RefCell::new(Vec::new()),
            batches: RefCell::new(Vec::new()),
        }
    }
}

impl StateValidity for Batched<'_> {
    fn is_valid(&self, state: &[f64]) -> bool {
        self.seen.borrow_mut().push(state.to_vec());
        self.world.is_valid(state)
    }

    fn batch_width(&self) -> usize {
        self.width
    }

    fn first_invalid(&self, states: &[f64], dimension: usize) -> Option<usize> {
        let n = states.len() / dimension;
        assert!(
            n >= 1 && n <= self.width,
            "a batch of {n} for width {}",
            self.width
        );
        self.batches.borrow_mut().push(n);
        // All lanes first, then the first invalid one: what a SIMD checker does.
        let valid: Vec<bool> = states
            .chunks_exact(dimension)
            .map(|s| self.is_valid(s))
            .collect();
        valid.iter().position(|v| !v)
    }
}

/// Fires from poll number `at` on, counting polls.
struct PollAt {
    polls: Cell<u64>,
    at: u64,
}

impl Stop for PollAt {
    fn should_stop(&self) -> bool {
        self.polls.set(self.polls.get() + 1);
        self.polls.get() >= self.at
    }
}

fn world_and_edge() -> impl Strategy<Value = (World, Vec<f64>, Vec<f64>)> {
    (1usize..=4).prop_flat_map(|n| {
        let boxes = prop::collection::vec(
            (
                prop::collection::vec(-0.5f64..0.5, n),
                prop::collection::vec(0.002f64..0.3, n),
            ),
            0..6,
        );
        let point = || prop::collection::vec(-0.5f64..0.5, n);
        (boxes, point(), point()).prop_filter_map("valid ends", move |(boxes, a, b)| {
            let mut world = World::new(vec![-0.5; n], vec![0.5; n]);
            for (center, widths) in boxes {
                world.add_obstacle(AxisBox::new(center, widths)).ok()?;
            }
            (world.is_valid(&a) && world.is_valid(&b)).then_some((world, a, b))
        })
    })
}

type Checker<'a> = Box<dyn EdgeChecker<RealVectorSpace, Batched<'a>> + 'a>;

fn checker<'a>(kind: usize, step: f64) -> Checker<'a> {
    match kind {
        0 => Box::new(DenseChecker::new(step).unwrap()),
        1 => Box::new(FixedSparseChecker::new(step).unwrap()),
        _ => Box::new(
            LengthAdaptiveChecker::with_parameters(step, 40.0 * step, 0.5, 2.0 * step).unwrap(),
        ),
    }
}

/// Statuses and progress after each check, the states tested, the batch sizes.
type Walked = (Vec<(EdgeStatus, EdgeProgress)>, Vec<Vec<f64>>, Vec<usize>);

/// One check: `(sparse?, reversed?, refine before?)`.
type Plan = Vec<(bool, bool, bool)>;

/// Runs `plan` on the edge with a checker of `width`, returning statuses, progress after each
/// check, the states tested and the batch sizes.
fn run(
    (world, a, b): (&World, &[f64], &[f64]),
    (kind, step, width): (usize, f64, usize),
    plan: &Plan,
    stop: &dyn Stop,
) -> Walked {
    let space = RealVectorSpace::cube(a.len(), -0.5, 0.5).unwrap();
    let validity = Batched::new(world, width);
    let mut checker = checker(kind, step);
    let mut progress = EdgeProgress::default();
    let mut out = Vec::new();
    for &(sparse, reversed, refine) in plan {
        if refine {
            checker.refine();
        }
        let (u, v) = if reversed { (b, a) } else { (a, b) };
        let status = if sparse {
            checker.check_sparse(&space, &validity, u, v, &mut progress, stop)
        } else {
            checker.check_full(&space, &validity, u, v, &mut progress, stop)
        };
        out.push((status, progress));
    }
    (
        out,
        validity.seen.into_inner(),
        validity.batches.into_inner(),
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn batched_walks_answer_exactly_as_one_by_one_walks(
        (world, a, b) in world_and_edge(),
        kind in 0usize..3,
        step in 0.001f64..0.05,
        width in 2usize..=16,
        plan in prop::collection::vec((any::<bool>(), any::<bool>(), any::<bool>()), 1..6),
    ) {
        let edge = (&world, &a[..], &b[..]);
        let (one, one_seen, _) = run(edge, (kind, step, 1), &plan, &Never);
        let (many, many_seen, batches) = run(edge, (kind, step, width), &plan, &Never);
        prop_assert_eq!(&one, &many);
        // No grid point twice.
        for (i, s) in many_seen.iter().enumerate() {
            prop_assert!(!many_seen[..i].contains(s), "{:?} tested twice", s);
        }
        // The same points in the same order, plus at most the rest of the batch that found
        // the invalid point.
        prop_assert_eq!(&many_seen[..one_seen.len()], &one_seen[..]);
        let extra = many_seen.len() - one_seen.len();
        let invalid = one.iter().any(|(s, _)| *s == EdgeStatus::Invalid);
        prop_assert!(extra == 0 || (invalid && extra < width), "{} extra points", extra);
        prop_assert!(batches.iter().all(|&n| n <= width));
    }

    #[test]
    fn batched_walks_poll_where_one_by_one_walks_poll(
        (world, a, b) in world_and_edge(),
        width in 2usize..=16,
        at in 1u64..5,
    ) {
        let edge = (&world, &a[..], &b[..]);
        let plan = vec![(false, false, false)];
        let step = 2e-4; // long walks: many poll periods
        let (one_stop, many_stop) = (PollAt { polls: Cell::new(0), at }, PollAt { polls: Cell::new(0), at });
        let (one, one_seen, _) = run(edge, (0, step, 1), &plan, &one_stop);
        let (many, many_seen, _) = run(edge, (0, step, width), &plan, &many_stop);
        prop_assert_eq!(&one, &many);
        prop_assert_eq!(one_stop.polls.get(), many_stop.polls.get());
        if one[0].0 == EdgeStatus::Unknown {
            prop_assert_eq!(one_seen.len(), many_seen.len());
            prop_assert_eq!(one_seen.len() as u64 % STOP_POLL, 0);
        }
    }
}
