//! A query whose start is one of its goals (issue 74, item 17): every configuration returns
//! the trivial path `(start, goal)` of cost 0 — RRT-Connect returned a detour of cost 5.37.

use std::time::Duration;

use mit_star::{
    Configuration, IterationLimit, Parameters, TerminationExt, TimeLimit, build_planner,
};

fn problem(goals: &str) -> mit_star_problems::Problem {
    let text = format!(
        "name = 'start-is-goal'\nstart = [-0.2, 0.1]\n{goals}\n\
         [bounds]\nlower = [-0.5, -0.5]\nupper = [0.5, 0.5]\n\
         [[obstacles]]\ncenter = [0.2, 0.0]\nwidths = [0.1, 0.6]\n"
    );
    mit_star_problems::Problem::from_toml_str(&text).unwrap()
}

#[test]
fn every_configuration_returns_the_trivial_path() {
    for goals in [
        "goal = [-0.2, 0.1]",
        // The start among several goals, not the first.
        "goals = [[0.4, 0.3], [-0.2, 0.1]]",
    ] {
        let problem = problem(goals);
        for configuration in Configuration::ALL {
            for seed in [0, 7] {
                let parameters = Parameters {
                    seed,
                    ..Parameters::default()
                };
                let mut planner = build_planner(configuration, &problem, &parameters).unwrap();
                let stop = IterationLimit::new(200).or(TimeLimit::new(Duration::from_secs(2)));
                let outcome = planner.solve(&stop).unwrap();
                let solution = outcome
                    .solution()
                    .unwrap_or_else(|| panic!("{configuration} ({goals}): no solution"));
                assert_eq!(
                    solution.cost, 0.0,
                    "{configuration} ({goals}): {solution:?}"
                );
                assert_eq!(solution.path.len(), 2, "{configuration} ({goals})");
                assert_eq!(&solution.path[0], problem.start(), "{configuration}");
                assert_eq!(&solution.path[1], problem.start(), "{configuration}");
                assert_eq!(planner.best_cost(), 0.0, "{configuration}");
            }
        }
    }
}
