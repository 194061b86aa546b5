use super::*;
use crate::{FirstSolution, IterationLimit, Parameters, TerminationExt, TimeLimit};

// The integration tests' clock for timed assertions (wall-clock less run-queue wait).
#[path = "../../../tests/common/scheduled.rs"]
mod scheduled;
use scheduled::Scheduled;

fn walls() -> mit_star_problems::Problem {
    mit_star_problems::DividingWalls::new(2)
        .build()
        .unwrap()
        .with_resolution(1e-4)
        .unwrap()
}

fn assert_valid(problem: &mit_star_problems::Problem, path: &States) {
    assert_eq!(&path[0], problem.start());
    assert_eq!(&path[path.len() - 1], &problem.goals()[0][..]);
    for (a, b) in path.iter().zip(path.iter().skip(1)) {
        assert!(
            problem.world().segment_verdict(a, b).is_valid(),
            "{a:?} → {b:?}"
        );
    }
}

#[test]
fn improves_on_its_first_solution_with_valid_paths_only() {
    let problem = walls();
    let parameters = Parameters {
        seed: 2,
        ..Parameters::default()
    };
    let mut planner = Aorrtc::for_problem(&problem, &parameters).unwrap();
    let first = planner
        .solve(&FirstSolution.or(TimeLimit::seconds(5.0)))
        .unwrap();
    assert_valid(&problem, &first.solution().unwrap().path);
    let later = planner.solve(&TimeLimit::seconds(0.3)).unwrap();
    assert_valid(&problem, &later.solution().unwrap().path);
    assert!(
        later.cost() < first.cost(),
        "{} vs {}",
        later.cost(),
        first.cost()
    );
    let costs: Vec<f64> = planner.trace().points().iter().map(|p| p.cost).collect();
    assert!(costs.windows(2).all(|w| w[1] < w[0]), "{costs:?}");
    // Searches ran, each bounded by the best cost when it started.
    let settings = planner.settings();
    let searches = settings.iter().find(|(k, _)| k == "searches").unwrap();
    assert!(searches.1.parse::<u64>().unwrap() > 1, "{settings:?}");
}

#[test]
fn converges_toward_the_optimum_without_obstacles_and_stops_at_it() {
    let problem = mit_star_problems::ObstacleFree::new(4).build().unwrap();
    let mut planner = Aorrtc::for_problem(&problem, &Parameters::default()).unwrap();
    let clock = Scheduled::start();
    let outcome = planner.solve(&TimeLimit::seconds(5.0)).unwrap();
    // RRT-Connect joins the two roots in steps; the simplifier then takes the straight line,
    // which no search can beat: the planner returns before its time is up.
    assert!((outcome.cost() - problem.straight_line_cost()).abs() < 1e-9);
    // On the time this thread was scheduled, so that a loaded machine does not fail it.
    let took = clock.elapsed();
    assert!(
        took.as_secs_f64() < 4.0,
        "took {took:?} of {}",
        clock.source()
    );
}

#[test]
fn without_simplification_the_searches_alone_improve() {
    let problem = walls();
    let parameters = Parameters {
        seed: 7,
        aorrtc_simplify: false,
        ..Parameters::default()
    };
    let mut planner = Aorrtc::for_problem(&problem, &parameters).unwrap();
    let outcome = planner.solve(&TimeLimit::seconds(0.3)).unwrap();
    assert_valid(&problem, &outcome.solution().unwrap().path);
    assert!(planner.trace().len() > 1, "{:?}", planner.trace());
    let settings = planner.settings();
    assert!(settings.contains(&("simplified_solutions".into(), "0".into())));
}

#[test]
fn the_same_seed_gives_the_same_plan_after_clear_and_in_slices() {
    let problem = walls();
    let parameters = Parameters {
        seed: 11,
        ..Parameters::default()
    };
    let mut planner = Aorrtc::for_problem(&problem, &parameters).unwrap();
    let whole = planner.solve(&IterationLimit::new(3000)).unwrap();
    planner.clear();
    assert_eq!(planner.best_cost(), f64::INFINITY);
    assert_eq!(planner.solve(&IterationLimit::new(3000)).unwrap(), whole);
    // Many short calls: each resumes where the last stopped, and every path is valid.
    let mut sliced = Aorrtc::for_problem(&problem, &parameters).unwrap();
    for _ in 0..300 {
        if let Outcome::Solved(s) = sliced.solve(&IterationLimit::new(10)).unwrap() {
            assert_valid(&problem, &s.path);
        }
    }
    assert!(sliced.best_cost().is_finite());
}

#[test]
fn bad_parameters_are_typed_errors() {
    let problem = walls();
    let parameters = Parameters {
        range: Some(-1.0),
        ..Parameters::default()
    };
    let error = Aorrtc::for_problem(&problem, &parameters).unwrap_err();
    assert!(error.to_string().contains("range"), "{error}");
}

/// The trace of AORRTC's first solution on four dividing walls, with the switches
/// `(simplify_smoothing, polish_when_idle)`.
fn first_solution_trace(smoothing: bool, polish: bool) -> Vec<f64> {
    let problem = mit_star_problems::DividingWalls::new(4)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let parameters = Parameters {
        seed: 1,
        simplify_smoothing: smoothing,
        polish_when_idle: polish,
        ..Parameters::default()
    };
    let mut planner = Aorrtc::for_problem(&problem, &parameters).unwrap();
    let outcome = planner
        .solve(&FirstSolution.or(TimeLimit::seconds(10.0)))
        .unwrap();
    assert_valid(&problem, &outcome.solution().unwrap().path);
    let points = planner.trace().points();
    points.iter().map(|p| p.cost).collect::<Vec<f64>>()
}

#[test]
fn each_solution_is_shortcut_then_smoothed_and_every_stage_is_a_trace_point() {
    let costs = |smoothing: bool| first_solution_trace(smoothing, false);
    let (on, off) = (costs(true), costs(false));
    // Without smoothing: the path as found, then shortcut.
    assert_eq!(off.len(), 2, "{off:?}");
    // With it: the same two, then each smoothing round that shortened the path.
    assert_eq!(on[..2], off[..], "{on:?} {off:?}");
    assert!(on.len() > 2, "{on:?}");
    assert!(on.windows(2).all(|w| w[1] < w[0]), "{on:?}");
}

#[test]
fn with_polishes_on_a_new_solution_is_shortcut_and_the_smoothing_left_to_them() {
    // Smoothing on (the default) and polishes on (the default): the path as found, then
    // shortcut, and no smoothing round.
    let polished = first_solution_trace(true, true);
    assert_eq!(polished.len(), 2, "{polished:?}");
    assert_eq!(polished, first_solution_trace(false, false));
    assert!(first_solution_trace(true, false).len() > 2);
}

#[test]
fn searches_that_stop_paying_are_followed_by_a_polish_unless_switched_off() {
    let problem = walls();
    let run = |polish: bool| {
        let parameters = Parameters {
            seed: 3,
            polish_when_idle: polish,
            ..Parameters::default()
        };
        let mut planner = Aorrtc::for_problem(&problem, &parameters).unwrap();
        let outcome = planner.solve(&IterationLimit::new(60_000)).unwrap();
        assert_valid(&problem, &outcome.solution().unwrap().path);
        let costs: Vec<f64> = planner.trace().points().iter().map(|p| p.cost).collect();
        assert!(costs.windows(2).all(|w| w[1] < w[0]), "{costs:?}");
        let settings = planner.settings();
        let count = |key: &str| {
            let value = &settings.iter().find(|(k, _)| k == key).unwrap().1;
            value.parse::<u64>().unwrap()
        };
        count("polished_solutions")
    };
    // A polish follows at least FIRST_POLISH_AFTER iterations in which the searches found
    // nothing cheaper.
    let polished = run(true);
    assert!(polished > 0);
    assert!(
        polished <= 60_000 / crate::simplification::IdlePolish::new(0).wait(),
        "{polished} polishes"
    );
    assert_eq!(run(false), 0);
}
