//! [`RobotView`]: a robot as the page draws it — per link, its collision spheres and its
//! visual meshes, in the link's frame.

use serde::Serialize;

use crate::encoding::{f32s, u32s};

/// A robot: its links in the order of a motion's link poses.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RobotView {
    /// The robot's name.
    pub name: String,
    /// Its links.
    pub links: Vec<LinkView>,
    /// Index of the link whose origin the hand's trace follows.
    pub hand: usize,
}

/// One link: spheres and meshes in its own frame.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LinkView {
    /// The link's name.
    pub name: String,
    /// Collision spheres, `[x, y, z, radius]` each, flattened.
    #[serde(serialize_with = "f32s")]
    pub spheres: Vec<f32>,
    /// Visual meshes, already in the link's frame (origin and scale applied).
    pub meshes: Vec<MeshView>,
}

/// A triangle mesh in its link's frame.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeshView {
    /// Vertex positions, `x, y, z` each, flattened.
    #[serde(serialize_with = "f32s")]
    pub positions: Vec<f32>,
    /// Triangles, three vertex indices each, flattened.
    #[serde(serialize_with = "u32s")]
    pub indices: Vec<u32>,
    /// Its colour, linear RGB in `[0, 1]` (the URDF material's, else grey).
    pub colour: [f32; 3],
}
