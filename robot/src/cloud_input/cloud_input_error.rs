//! [`CloudInputError`]: why a point cloud could not be read, sampled, moved or filtered.

use std::path::PathBuf;

use thiserror::Error;

use super::input_cloud::CloudFormat;

/// Why a point cloud could not be read, sampled, moved or filtered. A file's errors name the
/// file (`origin`: its path, or the name given to bytes read from elsewhere) and its format.
#[derive(Debug, Error)]
pub enum CloudInputError {
    /// The file could not be read: missing, unreadable, not a regular file (a device such as
    /// `/dev/zero`, a pipe, a folder) or larger than
    /// [`MAX_CLOUD_FILE_BYTES`](super::MAX_CLOUD_FILE_BYTES).
    #[error("cannot read point cloud `{}`: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The reason (a [`mit_star_problems::BoundedReadError`] inside for a device or a size).
        source: std::io::Error,
    },
    /// The file's extension names no format this crate reads.
    #[error(
        "`{}`: cannot tell the point cloud format from the extension `{extension}` (use .ply, .pcd or .npy)",
        path.display()
    )]
    UnknownFormat {
        /// The file.
        path: PathBuf,
        /// Its extension, lower case (empty if none).
        extension: String,
    },
    /// The header is not a header of this format (a missing magic word, a line it cannot
    /// parse, a count that is not a number).
    #[error("{origin}: not a valid {format} file: {message}")]
    Header {
        /// The file.
        origin: String,
        /// Its format.
        format: CloudFormat,
        /// What is wrong.
        message: String,
    },
    /// A field (PLY property, PCD field, npy dtype or shape) of a type or shape this reader
    /// does not know, or one the coordinates cannot be read from.
    #[error("{origin}: {format} field `{field}`: {message}")]
    UnsupportedField {
        /// The file.
        origin: String,
        /// Its format.
        format: CloudFormat,
        /// The field's name (`x`, `rgb`, `descr`).
        field: String,
        /// What is wrong with it.
        message: String,
    },
    /// The header declares more points than [`MAX_CLOUD_POINTS`](super::MAX_CLOUD_POINTS):
    /// refused before anything is allocated.
    #[error(
        "{origin}: the {format} header declares {declared} points, more than {limit}, the most a cloud may have"
    )]
    TooManyPoints {
        /// The file.
        origin: String,
        /// Its format.
        format: CloudFormat,
        /// The count the header gives.
        declared: u64,
        /// [`MAX_CLOUD_POINTS`](super::MAX_CLOUD_POINTS).
        limit: usize,
    },
    /// The data ends before the points the header declares (a truncated file, or a header
    /// that claims more points than the file holds).
    #[error("{origin}: the {format} header declares {declared} points, but the data {found}")]
    Truncated {
        /// The file.
        origin: String,
        /// Its format.
        format: CloudFormat,
        /// The count the header gives.
        declared: u64,
        /// What the data holds (`holds 12 bytes of the 2400 needed`, `ends after 3 rows`).
        found: String,
    },
    /// There is more data than the header declares (a header that claims fewer points than
    /// the file holds): refused rather than silently dropping points.
    #[error("{origin}: the {format} header declares {declared} points, but {extra} follow them")]
    TrailingData {
        /// The file.
        origin: String,
        /// Its format.
        format: CloudFormat,
        /// The count the header gives.
        declared: u64,
        /// What follows (`5 more rows`, `24 more bytes`).
        extra: String,
    },
    /// A row or value of the data cannot be read (ASCII: a word that is not a number, a row
    /// with too few values; compressed PCD: a corrupt stream).
    #[error("{origin}: {format} data, {location}: {message}")]
    Data {
        /// The file.
        origin: String,
        /// Its format.
        format: CloudFormat,
        /// Where (`row 12`, `compressed block`).
        location: String,
        /// What is wrong.
        message: String,
    },
    /// The cloud holds no point with finite coordinates: an empty file, or every point NaN or
    /// infinite. A scene is never silently left without its obstacles.
    #[error(
        "{origin}: the point cloud is empty ({dropped} points with NaN or infinite coordinates dropped)"
    )]
    Empty {
        /// The file, or what the cloud came from.
        origin: String,
        /// How many points were dropped for non-finite coordinates.
        dropped: usize,
    },
    /// A parameter of a transform, a sampler or a filter that cannot be used (a voxel size
    /// ≤ 0, a rotation that is not finite, a configuration of the wrong length).
    #[error("{what}: {message}")]
    Parameter {
        /// The parameter (`voxel size`, `sensor pose`, `configuration`).
        what: &'static str,
        /// What is wrong with it.
        message: String,
    },
}
