//! The point structure of cloud obstacles against brute force: no missed contact, a distance
//! bound never above the true distance (`f64`), batched answers equal to single ones; its
//! memory at 10⁶ points; and the errors of points that are not a cloud.

use glam::{DVec3, Vec3};
use mit_star_robot::{CloudError, CloudObstacle, PointCloud, PointTree};
use proptest::prelude::*;

/// Points in a box of half side `spread` around `(0.4, 0, 0.4)`, some in tight clusters (as a
/// surface sampled densely), from a seed.
fn cloud_points(count: usize, spread: f32, seed: u64) -> Vec<Vec3> {
    let mut state = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    let mut next = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 40) as f32 / (1u64 << 24) as f32) * 2.0 - 1.0
    };
    let mut points = Vec::with_capacity(count);
    while points.len() < count {
        let centre = Vec3::new(0.4, 0.0, 0.4) + spread * Vec3::new(next(), next(), next());
        // A cluster of up to 20 points within 5 mm, or one point.
        let members = if next() > 0.5 { 20 } else { 1 };
        for _ in 0..members.min(count - points.len()) {
            points.push(centre + 0.005 * Vec3::new(next(), next(), next()));
        }
    }
    points
}

/// The true distance in `f64` from `c` to the nearest point (the points as stored, in `f32`).
fn brute_distance(points: &[Vec3], c: Vec3) -> f64 {
    points
        .iter()
        .map(|p| p.as_dvec3().distance(c.as_dvec3()))
        .fold(f64::INFINITY, f64::min)
}

fn queries() -> impl Strategy<Value = Vec<(f32, f32, f32, f32)>> {
    prop::collection::vec(
        (-0.3..1.1_f32, -0.7..0.7_f32, -0.3..1.1_f32, 0.0..0.15_f32),
        1..40,
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Every contact brute force finds (in `f64`, beyond a micrometre of rounding) is found,
    /// and every contact found is one in `f32`; batched answers are the single ones.
    #[test]
    fn touches_are_brute_force_and_batches_agree(
        count in 1..3000_usize,
        spread in 0.01..0.6_f32,
        seed in any::<u64>(),
        radius in 0.001..0.02_f64,
        qs in queries(),
    ) {
        let points = cloud_points(count, spread, seed);
        let cloud = PointCloud::new(points.clone()).unwrap().with_radius(radius).unwrap();
        let obstacle = CloudObstacle::new("cloud", cloud);
        let centers: Vec<Vec3> = qs.iter().map(|&(x, y, z, _)| Vec3::new(x, y, z)).collect();
        let radii: Vec<f32> = qs.iter().map(|q| q.3).collect();
        let mut batched = vec![false; centers.len()];
        obstacle.touches_spheres(&centers, &radii, &mut batched);
        for ((&c, &r), &together) in centers.iter().zip(&radii).zip(&batched) {
            let single = obstacle.touches_sphere(c, r);
            prop_assert_eq!(single, together, "{} {}", c, r);
            let truth = brute_distance(&points, c) - radius - f64::from(r);
            if truth < -1e-6 {
                prop_assert!(single, "missed a contact {} deep at {}", -truth, c);
            }
            if truth > 1e-6 {
                prop_assert!(!single, "a contact {} away at {}", truth, c);
            }
        }
    }

    /// The distance lower bound is never above the true distance (`f64`) and within a
    /// micrometre of it when the limit allows; batched bounds are the single ones.
    #[test]
    fn distance_bounds_are_below_the_truth(
        count in 1..3000_usize,
        spread in 0.01..0.6_f32,
        seed in any::<u64>(),
        limit in 0.001..2.0_f32,
        qs in queries(),
    ) {
        let points = cloud_points(count, spread, seed);
        let cloud = PointCloud::new(points.clone()).unwrap();
        let radius = cloud.radius();
        let obstacle = CloudObstacle::new("cloud", cloud);
        let centers: Vec<Vec3> = qs.iter().map(|&(x, y, z, _)| Vec3::new(x, y, z)).collect();
        let mut batched = vec![0.0; centers.len()];
        obstacle.distance_lower_bounds(&centers, limit, &mut batched);
        for (&c, &together) in centers.iter().zip(&batched) {
            let single = obstacle.distance_lower_bound(c, limit);
            prop_assert_eq!(single.to_bits(), together.to_bits(), "{}", c);
            let truth = brute_distance(&points, c) - radius;
            prop_assert!(f64::from(single) <= truth, "{} above {} at {}", single, truth, c);
            let expected = truth.min(f64::from(limit));
            prop_assert!(f64::from(single) >= expected - 1e-5, "{} far below {}", single, expected);
            // The tree alone: the exact nearest point.
            let (index, _) = obstacle.tree().nearest(c, f32::INFINITY).unwrap();
            let nearest = points[index].as_dvec3().distance(c.as_dvec3());
            prop_assert!((nearest - brute_distance(&points, c)).abs() < 1e-6);
        }
    }
}

/// A million points take at most 64 bytes each (the budget), here about 19.
#[test]
fn a_million_points_fit_in_64_bytes_each() {
    let points = cloud_points(1_000_000, 1.0, 7);
    let tree = PointTree::new(&points);
    let per_point = tree.memory_bytes() as f64 / points.len() as f64;
    assert!(per_point <= 64.0, "{per_point} bytes a point");
    assert!(per_point <= 23.0, "{per_point} bytes a point");
    let c = Vec3::new(0.4, 0.1, 0.3);
    let (index, d) = tree.nearest(c, f32::INFINITY).unwrap();
    assert!((f64::from(d) - brute_distance(&points, c)).abs() < 1e-6);
    assert_eq!(points[index].distance(c), d);
}

/// Points that are not a cloud are refused, each with its reason.
#[test]
fn bad_points_are_named_errors() {
    assert_eq!(PointCloud::new(vec![]), Err(CloudError::Empty));
    let mut points = cloud_points(10, 0.1, 1);
    points[7].y = f32::NAN;
    let error = PointCloud::new(points.clone()).unwrap_err();
    assert!(
        matches!(error, CloudError::NotFinite { index: 7, .. }),
        "{error}"
    );
    assert!(error.to_string().contains("point 7"), "{error}");
    points[7].y = f32::INFINITY;
    assert!(matches!(
        PointCloud::new(points.clone()),
        Err(CloudError::NotFinite { index: 7, .. })
    ));
    points[7].y = 2e6;
    assert!(matches!(
        PointCloud::new(points.clone()),
        Err(CloudError::OutOfRange { index: 7, .. })
    ));
    points[7].y = 0.0;
    let cloud = PointCloud::new(points).unwrap();
    assert_eq!(cloud.radius(), PointCloud::DEFAULT_RADIUS);
    for radius in [0.0, -1e-3, f64::NAN, f64::INFINITY, 2.0] {
        let error = cloud.clone().with_radius(radius).unwrap_err();
        assert!(
            matches!(error, CloudError::Radius { .. }),
            "{radius}: {error}"
        );
    }
    // A billion points is refused from its count, before anything is allocated.
    let error = PointCloud::check_count(1_000_000_000).unwrap_err();
    assert_eq!(
        error,
        CloudError::TooMany {
            count: 1_000_000_000,
            cap: PointCloud::MAX_POINTS
        }
    );
    assert!(error.to_string().contains("1000000000"), "{error}");
    assert_eq!(PointCloud::check_count(0), Err(CloudError::Empty));
    assert!(PointCloud::check_count(PointCloud::MAX_POINTS).is_ok());
}

/// A polled build stops when told to, and builds the same tree otherwise.
#[test]
fn a_polled_build_stops() {
    struct Always;
    impl mit_star_spaces::Stop for Always {
        fn should_stop(&self) -> bool {
            true
        }
    }
    let points = cloud_points(200_000, 0.5, 3);
    assert!(PointTree::new_polled(&points, &Always).is_none());
    let cloud = PointCloud::new(points.clone()).unwrap();
    assert!(CloudObstacle::new_polled("c", cloud.clone(), &Always).is_none());
    let built = CloudObstacle::new_polled("c", cloud, &mit_star_spaces::Never).unwrap();
    let c = Vec3::new(0.1, 0.2, 0.3);
    let truth = points
        .iter()
        .map(|p| p.as_dvec3().distance(DVec3::new(0.1, 0.2, 0.3)))
        .fold(f64::INFINITY, f64::min);
    let bound = f64::from(built.distance_lower_bound(c, f32::INFINITY));
    assert!(
        bound <= truth - PointCloud::DEFAULT_RADIUS && bound > truth - 0.0026,
        "{bound} {truth}"
    );
}
