//! Robots other than the Panda: the shipped UR5 and Fetch load leniently, plan, and say which
//! links collide (problems 1 and 2 of `box_ur5` and `box_fetch`, copied from their tarballs).

use std::path::{Path, PathBuf};

use mit_star::{FirstSolution, Parameters, Planner, TerminationExt, TimeLimit};
use mit_star_problems::PlanningProblem;
use mit_star_robot::{ArmError, ArmProblem, ModelError, ModelWarning, RobotModel, ShippedRobot};
use mit_star_spaces::StateSpace;

fn folder(scene: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/mbm")
        .join(scene)
}

fn shipped(name: &str, strict: bool) -> RobotModel {
    ShippedRobot::find(name).unwrap().model(strict).unwrap()
}

#[test]
fn a_scene_naming_unknown_links_warns_unless_strict() {
    let problem = ArmProblem::mbm(shipped("ur5", false), &folder("box_ur5"), 1).unwrap();
    let unknown: Vec<&ModelWarning> = problem
        .robot()
        .warnings()
        .iter()
        .filter(|w| matches!(w, ModelWarning::UnknownLinks { .. }))
        .collect();
    let [ModelWarning::UnknownLinks { origin, links, .. }] = unknown.as_slice() else {
        panic!("{unknown:?}")
    };
    assert_eq!(
        (origin.as_str(), links.as_slice()),
        ("allowed-collision matrix", &["box_link".to_owned()][..])
    );
    let e = ArmProblem::mbm(shipped("ur5", true), &folder("box_ur5"), 1).unwrap_err();
    assert!(
        matches!(&e, ArmError::Model(ModelError::UnknownLink { link, .. }) if link == "box_link"),
        "{e}"
    );
}

#[test]
fn a_self_colliding_start_names_the_links() {
    let urdf = include_str!("../data/ur5/ur5_spherized.urdf");
    let srdf = include_str!("../data/ur5/ur5.srdf");
    // The SRDF alone, without the pairs the sphere model rules out.
    let bare = RobotModel::from_urdf_str(urdf)
        .unwrap()
        .with_srdf_str(srdf)
        .unwrap();
    let problem = ArmProblem::mbm(bare, &folder("box_ur5"), 1).unwrap();
    assert!(!problem.ends_are_valid());
    let e = problem.check_ends().unwrap_err();
    assert!(
        matches!(e, ArmError::EndInCollision { what: "start", .. }),
        "{e}"
    );
    assert!(e.to_string().contains("wrist_2_link/fts_robotside"), "{e}");
    for name in ["ur5", "fetch"] {
        let problem =
            ArmProblem::mbm(shipped(name, false), &folder(&format!("box_{name}")), 1).unwrap();
        problem.check_ends().unwrap();
    }
}

#[test]
fn values_a_rounding_outside_the_limits_are_snapped_onto_them() {
    // Fetch's roll joints are limited to ±3.14159; problem 2's goal asks for −π.
    let problem = ArmProblem::mbm(shipped("fetch", false), &folder("box_fetch"), 2).unwrap();
    let goal = &problem.goals()[0];
    problem.space().check_state(goal).unwrap();
    let on_a_lower_limit = goal
        .iter()
        .zip(problem.space().joints())
        .any(|(v, j)| matches!(j.kind, mit_star_spaces::JointKind::Revolute { lower, .. } if *v == lower));
    assert!(on_a_lower_limit, "{goal:?}");
}

#[test]
fn ur5_and_fetch_plan() {
    for name in ["ur5", "fetch"] {
        let problem =
            ArmProblem::mbm(shipped(name, false), &folder(&format!("box_{name}")), 1).unwrap();
        let parameters = Parameters {
            range: Some(1.0),
            seed: 1,
            ..Parameters::default()
        };
        let mut planner = mit_star::RrtConnect::for_problem(&problem, &parameters).unwrap();
        let outcome = planner
            .solve(&FirstSolution.or(TimeLimit::seconds(10.0)))
            .unwrap();
        assert!(outcome.is_solved(), "{name}");
    }
}
