//! [`PoseGoalSpec`]: a pose of a robot's link as the goal of an arm problem, as the command
//! line (`plan --goal-pose`) and experiment files (`[problems.pose_goal]`) give it.

use std::sync::Arc;

use glam::{DAffine3, DQuat, DVec3};
use mit_star_problems::PlanningProblem;
use mit_star_robot::{
    ArmProblem, IkSolver, OrientationTolerance, PoseGoal, PoseTarget, PositionTolerance,
};
use serde::{Deserialize, Serialize};

use crate::definition::pose_goal_source::PoseGoalSource;
use crate::error::HarnessError;

/// A link's pose as the goal of an arm problem, each value written as on the command line.
///
/// ```toml
/// [problems.pose_goal]
/// link = "panda_hand"
/// pose = "goal"                    # or "x,y,z,qx,qy,qz,qw" in the robot's root frame
/// tool = "0,0,0.1"                 # optional: a frame fixed to the link
/// position_tolerance = "0.005"     # optional: a ball radius, or "x,y,z" box half-extents
/// orientation_tolerance = "cone:z:0.1"  # optional: exact, free, cone:AXIS:ANGLE, axis:AXIS
/// ik_goals = 8                     # optional: the most goal configurations drawn
/// ik_initial_goals = 1             # optional: those drawn before planning starts
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PoseGoalSpec {
    /// The link whose pose is the goal.
    pub link: String,
    /// `x,y,z,qx,qy,qz,qw`, or `goal`: the pose the problem's goal configuration gives it.
    pub pose: String,
    /// A frame fixed to the link whose pose is the goal instead: `x,y,z[,qx,qy,qz,qw]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tool: Option<String>,
    /// `R` (a ball) or `X,Y,Z` (a box's half-extents); exact without it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub position_tolerance: Option<String>,
    /// `exact`, `free`, `cone:AXIS:ANGLE` or `axis:AXIS`; exact without it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub orientation_tolerance: Option<String>,
    /// The most goal configurations inverse kinematics supplies while planning.
    #[serde(default = "default_ik_goals")]
    pub ik_goals: usize,
    /// The goal configurations drawn before planning starts (at most `ik_goals`).
    #[serde(default = "default_ik_initial_goals")]
    pub ik_initial_goals: usize,
}

/// Eight goal configurations: enough for a redundant arm's several postures.
pub(crate) fn default_ik_goals() -> usize {
    8
}

/// One goal configuration before planning: the planner starts as soon as one is known.
pub(crate) fn default_ik_initial_goals() -> usize {
    1
}

impl PoseGoalSpec {
    /// Checks every value (before any run), naming the first one wrong.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] for malformed values.
    pub fn check(&self) -> Result<(), HarnessError> {
        if self.pose != "goal" {
            parse_pose("pose", &self.pose, false)?;
        }
        if let Some(tool) = &self.tool {
            parse_pose("tool", tool, true)?;
        }
        if let Some(text) = &self.position_tolerance {
            parse_position_tolerance(text)?;
        }
        if let Some(text) = &self.orientation_tolerance {
            parse_orientation_tolerance(text)?;
        }
        if self.ik_goals == 0 {
            return Err(HarnessError::Usage(
                "ik_goals (--ik-goals) must be at least 1".into(),
            ));
        }
        if self.ik_initial_goals == 0 || self.ik_initial_goals > self.ik_goals {
            return Err(HarnessError::Usage(format!(
                "ik_initial_goals (--ik-initial-goals) must be between 1 and ik_goals ({}); it is {}",
                self.ik_goals, self.ik_initial_goals
            )));
        }
        Ok(())
    }

    /// The goal region for `arm`: its inverse kinematics seeded with `seed`.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] for malformed values, [`HarnessError::PoseGoal`] for a link
    /// the robot lacks or a target the solver refuses (a quaternion of norm 0, a negative
    /// tolerance).
    pub fn source(&self, arm: &Arc<ArmProblem>, seed: u64) -> Result<PoseGoalSource, HarnessError> {
        self.check()?;
        let mut solver = IkSolver::new(arm.robot(), &self.link)?.seed(seed);
        if let Some(tool) = &self.tool {
            solver = solver.tool(parse_pose("tool", tool, true)?)?;
        }
        let target_pose = if self.pose == "goal" {
            solver.frame_pose(&arm.goals()[0])?
        } else {
            parse_pose("pose", &self.pose, false)?
        };
        let mut target = PoseTarget::from_pose(&target_pose)?;
        if let Some(text) = &self.position_tolerance {
            target = target.with_position_tolerance(parse_position_tolerance(text)?)?;
        }
        if let Some(text) = &self.orientation_tolerance {
            target = target.with_orientation_tolerance(parse_orientation_tolerance(text)?)?;
        }
        let goal = PoseGoal::new(solver, target).with_start(arm.start())?;
        Ok(PoseGoalSource::new(
            goal,
            Arc::clone(arm),
            (self.ik_initial_goals, self.ik_goals),
        ))
    }
}

/// `x,y,z` (with `rotation_optional`) or `x,y,z,qx,qy,qz,qw`.
pub(crate) fn parse_pose(
    flag: &str,
    text: &str,
    rotation_optional: bool,
) -> Result<DAffine3, HarnessError> {
    let values = numbers(flag, text)?;
    let usage = || {
        HarnessError::Usage(format!(
            "{flag} takes {}x,y,z,qx,qy,qz,qw; got `{text}`",
            if rotation_optional { "x,y,z or " } else { "" }
        ))
    };
    let rotation = match values.len() {
        3 if rotation_optional => DQuat::IDENTITY,
        7 => DQuat::from_xyzw(values[3], values[4], values[5], values[6]),
        _ => return Err(usage()),
    };
    let length = rotation.length();
    if !(length.is_finite() && length > 1e-9) {
        return Err(HarnessError::Usage(format!(
            "{flag}: the quaternion ({}, {}, {}, {}) has norm {length}; give a unit quaternion",
            rotation.x, rotation.y, rotation.z, rotation.w
        )));
    }
    let translation = DVec3::new(values[0], values[1], values[2]);
    Ok(DAffine3::from_rotation_translation(
        rotation / length,
        translation,
    ))
}

fn parse_position_tolerance(text: &str) -> Result<PositionTolerance, HarnessError> {
    let values = numbers("--position-tolerance", text)?;
    match values[..] {
        [radius] => Ok(PositionTolerance::Ball { radius }),
        [x, y, z] => Ok(PositionTolerance::Box {
            half_extents: DVec3::new(x, y, z),
        }),
        _ => Err(HarnessError::Usage(format!(
            "--position-tolerance takes R or X,Y,Z; got `{text}`"
        ))),
    }
}

fn parse_orientation_tolerance(text: &str) -> Result<OrientationTolerance, HarnessError> {
    let usage = || {
        HarnessError::Usage(format!(
            "--orientation-tolerance takes exact, free, cone:AXIS:ANGLE or axis:AXIS (AXIS: x, y, z or a;b;c); got `{text}`"
        ))
    };
    let parts: Vec<&str> = text.split(':').collect();
    match parts[..] {
        ["exact"] => Ok(OrientationTolerance::Exact),
        ["free"] => Ok(OrientationTolerance::Free),
        ["axis", axis] => Ok(OrientationTolerance::FreeAxis {
            axis: parse_axis(axis).ok_or_else(usage)?,
        }),
        ["cone", axis, angle] => Ok(OrientationTolerance::Cone {
            axis: parse_axis(axis).ok_or_else(usage)?,
            half_angle: angle.trim().parse().map_err(|_| usage())?,
        }),
        _ => Err(usage()),
    }
}

fn parse_axis(text: &str) -> Option<DVec3> {
    match text.trim() {
        "x" => Some(DVec3::X),
        "y" => Some(DVec3::Y),
        "z" => Some(DVec3::Z),
        other => {
            let v: Vec<f64> = other
                .split(';')
                .map(|s| s.trim().parse().ok())
                .collect::<Option<_>>()?;
            (v.len() == 3).then(|| DVec3::new(v[0], v[1], v[2]))
        }
    }
}

/// Comma-separated finite numbers.
fn numbers(flag: &str, text: &str) -> Result<Vec<f64>, HarnessError> {
    text.split(',')
        .map(|s| {
            s.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    HarnessError::Usage(format!(
                        "{flag}: `{}` is not a finite number (in `{text}`)",
                        s.trim()
                    ))
                })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_parse_and_bad_ones_are_named() {
        let pose = parse_pose("--goal-pose", "0.5,0,0.4,1,0,0,0", false).expect("a pose");
        assert!((pose.translation - DVec3::new(0.5, 0.0, 0.4)).length() < 1e-12);
        assert!(parse_pose("--tool", "0,0,0.1", true).is_ok());
        let e = parse_pose("--goal-pose", "0.5,0,0.4", false).expect_err("no rotation");
        assert!(e.to_string().contains("x,y,z,qx,qy,qz,qw"), "{e}");
        let e = parse_pose("--goal-pose", "0,0,0,0,0,0,0", false).expect_err("norm 0");
        assert!(e.to_string().contains("norm 0"), "{e}");
        let e = parse_pose("--goal-pose", "0,0,NaN,0,0,0,1", false).expect_err("NaN");
        assert!(e.to_string().contains("`NaN`"), "{e}");
        assert_eq!(
            parse_position_tolerance("0.01").expect("a ball"),
            PositionTolerance::Ball { radius: 0.01 }
        );
        assert!(parse_position_tolerance("1,2").is_err());
        assert_eq!(
            parse_orientation_tolerance("cone:z:0.1").expect("a cone"),
            OrientationTolerance::Cone {
                axis: DVec3::Z,
                half_angle: 0.1
            }
        );
        assert_eq!(
            parse_orientation_tolerance("axis:0;0;1").expect("an axis"),
            OrientationTolerance::FreeAxis { axis: DVec3::Z }
        );
        assert!(parse_orientation_tolerance("cone:w:0.1").is_err());
    }
}
