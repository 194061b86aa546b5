//! Certified motion: an arm edge the checker certifies has every configuration collision-free,
//! judged by the `f64` parry reference on a grid of 1e-4 rad — and an edge clear by a
//! millimetre is never refused.

use glam::{DQuat, DVec3};
use proptest::prelude::*;
use robot::{ArmChecker, ArmProblem, Obstacle, ParryChecker, RobotModel, Scene, Shape};
use spaces::{Never, StateSpace, Stop};
use std::cell::Cell;
use validity::{EdgeStatus, MotionProgress, StateValidity};

fn panda() -> RobotModel {
    ArmProblem::panda().unwrap()
}

const HOME: [f64; 7] = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];

/// The reference verdict on the edge `a → b` at steps of at most `step` rad, with every sphere
/// grown by `grow` metres: the first fraction found in collision, if any.
fn reference_hit(
    reference: &ParryChecker,
    a: &[f64],
    b: &[f64],
    step: f64,
    grow: f64,
) -> Option<f64> {
    let length = spaces::euclidean_distance(a, b);
    let pieces = (length / step).ceil().max(1.0) as u64;
    let mut q = vec![0.0; a.len()];
    (0..=pieces).find_map(|k| {
        let t = k as f64 / pieces as f64;
        for (x, (p, r)) in q.iter_mut().zip(a.iter().zip(b)) {
            *x = p + (r - p) * t;
        }
        (!reference.is_valid_with_margin(&q, grow)).then_some(t)
    })
}

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
    // The sphere farthest from the first joint's axis, at the home configuration.
    let fk = robot::Kinematics::new(&robot);
    let mut links = vec![glam::DAffine3::IDENTITY; fk.link_count()];
    let mut centers = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
    fk.sphere_centers_f64(&HOME, &mut links, &mut centers);
    let (tip, radius) = centers
        .iter()
        .copied()
        .max_by(|x, y| {
            let reach = |(c, r): (DVec3, f64)| c.truncate().length() + r;
            reach(*x).total_cmp(&reach(*y))
        })
        .unwrap();
    // A tab 1 mm thick across the path of that sphere's outer rim, 4 mm square: only the
    // rim's outer 3 mm pass through it.
    let outward = DVec3::new(tip.x, tip.y, 0.0).normalize();
    let plate = Obstacle::new(
        Shape::Cuboid {
            half_extents: DVec3::new(0.002, 0.0005, 0.002),
        },
        tip + outward * (radius - 0.001),
        DQuat::from_rotation_z(tip.y.atan2(tip.x)),
    );
    let scene = Scene::new(vec![plate]);
    let checker = ArmChecker::new(&robot, &scene);
    let reference = ParryChecker::new(&robot, &scene);
    let (mut a, mut b) = (HOME, HOME);
    a[0] = -0.6;
    b[0] = 0.55;
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
    let ball = Obstacle::new(
        Shape::Sphere { radius: 0.1 },
        DVec3::new(0.45, 0.3, 0.6),
        DQuat::IDENTITY,
    );
    let checker = ArmChecker::new(&robot, &Scene::new(vec![ball]));
    let (mut a, mut b) = (HOME, HOME);
    a[0] = -1.2;
    b[0] = 1.0;
    b[3] = -1.9;
    let (whole, done) = certify(&checker, &a, &b, &Never);
    for every in [2, 3, 5] {
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

fn obstacle() -> impl Strategy<Value = Obstacle> {
    let shape = prop_oneof![
        (0.0005..0.3f64, 0.01..0.3f64, 0.01..0.3f64).prop_map(|(x, y, z)| Shape::Cuboid {
            half_extents: DVec3::new(x, y, z)
        }),
        (0.01..0.3f64, 0.005..0.2f64).prop_map(|(h, r)| Shape::Cylinder {
            half_height: h,
            radius: r
        }),
        (0.005..0.2f64).prop_map(|r| Shape::Sphere { radius: r }),
    ];
    (
        shape,
        (-0.9..0.9f64, -0.9..0.9f64, -0.2..1.3f64),
        (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64, 0.1..1.0f64),
    )
        .prop_map(|(s, (x, y, z), (a, b, c, d))| {
            Obstacle::new(
                s,
                DVec3::new(x, y, z),
                DQuat::from_xyzw(a, b, c, d).normalize(),
            )
        })
}

fn edge() -> impl Strategy<Value = (Vec<f64>, Vec<f64>)> {
    let robot = panda();
    let space = robot.joint_space();
    let (lower, upper) = (space.lower().to_vec(), space.upper().to_vec());
    (
        prop::collection::vec(0.0..1.0f64, 7),
        prop::collection::vec(-1.0..1.0f64, 7),
        0.02..1.2f64,
    )
        .prop_map(move |(u, d, length)| {
            let a: Vec<f64> = (0..7)
                .map(|j| lower[j] + u[j] * (upper[j] - lower[j]))
                .collect();
            let norm = d.iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-9);
            let b = (0..7)
                .map(|j| (a[j] + d[j] / norm * length).clamp(lower[j], upper[j]))
                .collect();
            (a, b)
        })
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
