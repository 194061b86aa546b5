//! Time parameterisation of planned paths: limits, trajectories, their files and their check.
//!
//! - [`MotionLimits`] (`motion_limits.rs`): per coordinate velocity and acceleration limits
//!   from the URDF, a MoveIt `joint_limits.yaml` ([`JointLimitsYaml`],
//!   `joint_limits_yaml.rs`) or given, with MoveIt's scaling factors; mimic followers bound
//!   their leaders.
//! - [`Trajectory`], [`Sample`] (`trajectory.rs`): piecewise-quadratic motion, knots, exact
//!   evaluation, sampling; built by `blend_timing.rs` ([`Trajectory::stop_at_corners`],
//!   [`Trajectory::blended`], [`BlendReport`]).
//! - [`BlendCertifier`] (`blend_certifier.rs`): blends proven collision-free.
//! - [`TrajectoryFile`] (`trajectory_file.rs`): JSON and CSV writers and reader;
//!   [`check_trajectory`], [`TrajectoryCheck`] (`trajectory_check.rs`): a file checked against
//!   the robot and scene.
//! - [`TrajectoryError`] (`trajectory_error.rs`).
//!
//! # The guarantee
//! Let `path` be a polyline whose straight segments are collision-free for an
//! [`ArmChecker`](crate::ArmChecker) (as our planners certify every edge they return).
//!
//! - [`Trajectory::stop_at_corners`]: every configuration of the trajectory is on a segment of
//!   `path` (so collision-free), it passes through every waypoint at rest, and every
//!   coordinate's velocity and acceleration stay within the [`MotionLimits`] at every instant
//!   (velocity is piecewise linear and acceleration piecewise constant, and both are within
//!   the limits at every knot). Each segment takes the least time any motion starting and
//!   ending at rest along it, under those limits, can.
//! - [`Trajectory::blended`]: every configuration is either on a segment of `path` or on a
//!   blend that [`BlendCertifier`] certified: every sphere of the robot, at every instant of
//!   the blend, clear of the scene and of the links it is checked against by the checker's
//!   margin — the same sense in which the planner's edges are certified. The limits hold as
//!   above; blends are within the convex hull of their corner and its neighbours' points on
//!   the segments, so within the joint position limits. A blend that cannot be certified is
//!   shrunk, then replaced by a stop at its corner.
//!
//! Both start and end at rest at the path's ends. Continuous (wrapping) joints are taken as the
//! path gives them, unwrapped: no angle is wrapped by the timing.
//!
//! # Jerk
//! Jerk limits are not offered. A jerk-limited profile (Ruckig's, say) has no constant
//! acceleration phases, so the exact piecewise-quadratic evaluation and the chord
//! certification of blends would have to be redone for cubic pieces; a crate such as
//! `rsruckig` would time single segments but not certify corner blends. A controller
//! needing bounded jerk can follow this trajectory through its own jerk-limited filter.
//!
//! May use: `model` (the URDF's velocity limits, mimic rates, lever arms), `checking` (the
//! checker), `scenes`, and the `validity`, `spaces`, `serde`, `serde_json` and
//! `serde-saphyr` crates.

mod blend_certifier;
mod blend_timing;
mod joint_limits_yaml;
mod motion_limits;
#[allow(clippy::module_inception)]
mod trajectory;
mod trajectory_check;
mod trajectory_error;
mod trajectory_file;

pub use blend_certifier::BlendCertifier;
pub use blend_timing::BlendReport;
pub use joint_limits_yaml::JointLimitsYaml;
pub use motion_limits::{MotionLimits, PANDA_JOINT_LIMITS};
pub use trajectory::{Sample, Trajectory, merge_repeated_waypoints};
pub use trajectory_check::{TRAJECTORY_TOLERANCE, TrajectoryCheck, Violation, check_trajectory};
pub use trajectory_error::TrajectoryError;
pub use trajectory_file::TrajectoryFile;
