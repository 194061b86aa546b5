//! [`TrajectoryError`]: why limits could not be set, a path could not be timed, or a
//! trajectory file could not be read or checked.

use std::path::PathBuf;

/// What is wrong with motion limits, a path to time, or a trajectory file — naming the joint,
/// the waypoint or the sample.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TrajectoryError {
    /// A velocity or acceleration limit that is zero, negative, infinite or NaN.
    #[error("joint `{joint}`: {what} limit {value} is not a positive finite number")]
    BadLimit {
        /// The joint.
        joint: String,
        /// `velocity` or `acceleration`.
        what: &'static str,
        /// The value given.
        value: f64,
    },
    /// A joint without a velocity or acceleration limit, and no override for it.
    #[error("joint `{joint}` has no {what} limit: give one in a joint_limits.yaml{hint}")]
    MissingLimit {
        /// The joint.
        joint: String,
        /// `velocity` or `acceleration`.
        what: &'static str,
        /// Another way to give it.
        hint: &'static str,
    },
    /// A joint_limits.yaml entry naming a joint the robot does not have.
    #[error("the joint limits name joint `{joint}`, which the robot does not have")]
    UnknownJoint {
        /// The name.
        joint: String,
    },
    /// A velocity or acceleration scaling factor outside `(0, 1]`.
    #[error("{what} scaling {value} is outside (0, 1]")]
    BadScaling {
        /// `velocity` or `acceleration`.
        what: &'static str,
        /// The value given.
        value: f64,
    },
    /// Limits of the wrong length for the robot.
    #[error("{what}: {found} values for {expected} joints")]
    WrongLength {
        /// What was given.
        what: &'static str,
        /// How many values.
        found: usize,
        /// How many joints.
        expected: usize,
    },
    /// A malformed joint_limits.yaml.
    #[error("joint limits YAML {origin}: {message}")]
    Yaml {
        /// The file, or `text`.
        origin: String,
        /// What the parser said.
        message: String,
    },
    /// A path of fewer than two waypoints.
    #[error("a path to time needs at least two waypoints, this one has {points}")]
    TooShort {
        /// How many waypoints.
        points: usize,
    },
    /// A waypoint of the wrong length.
    #[error("waypoint {index} has {found} coordinates, the robot {expected}")]
    WrongDimension {
        /// The waypoint.
        index: usize,
        /// Its length.
        found: usize,
        /// The robot's dimension.
        expected: usize,
    },
    /// A waypoint coordinate that is NaN or infinite.
    #[error("waypoint {index}: joint `{joint}` is {value}")]
    NotFinite {
        /// The waypoint.
        index: usize,
        /// The joint.
        joint: String,
        /// The value.
        value: f64,
    },
    /// A waypoint equal to the one before it (merge them, or ask for merging).
    #[error("waypoint {index} repeats waypoint {}", index - 1)]
    RepeatedWaypoint {
        /// The second of the two.
        index: usize,
    },
    /// A sample period that is not positive and finite.
    #[error("sample period {value} s is not a positive finite number")]
    BadPeriod {
        /// The value given.
        value: f64,
    },
    /// A trajectory file that could not be read or written.
    #[error("{}: {message}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// What failed.
        message: String,
    },
    /// A malformed trajectory file.
    #[error("trajectory {origin}: {message}")]
    Format {
        /// The file, or `text`.
        origin: String,
        /// What is wrong, with the line or sample.
        message: String,
    },
    /// A trajectory whose joints are not the robot's, in its order.
    #[error("trajectory joints [{found}] are not the robot's [{expected}]")]
    JointNames {
        /// The robot's, comma separated.
        expected: String,
        /// The file's.
        found: String,
    },
    /// Sample times that do not strictly increase.
    #[error("sample {index} at t = {time} s does not come after the one before (t = {previous} s)")]
    TimeNotIncreasing {
        /// The sample.
        index: usize,
        /// The time before it.
        previous: f64,
        /// Its time.
        time: f64,
    },
}
