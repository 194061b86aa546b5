//! The arm checker's batches (eight lanes, or sixteen where the CPU has AVX-512) against its
//! scalar check and against parry.
//!
//! Random scenes and runs of 1 to 40 configurations (some outside the joint limits): the
//! batch's first invalid configuration is the one the scalar check finds first, and the one
//! parry finds first, whenever no configuration of the run lies within the stated tolerance
//! of touching (see `parry_agreement.rs`); `any_invalid` names an invalid configuration
//! exactly when there is one, whichever link met an obstacle in the check before; `are_valid`
//! decides each configuration as the scalar check and parry do. Points of a prepared segment
//! (`first_invalid_on`, `any_invalid_on`) get the answers of the interpolated configurations,
//! bit for bit.

use glam::DVec3;
use mit_star_robot::{ArmChecker, Obstacle, ParryChecker, Scene, Shape};
use mit_star_spaces::StateSpace;
use mit_star_validity::{Preparation, Segment, StateValidity};
use proptest::prelude::*;

const TOLERANCE: f64 = 1e-4;

use crate::arm_cases;
use arm_cases::panda;

fn obstacle() -> impl Strategy<Value = Obstacle> {
    arm_cases::posed(prop_oneof![
        (0.01..0.4f64, 0.01..0.4f64, 0.01..0.4f64).prop_map(|(x, y, z)| Shape::Cuboid {
            half_extents: DVec3::new(x, y, z)
        }),
        (0.01..0.4f64, 0.01..0.3f64).prop_map(|(h, r)| Shape::Cylinder {
            half_height: h,
            radius: r
        }),
        (0.01..0.3f64).prop_map(|r| Shape::Sphere { radius: r }),
    ])
}

/// Configurations as one flat run; a few stray 5 % beyond the limits.
fn run() -> impl Strategy<Value = Vec<f64>> {
    let robot = panda();
    let space = robot.joint_space();
    let (lower, upper) = (space.lower().to_vec(), space.upper().to_vec());
    prop::collection::vec(prop::collection::vec(0.0..1.0f64, 7), 1..=40).prop_map(move |qs| {
        qs.into_iter()
            .flat_map(|u| {
                (0..7)
                    .map(|j| {
                        let span = upper[j] - lower[j];
                        lower[j] - 0.05 * span + u[j] * 1.1 * span
                    })
                    .collect::<Vec<_>>()
            })
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn batches_find_the_first_invalid_configuration(
        obstacles in prop::collection::vec(obstacle(), 0..5),
        states in run(),
    ) {
        let robot = panda();
        let scene = Scene::new(obstacles);
        let fast = ArmChecker::new(&robot, &scene);
        let reference = ParryChecker::new(&robot, &scene);
        let configurations: Vec<&[f64]> = states.chunks_exact(7).collect();
        let sure = configurations.iter().all(|q| {
            reference.is_valid_with_margin(q, TOLERANCE) == reference.is_valid_with_margin(q, -TOLERANCE)
        });
        prop_assume!(sure);
        let scalar = configurations.iter().position(|q| !fast.is_valid(q));
        let parry = configurations.iter().position(|q| !reference.is_valid(q));
        prop_assert!(matches!(fast.batch_width(), 8 | 16), "{}", fast.batch_width());
        prop_assert_eq!(fast.first_invalid(&states, 7), scalar);
        prop_assert_eq!(scalar, parry);
        // `any_invalid` (edge checks): some configuration exactly when there is one, and an
        // invalid one.
        let any = fast.any_invalid(&states, 7);
        prop_assert_eq!(any.is_some(), scalar.is_some());
        if let Some(i) = any {
            prop_assert!(!fast.is_valid(configurations[i]), "configuration {} is valid", i);
        }
        // Each configuration alone, one after the other: a check that may stop at any contact
        // tests first the link that met an obstacle in the check before, which here is
        // another configuration's.
        for (i, q) in configurations.iter().enumerate() {
            prop_assert_eq!(
                fast.any_invalid(q, 7).is_some(),
                !reference.is_valid(q),
                "configuration {}",
                i
            );
        }
        // `are_valid` (samplers): every configuration's own answer, into as many answers as
        // are asked for.
        let mut valid = vec![false; configurations.len() + 1];
        fast.are_valid(&states, 7, &mut valid);
        for (i, q) in configurations.iter().enumerate() {
            prop_assert_eq!(valid[i], fast.is_valid(q), "configuration {}", i);
            prop_assert_eq!(valid[i], reference.is_valid(q), "configuration {}", i);
        }
        prop_assert!(!valid[configurations.len()], "an answer beyond the states was written");
        let fewer = configurations.len() / 2;
        let mut some = vec![false; fewer];
        fast.are_valid(&states, 7, &mut some);
        prop_assert_eq!(&some[..], &valid[..fewer]);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn prepared_segments_answer_as_interpolated_configurations(
        obstacles in prop::collection::vec(obstacle(), 0..5),
        ends in run(),
        fractions in prop::collection::vec(0.0..=1.0f64, 1..=40),
    ) {
        prop_assume!(ends.len() >= 14);
        let robot = panda();
        let space = robot.joint_space();
        let checker = ArmChecker::new(&robot, &Scene::new(obstacles));
        let (a, b) = (&ends[..7], &ends[7..14]);
        let mut segment = Segment::default();
        segment.set(a, b);
        prop_assert_eq!(checker.prepare_segment(&mut segment), Preparation::Prepared);
        let mut states = vec![0.0; 7 * fractions.len()];
        for (state, &t) in states.chunks_exact_mut(7).zip(&fractions) {
            space.interpolate(a, b, t, state);
        }
        let first = checker.first_invalid(&states, 7);
        prop_assert_eq!(checker.first_invalid_on(&mut segment, &fractions), first);
        let any = checker.any_invalid_on(&mut segment, &fractions);
        prop_assert_eq!(any.is_some(), first.is_some());
        if let Some(i) = any {
            prop_assert!(!checker.is_valid(&states[7 * i..7 * i + 7]), "point {} is valid", i);
        }
    }
}

#[test]
fn a_batch_of_the_wrong_dimension_is_invalid_at_once() {
    let checker = ArmChecker::new(&panda(), &Scene::new(Vec::new()));
    assert_eq!(checker.first_invalid(&[0.0; 12], 6), Some(0));
    let home = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];
    let batch: Vec<f64> = home.iter().cycle().take(7 * 11).copied().collect();
    assert_eq!(checker.first_invalid(&batch, 7), None);
    let mut broken = batch;
    broken[7 * 9 + 2] = f64::NAN;
    assert_eq!(checker.first_invalid(&broken, 7), Some(9));
}
