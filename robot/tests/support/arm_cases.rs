//! Cases shared by the arm-motion tests: the Panda, a thin tab across its fingertip's path,
//! random obstacles and edges, the dense `f64` reference verdict on an edge, and a planned path
//! of a MotionBenchMaker problem.

// Each test binary includes this file and uses a subset.
#![allow(dead_code)]

use glam::{DQuat, DVec3};
use mit_star_robot::{ArmProblem, Obstacle, ParryChecker, RobotModel, Scene, Shape};
use mit_star_spaces::StateSpace;
use proptest::prelude::*;

pub(crate) fn panda() -> RobotModel {
    ArmProblem::panda().unwrap()
}

pub(crate) const HOME: [f64; 7] = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];

/// The reference verdict on the edge `a → b` at steps of at most `step` rad, with every sphere
/// grown by `grow` metres: the first fraction found in collision, if any.
pub(crate) fn reference_hit(
    reference: &ParryChecker,
    a: &[f64],
    b: &[f64],
    step: f64,
    grow: f64,
) -> Option<f64> {
    let length = mit_star_spaces::euclidean_distance(a, b);
    let pieces = (length / step).ceil().max(1.0) as u64;
    let mut q = vec![0.0; a.len()];
    (0..=pieces).find_map(|k| {
        let t = k as f64 / pieces as f64;
        if k == pieces {
            // `a + (b - a) · 1` can round past `b`, and past a joint limit `b` sits on.
            q.copy_from_slice(b);
        } else {
            for (x, (p, r)) in q.iter_mut().zip(a.iter().zip(b)) {
                *x = p + (r - p) * t;
            }
        }
        (!reference.is_valid_with_margin(&q, grow)).then_some(t)
    })
}

/// A tab 1 mm thick across the fingertip's path as the first joint turns from `a` to `b`
/// (returned): no end touches it, and grids of 7 or more pieces walk past it.
pub(crate) fn tab_scene(robot: &RobotModel) -> (Scene, [f64; 7], [f64; 7]) {
    // The sphere farthest from the first joint's axis, at the home configuration.
    let fk = mit_star_robot::Kinematics::new(robot);
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
    let (mut a, mut b) = (HOME, HOME);
    a[0] = -0.6;
    b[0] = 0.55;
    (scene, a, b)
}

/// Obstacles of thin plates, cylinders and balls, anywhere near the Panda.
pub(crate) fn obstacle() -> impl Strategy<Value = Obstacle> {
    posed(prop_oneof![
        (0.0005..0.3f64, 0.01..0.3f64, 0.01..0.3f64).prop_map(|(x, y, z)| Shape::Cuboid {
            half_extents: DVec3::new(x, y, z)
        }),
        (0.01..0.3f64, 0.005..0.2f64).prop_map(|(h, r)| Shape::Cylinder {
            half_height: h,
            radius: r
        }),
        (0.005..0.2f64).prop_map(|r| Shape::Sphere { radius: r }),
    ])
}

/// Obstacles of the shapes `shape` draws, placed and turned at random within the Panda's reach.
pub(crate) fn posed(shape: impl Strategy<Value = Shape>) -> impl Strategy<Value = Obstacle> {
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

pub(crate) fn edge() -> impl Strategy<Value = (Vec<f64>, Vec<f64>)> {
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

/// Where a test places an obstacle to graze the edge `a → b`: at the fraction `at` of it, the
/// sphere `index` and a unit direction `across` its motion there.
pub(crate) struct Graze {
    /// Every sphere's centre and radius at `at`.
    pub(crate) centres: Vec<(DVec3, f64)>,
    pub(crate) index: usize,
    pub(crate) across: DVec3,
}

/// The graze of sphere `pick` (modulo the number of spheres) at the fraction `at` of `a → b`,
/// its direction across the motion turned by `turn` about it; `None` where that sphere moves
/// less than 5 cm per unit of the edge (its direction of motion is then ill-defined).
pub(crate) fn graze(
    robot: &RobotModel,
    (a, b): (&[f64], &[f64]),
    at: f64,
    pick: usize,
    turn: f64,
) -> Option<Graze> {
    let fk = mit_star_robot::Kinematics::new(robot);
    let mut links = vec![glam::DAffine3::IDENTITY; fk.link_count()];
    let mut centres = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
    let q = |t: f64| -> Vec<f64> { a.iter().zip(b).map(|(x, y)| x + (y - x) * t).collect() };
    let e = 1e-6;
    fk.sphere_centers_f64(&q(at + e), &mut links, &mut centres);
    let ahead = centres.clone();
    fk.sphere_centers_f64(&q(at), &mut links, &mut centres);
    let index = pick % centres.len();
    let velocity = (ahead[index].0 - centres[index].0) / e;
    if velocity.length() <= 0.05 {
        return None;
    }
    let u = velocity.normalize();
    let side = u.any_orthonormal_vector();
    let across = side * turn.cos() + u.cross(side) * turn.sin();
    Some(Graze {
        centres,
        index,
        across,
    })
}

/// Problem 1 of the MotionBenchMaker folder `scene` (in `tests/data/mbm`) and RRT-Connect's
/// first path on it (range 1, seeded), within 10 s.
pub(crate) fn first_mbm_path(scene: &str, seed: u64) -> (ArmProblem, Vec<Vec<f64>>) {
    use mit_star::{FirstSolution, Parameters, Planner, TerminationExt, TimeLimit};
    let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mbm");
    let problem = ArmProblem::panda_mbm(&folder.join(scene), 1).unwrap();
    let parameters = Parameters {
        range: Some(1.0),
        seed,
        ..Parameters::default()
    };
    let mut planner = mit_star::RrtConnect::for_problem(&problem, &parameters).unwrap();
    let outcome = planner
        .solve(&FirstSolution.or(TimeLimit::seconds(10.0)))
        .unwrap();
    let path = outcome
        .solution()
        .unwrap()
        .path
        .iter()
        .map(<[f64]>::to_vec)
        .collect();
    (problem, path)
}
