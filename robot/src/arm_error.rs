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
        source: mit_star_spaces::SpaceError,
    },
    /// A start or goal in collision ([`ArmProblem::check_ends`](crate::ArmProblem::check_ends)).
    #[error("problem `{problem}`: the {what} configuration collides with {with}")]
    EndInCollision {
        /// The problem's name.
        problem: String,
        /// `"start"` or `"goal"`.
        what: &'static str,
        /// What it collides with, deepest first: `itself: links a/b (overlap 3.100 mm), …`
        /// and `the scene: link l meets obstacle o (overlap 12.000 mm), …`.
        with: String,
    },
    /// A start or goal free of collision, but within the collision padding of an obstacle
    /// ([`ArmProblem::with_padding`](crate::ArmProblem::with_padding)): every configuration
    /// of a path keeps the padding, so none can start or end there.
    #[error(
        "problem `{problem}`: the {what} configuration is within the collision padding ({padding_mm} mm) of {near}: lower the padding, or move the {what} away"
    )]
    EndWithinPadding {
        /// The problem's name.
        problem: String,
        /// `"start"` or `"goal"`.
        what: &'static str,
        /// The padding, in millimetres.
        padding_mm: f64,
        /// The closest obstacles: `obstacle o (link l, gap 4.000 mm)`, closest first.
        near: String,
    },
    /// A start or goal free of collision, but so close to something that no certified motion
    /// reaches it ([`ArmProblem::check_ends`](crate::ArmProblem::check_ends)): its clearance
    /// beyond the checker's margin is below [`CERTIFICATION_FLOOR`](crate::CERTIFICATION_FLOOR).
    #[error(
        "problem `{problem}`: the {what} configuration is within the certification floor ({floor_um} µm beyond the checker's margin) of {near}, so no certified motion reaches it"
    )]
    EndWithinFloor {
        /// The problem's name.
        problem: String,
        /// `"start"` or `"goal"`.
        what: &'static str,
        /// The floor, in micrometres.
        floor_um: f64,
        /// What it is closest to: the obstacle, the link, the gap and the margin, or a link
        /// of the robot's own.
        near: String,
    },
    /// A collision-check resolution outside `(0, 1)`.
    #[error(
        "collision-check resolution {0} is not in (0, 1): it is a fraction of the maximum extent (the paper uses 5e-3)"
    )]
    Resolution(f64),
}
