//! Reading a collision mesh file of any supported format into a [`TriangleMesh`]: STL (this
//! crate's reader, `stl.rs`), Wavefront OBJ and COLLADA (`.dae`) through `mesh-loader`.
//!
//! **Why `mesh-loader`.** It is the mesh reader of the OpenRR project (the Rust robotics
//! stack whose `urdf-rs` this crate already uses, and whose `urdf-viz` loads ROS robot
//! packages with it), pure Rust, maintained (0.1.13), reads all three formats, applies the
//! COLLADA node transforms and `<unit meter>`, and has no dependency beyond `roxmltree`.
//! `tobj` reads only OBJ, so COLLADA would take a second reader (`collada`, `dae-parser`),
//! where one crate does both. STL stays with this crate's own reader (tested, with its size
//! limit).
//!
//! **Conventions, as ROS's own tools read a robot package's meshes.** Coordinates are in the
//! mesh's frame, scaled by `<mesh scale>` in the URDF. A COLLADA file's `<unit meter="…">`
//! scales it (RViz does the same). Its `<up_axis>` is *not* applied: RViz and MoveIt's
//! `geometric_shapes` drop the rotation Assimp derives from it (rviz#1045, geometric_shapes#52),
//! so a package's meshes are drawn and collision-checked in their file coordinates whatever
//! the tag says; the spheres follow what MoveIt checks. A Git LFS pointer (a text file that
//! stands for the mesh in a clone without `git lfs pull`) is recognised and named.

use std::io::Read;
use std::path::Path;

use glam::DVec3;

use super::spherise_error::SpheriseError;
use super::stl::parse_stl;
use super::triangle_mesh::TriangleMesh;

/// The largest mesh file read (bytes): larger files are refused without reading them whole
/// (a binary STL of 10⁷ triangles is 500 MB).
pub(super) const MAX_MESH_BYTES: u64 = 600_000_000;

/// How a Git LFS pointer file begins.
const LFS_POINTER: &[u8] = b"version https://git-lfs.github.com/spec/";

/// Reads the mesh file at `path`, by its extension (`.stl`, `.obj`, `.dae`, any case).
///
/// # Errors
/// [`SpheriseError::Io`] if the file cannot be read or exceeds [`MAX_MESH_BYTES`],
/// [`SpheriseError::LfsPointer`] for a Git LFS pointer, [`SpheriseError::UnsupportedFormat`]
/// for another extension, [`SpheriseError::Stl`] or [`SpheriseError::Mesh`] for a file its
/// reader refuses, [`SpheriseError::BadMesh`] for one without triangles or with a coordinate
/// that is not finite.
pub(crate) fn read_mesh(path: &Path) -> Result<TriangleMesh, SpheriseError> {
    let extension = path
        .extension()
        .map(|e| e.to_string_lossy().to_lowercase())
        .unwrap_or_default();
    let bytes = read_bounded(path)?;
    if bytes.starts_with(LFS_POINTER) {
        return Err(SpheriseError::LfsPointer {
            path: path.to_owned(),
        });
    }
    let bad = |format: &'static str, message: String| SpheriseError::Mesh {
        path: path.to_owned(),
        format,
        message,
    };
    let scene = match extension.as_str() {
        "stl" => {
            return parse_stl(&bytes).map_err(|message| SpheriseError::Stl {
                path: path.to_owned(),
                message,
            });
        }
        // Without the file's path the reader does not open the materials it names (`mtllib`):
        // only the geometry is read.
        "obj" => mesh_loader::obj::from_slice(&bytes, None, |_| -> std::io::Result<Vec<u8>> {
            Err(std::io::ErrorKind::NotFound.into())
        })
        .map_err(|e| bad("OBJ", e.to_string()))?,
        "dae" => {
            mesh_loader::collada::from_slice(&bytes).map_err(|e| bad("COLLADA", e.to_string()))?
        }
        _ => {
            return Err(SpheriseError::UnsupportedFormat {
                path: path.to_owned(),
                extension,
            });
        }
    };
    let format = if extension == "obj" { "OBJ" } else { "COLLADA" };
    let mut soup = Vec::new();
    for mesh in &scene.meshes {
        for face in &mesh.faces {
            let mut corners = [DVec3::ZERO; 3];
            for (corner, &index) in corners.iter_mut().zip(face) {
                let v = mesh.vertices.get(index as usize).ok_or_else(|| {
                    bad(
                        format,
                        format!(
                            "mesh `{}`: a face names vertex {index} of {}",
                            mesh.name,
                            mesh.vertices.len()
                        ),
                    )
                })?;
                *corner = DVec3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2]));
            }
            soup.push(corners);
        }
    }
    if soup.is_empty() {
        return Err(bad(format, "no triangle".into()));
    }
    TriangleMesh::from_soup(&soup).map_err(|e| bad(format, e.to_string()))
}

/// The bytes of `path`, refusing a file larger than [`MAX_MESH_BYTES`] (or one that never
/// ends, as `/dev/zero`) after reading at most that much.
fn read_bounded(path: &Path) -> Result<Vec<u8>, SpheriseError> {
    let io = |source| SpheriseError::Io {
        path: path.to_owned(),
        source,
    };
    let file = std::fs::File::open(path).map_err(io)?;
    let mut bytes = Vec::new();
    file.take(MAX_MESH_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > MAX_MESH_BYTES {
        return Err(io(std::io::Error::other(format!(
            "larger than {MAX_MESH_BYTES} bytes, the most a mesh file may be"
        ))));
    }
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn write(name: &str, bytes: &[u8]) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("mesh-file-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        std::fs::write(&path, bytes).unwrap();
        path
    }

    /// A unit cube as OBJ (quads, 1-based indices, a material library that is not there).
    pub(crate) const CUBE_OBJ: &str = "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
        v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nusemtl steel\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\n\
        f 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

    #[test]
    fn an_obj_cube_is_read_closed_with_its_quads_split() {
        let mesh = read_mesh(&write("cube.OBJ", CUBE_OBJ.as_bytes())).unwrap();
        assert_eq!((mesh.vertices().len(), mesh.triangles().len()), (8, 12));
        assert!(mesh.is_closed());
        assert_eq!(mesh.bounds(), (DVec3::ZERO, DVec3::ONE));
    }

    #[test]
    fn lfs_pointers_corrupt_files_and_other_formats_are_named() {
        let pointer = b"version https://git-lfs.github.com/spec/v1\noid sha256:4d7a\nsize 12345\n";
        for name in ["link.stl", "link.dae", "link.obj"] {
            let path = write(name, pointer);
            assert!(
                matches!(read_mesh(&path), Err(SpheriseError::LfsPointer { path: p }) if p == path),
                "{name}"
            );
        }
        let e = read_mesh(&write("broken.dae", b"<COLLADA><library_geometries>")).unwrap_err();
        assert!(
            matches!(
                e,
                SpheriseError::Mesh {
                    format: "COLLADA",
                    ..
                }
            ),
            "{e}"
        );
        let e = read_mesh(&write("face.obj", b"v 0 0 0\nf 1 2 3\n")).unwrap_err();
        assert!(e.to_string().contains("face.obj"), "{e}");
        let e = read_mesh(&write("empty.obj", b"# nothing\n")).unwrap_err();
        assert!(e.to_string().contains("no triangle"), "{e}");
        let e = read_mesh(&write("link.ply", b"ply\n")).unwrap_err();
        assert!(
            matches!(&e, SpheriseError::UnsupportedFormat { extension, .. } if extension == "ply"),
            "{e}"
        );
    }
}
