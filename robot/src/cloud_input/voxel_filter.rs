//! Voxel downsampling: one point per cube of a grid.

use std::time::Instant;

use glam::Vec3;

use super::cell_hash::{CellSet, cell_of};
use super::cloud_input_error::CloudInputError;
use super::filter_report::FilterReport;

/// Keeps one point per voxel (the cubes of side `size` of a grid aligned with the axes, one
/// corner at the origin): the first point of each voxel in the cloud's order, so every kept
/// point is one the sensor saw (PCL's `VoxelGrid` keeps the voxel's centroid instead, which
/// can lie off the surface). Every removed point has a kept point within the voxel's
/// diagonal, `size · √3`. The order of the kept points is kept. One allocation (the set of
/// voxels), none per point.
///
/// ```
/// use glam::Vec3;
/// let mut points = vec![Vec3::new(0.001, 0.0, 0.0), Vec3::new(0.015, 0.01, 0.0), Vec3::new(0.03, 0.0, 0.0)];
/// let report = mit_star_robot::voxel_downsample(&mut points, 0.02)?;
/// assert_eq!(points, [Vec3::new(0.001, 0.0, 0.0), Vec3::new(0.03, 0.0, 0.0)]);
/// assert_eq!((report.before, report.after), (3, 2));
/// # Ok::<(), mit_star_robot::CloudInputError>(())
/// ```
///
/// # Errors
/// [`CloudInputError::Parameter`] for a size that is not finite and positive.
pub fn voxel_downsample(
    points: &mut Vec<Vec3>,
    size: f64,
) -> Result<FilterReport, CloudInputError> {
    if !(size.is_finite() && size > 0.0) {
        return Err(CloudInputError::Parameter {
            what: "voxel size",
            message: format!("{size} m is not a positive length"),
        });
    }
    let start = Instant::now();
    let before = points.len();
    let inverse = 1.0 / size;
    let mut seen = CellSet::with_capacity_and_hasher(before, Default::default());
    points.retain(|&p| seen.insert(cell_of(p, inverse)));
    Ok(FilterReport::since(start, before, points.len()))
}
