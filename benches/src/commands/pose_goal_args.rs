//! [`PoseGoalArgs`]: a pose of a robot's link as the goal of an arm problem (`plan
//! --goal-pose`).

use clap::Args;

use crate::definition::pose_goal_spec::PoseGoalSpec;

/// The options that make a link's pose the goal of an arm problem.
#[derive(Debug, Args, Default, Clone)]
pub struct PoseGoalArgs {
    /// Plan to a pose of `--link` instead of the problem's goal configuration:
    /// `x,y,z,qx,qy,qz,qw` (metres, and a quaternion, normalised) in the robot's root frame;
    /// or `goal`, the pose the problem's goal configuration gives the link. Inverse kinematics
    /// supplies goal configurations while planning (collision-free, distinct).
    #[arg(long, value_name = "X,Y,Z,QX,QY,QZ,QW|goal", requires = "link")]
    pub goal_pose: Option<String>,
    /// The link whose pose `--goal-pose` gives (`mit-star robots NAME` lists the links).
    #[arg(long, value_name = "LINK", requires = "goal_pose")]
    pub link: Option<String>,
    /// A tool frame fixed to the link, whose pose `--goal-pose` gives instead:
    /// `x,y,z` or `x,y,z,qx,qy,qz,qw` in the link's frame.
    #[arg(long, value_name = "X,Y,Z[,QX,QY,QZ,QW]", requires = "goal_pose")]
    pub tool: Option<String>,
    /// How far the position may be from the target: `R`, a ball of radius R metres, or
    /// `X,Y,Z`, a box of these half-extents along the target frame's axes. Default: exact
    /// (within 1e-5 m).
    #[arg(
        long,
        value_name = "R|X,Y,Z",
        requires = "goal_pose",
        allow_hyphen_values = true
    )]
    pub position_tolerance: Option<String>,
    /// How far the orientation may be from the target: `exact` (default, within 1e-4 rad),
    /// `cone:AXIS:ANGLE` (AXIS within ANGLE radians of the target's, turning about it free),
    /// `axis:AXIS` (AXIS exactly the target's, turning about it free), or `free`. AXIS is
    /// `x`, `y`, `z` or `a;b;c` in the frame's own coordinates.
    #[arg(
        long,
        value_name = "exact|cone:AXIS:ANGLE|axis:AXIS|free",
        requires = "goal_pose"
    )]
    pub orientation_tolerance: Option<String>,
    /// The most goal configurations inverse kinematics supplies while planning.
    #[arg(long, default_value_t = 8, requires = "goal_pose")]
    pub ik_goals: usize,
    /// The goal configurations drawn before planning starts (more gives the planner a choice
    /// of goals from the start, at the price of a later first solution).
    #[arg(long, default_value_t = 1, requires = "goal_pose")]
    pub ik_initial_goals: usize,
}

impl PoseGoalArgs {
    /// The pose goal asked for, if any.
    pub fn spec(&self) -> Option<PoseGoalSpec> {
        let (pose, link) = (self.goal_pose.clone()?, self.link.clone()?);
        Some(PoseGoalSpec {
            link,
            pose,
            tool: self.tool.clone(),
            position_tolerance: self.position_tolerance.clone(),
            orientation_tolerance: self.orientation_tolerance.clone(),
            ik_goals: self.ik_goals,
            ik_initial_goals: self.ik_initial_goals,
        })
    }
}
