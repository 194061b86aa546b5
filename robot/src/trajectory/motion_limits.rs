//! [`MotionLimits`]: per coordinate, the largest speed and acceleration a trajectory may ask of
//! it — from the URDF, a MoveIt `joint_limits.yaml`, or given — with MoveIt's scaling factors.

use crate::{JointLimitsYaml, RobotModel, TrajectoryError};

/// Velocity and acceleration limits per coordinate of a robot (in its coordinate order), all
/// positive and finite.
///
/// [`for_robot`](Self::for_robot) takes, for each planned joint, the velocity limit of the
/// `joint_limits.yaml` (if it switches one on) or else the URDF's `<limit velocity=…>`, and the
/// acceleration limit given for every joint (`max_acceleration`) or else the YAML's. A mimic
/// joint moves at `|multiplier|` times its leader's rate, so its own limits (URDF or YAML)
/// bound its leader's at `limit / |multiplier|`. Continuous joints are limited like any other.
/// [`scaled`](Self::scaled) multiplies the limits by MoveIt's velocity and acceleration
/// scaling factors.
///
/// ```
/// let panda = mit_star_robot::ArmProblem::panda()?;
/// let yaml = mit_star_robot::JointLimitsYaml::parse(mit_star_robot::PANDA_JOINT_LIMITS, "panda")?;
/// let limits = mit_star_robot::MotionLimits::for_robot(&panda, Some(&yaml), None)?.scaled(0.5, 1.0)?;
/// // The URDF's 2.3925 rad/s for panda_joint1, halved; MoveIt's 3.75 rad/s².
/// assert!((limits.velocity()[0] - 0.5 * 2.3925).abs() < 1e-12);
/// assert_eq!(limits.acceleration()[0], 3.75);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct MotionLimits {
    names: Vec<String>,
    velocity: Vec<f64>,
    acceleration: Vec<f64>,
}

impl MotionLimits {
    /// Limits given for each coordinate, named `names`.
    ///
    /// # Errors
    /// [`TrajectoryError::WrongLength`] for lists of different lengths;
    /// [`TrajectoryError::BadLimit`] naming the joint of a limit that is not positive and
    /// finite.
    pub fn new(
        names: Vec<String>,
        velocity: Vec<f64>,
        acceleration: Vec<f64>,
    ) -> Result<Self, TrajectoryError> {
        for (what, list) in [("velocity", &velocity), ("acceleration", &acceleration)] {
            if list.len() != names.len() {
                return Err(TrajectoryError::WrongLength {
                    what,
                    found: list.len(),
                    expected: names.len(),
                });
            }
            for (name, &value) in names.iter().zip(list) {
                checked(name, what, value)?;
            }
        }
        Ok(Self {
            names,
            velocity,
            acceleration,
        })
    }

    /// The limits of `robot`'s coordinates as the type's docs say: velocity from `yaml` or the
    /// URDF, acceleration `max_acceleration` for every joint or else from `yaml`.
    ///
    /// # Errors
    /// [`TrajectoryError::UnknownJoint`] for a YAML entry naming no joint of the URDF;
    /// [`TrajectoryError::BadLimit`] naming the joint of a limit (URDF, YAML or given) that is
    /// zero, negative, infinite or NaN; [`TrajectoryError::MissingLimit`] naming a planned
    /// joint without a velocity or acceleration limit.
    pub fn for_robot(
        robot: &RobotModel,
        yaml: Option<&JointLimitsYaml>,
        max_acceleration: Option<f64>,
    ) -> Result<Self, TrajectoryError> {
        if let Some(yaml) = yaml {
            let known: std::collections::HashSet<&str> = robot.all_joint_names().collect();
            if let Some(name) = yaml.names().find(|n| !known.contains(n)) {
                return Err(TrajectoryError::UnknownJoint {
                    joint: name.to_owned(),
                });
            }
        }
        let names = robot.joint_names().to_vec();
        let mut velocity: Vec<Option<f64>> = vec![None; names.len()];
        let mut acceleration: Vec<Option<f64>> = vec![None; names.len()];
        let tighten = |slot: &mut Option<f64>, value: f64| {
            *slot = Some(slot.map_or(value, |v: f64| v.min(value)));
        };
        for rate in robot.joint_rates() {
            let Some((coordinate, multiplier)) = rate.follows else {
                continue;
            };
            if multiplier == 0.0 {
                continue;
            }
            let name = rate.name.as_str();
            let own_velocity = yaml.and_then(|y| y.velocity(name)).or(rate.velocity);
            if let Some(v) = own_velocity {
                tighten(
                    &mut velocity[coordinate],
                    checked(name, "velocity", v)? / multiplier.abs(),
                );
            }
            let own_acceleration = match max_acceleration {
                Some(a) => Some(a),
                None => yaml.and_then(|y| y.acceleration(name)),
            };
            if let Some(a) = own_acceleration {
                tighten(
                    &mut acceleration[coordinate],
                    checked(name, "acceleration", a)? / multiplier.abs(),
                );
            }
        }
        let missing = |c: usize, what, hint| TrajectoryError::MissingLimit {
            joint: names[c].clone(),
            what,
            hint,
        };
        let velocity = (0..names.len())
            .map(|c| velocity[c].ok_or_else(|| missing(c, "velocity", " or the URDF")))
            .collect::<Result<Vec<_>, _>>()?;
        let acceleration = (0..names.len())
            .map(|c| {
                acceleration[c].ok_or_else(|| missing(c, "acceleration", " or a max acceleration"))
            })
            .collect::<Result<Vec<_>, _>>()?;
        Self::new(names, velocity, acceleration)
    }

    /// The limits times MoveIt's scaling factors.
    ///
    /// # Errors
    /// [`TrajectoryError::BadScaling`] for a factor outside `(0, 1]` (NaN included).
    pub fn scaled(mut self, velocity: f64, acceleration: f64) -> Result<Self, TrajectoryError> {
        for (what, value) in [("velocity", velocity), ("acceleration", acceleration)] {
            if !(value > 0.0 && value <= 1.0) {
                return Err(TrajectoryError::BadScaling { what, value });
            }
        }
        self.velocity.iter_mut().for_each(|v| *v *= velocity);
        self.acceleration
            .iter_mut()
            .for_each(|a| *a *= acceleration);
        Ok(self)
    }

    /// The coordinates' names.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The velocity limit of each coordinate (rad/s or m/s).
    pub fn velocity(&self) -> &[f64] {
        &self.velocity
    }

    /// The acceleration limit of each coordinate (rad/s² or m/s²).
    pub fn acceleration(&self) -> &[f64] {
        &self.acceleration
    }
}

/// `value` if a positive finite number, else the error naming `joint`.
fn checked(joint: &str, what: &'static str, value: f64) -> Result<f64, TrajectoryError> {
    if value > 0.0 && value.is_finite() {
        Ok(value)
    } else {
        Err(TrajectoryError::BadLimit {
            joint: joint.to_owned(),
            what,
            value,
        })
    }
}

/// MoveIt's `joint_limits.yaml` for the Panda as `moveit_resources`' `panda_moveit_config`
/// ships it, acceleration limits only (velocities switched off, so the URDF's rule): 3.75,
/// 1.875, 2.5, 3.125, 3.75, 5, 5 rad/s² for `panda_joint1` … `panda_joint7`.
pub const PANDA_JOINT_LIMITS: &str = include_str!("../../data/panda/joint_limits.yaml");

#[cfg(test)]
mod tests {
    use super::*;

    fn urdf(velocity: &str, mimic: &str) -> String {
        format!(
            r#"<robot name="r"><link name="a"/><link name="b"/><link name="c"/>
<joint name="j1" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
<limit lower="-1" upper="1" {velocity} effort="1"/></joint>
<joint name="j2" type="revolute"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/>
<limit lower="-1" upper="1" velocity="3" effort="1"/>{mimic}</joint></robot>"#
        )
    }

    #[test]
    fn a_mimic_follower_bounds_its_leader() {
        // Prismatic: a revolute mimic joint turns at ±1 only.
        let model = RobotModel::from_urdf_str(
            &urdf("velocity=\"2\"", r#"<mimic joint="j1" multiplier="-2"/>"#)
                .replace("revolute", "prismatic"),
        )
        .unwrap();
        let limits = MotionLimits::for_robot(&model, None, Some(4.0)).unwrap();
        assert_eq!(limits.names(), ["j1"]);
        assert_eq!(limits.velocity(), [1.5]);
        assert_eq!(limits.acceleration(), [2.0]);
    }

    #[test]
    fn names_the_joint_of_a_missing_or_bad_limit() {
        let model = RobotModel::from_urdf_str(&urdf("velocity=\"2\"", "").replace(
            r#"type="revolute"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/>
<limit lower="-1" upper="1" velocity="3" effort="1"/>"#,
            r#"type="continuous"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/>"#,
        ))
        .unwrap();
        let e = MotionLimits::for_robot(&model, None, Some(1.0)).unwrap_err();
        assert!(
            matches!(&e, TrajectoryError::MissingLimit { joint, what: "velocity", .. } if joint == "j2"),
            "{e}"
        );
        let e = MotionLimits::for_robot(&model, None, None).unwrap_err();
        assert!(
            matches!(&e, TrajectoryError::MissingLimit { joint, .. } if joint == "j1" || joint == "j2")
        );
        let model = RobotModel::from_urdf_str(&urdf("velocity=\"-2\"", "")).unwrap();
        let e = MotionLimits::for_robot(&model, None, Some(1.0)).unwrap_err();
        assert!(
            matches!(&e, TrajectoryError::BadLimit { joint, value, .. } if joint == "j1" && *value == -2.0)
        );
        let yaml = JointLimitsYaml::parse(
            "joint_limits:\n  j1: {has_velocity_limits: true, max_velocity: 1}\n  nope: {}\n",
            "t",
        )
        .unwrap();
        let model = RobotModel::from_urdf_str(&urdf("velocity=\"2\"", "")).unwrap();
        let e = MotionLimits::for_robot(&model, Some(&yaml), Some(1.0)).unwrap_err();
        assert_eq!(
            e,
            TrajectoryError::UnknownJoint {
                joint: "nope".into()
            }
        );
        let e = MotionLimits::for_robot(&model, None, Some(f64::NAN)).unwrap_err();
        assert!(matches!(
            e,
            TrajectoryError::BadLimit {
                what: "acceleration",
                ..
            }
        ));
    }

    #[test]
    fn the_yaml_overrides_the_urdf_and_scaling_is_checked() {
        let yaml = JointLimitsYaml::parse(
            "joint_limits:\n  j1: {has_velocity_limits: true, max_velocity: 1, has_acceleration_limits: true, max_acceleration: 7}\n  j2: {has_acceleration_limits: true, max_acceleration: 8}\n",
            "t",
        )
        .unwrap();
        let model = RobotModel::from_urdf_str(&urdf("velocity=\"2\"", "")).unwrap();
        let limits = MotionLimits::for_robot(&model, Some(&yaml), None).unwrap();
        assert_eq!(limits.velocity(), [1.0, 3.0]);
        assert_eq!(limits.acceleration(), [7.0, 8.0]);
        for bad in [0.0, -1.0, 1.5, f64::NAN] {
            assert!(matches!(
                limits.clone().scaled(bad, 1.0),
                Err(TrajectoryError::BadScaling {
                    what: "velocity",
                    ..
                })
            ));
        }
    }
}
