//! [`Kinematics`]: forward kinematics of a [`RobotModel`], in `f32` for checking and `f64`
//! for reference.

use glam::{Affine3A, DAffine3, DVec3, Vec3A};

use crate::{Motion, RobotModel};

/// One link's step of the tree walk, precomputed in both precisions.
#[derive(Debug, Clone, Copy)]
struct Step {
    /// The parent link (`usize::MAX` for the root).
    parent: usize,
    origin: Affine3A,
    origin64: DAffine3,
    /// How the joint moves the link, in `f32`.
    motion: JointMotion,
    /// The joint's unit axis in `f64` (zero for a fixed joint).
    axis64: DVec3,
}

/// How a link's joint moves it, classified once for the `f32` walks (the scalar one here and
/// the eight-lane one in `checking/lanes.rs`): the unit axis and the joint coordinate.
#[derive(Debug, Clone, Copy)]
pub(crate) enum JointMotion {
    Fixed,
    /// About the joint frame's z axis (the usual URDF convention): two rotation columns turn.
    RevoluteZ(usize),
    Revolute(Vec3A, usize),
    Prismatic(Vec3A, usize),
}

/// Forward kinematics of a robot: places every link and every collision sphere for a
/// configuration.
///
/// The `f32` path ([`link_poses`](Self::link_poses), [`sphere_centers`](Self::sphere_centers))
/// is what collision checking uses (glam's SIMD-friendly `Affine3A`); the `f64` twins are for
/// reference checks. Nothing allocates: callers pass the output slices (one pose per link,
/// one centre per sphere) and reuse them.
///
/// ```
/// use glam::{Affine3A, Vec3A};
/// let urdf = include_str!("../../data/panda/panda_spherized.urdf");
/// let panda = mit_star_robot::RobotModel::from_urdf_str(urdf)?;
/// let fk = mit_star_robot::Kinematics::new(&panda);
/// let mut links = vec![Affine3A::IDENTITY; fk.link_count()];
/// let mut centers = vec![Vec3A::ZERO; fk.sphere_count()];
/// fk.sphere_centers(&[0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785], &mut links, &mut centers);
/// // The base sphere does not move.
/// assert!((centers[0] - Vec3A::new(0.0, 0.0, 0.05)).length() < 1e-6);
/// # Ok::<(), mit_star_robot::ModelError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Kinematics {
    steps: Vec<Step>,
    dimension: usize,
    /// Per sphere: its link, its centre in the link frame and its radius.
    spheres: Vec<(usize, Vec3A, f32)>,
    spheres64: Vec<(usize, DVec3, f64)>,
}

impl Kinematics {
    /// Precomputes the tree walk of `robot`.
    pub fn new(robot: &RobotModel) -> Self {
        let steps = robot
            .links()
            .iter()
            .map(|link| {
                let (motion, axis64) = match link.motion {
                    Motion::Fixed => (JointMotion::Fixed, DVec3::ZERO),
                    Motion::Revolute { axis, coordinate } if axis.as_vec3a() == Vec3A::Z => {
                        (JointMotion::RevoluteZ(coordinate), axis)
                    }
                    Motion::Revolute { axis, coordinate } => {
                        (JointMotion::Revolute(axis.as_vec3a(), coordinate), axis)
                    }
                    Motion::Prismatic { axis, coordinate } => {
                        (JointMotion::Prismatic(axis.as_vec3a(), coordinate), axis)
                    }
                };
                Step {
                    parent: link.parent.unwrap_or(usize::MAX),
                    origin: to_f32(&link.origin),
                    origin64: link.origin,
                    motion,
                    axis64,
                }
            })
            .collect();
        let spheres64: Vec<(usize, DVec3, f64)> = robot
            .spheres()
            .iter()
            .map(|s| (s.link, s.center, s.radius))
            .collect();
        Self {
            steps,
            dimension: robot.joint_names().len(),
            spheres: spheres64
                .iter()
                .map(|&(l, c, r)| (l, c.as_vec3a(), r as f32))
                .collect(),
            spheres64,
        }
    }

    /// Number of links (length of the pose buffers).
    pub fn link_count(&self) -> usize {
        self.steps.len()
    }

    /// Number of spheres (length of the centre buffers).
    pub fn sphere_count(&self) -> usize {
        self.spheres.len()
    }

    /// Number of joint coordinates a configuration has.
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// Link `i`'s step of the walk in `f32`: its parent (`usize::MAX` for the root), the
    /// joint origin and the joint's motion. For the SIMD walk, which mirrors
    /// [`link_poses`](Self::link_poses).
    pub(crate) fn step(&self, i: usize) -> (usize, Affine3A, JointMotion) {
        let s = &self.steps[i];
        (s.parent, s.origin, s.motion)
    }

    /// The radius of sphere `i` in `f32`.
    #[inline]
    pub fn radius(&self, i: usize) -> f32 {
        self.spheres[i].2
    }

    /// Writes the world pose of every link for configuration `q` into `out`.
    ///
    /// `q` must have [`dimension`](Self::dimension) values and `out` at least
    /// [`link_count`](Self::link_count) entries (a debug assertion; the planner always passes
    /// states of its space's dimension).
    #[inline]
    pub fn link_poses(&self, q: &[f64], out: &mut [Affine3A]) {
        debug_assert!(q.len() >= self.dimension && out.len() >= self.steps.len());
        for link in 0..self.steps.len() {
            self.link_pose(q, link, out);
        }
    }

    /// Writes the world pose of link `link` only, given the poses of the links before it
    /// (the walk of [`link_poses`](Self::link_poses) one link at a time, for early exits).
    #[inline]
    pub fn link_pose(&self, q: &[f64], link: usize, out: &mut [Affine3A]) {
        let step = &self.steps[link];
        let mut local = step.origin;
        match step.motion {
            JointMotion::Fixed => {}
            JointMotion::Prismatic(axis, c) => {
                local.translation += local.matrix3 * (axis * q[c] as f32);
            }
            JointMotion::RevoluteZ(c) => {
                // origin · Rz(q): only the first two rotation columns turn.
                let (s, cos) = (q[c] as f32).sin_cos();
                let (x, y) = (local.matrix3.x_axis, local.matrix3.y_axis);
                local.matrix3.x_axis = x * cos + y * s;
                local.matrix3.y_axis = y * cos - x * s;
            }
            JointMotion::Revolute(axis, c) => {
                local *= Affine3A::from_axis_angle(axis.into(), q[c] as f32);
            }
        }
        out[link] = if step.parent == usize::MAX {
            local
        } else {
            out[step.parent] * local
        };
    }

    /// Writes the world centre of every sphere for `q` into `centers`, using `links` as the
    /// pose buffer (see [`link_poses`](Self::link_poses)).
    pub fn sphere_centers(&self, q: &[f64], links: &mut [Affine3A], centers: &mut [Vec3A]) {
        self.link_poses(q, links);
        for (out, &(link, center, _)) in centers.iter_mut().zip(&self.spheres) {
            *out = links[link].transform_point3a(center);
        }
    }

    /// The `f64` twin of [`link_poses`](Self::link_poses).
    pub fn link_poses_f64(&self, q: &[f64], out: &mut [DAffine3]) {
        debug_assert!(q.len() >= self.dimension && out.len() >= self.steps.len());
        for link in 0..self.steps.len() {
            self.link_pose_f64(q, link, out);
        }
    }

    /// The `f64` twin of [`link_pose`](Self::link_pose): writes the world pose of link `link`
    /// only, given the poses of its ancestors in `out` (inverse kinematics walks the chain of
    /// one link this way).
    #[inline]
    pub fn link_pose_f64(&self, q: &[f64], link: usize, out: &mut [DAffine3]) {
        let step = &self.steps[link];
        let mut local = step.origin64;
        match step.motion {
            JointMotion::Fixed => {}
            JointMotion::Prismatic(_, c) => {
                local *= DAffine3::from_translation(step.axis64 * q[c]);
            }
            JointMotion::RevoluteZ(c) | JointMotion::Revolute(_, c) => {
                local *= DAffine3::from_axis_angle(step.axis64, q[c]);
            }
        }
        out[link] = if step.parent == usize::MAX {
            local
        } else {
            out[step.parent] * local
        };
    }

    /// The `f64` twin of [`sphere_centers`](Self::sphere_centers); also gives the radii.
    pub fn sphere_centers_f64(
        &self,
        q: &[f64],
        links: &mut [DAffine3],
        centers: &mut [(DVec3, f64)],
    ) {
        self.link_poses_f64(q, links);
        for (out, &(link, center, radius)) in centers.iter_mut().zip(&self.spheres64) {
            *out = (links[link].transform_point3(center), radius);
        }
    }
}

/// An `f64` affine transform in `f32`.
pub(crate) fn to_f32(t: &DAffine3) -> Affine3A {
    Affine3A::from_mat3_translation(t.matrix3.as_mat3(), t.translation.as_vec3())
}
