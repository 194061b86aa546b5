//! Cropping a cloud to a ball (the robot's reach) or a box.

use std::time::Instant;

use glam::{DVec3, Vec3};

use super::cloud_input_error::CloudInputError;
use super::filter_report::FilterReport;

/// Keeps the points within `radius` of `center` (the boundary included, distances in `f64`):
/// cropped to the robot's reach around its base, a cloud keeps only what the arm can touch
/// (VAMP culls at 1.19 m around the Panda's first joint). Points beyond the reach cannot
/// collide with the robot, so cropping changes no answer of the checker when the ball is
/// [`reach_ball`](super::reach_ball)'s, widened by the points' radius and the margin.
///
/// # Errors
/// [`CloudInputError::Parameter`] for a centre that is not finite or a radius that is not
/// finite and non-negative.
pub fn crop_to_ball(
    points: &mut Vec<Vec3>,
    center: DVec3,
    radius: f64,
) -> Result<FilterReport, CloudInputError> {
    if !(center.is_finite() && radius.is_finite() && radius >= 0.0) {
        return Err(CloudInputError::Parameter {
            what: "crop ball",
            message: format!(
                "centre {center} and radius {radius} m: a finite centre and a radius ≥ 0"
            ),
        });
    }
    let start = Instant::now();
    let before = points.len();
    let limit = radius * radius;
    points.retain(|p| p.as_dvec3().distance_squared(center) <= limit);
    Ok(FilterReport::since(start, before, points.len()))
}

/// Keeps the points inside the axis-aligned box from `lower` to `upper` (the faces
/// included): a workspace, or a table's top.
///
/// # Errors
/// [`CloudInputError::Parameter`] for corners that are not finite or a `lower` above `upper`
/// on some axis.
pub fn crop_to_box(
    points: &mut Vec<Vec3>,
    lower: DVec3,
    upper: DVec3,
) -> Result<FilterReport, CloudInputError> {
    if !lower.is_finite() || !upper.is_finite() || lower.cmpgt(upper).any() {
        return Err(CloudInputError::Parameter {
            what: "crop box",
            message: format!(
                "corners {lower} and {upper}: finite, the first ≤ the second on every axis"
            ),
        });
    }
    let start = Instant::now();
    let before = points.len();
    points.retain(|p| {
        let p = p.as_dvec3();
        p.cmpge(lower).all() && p.cmple(upper).all()
    });
    Ok(FilterReport::since(start, before, points.len()))
}
