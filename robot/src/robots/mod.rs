//! Choosing a robot: the models shipped with the crate and robots named on the command line.
//!
//! - [`ShippedRobot`] (`shipped_robot.rs`): the Panda, UR5, Fetch and Baxter spherised models, compiled
//!   in, and where their MotionBenchMaker problem sets are.
//! - [`RobotSource`] (`robot_source.rs`): a shipped name or a folder with a URDF and an SRDF,
//!   loaded strictly or leniently; [`RobotSourceError`] (`robot_source_error.rs`): what is wrong.
//!
//! May use: `model`. Used by [`ArmProblem`](crate::ArmProblem) (the Panda) and the
//! command-line tool.

mod robot_source;
mod robot_source_error;
mod shipped_robot;

pub use robot_source::RobotSource;
pub use robot_source_error::RobotSourceError;
pub use shipped_robot::ShippedRobot;
