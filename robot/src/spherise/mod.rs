//! Spheres from meshes: a conservative sphere cover of each link's collision meshes, and a
//! URDF written with those spheres as its collision geometry (`mit-star spherise`).
//!
//! - [`TriangleMesh`] (`triangle_mesh.rs`): triangles over shared vertices, boxes and
//!   cylinders as meshes; [`read_stl`] and [`parse_stl`] (`stl.rs`): binary and ASCII STL;
//!   `mesh_file.rs`: any collision mesh file by its extension (STL, OBJ and COLLADA, the
//!   latter two through `mesh-loader`: why that crate, and the units and up-axis rules, are
//!   in its doc), Git LFS pointers recognised.
//! - `vertex_weld.rs`: an open mesh closed by merging vertices a few micrometres apart
//!   (exporters' float noise), covered as that solid with its spheres grown by the move.
//! - `solid.rs`: a mesh as a point set (the solid of a closed mesh, the surface of an open
//!   one), distances through parry and a robust ray-parity test of inside.
//! - `enclosed_fill.rs`: the space a hollow mesh walls in (a thin-walled housing's inside),
//!   counted as solid so that spheres may fill it.
//! - `cell_grid.rs`: the solid cut into cells, each cell's part bounded by a box.
//! - [`SphereCover`] (`sphere_cover.rs`): few spheres containing every cell's box, each
//!   protruding by at most the tolerance, with [`CoverOptions`] and [`CoverSphere`];
//!   [`Placement`] chooses between its grid placement and `medial_cover.rs`'s medial one
//!   (candidates on an approximate medial axis, a finer grid, pairs merged) and
//!   `cover_search.rs`'s searched one (the medial candidates, the greedy cover improved by a
//!   local search for a cover with fewer spheres: what a sphere budget uses).
//! - `outward_error.rs`: a cover's outward error measured by branch and bound over the
//!   spheres' surfaces (the largest distance from the union's boundary to the mesh).
//! - [`SpherisedUrdf`] (`spherised_urdf.rs`): a URDF's collision meshes and primitives
//!   covered link by link, and the URDF rewritten with spheres; `urdf_collisions.rs` reads
//!   the collision elements and finds their mesh files through [`MeshResolver`]
//!   (`mesh_resolver.rs`: `package://`, relative and absolute names, aliases); `sphere_budget.rs` finds the finest
//!   tolerance whose covers fit a whole-model sphere budget, and `budget_allocation.rs`
//!   then chooses each link's cover among a ladder of tolerances about it, by measured
//!   outward error (the worst link's least, leftovers where they cut most).
//! - [`SpheriseError`] (`spherise_error.rs`): what went wrong, naming the file or link.
//!
//! **The guarantee:** the union of a cover's spheres contains every point of every triangle
//! and, for a closed mesh, every point inside it; no point of a sphere lies farther from the
//! mesh's solid (a hollow mesh's walled-in inside counted in) than the sphere's reported
//! protrusion, and no point of the union's boundary farther from the mesh's surface than
//! the cover's reported outward error (tested in `robot/tests/sphere_cover.rs` and
//! `robot/tests/budget_cover.rs`).
//!
//! May use: `glam`, `parry3d-f64`, `roxmltree`, `mesh-loader`, `thiserror`, and
//! `rpy_matrix` from `model`.
//! Used by `visuals` (the mesh reader and the resolver, for visual meshes).

mod budget_allocation;
mod cell_grid;
mod cover_search;
mod enclosed_fill;
mod medial_cover;
mod mesh_file;
mod mesh_resolver;
mod outward_error;
mod solid;
mod sphere_budget;
mod sphere_cover;
mod spherise_error;
mod spherised_urdf;
mod stl;
mod triangle_mesh;
mod urdf_collisions;
mod vertex_weld;

/// The most grid cells one mesh's cover may take (about a gigabyte of work at most): a
/// tolerance that would need more for the mesh's size (a `10⁻⁹` m tolerance, or a `10³⁰`
/// scale) is refused with [`SpheriseError::TooMuchWork`] before any work. At the default
/// 10 mm tolerance, a mesh up to about 0.9 m in each direction fits.
pub const MAX_COVER_CELLS: usize = 4_000_000;

pub(crate) use mesh_file::read_mesh;
pub use mesh_resolver::{MeshResolver, ResolveError};
pub use sphere_cover::{CoverOptions, CoverSphere, Placement, SphereCover};
pub use spherise_error::SpheriseError;
pub use spherised_urdf::{LinkReport, LinkSource, SpheriseOptions, SpherisedUrdf};
pub use stl::{parse_stl, read_stl};
pub use triangle_mesh::TriangleMesh;
