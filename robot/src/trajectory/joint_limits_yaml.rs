//! [`JointLimitsYaml`]: MoveIt's `joint_limits.yaml` — per joint, a velocity and an
//! acceleration limit, each switched on by its `has_…_limits` flag.

use std::collections::BTreeMap;
use std::path::Path;

use serde::Deserialize;

use crate::TrajectoryError;

/// The limits a MoveIt `joint_limits.yaml` gives:
///
/// ```yaml
/// joint_limits:
///   panda_joint1:
///     has_velocity_limits: true
///     max_velocity: 2.175
///     has_acceleration_limits: true
///     max_acceleration: 3.75
/// ```
///
/// A limit counts only when its flag is `true` (as in MoveIt); other keys
/// (`max_position`, `has_jerk_limits`, …) and the top-level scaling defaults are ignored.
///
/// ```
/// let yaml = mit_star_robot::JointLimitsYaml::parse(
///     "joint_limits:\n  j1: {has_velocity_limits: true, max_velocity: 2.0,\n       has_acceleration_limits: false, max_acceleration: 0}\n",
///     "text",
/// )?;
/// assert_eq!(yaml.velocity("j1"), Some(2.0));
/// assert_eq!(yaml.acceleration("j1"), None);
/// # Ok::<(), mit_star_robot::TrajectoryError>(())
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct JointLimitsYaml {
    /// Per joint name: the velocity and acceleration limits that are switched on.
    joints: BTreeMap<String, (Option<f64>, Option<f64>)>,
}

#[derive(Deserialize)]
struct Document {
    #[serde(default)]
    joint_limits: BTreeMap<String, Entry>,
}

#[derive(Deserialize)]
struct Entry {
    #[serde(default)]
    has_velocity_limits: bool,
    #[serde(default)]
    max_velocity: Option<f64>,
    #[serde(default)]
    has_acceleration_limits: bool,
    #[serde(default)]
    max_acceleration: Option<f64>,
}

impl JointLimitsYaml {
    /// The largest file read, in bytes: a robot's limits are a few kilobytes.
    pub const MAX_BYTES: u64 = 1 << 20;

    /// Reads a `joint_limits.yaml` file.
    ///
    /// # Errors
    /// [`TrajectoryError::Io`] for a file that cannot be read (or over
    /// [`MAX_BYTES`](Self::MAX_BYTES)), else as [`parse`](Self::parse).
    pub fn read(path: &Path) -> Result<Self, TrajectoryError> {
        let io = |message: String| TrajectoryError::Io {
            path: path.to_owned(),
            message,
        };
        let size = std::fs::metadata(path)
            .map_err(|e| io(e.to_string()))?
            .len();
        if size > Self::MAX_BYTES {
            return Err(io(format!("{size} bytes, over {}", Self::MAX_BYTES)));
        }
        let text = std::fs::read_to_string(path).map_err(|e| io(e.to_string()))?;
        Self::parse(&text, &path.display().to_string())
    }

    /// Parses a `joint_limits.yaml` document; `origin` names it in errors.
    ///
    /// # Errors
    /// [`TrajectoryError::Yaml`] for malformed YAML or a flag switched on without its value.
    /// The values themselves are checked when they become limits
    /// ([`MotionLimits`](crate::MotionLimits)).
    pub fn parse(text: &str, origin: &str) -> Result<Self, TrajectoryError> {
        let yaml = |message: String| TrajectoryError::Yaml {
            origin: origin.to_owned(),
            message,
        };
        let document: Document = serde_saphyr::from_str(text).map_err(|e| yaml(e.to_string()))?;
        let mut joints = BTreeMap::new();
        for (name, entry) in document.joint_limits {
            let pick = |on: bool, value: Option<f64>, what: &str| match (on, value) {
                (false, _) => Ok(None),
                (true, Some(v)) => Ok(Some(v)),
                (true, None) => Err(yaml(format!(
                    "joint `{name}`: has_{what}_limits is true without max_{what}"
                ))),
            };
            let velocity = pick(entry.has_velocity_limits, entry.max_velocity, "velocity")?;
            let acceleration = pick(
                entry.has_acceleration_limits,
                entry.max_acceleration,
                "acceleration",
            )?;
            joints.insert(name, (velocity, acceleration));
        }
        Ok(Self { joints })
    }

    /// The joints named, in name order.
    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.joints.keys().map(String::as_str)
    }

    /// Joint `name`'s velocity limit, if switched on.
    pub fn velocity(&self, name: &str) -> Option<f64> {
        self.joints.get(name).and_then(|l| l.0)
    }

    /// Joint `name`'s acceleration limit, if switched on.
    pub fn acceleration(&self, name: &str) -> Option<f64> {
        self.joints.get(name).and_then(|l| l.1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_flags_and_values() {
        let text = "joint_limits:\n  a:\n    has_velocity_limits: true\n    max_velocity: 1.5\n    has_acceleration_limits: true\n    max_acceleration: 3\n  b:\n    has_velocity_limits: false\n    max_velocity: 9\n";
        let y = JointLimitsYaml::parse(text, "t").unwrap();
        assert_eq!(y.velocity("a"), Some(1.5));
        assert_eq!(y.acceleration("a"), Some(3.0));
        assert_eq!(y.velocity("b"), None);
        assert_eq!(y.names().collect::<Vec<_>>(), ["a", "b"]);
    }

    #[test]
    fn refuses_a_flag_without_value_and_bad_yaml() {
        let e = JointLimitsYaml::parse("joint_limits:\n  a: {has_velocity_limits: true}\n", "t");
        assert!(matches!(e, Err(TrajectoryError::Yaml { message, .. }) if message.contains("`a`")));
        assert!(JointLimitsYaml::parse("joint_limits: [1, 2", "t").is_err());
    }
}
