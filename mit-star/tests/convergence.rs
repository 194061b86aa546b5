//! Asymptotic behaviour (spec §10): on problems with a known optimum, the cost approaches it as
//! the planner is given more iterations.

use crate::common;

use common::{assert_solution_sound, assert_trace_monotone, path_is_valid};
use mit_star::{
    Configuration, EitStar, IterationLimit, MitStar, Parameters, Planner, build_planner,
};
use mit_star_problems::{ObstacleFree, Problem, WallGap};

/// Costs after successive iteration budgets, and the final relative gap to the optimum.
fn costs_over_time(problem: &Problem, budgets: &[u64], seed: u64, mit: bool) -> Vec<f64> {
    let mut costs = Vec::new();
    if mit {
        let mut planner = MitStar::for_problem(problem).seed(seed).build().unwrap();
        for &b in budgets {
            let outcome = planner.solve(&IterationLimit::new(b)).unwrap();
            if let Some(s) = outcome.solution() {
                assert_solution_sound(&planner, s, problem.start(), problem.goals());
            }
            costs.push(outcome.cost());
        }
        assert_trace_monotone(&planner);
    } else {
        let mut planner = EitStar::for_problem(problem).seed(seed).build().unwrap();
        for &b in budgets {
            let outcome = planner.solve(&IterationLimit::new(b)).unwrap();
            if let Some(s) = outcome.solution() {
                assert_solution_sound(&planner, s, problem.start(), problem.goals());
            }
            costs.push(outcome.cost());
        }
        assert_trace_monotone(&planner);
    }
    costs
}

#[test]
fn wall_gap_cost_converges_toward_the_optimum() {
    let problem = WallGap::new(2)
        .build()
        .unwrap()
        .with_resolution(1e-4)
        .unwrap();
    let optimum = problem
        .optimum()
        .expect("wall gap has a closed-form optimum");
    for mit in [false, true] {
        let costs = costs_over_time(&problem, &[3_000, 20_000, 60_000], 21, mit);
        assert!(costs[0].is_finite(), "solved early: {costs:?}");
        assert!(costs.windows(2).all(|w| w[1] <= w[0]), "{costs:?}");
        // More time improves the path, unless the first one was already within 2 %.
        assert!(
            costs[2] < costs[0] || costs[0] / optimum - 1.0 < 0.02,
            "more time improved the path (MIT*: {mit}): {costs:?}"
        );
        let gap = costs[2] / optimum - 1.0;
        assert!(
            (0.0..0.05).contains(&gap),
            "within 5 % of {optimum}: {costs:?}"
        );
    }
}

#[test]
fn obstacle_free_r8_is_the_straight_line() {
    let problem = ObstacleFree::new(8).build().unwrap();
    let optimum = problem.optimum().unwrap();
    let costs = costs_over_time(&problem, &[100], 0, true);
    assert!((costs[0] - optimum).abs() <= 1e-12 * optimum);
}

#[test]
fn dividing_walls_r2_cost_converges_toward_the_optimum() {
    let problem = mit_star_problems::DividingWalls::new(2)
        .build()
        .unwrap()
        .with_resolution(1e-4)
        .unwrap();
    let optimum = problem.optimum().unwrap();
    // Iterations include every reverse-search step: 282 000 in all are about 0.25 s in release.
    // Six seeds: a run can stay in another homotopy class at this budget (seed 5 ends 14.6 %
    // above the optimum through another gap; 19 of seeds 0–19 end within 0.4 %).
    let mut close = 0;
    for seed in 0..6 {
        let costs = costs_over_time(&problem, &[2_000, 30_000, 250_000], seed, true);
        assert!(costs[0].is_finite(), "seed {seed}: {costs:?}");
        assert!(costs[2] < costs[0], "seed {seed}: {costs:?}");
        if costs[2] / optimum - 1.0 < 0.02 {
            close += 1;
        }
    }
    assert!(close >= 5, "{close} of 6 seeds within 2 % of {optimum}");
}

/// The conformance suite's convergence requirement, for every asymptotically optimal planner
/// selectable by name: on the wall gap in R^2 (optimum known in closed form) the cost after a
/// long run is within 5 % of the optimum, never increases between calls, and every path is
/// valid by the independent check.
#[test]
fn every_asymptotically_optimal_planner_converges_toward_the_optimum() {
    let problem = WallGap::new(2)
        .build()
        .unwrap()
        .with_resolution(1e-4)
        .unwrap();
    let optimum = problem.optimum().unwrap();
    let parameters = Parameters {
        seed: 3,
        ..Parameters::default()
    };
    for configuration in Configuration::ALL {
        if !configuration.is_asymptotically_optimal() {
            continue;
        }
        let mut planner = build_planner(configuration, &problem, &parameters).unwrap();
        let mut costs = Vec::new();
        for budget in [5_000, 60_000, 120_000] {
            let outcome = planner.solve(&IterationLimit::new(budget)).unwrap();
            if let Some(solution) = outcome.solution() {
                assert!(
                    path_is_valid(problem.world(), &solution.path, problem.step()),
                    "{configuration}: invalid path"
                );
            }
            costs.push(outcome.cost());
        }
        assert_trace_monotone(planner.as_ref());
        assert!(
            costs[0].is_finite(),
            "{configuration} solved early: {costs:?}"
        );
        assert!(
            costs.windows(2).all(|w| w[1] <= w[0]),
            "{configuration}: {costs:?}"
        );
        let gap = costs[2] / optimum - 1.0;
        assert!(
            (0.0..0.05).contains(&gap),
            "{configuration} within 5 % of {optimum}: {costs:?}"
        );
    }
}
