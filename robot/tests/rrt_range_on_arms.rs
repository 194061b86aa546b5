//! Arm problems default RRT-Connect's, AORRTC's and Informed RRT*'s `range` to their robot's:
//! the value measured for a shipped robot, the joint-span rule for any other; a set `range`
//! wins, and box worlds keep the planners' own rule.

use mit_star::{Configuration, Parameters, default_range};
use mit_star_problems::PlanningProblem;
use mit_star_robot::{ArmProblem, RobotModel, ShippedRobot};
use mit_star_spaces::StateSpace;

/// The range `configuration` runs with on `problem` given `parameters`.
fn range<P: PlanningProblem>(
    configuration: Configuration,
    problem: &P,
    parameters: &Parameters,
) -> Option<f64> {
    configuration
        .effective_parameters(problem, parameters)
        .unwrap()
        .range
}

#[test]
fn each_shipped_robot_steps_by_its_measured_range_unless_one_is_set() {
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/mbm");
    // Robots whose measured range differs from the planners' own default: the ones on
    // which this test can tell the two apart (the Fetch's measured 1.25 is also the
    // planners' 8-D value).
    let mut distinct = 0;
    for (robot, folder) in [
        ("panda", "box_panda"),
        ("ur5", "box_ur5"),
        ("fetch", "box_fetch"),
    ] {
        let shipped = ShippedRobot::find(robot).unwrap();
        let model = shipped.model(false).unwrap();
        assert_eq!(model.rrt_range(), shipped.range, "{robot}");
        let arm = ArmProblem::mbm(model, format!("{data}/{folder}").as_ref(), 1).unwrap();
        assert_eq!(arm.default_range(), Some(shipped.range), "{robot}");
        let space = arm.space();
        let ompl = default_range(space.dimension(), space.maximum_extent());
        distinct += usize::from(ompl != shipped.range);
        for configuration in [
            Configuration::RrtConnect,
            Configuration::Aorrtc,
            Configuration::InformedRrtStar,
        ] {
            let defaults = Parameters::default();
            assert_eq!(
                range(configuration, &arm, &defaults),
                Some(shipped.range),
                "{robot} {configuration}"
            );
            let set = Parameters {
                range: Some(0.25),
                ..Parameters::default()
            };
            assert_eq!(range(configuration, &arm, &set), Some(0.25));
            // The planner built steps by it.
            let planner = mit_star::build_planner(configuration, &arm, &defaults).unwrap();
            let settings = planner.settings();
            assert!(
                settings
                    .iter()
                    .any(|(k, v)| k == "range" && v.parse::<f64>().ok() == Some(shipped.range)),
                "{robot} {configuration}: {settings:?}"
            );
        }
    }
    assert_eq!(
        distinct, 2,
        "the Panda's and the UR5's ranges differ from the planners'"
    );
    let boxes = mit_star_problems::DividingWalls::new(2).build().unwrap();
    assert_eq!(boxes.default_range(), None);
    assert_eq!(
        range(Configuration::RrtConnect, &boxes, &Parameters::default()),
        Some(default_range(2, boxes.space().maximum_extent()))
    );
}

#[test]
fn a_robot_nobody_measured_steps_by_the_rule_on_its_joints() {
    let urdf = include_str!("../data/ur5/ur5_spherized.urdf");
    let model = RobotModel::from_urdf_str(urdf).unwrap();
    let rule = RobotModel::range_rule(model.joint_space());
    assert_eq!(model.rrt_range(), rule);
    assert!((rule - std::f64::consts::PI / 3.0).abs() < 1e-6, "{rule}");
    // Set, it wins; a value that is no range leaves the rule.
    assert_eq!(model.clone().with_rrt_range(0.7).rrt_range(), 0.7);
    assert_eq!(model.with_rrt_range(f64::NAN).rrt_range(), rule);
    // The rule near each shipped robot's measured range (within a factor of two).
    for shipped in ShippedRobot::all() {
        let model = shipped.model(false).unwrap();
        let rule = RobotModel::range_rule(model.joint_space());
        let ratio = rule / shipped.range;
        assert!(
            (0.5..=2.0).contains(&ratio),
            "{}: rule {rule}",
            shipped.name
        );
    }
}
