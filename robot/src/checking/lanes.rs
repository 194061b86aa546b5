//! Eight configurations at once: forward kinematics in structure-of-arrays form over `f32x8`
//! lanes (the `wide` crate, safe code), as VAMP lays out its checks.
//!
//! Lane `l` of every vector belongs to configuration `l` of the batch. A pose is nine rotation
//! vectors and three translation vectors; the walk down the tree is the scalar walk of
//! [`Kinematics::link_poses`](crate::Kinematics::link_poses) with every number replaced by
//! eight. Constants (joint origins, local sphere centres, obstacle transforms) are splatted.

use glam::{Affine3A, Vec3A};
use wide::f32x8;

use crate::Kinematics;
use crate::model::JointMotion;

/// Lanes per batch.
pub(crate) const LANES: usize = 8;

/// Three coordinates, eight lanes each.
pub(crate) type Point8 = [f32x8; 3];

/// A rigid transform per lane: rotation columns `r[column][row]` and translation `t`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Pose8 {
    r: [[f32x8; 3]; 3],
    t: [f32x8; 3],
}

impl Pose8 {
    pub(crate) const IDENTITY: Self = {
        let (o, l) = (f32x8::ZERO, f32x8::ONE);
        Self {
            r: [[l, o, o], [o, l, o], [o, o, l]],
            t: [o, o, o],
        }
    };

    /// The rotation applied to a constant vector.
    #[inline]
    pub(crate) fn rotate(&self, v: Vec3A) -> Point8 {
        let (x, y, z) = (f32x8::splat(v.x), f32x8::splat(v.y), f32x8::splat(v.z));
        std::array::from_fn(|i| self.r[0][i] * x + self.r[1][i] * y + self.r[2][i] * z)
    }

    /// The translation: where the frame's origin is.
    #[inline]
    pub(crate) fn translation(&self) -> Point8 {
        self.t
    }

    /// The transform applied to a constant point (a local sphere centre).
    #[inline]
    pub(crate) fn point(&self, p: Vec3A) -> Point8 {
        let [x, y, z] = self.rotate(p);
        [x + self.t[0], y + self.t[1], z + self.t[2]]
    }

    /// `self * a` for a constant `a`.
    #[inline]
    fn then_constant(&self, a: &Affine3A) -> Self {
        let m = &a.matrix3;
        Self {
            r: [
                self.rotate(m.x_axis),
                self.rotate(m.y_axis),
                self.rotate(m.z_axis),
            ],
            t: self.point(a.translation),
        }
    }
}

/// The tree walk of a [`Kinematics`], eight configurations at a time.
#[derive(Debug, Clone)]
pub(crate) struct LaneKinematics {
    steps: Vec<(usize, Affine3A, JointMotion)>,
}

impl LaneKinematics {
    pub(crate) fn new(fk: &Kinematics) -> Self {
        let steps = (0..fk.link_count()).map(|i| fk.step(i)).collect();
        Self { steps }
    }

    /// Writes every link's world pose, per lane, for joint values `q[coordinate]` (one vector
    /// per coordinate) into `out` (one pose per link).
    #[inline]
    pub(crate) fn link_poses(&self, q: &[f32x8], out: &mut [Pose8]) {
        for (i, &(parent, ref origin, joint)) in self.steps.iter().enumerate() {
            let base = if parent == usize::MAX {
                Pose8::IDENTITY
            } else {
                out[parent]
            };
            // parent · origin, then the joint's own motion.
            let mut pose = base.then_constant(origin);
            match joint {
                JointMotion::Fixed => {}
                JointMotion::RevoluteZ(c) => {
                    let (s, cos) = q[c].sin_cos();
                    let [x, y, _] = pose.r;
                    pose.r[0] = std::array::from_fn(|k| x[k] * cos + y[k] * s);
                    pose.r[1] = std::array::from_fn(|k| y[k] * cos - x[k] * s);
                }
                JointMotion::Revolute(u, c) => {
                    let (s, cos) = q[c].sin_cos();
                    let one_minus = f32x8::ONE - cos;
                    let u = [u.x, u.y, u.z];
                    // Rodrigues: R = cos·I + sin·[u]× + (1 − cos)·u uᵀ, column j row i.
                    let cross = [[0.0, u[2], -u[1]], [-u[2], 0.0, u[0]], [u[1], -u[0], 0.0]];
                    let rot: [[f32x8; 3]; 3] = std::array::from_fn(|j| {
                        std::array::from_fn(|i| {
                            let diagonal = if i == j { cos } else { f32x8::ZERO };
                            diagonal
                                + s * f32x8::splat(cross[j][i])
                                + one_minus * f32x8::splat(u[i] * u[j])
                        })
                    });
                    let a = pose.r;
                    pose.r = std::array::from_fn(|j| {
                        std::array::from_fn(|k| {
                            a[0][k] * rot[j][0] + a[1][k] * rot[j][1] + a[2][k] * rot[j][2]
                        })
                    });
                }
                JointMotion::Prismatic(u, c) => {
                    let d = pose.rotate(u);
                    for (t, d) in pose.t.iter_mut().zip(d) {
                        *t += d * q[c];
                    }
                }
            }
            out[i] = pose;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::RobotModel;

    #[test]
    fn lanes_place_links_as_the_scalar_walk_does() {
        let urdf = include_str!("../../data/panda/panda_spherized.urdf");
        let panda = RobotModel::from_urdf_str(urdf).unwrap();
        let fk = Kinematics::new(&panda);
        let lanes = LaneKinematics::new(&fk);
        let configurations: Vec<[f64; 7]> = (0..LANES)
            .map(|l| std::array::from_fn(|j| ((l * 7 + j) as f64 * 0.37).sin() * 1.5))
            .collect();
        let q: Vec<f32x8> = (0..7)
            .map(|j| f32x8::new(std::array::from_fn(|l| configurations[l][j] as f32)))
            .collect();
        let mut poses = vec![Pose8::IDENTITY; fk.link_count()];
        lanes.link_poses(&q, &mut poses);
        let mut scalar = vec![Affine3A::IDENTITY; fk.link_count()];
        for (l, c) in configurations.iter().enumerate() {
            fk.link_poses(c, &mut scalar);
            for (link, (pose, want)) in poses.iter().zip(&scalar).enumerate() {
                let probe = Vec3A::new(0.1, -0.2, 0.3);
                let got = pose.point(probe);
                let want = want.transform_point3a(probe);
                let got = Vec3A::new(
                    got[0].to_array()[l],
                    got[1].to_array()[l],
                    got[2].to_array()[l],
                );
                assert!(
                    got.distance(want) < 1e-5,
                    "lane {l} link {link}: {got} vs {want}"
                );
            }
        }
    }
}
