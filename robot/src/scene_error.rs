//! [`SceneError`]: why a scene or a MotionBenchMaker problem could not be read.

use std::path::PathBuf;

use thiserror::Error;

/// Why a [`Scene`](crate::Scene) or [`MbmProblem`](crate::MbmProblem) could not be read. Every
/// variant names the file, and the field where one is at fault (`world.collision_objects[2]
/// .primitives[0].dimensions`).
#[derive(Debug, Error)]
pub enum SceneError {
    /// A file could not be read.
    #[error("cannot read `{path}`: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// The text is not YAML of the expected shape (the parser's message gives line and column).
    #[error("{origin}: {message}")]
    Yaml {
        /// The file (or `"scene text"`).
        origin: String,
        /// The parser's message.
        message: String,
    },
    /// A field has a value the scene cannot use.
    #[error("{origin}: {field}: {message}")]
    Field {
        /// The file.
        origin: String,
        /// The path of the field.
        field: String,
        /// What is wrong with it.
        message: String,
    },
    /// A folder holds no MotionBenchMaker problem, or only half of one.
    #[error("{folder}: {message}")]
    Folder {
        /// The folder.
        folder: PathBuf,
        /// What is missing.
        message: String,
    },
    /// A request does not give a value for a joint the robot has.
    #[error("{origin}: {what} has no value for joint `{joint}`")]
    MissingJoint {
        /// The request file.
        origin: String,
        /// `"start_state.joint_state"` or `"goal_constraints[0].joint_constraints"`.
        what: &'static str,
        /// The joint.
        joint: String,
    },
}
