//! Certified motion past the robot's own links: a sphere of one link grazing a sphere of
//! another, where certification judges the pair by how fast the two approach each other. A
//! hand-written arm sweeps its hand past a ball on its base, the ball sized so that the
//! closest approach over the edge is exactly `depth` beyond contact.

use glam::{DAffine3, DVec3};
use mit_star_robot::{ArmChecker, Kinematics, ParryChecker, RobotModel, Scene};
use mit_star_spaces::Never;
use mit_star_validity::{EdgeStatus, MotionProgress, StateValidity};
use proptest::prelude::*;

use crate::arm_cases::reference_hit;

/// A column turning about `z` on a base that carries one ball (at `BALL` with `RADIUS`), a boom
/// lifted about `y`, and a hand bent about `y` at the boom's end with one sphere 0.2 m out: the
/// ball and the hand's sphere are the only spheres, so their pair is all there is to hit.
const ROBOT: &str = r#"<?xml version="1.0"?>
<robot name="sweeper">
  <link name="base"><collision><origin xyz="BALL"/><geometry><sphere radius="RADIUS"/></geometry></collision></link>
  <link name="column"/>
  <link name="boom"/>
  <link name="hand"><collision><origin xyz="0.2 0 0"/><geometry><sphere radius="0.04"/></geometry></collision></link>
  <joint name="turn" type="revolute">
    <parent link="base"/><child link="column"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/>
  </joint>
  <joint name="lift" type="revolute">
    <parent link="column"/><child link="boom"/><origin xyz="0 0 0.3"/><axis xyz="0 1 0"/>
    <limit lower="-1.5" upper="1.5" effort="1" velocity="1"/>
  </joint>
  <joint name="bend" type="revolute">
    <parent link="boom"/><child link="hand"/><origin xyz="0.5 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-2.5" upper="2.5" effort="1" velocity="1"/>
  </joint>
</robot>"#;

/// The hand sphere's radius in [`ROBOT`].
const HAND: f64 = 0.04;

/// The robot with its base ball at `at` with `radius`.
fn sweeper(at: DVec3, radius: f64) -> RobotModel {
    let text = ROBOT
        .replace("BALL", &format!("{} {} {}", at.x, at.y, at.z))
        .replace("RADIUS", &radius.to_string());
    RobotModel::from_urdf_str(&text).unwrap()
}

/// The hand sphere's centre at the fraction `t` of `a → b`.
fn hand(fk: &Kinematics, (a, b): (&[f64], &[f64]), t: f64) -> DVec3 {
    let q: Vec<f64> = a.iter().zip(b).map(|(x, y)| x + (y - x) * t).collect();
    let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
    let mut centres = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
    fk.sphere_centers_f64(&q, &mut links, &mut centres);
    let (centre, radius) = *centres.last().unwrap();
    assert_eq!(radius, HAND, "the hand's sphere is the last");
    centre
}

/// The least distance from `p` to the hand's centre over the edge: on a grid of a thousand
/// pieces, then by golden sections around the grid's least.
fn closest(fk: &Kinematics, edge: (&[f64], &[f64]), p: DVec3) -> f64 {
    let distance = |t: f64| hand(fk, edge, t).distance(p);
    let pieces = 1000_u32;
    let at = |i: u32| f64::from(i) / f64::from(pieces);
    let best = (0..=pieces)
        .min_by(|&i, &j| distance(at(i)).total_cmp(&distance(at(j))))
        .unwrap();
    let (mut lo, mut hi) = (at(best.saturating_sub(1)), at((best + 1).min(pieces)));
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..60 {
        let (x, y) = (hi - ratio * (hi - lo), lo + ratio * (hi - lo));
        if distance(x) < distance(y) {
            hi = y;
        } else {
            lo = x;
        }
    }
    distance((lo + hi) / 2.0)
        .min(distance(0.0))
        .min(distance(1.0))
}

fn certify(robot: &RobotModel, checker: &ArmChecker, a: &[f64], b: &[f64]) -> EdgeStatus {
    let mut progress = MotionProgress::default();
    checker
        .certify_motion(robot.joint_space(), a, b, &mut progress, &Never)
        .expect("the arm checker certifies motions of its joint space")
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 128,
        max_global_rejects: 1 << 14,
        ..ProptestConfig::default()
    })]

    /// A ball on the base, `away` from the hand's path across its motion at the fraction `at`
    /// of the edge (turned by `turn` about the motion: on the inside of a turn, the path
    /// curves towards it), sized so that the hand passes it `depth` beyond contact (negative:
    /// into it). Certified ⇒ no collision on the reference's grid of 1e-4 rad; a ball reaching
    /// 0.2 mm into the path is never certified.
    #[test]
    fn grazing_links_are_judged_exactly(
        start in prop::collection::vec(-1.0..1.0_f64, 3),
        motion in prop::collection::vec(-1.0..1.0_f64, 3),
        length in 0.3..3.0_f64,
        at in 0.15..0.85_f64,
        away in 0.06..0.3_f64,
        turn in 0.0..std::f64::consts::TAU,
        depth in prop_oneof![-1e-3..1e-3_f64, -1e-4..1e-4_f64],
    ) {
        let limits = [3.0, 1.5, 2.5];
        let a: Vec<f64> = start.iter().zip(limits).map(|(u, l)| u * l).collect();
        let norm = motion.iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-9);
        let b: Vec<f64> = (0..3)
            .map(|j| (a[j] + motion[j] / norm * length).clamp(-limits[j], limits[j]))
            .collect();
        // Where the ball goes: beside the hand's centre at `at`, across its motion.
        let probe = sweeper(DVec3::new(0.0, 0.0, -5.0), 0.01);
        let fk = Kinematics::new(&probe);
        let e = 1e-6;
        let (here, ahead) = (hand(&fk, (&a, &b), at), hand(&fk, (&a, &b), at + e));
        let velocity = (ahead - here) / e;
        prop_assume!(velocity.length() > 0.05);
        let u = velocity.normalize();
        let side = u.any_orthonormal_vector();
        let across = side * turn.cos() + u.cross(side) * turn.sin();
        let ball = here + across * away;
        let radius = closest(&fk, (&a, &b), ball) - HAND - depth;
        prop_assume!(radius > 0.01);
        let robot = sweeper(ball, radius);
        let scene = Scene::new(vec![]);
        let checker = ArmChecker::new(&robot, &scene);
        let reference = ParryChecker::new(&robot, &scene);
        prop_assume!(checker.is_valid(&a) && checker.is_valid(&b));
        if certify(&robot, &checker, &a, &b) == EdgeStatus::Valid {
            prop_assert!(depth > -2e-4, "a ball {depth} m into the path was certified");
            prop_assert_eq!(reference_hit(&reference, &a, &b, 1e-4, 0.0), None);
        }
    }
}

/// The sweeper's base ball and its hand are a checked pair (not adjacent: two joints move the
/// hand about the base), so the test above is about self-collision.
#[test]
fn the_base_ball_and_the_hand_are_a_checked_pair() {
    let robot = sweeper(DVec3::new(0.3, 0.0, 0.3), 0.05);
    let reference = ParryChecker::new(&robot, &Scene::new(vec![]));
    let hand = robot.spheres().len() - 1;
    assert!(reference.sphere_pairs().contains(&(0, hand)));
}
