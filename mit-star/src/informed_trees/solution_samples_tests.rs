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
