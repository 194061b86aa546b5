//! Collision checking of arm configurations and motions: the planners' checker, its SIMD
//! lanes and certified motion, and the independent `f64` checks used as references.
//!
//! - [`ArmChecker`] (`arm_checker.rs`): the checker planners use — joint limits, scene and
//!   self-collision with broad phases, one-sided (a margin covers `f32` rounding); `lanes.rs`
//!   runs its forward kinematics on a batch of configurations at once (`LaneF32`: eight
//!   lanes, or sixteen with AVX-512).
//! - `arm_certification.rs`: certified motion, every configuration of an edge proven clear
//!   (not only grid points) by conservative advancement, with its floor
//!   [`CERTIFICATION_FLOOR`]; `clearance.rs` turns a batch of configurations' clearances into how
//!   far along the edge each stays clear; `local_sweep.rs` bounds how far spheres move over a
//!   piece of an edge, from the piece's middle configuration, and how fast the two links of a
//!   self-collision pair move relative to each other.
//! - `reachable_obstacles.rs`: per link, the obstacles it can reach in some configuration
//!   (the only ones its checks and clearances look at); `obstacle_grid.rs`: where a link
//!   reaches many obstacles (a scene of thousands of boxes), a uniform grid over them, so that
//!   its checks and clearances test only those near its lanes, with the same answers.
//! - [`ParryChecker`] (`parry_checker.rs`): the reference checker, `f64` and parry queries, no
//!   culling (tests and path re-checks).
//! - [`MotionAudit`], [`AuditVerdict`], [`AUDIT_CONTACT`] (`motion_audit.rs`): an independent
//!   continuous check of a motion by conservative advancement on parry distances, with its
//!   own broad phase (`audit_broad_phase.rs`: per-link bounding spheres first).
//! - [`StateDiagnosis`] (`state_diagnosis.rs`): what one configuration touches, by name, in
//!   `f64` (`mit-star check-state`).
//! - `audit_clouds.rs`: the reference checker's and the audit's own view of point clouds,
//!   every point in `f64` by brute force (no code shared with `clouds::PointTree`).
//! - [`Padding`] (`padding.rs`): the clearance a user asks paths to keep from every obstacle
//!   (environment only, not between the robot's links), which every check, certification and
//!   reference check above grows the robot's spheres by against the scene.
//! - `scratch_cell.rs`: the per-clone scratch buffers both checkers keep behind a mutex;
//!   `spare_scratch.rs`: the arm checker's, kept on their thread when a checker is dropped and
//!   handed to the next clone of the same shape.
//!
//! May use: `model` (the robot, its kinematics and lever arms), `scenes` (the obstacles),
//! `clouds` (point clouds and their tree: the planners' checker only), and
//! the `spaces`, `validity`, `glam`, `wide` and `parry3d-f64` crates. Used by
//! [`ArmProblem`](crate::ArmProblem).

mod arm_certification;
mod arm_checker;
mod audit_broad_phase;
mod audit_clouds;
mod clearance;
mod lanes;
mod local_sweep;
mod motion_audit;
mod obstacle_grid;
mod padding;
mod parry_checker;
mod reachable_obstacles;
mod scratch_cell;
mod spare_scratch;
mod state_diagnosis;

pub use arm_certification::FLOOR as CERTIFICATION_FLOOR;
pub use arm_checker::ArmChecker;
pub use motion_audit::{AUDIT_CONTACT, AuditVerdict, MotionAudit};
pub use padding::{MAX_PADDING, Padding, PaddingError};
pub use parry_checker::ParryChecker;
pub use state_diagnosis::{Contact, LimitViolation, StateDiagnosis};
