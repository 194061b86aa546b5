//! Arm problems ask MIT* for denser sparse checks than the authors' constants
//! ([`ArmProblem::SPARSE_SPACING`]); the authors' spacing stays two parameters away.

use mit_star::{
    Configuration, Connection, Counters, FirstSolution, MitStar, Parameters, Planner,
    TerminationExt, TimeLimit, build_planner,
};
use problems::{PAPER_SPARSE_SPACING, PlanningProblem};
use robot::ArmProblem;

#[path = "support/cage_batches.rs"]
mod cage_batches;
use cage_batches::cage;

/// Grid points a sparse check tested, on average, solving to the first solution.
fn points_per_sparse_check(planner: &mut dyn Planner) -> f64 {
    let outcome = planner
        .solve(&FirstSolution.or(TimeLimit::seconds(20.0)))
        .unwrap();
    assert!(outcome.solution().is_some(), "cage #1 unsolved in 20 s");
    let counters: Counters = planner.counters();
    let points: u64 = counters.sparse_points_by_length.iter().sum();
    let checks: u64 = counters.sparse_checks_by_length.iter().sum();
    assert!(checks > 0, "no sparse check");
    points as f64 / checks as f64
}

/// The tool's MIT* on the Panda's first `cage` problem with the given spacing (k-nearest and
/// batches of 100, so that only the spacing differs from the build these figures were first
/// taken with; the arm's default radius makes edges longer, and every spacing tests more of
/// each).
fn tool_mit_star(spacing: Option<(f64, f64)>) -> f64 {
    let parameters = Parameters {
        seed: 1,
        sparse_initial_steps: spacing.map(|s| s.0),
        sparse_min_steps: spacing.map(|s| s.1),
        connection: Some(Connection::KNearest),
        batch_size: Some(problems::PAPER_BATCH_SIZE),
        ..Parameters::default()
    };
    let mut planner = build_planner(Configuration::MitStar, &cage(), &parameters).unwrap();
    points_per_sparse_check(planner.as_mut())
}

#[test]
fn arm_problems_check_sparsely_every_few_steps_unless_told_otherwise() {
    assert_eq!(cage().sparse_spacing(), ArmProblem::SPARSE_SPACING);
    assert!(ArmProblem::SPARSE_SPACING.0 < PAPER_SPARSE_SPACING.0);
    let arm = tool_mit_star(None);
    let authors = tool_mit_star(Some(PAPER_SPARSE_SPACING));
    // An edge of the cage's graph is tens of steps long: the authors' spacing tests about one
    // point of it, the arm's every fourth.
    assert!(
        authors < 2.0,
        "{authors} points per sparse check at 2000, 10"
    );
    assert!(
        arm > 2.0 * authors,
        "{arm} points per sparse check by default, {authors} at 2000, 10"
    );
    // The library's builder takes the problem's spacing too.
    let mut planner = MitStar::for_problem(&cage())
        .seed(1)
        .connection(Connection::KNearest)
        .batch_size(problems::PAPER_BATCH_SIZE)
        .build()
        .unwrap();
    let built = points_per_sparse_check(&mut planner);
    assert!(built > 2.0 * authors, "{built} points per sparse check");
}
