//! Properties of every built-in family in every dimension from 2 to 16: endpoints valid, the
//! straight line blocked where the spec says so, gaps passable and enclosures closed, random
//! rectangles a function of the seed, and problem files round-tripping every problem.

use mit_star_problems::{
    CenterSquare, DividingWalls, DoubleEnclosure, FlankingGap, GoalEnclosure, NarrowPassage,
    ObstacleFree, Problem, RandomRectangles, RepeatingRectangles, StartEnclosure, WallGap,
    catalogue,
};
use mit_star_spaces::StateSpace;
use mit_star_validity::StateValidity;
use proptest::prelude::*;

const DIMENSIONS: std::ops::RangeInclusive<usize> = 2..=16;

/// Every family, built with its defaults in `n` dimensions.
fn all_families(n: usize, seed: u64) -> Vec<Problem> {
    catalogue()
        .iter()
        .map(|family| {
            family
                .build(n, seed)
                .unwrap_or_else(|e| panic!("{} in R^{n}: {e}", family.name()))
        })
        .collect()
}

/// `true` if some point of the segment from `a` to `b`, sampled at `samples + 1` evenly
/// spaced points, is invalid.
fn segment_blocked(problem: &Problem, a: &[f64], b: &[f64], samples: usize) -> bool {
    let mut point = vec![0.0; a.len()];
    (0..=samples).any(|i| {
        let t = i as f64 / samples as f64;
        for ((p, x), y) in point.iter_mut().zip(a).zip(b) {
            *p = x + (y - x) * t;
        }
        !problem.world().is_valid(&point)
    })
}

fn straight_line_blocked(problem: &Problem) -> bool {
    segment_blocked(problem, problem.start(), &problem.goals()[0], 50_000)
}

/// `(x, y, 0, …, 0)` in `R^n`.
fn point(n: usize, x: f64, y: f64) -> Vec<f64> {
    let mut p = vec![0.0; n];
    p[0] = x;
    p[1] = y;
    p
}

#[test]
fn endpoints_are_valid_in_every_dimension() {
    for n in DIMENSIONS {
        for problem in all_families(n, 7) {
            assert!(problem.validate().is_ok(), "{} R^{n}", problem.name());
            assert_eq!(problem.dimension(), n);
            assert!(
                problem.world().is_valid(problem.start()),
                "{}",
                problem.name()
            );
            for goal in problem.goals() {
                assert!(problem.space().contains(goal), "{}", problem.name());
                assert!(problem.world().is_valid(goal), "{}", problem.name());
            }
        }
    }
}

#[test]
fn straight_line_is_blocked_where_the_spec_says() {
    for n in DIMENSIONS {
        let blocked = [
            FlankingGap::new(n).build().unwrap(),
            DividingWalls::new(n).build().unwrap(),
            GoalEnclosure::new(n).build().unwrap(),
            StartEnclosure::new(n).build().unwrap(),
            DoubleEnclosure::new(n).build().unwrap(),
            CenterSquare::new(n).build().unwrap(),
            WallGap::new(n).build().unwrap(),
            NarrowPassage::new(n).build().unwrap(),
            RepeatingRectangles::new(n).build().unwrap(),
        ];
        for problem in blocked {
            assert!(straight_line_blocked(&problem), "{} R^{n}", problem.name());
            // A blocked straight line means a strictly longer optimum, where one is known.
            if let Some(optimum) = problem.optimum() {
                assert!(
                    optimum > problem.straight_line_cost() + 1e-3,
                    "{}",
                    problem.name()
                );
            }
        }
        let free = ObstacleFree::new(n).build().unwrap();
        assert!(!straight_line_blocked(&free));
        assert_eq!(free.optimum(), Some(free.straight_line_cost()));
    }
}

#[test]
fn known_optima_never_beat_the_straight_line() {
    for n in DIMENSIONS {
        for problem in all_families(n, 0) {
            if let Some(optimum) = problem.optimum() {
                assert!(
                    optimum >= problem.straight_line_cost(),
                    "{}",
                    problem.name()
                );
            }
        }
    }
}

#[test]
fn flanking_gap_is_passable_and_the_wall_is_not() {
    for n in DIMENSIONS {
        let problem = FlankingGap::new(n).build().unwrap();
        let world = problem.world();
        let (offset, width, half_wall) = if n == 2 {
            (0.2, 0.03, 0.35)
        } else {
            (0.1, 0.01, 0.4)
        };
        // Through the gap, all along the wall's thickness.
        for x in [-0.05, -0.02, 0.0, 0.03, 0.05] {
            assert!(
                world.is_valid(&point(n, x, offset + width / 2.0)),
                "R^{n} x={x}"
            );
        }
        // In the wall, beside the gap and elsewhere.
        for y in [
            0.0,
            offset - 0.005,
            offset + width + 0.005,
            -half_wall + 0.01,
        ] {
            assert!(!world.is_valid(&point(n, 0.0, y)), "R^{n} y={y}");
        }
        if n > 2 {
            // The gap is a square hole, not a slot: off it in z is wall.
            let mut p = point(n, 0.0, offset + width / 2.0);
            p[2] = width;
            assert!(!world.is_valid(&p), "R^{n}");
        }
        // The flanking corridor.
        assert!(world.is_valid(&point(n, 0.0, half_wall + 0.01)));
        // The segment through the gap's centre line is free end to end.
        let y = offset + width / 2.0;
        assert!(!segment_blocked(
            &problem,
            &point(n, -0.2, y),
            &point(n, 0.2, y),
            10_000
        ));
    }
}

#[test]
fn goal_enclosure_is_closed_but_for_its_opening() {
    for n in DIMENSIONS {
        let problem = GoalEnclosure::new(n).build().unwrap();
        let world = problem.world();
        // Shell: x ∈ [0.075, 0.1] ∪ [0.3, 0.325], every other |coordinate| ∈ [0.1, 0.125].
        assert!(!world.is_valid(&point(n, 0.0875, 0.0)), "R^{n} −x face");
        assert!(!world.is_valid(&point(n, 0.2, 0.1125)), "R^{n} +y face");
        assert!(!world.is_valid(&point(n, 0.2, -0.1125)), "R^{n} −y face");
        let mut last = point(n, 0.2, 0.0);
        last[n - 1] = 0.1125;
        assert!(!world.is_valid(&last), "R^{n} face in the last coordinate");
        assert!(
            !world.is_valid(&point(n, 0.3125, 0.1125)),
            "R^{n} +x face beside the opening"
        );
        // The opening and the hollow.
        assert!(world.is_valid(&point(n, 0.3125, 0.0)), "R^{n} opening");
        assert!(
            world.is_valid(&point(n, 0.3125, 0.099)),
            "R^{n} opening edge"
        );
        assert!(world.is_valid(&point(n, 0.25, 0.05)), "R^{n} hollow");
        // A ray from the goal leaves through the opening and nowhere else.
        let goal = &problem.goals()[0];
        assert!(!segment_blocked(
            &problem,
            goal,
            &point(n, 0.45, 0.0),
            10_000
        ));
        assert!(segment_blocked(
            &problem,
            goal,
            &point(n, -0.45, 0.0),
            10_000
        ));
        assert!(segment_blocked(
            &problem,
            goal,
            &point(n, 0.2, 0.45),
            10_000
        ));
    }
}

#[test]
fn lower_dimensions_are_refused_by_name() {
    for family in catalogue() {
        for n in [0, 1] {
            let err = family.build(n, 0).unwrap_err();
            assert_eq!(
                err.to_string(),
                format!("{} needs at least 2 dimensions, got {n}", family.name())
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn random_rectangles_are_a_function_of_the_seed(n in 2usize..=16, seed in any::<u64>()) {
        let a = RandomRectangles::new(n).seed(seed).build().unwrap();
        let b = RandomRectangles::new(n).seed(seed).build().unwrap();
        prop_assert_eq!(&a, &b);
        prop_assert_eq!(a.world().obstacles().len(), 35);
        prop_assert!(a.validate().is_ok());
        prop_assert!(a.world().is_valid(a.start()));
        prop_assert!(a.world().is_valid(&a.goals()[0]));
        for b in a.world().obstacles() {
            prop_assert!(b.center.iter().all(|c| (-0.5..=0.5).contains(c)));
            prop_assert!(b.widths.iter().all(|w| (0.1..=0.2).contains(w)));
        }
        let other = RandomRectangles::new(n).seed(seed.wrapping_add(1)).build().unwrap();
        prop_assert_ne!(a.world().obstacles(), other.world().obstacles());
    }

    #[test]
    fn problem_files_round_trip_every_family(
        index in 0..catalogue().len(),
        n in 2usize..=16,
        seed in any::<u64>(),
        resolution in 1e-7f64..1e-2,
    ) {
        let family = &catalogue()[index];
        let problem = family.build(n, seed).unwrap().with_resolution(resolution).unwrap();
        let text = problem.to_toml_string();
        let back = Problem::from_toml_str(&text);
        prop_assert!(back.is_ok(), "{}: {:?}\n{}", family.name(), back, text);
        prop_assert_eq!(back.unwrap(), problem);
    }
}
