//! The arm checker is one-sided and has one arithmetic: at contacts within micrometres of
//! touching — where `f32` rounding decides — a configuration it calls valid is valid in `f64`
//! (parry, no margin), and its single and eight-lane answers are the same.

use glam::{DQuat, DVec3};
use mit_star_robot::{ArmChecker, ArmProblem, Kinematics, Obstacle, ParryChecker, Scene, Shape};
use mit_star_spaces::StateSpace;
use mit_star_validity::StateValidity;
use proptest::prelude::*;

fn configuration() -> impl Strategy<Value = Vec<f64>> {
    let robot = ArmProblem::panda().unwrap();
    let space = robot.joint_space();
    let (lower, upper) = (space.lower().to_vec(), space.upper().to_vec());
    prop::collection::vec(0.0..1.0f64, 7).prop_map(move |u| {
        (0..7)
            .map(|j| lower[j] + u[j] * (upper[j] - lower[j]))
            .collect()
    })
}

/// An obstacle of kind `kind` approached from the direction `(yaw, pitch)` towards sphere
/// `sphere` of the Panda at `q`, then slid along that direction until the robot's nearest
/// sphere is about `gap` metres from it (negative: overlapping by about that much), measured
/// in `f64`. Returns the obstacle and the distance measured after the last move (0 when they
/// overlap).
fn near(q: &[f64], sphere: usize, kind: u8, (yaw, pitch): (f64, f64), gap: f64) -> (Obstacle, f64) {
    let robot = ArmProblem::panda().unwrap();
    let fk = Kinematics::new(&robot);
    let mut links = vec![glam::DAffine3::IDENTITY; fk.link_count()];
    let mut centers = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
    fk.sphere_centers_f64(q, &mut links, &mut centers);
    let (c, r) = centers[sphere % centers.len()];
    let rotation = DQuat::from_euler(glam::EulerRot::ZYX, yaw, pitch, 0.0);
    let outward = rotation * DVec3::X;
    let place = |offset: f64| match kind % 3 {
        0 => {
            let half = DVec3::new(0.05, 0.2, 0.15);
            Obstacle::new(
                Shape::Cuboid { half_extents: half },
                c + outward * (r + offset + half.x),
                rotation,
            )
        }
        1 => Obstacle::new(
            Shape::Sphere { radius: 0.07 },
            c + outward * (r + offset + 0.07),
            DQuat::IDENTITY,
        ),
        // A cylinder along the rotated z axis, its side facing the sphere.
        _ => Obstacle::new(
            Shape::Cylinder {
                half_height: 0.2,
                radius: 0.04,
            },
            c + outward * (r + offset + 0.04),
            rotation,
        ),
    };
    let distance = |obstacle: &Obstacle| {
        let reference = ParryChecker::new(&robot, &Scene::new(vec![*obstacle]));
        let mut gaps = vec![0.0; centers.len()];
        let mut pairs = vec![0.0; reference.sphere_pairs().len()];
        reference.gaps(q, &mut gaps, &mut pairs);
        gaps.into_iter().fold(f64::INFINITY, f64::min)
    };
    // Slide out until clear, then in until the nearest sphere is 1 nm away; overlaps are
    // made from there.
    let mut offset = 0.01;
    while distance(&place(offset)) <= 0.0 {
        offset += 0.01;
    }
    for _ in 0..30 {
        let d = distance(&place(offset));
        if (d - 1e-9).abs() < 1e-10 {
            break;
        }
        offset -= d - 1e-9;
    }
    let obstacle = place(offset - 1e-9 + gap);
    let measured = distance(&obstacle);
    (obstacle, measured)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn valid_in_f32_is_valid_in_f64_and_lanes_agree_with_single_checks(
        q in configuration(),
        others in prop::collection::vec(configuration(), 7),
        sphere in 0usize..59,
        kind in 0u8..3,
        direction in (-3.1..3.1f64, -1.5..1.5f64),
        gap in prop_oneof![-2e-6..2e-6f64, -5e-5..1.5e-4f64],
    ) {
        let robot = ArmProblem::panda().unwrap();
        prop_assume!(ParryChecker::new(&robot, &Scene::new(vec![])).is_valid_with_margin(&q, 1e-3));
        let (obstacle, measured) = near(&q, sphere, kind, direction, gap);
        let scene = Scene::new(vec![obstacle]);
        let fast = ArmChecker::new(&robot, &scene);
        let reference = ParryChecker::new(&robot, &scene);
        if fast.is_valid(&q) {
            prop_assert!(reference.is_valid(&q), "valid in f32, colliding in f64 (gap {gap})");
        }
        // One arithmetic: the lane of a batch answers as the single check does.
        let mut batch = q.clone();
        for o in &others {
            batch.extend_from_slice(o);
        }
        let singles: Vec<bool> = std::iter::once(&q).chain(&others).map(|c| fast.is_valid(c)).collect();
        prop_assert_eq!(fast.first_invalid(&batch, 7), singles.iter().position(|v| !v));
        // Not vacuous: a gap wider than twice the margin is seen as free.
        if measured > 2.0 * fast.margin() {
            prop_assert!(fast.is_valid(&q), "kind {kind}: clear by {measured}, margin {}", fast.margin());
        }
    }
}

#[test]
fn the_margin_is_small_and_stated() {
    let robot = ArmProblem::panda().unwrap();
    let checker = ArmChecker::new(&robot, &Scene::new(vec![]));
    // 2e-5 m plus 2e-6 per metre of reach and scene extent: tens of micrometres.
    assert!(
        checker.margin() > 2e-5 && checker.margin() < 5e-5,
        "{}",
        checker.margin()
    );
    let space = robot.joint_space();
    assert_eq!(space.dimension(), 7);
}
