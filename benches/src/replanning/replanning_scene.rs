//! [`ReplanningScene`]: the two scenes of the paper's re-planning experiment (§V-C), built for
//! the Panda: the table, the moving obstacles, the start and the goal.

use std::f64::consts::FRAC_PI_4;

use glam::{DAffine3, DQuat, DVec3};
use mit_star_robot::{ArmProblem, MovingObstacle, MovingScene, Obstacle, RobotModel, Shape};

use crate::error::HarnessError;

/// Which re-planning scene.
///
/// Coordinates are metres in the Panda's base frame (x forward, y to the left, z up; the base
/// at the origin). Both scenes share a table whose top is the plane z = 0, 0.25–0.95 m in
/// front of the base and 1.4 m wide, and a block position on each side of it: the arm travels
/// between a configuration with the hand 0.15 m above the table at (0.5, −0.35) (right, the
/// start) and one at (0.5, +0.35) (left, the goal), pointing down. The obstacles are
/// axis-aligned boxes going back and forth along straight lines at a constant speed; none of
/// them can reach the arm at the start or the goal (a test checks it), so an arm holding
/// there is always safe.
///
/// - **Horizontal** (the paper's "Horizontal-movement" block task): one box 0.12 m × 0.12 m
///   × 0.24 m (x × y × z) between the two blocks, its centre going back and forth along y
///   between −0.12 and +0.12 at x = 0.5, z = 0.17 (5–29 cm above the table), at
///   0.16 m/s (a 3 s period; at time 0 it is at y = 0, going left).
/// - **Vertical** (the "two vertical-movement blocks" task, a narrow space): a ceiling board
///   0.75 m above the table over x 0.30–0.95 and a back wall at x = 0.78 close the space in
///   which the arm works; two plates 0.30 m × 0.06 m × 0.20 m (x × y × z) at y = −0.12 and
///   y = +0.12, spanning x 0.40–0.70, go up and down between centre heights 0.12 and 0.58 m
///   (so each sweeps z 0.02–0.68) at 0.15 m/s (a 6.13 s period): `rising` starts at the
///   bottom going up, `falling` at the top going down. The arm crosses both planes of the
///   plates on every leg: over a low plate, or around their front ends close to its base.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ReplanningScene {
    /// One obstacle moving horizontally across the table.
    Horizontal,
    /// Two obstacles moving vertically in opposite directions in a narrow space.
    Vertical,
}

/// A re-planning scene made concrete: its obstacles and the two configurations the arm
/// travels between.
#[derive(Debug, Clone)]
pub struct ReplanningSetup {
    /// The scene's name (`horizontal`, `vertical`).
    pub name: &'static str,
    /// The robot (the shipped Panda).
    pub robot: RobotModel,
    /// The fixed and moving obstacles.
    pub scene: MovingScene,
    /// The first leg's start (the right block).
    pub start: Vec<f64>,
    /// The first leg's goal (the left block).
    pub goal: Vec<f64>,
}

/// The joint configuration with the hand pointing down, the arm turned by `yaw` about the
/// base, and the shoulder, elbow and wrist at `(q2, q4)` (`q6 = q2 − q4` keeps the hand
/// vertical).
fn pointing_down(yaw: f64, q2: f64, q4: f64) -> Vec<f64> {
    vec![yaw, q2, 0.0, q4, 0.0, q2 - q4, FRAC_PI_4]
}

/// The shoulder and elbow angles that put the grasp point 0.15 m above the table at 0.61 m
/// from the base axis (found by a grid search on the forward kinematics; a test checks it).
const REACH: (f64, f64) = (0.41125, -1.9875);

fn cuboid(center: DVec3, size: DVec3) -> Obstacle {
    Obstacle::new(
        Shape::Cuboid {
            half_extents: size * 0.5,
        },
        center,
        DQuat::IDENTITY,
    )
}

/// The table: top at z = 0.
fn table() -> Obstacle {
    cuboid(DVec3::new(0.6, 0.0, -0.05), DVec3::new(0.7, 1.4, 0.1))
}

impl ReplanningScene {
    /// Both scenes, in the order reports list them.
    pub const ALL: [Self; 2] = [Self::Horizontal, Self::Vertical];

    /// The scene's name.
    pub fn name(self) -> &'static str {
        match self {
            Self::Horizontal => "horizontal",
            Self::Vertical => "vertical",
        }
    }

    /// The scene called `name` (`horizontal`, `vertical`).
    ///
    /// # Errors
    /// [`HarnessError::Usage`] naming the valid scenes.
    pub fn parse(name: &str) -> Result<Self, HarnessError> {
        Self::ALL
            .into_iter()
            .find(|s| s.name() == name.trim())
            .ok_or_else(|| {
                HarnessError::Usage(format!(
                    "unknown re-planning scene `{}`; valid scenes: horizontal, vertical",
                    name.trim()
                ))
            })
    }

    /// The scene with its robot, obstacles, start and goal.
    ///
    /// # Errors
    /// [`HarnessError::Arm`] if the shipped Panda cannot be loaded (not in practice).
    pub fn setup(self) -> Result<ReplanningSetup, HarnessError> {
        let robot = ArmProblem::panda().map_err(|source| HarnessError::Arm {
            name: "panda".to_owned(),
            source,
        })?;
        let yaw = (0.35f64).atan2(0.5);
        let (q2, q4) = REACH;
        let (start, goal) = (pointing_down(-yaw, q2, q4), pointing_down(yaw, q2, q4));
        let moving = |id: &str, size: DVec3, ends: (DVec3, DVec3), speed: f64, offset: f64| {
            MovingObstacle::new(id, size * 0.5, ends, speed, offset)
                .expect("the scenes' obstacles are valid (tested)")
        };
        let scene = match self {
            Self::Horizontal => MovingScene::new(
                vec![table()],
                vec![moving(
                    "slider",
                    DVec3::new(0.12, 0.12, 0.24),
                    (DVec3::new(0.5, -0.12, 0.17), DVec3::new(0.5, 0.12, 0.17)),
                    0.16,
                    0.75,
                )],
            ),
            Self::Vertical => {
                let plate = DVec3::new(0.3, 0.06, 0.2);
                let (low, high, speed) = (0.12, 0.58, 0.15);
                let line = |y: f64| (DVec3::new(0.55, y, low), DVec3::new(0.55, y, high));
                let period = 2.0 * (high - low) / speed;
                MovingScene::new(
                    vec![
                        table(),
                        cuboid(DVec3::new(0.625, 0.0, 0.76), DVec3::new(0.65, 1.4, 0.02)),
                        cuboid(DVec3::new(0.79, 0.0, 0.375), DVec3::new(0.02, 1.4, 0.75)),
                    ],
                    vec![
                        moving("rising", plate, line(-0.12), speed, 0.0),
                        moving("falling", plate, line(0.12), speed, period / 2.0),
                    ],
                )
            }
        };
        Ok(ReplanningSetup {
            name: self.name(),
            robot,
            scene,
            start,
            goal,
        })
    }
}

/// Where the grasp point (`panda_grasptarget`, between the fingertips; the last link if the
/// model has none) of `robot` is at `q`.
pub fn hand_position(robot: &RobotModel, q: &[f64]) -> DVec3 {
    let links = robot.links();
    let hand = robot
        .link_index("panda_grasptarget")
        .unwrap_or(links.len().saturating_sub(1));
    let mut poses = vec![DAffine3::IDENTITY; links.len()];
    mit_star_robot::Kinematics::new(robot).link_poses_f64(q, &mut poses);
    poses[hand].translation
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::replanning::motion_judge::path_is_clear;

    #[test]
    fn the_hand_is_above_the_blocks_and_the_ends_are_always_safe() {
        for scene in ReplanningScene::ALL {
            let setup = scene.setup().unwrap();
            for (q, y) in [(&setup.start, -0.35), (&setup.goal, 0.35)] {
                let hand = hand_position(&setup.robot, q);
                assert!((hand - DVec3::new(0.5, y, 0.15)).length() < 0.01, "{hand}");
                // Clear of every obstacle over a whole period of the motion.
                let swept = setup.scene.swept(0.0, 10.0);
                assert!(
                    path_is_clear(&setup.robot, &swept, std::slice::from_ref(q)),
                    "{}",
                    scene.name()
                );
            }
            assert_eq!(ReplanningScene::parse(scene.name()).unwrap(), scene);
        }
        assert!(ReplanningScene::parse("diagonal").is_err());
    }

    #[test]
    fn the_straight_motion_meets_the_moving_obstacles() {
        // Not a trivial scene: the straight motion from start to goal is blocked by the
        // obstacles' sweep, but free of the fixed obstacles.
        for scene in ReplanningScene::ALL {
            let setup = scene.setup().unwrap();
            let straight = [setup.start.clone(), setup.goal.clone()];
            let fixed = mit_star_robot::Scene::new(setup.scene.fixed().to_vec());
            assert!(
                path_is_clear(&setup.robot, &fixed, &straight),
                "{}",
                scene.name()
            );
            let swept = setup.scene.swept(0.0, 10.0);
            assert!(
                !path_is_clear(&setup.robot, &swept, &straight),
                "{}",
                scene.name()
            );
        }
    }
}
