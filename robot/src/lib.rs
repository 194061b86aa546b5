//! Robot arms for planning.
//!
//! A robot is a kinematic tree read from URDF whose collision geometry is spheres (the
//! "spherised" models of VAMP and MotionBenchMaker); its actuated joints span a
//! [`spaces::JointSpace`]. A scene is a set of boxes, cylinders and spheres in the robot's base
//! frame, read from MotionBenchMaker's MoveIt YAML. Checking a configuration places every
//! sphere by forward kinematics and tests it against the scene and the robot itself. An
//! [`ArmProblem`] is a [`problems::PlanningProblem`]: every planner plans for it.
//!
//! ```
//! use mit_star::{FirstSolution, MitStar, Planner, TerminationExt};
//! let folder = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/mbm/table_pick_panda");
//! let problem = robot::ArmProblem::panda_mbm(folder.as_ref(), 1)?;
//! let mut planner = MitStar::for_problem(&problem).seed(1).build()?;
//! let outcome = planner.solve(&FirstSolution.or(mit_star::TimeLimit::seconds(5.0)))?;
//! assert!(outcome.is_solved());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Catalogue
//! | item | what it is |
//! |---|---|
//! | [`RobotModel`], [`LinkFrame`], [`Motion`], [`LinkSphere`], [`rpy_matrix`] | a sphere-model robot from URDF (urdf-rs) and SRDF (its disabled pairs), links in tree order |
//! | [`Kinematics`] | forward kinematics: link poses and sphere centres, `f32` and `f64`, no allocation |
//! | [`Obstacle`], [`Shape`] | boxes, cylinders and spheres with poses; exact sphere contact tests |
//! | [`Scene`] | a MoveIt planning scene (MotionBenchMaker YAML): obstacles and allowed collisions |
//! | [`MbmProblem`] | a MotionBenchMaker scene + request pair |
//! | [`ArmChecker`] | the collision checker: joint limits, scene and self-collision with broad phases, one-sided (a margin covers `f32` rounding), and certified motion (every configuration of an edge, not only grid points) |
//! | [`LeverArms`], [`CERTIFICATION_FLOOR`] | how far each link's spheres can move per unit of each joint, over all configurations: the bound certified motion rests on |
//! | [`ParryChecker`] | the reference checker: `f64`, parry queries, no culling (tests and path re-checks) |
//! | [`MotionAudit`], [`AuditVerdict`], [`AUDIT_CONTACT`] | an independent continuous check of a motion: conservative advancement in `f64` from parry distances and its own speed bound (the harness's re-check of returned arm paths) |
//! | [`ArmProblem`], [`CHECKS_PER_UNIT`], [`CERTIFICATION`] | an arm planning problem, with its default check density and the certification its edges ask for |
//! | [`ModelError`], [`SceneError`], [`ArmError`] | what is wrong, naming the file and field |

#![forbid(unsafe_code)]

mod arm_certification;
mod arm_checker;
mod arm_error;
mod arm_problem;
mod kinematics;
mod lanes;
mod lever_arms;
mod local_sweep;
mod mbm_problem;
mod model_error;
mod motion_audit;
mod obstacle;
mod parry_checker;
mod robot_model;
mod scene;
mod scene_error;
mod scratch_cell;
mod srdf;
mod yaml_text;

pub use arm_certification::FLOOR as CERTIFICATION_FLOOR;
pub use arm_checker::ArmChecker;
pub use arm_error::ArmError;
pub use arm_problem::{ArmProblem, CERTIFICATION, CHECKS_PER_UNIT};
pub use kinematics::Kinematics;
pub use lever_arms::LeverArms;
pub use mbm_problem::MbmProblem;
pub use model_error::ModelError;
pub use motion_audit::{AUDIT_CONTACT, AuditVerdict, MotionAudit};
pub use obstacle::{Obstacle, Shape};
pub use parry_checker::ParryChecker;
pub use robot_model::{LinkFrame, LinkSphere, Motion, RobotModel, rpy_matrix};
pub use scene::Scene;
pub use scene_error::SceneError;
