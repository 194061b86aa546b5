//! [`SearchOverlay`]: the planner's tree or graph, drawn in the workspace.

use serde::Serialize;

use crate::encoding::f32s;

/// Edges of the search as segments in the workspace (an arm's edges through its hand's
/// position, a box world's directly), each coloured by the cost-to-come of its child, and the
/// informed set where it can be drawn.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SearchOverlay {
    /// Segments, `[x0, y0, z0, x1, y1, z1]` each, flattened.
    #[serde(serialize_with = "f32s")]
    pub segments: Vec<f32>,
    /// Cost-to-come of each segment's far end (`∞` is written as a large number).
    #[serde(serialize_with = "f32s")]
    pub costs: Vec<f32>,
    /// The informed set of a Euclidean box world: the prolate hyperspheroid with these foci
    /// and this cost (`None` where it cannot be drawn, as on an arm).
    pub informed: Option<InformedView>,
    /// What the segments are ("forward tree, 1 234 edges").
    pub label: String,
}

/// An ellipsoid `{x : |x − a| + |x − b| ≤ cost}`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct InformedView {
    /// One focus (the start).
    pub start: [f32; 3],
    /// The other focus (the goal).
    pub goal: [f32; 3],
    /// The best cost.
    pub cost: f32,
}
