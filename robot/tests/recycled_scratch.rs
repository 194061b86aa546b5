//! A dropped arm checker leaves its scratch to the next clone on its thread; what the next
//! planner decides does not depend on it. RRT-Connect and MIT* planned on one thread, after
//! other plans (the Panda and the UR5, whose checkers differ in shape), find exactly the path,
//! cost and counters they find on a thread of their own.

use mit_star::{Configuration, FirstSolution, IterationLimit, Parameters, TerminationExt};
use mit_star_robot::{ArmProblem, ShippedRobot};
use std::path::Path;

use crate::cage_batches::cage;

/// The path, cost and counters of `configuration` with `seed` on `problem`, to its first
/// solution within 200 000 iterations.
fn plan(problem: &ArmProblem, configuration: Configuration, seed: u64) -> String {
    let parameters = Parameters {
        seed,
        ..Parameters::default()
    };
    let mut planner = mit_star::build_planner(configuration, problem, &parameters).unwrap();
    let outcome = planner
        .solve(&FirstSolution.or(IterationLimit::new(200_000)))
        .unwrap();
    format!("{outcome:?} {:?}", planner.counters())
}

/// The UR5's first `box` problem: a checker of another shape.
fn ur5() -> ArmProblem {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mbm/box_ur5");
    let robot = ShippedRobot::find("ur5").unwrap().model(false).unwrap();
    ArmProblem::mbm(robot, &folder, 1).unwrap()
}

#[test]
fn plans_after_other_plans_on_one_thread_are_those_of_a_fresh_thread() {
    let cases = [
        (Configuration::RrtConnect, 3),
        (Configuration::MitStar, 1),
        (Configuration::RrtConnect, 8),
    ];
    let fresh: Vec<String> = cases
        .iter()
        .map(|&(configuration, seed)| {
            std::thread::spawn(move || plan(&cage(), configuration, seed))
                .join()
                .unwrap()
        })
        .collect();
    let in_turn = std::thread::spawn(move || {
        let (panda, other) = (cage(), ur5());
        let mut seen = Vec::new();
        for &(configuration, seed) in &cases {
            // Another robot's plan in between leaves a spare of another shape.
            plan(&other, Configuration::RrtConnect, seed);
            seen.push(plan(&panda, configuration, seed));
            seen.push(plan(&panda, configuration, seed));
        }
        seen
    })
    .join()
    .unwrap();
    for (k, expected) in fresh.iter().enumerate() {
        assert_eq!(&in_turn[2 * k], expected, "{:?}", cases[k]);
        assert_eq!(&in_turn[2 * k + 1], expected, "{:?} again", cases[k]);
    }
    assert!(fresh.iter().all(|run| run.contains("Solved")), "{fresh:?}");
}
