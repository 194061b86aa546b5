//! [`SceneError`]: why a scene or a MotionBenchMaker problem could not be read.

use std::path::PathBuf;

use thiserror::Error;

/// Why a [`Scene`](crate::Scene) or [`MbmProblem`](crate::MbmProblem) could not be read. Every
/// variant names the file, and the field where one is at fault (`world.collision_objects[2]
/// .primitives[0].dimensions[1]`); [`field`](Self::field) gives it.
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
    /// A number the scene cannot use: coordinates must be finite and within
    /// ±[`Scene::MAX_LENGTH`](crate::Scene::MAX_LENGTH) (10⁶ m), sizes in
    /// (0, [`Scene::MAX_LENGTH`](crate::Scene::MAX_LENGTH)], quaternion components finite.
    #[error("{origin}: {field}: {} is not {allowed}", readable(*.value))]
    Number {
        /// The file.
        origin: String,
        /// The path of the field (`world.collision_objects[0].pose.position[2]`).
        field: String,
        /// The value as read.
        value: f64,
        /// What is accepted there (`a coordinate within ±1e6 m`).
        allowed: &'static str,
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
    /// A request gives a joint two values (which one is meant is not known).
    #[error("{origin}: {what} lists joint `{joint}` twice")]
    DuplicateJoint {
        /// The request file.
        origin: String,
        /// `"start_state.joint_state.name"` or `"goal_constraints[0].joint_constraints"`.
        what: &'static str,
        /// The joint.
        joint: String,
    },
}

impl SceneError {
    /// The path of the field at fault, for the variants that name one.
    pub fn field(&self) -> Option<&str> {
        match self {
            Self::Field { field, .. } | Self::Number { field, .. } => Some(field),
            Self::MissingJoint { what, .. } | Self::DuplicateJoint { what, .. } => Some(what),
            Self::Io { .. } | Self::Yaml { .. } | Self::Folder { .. } => None,
        }
    }
}

/// `value` as written by a person: plain for ordinary magnitudes, in scientific notation for
/// the huge and the tiny (`1e308`, not 309 digits).
fn readable(value: f64) -> String {
    if value == 0.0 || !value.is_finite() || (1e-4..1e7).contains(&value.abs()) {
        value.to_string()
    } else {
        format!("{value:e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_written_readably() {
        let e = |value| SceneError::Number {
            origin: "s.yaml".into(),
            field: "f".into(),
            value,
            allowed: "a coordinate within ±1e6 m",
        };
        assert_eq!(
            e(1e308).to_string(),
            "s.yaml: f: 1e308 is not a coordinate within ±1e6 m"
        );
        assert_eq!(
            e(-2.5).to_string(),
            "s.yaml: f: -2.5 is not a coordinate within ±1e6 m"
        );
        assert_eq!(
            e(f64::NAN).to_string(),
            "s.yaml: f: NaN is not a coordinate within ±1e6 m"
        );
        assert_eq!(e(1e-300).field(), Some("f"));
        assert!(e(1e-300).to_string().contains(" 1e-300 "));
    }
}
