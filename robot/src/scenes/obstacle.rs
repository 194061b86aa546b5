//! [`Obstacle`]: a box, cylinder or sphere placed in the world, and exact sphere tests.

use crate::lane_f32::LaneF32;
use glam::{Affine3A, DAffine3, DQuat, DVec3, Vec3A};

/// The shape of an obstacle, in its own frame (centred at the origin).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// A box with these half side lengths along x, y, z.
    Cuboid {
        /// Half side lengths.
        half_extents: DVec3,
    },
    /// A cylinder along z: `|z| ≤ half_height`, `x² + y² ≤ radius²`.
    Cylinder {
        /// Half of the height.
        half_height: f64,
        /// Radius.
        radius: f64,
    },
    /// A ball.
    Sphere {
        /// Radius.
        radius: f64,
    },
}

/// A solid obstacle: a [`Shape`] at a pose (rotation then translation) in the robot's base
/// frame, with its `f32` world-to-local transform for the fast tests and a bounding sphere.
///
/// Contact convention: a ball and a solid **collide** when they share at least one point —
/// when the distance from the ball's centre to the solid is at most the ball's radius
/// (touching counts as collision, as in VAMP and FCL's boolean queries).
///
/// ```
/// use glam::{DQuat, DVec3, Vec3A};
/// use mit_star_robot::{Obstacle, Shape};
/// let wall = Obstacle::new(
///     Shape::Cuboid { half_extents: DVec3::new(0.01, 0.5, 0.5) },
///     DVec3::new(0.5, 0.0, 0.0),
///     DQuat::IDENTITY,
/// );
/// assert!(wall.collides_sphere(Vec3A::new(0.45, 0.0, 0.0), 0.05));
/// assert!(!wall.collides_sphere(Vec3A::new(0.4, 0.0, 0.0), 0.05));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Obstacle {
    shape: Shape,
    pose: DAffine3,
    /// World to local, `f32`.
    inverse: Affine3A,
    /// World to local, `f64`.
    inverse64: DAffine3,
    /// The shape's parameters in `f32`: half extents, or (radius, half height, 0).
    size: Vec3A,
    center: Vec3A,
    bound: f32,
}

impl Obstacle {
    /// `shape` rotated by `rotation` (normalised here) and moved to `position`.
    pub fn new(shape: Shape, position: DVec3, rotation: DQuat) -> Self {
        let pose = DAffine3::from_rotation_translation(rotation.normalize(), position);
        let inverse64 = pose.inverse();
        let (size, bound) = match shape {
            Shape::Cuboid { half_extents } => (half_extents.as_vec3a(), half_extents.length()),
            Shape::Cylinder {
                half_height,
                radius,
            } => (
                Vec3A::new(radius as f32, half_height as f32, 0.0),
                radius.hypot(half_height),
            ),
            Shape::Sphere { radius } => (Vec3A::splat(radius as f32), radius),
        };
        Self {
            shape,
            pose,
            inverse: crate::model::to_f32(&inverse64),
            inverse64,
            size,
            center: position.as_vec3a(),
            // Rounded up so that the `f32` cull never rejects a real contact.
            bound: (bound * (1.0 + 1e-6) + 1e-6) as f32,
        }
    }

    /// The shape.
    pub fn shape(&self) -> Shape {
        self.shape
    }

    /// The pose (local to world).
    pub fn pose(&self) -> DAffine3 {
        self.pose
    }

    /// Centre and radius of a sphere enclosing the obstacle.
    pub fn bounding_sphere(&self) -> (Vec3A, f32) {
        (self.center, self.bound)
    }

    /// `true` if the ball of `radius` at `center` meets the obstacle (`f32`, the fast test).
    #[inline]
    pub fn collides_sphere(&self, center: Vec3A, radius: f32) -> bool {
        let reach = self.bound + radius;
        if center.distance_squared(self.center) > reach * reach {
            return false;
        }
        let p = self.inverse.transform_point3a(center);
        let excess = match self.shape {
            Shape::Cuboid { .. } => (p.abs() - self.size).max(Vec3A::ZERO).length_squared(),
            Shape::Cylinder { .. } => {
                let radial = (p.x * p.x + p.y * p.y).sqrt() - self.size.x;
                let axial = p.z.abs() - self.size.y;
                let (r, a) = (radial.max(0.0), axial.max(0.0));
                r * r + a * a
            }
            Shape::Sphere { .. } => {
                let d = (p.length() - self.size.x).max(0.0);
                d * d
            }
        };
        excess <= radius * radius
    }

    /// The SIMD twin of [`collides_sphere`](Self::collides_sphere): bit `l` of the result is
    /// set if lane `l`'s ball (centre `center[..][l]`, radius `radius[l]`) meets the obstacle.
    /// The same arithmetic in the same order, a lane's worth of balls at a time.
    #[inline(always)]
    pub(crate) fn collides_spheres_lanes(&self, center: &[LaneF32; 3], radius: LaneF32) -> u32 {
        let near = self.bound_meets_lanes(center, radius);
        if near == 0 {
            return 0;
        }
        near & self
            .excess_lanes(center)
            .simd_le(radius * radius)
            .to_bitmask()
    }

    /// Bit `l` set if lane `l`'s ball meets the solid's bounding sphere (no square root): the
    /// cheap first test of [`collides_spheres_lanes`](Self::collides_spheres_lanes).
    #[inline(always)]
    fn bound_meets_lanes(&self, center: &[LaneF32; 3], radius: LaneF32) -> u32 {
        let reach = LaneF32::splat(self.bound) + radius;
        self.centre_distance_squared(center)
            .simd_le(reach * reach)
            .to_bitmask()
    }

    /// Per lane, the squared distance from the point to the centre of the solid's bounding
    /// sphere.
    #[inline(always)]
    fn centre_distance_squared(&self, &[x, y, z]: &[LaneF32; 3]) -> LaneF32 {
        let (dx, dy, dz) = (
            x - LaneF32::splat(self.center.x),
            y - LaneF32::splat(self.center.y),
            z - LaneF32::splat(self.center.z),
        );
        dx * dx + dy * dy + dz * dz
    }

    /// [`collides_spheres_lanes`](Self::collides_spheres_lanes) that also hands back, where
    /// some lane's ball meets the solid, every lane's squared distance from its centre to the
    /// solid (as [`excess_lanes`](Self::excess_lanes) computes it): `None` if no lane's ball
    /// meets it.
    #[inline]
    pub(crate) fn contacts_lanes(
        &self,
        center: &[LaneF32; 3],
        radius: LaneF32,
    ) -> Option<(u32, LaneF32)> {
        let near = self.bound_meets_lanes(center, radius);
        if near == 0 {
            return None;
        }
        let excess = self.excess_lanes(center);
        let hit = near & excess.simd_le(radius * radius).to_bitmask();
        (hit != 0).then_some((hit, excess))
    }

    /// Bit `l` set if lane `l`'s point may be closer than `limit[l]` to the solid: closer
    /// than `limit + bound` to the bounding sphere's centre (no square root; a cheaper, looser
    /// test than comparing [`excess_lanes`](Self::excess_lanes) with `limit²`).
    #[inline]
    pub(crate) fn may_be_within_lanes(&self, point: &[LaneF32; 3], limit: LaneF32) -> u32 {
        let reach = limit + LaneF32::splat(self.bound);
        let positive = limit.simd_gt(LaneF32::ZERO).to_bitmask();
        positive
            & self
                .centre_distance_squared(point)
                .simd_lt(reach * reach)
                .to_bitmask()
    }

    /// Per lane, the distance from the point (given in the solid's frame by
    /// [`local_lanes`](Self::local_lanes)) to the solid, 0 inside: the arithmetic of
    /// [`collides_spheres_lanes`](Self::collides_spheres_lanes), square-rooted.
    #[inline]
    pub(crate) fn distances_local_lanes(&self, local: &[LaneF32; 3]) -> LaneF32 {
        self.excess_local_lanes(local).sqrt()
    }

    /// Per lane, how fast the distance from the point (in the solid's frame, at `distance`
    /// from it) changes when the point moves at `velocity` (in the world frame): `n · v`, `n`
    /// the unit direction from the solid's nearest point to the point (0 inside, where no
    /// direction is defined).
    ///
    /// Every shape is convex, so the distance is a convex function of the point and
    /// `dist(y) ≥ dist(x) + n · (y − x)` for every `y`: the rate bounds how fast the point can
    /// approach the solid to first order, whatever the motion's length (certification's
    /// directional bound, `clearance.rs`).
    #[inline]
    pub(crate) fn rates_local_lanes(
        &self,
        [px, py, pz]: &[LaneF32; 3],
        distance: LaneF32,
        velocity: &[LaneF32; 3],
    ) -> LaneF32 {
        let (px, py, pz) = (*px, *py, *pz);
        let m = &self.inverse.matrix3;
        let [vx, vy, vz] = *velocity;
        let turn = |a: Vec3A| {
            LaneF32::splat(a.x) * vx + LaneF32::splat(a.y) * vy + LaneF32::splat(a.z) * vz
        };
        let (ux, uy, uz) = (
            turn(Vec3A::new(m.x_axis.x, m.y_axis.x, m.z_axis.x)),
            turn(Vec3A::new(m.x_axis.y, m.y_axis.y, m.z_axis.y)),
            turn(Vec3A::new(m.x_axis.z, m.y_axis.z, m.z_axis.z)),
        );
        let zero = LaneF32::ZERO;
        // The excess beyond the solid along each of its local directions, times its rate.
        let along = match self.shape {
            Shape::Cuboid { .. } => {
                let ex = (px.abs() - LaneF32::splat(self.size.x)).max(zero);
                let ey = (py.abs() - LaneF32::splat(self.size.y)).max(zero);
                let ez = (pz.abs() - LaneF32::splat(self.size.z)).max(zero);
                ex.copysign(px) * ux + ey.copysign(py) * uy + ez.copysign(pz) * uz
            }
            Shape::Cylinder { .. } => {
                let planar = (px * px + py * py).sqrt();
                let radial = (planar - LaneF32::splat(self.size.x)).max(zero);
                let axial = (pz.abs() - LaneF32::splat(self.size.y)).max(zero);
                let outward = (px * ux + py * uy) / planar.max(LaneF32::splat(f32::MIN_POSITIVE));
                radial * outward + axial.copysign(pz) * uz
            }
            Shape::Sphere { .. } => {
                let length = (px * px + py * py + pz * pz).sqrt();
                let d = (length - LaneF32::splat(self.size.x)).max(zero);
                let outward =
                    (px * ux + py * uy + pz * uz) / length.max(LaneF32::splat(f32::MIN_POSITIVE));
                d * outward
            }
        };
        along / distance.max(LaneF32::splat(f32::MIN_POSITIVE))
    }

    /// The point in the solid's frame.
    #[inline]
    pub(crate) fn local_lanes(&self, &[x, y, z]: &[LaneF32; 3]) -> [LaneF32; 3] {
        let m = &self.inverse.matrix3;
        let t = self.inverse.translation;
        let row = |a: Vec3A, t: f32| {
            LaneF32::splat(a.x) * x
                + LaneF32::splat(a.y) * y
                + LaneF32::splat(a.z) * z
                + LaneF32::splat(t)
        };
        // Row i of the rotation is (x_axis[i], y_axis[i], z_axis[i]).
        [
            row(Vec3A::new(m.x_axis.x, m.y_axis.x, m.z_axis.x), t.x),
            row(Vec3A::new(m.x_axis.y, m.y_axis.y, m.z_axis.y), t.y),
            row(Vec3A::new(m.x_axis.z, m.y_axis.z, m.z_axis.z), t.z),
        ]
    }

    /// Per lane, the squared distance from the point to the solid (0 inside), `f32`.
    #[inline]
    pub(crate) fn excess_lanes(&self, point: &[LaneF32; 3]) -> LaneF32 {
        self.excess_local_lanes(&self.local_lanes(point))
    }

    /// [`excess_lanes`](Self::excess_lanes) of a point given in the solid's frame.
    #[inline]
    fn excess_local_lanes(&self, &[px, py, pz]: &[LaneF32; 3]) -> LaneF32 {
        let zero = LaneF32::ZERO;
        match self.shape {
            Shape::Cuboid { .. } => {
                let ex = (px.abs() - LaneF32::splat(self.size.x)).max(zero);
                let ey = (py.abs() - LaneF32::splat(self.size.y)).max(zero);
                let ez = (pz.abs() - LaneF32::splat(self.size.z)).max(zero);
                ex * ex + ey * ey + ez * ez
            }
            Shape::Cylinder { .. } => {
                let radial = ((px * px + py * py).sqrt() - LaneF32::splat(self.size.x)).max(zero);
                let axial = (pz.abs() - LaneF32::splat(self.size.y)).max(zero);
                radial * radial + axial * axial
            }
            Shape::Sphere { .. } => {
                let d =
                    ((px * px + py * py + pz * pz).sqrt() - LaneF32::splat(self.size.x)).max(zero);
                d * d
            }
        }
    }

    /// The distance from `point` to the solid (0 inside), in `f64`: the reference for the
    /// fast test.
    pub fn distance_f64(&self, point: DVec3) -> f64 {
        let p = self.inverse64.transform_point3(point);
        match self.shape {
            Shape::Cuboid { half_extents } => (p.abs() - half_extents).max(DVec3::ZERO).length(),
            Shape::Cylinder {
                half_height,
                radius,
            } => {
                let radial = (p.x.hypot(p.y) - radius).max(0.0);
                let axial = (p.z.abs() - half_height).max(0.0);
                radial.hypot(axial)
            }
            Shape::Sphere { radius } => (p.length() - radius).max(0.0),
        }
    }

    /// `f64` twin of [`collides_sphere`](Self::collides_sphere).
    pub fn collides_sphere_f64(&self, center: DVec3, radius: f64) -> bool {
        self.distance_f64(center) <= radius
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotated_cylinders_and_spheres() {
        // A cylinder lying along x (z rotated onto x), radius 0.1, length 1.
        let rod = Obstacle::new(
            Shape::Cylinder {
                half_height: 0.5,
                radius: 0.1,
            },
            DVec3::ZERO,
            DQuat::from_rotation_y(std::f64::consts::FRAC_PI_2),
        );
        assert!(rod.collides_sphere(Vec3A::new(0.45, 0.0, 0.15), 0.06));
        assert!(!rod.collides_sphere(Vec3A::new(0.45, 0.0, 0.25), 0.06));
        assert!(!rod.collides_sphere(Vec3A::new(0.62, 0.0, 0.0), 0.1));
        assert!((rod.distance_f64(DVec3::new(0.0, 0.3, 0.0)) - 0.2).abs() < 1e-12);
        let ball = Obstacle::new(Shape::Sphere { radius: 0.2 }, DVec3::X, DQuat::IDENTITY);
        assert!(ball.collides_sphere(Vec3A::new(1.0, 0.29, 0.0), 0.1));
        assert!(!ball.collides_sphere(Vec3A::new(1.0, 0.31, 0.0), 0.1));
        assert_eq!(ball.distance_f64(DVec3::X), 0.0);
    }

    /// The rate of approach is the derivative of the distance along the velocity (central
    /// differences in `f64`), for every shape, from points around it in every direction.
    #[test]
    fn the_rate_of_approach_is_the_distance_derivative() {
        let turn = DQuat::from_euler(glam::EulerRot::XYZ, 0.3, -0.7, 1.1);
        let solids = [
            Shape::Cuboid {
                half_extents: DVec3::new(0.1, 0.2, 0.05),
            },
            Shape::Cylinder {
                half_height: 0.15,
                radius: 0.08,
            },
            Shape::Sphere { radius: 0.12 },
        ];
        let mut checked = 0;
        for shape in solids {
            let solid = Obstacle::new(shape, DVec3::new(0.4, -0.1, 0.3), turn);
            for i in 0..64 {
                let f = f64::from(i);
                let direction =
                    DVec3::new((f * 0.7).sin(), (f * 1.3).cos(), (f * 0.37).sin()).normalize();
                let point = DVec3::new(0.4, -0.1, 0.3) + direction * (0.15 + 0.003 * f);
                let velocity = DVec3::new((f * 2.1).cos(), (f * 0.9).sin(), 0.5 - (f * 0.2).cos());
                if solid.distance_f64(point) < 1e-3 {
                    continue;
                }
                let e = 1e-6;
                let expected = (solid.distance_f64(point + velocity * e)
                    - solid.distance_f64(point - velocity * e))
                    / (2.0 * e);
                let splat = |v: DVec3| [v.x, v.y, v.z].map(|x| LaneF32::splat(x as f32));
                let local = solid.local_lanes(&splat(point));
                let distance = solid.distances_local_lanes(&local);
                let rate = solid.rates_local_lanes(&local, distance, &splat(velocity));
                let (distance, rate) = (distance.to_array()[0], rate.to_array()[0]);
                assert!((f64::from(distance) - solid.distance_f64(point)).abs() < 1e-5);
                assert!(
                    (f64::from(rate) - expected).abs() < 1e-3 * (1.0 + velocity.length()),
                    "{shape:?} at {point}: {rate} against {expected}"
                );
                checked += 1;
            }
        }
        assert!(checked > 150, "{checked}");
    }
}
