//! [`ModelJoint`]: a moving URDF joint as the model keeps it, and how the model turns its
//! joints into coordinates: the planned joints, the joints held still, and the mimic joints
//! following their leaders.

use glam::{DAffine3, DVec3};
use mit_star_spaces::{Joint, JointKind, JointSpace, wrap_angle};

use crate::{LeverArms, ModelError, Motion, RobotModel};

/// A revolute, continuous or prismatic URDF joint, as read: the model derives its link's
/// frame ([`LinkFrame`](crate::LinkFrame)) from it whenever the planned joints or the held
/// values change.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ModelJoint {
    pub(crate) name: String,
    /// The link it moves (its child).
    pub(crate) link: usize,
    /// The URDF `<origin>`.
    pub(crate) origin: DAffine3,
    /// The unit axis.
    pub(crate) axis: DVec3,
    pub(crate) prismatic: bool,
    /// Its limits as a coordinate (`None` for a mimic joint: its leader's limits rule).
    pub(crate) spec: Option<Joint>,
    /// `<mimic joint= multiplier= offset=>`: the leader's name, the multiplier and the offset.
    pub(crate) mimic: Option<(String, f64, f64)>,
    /// A mimic joint's own `<limit>` (`None` for a continuous one, or one without limits):
    /// its leader's range is shrunk to keep it within them.
    pub(crate) limits: Option<(f64, f64)>,
    /// A coordinate of the configuration (else held at `value`).
    pub(crate) planned: bool,
    /// The value when held still.
    pub(crate) value: f64,
    /// Its `<limit velocity=…>` as written (`None` when absent, or 0 or infinite — what
    /// urdf-rs reads for a missing attribute): checked only when a trajectory is timed
    /// ([`MotionLimits`](crate::MotionLimits)).
    pub(crate) velocity: Option<f64>,
}

/// How one moving URDF joint follows the configuration, for timing: its name, its URDF
/// velocity limit, and the coordinate it moves with and at what rate (`None` for a joint held
/// still).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct JointRate {
    pub(crate) name: String,
    pub(crate) velocity: Option<f64>,
    pub(crate) follows: Option<(usize, f64)>,
}

/// Where a joint's value comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Drive {
    /// `multiplier · q[coordinate] + offset`.
    Coordinate {
        coordinate: usize,
        multiplier: f64,
        offset: f64,
    },
    /// A constant.
    Held(f64),
}

impl ModelJoint {
    /// MoveIt's default value: 0, or the middle of the limits when 0 is outside them.
    pub(crate) fn default_value(&self) -> f64 {
        self.spec.as_ref().map_or(0.0, |s| default_value(&s.kind))
    }

    /// `value` made a position of this joint: clamped into its limits, or wrapped into
    /// `[-π, π]` for a continuous joint.
    pub(crate) fn admit(&self, value: f64) -> f64 {
        match self.spec.as_ref().map(|s| &s.kind) {
            Some(JointKind::Revolute { lower, upper } | JointKind::Prismatic { lower, upper }) => {
                value.clamp(*lower, *upper)
            }
            Some(JointKind::Continuous) => wrap_angle(value),
            None => value,
        }
    }

    /// The joint's own motion by `value`: a turn about its axis, or a slide along it.
    fn displacement(&self, value: f64) -> DAffine3 {
        if self.prismatic {
            DAffine3::from_translation(self.axis * value)
        } else {
            DAffine3::from_axis_angle(self.axis, value)
        }
    }
}

impl RobotModel {
    /// Derives the link frames, the coordinates and the joint space from the joints: planned
    /// joints (not mimicking) are the coordinates in tree order; a mimic joint follows its
    /// leader (`multiplier · leader + offset`), moving with the leader's coordinate or held
    /// with it; every other joint is held at its value and rides along like a fixed joint.
    ///
    /// Prismatic coordinates are weighted `1 / R` in the metric, `R` the longest lever arm of
    /// a revolute coordinate ([`LeverArms`]): a metre of slide then costs what the turn that
    /// moves the farthest sphere by at most a metre costs.
    pub(super) fn rebuild(&mut self) -> Result<(), ModelError> {
        let mut coordinates = vec![None; self.joints.len()];
        let mut specs = Vec::new();
        for (i, joint) in self.joints.iter().enumerate() {
            if let (true, None, Some(spec)) = (joint.planned, &joint.mimic, &joint.spec) {
                coordinates[i] = Some(specs.len());
                specs.push(spec.clone());
            }
        }
        if specs.is_empty() {
            return Err(ModelError::NoJoints);
        }
        for i in 0..self.joints.len() {
            let joint = &self.joints[i];
            let drive = self.drive(i, &coordinates, 0)?;
            let (origin, motion) = match drive {
                Drive::Held(value) => (joint.origin * joint.displacement(value), Motion::Fixed),
                Drive::Coordinate {
                    coordinate,
                    multiplier,
                    offset,
                } => {
                    let origin = joint.origin * joint.displacement(offset);
                    let motion = if joint.prismatic {
                        Motion::Prismatic {
                            axis: joint.axis * multiplier,
                            coordinate,
                        }
                    } else if multiplier == 1.0 || multiplier == -1.0 {
                        Motion::Revolute {
                            axis: joint.axis * multiplier,
                            coordinate,
                        }
                    } else {
                        return Err(ModelError::UnsupportedJoint {
                            joint: joint.name.clone(),
                            what: "a revolute mimic joint turning at a multiplier other than ±1",
                        });
                    };
                    (origin, motion)
                }
            };
            let link = &mut self.links[joint.link];
            link.origin = origin;
            link.motion = motion;
        }
        self.joint_names = specs.iter().map(|s| s.name.clone()).collect();
        self.space = JointSpace::new(specs.clone())?;
        if specs
            .iter()
            .any(|s| matches!(s.kind, JointKind::Prismatic { .. }))
        {
            let reach = self.revolute_reach();
            let weight = if reach > 0.0 { 1.0 / reach } else { 1.0 };
            for spec in &mut specs {
                if matches!(spec.kind, JointKind::Prismatic { .. }) {
                    spec.weight = weight;
                }
            }
            self.space = JointSpace::new(specs)?;
        }
        Ok(())
    }

    /// Every moving joint with the coordinate it follows and at what rate (`1` for a planned
    /// joint, the composed multiplier for a mimic follower), for velocity limits.
    pub(crate) fn joint_rates(&self) -> Vec<JointRate> {
        let mut coordinates = vec![None; self.joints.len()];
        let mut next = 0;
        for (i, joint) in self.joints.iter().enumerate() {
            if joint.planned && joint.mimic.is_none() && joint.spec.is_some() {
                coordinates[i] = Some(next);
                next += 1;
            }
        }
        (0..self.joints.len())
            .map(|i| JointRate {
                name: self.joints[i].name.clone(),
                velocity: self.joints[i].velocity,
                follows: match self.drive(i, &coordinates, 0) {
                    Ok(Drive::Coordinate {
                        coordinate,
                        multiplier,
                        ..
                    }) => Some((coordinate, multiplier)),
                    _ => None,
                },
            })
            .collect()
    }

    /// Every joint name of the URDF that the model kept a frame for (fixed joints included).
    pub(crate) fn all_joint_names(&self) -> impl Iterator<Item = &str> {
        self.link_joints.iter().flatten().map(String::as_str)
    }

    /// A copy whose every sphere (and link bounding sphere) is grown by `by` metres: a
    /// checker of it proves clearance `by` beyond its margin (the blend certification of
    /// [`Trajectory`](crate::Trajectory)).
    pub(crate) fn with_grown_spheres(&self, by: f64) -> RobotModel {
        let mut grown = self.clone();
        grown.grow_spheres(by);
        grown
    }

    /// The longest lever arm of a revolute (or continuous) coordinate over every link
    /// ([`LeverArms`]): how far, at most, any sphere is from the axis of a joint turning it.
    /// Zero for a robot without revolute coordinates.
    pub fn revolute_reach(&self) -> f64 {
        let levers = LeverArms::new(self);
        let revolute: Vec<usize> = (0..self.joint_names.len())
            .filter(|&c| !matches!(self.space.joints()[c].kind, JointKind::Prismatic { .. }))
            .collect();
        (0..self.links.len())
            .flat_map(|l| revolute.iter().map(move |&c| (l, c)))
            .map(|(l, c)| levers.lever(l, c))
            .fold(0.0, f64::max)
    }

    /// Where joint `i`'s value comes from; `depth` counts mimic links followed (a cycle of
    /// mimic joints is refused).
    fn drive(
        &self,
        i: usize,
        coordinates: &[Option<usize>],
        depth: usize,
    ) -> Result<Drive, ModelError> {
        let joint = &self.joints[i];
        let Some((leader, multiplier, offset)) = &joint.mimic else {
            return Ok(match coordinates[i] {
                Some(coordinate) => Drive::Coordinate {
                    coordinate,
                    multiplier: 1.0,
                    offset: 0.0,
                },
                None => Drive::Held(joint.value),
            });
        };
        let unknown = || ModelError::MimicLeader {
            joint: joint.name.clone(),
            leader: leader.clone(),
        };
        if depth > self.joints.len() {
            return Err(unknown());
        }
        let l = self
            .joints
            .iter()
            .position(|j| &j.name == leader)
            .ok_or_else(unknown)?;
        Ok(match self.drive(l, coordinates, depth + 1)? {
            Drive::Held(v) => Drive::Held(multiplier * v + offset),
            Drive::Coordinate { .. } if *multiplier == 0.0 => Drive::Held(*offset),
            Drive::Coordinate {
                coordinate,
                multiplier: m,
                offset: o,
            } => Drive::Coordinate {
                coordinate,
                multiplier: multiplier * m,
                offset: multiplier * o + offset,
            },
        })
    }
}

/// MoveIt's default value of a joint of `kind`: 0, or the middle of the limits when 0 is
/// outside them.
pub(crate) fn default_value(kind: &JointKind) -> f64 {
    match *kind {
        JointKind::Revolute { lower, upper } | JointKind::Prismatic { lower, upper } => {
            if (lower..=upper).contains(&0.0) {
                0.0
            } else {
                0.5 * (lower + upper)
            }
        }
        JointKind::Continuous => 0.0,
    }
}
