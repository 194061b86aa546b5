//! Clouds sampled on the surfaces of a scene's obstacles: the point-cloud protocol of VAMP's
//! benchmark (`evaluate_mbm.py --pointcloud True`), seeded.

use glam::{DVec3, Vec3};
use mit_star_spaces::SeededRng;
use mit_star_spaces::rand::{RngExt, SeedableRng};

use super::cloud_input_error::CloudInputError;
use super::input_cloud::{CloudOrigin, InputCloud, MAX_CLOUD_POINTS};
use crate::{Obstacle, Shape};

/// Points sampled on each obstacle by default: VAMP's benchmark samples 10 000 per object.
pub const DEFAULT_SAMPLES_PER_OBSTACLE: usize = 10_000;

/// `per_obstacle` points on the surface of each obstacle, uniformly by area (each face or
/// cap of a box or cylinder gets its share of the points by its area), from the project's
/// generator seeded with `seed`: the same seed gives the same cloud on every machine.
///
/// This is the protocol of VAMP's `evaluate_mbm.py --pointcloud True` (10 000 points per
/// primitive, then filtering). It differs in one point: VAMP draws a cylinder cap's points
/// at a uniform *radius*, which crowds them towards the centre; here they are uniform by area
/// (radius `r·√u`), as the sphere and box faces are in both.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use mit_star_robot::{Obstacle, Shape};
/// let ball = Obstacle::new(Shape::Sphere { radius: 0.1 }, DVec3::X, DQuat::IDENTITY);
/// let cloud = mit_star_robot::sample_surfaces(&[ball], 1000, 7)?;
/// assert_eq!(cloud.len(), 1000);
/// assert!(cloud.points.iter().all(|p| (p.as_dvec3().distance(DVec3::X) - 0.1).abs() < 1e-6));
/// # Ok::<(), mit_star_robot::CloudInputError>(())
/// ```
///
/// # Errors
/// [`CloudInputError::Empty`] for no obstacle or `per_obstacle == 0`;
/// [`CloudInputError::Parameter`] if the total exceeds
/// [`MAX_CLOUD_POINTS`](super::MAX_CLOUD_POINTS).
pub fn sample_surfaces(
    obstacles: &[Obstacle],
    per_obstacle: usize,
    seed: u64,
) -> Result<InputCloud, CloudInputError> {
    let origin = CloudOrigin::Sampled {
        obstacles: obstacles.len(),
        per_obstacle,
        seed,
    };
    let total = obstacles
        .len()
        .checked_mul(per_obstacle)
        .filter(|&n| n <= MAX_CLOUD_POINTS)
        .ok_or_else(|| CloudInputError::Parameter {
            what: "points per obstacle",
            message: format!(
                "{per_obstacle} on each of {} obstacles is more than {MAX_CLOUD_POINTS} points",
                obstacles.len()
            ),
        })?;
    if total == 0 {
        return Err(CloudInputError::Empty {
            origin: origin.to_string(),
            dropped: 0,
        });
    }
    let mut rng = SeededRng::seed_from_u64(seed);
    let mut points = Vec::with_capacity(total);
    for obstacle in obstacles {
        sample_obstacle_surface(obstacle, per_obstacle, &mut rng, &mut points);
    }
    Ok(InputCloud {
        points,
        origin,
        dropped_non_finite: 0,
    })
}

/// Appends `count` points drawn uniformly (by area) on `obstacle`'s surface to `out`.
pub fn sample_obstacle_surface(
    obstacle: &Obstacle,
    count: usize,
    rng: &mut SeededRng,
    out: &mut Vec<Vec3>,
) {
    let pose = obstacle.pose();
    out.reserve(count);
    for _ in 0..count {
        let local = match obstacle.shape() {
            Shape::Cuboid { half_extents: h } => box_point(h, rng),
            Shape::Cylinder {
                half_height,
                radius,
            } => cylinder_point(radius, half_height, rng),
            Shape::Sphere { radius } => sphere_direction(rng) * radius,
        };
        out.push(pose.transform_point3(local).as_vec3());
    }
}

/// A uniform draw in `[-1, 1)`.
fn symmetric(rng: &mut SeededRng) -> f64 {
    rng.random::<f64>() * 2.0 - 1.0
}

fn box_point(h: DVec3, rng: &mut SeededRng) -> DVec3 {
    // Each pair of opposite faces by its area: ±x faces 4·hy·hz, and so on.
    let areas = [h.y * h.z, h.x * h.z, h.x * h.y];
    let total = areas[0] + areas[1] + areas[2];
    let pick = rng.random::<f64>() * total;
    let axis = if pick < areas[0] {
        0
    } else if pick < areas[0] + areas[1] {
        1
    } else {
        2
    };
    let side = if rng.random::<bool>() { 1.0 } else { -1.0 };
    let mut p = DVec3::new(symmetric(rng), symmetric(rng), symmetric(rng)) * h;
    p[axis] = side * h[axis];
    p
}

fn cylinder_point(radius: f64, half_height: f64, rng: &mut SeededRng) -> DVec3 {
    let cap = radius * radius; // each cap: π r², the side: 2π r · 2 half_height (π dropped)
    let side = 4.0 * radius * half_height;
    let pick = rng.random::<f64>() * (2.0 * cap + side);
    let angle = rng.random::<f64>() * std::f64::consts::TAU;
    let (sin, cos) = angle.sin_cos();
    if pick < side {
        DVec3::new(radius * cos, radius * sin, symmetric(rng) * half_height)
    } else {
        let r = radius * rng.random::<f64>().sqrt();
        let z = if pick < side + cap {
            half_height
        } else {
            -half_height
        };
        DVec3::new(r * cos, r * sin, z)
    }
}

/// A uniform direction (Archimedes: `z` uniform in `[-1, 1]`, the azimuth uniform).
fn sphere_direction(rng: &mut SeededRng) -> DVec3 {
    let z = symmetric(rng);
    let angle = rng.random::<f64>() * std::f64::consts::TAU;
    let planar = (1.0 - z * z).max(0.0).sqrt();
    DVec3::new(planar * angle.cos(), planar * angle.sin(), z)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DQuat;

    /// Faces get points in proportion to their area: a flat box (2 × 2 × 0.02) has 98% of
    /// its area on its two large faces.
    #[test]
    fn points_spread_by_area() {
        let plate = Obstacle::new(
            Shape::Cuboid {
                half_extents: DVec3::new(1.0, 1.0, 0.01),
            },
            DVec3::ZERO,
            DQuat::IDENTITY,
        );
        let cloud = sample_surfaces(&[plate], 10_000, 3).unwrap();
        let large = cloud
            .points
            .iter()
            .filter(|p| (p.z.abs() - 0.01).abs() < 1e-6)
            .count();
        let share = large as f64 / 10_000.0;
        assert!((share - 4.0 / 4.08).abs() < 0.01, "{share}");
        // A cylinder of radius 1, height 2: the side is 4π of its 6π.
        let can = Obstacle::new(
            Shape::Cylinder {
                half_height: 1.0,
                radius: 1.0,
            },
            DVec3::ZERO,
            DQuat::IDENTITY,
        );
        let cloud = sample_surfaces(&[can], 10_000, 4).unwrap();
        let side = cloud
            .points
            .iter()
            .filter(|p| p.z.abs() < 1.0 - 1e-6)
            .count();
        assert!((side as f64 / 10_000.0 - 2.0 / 3.0).abs() < 0.02, "{side}");
        // Caps uniform by area: a quarter of a cap's points within half its radius.
        let caps: Vec<_> = cloud
            .points
            .iter()
            .filter(|p| p.z.abs() >= 1.0 - 1e-6)
            .collect();
        let inner = caps.iter().filter(|p| p.truncate().length() < 0.5).count();
        assert!(
            (inner as f64 / caps.len() as f64 - 0.25).abs() < 0.04,
            "{inner} of {}",
            caps.len()
        );
    }

    #[test]
    fn same_seed_same_cloud_and_limits() {
        let ball = Obstacle::new(Shape::Sphere { radius: 0.2 }, DVec3::ZERO, DQuat::IDENTITY);
        let a = sample_surfaces(&[ball, ball], 50, 11).unwrap();
        let b = sample_surfaces(&[ball, ball], 50, 11).unwrap();
        let c = sample_surfaces(&[ball, ball], 50, 12).unwrap();
        assert_eq!(a, b);
        assert_ne!(a.points, c.points);
        assert!(matches!(
            sample_surfaces(&[], 50, 1),
            Err(CloudInputError::Empty { .. })
        ));
        assert!(matches!(
            sample_surfaces(&[ball], 0, 1),
            Err(CloudInputError::Empty { .. })
        ));
        let e = sample_surfaces(&[ball, ball], MAX_CLOUD_POINTS, 1).unwrap_err();
        assert!(matches!(e, CloudInputError::Parameter { .. }), "{e}");
    }
}
