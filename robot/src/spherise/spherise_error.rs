//! [`SpheriseError`]: why a mesh could not be read or a URDF could not be spherised.

use std::path::PathBuf;

use thiserror::Error;

/// Why a mesh could not be read, covered or written into a spherised URDF. Every variant names
/// the file, link or value at fault.
#[derive(Debug, Error)]
pub enum SpheriseError {
    /// A file could not be read or written.
    #[error("cannot access `{}`: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// A mesh file is not a readable STL.
    #[error("`{}`: not a readable STL: {message}", path.display())]
    Stl {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        message: String,
    },
    /// A mesh file's format is not one this reader knows (only STL is read).
    #[error("`{}`: mesh format `{extension}` is not supported (only STL)", path.display())]
    UnsupportedFormat {
        /// The file.
        path: PathBuf,
        /// Its extension.
        extension: String,
    },
    /// A mesh has no triangle, or a coordinate that is not finite.
    #[error("{what}: {why}")]
    BadMesh {
        /// The mesh (file or description).
        what: String,
        /// What is wrong.
        why: String,
    },
    /// The URDF is not well-formed XML or lacks what a URDF must have.
    #[error("{origin}: not a readable URDF: {message}")]
    Urdf {
        /// The file (or `"URDF text"`).
        origin: String,
        /// The parser's message.
        message: String,
    },
    /// A number in the URDF could not be read.
    #[error("link `{link}`: {what} `{text}` is not a list of {count} finite numbers")]
    BadNumber {
        /// The link.
        link: String,
        /// The attribute (`origin xyz`, `mesh scale`, …).
        what: &'static str,
        /// The text found.
        text: String,
        /// How many numbers were expected.
        count: usize,
    },
    /// A `package://` address names a package no given root holds.
    #[error(
        "link `{link}`: `{uri}` is not under any package root (tried {tried}); pass --package-root"
    )]
    UnknownPackage {
        /// The link.
        link: String,
        /// The address.
        uri: String,
        /// The paths tried, comma separated (or `no package root given`).
        tried: String,
    },
    /// Mesh files that do not exist, with no fallback spheres for their links.
    #[error(
        "{} mesh file(s) missing: {}; give the links spheres from another model (--fallback) or add the files",
        .missing.len(),
        .missing.iter().map(|(link, file)| format!("{link}: {file}")).collect::<Vec<_>>().join(", ")
    )]
    MissingMeshes {
        /// Each link and the file it names.
        missing: Vec<(String, String)>,
    },
    /// A tolerance or sphere budget that cannot be honoured.
    #[error("{what} must be {rule}; got {value}")]
    BadOption {
        /// The option.
        what: &'static str,
        /// What it must be.
        rule: &'static str,
        /// The value given.
        value: String,
    },
}
