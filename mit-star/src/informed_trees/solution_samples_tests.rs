//! Tests of the states a batch places along the best path (`solution_samples.rs`).

use mit_star_heuristics::{Euclidean, Heuristic};
use mit_star_samplers::SampleOrigin;
use mit_star_validity::StateValidity;

use crate::termination::SolveStop;
use crate::{IterationLimit, MitStar, Planner};
use mit_star_problems::PlanningProblem;

/// MIT* on the dividing walls of R^4 with `fraction` of each batch along the best path, after
/// iterations enough for a first solution, then one more batch.
fn planner_after_a_batch(fraction: f64) -> (MitStar, mit_star_problems::Problem) {
    let problem = mit_star_problems::DividingWalls::new(4)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let mut planner = MitStar::for_problem(&problem)
        .seed(5)
        .batch_size(200)
        .solution_samples(fraction)
        .build()
        .unwrap();
    let mut iterations = 0;
    while !planner.best_cost().is_finite() {
        planner.solve(&IterationLimit::new(500)).unwrap();
        iterations += 500;
        assert!(iterations < 200_000, "no first solution");
    }
    let limit = IterationLimit::new(u64::MAX);
    planner.add_batch(&SolveStop::new(&limit));
    (planner, problem)
}

#[test]
fn states_along_the_path_are_valid_informed_and_left_out_of_the_density() {
    let (planner, problem) = planner_after_a_batch(0.5);
    let graph = planner.graph();
    let along: Vec<_> = graph
        .vertices()
        .filter(|&(id, _)| graph.origin(id) == SampleOrigin::NearSolution)
        .collect();
    assert!(!along.is_empty(), "a batch with a solution places states");
    assert!(
        along.len() <= 100,
        "at most half of the batch: {}",
        along.len()
    );
    assert_eq!(planner.counters().solution_samples, along.len() as u64);
    let (space, start, goals) = (problem.space(), problem.start(), problem.goals());
    let world = problem.validity();
    for (_, x) in &along {
        assert!(world.is_valid(x));
        let through =
            Euclidean.cost_to_come(space, start, x) + Euclidean.cost_to_go(space, x, goals);
        assert!(
            through < planner.best_cost(),
            "{through} outside the informed set"
        );
    }
    assert_eq!(graph.density_count(), graph.vertex_count() - along.len());
}

#[test]
fn no_fraction_places_no_state() {
    let (planner, _) = planner_after_a_batch(0.0);
    let graph = planner.graph();
    assert!(
        graph
            .vertices()
            .all(|(id, _)| graph.origin(id) != SampleOrigin::NearSolution)
    );
    assert_eq!(planner.counters().solution_samples, 0);
}

/// The running corner weights of the path through `points` in the plane.
fn corner_weights_of(points: &[[f64; 2]]) -> Vec<f64> {
    let space = mit_star_spaces::RealVectorSpace::new(vec![-10.0; 2], vec![10.0; 2]).unwrap();
    let states: Vec<f64> = points.iter().flatten().copied().collect();
    let mut weights = Vec::new();
    super::solution_samples::cumulative_corner_weights(&space, &states, &mut weights);
    weights
}

#[test]
fn a_straight_path_has_no_corner_to_draw() {
    let weights = corner_weights_of(&[[0.0, 0.0], [1.0, 1.0], [1.5, 1.5], [3.0, 3.0]]);
    assert_eq!(weights.len(), 2, "one weight per interior vertex");
    assert!(weights.iter().all(|&w| w.abs() < 1e-12), "{weights:?}");
    let mut rng =
        <mit_star_spaces::SeededRng as mit_star_spaces::rand::SeedableRng>::seed_from_u64(1);
    assert_eq!(
        super::solution_samples::draw_corner(&weights, &mut rng),
        None
    );
    assert_eq!(super::solution_samples::draw_corner(&[], &mut rng), None);
}

/// A draw that rounding puts at the total still lands on a vertex that adds length, not on
/// the straight stretch after the last corner (interior vertices 1 to 4; 2 and 4 add none).
#[test]
fn a_draw_at_the_total_lands_on_the_last_corner() {
    use super::solution_samples::corner_at;
    let cumulative = [0.5, 0.5, 1.0, 1.0];
    assert_eq!(corner_at(&cumulative, 0.0), 1);
    assert_eq!(corner_at(&cumulative, 0.5), 3, "the running sum above 0.5");
    assert_eq!(corner_at(&cumulative, 0.99), 3);
    assert_eq!(
        corner_at(&cumulative, 1.0),
        3,
        "rounding's draw at the total"
    );
}

#[test]
fn corners_are_drawn_in_proportion_to_the_length_they_add() {
    // Vertex 2 turns by 90° (adds 2 − √2), vertex 4 by 45° with legs of 1 (adds
    // 2 − √(2 + √2)); vertices 1 and 3 lie on straight stretches and add nothing.
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let weights = corner_weights_of(&[
        [0.0, 0.0],
        [1.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [2.0, 2.0],
        [2.0 + s, 2.0 + s],
    ]);
    let right = 2.0 - 2f64.sqrt();
    let half_right = 2.0 - (2.0 + 2f64.sqrt()).sqrt();
    assert_eq!(weights.len(), 4);
    assert!(
        (weights[3] - right - half_right).abs() < 1e-12,
        "{weights:?}"
    );
    let mut rng =
        <mit_star_spaces::SeededRng as mit_star_spaces::rand::SeedableRng>::seed_from_u64(2);
    let mut drawn = [0usize; 6];
    let draws = 20_000_u32;
    for _ in 0..draws {
        drawn[super::solution_samples::draw_corner(&weights, &mut rng).unwrap()] += 1;
    }
    assert_eq!(drawn[0] + drawn[1] + drawn[3] + drawn[5], 0, "{drawn:?}");
    let share = drawn[2] as f64 / f64::from(draws);
    let expected = right / (right + half_right);
    // Five standard deviations of a binomial share.
    let tolerance = 5.0 * (expected * (1.0 - expected) / f64::from(draws)).sqrt();
    assert!(
        (share - expected).abs() < tolerance,
        "{share} against {expected}"
    );
}
