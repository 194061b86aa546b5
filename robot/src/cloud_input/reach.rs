//! [`reach_ball`]: a ball that holds the whole robot at every configuration, for cropping a
//! cloud to what the robot can touch.

use glam::{DAffine3, DVec3};
use mit_star_spaces::StateSpace;

use crate::{Motion, RobotModel};

/// A ball that holds every collision sphere of `robot` at every configuration within its
/// joint limits: its centre is the origin of the first moving joint (for the Panda,
/// `panda_joint1` at `(0, 0, 0.333)`, where VAMP centres its crop), its radius a bound by the
/// triangle inequality along each chain (each joint's offset, each prismatic joint's longest
/// travel, then each sphere's offset and radius). A point farther than `radius + r` from the
/// centre is farther than `r` from every sphere at every configuration, so
/// [`crop_to_ball`](super::crop_to_ball) with that radius (`r` the points' radius plus the
/// checker's margin) removes no point the checker could ever meet.
///
/// The triangle inequality counts sideways offsets in full, so the bound is loose by the
/// chains' bends: 1.130 m for the Panda, whose farthest sphere found by search reaches
/// 0.995 m (VAMP crops at 1.19 m); 1.52 m for the UR5 against 1.11 m found.
pub fn reach_ball(robot: &RobotModel) -> (DVec3, f64) {
    let links = robot.links();
    let space = robot.joint_space();
    let travel = |motion: Motion| match motion {
        Motion::Prismatic { axis, coordinate } => {
            axis.length()
                * space.lower()[coordinate]
                    .abs()
                    .max(space.upper()[coordinate].abs())
        }
        _ => 0.0,
    };
    // Each link's pose while every joint above it (and its own) is fixed.
    let mut rigid: Vec<Option<DAffine3>> = Vec::with_capacity(links.len());
    let mut center = None;
    for link in links {
        let parent = link.parent.map_or(Some(DAffine3::IDENTITY), |p| rigid[p]);
        if center.is_none() && link.motion != Motion::Fixed {
            center = parent.map(|pose| pose.transform_point3(link.origin.translation));
        }
        rigid.push(match (parent, link.motion) {
            (Some(pose), Motion::Fixed) => Some(pose * link.origin),
            _ => None,
        });
    }
    let center = center.unwrap_or(DVec3::ZERO);
    // How far each link's frame origin can be from the centre.
    let mut bound = vec![0.0_f64; links.len()];
    for (l, link) in links.iter().enumerate() {
        let parent_pose = link.parent.map_or(Some(DAffine3::IDENTITY), |p| rigid[p]);
        let from_parent = match (parent_pose, link.parent) {
            (Some(pose), _) => pose
                .transform_point3(link.origin.translation)
                .distance(center),
            (None, Some(p)) => bound[p] + link.origin.translation.length(),
            (None, None) => link.origin.translation.distance(center),
        };
        bound[l] = from_parent + travel(link.motion);
    }
    let radius = robot
        .spheres()
        .iter()
        .map(|s| match rigid[s.link] {
            Some(pose) => pose.transform_point3(s.center).distance(center) + s.radius,
            None => bound[s.link] + s.center.length() + s.radius,
        })
        .fold(0.0, f64::max);
    (center, radius)
}
