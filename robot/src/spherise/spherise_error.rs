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
    /// A mesh file is not a readable OBJ or COLLADA file (the reader's message).
    #[error("`{}`: not a readable {format} mesh: {message}", path.display())]
    Mesh {
        /// The file.
        path: PathBuf,
        /// The format it was read as (`OBJ`, `COLLADA`).
        format: &'static str,
        /// What is wrong with it.
        message: String,
    },
    /// A mesh file is a Git LFS pointer: the repository was cloned without `git lfs pull`.
    #[error(
        "`{}`: a Git LFS pointer, not the mesh (run `git lfs pull` in its repository, or give \
         the link spheres from another model with --fallback)",
        path.display()
    )]
    LfsPointer {
        /// The file.
        path: PathBuf,
    },
    /// A mesh file's format is not one this reader knows (STL, OBJ and COLLADA are read).
    #[error(
        "`{}`: mesh format `{extension}` is not supported (STL, OBJ and COLLADA .dae are)",
        path.display()
    )]
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
    /// Mesh files that do not exist or cannot be read (a Git LFS pointer, a corrupt file, an
    /// unsupported format), with no fallback spheres for their links.
    #[error(
        "{} mesh file(s) missing or unreadable: {}; {}",
        .missing.len(),
        .missing.iter().map(|(link, file)| format!("{link}: {file}")).collect::<Vec<_>>().join(", "),
        if *.fallback_given {
            "the fallback URDF has no spheres for these links: add them to it, or repair the files"
        } else {
            "give the links spheres from another model (--fallback) or add the files"
        }
    )]
    MissingMeshes {
        /// Each link and the file it names, with why it is unusable when it exists
        /// (`file (a Git LFS pointer)`).
        missing: Vec<(String, String)>,
        /// Whether a fallback URDF was given (it lacks spheres for these links).
        fallback_given: bool,
    },
    /// A cover would take more grid cells than the cap: a tolerance too fine for the mesh's
    /// size, or a scale that makes the mesh huge. Refused before any work.
    #[error(
        "{what}: a mesh {extent:.3e} m across at a tolerance of {tolerance:e} m needs about \
         {cells:.1e} grid cells (at most {cap}): raise --tolerance or check the mesh's scale"
    )]
    TooMuchWork {
        /// The mesh (link).
        what: String,
        /// The mesh's largest extent, in metres.
        extent: f64,
        /// The tolerance asked.
        tolerance: f64,
        /// The estimated cells.
        cells: f64,
        /// The cap ([`MAX_COVER_CELLS`](crate::spherise::MAX_COVER_CELLS)).
        cap: usize,
    },
    /// A stop was asked for (SIGINT or SIGTERM) before the cover was finished.
    #[error("stopped before the cover was finished (SIGINT or SIGTERM)")]
    Stopped,
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
