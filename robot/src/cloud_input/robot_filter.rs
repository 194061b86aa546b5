//! Removing the points a camera sees on the robot itself.

use std::time::Instant;

use glam::{DAffine3, DVec3, Vec3};

use super::cloud_input_error::CloudInputError;
use super::filter_report::FilterReport;
use crate::{Kinematics, RobotModel};

/// Removes the points within `padding` of the robot's collision spheres at configuration
/// `q`: a point at distance `d` from a sphere's centre of radius `r` goes when
/// `d ≤ r + padding` (`f64` forward kinematics and distances). A depth camera sees the arm;
/// left in the cloud, those points make every configuration near `q` collide, the start
/// included. The padding covers the gap between the sphere model and the real links (a few
/// millimetres to centimetres); too large a padding also removes real obstacles near the
/// arm, which the planner then does not see.
///
/// Points outside the box around every padded sphere are kept after one comparison; the
/// others are tested against each sphere. No allocation per point.
///
/// # Errors
/// [`CloudInputError::Parameter`] for a configuration of the wrong length or with a value
/// that is not finite, or a padding that is not finite and non-negative.
pub fn remove_robot_points(
    points: &mut Vec<Vec3>,
    robot: &RobotModel,
    q: &[f64],
    padding: f64,
) -> Result<FilterReport, CloudInputError> {
    let kinematics = Kinematics::new(robot);
    let dimension = kinematics.dimension();
    if q.len() != dimension || !q.iter().all(|v| v.is_finite()) {
        return Err(CloudInputError::Parameter {
            what: "configuration",
            message: format!(
                "{q:?}: robot `{}` takes {dimension} finite joint values",
                robot.name()
            ),
        });
    }
    if !(padding.is_finite() && padding >= 0.0) {
        return Err(CloudInputError::Parameter {
            what: "padding",
            message: format!("{padding} m is not a length ≥ 0"),
        });
    }
    let start = Instant::now();
    let before = points.len();
    let mut links = vec![DAffine3::IDENTITY; kinematics.link_count()];
    let mut spheres = vec![(DVec3::ZERO, 0.0); kinematics.sphere_count()];
    kinematics.sphere_centers_f64(q, &mut links, &mut spheres);
    // Each sphere's centre and squared reach, and the box around all of them.
    let mut lower = DVec3::INFINITY;
    let mut upper = DVec3::NEG_INFINITY;
    for (center, radius) in &mut spheres {
        let reach = *radius + padding;
        lower = lower.min(*center - reach);
        upper = upper.max(*center + reach);
        *radius = reach * reach;
    }
    points.retain(|p| {
        let p = p.as_dvec3();
        if p.cmplt(lower).any() || p.cmpgt(upper).any() {
            return true;
        }
        spheres
            .iter()
            .all(|&(center, reach_squared)| p.distance_squared(center) > reach_squared)
    });
    Ok(FilterReport::since(start, before, points.len()))
}
