//! Certified motion: an arm edge the checker certifies has every configuration collision-free,
//! judged by the `f64` parry reference on a grid of 1e-4 rad — and an edge clear by a
//! millimetre is never refused.

use glam::{DQuat, DVec3};
use mit_star_robot::{ArmChecker, Obstacle, ParryChecker, Scene, Shape};
use mit_star_spaces::{Never, Stop};
use mit_star_validity::{EdgeStatus, MotionProgress, StateValidity};
use proptest::prelude::*;
use std::cell::Cell;

use crate::arm_cases;
use arm_cases::{Graze, HOME, edge, graze, obstacle, panda, reference_hit, tab_scene};

fn certify(
    checker: &ArmChecker,
    a: &[f64],
    b: &[f64],
    stop: &dyn Stop,
) -> (EdgeStatus, MotionProgress) {
    let robot = panda();
    let mut progress = MotionProgress::default();
    let status = checker
        .certify_motion(robot.joint_space(), a, b, &mut progress, stop)
        .expect("the arm checker certifies motions of its joint space");
    (status, progress)
}

/// A tab 1 mm thick across the fingertip's path as the first joint turns: no end touches it, the
/// grid of a coarse step walks past it, and certification finds it.
#[test]
fn a_one_millimetre_plate_between_two_configurations_is_found() {
    let robot = panda();
    let (scene, a, b) = tab_scene(&robot);
    let checker = ArmChecker::new(&robot, &scene);
    let reference = ParryChecker::new(&robot, &scene);
    assert!(checker.is_valid(&a) && checker.is_valid(&b));
    assert!(reference.is_valid(&a) && reference.is_valid(&b));
    // The truth: the hand crosses the plate.
    assert!(reference_hit(&reference, &a, &b, 1e-4, 0.0).is_some());
    // Grids as fine as 0.17 rad (7 pieces) walk past it.
    let misses = |pieces: u32| {
        let grid: Vec<f64> = (0..=pieces)
            .flat_map(|k| {
                let t = f64::from(k) / f64::from(pieces);
                a.iter().zip(&b).map(move |(p, q)| p + (q - p) * t)
            })
            .collect();
        checker.first_invalid(&grid, 7).is_none()
    };
    let missed: Vec<u32> = (2..40).filter(|&n| misses(n)).collect();
    assert!(missed.iter().any(|&n| n >= 7), "{missed:?}");
    let (status, progress) = certify(&checker, &a, &b, &Never);
    assert_eq!(status, EdgeStatus::Invalid);
    assert!(progress.evaluations() < 400, "{progress:?}");
}

/// Counts polls; fires on every `every`-th one.
struct Every {
    polls: Cell<u64>,
    every: u64,
}

impl Stop for Every {
    fn should_stop(&self) -> bool {
        self.polls.set(self.polls.get() + 1);
        self.polls.get().is_multiple_of(self.every)
    }
}

#[test]
fn a_stopped_certification_resumes_and_agrees() {
    let robot = panda();
    // A ball on the base's axis, 0.2 mm beyond the margin from the nearest sphere at `HOME`:
    // turning the first joint keeps every distance to it, so the edge slides along it and
    // its certification takes many short pieces.
    let fk = mit_star_robot::Kinematics::new(&robot);
    let mut links = vec![glam::DAffine3::IDENTITY; fk.link_count()];
    let mut centres = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
    fk.sphere_centers_f64(&HOME, &mut links, &mut centres);
    let above = DVec3::new(0.0, 0.0, 1.6);
    let nearest = centres
        .iter()
        .map(|(c, r)| c.distance(above) - r)
        .fold(f64::INFINITY, f64::min);
    let build = |gap: f64| {
        Scene::new(vec![Obstacle::new(
            Shape::Sphere {
                radius: nearest - gap,
            },
            above,
            DQuat::IDENTITY,
        )])
    };
    let margin = ArmChecker::new(&robot, &build(0.0)).margin();
    let checker = ArmChecker::new(&robot, &build(margin + 2e-4));
    let (mut a, mut b) = (HOME, HOME);
    a[0] = -2.5;
    b[0] = 2.5;
    let (whole, done) = certify(&checker, &a, &b, &Never);
    assert_eq!(whole, EdgeStatus::Valid);
    // Long enough to be stopped by every stop below: a poll before every fourth batch of
    // eight (batches 1, 5, 9, …), so more than eight batches make three polls.
    assert!(done.evaluations() > 2 * 4 * 8, "{done:?} {whole:?}");
    for every in [2, 3] {
        let stop = Every {
            polls: Cell::new(0),
            every,
        };
        let mut progress = MotionProgress::default();
        let mut calls = 0;
        let status = loop {
            calls += 1;
            let status = checker
                .certify_motion(robot.joint_space(), &a, &b, &mut progress, &stop)
                .unwrap();
            if status != EdgeStatus::Unknown {
                break status;
            }
            assert!(calls < 10_000, "no progress");
        };
        assert_eq!(status, whole, "stopped every {every} polls");
        assert!(calls > 1);
        // Resuming repeats no work.
        assert_eq!(progress.evaluations(), done.evaluations(), "every {every}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Certified ⇒ no configuration in collision at 1e-4 rad (f64, parry); clear by 1 mm
    /// everywhere ⇒ certified.
    #[test]
    fn certified_edges_are_collision_free_everywhere(
        obstacles in prop::collection::vec(obstacle(), 1..6),
        (a, b) in edge(),
    ) {
        let robot = panda();
        let scene = Scene::new(obstacles);
        let checker = ArmChecker::new(&robot, &scene);
        let reference = ParryChecker::new(&robot, &scene);
        prop_assume!(checker.is_valid(&a) && checker.is_valid(&b));
        let (status, _) = certify(&checker, &a, &b, &Never);
        if status == EdgeStatus::Valid {
            prop_assert_eq!(reference_hit(&reference, &a, &b, 1e-4, 0.0), None);
        } else {
            prop_assert_eq!(status, EdgeStatus::Invalid);
            prop_assert!(
                reference_hit(&reference, &a, &b, 5e-4, 1e-3).is_some(),
                "an edge clear by 1 mm was refused"
            );
        }
    }
}

/// A sphere placed `extra` beyond the checker's margin from the Panda's farthest sphere in `+x`
/// at `HOME`: the problem from `HOME` to `HOME` in that scene.
fn home_near_a_sphere(extra: f64) -> mit_star_robot::ArmProblem {
    let robot = panda();
    let fk = mit_star_robot::Kinematics::new(&robot);
    let mut links = vec![glam::DAffine3::IDENTITY; fk.link_count()];
    let mut centers = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
    fk.sphere_centers_f64(&HOME, &mut links, &mut centers);
    let (c, r) = centers
        .iter()
        .copied()
        .max_by(|a, b| (a.0.x + a.1).total_cmp(&(b.0.x + b.1)))
        .unwrap();
    // Every other sphere ends at most where this one does in `x`, so it is the nearest.
    let radius = 0.05;
    let build = |gap: f64| {
        let at = DVec3::new(c.x + r + gap + radius, c.y, c.z);
        let scene = Scene::new(vec![Obstacle::new(
            Shape::Sphere { radius },
            at,
            DQuat::IDENTITY,
        )]);
        mit_star_robot::ArmProblem::new("floor", robot.clone(), scene, HOME.to_vec(), HOME.to_vec())
            .unwrap()
    };
    // The margin grows with the scene's extent: measured with the sphere nearly in place.
    let margin = mit_star_problems::PlanningProblem::validity(&build(extra)).margin();
    build(margin + extra)
}

/// A start or goal free of collision but within the certification floor beyond the margin can
/// be joined by no certified edge, so the problem refuses it (as it refuses one in collision);
/// a millimetre's clearance more is accepted.
#[test]
fn an_end_within_the_certification_floor_is_refused() {
    let close = home_near_a_sphere(0.5 * mit_star_robot::CERTIFICATION_FLOOR);
    let checker = mit_star_problems::PlanningProblem::validity(&close);
    assert!(checker.is_valid(&HOME), "free beyond the margin");
    let (status, _) = certify(checker, &HOME, &HOME, &Never);
    assert_eq!(
        status,
        EdgeStatus::Invalid,
        "no certified motion reaches it"
    );
    assert!(!close.ends_are_valid());
    assert!(!close.joinable(&HOME));
    let error = close.check_ends().unwrap_err().to_string();
    assert!(error.contains("certification floor"), "{error}");

    let clear = home_near_a_sphere(1e-3);
    assert!(clear.ends_are_valid());
    assert!(clear.check_ends().is_ok());
}

proptest! {
    // About four draws are set aside per case run (a sphere barely moving, an end in
    // collision): room for them beyond proptest's default of 1 024.
    #![proptest_config(ProptestConfig {
        cases: 96,
        max_global_rejects: 1 << 14,
        ..ProptestConfig::default()
    })]

    /// Grazes, where the directional bound matters: a ball beside a sphere's path, across its
    /// motion at a point of the edge, its surface `depth` beyond the sphere's (negative:
    /// into it). Certified ⇒ collision-free on the reference's grid of 1e-4 rad; and a ball
    /// reaching 0.2 mm into the path is never certified.
    #[test]
    fn grazing_balls_are_judged_exactly(
        (a, b) in edge(),
        at in 0.15..0.85_f64,
        depth in -1e-3..1e-3_f64,
        pick in 0..1000_usize,
        turn in 0.0..std::f64::consts::TAU,
    ) {
        let robot = panda();
        let graze = graze(&robot, (&a, &b), at, pick, turn);
        prop_assume!(graze.is_some());
        let Graze { centres, index, across } = graze.unwrap();
        let (c, r) = centres[index];
        let radius = 0.04;
        let ball = Obstacle::new(
            Shape::Sphere { radius },
            c + across * (r + radius + depth),
            DQuat::IDENTITY,
        );
        let scene = Scene::new(vec![ball]);
        let checker = ArmChecker::new(&robot, &scene);
        let reference = ParryChecker::new(&robot, &scene);
        prop_assume!(checker.is_valid(&a) && checker.is_valid(&b));
        let (status, _) = certify(&checker, &a, &b, &Never);
        if status == EdgeStatus::Valid {
            prop_assert!(depth > -2e-4, "a ball {depth} m into the path was certified");
            prop_assert_eq!(reference_hit(&reference, &a, &b, 1e-4, 0.0), None);
        }
    }
}
