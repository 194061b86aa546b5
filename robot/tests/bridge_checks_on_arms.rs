//! Arm problems ask MIT*'s adaptive sampler to test [`ArmProblem::BRIDGE_CHECKS`] segment
//! points per repair; box worlds keep the spec's 8, and a set `bridge_checks` wins over either.
//! The problem's number reaches the sampler: MIT* built for the cage with no setting does
//! exactly what it does with 4 set, and not what it does with 8.

use mit_star::{Configuration, Counters, IterationLimit, MitStar, Parameters, Planner};
use mit_star_problems::{DEFAULT_BRIDGE_CHECKS, PlanningProblem};
use mit_star_robot::ArmProblem;

use crate::cage_batches::cage;

#[test]
fn arm_problems_test_fewer_segment_points_unless_told_otherwise() {
    let arm = cage();
    assert_eq!(arm.bridge_checks(), ArmProblem::BRIDGE_CHECKS);
    const { assert!(ArmProblem::BRIDGE_CHECKS > 0 && ArmProblem::BRIDGE_CHECKS < 8) };
    assert_eq!(DEFAULT_BRIDGE_CHECKS, 8);
    let boxes = mit_star_problems::DividingWalls::new(2).build().unwrap();
    assert_eq!(boxes.bridge_checks(), DEFAULT_BRIDGE_CHECKS);
    let defaults = Parameters::default();
    assert_eq!(defaults.bridge_checks, None);
    let set = Parameters {
        bridge_checks: Some(DEFAULT_BRIDGE_CHECKS),
        ..Parameters::default()
    };
    for configuration in [Configuration::MitStar, Configuration::MitStarEis] {
        let on_arm = configuration.effective_parameters(&arm, &defaults).unwrap();
        assert_eq!(
            on_arm.bridge_checks,
            Some(ArmProblem::BRIDGE_CHECKS),
            "{configuration}"
        );
        let in_boxes = configuration
            .effective_parameters(&boxes, &defaults)
            .unwrap();
        assert_eq!(
            in_boxes.bridge_checks,
            Some(DEFAULT_BRIDGE_CHECKS),
            "{configuration}"
        );
        let kept = configuration.effective_parameters(&arm, &set).unwrap();
        assert_eq!(
            kept.bridge_checks,
            Some(DEFAULT_BRIDGE_CHECKS),
            "{configuration}"
        );
    }
}

/// MIT*'s counters after 3 000 iterations on the cage (seed 1), with `bridge_checks` set
/// where given.
fn run(bridge_checks: Option<usize>) -> Counters {
    let mut builder = MitStar::for_problem(&cage()).seed(1);
    if let Some(checks) = bridge_checks {
        builder = builder.bridge_checks(checks);
    }
    let mut planner = builder.build().unwrap();
    planner.solve(&IterationLimit::new(3_000)).unwrap();
    planner.counters()
}

#[test]
fn the_sampler_repairs_with_the_problems_budget_or_the_one_it_is_given() {
    let default = run(None);
    let four = run(Some(ArmProblem::BRIDGE_CHECKS));
    let eight = run(Some(DEFAULT_BRIDGE_CHECKS));
    assert!(default.sampler_restarts > 0, "{default:?}");
    // Same decisions as with the budget set explicitly.
    assert_eq!(
        (
            default.samples,
            default.sampler_checks,
            default.sampler_bridge
        ),
        (four.samples, four.sampler_checks, four.sampler_bridge)
    );
    // A larger budget tests more points per failed repair.
    assert_ne!(default.sampler_checks, eight.sampler_checks);
}
