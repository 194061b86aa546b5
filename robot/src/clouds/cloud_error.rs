//! [`CloudError`]: why a set of points is not a [`PointCloud`](crate::PointCloud).

use thiserror::Error;

/// Why points cannot make a [`PointCloud`](crate::PointCloud): each variant names what is
/// wrong (the point's index for a bad coordinate).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CloudError {
    /// No points: an empty cloud is refused rather than read as an empty scene.
    #[error("the point cloud has no points (an empty cloud would silently be an empty scene)")]
    Empty,
    /// More points than [`PointCloud::MAX_POINTS`](crate::PointCloud::MAX_POINTS).
    #[error(
        "the point cloud has {count} points, more than the cap of {cap} (downsample it, e.g. \
         keep one point per voxel)"
    )]
    TooMany {
        /// How many points were given (or announced by a file's header).
        count: usize,
        /// The cap.
        cap: usize,
    },
    /// A coordinate is NaN or infinite.
    #[error("point {index} of the cloud is not finite: ({}, {}, {})", .point[0], .point[1], .point[2])]
    NotFinite {
        /// The point's index in the cloud as given.
        index: usize,
        /// Its coordinates.
        point: [f32; 3],
    },
    /// A coordinate is beyond ±[`Scene::MAX_LENGTH`](crate::Scene::MAX_LENGTH) (10⁶ m).
    #[error(
        "point {index} of the cloud is out of range: ({}, {}, {}) (coordinates must be within \
         ±1e6 m)",
        .point[0], .point[1], .point[2]
    )]
    OutOfRange {
        /// The point's index in the cloud as given.
        index: usize,
        /// Its coordinates.
        point: [f32; 3],
    },
    /// The points' radius is not a positive, finite length of at most 1 m.
    #[error("the points' radius {radius} m is not in (0, 1] m")]
    Radius {
        /// The radius given.
        radius: f64,
    },
}
