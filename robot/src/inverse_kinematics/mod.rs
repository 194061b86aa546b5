//! Inverse kinematics for pose goals: configurations placing a link (or a tool frame on it)
//! at a target pose, within position and orientation tolerances, collision-free.
//!
//! - [`PoseTarget`] (`pose_target.rs`): the pose and its tolerances, checked once;
//!   [`PositionTolerance`] (`position_tolerance.rs`: exact, a box, a ball) and
//!   [`OrientationTolerance`] (`orientation_tolerance.rs`: exact, a cone about an axis, free
//!   rotation about an axis, free), each giving the residual the solver drives to zero.
//! - [`IkSolver`] (`ik_solver.rs`: construction, settings; `ik_search.rs`: restarts and the
//!   Levenberg–Marquardt descent), on the chain's `f64` forward kinematics and analytic
//!   Jacobian (`ik_chain.rs`) and a 6×6 damped least-squares step (`dls_step.rs`);
//!   [`IkSolution`] (`ik_solution.rs`) is what it returns.
//! - [`PoseGoal`] (`pose_goal.rs`): a target as a source of distinct goal configurations for
//!   planners.
//! - [`IkError`] (`ik_error.rs`): every bad input named, and why no solution was found.
//!
//! May use: `model` (the robot, its forward kinematics), `spaces` (limits, metric, random
//! restarts, stop conditions), `validity` (the checker answering which solutions are
//! collision-free), `glam`, `rand`, `thiserror`.

mod dls_step;
mod ik_chain;
mod ik_error;
mod ik_search;
mod ik_solution;
mod ik_solver;
mod orientation_tolerance;
mod pose_goal;
mod pose_target;
mod position_tolerance;

pub use ik_error::IkError;
pub use ik_solution::IkSolution;
pub use ik_solver::IkSolver;
pub use orientation_tolerance::OrientationTolerance;
pub use pose_goal::PoseGoal;
pub use pose_target::PoseTarget;
pub use position_tolerance::PositionTolerance;
