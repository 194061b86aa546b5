//! [`ArmError`]: why an arm problem could not be made.

use thiserror::Error;

use crate::{ModelError, SceneError};

/// Why an [`ArmProblem`](crate::ArmProblem) could not be made: the robot model, the scene files,
/// or the query itself.
#[derive(Debug, Error)]
pub enum ArmError {
    /// The robot model (URDF, SRDF, or an allowed-collision pair naming an unknown link).
    #[error(transparent)]
    Model(#[from] ModelError),
    /// The scene or request files.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// A start or goal configuration the robot cannot take.
    #[error("problem `{problem}`: the {what} configuration is unusable: {source}")]
    Query {
        /// The problem's name.
        problem: String,
        /// `"start"` or `"goal"`.
        what: &'static str,
        /// What is wrong with it.
        source: spaces::SpaceError,
    },
    /// A start or goal in collision ([`ArmProblem::check_ends`](crate::ArmProblem::check_ends)).
    #[error("problem `{problem}`: the {what} configuration collides with {with}")]
    EndInCollision {
        /// The problem's name.
        problem: String,
        /// `"start"` or `"goal"`.
        what: &'static str,
        /// What it collides with: `itself: links a/b, c/d`, or the scene.
        with: String,
    },
    /// A collision-check resolution outside `(0, 1)`.
    #[error(
        "collision-check resolution {0} is not in (0, 1): it is a fraction of the maximum extent (the paper uses 5e-3)"
    )]
    Resolution(f64),
}
