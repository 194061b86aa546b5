//! The fast checker against parry.
//!
//! Random Panda configurations in random scenes of boxes, cylinders and balls: whenever the
//! reference ([`ParryChecker`], `f64`, parry queries, no culling) is sure — the answer does not
//! change when every robot sphere grows or shrinks by [`TOLERANCE`] — the fast `f32` checker
//! must give the same answer. Only contacts within 0.1 mm of touching may differ (the fast
//! checker computes in `f32`, whose rounding at a metre is about 0.1 µm, so the tolerance is
//! generous by three orders of magnitude while still far below any sphere model's accuracy).

use glam::{DQuat, DVec3, Vec3A};
use mit_star_robot::{ArmChecker, Obstacle, ParryChecker, RobotModel, Scene, Shape};
use mit_star_spaces::StateSpace;
use mit_star_validity::StateValidity;
use parry3d_f64::math::Pose;
use parry3d_f64::query::intersection_test;
use parry3d_f64::shape::{Ball, Cuboid, Cylinder};
use proptest::prelude::*;

/// Metres: contacts closer than this to touching may be judged either way.
const TOLERANCE: f64 = 1e-4;

fn panda() -> RobotModel {
    RobotModel::from_urdf_str(include_str!("../data/panda/panda_spherized.urdf"))
        .unwrap()
        .with_srdf_str(include_str!("../data/panda/panda.srdf"))
        .unwrap()
}

fn shape() -> impl Strategy<Value = Shape> {
    prop_oneof![
        (0.01..0.4f64, 0.01..0.4f64, 0.01..0.4f64).prop_map(|(x, y, z)| Shape::Cuboid {
            half_extents: DVec3::new(x, y, z)
        }),
        (0.01..0.4f64, 0.01..0.3f64).prop_map(|(h, r)| Shape::Cylinder {
            half_height: h,
            radius: r
        }),
        (0.01..0.3f64).prop_map(|r| Shape::Sphere { radius: r }),
    ]
}

fn obstacle() -> impl Strategy<Value = Obstacle> {
    (
        shape(),
        (-0.9..0.9f64, -0.9..0.9f64, -0.2..1.3f64),
        (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64),
    )
        .prop_filter_map("a rotation", |(s, (x, y, z), (a, b, c, d))| {
            let q = DQuat::from_xyzw(a, b, c, d);
            (q.length() > 0.1).then(|| Obstacle::new(s, DVec3::new(x, y, z), q.normalize()))
        })
}

fn configuration() -> impl Strategy<Value = Vec<f64>> {
    let space = panda();
    let space = space.joint_space();
    let ranges: Vec<_> = space
        .lower()
        .iter()
        .zip(space.upper())
        .map(|(&l, &u)| l..=u)
        .collect();
    ranges
}

/// `Some(valid)` when the reference is sure, `None` within the tolerance of touching.
fn sure(reference: &ParryChecker, q: &[f64]) -> Option<bool> {
    let grown = reference.is_valid_with_margin(q, TOLERANCE);
    let shrunk = reference.is_valid_with_margin(q, -TOLERANCE);
    (grown == shrunk).then_some(grown)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn the_fast_checker_agrees_with_parry(
        obstacles in prop::collection::vec(obstacle(), 0..5),
        q in configuration(),
    ) {
        let robot = panda();
        let scene = Scene::new(obstacles);
        let fast = ArmChecker::new(&robot, &scene);
        let reference = ParryChecker::new(&robot, &scene);
        if let Some(valid) = sure(&reference, &q) {
            prop_assert_eq!(fast.is_valid(&q), valid);
        }
    }

    #[test]
    fn sphere_tests_agree_with_parry(
        o in obstacle(),
        (x, y, z) in (-1.3..1.3f64, -1.3..1.3f64, -0.6..1.7f64),
        r in 0.005..0.2f64,
    ) {
        let c = DVec3::new(x, y, z);
        let pose = o.pose();
        let rotation = DQuat::from_mat3(&pose.matrix3);
        let at = |extra: DQuat| Pose::from_parts(pose.translation, rotation * extra);
        let ball = |radius: f64| {
            let p = Pose::from_translation(c);
            let b = Ball::new(radius);
            match o.shape() {
                Shape::Cuboid { half_extents } => {
                    intersection_test(&p, &b, &at(DQuat::IDENTITY), &Cuboid::new(half_extents))
                }
                Shape::Cylinder { half_height, radius } => intersection_test(
                    &p,
                    &b,
                    &at(DQuat::from_rotation_x(std::f64::consts::FRAC_PI_2)),
                    &Cylinder::new(half_height, radius),
                ),
                Shape::Sphere { radius } => {
                    intersection_test(&p, &b, &at(DQuat::IDENTITY), &Ball::new(radius))
                }
            }
            .unwrap()
            .intersecting
        };
        let (grown, shrunk) = (ball(r + TOLERANCE), ball(r - TOLERANCE));
        if grown == shrunk {
            prop_assert_eq!(o.collides_sphere(Vec3A::new(x as f32, y as f32, z as f32), r as f32), grown);
            prop_assert_eq!(o.collides_sphere_f64(c, r), grown);
        }
    }
}

/// The property above cannot pass vacuously: over a fixed set of scenes and configurations
/// both answers are common, self-collisions included, and the fast checker agrees on every
/// sure case.
#[test]
fn agreement_covers_free_scene_and_self_collision_cases() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
    let mut runner = TestRunner::new_with_rng(
        Config::default(),
        TestRng::from_seed(RngAlgorithm::ChaCha, &[7; 32]),
    );
    let robot = panda();
    let empty = Scene::new(Vec::new());
    let self_only = ParryChecker::new(&robot, &empty);
    let (mut free, mut blocked, mut self_hits, mut unsure) = (0, 0, 0, 0);
    for _ in 0..100 {
        let obstacles = prop::collection::vec(obstacle(), 1..5)
            .new_tree(&mut runner)
            .unwrap()
            .current();
        let scene = Scene::new(obstacles);
        let fast = ArmChecker::new(&robot, &scene);
        let reference = ParryChecker::new(&robot, &scene);
        for _ in 0..20 {
            let q = configuration().new_tree(&mut runner).unwrap().current();
            match sure(&reference, &q) {
                None => unsure += 1,
                Some(valid) => {
                    assert_eq!(fast.is_valid(&q), valid, "{q:?}");
                    if valid {
                        free += 1;
                    } else {
                        blocked += 1;
                        if !self_only.is_valid(&q) {
                            self_hits += 1;
                        }
                    }
                }
            }
        }
    }
    eprintln!("{free} free, {blocked} blocked ({self_hits} self), {unsure} unsure");
    assert!(
        free > 200 && blocked > 200,
        "{free} free, {blocked} blocked"
    );
    assert!(self_hits > 50, "{self_hits} self-collisions");
    assert!(unsure < 20, "{unsure} within the tolerance");
}
