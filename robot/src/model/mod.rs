//! The robot model: the sphere-model kinematic tree read from URDF and SRDF, its forward
//! kinematics, and the lever-arm bound on how fast its spheres can move.
//!
//! - [`RobotModel`] (`robot_model.rs`): links in tree order, joints, collision spheres, allowed
//!   self-collision pairs; with [`LinkFrame`], [`LinkSphere`], [`Motion`] and [`rpy_matrix`].
//!   `srdf.rs` reads the SRDF's `disable_collisions` pairs; `collision_pairs.rs` applies them
//!   and a scene's allowed collisions, leniently (warnings) or strictly (errors);
//!   `model_pairs.rs` finds the pairs the sphere model rules out (adjacent links, pairs in
//!   collision everywhere) and the pairs colliding at a configuration; `model_joint.rs` derives
//!   the coordinates and link frames from the joints (planned, held, mimic; the prismatic
//!   weight); `planning_group.rs` reads SRDF planning groups and the held joints' values;
//!   `rrt_range.rs` gives the RRT range its problems default to (measured, or a rule).
//! - [`LinkVisual`], [`VisualGeometry`] (`link_visual.rs`): each link's URDF `<visual>`
//!   elements (origin, mesh file and scale or primitive, material colour), for viewers.
//! - [`Kinematics`] (`kinematics.rs`): forward kinematics, link poses and sphere centres, `f32`
//!   and `f64`, no allocation; its per-joint steps are what the SIMD lanes of `checking` replay.
//! - [`LeverArms`] (`lever_arms.rs`): how far each link's spheres can move per unit of each
//!   joint, over all configurations — the bound certified motion rests on.
//! - [`ModelError`] (`model_error.rs`): why a URDF or SRDF could not be loaded;
//!   [`ModelWarning`] (`model_warning.rs`): what a lenient model ignored (unknown link names).
//!
//! May use: the `spaces`, `glam`, `urdf-rs`, `roxmltree` and `thiserror` crates, and of this
//! crate only `Scene::MAX_LENGTH` from `scenes` (models and scenes share one length limit).
//! Knows nothing of checking. Used by `scenes` (the `f32` pose conversion), `checking` and
//! [`ArmProblem`](crate::ArmProblem).

mod collision_pairs;
mod joint_limits;
mod kinematics;
mod lever_arms;
mod link_visual;
mod model_error;
mod model_joint;
mod model_pairs;
mod model_warning;
mod planning_group;
mod robot_model;
mod rrt_range;
mod srdf;
mod xml_guard;

pub use kinematics::Kinematics;
pub(crate) use kinematics::{JointMotion, to_f32};
pub use lever_arms::LeverArms;
pub use link_visual::{LinkVisual, VisualGeometry};
pub use model_error::ModelError;
pub use model_warning::ModelWarning;
pub use robot_model::{LinkFrame, LinkSphere, Motion, RobotModel, rpy_matrix};
