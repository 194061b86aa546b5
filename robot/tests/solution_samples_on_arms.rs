//! Arm problems ask the EIT* family to place [`ArmProblem::SOLUTION_SAMPLES`] of each batch
//! along the best path once there is one; box worlds place none (the papers' sampling), and a
//! set `solution_samples` wins over either. On a Panda box problem the path at the end goes
//! through placed states and is shorter than the same seed's path without them.

use std::path::Path;

use mit_star::{Configuration, IterationLimit, MitStar, Parameters, Planner};
use mit_star_problems::PlanningProblem;
use mit_star_robot::ArmProblem;
use mit_star_samplers::SampleOrigin;

use crate::cage_batches::cage;

/// The fraction `configuration` places along the path on `problem` given `parameters`.
fn fraction<P: PlanningProblem>(
    configuration: Configuration,
    problem: &P,
    parameters: &Parameters,
) -> Option<f64> {
    let effective = configuration
        .effective_parameters(problem, parameters)
        .unwrap();
    effective.solution_samples
}

#[test]
fn arm_problems_place_states_along_the_path_unless_told_otherwise() {
    let arm = cage();
    assert_eq!(arm.solution_samples(), ArmProblem::SOLUTION_SAMPLES);
    const { assert!(ArmProblem::SOLUTION_SAMPLES > 0.0 && ArmProblem::SOLUTION_SAMPLES < 1.0) };
    let boxes = mit_star_problems::DividingWalls::new(2).build().unwrap();
    assert_eq!(boxes.solution_samples(), 0.0);
    let defaults = Parameters::default();
    let none = Parameters {
        solution_samples: Some(0.0),
        ..Parameters::default()
    };
    for configuration in [Configuration::MitStar, Configuration::EitStar] {
        let on_arm = fraction(configuration, &arm, &defaults);
        assert_eq!(on_arm, Some(ArmProblem::SOLUTION_SAMPLES));
        assert_eq!(fraction(configuration, &boxes, &defaults), Some(0.0));
        assert_eq!(fraction(configuration, &arm, &none), Some(0.0));
    }
}

/// Over four seeds (one seed's draw can go either way): MIT* with states placed along its
/// best path ends with shorter paths in sum, and some of them go through placed states.
#[test]
fn states_along_the_path_shorten_it_on_the_box() {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mbm/box_panda");
    let arm = ArmProblem::panda_mbm(&folder, 1).unwrap();
    let run = |fraction: f64, seed: u64| {
        let mut planner = MitStar::for_problem(&arm)
            .seed(seed)
            .solution_samples(fraction)
            .build()
            .unwrap();
        let outcome = planner.solve(&IterationLimit::new(200_000)).unwrap();
        let cost = outcome.solution().expect("a path").cost;
        let graph = planner.graph();
        let through = planner
            .solution_vertices()
            .iter()
            .filter(|&&v| graph.origin(v) == SampleOrigin::NearSolution)
            .count();
        (cost, through, planner.counters().solution_samples)
    };
    let (mut with, mut without, mut through) = (0.0, 0.0, 0);
    for seed in 3..7 {
        let (cost_without, _, placed_without) = run(0.0, seed);
        let (cost_with, through_with, placed) = run(ArmProblem::SOLUTION_SAMPLES, seed);
        assert_eq!(placed_without, 0);
        assert!(placed > 0, "seed {seed}: no state placed along the path");
        (with, without, through) = (
            with + cost_with,
            without + cost_without,
            through + through_with,
        );
    }
    assert!(through > 0, "no path goes through a placed state");
    assert!(
        with < without,
        "{with} in sum with the placed states, {without} without"
    );
}
