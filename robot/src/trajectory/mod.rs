//! Time parameterisation of planned paths: limits, trajectories, their files and their check.
//!
//! - [`MotionLimits`] (`motion_limits.rs`): per coordinate velocity and acceleration limits
//!   from the URDF, a MoveIt `joint_limits.yaml` ([`JointLimitsYaml`],
//!   `joint_limits_yaml.rs`) or given, with MoveIt's scaling factors; mimic followers bound
//!   their leaders.
//! - [`Trajectory`], [`Sample`] (`trajectory.rs`): piecewise-quadratic motion, knots, exact
//!   evaluation, sampling; built by `blend_timing.rs` ([`Trajectory::stop_at_corners`],
//!   [`Trajectory::blended`], [`BlendReport`]), whose corners' speeds `corner_search.rs`
//!   chooses (the least time over grids of them, by dynamic programming).
//! - [`BlendCertifier`] (`blend_certifier.rs`): blends proven collision-free.
//! - [`TrajectoryFile`] (`trajectory_file.rs`): JSON and CSV writers and reader;
//!   [`check_trajectory`], [`TrajectoryCheck`] (`trajectory_check.rs`): a file checked against
//!   the robot and scene.
//! - [`TrajectoryError`] (`trajectory_error.rs`).
//!
//! The guarantee of each timing, and why there are no jerk limits: [`Trajectory`]'s docs.
//!
//! May use: `model` (the URDF's velocity limits, mimic rates, lever arms), `checking` (the
//! checker), `scenes`, and the `validity`, `spaces`, `serde`, `serde_json` and
//! `serde-saphyr` crates.

mod blend_certifier;
mod blend_timing;
mod corner_search;
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
