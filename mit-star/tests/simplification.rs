//! The path simplifier: same ends, never longer, every segment valid, the stop honoured, bad
//! paths refused with a typed error.

use std::time::Duration;

use mit_star::{
    BuildError, FirstSolution, Parameters, PathSimplifier, Planner, RrtConnect, TerminationExt,
    TimeLimit,
};
use mit_star_problems::PlanningProblem;
use mit_star_spaces::{Deadline, StateSpace};

fn rrt_path(problem: &mit_star_problems::Problem, seed: u64) -> Vec<Vec<f64>> {
    let parameters = Parameters {
        seed,
        ..Parameters::default()
    };
    let mut planner = RrtConnect::for_problem(problem, &parameters).unwrap();
    let outcome = planner
        .solve(&FirstSolution.or(TimeLimit::seconds(10.0)))
        .unwrap();
    outcome
        .solution()
        .unwrap()
        .path
        .iter()
        .map(<[f64]>::to_vec)
        .collect()
}

#[test]
fn simplified_paths_keep_their_ends_get_no_longer_and_stay_valid() {
    let mut totals = (0.0, 0.0);
    for (dimension, seed) in [(2, 1), (2, 2), (4, 3), (8, 4)] {
        let problem = mit_star_problems::DividingWalls::new(dimension)
            .build()
            .unwrap()
            .with_resolution(1e-3)
            .unwrap();
        let path = rrt_path(&problem, seed);
        let simplified = PathSimplifier::new()
            .seed(seed)
            .simplify(&problem, &path, &Deadline::after(Duration::from_secs(5)))
            .unwrap();
        assert_eq!(simplified.path.first(), path.first());
        assert_eq!(simplified.path.last(), path.last());
        assert!(simplified.cost <= simplified.original_cost + 1e-12);
        assert!(simplified.cost >= problem.straight_line_cost() - 1e-9);
        let length: f64 = simplified
            .path
            .windows(2)
            .map(|w| problem.space().distance(&w[0], &w[1]))
            .sum();
        assert!((length - simplified.cost).abs() < 1e-9);
        for w in simplified.path.windows(2) {
            assert!(
                problem.world().segment_verdict(&w[0], &w[1]).is_valid(),
                "R^{dimension} seed {seed}: an invalid segment"
            );
        }
        // An RRT-Connect path through two walls always has a shortcut.
        assert!(
            simplified.cost < simplified.original_cost,
            "R^{dimension} seed {seed}: {} -> {}",
            simplified.original_cost,
            simplified.cost
        );
        assert!(!simplified.stopped);
        totals.0 += simplified.original_cost;
        totals.1 += simplified.cost;
    }
    // And together they shorten a lot.
    assert!(totals.1 < 0.85 * totals.0, "{totals:?}");
}

#[test]
fn a_fired_stop_returns_the_path_unchanged() {
    let problem = mit_star_problems::DividingWalls::new(2)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let path = rrt_path(&problem, 5);
    let simplified = PathSimplifier::new()
        .simplify(&problem, &path, &|| true)
        .unwrap();
    assert!(simplified.stopped);
    assert_eq!(simplified.path, path);
    assert_eq!(simplified.edges_checked, 0);
}

#[test]
fn bad_paths_are_typed_errors() {
    let problem = mit_star_problems::DividingWalls::new(2).build().unwrap();
    let never = mit_star_spaces::Never;
    let simplifier = PathSimplifier::new();
    for (path, state) in [
        (vec![vec![0.1, 0.1]], 1),
        (vec![vec![0.1, 0.1], vec![0.2]], 1),
        (vec![vec![f64::NAN, 0.1], vec![0.2, 0.2]], 0),
    ] {
        match simplifier.simplify(&problem, &path, &never) {
            Err(BuildError::BadPath {
                state: s,
                dimension: 2,
                ..
            }) => assert_eq!(s, state),
            other => panic!("{other:?}"),
        }
    }
}

#[test]
fn a_simplifying_planner_reports_shorter_valid_paths_at_every_solution() {
    let problem = mit_star_problems::DividingWalls::new(4)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    for configuration in [
        mit_star::Configuration::MitStar,
        mit_star::Configuration::RrtConnect,
    ] {
        let plain = Parameters {
            seed: 2,
            ..Parameters::default()
        };
        let simplified = Parameters {
            simplify_solutions: true,
            ..plain.clone()
        };
        let mut inner = mit_star::build_planner(configuration, &problem, &plain).unwrap();
        let mut wrapped = mit_star::build_planner(configuration, &problem, &simplified).unwrap();
        let stop = FirstSolution.or(TimeLimit::seconds(10.0));
        let first_inner = inner.solve(&stop).unwrap();
        let first = wrapped.solve(&stop).unwrap();
        // The same planner found the same first path; the wrapper shortened it.
        assert!(first.cost() < first_inner.cost(), "{configuration}");
        let more = wrapped
            .solve(&mit_star::IterationLimit::new(2_000).or(TimeLimit::seconds(10.0)))
            .unwrap();
        let path = &more.solution().unwrap().path;
        assert_eq!(&path[0], problem.start());
        let mut length = 0.0;
        for (a, b) in path.iter().zip(path.iter().skip(1)) {
            assert!(problem.world().segment_verdict(a, b).is_valid());
            length += problem.space().distance(a, b);
        }
        assert!((length - more.cost()).abs() < 1e-9);
        assert_eq!(wrapped.best_cost(), more.cost());
        let costs: Vec<f64> = wrapped.trace().points().iter().map(|p| p.cost).collect();
        assert!(costs.windows(2).all(|w| w[1] < w[0]), "{costs:?}");
        assert!(
            wrapped
                .settings()
                .iter()
                .any(|(k, v)| k == "simplified_solutions" && v != "0")
        );
        wrapped.clear();
        assert_eq!(wrapped.best_cost(), f64::INFINITY);
        assert!(wrapped.trace().is_empty());
    }
}

#[test]
fn a_simplifying_planner_smooths_unless_told_not_to() {
    let problem = mit_star_problems::DividingWalls::new(4)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let moves = |smoothing: bool| {
        let parameters = Parameters {
            seed: 3,
            simplify_solutions: true,
            simplify_smoothing: smoothing,
            ..Parameters::default()
        };
        let mut planner =
            mit_star::build_planner(mit_star::Configuration::RrtConnect, &problem, &parameters)
                .unwrap();
        let outcome = planner
            .solve(&FirstSolution.or(TimeLimit::seconds(10.0)))
            .unwrap();
        for w in outcome
            .solution()
            .unwrap()
            .path
            .iter()
            .collect::<Vec<_>>()
            .windows(2)
        {
            assert!(problem.world().segment_verdict(w[0], w[1]).is_valid());
        }
        let settings = planner.settings();
        let moves = settings
            .iter()
            .find(|(k, _)| k == "smoothing_moves")
            .map(|(_, v)| v.parse::<u64>().unwrap());
        (moves, outcome.cost())
    };
    let (on, off) = (moves(true), moves(false));
    assert!(on.0.unwrap() > 0, "{on:?}");
    assert_eq!(off.0, Some(0));
    // The same first path and shortcuts; smoothing only ever shortens.
    assert!(on.1 <= off.1, "{on:?} {off:?}");
}

#[test]
fn stages_report_whole_shortcuts_first_then_per_joint_ones_then_smoothing() {
    let problem = mit_star_problems::DividingWalls::new(4)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let path = rrt_path(&problem, 5);
    let checks = (
        PlanningProblem::check_step(&problem).unwrap(),
        problem.certification(),
    );
    let (space, validity) = (problem.space(), problem.validity());
    let simplifier = PathSimplifier::new().seed(3).smoothing_rounds(2);
    let mut stages = Vec::new();
    let last = simplifier
        .simplify_in_stages(
            space,
            validity,
            checks,
            &path,
            &mit_star_spaces::Never,
            &mut |s| {
                stages.push(s.clone());
            },
        )
        .unwrap();
    // The first stage is what whole shortcuts alone make of the path, so a caller has it
    // before the slower per-joint shortcuts run.
    let whole = simplifier
        .clone()
        .partial_shortcuts(false)
        .smoothing_rounds(0)
        .simplify_in(space, validity, checks, &path, &mit_star_spaces::Never)
        .unwrap();
    assert_eq!(stages[0], whole);
    assert_eq!(stages[0].partial_shortcuts, 0);
    // Then per-joint shortcuts on it, then each smoothing round on the stage before.
    assert!(stages.len() >= 3, "{} stages", stages.len());
    assert_eq!(stages[1].original_cost, stages[0].cost);
    assert!(stages[1].partial_shortcuts > 0, "{:?}", stages[1]);
    for pair in stages.windows(2) {
        assert_eq!(pair[1].original_cost, pair[0].cost);
        assert!(pair[1].cost <= pair[0].cost);
    }
    assert_eq!(stages.last(), Some(&last));
    // Without per-joint shortcuts there is no second shortcut stage.
    let mut count = 0;
    simplifier
        .partial_shortcuts(false)
        .smoothing_rounds(0)
        .simplify_in_stages(
            space,
            validity,
            checks,
            &path,
            &mit_star_spaces::Never,
            &mut |_| {
                count += 1;
            },
        )
        .unwrap();
    assert_eq!(count, 1);
}

#[test]
fn a_simplifying_planner_polishes_while_the_inner_planner_finds_nothing_cheaper() {
    let problem = mit_star_problems::DividingWalls::new(2)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let run = |polish: bool| {
        let parameters = Parameters {
            seed: 4,
            simplify_solutions: true,
            polish_when_idle: polish,
            ..Parameters::default()
        };
        let mut planner =
            mit_star::build_planner(mit_star::Configuration::MitStar, &problem, &parameters)
                .unwrap();
        // An iteration limit still ends the call: it counts the inner planner's iterations
        // since its last cheaper solution, across the stretches that polishes cut.
        let outcome = planner
            .solve(&mit_star::IterationLimit::new(30_000))
            .unwrap();
        let path: Vec<&[f64]> = outcome.solution().unwrap().path.iter().collect();
        for w in path.windows(2) {
            assert!(problem.world().segment_verdict(w[0], w[1]).is_valid());
        }
        let costs: Vec<f64> = planner.trace().points().iter().map(|p| p.cost).collect();
        assert!(costs.windows(2).all(|w| w[1] < w[0]), "{costs:?}");
        let settings = planner.settings();
        let polished = &settings.iter().find(|(k, _)| k == "polished_solutions");
        polished.unwrap().1.parse::<u64>().unwrap()
    };
    assert!(run(true) > 0);
    assert_eq!(run(false), 0);
}
