//! Which obstacles each link can reach at all, whatever the configuration: the checker tests a
//! link only against those.
//!
//! # The bound
//! Follow the chain from a link up to the root. Above its topmost moving joint nothing moves,
//! so that joint's frame origin `p` has one place in the world. If every joint on the chain is
//! revolute, every point of the link's spheres stays within `ρ` of `p` in every
//! configuration, `ρ` the lever arm of the link about that joint
//! ([`LeverArms`]: the distance from `p` to the spheres, summed over the
//! chain's offsets, which rotations cannot lengthen). An obstacle farther than `ρ` (plus a
//! slack) from `p` can never touch the link. A link on no moving joint stays where it is, so
//! only the obstacles its bounding sphere meets matter; a link below a prismatic joint keeps
//! every obstacle.

use std::ops::Range;
use std::sync::Arc;

use glam::{DAffine3, Vec3A};
use mit_star_spaces::StateSpace;

use crate::{CloudObstacle, Kinematics, LeverArms, Motion, Obstacle, RobotModel};

/// Slack added to every reach, in metres: much more than the checks' growth (the `f32`
/// margin, tens of micrometres) and the rounding of the reach itself.
const SLACK: f64 = 1e-3;

/// Per entry of `links` (the checker's links with spheres: link index, sphere range, local
/// bounding sphere), the obstacles of `obstacles` it can reach with its spheres grown by
/// `padding` (metres), in their original order, and the clouds of `clouds` with a point's ball
/// it can reach so (as indices); `fk` and `levers` are `robot`'s.
pub(crate) fn reachable_obstacles(
    (robot, fk, levers): (&RobotModel, &Kinematics, &LeverArms),
    links: &[(usize, Range<usize>, Vec3A, f32)],
    (obstacles, clouds): (&[Obstacle], &[Arc<CloudObstacle>]),
    padding: f64,
) -> (Vec<Vec<Obstacle>>, Vec<Vec<usize>>) {
    let frames = robot.links();
    // Any configuration places the fixed frames: the middle of the limits.
    let space = robot.joint_space();
    let q: Vec<f64> = space
        .lower()
        .iter()
        .zip(space.upper())
        .map(|(lo, hi)| {
            if lo.is_finite() && hi.is_finite() {
                0.5 * (lo + hi)
            } else {
                0.0
            }
        })
        .collect();
    let mut poses = vec![DAffine3::IDENTITY; fk.link_count()];
    fk.link_poses_f64(&q, &mut poses);
    links
        .iter()
        .map(
            |&(link, _, center, radius)| -> (Vec<Obstacle>, Vec<usize>) {
                // The topmost revolute joint: its frame and coordinate.
                let mut top = None;
                let mut at = Some(link);
                while let Some(a) = at {
                    match frames[a].motion {
                        Motion::Fixed => {}
                        Motion::Revolute { coordinate, .. } => top = Some((a, coordinate)),
                        Motion::Prismatic { .. } => {
                            return (obstacles.to_vec(), (0..clouds.len()).collect());
                        }
                    }
                    at = frames[a].parent;
                }
                let (p, rho) = match top {
                    Some((a, coordinate)) => (poses[a].translation, levers.lever(link, coordinate)),
                    None => (
                        poses[link].transform_point3(center.as_dvec3()),
                        f64::from(radius),
                    ),
                };
                let rho = rho + padding + SLACK;
                let near = obstacles
                    .iter()
                    .filter(|o| o.distance_f64(p) <= rho)
                    .copied()
                    .collect();
                // The `f32` lower bound (of a centre rounded to `f32`, a slack more for that) is
                // never above the distance: a cloud it puts beyond the reach is out of reach.
                let reach = (rho + SLACK) as f32;
                let touched = (0..clouds.len())
                    .filter(|&c| clouds[c].distance_lower_bound(p.as_vec3(), reach) <= reach)
                    .collect();
                (near, touched)
            },
        )
        .unzip()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{ArmChecker, Scene, Shape};
    use glam::{DQuat, DVec3};
    use mit_star_validity::StateValidity;

    /// A box the arm cannot reach is dropped for every link; one at the base is kept for the
    /// base; the checker answers as without the culling on random configurations.
    #[test]
    fn unreachable_obstacles_are_dropped_and_answers_stay() {
        let robot = &crate::ArmProblem::panda().unwrap();
        let far = Obstacle::new(
            Shape::Cuboid {
                half_extents: DVec3::splat(0.1),
            },
            DVec3::new(3.0, 0.0, 0.5),
            DQuat::IDENTITY,
        );
        let base = Obstacle::new(
            Shape::Sphere { radius: 0.05 },
            DVec3::new(0.0, 0.0, -0.02),
            DQuat::IDENTITY,
        );
        let near = Obstacle::new(
            Shape::Cuboid {
                half_extents: DVec3::new(0.05, 0.3, 0.3),
            },
            DVec3::new(0.45, 0.0, 0.4),
            DQuat::IDENTITY,
        );
        let bounds = robot.link_bounding_spheres();
        let links: Vec<_> = (0..robot.links().len())
            .filter_map(|l| bounds[l].map(|(c, r)| (l, 0..0, c.as_vec3a(), r as f32)))
            .collect();
        let parts = (robot, &Kinematics::new(robot), &LeverArms::new(robot));
        let (kept, _) = reachable_obstacles(parts, &links, (&[far, base, near], &[]), 0.0);
        assert!(
            kept.iter()
                .all(|k| k.iter().all(|o| o.pose() != far.pose()))
        );
        // The base link (fixed) keeps only the sphere it sits on; the hand reaches both.
        let poses = |k: &Vec<Obstacle>| k.iter().map(Obstacle::pose).collect::<Vec<_>>();
        assert_eq!(poses(&kept[0]), vec![base.pose()]);
        assert_eq!(poses(kept.last().unwrap()), vec![base.pose(), near.pose()]);
        let scene = Scene::new(vec![far, near]);
        let checker = ArmChecker::new(robot, &scene);
        let reference = crate::ParryChecker::new(robot, &scene);
        let space = robot.joint_space();
        let mut rng =
            <mit_star_spaces::SeededRng as mit_star_spaces::rand::SeedableRng>::seed_from_u64(3);
        let mut q = vec![0.0; 7];
        let mut invalid = 0;
        for _ in 0..2000 {
            space.sample_uniform(&mut rng, &mut q);
            let fast = checker.is_valid(&q);
            if reference.is_valid_with_margin(&q, 1e-4) == reference.is_valid_with_margin(&q, -1e-4)
            {
                assert_eq!(fast, reference.is_valid(&q), "{q:?}");
            }
            invalid += usize::from(!fast);
        }
        assert!(invalid > 100, "{invalid}");
    }
}
