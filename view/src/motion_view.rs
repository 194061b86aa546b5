//! [`MotionView`]: one motion to scrub through — frames of joint values and of poses, the
//! path's waypoints among them, and the frames found in collision.

use serde::Serialize;

use crate::encoding::f32s;

/// One motion: `frames` moments, each with the joint values and where every link (or, in a box
/// world, the point) is.
///
/// Frames are what the slider steps through: the path's waypoints and states interpolated
/// between them (or a trajectory's samples, with their times). The page interpolates between
/// neighbouring frames when playing.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MotionView {
    /// Its name in the page's motion selector ("plan", "best run (seed 3)", "trajectory").
    pub label: String,
    /// Names of the coordinates, in the order of `joints` (shown as you scrub).
    pub joint_names: Vec<String>,
    /// How many frames.
    pub frames: usize,
    /// Joint values, `frames × joint_names.len()`, frame-major.
    #[serde(serialize_with = "f32s")]
    pub joints: Vec<f32>,
    /// Arms: link poses, `frames × links × 7` (`x, y, z, qx, qy, qz, qw`), frame-major, links in
    /// [`RobotView::links`](crate::RobotView::links) order. Box worlds: the point's position,
    /// `frames × 3`.
    #[serde(serialize_with = "f32s")]
    pub poses: Vec<f32>,
    /// The time of each frame in seconds, for a timed trajectory (`None`: the slider shows
    /// the fraction of path length).
    pub times: Option<Vec<f64>>,
    /// Frames that are the path's own states (drawn as ghosts), ascending.
    pub waypoints: Vec<usize>,
    /// Frames found in collision (drawn in red), ascending.
    pub colliding: Vec<usize>,
    /// Where each of the scene's [`movers`](crate::SceneView::movers) is at each frame,
    /// `frames × movers × 3`, frame-major (empty without movers).
    #[serde(serialize_with = "f32s")]
    pub mover_positions: Vec<f32>,
}
