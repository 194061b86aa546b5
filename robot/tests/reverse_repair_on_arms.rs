//! Arm problems ask MIT* to repair its reverse search in place
//! ([`ArmProblem::REPAIR_REVERSE_SEARCH`]); the paper's restart stays one parameter away.

use mit_star::{
    Configuration, Connection, FirstSolution, MitStar, Parameters, Planner, TerminationExt,
    TimeLimit, build_planner,
};

use crate::cage_batches;
use cage_batches::cage;

/// Solves to the first solution and returns the planner's (restarts, repairs).
fn restarts_and_repairs(planner: &mut dyn Planner) -> (u64, u64) {
    let outcome = planner
        .solve(&FirstSolution.or(TimeLimit::seconds(20.0)))
        .unwrap();
    assert!(outcome.solution().is_some(), "cage #1 unsolved in 20 s");
    let counters = planner.counters();
    (counters.reverse_restarts, counters.reverse_repairs)
}

/// The tool's MIT* on the Panda's first `cage` problem: its (restarts, repairs). With
/// k-nearest connections and fixed batches, under which this problem's lazy paths fail on the
/// way (with the arm's default r-disc, or with its growing batches, seed 1 finds its first
/// path without an invalid lazy edge).
fn tool_mit_star(repair: Option<bool>) -> (u64, u64) {
    let parameters = Parameters {
        seed: 1,
        repair_reverse_search: repair,
        connection: Some(Connection::KNearest),
        batch_growth: Some(0.0),
        ..Parameters::default()
    };
    let mut planner = build_planner(Configuration::MitStar, &cage(), &parameters).unwrap();
    restarts_and_repairs(planner.as_mut())
}

#[test]
fn arm_problems_repair_the_reverse_search_unless_told_to_restart() {
    let (restarts, repairs) = tool_mit_star(None);
    assert!(repairs > 0, "no repair by default on an arm");
    assert_eq!(restarts, 0, "a restart on an arm by default");
    let (restarts, repairs) = tool_mit_star(Some(false));
    assert!(restarts > 0, "no restart when told to restart");
    assert_eq!(repairs, 0);
    // The library's builder takes the problem's choice too.
    let mut planner = MitStar::for_problem(&cage())
        .seed(1)
        .connection(Connection::KNearest)
        .batch_growth(0.0)
        .build()
        .unwrap();
    let (restarts, repairs) = restarts_and_repairs(&mut planner);
    assert!(
        repairs > 0 && restarts == 0,
        "{restarts} restarts, {repairs} repairs"
    );
}
