//! Joint kinds and planning groups on a hand-written robot: mimic joints follow their leader,
//! continuous joints wrap, prismatic joints are weighted in the metric, SRDF planning groups
//! choose the coordinates and a request's start state holds the other joints.

use std::f64::consts::PI;

use glam::{DAffine3, DVec3};
use mit_star_robot::{ArmProblem, Kinematics, ModelError, ModelWarning, RobotModel};
use mit_star_spaces::{JointKind, StateSpace};

/// A base; `turn` (revolute about z) carries `arm` with a sphere 0.5 m out along x;
/// `spin` (continuous about x) carries `wrist`; `lift` (prismatic along z) carries `tray`;
/// `left` (prismatic along y) a finger, and `right` mimics it (multiplier -2, offset 0.01);
/// `twin` mimics `turn` turned the other way (multiplier -1, offset 0.5). The followers' own
/// limits hold over their leaders' whole ranges (`tests/mimic_limits.rs` shrinks ranges).
const ROBOT: &str = r#"<?xml version="1.0"?>
<robot name="kinds">
  <link name="base"><collision><geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="arm"><collision><origin xyz="0.5 0 0"/><geometry><sphere radius="0.04"/></geometry></collision></link>
  <link name="wrist"><collision><origin xyz="0 0.1 0"/><geometry><sphere radius="0.02"/></geometry></collision></link>
  <link name="tray"><collision><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="finger_l"><collision><geometry><sphere radius="0.01"/></geometry></collision></link>
  <link name="finger_r"><collision><geometry><sphere radius="0.01"/></geometry></collision></link>
  <link name="twin"><collision><origin xyz="0.3 0 0"/><geometry><sphere radius="0.01"/></geometry></collision></link>
  <joint name="turn" type="revolute">
    <parent link="base"/><child link="arm"/><origin xyz="0 0 0.1"/><axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/>
  </joint>
  <joint name="spin" type="continuous">
    <parent link="arm"/><child link="wrist"/><origin xyz="0.5 0 0"/><axis xyz="1 0 0"/>
  </joint>
  <joint name="lift" type="prismatic">
    <parent link="base"/><child link="tray"/><origin xyz="0 0 -1"/><axis xyz="0 0 1"/>
    <limit lower="0.1" upper="0.4" effort="1" velocity="1"/>
  </joint>
  <joint name="left" type="prismatic">
    <parent link="wrist"/><child link="finger_l"/><origin xyz="0 0.2 0"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="0.04" effort="1" velocity="1"/>
  </joint>
  <joint name="right" type="prismatic">
    <parent link="wrist"/><child link="finger_r"/><origin xyz="0 0.2 0"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="0.5" effort="1" velocity="1"/>
    <mimic joint="left" multiplier="-2" offset="0.01"/>
  </joint>
  <joint name="mirror" type="revolute">
    <parent link="base"/><child link="twin"/><origin xyz="0 0 0.2"/><axis xyz="0 0 1"/>
    <limit lower="-2" upper="3" effort="1" velocity="1"/>
    <mimic joint="turn" multiplier="-1" offset="0.5"/>
  </joint>
</robot>"#;

const SRDF: &str = r#"<robot name="kinds">
  <group name="reach"><chain base_link="base" tip_link="wrist"/></group>
  <group name="hand"><link name="finger_l"/><joint name="lift"/><link name="camera"/></group>
  <group name="all"><group name="reach"/><group name="hand"/></group>
  <group name="loop"><group name="loop"/></group>
  <group name="upside_down"><chain base_link="wrist" tip_link="base"/></group>
</robot>"#;

/// The world positions of every sphere centre at `q`.
fn centres(robot: &RobotModel, q: &[f64]) -> Vec<DVec3> {
    let fk = Kinematics::new(robot);
    let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
    let mut centers = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
    fk.sphere_centers_f64(q, &mut links, &mut centers);
    centers.into_iter().map(|(c, _)| c).collect()
}

fn sphere_of(robot: &RobotModel, link: &str) -> usize {
    robot
        .link_sphere_range(robot.link_index(link).unwrap())
        .start
}

#[test]
fn mimic_joints_follow_their_leader_and_are_not_coordinates() {
    let robot = RobotModel::from_urdf_str(ROBOT).unwrap();
    assert_eq!(robot.joint_names(), ["turn", "spin", "left", "lift"]);
    let (turn, spin, left, lift) = (0.7, 0.3, 0.03, 0.2);
    let c = centres(&robot, &[turn, spin, left, lift]);
    // The right finger slides -2·left + 0.01 along the wrist's y, like the left one slides
    // `left`: both start 0.2 out from the wrist, so their offsets differ by -3·left + 0.01.
    let (l, r) = (sphere_of(&robot, "finger_l"), sphere_of(&robot, "finger_r"));
    let wrist_y = DAffine3::from_rotation_z(turn) * DAffine3::from_rotation_x(spin);
    let y = wrist_y.transform_vector3(DVec3::Y);
    assert!((c[r] - c[l] - y * (-3.0 * left + 0.01)).length() < 1e-12);
    // The twin turns by -turn + 0.5 about z, 0.3 m out.
    let angle: f64 = -turn + 0.5;
    let want = DVec3::new(0.3 * angle.cos(), 0.3 * angle.sin(), 0.2);
    assert!((c[sphere_of(&robot, "twin")] - want).length() < 1e-12);
}

#[test]
fn a_revolute_mimic_joint_at_another_speed_is_refused_by_name() {
    let urdf = ROBOT.replace(
        r#"multiplier="-1" offset="0.5""#,
        r#"multiplier="2" offset="0.5""#,
    );
    let error = RobotModel::from_urdf_str(&urdf).unwrap_err();
    assert!(
        matches!(&error, ModelError::UnsupportedJoint { joint, .. } if joint == "mirror"),
        "{error}"
    );
    let urdf = ROBOT.replace(r#"<mimic joint="turn""#, r#"<mimic joint="nowhere""#);
    let error = RobotModel::from_urdf_str(&urdf).unwrap_err();
    assert!(
        matches!(&error, ModelError::MimicLeader { leader, .. } if leader == "nowhere"),
        "{error}"
    );
}

#[test]
fn continuous_joints_wrap_and_prismatic_joints_weigh_a_metre_as_the_longest_lever() {
    let robot = RobotModel::from_urdf_str(ROBOT).unwrap();
    let space = robot.joint_space();
    assert_eq!(space.joints()[1].kind, JointKind::Continuous);
    // The short way round across ±π.
    let d = space.distance(&[0.0, 3.0, 0.0, 0.2], &[0.0, -3.0, 0.0, 0.2]);
    assert!((d - (2.0 * PI - 6.0)).abs() < 1e-12, "{d}");
    // Revolute and continuous coordinates weigh 1; prismatic ones 1/R.
    let reach = robot.revolute_reach();
    assert!(reach > 0.5 && reach < 2.0, "{reach}");
    let weights: Vec<f64> = space.joints().iter().map(|j| j.weight).collect();
    assert_eq!(weights, [1.0, 1.0, 1.0 / reach, 1.0 / reach]);
    let d = space.distance(&[0.0, 0.0, 0.0, 0.1], &[0.0, 0.0, 0.0, 0.3]);
    assert!((d - 0.2 / reach).abs() < 1e-12);
}

#[test]
fn srdf_groups_choose_the_coordinates_and_hold_the_rest() {
    let robot = RobotModel::from_urdf_str(ROBOT).unwrap();
    let reach = robot.clone().with_group_str(SRDF, "reach").unwrap();
    assert_eq!(reach.joint_names(), ["turn", "spin"]);
    // Held at MoveIt's default: 0, or the middle of the limits when 0 is outside them.
    assert_eq!(reach.held_joints(), [("left", 0.0), ("lift", 0.25)]);
    let hand = robot.clone().with_group_str(SRDF, "hand").unwrap();
    assert_eq!(hand.joint_names(), ["left", "lift"]);
    assert!(matches!(
        &hand.warnings()[0],
        ModelWarning::UnknownGroupMembers { names, .. } if names == &["link `camera`"]
    ));
    let all = robot.clone().with_group_str(SRDF, "all").unwrap();
    assert_eq!(all.joint_names(), robot.joint_names());
    // Held joints take the values they are given, clamped and wrapped.
    let held = reach
        .with_joint_positions([("lift", 9.0), ("left", 0.02), ("turn", 1.0)])
        .unwrap();
    assert_eq!(held.held_joints(), [("left", 0.02), ("lift", 0.4)]);
    let c = centres(&held, &[0.0, 0.0]);
    assert!((c[sphere_of(&held, "tray")] - DVec3::new(0.0, 0.0, -0.6)).length() < 1e-12);
    // The mimic finger follows the held one: 0.2 out, then -2·0.02 + 0.01.
    assert!((c[sphere_of(&held, "finger_r")].y - (0.2 - 0.03)).abs() < 1e-12);
    let spun = robot
        .with_group_str(SRDF, "hand")
        .unwrap()
        .with_joint_positions([("spin", 2.0 * PI + 0.25)])
        .unwrap();
    assert!((spun.held_joints()[1].1 - 0.25).abs() < 1e-12);
}

#[test]
fn bad_groups_are_typed_errors_naming_the_group() {
    let robot = RobotModel::from_urdf_str(ROBOT).unwrap();
    let error = robot.clone().with_group_str(SRDF, "legs").unwrap_err();
    assert!(
        matches!(&error, ModelError::UnknownGroup { known, .. } if known.starts_with("reach, hand")),
        "{error}"
    );
    for group in ["loop", "upside_down"] {
        let error = robot.clone().with_group_str(SRDF, group).unwrap_err();
        assert!(
            matches!(&error, ModelError::BadGroup { group: g, .. } if g == group),
            "{error}"
        );
    }
    let error = robot.clone().strict(true).with_group_str(SRDF, "hand");
    assert!(matches!(error, Err(ModelError::BadGroup { .. })));
    let error = robot
        .clone()
        .with_planned_joints(&["turn", "elbow"])
        .unwrap_err();
    assert!(error.to_string().contains("`elbow`"), "{error}");
    let error = robot.with_planned_joints(&["right"]).unwrap_err();
    assert!(matches!(error, ModelError::NoJoints), "{error}");
}

#[test]
fn a_request_holds_the_joints_outside_the_group_and_wraps_continuous_ones() {
    let dir = std::env::temp_dir().join(format!("joint-kinds-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("scene0001.yaml"), "world: {}\n").unwrap();
    let request = format!(
        "start_state:\n  joint_state:\n    name: [turn, spin, left, lift]\n    position: [0.5, {}, 0.01, 0.3]\n\
         goal_constraints:\n  - joint_constraints:\n      - {{joint_name: turn, position: -0.5}}\n      - {{joint_name: spin, position: -4.0}}\n",
        2.0 * PI + 1.0
    );
    std::fs::write(dir.join("request0001.yaml"), request).unwrap();
    let robot = RobotModel::from_urdf_str(ROBOT)
        .unwrap()
        .with_group_str(SRDF, "reach")
        .unwrap();
    let problem = ArmProblem::mbm(robot, &dir, 1).unwrap();
    use mit_star_problems::PlanningProblem;
    assert!((problem.start()[1] - 1.0).abs() < 1e-12);
    assert!((problem.goals()[0][1] - (2.0 * PI - 4.0)).abs() < 1e-12);
    assert_eq!(
        problem.robot().held_joints(),
        [("left", 0.01), ("lift", 0.3)]
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
