//! Properties of the point-cloud inputs and filters: sampled points lie on their primitive's
//! surface, voxel and minimum-distance downsampling keep what they promise, crops keep
//! exactly the points inside, and the robot filter removes exactly the points within its
//! padding of a collision sphere.

use glam::{DAffine3, DQuat, DVec3, Vec3};
use mit_star_robot::{ArmProblem, Kinematics, Obstacle, SensorPose, Shape};
use mit_star_spaces::StateSpace;
use proptest::prelude::*;

fn shape() -> impl Strategy<Value = Shape> {
    prop_oneof![
        (0.005..1.0f64, 0.005..1.0f64, 0.005..1.0f64).prop_map(|(x, y, z)| Shape::Cuboid {
            half_extents: DVec3::new(x, y, z)
        }),
        (0.005..1.0f64, 0.005..1.0f64).prop_map(|(half_height, radius)| Shape::Cylinder {
            half_height,
            radius
        }),
        (0.005..1.0f64).prop_map(|radius| Shape::Sphere { radius }),
    ]
}

fn obstacle() -> impl Strategy<Value = Obstacle> {
    (
        shape(),
        prop::array::uniform3(-2.0..2.0f64),
        prop::array::uniform4(-1.0..1.0f64),
    )
        .prop_filter("a rotation", |(_, _, q)| {
            q.iter().map(|c| c * c).sum::<f64>() > 0.01
        })
        .prop_map(|(shape, p, [x, y, z, w])| {
            Obstacle::new(shape, DVec3::from_array(p), DQuat::from_xyzw(x, y, z, w))
        })
}

/// How far a point (in the solid's frame) is from the solid's surface, inside or out.
fn surface_distance(shape: Shape, p: DVec3) -> f64 {
    match shape {
        Shape::Cuboid { half_extents } => {
            let excess = p.abs() - half_extents;
            if excess.max_element() > 0.0 {
                excess.max(DVec3::ZERO).length()
            } else {
                -excess.max_element()
            }
        }
        Shape::Cylinder {
            half_height,
            radius,
        } => {
            let (radial, axial) = (p.x.hypot(p.y) - radius, p.z.abs() - half_height);
            if radial > 0.0 || axial > 0.0 {
                radial.max(0.0).hypot(axial.max(0.0))
            } else {
                -radial.max(axial)
            }
        }
        Shape::Sphere { radius } => (p.length() - radius).abs(),
    }
}

fn points(range: f32, max: usize) -> impl Strategy<Value = Vec<Vec3>> {
    // A mix of spread points and tight clusters, so that voxels and radii hold several.
    prop::collection::vec(
        (prop::array::uniform3(-range..range), prop::bool::ANY),
        0..max,
    )
    .prop_map(|raw| {
        raw.iter()
            .scan(Vec3::ZERO, |last, &(p, near)| {
                let p = Vec3::from_array(p);
                *last = if near { *last + p * 0.01 } else { p };
                Some(*last)
            })
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn sampled_points_lie_on_the_surface(obstacle in obstacle(), seed in any::<u64>()) {
        let cloud = mit_star_robot::sample_surfaces(&[obstacle], 300, seed).unwrap();
        prop_assert_eq!(cloud.len(), 300);
        let inverse = obstacle.pose().inverse();
        for p in &cloud.points {
            let local = inverse.transform_point3(p.as_dvec3());
            let d = surface_distance(obstacle.shape(), local);
            prop_assert!(d <= 1e-5, "{:?}: {} is {} from the surface", obstacle.shape(), p, d);
        }
    }

    #[test]
    fn voxels_keep_one_point_each_and_one_near_every_point(
        input in points(1.0, 400),
        size in 0.005..0.5f64,
    ) {
        let mut kept = input.clone();
        let report = mit_star_robot::voxel_downsample(&mut kept, size).unwrap();
        prop_assert_eq!((report.before, report.after), (input.len(), kept.len()));
        let cell = |p: &Vec3| (p.as_dvec3() * (1.0 / size)).floor().as_i64vec3();
        let mut cells: Vec<_> = kept.iter().map(cell).collect();
        cells.sort_by_key(|c| c.to_array());
        cells.dedup();
        prop_assert_eq!(cells.len(), kept.len(), "two kept points share a voxel");
        let diagonal = size * 3f64.sqrt() + 1e-6;
        for p in &input {
            prop_assert!(
                kept.iter().any(|k| k.as_dvec3().distance(p.as_dvec3()) <= diagonal),
                "{} has no kept point within {}", p, diagonal
            );
        }
        // Kept points are input points, in the input's order.
        let mut rest = input.iter();
        for k in &kept {
            prop_assert!(rest.any(|p| p == k));
        }
    }

    #[test]
    fn minimum_distance_keeps_points_apart_and_near_every_point(
        input in points(0.5, 300),
        radius in 0.005..0.3f64,
    ) {
        let mut kept = input.clone();
        mit_star_robot::min_distance_downsample(&mut kept, radius).unwrap();
        for (i, a) in kept.iter().enumerate() {
            for b in &kept[i + 1..] {
                prop_assert!(a.as_dvec3().distance(b.as_dvec3()) >= radius * (1.0 - 1e-12));
            }
        }
        for p in &input {
            prop_assert!(kept.iter().any(|k| k.as_dvec3().distance(p.as_dvec3()) <= radius));
        }
    }

    #[test]
    fn crops_keep_exactly_the_points_inside(
        input in points(2.0, 300),
        center in prop::array::uniform3(-1.0..1.0f64),
        radius in 0.0..2.0f64,
        corners in (prop::array::uniform3(-2.0..2.0f64), prop::array::uniform3(0.0..2.0f64)),
    ) {
        let center = DVec3::from_array(center);
        let mut ball = input.clone();
        mit_star_robot::crop_to_ball(&mut ball, center, radius).unwrap();
        let inside: Vec<Vec3> = input
            .iter()
            .copied()
            .filter(|p| (p.as_dvec3() - center).length() <= radius * (1.0 + 1e-12))
            .collect();
        let clear: Vec<Vec3> = inside
            .iter()
            .copied()
            .filter(|p| (p.as_dvec3() - center).length() <= radius * (1.0 - 1e-12))
            .collect();
        // Exactly the inside ones (a point within rounding of the sphere may go either way).
        prop_assert!(ball.iter().all(|p| inside.contains(p)));
        prop_assert!(clear.iter().all(|p| ball.contains(p)));
        let lower = DVec3::from_array(corners.0);
        let upper = lower + DVec3::from_array(corners.1);
        let mut boxed = input.clone();
        mit_star_robot::crop_to_box(&mut boxed, lower, upper).unwrap();
        let expected: Vec<Vec3> = input
            .iter()
            .copied()
            .filter(|p| {
                let p = p.as_dvec3();
                (0..3).all(|i| lower[i] <= p[i] && p[i] <= upper[i])
            })
            .collect();
        prop_assert_eq!(boxed, expected);
    }

    #[test]
    fn sensor_poses_move_clouds_rigidly(
        input in points(2.0, 50),
        xyz in prop::array::uniform3(-2.0..2.0f64),
        rpy in prop::array::uniform3(-3.2..3.2f64),
    ) {
        let pose = SensorPose::from_xyz_rpy(xyz, rpy).unwrap();
        let mut moved = input.clone();
        pose.apply(&mut moved);
        let back: DAffine3 = pose.affine().inverse();
        for (p, m) in input.iter().zip(&moved) {
            prop_assert!((back.transform_point3(m.as_dvec3()) - p.as_dvec3()).length() < 1e-5);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn the_robot_filter_removes_exactly_the_points_near_its_spheres(
        u in prop::collection::vec(0.0..1.0f64, 7),
        offsets in prop::collection::vec((0usize..59, prop::array::uniform3(-0.15..0.15f64)), 0..300),
        padding in 0.0..0.05f64,
    ) {
        let robot = ArmProblem::panda().unwrap();
        let space = robot.joint_space();
        let q: Vec<f64> = (0..7).map(|j| space.lower()[j] + u[j] * (space.upper()[j] - space.lower()[j])).collect();
        let fk = Kinematics::new(&robot);
        let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
        let mut spheres = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
        fk.sphere_centers_f64(&q, &mut links, &mut spheres);
        // Points scattered around the spheres: some inside the padding, some outside.
        let input: Vec<Vec3> = offsets
            .iter()
            .map(|&(s, d)| (spheres[s].0 + DVec3::from_array(d)).as_vec3())
            .collect();
        let mut kept = input.clone();
        let report = mit_star_robot::remove_robot_points(&mut kept, &robot, &q, padding).unwrap();
        let expected: Vec<Vec3> = input
            .iter()
            .copied()
            .filter(|p| spheres.iter().all(|&(c, r)| p.as_dvec3().distance(c) > r + padding))
            .collect();
        prop_assert_eq!(&kept, &expected);
        prop_assert_eq!(report.removed(), input.len() - expected.len());
    }
}

#[test]
fn the_robot_filter_refuses_bad_configurations_and_padding() {
    let robot = ArmProblem::panda().unwrap();
    let mut points = vec![Vec3::ZERO];
    assert!(mit_star_robot::remove_robot_points(&mut points, &robot, &[0.0; 6], 0.0).is_err());
    assert!(mit_star_robot::remove_robot_points(&mut points, &robot, &[f64::NAN; 7], 0.0).is_err());
    let e = mit_star_robot::remove_robot_points(&mut points, &robot, &[0.0; 7], -0.01).unwrap_err();
    assert!(e.to_string().starts_with("padding:"), "{e}");
    // The base sphere's centre: the point there goes.
    points[0] = Vec3::new(0.0, 0.0, 0.05);
    let report = mit_star_robot::remove_robot_points(&mut points, &robot, &[0.0; 7], 0.0).unwrap();
    assert_eq!((report.before, report.after), (1, 0));
    assert!(mit_star_robot::voxel_downsample(&mut points, 0.0).is_err());
    assert!(mit_star_robot::min_distance_downsample(&mut points, f64::NAN).is_err());
    assert!(mit_star_robot::crop_to_ball(&mut points, DVec3::ZERO, -1.0).is_err());
    assert!(mit_star_robot::crop_to_box(&mut points, DVec3::ONE, DVec3::ZERO).is_err());
}

/// VAMP's benchmark protocol on a MotionBenchMaker problem: 10 000 points on each primitive,
/// cropped to the Panda's reach around its first joint, one point per 2 cm. The start is
/// valid, so no sampled point lies within a sphere there: the robot filter without padding
/// removes nothing.
#[test]
fn the_benchmark_protocol_on_table_pick() {
    use mit_star_problems::PlanningProblem;
    let folder = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/mbm/table_pick_panda"
    );
    let problem = ArmProblem::panda_mbm(folder.as_ref(), 1).unwrap();
    let obstacles = problem.scene().obstacles();
    let cloud =
        mit_star_robot::sample_surfaces(obstacles, mit_star_robot::DEFAULT_SAMPLES_PER_OBSTACLE, 0)
            .unwrap();
    assert_eq!(cloud.len(), obstacles.len() * 10_000);
    assert!(cloud.points.iter().all(|p| {
        obstacles
            .iter()
            .any(|o| o.distance_f64(p.as_dvec3()) <= 1e-5)
    }));
    let mut points = cloud.points;
    let crop =
        mit_star_robot::crop_to_ball(&mut points, DVec3::new(0.0, 0.0, 0.333), 1.19).unwrap();
    let mut voxels = points.clone();
    let thin = mit_star_robot::min_distance_downsample(&mut points, 0.02).unwrap();
    let arm =
        mit_star_robot::remove_robot_points(&mut points, problem.robot(), problem.start(), 0.0)
            .unwrap();
    assert_eq!(arm.removed(), 0);
    assert!(thin.after < thin.before / 4, "{thin:?}");
    eprintln!(
        "table_pick #1: {} obstacles, {} points; crop {} left in {:?}; 2 cm apart {} in {:?}; robot {:?}",
        obstacles.len(),
        crop.before,
        crop.after,
        crop.elapsed,
        thin.after,
        thin.elapsed,
        arm.elapsed
    );
    let grid = mit_star_robot::voxel_downsample(&mut voxels, 0.02).unwrap();
    eprintln!("  voxels of 2 cm: {} in {:?}", grid.after, grid.elapsed);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Every sphere of every shipped robot stays inside its reach ball, at random
    /// configurations within the limits.
    #[test]
    fn the_reach_ball_holds_every_robot_at_every_configuration(
        u in prop::collection::vec(0.0..=1.0f64, 32),
    ) {
        for shipped in mit_star_robot::ShippedRobot::all() {
            let model = shipped.model(false).unwrap();
            let (center, radius) = mit_star_robot::reach_ball(&model);
            let space = model.joint_space();
            let q: Vec<f64> = (0..space.dimension())
                .map(|j| space.lower()[j] + u[j % u.len()] * (space.upper()[j] - space.lower()[j]))
                .collect();
            let fk = Kinematics::new(&model);
            let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
            let mut spheres = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
            fk.sphere_centers_f64(&q, &mut links, &mut spheres);
            for (c, r) in spheres {
                prop_assert!(
                    c.distance(center) + r <= radius * (1.0 + 1e-12),
                    "{}: a sphere reaches {} of {}", model.name(), c.distance(center) + r, radius
                );
            }
        }
    }
}

/// The farthest any sphere of `model` gets from `center` at `q`.
fn farthest(model: &mit_star_robot::RobotModel, center: DVec3, q: &[f64]) -> f64 {
    let fk = Kinematics::new(model);
    let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
    let mut spheres = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
    fk.sphere_centers_f64(q, &mut links, &mut spheres);
    spheres
        .iter()
        .map(|&(c, r)| c.distance(center) + r)
        .fold(0.0, f64::max)
}

/// A hill climb towards each robot's most stretched configuration stays inside the ball, and
/// comes within 40% of its radius (the triangle inequality adds sideways offsets in full:
/// the UR5's bound is about 35% above the farthest configuration found, the Panda's 12%).
#[test]
fn the_reach_ball_holds_the_most_stretched_configurations() {
    use mit_star_spaces::rand::{RngExt, SeedableRng};
    let mut rng = mit_star_spaces::SeededRng::seed_from_u64(5);
    for shipped in mit_star_robot::ShippedRobot::all() {
        let model = shipped.model(false).unwrap();
        let (center, radius) = mit_star_robot::reach_ball(&model);
        let space = model.joint_space();
        let n = space.dimension();
        let mut best_q: Vec<f64> = (0..n)
            .map(|j| rng.random_range(space.lower()[j]..=space.upper()[j]))
            .collect();
        let mut best = farthest(&model, center, &best_q);
        for step in 0..3000 {
            let scale = if step < 1500 { 0.5 } else { 0.05 };
            let q: Vec<f64> = best_q
                .iter()
                .enumerate()
                .map(|(j, &v)| {
                    (v + scale * rng.random_range(-1.0..1.0))
                        .clamp(space.lower()[j], space.upper()[j])
                })
                .collect();
            let reach = farthest(&model, center, &q);
            if reach > best {
                (best, best_q) = (reach, q);
            }
        }
        assert!(best <= radius, "{}: {best} beyond {radius}", model.name());
        assert!(best >= 0.6 * radius, "{}: {best} of {radius}", model.name());
        eprintln!(
            "{}: reach ball {radius:.4} m, farthest found {best:.4} m",
            model.name()
        );
    }
}

#[test]
fn the_pandas_reach_is_vamps() {
    let (center, radius) = mit_star_robot::reach_ball(&ArmProblem::panda().unwrap());
    assert!(
        (center - DVec3::new(0.0, 0.0, 0.333)).length() < 1e-12,
        "{center}"
    );
    assert!((1.0..1.3).contains(&radius), "{radius}");
    eprintln!("Panda reach ball: centre {center}, radius {radius:.4} m");
}
