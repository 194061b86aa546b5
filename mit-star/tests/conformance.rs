//! Conformance: every configuration on PDT's flanking gap, dividing walls, goal enclosure and
//! random rectangles in R^2, R^4 and R^8, at the paper's resolution. Every returned path must be
//! valid and every trace monotone; the easier problems must be solved within the budget.

use crate::common;

use std::time::Duration;

use common::{assert_trace_monotone, path_is_valid};
use mit_star::{
    Configuration, IterationLimit, Parameters, TerminationExt, TimeLimit, build_planner,
};

/// Iterations per run (plus a wall-clock cap so a slow machine cannot stall the suite).
const ITERATIONS: u64 = 8_000;

#[test]
fn every_configuration_on_every_problem_family() {
    let mut report = Vec::new();
    for family in [
        "flanking-gap",
        "dividing-walls",
        "goal-enclosure",
        "random-rectangles",
    ] {
        for n in [2, 4, 8] {
            let problem = mit_star_problems::builtin(family, n, 1).expect("a built-in problem");
            for configuration in Configuration::ALL {
                let parameters = Parameters {
                    seed: 7,
                    ..Parameters::default()
                };
                let mut planner = build_planner(configuration, &problem, &parameters).unwrap();
                assert_eq!(planner.name(), configuration.label());
                let stop =
                    IterationLimit::new(ITERATIONS).or(TimeLimit::new(Duration::from_secs(3)));
                let outcome = planner.solve(&stop).unwrap();
                assert_trace_monotone(planner.as_ref());
                if let Some(solution) = outcome.solution() {
                    let step = problem.step();
                    assert!(
                        path_is_valid(problem.world(), &solution.path, step),
                        "{configuration} on {family} R^{n}: invalid path"
                    );
                    assert_eq!(&solution.path[0], problem.start());
                    assert!(solution.cost >= problem.straight_line_cost() - 1e-12);
                    if let Some(optimum) = problem.optimum() {
                        assert!(
                            solution.cost >= optimum - 1e-9,
                            "{family} R^{n} beat its optimum"
                        );
                    }
                }
                report.push((family, n, configuration, outcome.cost()));
                // The easier instances must be solved within the budget — except goal
                // enclosure R^4 by Informed RRT*, which rarely escapes the enclosure's far
                // opening in time (3 of 100 runs in 0.1 s in `paper-planners`; OMPL's own
                // Informed RRT* 4 of 100).
                let weak = configuration == Configuration::InformedRrtStar
                    && family == "goal-enclosure"
                    && n == 4;
                let easy = n <= 4 && family != "random-rectangles" && !weak;
                assert!(
                    !easy || outcome.is_solved(),
                    "{configuration} failed {family} R^{n} in {ITERATIONS} iterations"
                );
            }
        }
    }
    for r in &report {
        println!("{:18} R^{} {:13} {:.4}", r.0, r.1, r.2.label(), r.3);
    }
    let solved = report.iter().filter(|r| r.3.is_finite()).count();
    assert!(
        solved * 10 >= report.len() * 8,
        "only {solved}/{} runs solved: {report:?}",
        report.len()
    );
}
