//! A batch of configurations at once ([`LANES`]: eight, or sixteen with AVX-512): forward
//! kinematics in structure-of-arrays form over [`LaneF32`] lanes (the `wide` crate, safe
//! code), as VAMP lays out its checks.
//!
//! Lane `l` of every vector belongs to configuration `l` of the batch. A pose is nine rotation
//! vectors and three translation vectors; the walk down the tree is the scalar walk of
//! [`Kinematics::link_poses`](crate::Kinematics::link_poses) with every number replaced by a
//! vector of lanes. Constants (joint origins, local sphere centres, obstacle transforms) are
//! splatted.

use std::ops::Range;

use glam::Vec3A;

use crate::Kinematics;
use crate::model::JointMotion;

pub(crate) use crate::lane_f32::{LANES, LaneF32};

/// Three coordinates, a vector of lanes each.
pub(crate) type LanePoint = [LaneF32; 3];

/// A rigid transform per lane: rotation columns `r[column][row]` and translation `t`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LanePose {
    r: [[LaneF32; 3]; 3],
    t: [LaneF32; 3],
}

impl LanePose {
    pub(crate) const IDENTITY: Self = {
        let (o, l) = (LaneF32::ZERO, LaneF32::ONE);
        Self {
            r: [[l, o, o], [o, l, o], [o, o, l]],
            t: [o, o, o],
        }
    };

    /// The rotation applied to a constant vector.
    #[inline]
    pub(crate) fn rotate(&self, v: Vec3A) -> LanePoint {
        let (x, y, z) = (
            LaneF32::splat(v.x),
            LaneF32::splat(v.y),
            LaneF32::splat(v.z),
        );
        std::array::from_fn(|i| self.r[0][i] * x + self.r[1][i] * y + self.r[2][i] * z)
    }

    /// The translation: where the frame's origin is.
    #[inline]
    pub(crate) fn translation(&self) -> LanePoint {
        self.t
    }

    /// The transform applied to a constant point (a local sphere centre).
    #[inline]
    pub(crate) fn point(&self, p: Vec3A) -> LanePoint {
        let [x, y, z] = self.rotate(p);
        [x + self.t[0], y + self.t[1], z + self.t[2]]
    }
}

/// How a step's constant joint origin turns the parent's rotation, classified once: most
/// URDF origins turn by nothing or by quarter turns about an axis (the Panda's `rpy` of
/// ±π/2), which only permute the parent's rotation columns and flip their signs.
#[derive(Debug, Clone, Copy)]
enum Turn {
    /// The identity: the columns stay.
    Keep,
    /// Column `j` becomes the parent's column `from[j]`, negated if `negate[j]`.
    Permute { from: [usize; 3], negate: [bool; 3] },
    /// Any other rotation, by its columns.
    Matrix([Vec3A; 3]),
}

impl Turn {
    /// The turn of `m`, whose entries within [`SNAP`] of 0 or ±1 count as exactly that.
    fn of(m: &glam::Mat3A) -> Self {
        let columns = [m.x_axis, m.y_axis, m.z_axis];
        let mut from = [0; 3];
        let mut negate = [false; 3];
        for (j, column) in columns.iter().enumerate() {
            let entries = column.to_array();
            let unit = entries.iter().position(|e| (e.abs() - 1.0).abs() <= SNAP);
            let rest_zero = |k: usize| {
                entries
                    .iter()
                    .enumerate()
                    .all(|(i, e)| i == k || e.abs() <= SNAP)
            };
            match unit {
                Some(k) if rest_zero(k) => {
                    from[j] = k;
                    negate[j] = entries[k] < 0.0;
                }
                _ => return Self::Matrix(columns),
            }
        }
        if from == [0, 1, 2] && negate == [false; 3] {
            Self::Keep
        } else {
            Self::Permute { from, negate }
        }
    }
}

/// How close to 0 or ±1 (in `f32`) an entry of a joint origin's rotation counts as exactly
/// that. URDF `rpy` values written to 12 digits (`1.57079632679`) leave entries of about
/// 5e-12 where a quarter turn has zeros; treating them as zeros moves a point one metre from
/// the joint by about 1e-9 m, against the checker's margin of 2e-5 m.
const SNAP: f32 = 1e-9;

/// One link's step of the lane walk: its parent, the origin's turn and the nonzero
/// components of its translation, and the joint's motion.
#[derive(Debug, Clone, Copy)]
struct LaneStep {
    parent: usize,
    turn: Turn,
    /// `(axis, value)` for each nonzero component of the origin's translation, first
    /// `shifts` entries.
    shift: [(usize, f32); 3],
    shifts: usize,
    motion: JointMotion,
}

/// The tree walk of a [`Kinematics`], a batch of configurations at a time, with each joint
/// origin's constant transform applied by only the arithmetic it needs (a generic robot's
/// constants folded at load time: see [`Turn`]).
#[derive(Debug, Clone)]
pub(crate) struct LaneKinematics {
    steps: Vec<LaneStep>,
}

impl LaneKinematics {
    pub(crate) fn new(fk: &Kinematics) -> Self {
        let steps = (0..fk.link_count())
            .map(|i| {
                let (parent, origin, motion) = fk.step(i);
                let mut shift = [(0, 0.0); 3];
                let mut shifts = 0;
                for (axis, value) in origin.translation.to_array().into_iter().enumerate() {
                    if value != 0.0 {
                        shift[shifts] = (axis, value);
                        shifts += 1;
                    }
                }
                LaneStep {
                    parent,
                    turn: Turn::of(&origin.matrix3),
                    shift,
                    shifts,
                    motion,
                }
            })
            .collect();
        Self { steps }
    }

    /// Writes every link's world pose, per lane, for joint values `q[coordinate]` (one vector
    /// per coordinate) into `out` (one pose per link).
    #[inline]
    pub(crate) fn link_poses(&self, q: &[LaneF32], out: &mut [LanePose]) {
        self.link_poses_in(q, out, 0..self.steps.len());
    }

    /// Writes the world poses of the links in `links` only, given those of the links before
    /// (the walk of [`link_poses`](Self::link_poses) a stretch at a time, so that a check can
    /// stop before placing the links it no longer needs).
    #[inline]
    pub(crate) fn link_poses_in(&self, q: &[LaneF32], out: &mut [LanePose], links: Range<usize>) {
        for i in links {
            let step = &self.steps[i];
            // In place: the parent comes before the link in tree order.
            let (done, rest) = out.split_at_mut(i);
            let pose = &mut rest[0];
            let base = if step.parent == usize::MAX {
                &LanePose::IDENTITY
            } else {
                &done[step.parent]
            };
            // parent · origin: the translation through the parent's rotation, then the turn.
            // Computed in locals and stored once: copying the parent's 288-byte rotation into
            // the link's slot to turn it there compiles to a `memmove` call per link.
            let mut t = base.t;
            for &(axis, value) in &step.shift[..step.shifts] {
                let value = LaneF32::splat(value);
                for (t, r) in t.iter_mut().zip(base.r[axis]) {
                    *t += r * value;
                }
            }
            let mut r = match step.turn {
                Turn::Keep => base.r,
                Turn::Permute { from, negate } => std::array::from_fn(|j| {
                    let column = base.r[from[j]];
                    if negate[j] {
                        column.map(|x| -x)
                    } else {
                        column
                    }
                }),
                Turn::Matrix(columns) => columns.map(|c| base.rotate(c)),
            };
            // Then the joint's own motion.
            match step.motion {
                JointMotion::Fixed => {}
                JointMotion::RevoluteZ(c) => {
                    let (s, cos) = q[c].sin_cos();
                    let [x, y, _] = r;
                    r[0] = std::array::from_fn(|k| x[k] * cos + y[k] * s);
                    r[1] = std::array::from_fn(|k| y[k] * cos - x[k] * s);
                }
                JointMotion::Revolute(u, c) => {
                    let (s, cos) = q[c].sin_cos();
                    let one_minus = LaneF32::ONE - cos;
                    let u = [u.x, u.y, u.z];
                    // Rodrigues: R = cos·I + sin·[u]× + (1 − cos)·u uᵀ, column j row i.
                    let cross = [[0.0, u[2], -u[1]], [-u[2], 0.0, u[0]], [u[1], -u[0], 0.0]];
                    let rot: [[LaneF32; 3]; 3] = std::array::from_fn(|j| {
                        std::array::from_fn(|i| {
                            let diagonal = if i == j { cos } else { LaneF32::ZERO };
                            diagonal
                                + s * LaneF32::splat(cross[j][i])
                                + one_minus * LaneF32::splat(u[i] * u[j])
                        })
                    });
                    let a = r;
                    r = std::array::from_fn(|j| {
                        std::array::from_fn(|k| {
                            a[0][k] * rot[j][0] + a[1][k] * rot[j][1] + a[2][k] * rot[j][2]
                        })
                    });
                }
                JointMotion::Prismatic(u, c) => {
                    let d = LanePose { r, t }.rotate(u);
                    for (t, d) in t.iter_mut().zip(d) {
                        *t += d * q[c];
                    }
                }
            }
            *pose = LanePose { r, t };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::RobotModel;
    use glam::Affine3A;

    #[test]
    fn quarter_turn_origins_only_permute_columns() {
        let urdf = include_str!("../../data/panda/panda_spherized.urdf");
        let panda = RobotModel::from_urdf_str(urdf).unwrap();
        let lanes = LaneKinematics::new(&Kinematics::new(&panda));
        let turns: Vec<&str> = lanes
            .steps
            .iter()
            .map(|s| match s.turn {
                Turn::Keep => "keep",
                Turn::Permute { .. } => "permute",
                Turn::Matrix(_) => "matrix",
            })
            .collect();
        // Joints 2-7 turn by ±π/2 about x (`rpy` written to 12 digits); the hand by -π/4.
        assert_eq!(
            turns.iter().filter(|t| **t == "permute").count(),
            6,
            "{turns:?}"
        );
        assert_eq!(
            turns.iter().filter(|t| **t == "matrix").count(),
            1,
            "{turns:?}"
        );
        // Translations keep only their nonzero components (joint 1: z = 0.333).
        assert!(
            lanes
                .steps
                .iter()
                .any(|s| s.shifts == 1 && s.shift[0] == (2, 0.333))
        );
    }

    #[test]
    fn lanes_place_links_as_the_scalar_walk_does() {
        let urdf = include_str!("../../data/panda/panda_spherized.urdf");
        let panda = RobotModel::from_urdf_str(urdf).unwrap();
        let fk = Kinematics::new(&panda);
        let lanes = LaneKinematics::new(&fk);
        let configurations: Vec<[f64; 7]> = (0..LANES)
            .map(|l| std::array::from_fn(|j| ((l * 7 + j) as f64 * 0.37).sin() * 1.5))
            .collect();
        let q: Vec<LaneF32> = (0..7)
            .map(|j| LaneF32::new(std::array::from_fn(|l| configurations[l][j] as f32)))
            .collect();
        let mut poses = vec![LanePose::IDENTITY; fk.link_count()];
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
