//! What a viewer draws: a robot's URDF visual elements as triangle meshes in their links'
//! frames.
//!
//! - [`VisualMeshes`] (`visual_meshes.rs`): every visual element of a
//!   [`RobotModel`](crate::RobotModel) loaded ([`LinkMesh`]) or reported
//!   ([`MeshLoadFailure`], [`MeshLoadError`]): mesh files found by a
//!   [`MeshResolver`](crate::MeshResolver) and read by `spherise`'s reader, primitives
//!   tessellated; `capsule.rs` makes spheres and capsules.
//!
//! May use: `model` (the visual elements) and `spherise` (the mesh reader, the resolver,
//! [`TriangleMesh`](crate::TriangleMesh)). Used by the command-line tool's views.

mod capsule;
mod visual_meshes;

pub use visual_meshes::{
    LinkMesh, MeshLoadError, MeshLoadFailure, PRIMITIVE_SEGMENTS, VisualMeshes,
};
