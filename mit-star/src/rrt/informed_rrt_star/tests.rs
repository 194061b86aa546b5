//! Tests of [`InformedRrtStar`](super::InformedRrtStar).

use std::time::Duration;

use super::*;
use crate::{FirstSolution, IterationLimit, Solution, TerminationExt, TimeLimit};

/// Every edge of the path valid in the world, the path from the start to a goal, its cost the
/// sum of its edges.
fn assert_valid(problem: &mit_star_problems::Problem, solution: &Solution) {
    let path = &solution.path;
    assert_eq!(&path[0], problem.start());
    assert!(
        problem
            .goals()
            .iter()
            .any(|g| path[path.len() - 1] == g[..])
    );
    let mut cost = 0.0;
    for (a, b) in path.iter().zip(path.iter().skip(1)) {
        assert!(problem.world().segment_verdict(a, b).is_valid());
        cost += problem.space().distance(a, b);
    }
    assert!((cost - solution.cost).abs() < 1e-12);
}

/// PDT's dividing walls in R^2, at a coarse resolution to keep the tests quick.
fn walls() -> mit_star_problems::Problem {
    let problem = mit_star_problems::DividingWalls::new(2).build().unwrap();
    problem.with_resolution(1e-4).unwrap()
}

#[test]
fn the_cost_falls_over_calls_towards_the_straight_line() {
    let problem = mit_star_problems::ObstacleFree::new(2).build().unwrap();
    let parameters = Parameters {
        seed: 5,
        ..Parameters::default()
    };
    let mut planner = InformedRrtStar::for_problem(&problem, &parameters).unwrap();
    let mut costs = Vec::new();
    for _ in 0..6 {
        let outcome = planner.solve(&IterationLimit::new(400)).unwrap();
        if let Some(solution) = outcome.solution() {
            assert_valid(&problem, solution);
        }
        costs.push(outcome.cost());
    }
    assert!(costs.windows(2).all(|w| w[1] <= w[0]), "{costs:?}");
    let best = costs[costs.len() - 1];
    let optimum = problem.straight_line_cost();
    assert!(best >= optimum && best < 1.02 * optimum, "{costs:?}");
    let trace: Vec<f64> = planner.trace().points().iter().map(|p| p.cost).collect();
    assert!(trace.windows(2).all(|w| w[1] < w[0]));
    assert_eq!(trace.last(), Some(&best));
    // Informed sampling and pruning keep the tree inside the shrinking informed set.
    let counters = planner.counters();
    assert!(counters.pruned > 0);
    assert!(counters.vertices < counters.samples + 1);
    assert_eq!(counters.edges + 1, counters.vertices);
}

#[test]
fn edges_respect_the_range_and_clear_replays_the_run() {
    let problem = walls();
    let parameters = Parameters {
        range: Some(0.1),
        seed: 3,
        ..Parameters::default()
    };
    let mut planner = InformedRrtStar::for_problem(&problem, &parameters).unwrap();
    assert_eq!(planner.range(), 0.1);
    let stop = IterationLimit::new(4000);
    let first = planner.solve(&stop).unwrap();
    let solution = first.solution().expect("solved in 4000 iterations");
    assert_valid(&problem, solution);
    let snapshot = planner.snapshot().unwrap();
    assert_eq!(snapshot.forward_edges.len() + 1, snapshot.states.len());
    for &(parent, child) in &snapshot.forward_edges {
        let d = problem
            .space()
            .distance(&snapshot.states[parent], &snapshot.states[child]);
        assert!(d <= 0.1 + 1e-12, "edge of length {d}");
    }
    assert_eq!(snapshot.kinds[0], VertexKind::Start);
    assert_eq!(snapshot.solution.first(), Some(&0));
    planner.clear();
    assert_eq!(planner.best_cost(), f64::INFINITY);
    assert_eq!(planner.solve(&stop).unwrap(), first);
}

#[test]
fn interrupted_checks_resume_and_certification_is_counted() {
    let problem = walls();
    let parameters = Parameters {
        certification: Some(4),
        seed: 11,
        ..Parameters::default()
    };
    let mut planner = InformedRrtStar::for_problem(&problem, &parameters).unwrap();
    let stop = FirstSolution.or(TimeLimit::seconds(20.0));
    // Many tiny calls: every phase gets interrupted somewhere, and resumes.
    let mut outcome = Outcome::NoSolution;
    for _ in 0..20_000 {
        outcome = planner
            .solve(&TimeLimit::new(Duration::from_micros(50)))
            .unwrap();
        if outcome.is_solved() {
            break;
        }
    }
    if !outcome.is_solved() {
        outcome = planner.solve(&stop).unwrap();
    }
    assert_valid(&problem, outcome.solution().unwrap());
    let counters = planner.counters();
    assert!(counters.certifications > 0);
    assert!(counters.full_checks >= counters.certifications);
    let settings = planner.settings();
    for key in ["range", "goal_bias", "rrt_rewire_factor", "pruning", "seed"] {
        assert!(settings.iter().any(|(k, _)| k == key), "{key}");
    }
    assert!(settings.contains(&("certification".into(), "4".into())));
}

#[test]
fn bad_parameters_and_queries_are_typed_errors() {
    let problem = mit_star_problems::DividingWalls::new(2).build().unwrap();
    for goal_bias in [-0.1, 1.5, f64::NAN] {
        let parameters = Parameters {
            goal_bias,
            ..Parameters::default()
        };
        let error = InformedRrtStar::for_problem(&problem, &parameters).unwrap_err();
        assert!(
            matches!(
                error,
                BuildError::Parameter {
                    name: "goal_bias",
                    ..
                }
            ),
            "{error}"
        );
    }
    let parameters = Parameters {
        rrt_rewire_factor: 0.0,
        ..Parameters::default()
    };
    let error = InformedRrtStar::for_problem(&problem, &parameters).unwrap_err();
    assert!(error.to_string().contains("rrt_rewire_factor"), "{error}");
    let query = (vec![0.0; 3], vec![vec![0.0; 2]]);
    let space = problem.space().clone();
    let error = InformedRrtStar::new(space, problem.world().clone(), query, Parameters::default())
        .unwrap_err();
    assert!(matches!(error, BuildError::Query(_)), "{error}");
}
