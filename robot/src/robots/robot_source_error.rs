//! [`RobotSourceError`]: why a named robot could not be found or loaded.

use std::path::PathBuf;

use thiserror::Error;

use crate::ModelError;

/// Why a [`RobotSource`](crate::RobotSource) could not be found or loaded.
#[derive(Debug, Error)]
pub enum RobotSourceError {
    /// Neither a shipped robot's name nor a folder.
    #[error(
        "`{name}` is neither a shipped robot ({known}) nor a URDF file nor a folder holding a URDF and an SRDF"
    )]
    Unknown {
        /// What was given.
        name: String,
        /// The shipped robots' names.
        known: String,
    },
    /// A folder without the URDF or the SRDF.
    #[error("folder `{}` holds no {what}", folder.display())]
    Missing {
        /// The folder.
        folder: PathBuf,
        /// `URDF (*.urdf)` or `SRDF (*.srdf)`.
        what: &'static str,
    },
    /// A folder with several candidates.
    #[error("folder `{}` holds several {what} files ({files}): keep one", folder.display())]
    Ambiguous {
        /// The folder.
        folder: PathBuf,
        /// `URDF (*.urdf)` or `SRDF (*.srdf)`.
        what: &'static str,
        /// Their names, comma separated.
        files: String,
    },
    /// A folder that cannot be listed.
    #[error("cannot list `{}`: {source}", path.display())]
    Io {
        /// The folder.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// A planning group asked of a URDF without an SRDF.
    #[error(
        "robot `{}` has no SRDF (none beside the URDF), so no planning group `{group}`: put its SRDF beside it (same stem, `.srdf`) or plan every joint",
        urdf.display()
    )]
    NoGroups {
        /// The URDF.
        urdf: PathBuf,
        /// The group asked for.
        group: String,
    },
    /// The files were found but the model could not be made from them.
    #[error("robot `{robot}`: {source}")]
    Model {
        /// The robot's name or URDF.
        robot: String,
        /// What is wrong.
        source: ModelError,
    },
}
