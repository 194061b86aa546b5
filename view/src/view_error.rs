//! [`ViewError`]: why a page could not be made.

use std::path::PathBuf;

/// Why [`ViewDocument::to_html`](crate::ViewDocument::to_html) or
/// [`write_html`](crate::ViewDocument::write_html) failed.
#[derive(Debug, thiserror::Error)]
pub enum ViewError {
    /// The page could not be written.
    #[error("cannot write the view page {path}: {source}")]
    Io {
        /// The file being written.
        path: PathBuf,
        /// What the system said.
        source: std::io::Error,
    },
    /// The document contradicts itself (sizes that do not match, indices past the end,
    /// non-finite numbers).
    #[error("invalid view document: {field}: {problem}")]
    Invalid {
        /// Where: `motions[0].poses`, `scene.solids[3].position`, `robot.hand`.
        field: String,
        /// What is wrong, with the numbers.
        problem: String,
    },
    /// The document could not be written as JSON.
    #[error("cannot write the view document as JSON: {0}")]
    Json(#[from] serde_json::Error),
}

impl ViewError {
    /// An [`Invalid`](Self::Invalid) error.
    pub(crate) fn invalid(field: impl Into<String>, problem: impl Into<String>) -> Self {
        Self::Invalid {
            field: field.into(),
            problem: problem.into(),
        }
    }
}
