//! [`VisualMeshes`]: a model's visual elements as triangles in their links' frames.

use std::collections::HashMap;
use std::path::PathBuf;

use glam::DVec3;
use thiserror::Error;

use super::capsule::capsule;
use crate::spherise::read_mesh;
use crate::{
    LinkVisual, MeshResolver, ResolveError, RobotModel, SpheriseError, TriangleMesh, VisualGeometry,
};

/// Sides of the polygon approximating a cylinder's, sphere's or capsule's circle.
pub const PRIMITIVE_SEGMENTS: u32 = 32;

/// One visual element as triangles in its link's frame (its origin and scale applied).
#[derive(Debug, Clone, PartialEq)]
pub struct LinkMesh {
    /// Index of its link in [`RobotModel::links`].
    pub link: usize,
    /// The mesh file as the URDF names it, or `None` for a box, cylinder, capsule or sphere.
    pub filename: Option<String>,
    /// Vertex positions, `x, y, z` each, flattened, in metres in the link frame.
    pub positions: Vec<f32>,
    /// Triangles, three indices into the vertices each, flattened, counter-clockwise seen
    /// from outside for primitives and as the file orders them (mirrored by a negative scale
    /// and put back) for meshes.
    pub indices: Vec<u32>,
    /// Its material's colour, RGBA ([`LinkVisual::colour`]).
    pub colour: Option<[f32; 4]>,
}

impl LinkMesh {
    /// How many triangles it has.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// How many vertices it has.
    pub fn vertex_count(&self) -> usize {
        self.positions.len() / 3
    }
}

/// Why a visual element has no mesh.
#[derive(Debug, Error)]
pub enum MeshLoadError {
    /// Its file name leads to no file.
    #[error(transparent)]
    Unresolved(#[from] ResolveError),
    /// Its file could not be read as a mesh (unreadable, a Git LFS pointer, an unsupported
    /// format, corrupt, or without triangles).
    #[error(transparent)]
    Unreadable(#[from] SpheriseError),
}

/// A visual element left without a mesh, and why.
#[derive(Debug)]
pub struct MeshLoadFailure {
    /// Index of its link in [`RobotModel::links`].
    pub link: usize,
    /// Its link's name.
    pub link_name: String,
    /// The mesh file as the URDF names it (for a primitive: `box`, `cylinder`, …).
    pub filename: String,
    /// Why.
    pub reason: MeshLoadError,
}

impl std::fmt::Display for MeshLoadFailure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "link `{}`: {}", self.link_name, self.reason)
    }
}

/// A robot's visual elements as triangle meshes, each in its link's frame, and the elements
/// whose meshes could not be had.
///
/// Mesh files are found by a [`MeshResolver`] and read as `spherise` reads them (STL by this
/// crate's reader, OBJ and COLLADA by `mesh-loader`, at most
/// 600 MB a file; the conventions are `spherise`'s: COLLADA `<unit>` applied, `<up_axis>`
/// not, as RViz draws them). A file named by several elements is read once. Boxes,
/// cylinders, capsules and spheres are tessellated ([`PRIMITIVE_SEGMENTS`] sides; a
/// cylinder's polygon circumscribes its circle). Meshes are kept whole: no decimation, so a
/// detailed file stays large ([`triangle_count`](Self::triangle_count)).
///
/// ```
/// let panda = mit_star_robot::ShippedRobot::find("panda").expect("shipped");
/// let model = panda.model(false)?;
/// let visuals = mit_star_robot::VisualMeshes::load(&model, &panda.mesh_resolver());
/// assert!(visuals.failures.is_empty(), "{:?}", visuals.failures);
/// assert_eq!(visuals.meshes.len(), model.visuals().len());
/// # Ok::<(), mit_star_robot::ModelError>(())
/// ```
#[derive(Debug, Default)]
pub struct VisualMeshes {
    /// The meshes, in the order of [`RobotModel::visuals`] (tree order of their links).
    pub meshes: Vec<LinkMesh>,
    /// The visual elements without a mesh, in the same order.
    pub failures: Vec<MeshLoadFailure>,
}

impl VisualMeshes {
    /// Meshes for every visual element of `model`: never fails as a whole, a file that cannot
    /// be found or read is a [`MeshLoadFailure`] and the others load.
    pub fn load(model: &RobotModel, resolver: &MeshResolver) -> Self {
        let mut read: HashMap<PathBuf, TriangleMesh> = HashMap::new();
        let mut out = Self::default();
        for visual in model.visuals() {
            let link_name = || model.links()[visual.link].name.clone();
            match element_mesh(visual, resolver, &mut read) {
                Ok(mesh) => out.meshes.push(mesh),
                Err((filename, reason)) => out.failures.push(MeshLoadFailure {
                    link: visual.link,
                    link_name: link_name(),
                    filename,
                    reason,
                }),
            }
        }
        out
    }

    /// The triangles of all meshes.
    pub fn triangle_count(&self) -> usize {
        self.meshes.iter().map(LinkMesh::triangle_count).sum()
    }

    /// The meshes of link `link`.
    pub fn of_link(&self, link: usize) -> impl Iterator<Item = &LinkMesh> {
        self.meshes.iter().filter(move |m| m.link == link)
    }
}

/// The mesh of one visual element, or its name and why there is none.
fn element_mesh(
    visual: &LinkVisual,
    resolver: &MeshResolver,
    read: &mut HashMap<PathBuf, TriangleMesh>,
) -> Result<LinkMesh, (String, MeshLoadError)> {
    let (shape, scale, filename) = match &visual.geometry {
        VisualGeometry::Mesh { filename, scale } => {
            let fail = |e: MeshLoadError| (filename.clone(), e);
            let path = resolver
                .resolve(filename)
                .map_err(|e| fail(MeshLoadError::from(e)))?;
            let mesh = match read.get(&path) {
                Some(mesh) => mesh.clone(),
                None => {
                    let mesh = read_mesh(&path).map_err(|e| fail(MeshLoadError::from(e)))?;
                    read.insert(path, mesh.clone());
                    mesh
                }
            };
            (mesh, *scale, Some(filename.clone()))
        }
        &VisualGeometry::Box { size } => (
            primitive("box", TriangleMesh::cuboid(size / 2.0))?,
            DVec3::ONE,
            None,
        ),
        &VisualGeometry::Cylinder { radius, length } => (
            primitive(
                "cylinder",
                TriangleMesh::cylinder(radius, length, PRIMITIVE_SEGMENTS),
            )?,
            DVec3::ONE,
            None,
        ),
        &VisualGeometry::Capsule { radius, length } => (
            primitive(
                "capsule",
                capsule(radius, length, PRIMITIVE_SEGMENTS, RINGS),
            )?,
            DVec3::ONE,
            None,
        ),
        &VisualGeometry::Sphere { radius } => (
            primitive("sphere", capsule(radius, 0.0, PRIMITIVE_SEGMENTS, RINGS))?,
            DVec3::ONE,
            None,
        ),
    };
    Ok(place(&shape, visual, scale, filename))
}

/// Rings of latitude of a sphere or capsule (poles to poles).
const RINGS: u32 = PRIMITIVE_SEGMENTS / 2;

/// A primitive's mesh, or its name and why there is none.
fn primitive(
    name: &str,
    mesh: Result<TriangleMesh, SpheriseError>,
) -> Result<TriangleMesh, (String, MeshLoadError)> {
    mesh.map_err(|e| (name.to_owned(), e.into()))
}

/// `p ↦ origin (scale ⊙ p)` for every vertex, in `f32`; a mirroring scale (an odd number of
/// negative factors) has its triangles' corners reordered to keep their facing.
fn place(
    shape: &TriangleMesh,
    visual: &LinkVisual,
    scale: DVec3,
    filename: Option<String>,
) -> LinkMesh {
    let origin = visual.origin;
    let positions = shape
        .vertices()
        .iter()
        .flat_map(|&v| {
            origin
                .transform_point3(v * scale)
                .to_array()
                .map(|c| c as f32)
        })
        .collect();
    let mirrored = scale.x * scale.y * scale.z < 0.0;
    let indices = shape
        .triangles()
        .iter()
        .flat_map(|&[a, b, c]| if mirrored { [a, c, b] } else { [a, b, c] })
        .collect();
    LinkMesh {
        link: visual.link,
        filename,
        positions,
        indices,
        colour: visual.colour,
    }
}
