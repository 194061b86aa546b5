//! [`PointCloud`]: validated points, each the centre of a small ball.

use glam::Vec3;

use crate::CloudError;

/// A point cloud as an obstacle: points in the robot's base frame (metres, `f32`, contiguous),
/// each the centre of a ball of the same [radius](Self::radius) (by default
/// [`DEFAULT_RADIUS`](Self::DEFAULT_RADIUS), 2.5 mm, as VAMP's point clouds).
///
/// Validated when built: at least one point, at most [`MAX_POINTS`](Self::MAX_POINTS), every
/// coordinate finite and within ±10⁶ m; the radius in (0, 1] m.
///
/// ```
/// use glam::Vec3;
/// use mit_star_robot::{CloudError, PointCloud};
/// let cloud = PointCloud::new(vec![Vec3::new(0.5, 0.0, 0.2), Vec3::new(0.5, 0.1, 0.2)])?
///     .with_radius(0.005)?;
/// assert_eq!(cloud.len(), 2);
/// assert_eq!(cloud.radius(), 0.005);
/// assert_eq!(PointCloud::new(vec![]), Err(CloudError::Empty));
/// assert!(matches!(
///     PointCloud::new(vec![Vec3::ZERO, Vec3::new(f32::NAN, 0.0, 0.0)]),
///     Err(CloudError::NotFinite { index: 1, .. })
/// ));
/// assert!(PointCloud::check_count(1_000_000_000).is_err());
/// # Ok::<(), CloudError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct PointCloud {
    points: Vec<Vec3>,
    radius: f64,
}

impl PointCloud {
    /// The points' radius unless set: 2.5 mm (VAMP's `add_pointcloud(…, 0.0025)`).
    pub const DEFAULT_RADIUS: f64 = 0.0025;

    /// The most points a cloud may hold: 2²⁴ = 16 777 216. The checker's structure takes
    /// about 30 bytes a point (half a gigabyte at the cap); a denser cloud is a sensor's raw
    /// output and wants downsampling (a 2 cm voxel grid leaves a few thousand points of a
    /// table scene). Readers call [`check_count`](Self::check_count) with a header's count
    /// before they allocate.
    pub const MAX_POINTS: usize = 1 << 24;

    /// The largest radius accepted, in metres.
    pub const MAX_RADIUS: f64 = 1.0;

    /// A cloud of `points` (kept as given, no copy) with the default radius.
    ///
    /// # Errors
    /// [`CloudError::Empty`], [`CloudError::TooMany`], and [`CloudError::NotFinite`] or
    /// [`CloudError::OutOfRange`] naming the first bad point.
    pub fn new(points: Vec<Vec3>) -> Result<Self, CloudError> {
        if points.is_empty() {
            return Err(CloudError::Empty);
        }
        Self::check_count(points.len())?;
        let limit = crate::Scene::MAX_LENGTH as f32;
        for (index, p) in points.iter().enumerate() {
            if !p.is_finite() {
                return Err(CloudError::NotFinite {
                    index,
                    point: p.to_array(),
                });
            }
            if p.abs().max_element() > limit {
                return Err(CloudError::OutOfRange {
                    index,
                    point: p.to_array(),
                });
            }
        }
        Ok(Self {
            points,
            radius: Self::DEFAULT_RADIUS,
        })
    }

    /// Refuses a count above [`MAX_POINTS`](Self::MAX_POINTS) (and a count of zero): for
    /// readers, before they allocate for a file's announced points.
    ///
    /// # Errors
    /// [`CloudError::TooMany`] or [`CloudError::Empty`].
    pub fn check_count(count: usize) -> Result<(), CloudError> {
        if count == 0 {
            return Err(CloudError::Empty);
        }
        if count > Self::MAX_POINTS {
            return Err(CloudError::TooMany {
                count,
                cap: Self::MAX_POINTS,
            });
        }
        Ok(())
    }

    /// The same cloud with points of `radius` metres.
    ///
    /// # Errors
    /// [`CloudError::Radius`] unless `radius` is in (0, [`MAX_RADIUS`](Self::MAX_RADIUS)].
    pub fn with_radius(mut self, radius: f64) -> Result<Self, CloudError> {
        if !(radius > 0.0 && radius <= Self::MAX_RADIUS) {
            return Err(CloudError::Radius { radius });
        }
        self.radius = radius;
        Ok(self)
    }

    /// The points, as given.
    pub fn points(&self) -> &[Vec3] {
        &self.points
    }

    /// The radius of every point's ball, metres.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// How many points (never 0).
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Always `false`: a cloud has at least one point.
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The points, giving the vector back.
    pub fn into_points(self) -> Vec<Vec3> {
        self.points
    }
}
