//! [`InputCloud`]: points read or sampled, with where they came from; [`read_cloud`] and
//! [`parse_cloud`], which pick the reader by format.

use std::fmt;
use std::path::{Path, PathBuf};

use glam::Vec3;

use super::cloud_input_error::CloudInputError;

/// The most points a cloud may have, from a file's header or a sampler: 2²⁴ = 16 777 216
/// (200 MB of `f32` coordinates), the most a [`PointCloud`](crate::PointCloud) holds. A header
/// declaring more is refused before anything is allocated; a depth camera gives about 300 000
/// points a frame, VAMP's benchmark clouds 10⁴–10⁵.
pub const MAX_CLOUD_POINTS: usize = crate::PointCloud::MAX_POINTS;

/// The largest point cloud file read: 1 GiB (an ASCII PLY of [`MAX_CLOUD_POINTS`] points is
/// about 600 MB). Larger files are refused without being read whole.
pub const MAX_CLOUD_FILE_BYTES: u64 = 1 << 30;

/// A point cloud file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CloudFormat {
    /// Stanford PLY, ASCII or binary (little or big endian).
    Ply,
    /// PCL's PCD, ASCII, binary or binary_compressed.
    Pcd,
    /// NumPy's `.npy`: an N×3 array of `float32` or `float64`.
    Npy,
}

impl CloudFormat {
    /// The format a file's extension names (`.ply`, `.pcd`, `.npy`, any case).
    pub fn from_path(path: &Path) -> Option<Self> {
        let extension = path.extension()?.to_string_lossy().to_lowercase();
        match extension.as_str() {
            "ply" => Some(Self::Ply),
            "pcd" => Some(Self::Pcd),
            "npy" => Some(Self::Npy),
            _ => None,
        }
    }
}

impl fmt::Display for CloudFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Ply => "PLY",
            Self::Pcd => "PCD",
            Self::Npy => "npy",
        })
    }
}

/// Where an [`InputCloud`]'s points came from.
#[derive(Debug, Clone, PartialEq)]
pub enum CloudOrigin {
    /// A file.
    File {
        /// The file.
        path: PathBuf,
        /// Its format.
        format: CloudFormat,
    },
    /// Bytes of a file read elsewhere ([`parse_cloud`]).
    Bytes {
        /// The name given to them.
        name: String,
        /// Their format.
        format: CloudFormat,
    },
    /// Coordinates handed over in memory ([`InputCloud::from_xyz`]): a numpy array, a
    /// camera driver's buffer.
    Array {
        /// The name given to them.
        name: String,
    },
    /// Sampled on the surfaces of a scene's obstacles
    /// ([`sample_surfaces`](super::sample_surfaces)).
    Sampled {
        /// How many obstacles were sampled.
        obstacles: usize,
        /// Points per obstacle.
        per_obstacle: usize,
        /// The seed of the generator.
        seed: u64,
    },
}

impl fmt::Display for CloudOrigin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::File { path, format } => write!(f, "{format} file `{}`", path.display()),
            Self::Bytes { name, format } => write!(f, "{format} data `{name}`"),
            Self::Array { name } => write!(f, "array `{name}`"),
            Self::Sampled {
                obstacles,
                per_obstacle,
                seed,
            } => write!(
                f,
                "{per_obstacle} points sampled on each of {obstacles} obstacles (seed {seed})"
            ),
        }
    }
}

/// A point cloud as read or sampled: points in one contiguous `f32` array, where they came
/// from, and how many points the reader dropped for NaN or infinite coordinates.
///
/// **Non-finite points are dropped and counted**, as PCL does for unorganised clouds (a depth
/// camera marks pixels without a return with NaN); a cloud left with no point is an error
/// ([`CloudInputError::Empty`]), never an empty scene.
#[derive(Debug, Clone, PartialEq)]
pub struct InputCloud {
    /// The points, in the frame they were given in.
    pub points: Vec<Vec3>,
    /// Where they came from.
    pub origin: CloudOrigin,
    /// How many points were dropped for a NaN or infinite coordinate (an `f64` coordinate
    /// beyond `f32`'s range counts as infinite).
    pub dropped_non_finite: usize,
}

impl InputCloud {
    /// The number of points.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// `true` if there is no point (never for a cloud a reader returns).
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// A cloud from coordinates in memory, `x y z` after one another (a C-ordered N×3
    /// `float32` or `float64` numpy array's buffer), under the readers' rules: points with a
    /// NaN or infinite coordinate dropped and counted, at most [`MAX_CLOUD_POINTS`], none left
    /// an error. `name` names the array in errors.
    ///
    /// ```
    /// let cloud = mit_star_robot::InputCloud::from_xyz("camera", &[0.0_f32, 1.0, 2.0, f32::NAN, 0.0, 0.0])?;
    /// assert_eq!((cloud.len(), cloud.dropped_non_finite), (1, 1));
    /// assert!(mit_star_robot::InputCloud::from_xyz("pairs", &[0.0_f64, 1.0]).is_err());
    /// # Ok::<(), mit_star_robot::CloudInputError>(())
    /// ```
    ///
    /// # Errors
    /// [`CloudInputError::Parameter`] for a length that is not a multiple of 3 or more than
    /// [`MAX_CLOUD_POINTS`] points; [`CloudInputError::Empty`] if no point is left.
    pub fn from_xyz<T: Copy + Into<f64>>(name: &str, xyz: &[T]) -> Result<Self, CloudInputError> {
        if !xyz.len().is_multiple_of(3) || xyz.len() / 3 > MAX_CLOUD_POINTS {
            return Err(CloudInputError::Parameter {
                what: "point coordinates",
                message: format!(
                    "array `{name}` holds {} values: x y z for at most {MAX_CLOUD_POINTS} points",
                    xyz.len()
                ),
            });
        }
        let mut sink = PointSink::with_capacity(xyz.len() / 3);
        for p in xyz.chunks_exact(3) {
            sink.push(p[0].into(), p[1].into(), p[2].into());
        }
        sink.finish(
            CloudOrigin::Array {
                name: name.to_owned(),
            },
            name,
        )
    }
}

/// Reads the point cloud file `path`, its format told by its extension (`.ply`, `.pcd`,
/// `.npy`, any case).
///
/// ```
/// use glam::Vec3;
/// let dir = std::env::temp_dir().join(format!("read-cloud-doc-{}", std::process::id()));
/// std::fs::create_dir_all(&dir)?;
/// let file = dir.join("two.ply");
/// let points = [Vec3::new(0.1, 0.2, 0.3), Vec3::new(-1.0, 0.0, 2.5)];
/// mit_star_robot::write_ply(&file, &points, mit_star_robot::PlyEncoding::BinaryLittleEndian)?;
/// let cloud = mit_star_robot::read_cloud(&file)?;
/// assert_eq!(cloud.points, points);
/// # std::fs::remove_dir_all(&dir)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`CloudInputError`] naming the file and what is wrong with it.
pub fn read_cloud(path: &Path) -> Result<InputCloud, CloudInputError> {
    let format = CloudFormat::from_path(path).ok_or_else(|| CloudInputError::UnknownFormat {
        path: path.to_owned(),
        extension: path
            .extension()
            .map(|e| e.to_string_lossy().to_lowercase())
            .unwrap_or_default(),
    })?;
    let bytes =
        mit_star_problems::read_bounded_bytes(path, MAX_CLOUD_FILE_BYTES, "point cloud file")
            .map_err(|e| CloudInputError::Io {
                path: path.to_owned(),
                source: e.into(),
            })?;
    let origin = path.display().to_string();
    let sink = parse_with(&bytes, format, &origin)?;
    sink.finish(
        CloudOrigin::File {
            path: path.to_owned(),
            format,
        },
        &origin,
    )
}

/// Parses the bytes of a point cloud file of `format`; `name` names them in errors and in
/// the cloud's [`CloudOrigin::Bytes`].
///
/// # Errors
/// [`CloudInputError`] naming `name` and what is wrong.
pub fn parse_cloud(
    bytes: &[u8],
    format: CloudFormat,
    name: &str,
) -> Result<InputCloud, CloudInputError> {
    parse_with(bytes, format, name)?.finish(
        CloudOrigin::Bytes {
            name: name.to_owned(),
            format,
        },
        name,
    )
}

fn parse_with(
    bytes: &[u8],
    format: CloudFormat,
    origin: &str,
) -> Result<PointSink, CloudInputError> {
    match format {
        CloudFormat::Ply => super::ply::parse_ply(bytes, origin),
        CloudFormat::Pcd => super::pcd::parse_pcd(bytes, origin),
        CloudFormat::Npy => super::npy::parse_npy(bytes, origin),
    }
}

/// The points a reader collects: finite ones kept in `f32`, the others counted.
#[derive(Debug)]
pub(super) struct PointSink {
    points: Vec<Vec3>,
    dropped: usize,
}

impl PointSink {
    /// An empty sink with room for `capacity` points (the caller has checked the count
    /// against [`MAX_CLOUD_POINTS`] and the data's size).
    pub(super) fn with_capacity(capacity: usize) -> Self {
        Self {
            points: Vec::with_capacity(capacity),
            dropped: 0,
        }
    }

    /// Adds the point, or counts it as dropped if a coordinate is not finite in `f32`.
    #[inline]
    pub(super) fn push(&mut self, x: f64, y: f64, z: f64) {
        let p = Vec3::new(x as f32, y as f32, z as f32);
        if p.is_finite() {
            self.points.push(p);
        } else {
            self.dropped += 1;
        }
    }

    /// The cloud, or [`CloudInputError::Empty`] if no point is left.
    pub(super) fn finish(
        self,
        origin: CloudOrigin,
        name: &str,
    ) -> Result<InputCloud, CloudInputError> {
        if self.points.is_empty() {
            return Err(CloudInputError::Empty {
                origin: name.to_owned(),
                dropped: self.dropped,
            });
        }
        Ok(InputCloud {
            points: self.points,
            origin,
            dropped_non_finite: self.dropped,
        })
    }
}

/// Checks a header's point count against [`MAX_CLOUD_POINTS`].
pub(super) fn check_count(
    declared: u64,
    origin: &str,
    format: CloudFormat,
) -> Result<usize, CloudInputError> {
    usize::try_from(declared)
        .ok()
        .filter(|&n| n <= MAX_CLOUD_POINTS)
        .ok_or_else(|| CloudInputError::TooManyPoints {
            origin: origin.to_owned(),
            format,
            declared,
            limit: MAX_CLOUD_POINTS,
        })
}
