//! [`MotionJudge`]: whether an executed arm motion touched the moving obstacles, proven over
//! time, and whether a path is clear of a scene.

use mit_star_robot::{ArmChecker, MovingScene, RobotModel, Scene};
use mit_star_spaces::{JointSpace, Never};
use mit_star_validity::{EdgeStatus, MotionProgress, StateValidity};

use crate::replanning::timed_path::Piece;

/// Judges executed motion against a [`MovingScene`] continuously in time.
///
/// A timed [`Piece`] of motion is **clear** when the arm's motion over it is certified
/// collision-free (the planners' certified motion check: every configuration of the straight
/// joint-space motion, not only sampled ones, with the `f32` margin) against the scene *swept*
/// over the piece's time interval — every moving obstacle replaced by the box holding all its
/// positions during that interval. Clear against the sweep implies clear of the obstacles at
/// every instant. A piece that cannot be proven clear is halved in time, earliest half first;
/// a piece shorter than `floor` seconds that still cannot be proven clear is a contact at its
/// start time. So a reported contact is a collision, or a near-contact: a clearance smaller
/// than what the arm and the obstacles move in `floor` seconds (at most about 0.3 mm for the
/// Panda at its velocity limits with `floor` = 1e-4 s) plus the checker's `f32` margin
/// (about 25 µm). Self-collision and joint limits are judged by the same checker.
#[derive(Debug)]
pub struct MotionJudge<'a> {
    robot: &'a RobotModel,
    scene: &'a MovingScene,
    space: JointSpace,
    floor: f64,
    checks: u64,
}

impl<'a> MotionJudge<'a> {
    /// A judge of `robot`'s motion among `scene`, splitting time down to `floor` seconds.
    pub fn new(robot: &'a RobotModel, scene: &'a MovingScene, floor: f64) -> Self {
        Self {
            robot,
            scene,
            space: robot.joint_space().clone(),
            floor,
            checks: 0,
        }
    }

    /// How many sweep checks the judge has made.
    pub fn checks(&self) -> u64 {
        self.checks
    }

    /// The earliest time at which the motion `pieces` (in time order) may touch an obstacle,
    /// or `None` if it is proven clear.
    pub fn first_contact(&mut self, pieces: &[Piece]) -> Option<f64> {
        pieces.iter().find_map(|p| self.first_contact_in(p))
    }

    fn first_contact_in(&mut self, piece: &Piece) -> Option<f64> {
        let mut stack = vec![piece.clone()];
        while let Some(p) = stack.pop() {
            self.checks += 1;
            let checker = ArmChecker::new(self.robot, &self.scene.swept(p.t0, p.t1));
            if motion_is_clear(&checker, &self.space, &p.a, &p.b) {
                continue;
            }
            if p.t1 - p.t0 <= self.floor {
                return Some(p.t0);
            }
            let (first, second) = p.halves(&self.space);
            stack.push(second);
            stack.push(first);
        }
        None
    }
}

/// `true` if every edge of `path` is certified clear in `scene` for `robot`.
pub fn path_is_clear(robot: &RobotModel, scene: &Scene, path: &[Vec<f64>]) -> bool {
    let checker = ArmChecker::new(robot, scene);
    let space = robot.joint_space();
    if let [q] = path {
        return checker.is_valid(q);
    }
    path.windows(2)
        .all(|w| motion_is_clear(&checker, space, &w[0], &w[1]))
}

/// `true` if the straight motion `a → b` is certified clear (`a == b`: the configuration is
/// valid).
fn motion_is_clear(checker: &ArmChecker, space: &JointSpace, a: &[f64], b: &[f64]) -> bool {
    if a == b {
        return checker.is_valid(a);
    }
    let mut progress = MotionProgress::default();
    checker.certify_motion(space, a, b, &mut progress, &Never) == Some(EdgeStatus::Valid)
}

#[cfg(test)]
mod tests {
    use glam::DVec3;
    use mit_star_robot::{ArmProblem, MovingObstacle};

    use super::*;

    /// The Panda's ready pose; its hand is near (0.31, 0, 0.49) (the flange near z 0.59).
    const READY: [f64; 7] = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];

    #[test]
    fn an_obstacle_driven_through_the_arm_is_a_contact_at_the_right_time() {
        let robot = ArmProblem::panda().unwrap();
        // A 10 cm block sweeping along y through the hand's place at 0.5 m/s: it reaches the
        // hand's spheres (within about 0.1 m of y = 0) about a second after it starts at y = -0.6.
        let block = MovingObstacle::new(
            "block",
            DVec3::splat(0.05),
            (DVec3::new(0.31, -0.6, 0.5), DVec3::new(0.31, 0.6, 0.5)),
            0.5,
            0.0,
        )
        .unwrap();
        let scene = MovingScene::new(Vec::new(), vec![block]);
        let mut judge = MotionJudge::new(&robot, &scene, 1e-4);
        assert_eq!(judge.first_contact(&[Piece::hold(0.0, 0.5, &READY)]), None);
        let contact = judge
            .first_contact(&[Piece::hold(0.0, 2.0, &READY)])
            .unwrap();
        assert!((0.6..1.2).contains(&contact), "contact at {contact}");
        // The contact time is sharp: just before it the arm is clear.
        assert_eq!(
            judge.first_contact(&[Piece::hold(0.0, contact - 2e-3, &READY)]),
            None
        );
        assert!(judge.checks() > 10);
        // Moving away in time: turning joint 1 by 1.2 rad in the first 0.6 s clears the block.
        let mut away = READY;
        away[0] = 1.2;
        let escape = [
            Piece {
                t0: 0.0,
                t1: 0.6,
                a: READY.to_vec(),
                b: away.to_vec(),
            },
            Piece::hold(0.6, 4.0, &away),
        ];
        assert_eq!(judge.first_contact(&escape), None);
    }

    #[test]
    fn paths_are_judged_against_a_static_scene() {
        let robot = ArmProblem::panda().unwrap();
        let wall = MovingObstacle::new(
            "wall",
            DVec3::new(0.02, 0.3, 0.3),
            (DVec3::new(0.45, 0.0, 0.5), DVec3::new(0.45, 0.0, 0.5)),
            0.0,
            0.0,
        )
        .unwrap();
        let scene = MovingScene::new(Vec::new(), vec![wall]).at(0.0);
        assert!(path_is_clear(&robot, &scene, &[READY.to_vec()]));
        let mut reach = READY;
        reach[1] = 0.6;
        reach[3] = -1.2;
        assert!(!path_is_clear(
            &robot,
            &scene,
            &[READY.to_vec(), reach.to_vec()]
        ));
    }
}
