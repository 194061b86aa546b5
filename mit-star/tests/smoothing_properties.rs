//! Property test of the smoothing pass: random valid paths over a wall among random boxes stay
//! valid, keep their ends and get no longer, whatever the smoothing moves.

use mit_star::{PathSimplifier, SmoothingMoves};
use mit_star_problems::Problem;
use mit_star_spaces::StateSpace;
use mit_star_validity::{AxisBox, World};
use proptest::prelude::*;

/// A random instance: the dimension, the wall's height, boxes (centre, widths), waypoints on
/// the near side, the crossing point's height above the wall, waypoints on the far side, the
/// seed and the smoothing moves.
type Instance = (
    usize,
    f64,
    Vec<(Vec<f64>, Vec<f64>)>,
    Vec<Vec<f64>>,
    f64,
    Vec<Vec<f64>>,
    u64,
    u8,
);

/// The unit cube of `dimension` with a wall at `x₀ ∈ [0.49, 0.51]` from the floor of `x₁` to
/// `height`, and `boxes`; and a valid path from the first near waypoint over the wall to the
/// last far one, through every waypoint whose segment from the one before is valid. `None` if
/// the ends are not valid or do not join.
fn world_and_path(
    (dimension, height, boxes, near, over, far, _, _): &Instance,
) -> Option<(Problem, Vec<Vec<f64>>)> {
    let (dimension, height, over) = (*dimension, *height, *over);
    let mut world = World::new(vec![0.0; dimension], vec![1.0; dimension]);
    let mut center = vec![0.5; dimension];
    let mut widths = vec![1.0; dimension];
    (center[1], widths[0], widths[1]) = (height / 2.0, 0.02, height);
    world.add_obstacle(AxisBox::new(center, widths)).ok()?;
    for (center, widths) in boxes {
        world
            .add_obstacle(AxisBox::new(center.clone(), widths.clone()))
            .ok()?;
    }
    let mut crossing = vec![0.5; dimension];
    crossing[1] = height + over * (1.0 - height);
    // Near waypoints on the near side of the wall, far ones on the far side.
    let side = |p: &Vec<f64>, near: bool| {
        let mut p = p.clone();
        p[0] = if near { 0.45 * p[0] } else { 1.0 - 0.45 * p[0] };
        p
    };
    let waypoints = near
        .iter()
        .map(|p| side(p, true))
        .chain(std::iter::once(crossing.clone()))
        .chain(far.iter().map(|p| side(p, false)));
    let mut path: Vec<Vec<f64>> = Vec::new();
    for point in waypoints {
        let joins = path
            .last()
            .map_or(world.segment_verdict(&point, &point), |last| {
                world.segment_verdict(last, &point)
            })
            .is_valid();
        if joins {
            path.push(point);
        } else if point == crossing || path.is_empty() {
            return None;
        }
    }
    if path.last()? == &crossing {
        return None;
    }
    let goal = path[path.len() - 1].clone();
    let problem = Problem::new("over a wall", world, path[0].clone(), vec![goal])
        .ok()?
        .with_resolution(1e-3)
        .ok()?;
    Some((problem, path))
}

fn instance() -> impl Strategy<Value = Instance> {
    (2usize..=4).prop_flat_map(|n| {
        let point = move || prop::collection::vec(0.0f64..1.0, n);
        (
            Just(n),
            0.4f64..0.9,
            prop::collection::vec(
                (
                    prop::collection::vec(0.0f64..1.0, n),
                    prop::collection::vec(0.02f64..0.2, n),
                ),
                0..20,
            ),
            prop::collection::vec(point(), 1..8),
            0.05f64..0.95,
            prop::collection::vec(point(), 1..8),
            any::<u64>(),
            0u8..3,
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn smoothed_paths_stay_valid_keep_their_ends_and_get_no_longer(instance in instance()) {
        let Some((problem, path)) = world_and_path(&instance) else {
            return Ok(());
        };
        let (seed, moves) = (instance.6, instance.7);
        let moves = [SmoothingMoves::Relax, SmoothingMoves::Perturb, SmoothingMoves::RelaxThenPerturb]
            [usize::from(moves)];
        // Smoothing right after vertex reduction, no shortcuts.
        let simplifier = PathSimplifier::new()
            .seed(seed)
            .attempts(0)
            .smoothing_moves(moves)
            .smoothing_rounds(20);
        let smoothed = simplifier.simplify(&problem, &path, &mit_star_spaces::Never).unwrap();
        prop_assert_eq!(smoothed.path.first(), path.first());
        prop_assert_eq!(smoothed.path.last(), path.last());
        prop_assert!(smoothed.cost <= smoothed.original_cost + 1e-12);
        let length: f64 = smoothed
            .path
            .windows(2)
            .map(|w| problem.space().distance(&w[0], &w[1]))
            .sum();
        prop_assert!((length - smoothed.cost).abs() <= 1e-9);
        for w in smoothed.path.windows(2) {
            prop_assert!(
                problem.world().segment_verdict(&w[0], &w[1]).is_valid(),
                "{:?} -> {:?}", w[0], w[1]
            );
        }
    }
}
