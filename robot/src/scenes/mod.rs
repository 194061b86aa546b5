//! Scenes and the files they come from: obstacles, MoveIt planning scenes, and
//! MotionBenchMaker problems.
//!
//! - [`Obstacle`], [`Shape`] (`obstacle.rs`): boxes, cylinders and spheres with poses, and the
//!   exact sphere contact tests (one sphere, or eight at once for the SIMD checker).
//! - [`Scene`] (`scene.rs`): a MoveIt planning scene from MotionBenchMaker's YAML: obstacles in
//!   the robot's base frame and allowed collisions; and point clouds
//!   ([`CloudObstacle`](crate::CloudObstacle)).
//! - [`MbmProblem`] (`mbm_problem.rs`): a MotionBenchMaker scene and request pair.
//! - [`MovingObstacle`] (`moving_obstacle.rs`): a box going back and forth along a line, where
//!   it is at any time and the box it sweeps over an interval; [`MovingScene`]
//!   (`moving_scene.rs`): fixed and moving obstacles as a [`Scene`] at a time or over an interval.
//! - `yaml_text.rs`: `read_yaml`, MoveIt's YAML parsed with limits that scale with the text.
//! - [`SceneError`] (`scene_error.rs`): why a scene or problem file could not be read, naming
//!   the file and field.
//!
//! May use: the `glam`, `wide`, `serde`, `serde-saphyr` and `thiserror` crates, and of this
//! crate only the `f32` pose conversion of `model`, the SIMD lane type (`lane_f32.rs`) and the
//! point clouds (`clouds`).
//! Knows nothing of checking. Used by `model` (the shared length limit), `checking` and
//! [`ArmProblem`](crate::ArmProblem).

mod mbm_problem;
mod moving_obstacle;
mod moving_scene;
mod obstacle;
mod scene;
mod scene_error;
mod yaml_text;

pub use mbm_problem::MbmProblem;
pub use moving_obstacle::MovingObstacle;
pub use moving_scene::MovingScene;
pub use obstacle::{Obstacle, Shape};
pub use scene::Scene;
pub use scene_error::SceneError;
