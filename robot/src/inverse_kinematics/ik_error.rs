//! [`IkError`]: why a pose target, a solver setting or an inverse-kinematics query was refused,
//! or why no solution was found.

/// What is wrong with an inverse-kinematics input, or why no solution was found.
///
/// Every bad input is named with its value; nothing in this module panics on bad input.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum IkError {
    /// The solver was asked for a link the model lacks.
    #[error("unknown link `{link}`; the model has {count} links, e.g. {examples}")]
    UnknownLink {
        /// The name asked for.
        link: String,
        /// How many links the model has.
        count: usize,
        /// A few of its link names (the last ones in tree order: the tips), comma separated.
        examples: String,
    },
    /// No coordinate of the configuration moves the link: its pose cannot be changed.
    #[error("link `{link}` is not moved by any planned joint")]
    ImmovableLink {
        /// The link's name.
        link: String,
    },
    /// A target orientation that is not a rotation: NaN or infinite components, or norm 0.
    #[error("bad target quaternion [x, y, z, w] = {quaternion:?}: {why}")]
    BadQuaternion {
        /// The quaternion as given, `[x, y, z, w]`.
        quaternion: [f64; 4],
        /// What is wrong with it.
        why: &'static str,
    },
    /// A target position with NaN or infinite coordinates.
    #[error("bad target position {position:?}: coordinates must be finite")]
    BadPosition {
        /// The position as given.
        position: [f64; 3],
    },
    /// A tolerance that is negative, NaN, infinite or out of its range.
    #[error("bad {what}: {value} (expected {expected})")]
    BadTolerance {
        /// Which tolerance (`box half-extent x`, `ball radius`, `cone half-angle`, …).
        what: &'static str,
        /// The value given.
        value: f64,
        /// The range it must lie in.
        expected: &'static str,
    },
    /// An axis of an orientation tolerance that is zero, NaN or infinite.
    #[error("bad {what} axis {axis:?}: must be finite and non-zero")]
    BadAxis {
        /// Which tolerance the axis belongs to.
        what: &'static str,
        /// The axis as given.
        axis: [f64; 3],
    },
    /// A solver setting out of its range.
    #[error("bad solver setting `{setting}`: {value} (expected {expected})")]
    BadSetting {
        /// The setter's name.
        setting: &'static str,
        /// The value given.
        value: f64,
        /// The range it must lie in.
        expected: &'static str,
    },
    /// A tool offset that is not a rigid transform (non-finite, or its rotation part not
    /// orthonormal with determinant 1 within 1e-6).
    #[error("bad tool offset: {why}")]
    BadTool {
        /// What is wrong with it.
        why: &'static str,
    },
    /// A configuration with the wrong number of coordinates.
    #[error("configuration of {got} coordinates; the model has {expected}")]
    WrongLength {
        /// The model's number of coordinates.
        expected: usize,
        /// The length given.
        got: usize,
    },
    /// A configuration with a NaN or infinite coordinate.
    #[error("configuration coordinate {index} is {value}: coordinates must be finite")]
    NonFiniteCoordinate {
        /// Which coordinate.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// No new valid solution within the attempt budget.
    #[error(
        "unreachable: no new valid solution in {attempts} attempts ({rejected} converged but \
         were invalid or not distinct); best position error {position_error:.3e} m, \
         orientation error {orientation_error:.3e} rad"
    )]
    Unreachable {
        /// Attempts made (the first start and the restarts).
        attempts: usize,
        /// Attempts that converged to a configuration the checker refused, or one too close to
        /// a solution to avoid.
        rejected: usize,
        /// The smallest position error reached (distance to the position tolerance set).
        position_error: f64,
        /// The orientation error at that point (angle to the orientation tolerance set).
        orientation_error: f64,
    },
    /// The stop condition fired before a new valid solution was found.
    #[error(
        "stopped after {attempts} attempts; best position error {position_error:.3e} m, \
         orientation error {orientation_error:.3e} rad"
    )]
    Stopped {
        /// Attempts begun.
        attempts: usize,
        /// The smallest position error reached.
        position_error: f64,
        /// The orientation error at that point.
        orientation_error: f64,
    },
}
