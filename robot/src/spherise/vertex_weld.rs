//! [`VertexWeld`]: a mesh whose shells are open only because the exporter wrote the same
//! corner twice at slightly different coordinates (float noise, or two boundary chains a few
//! micrometres apart), closed by merging vertices that lie within a small distance.
//!
//! Why it matters: an open shell stands for its surface only, so its cover cannot centre a
//! sphere inside it and takes many small spheres hugging the surface. The Kinova Gen3's arm
//! meshes (cuRobo's copy of `kortex_description`) have 44 to 144 unmatched edges each; merging
//! vertices within 0.1 µm closes six of its eight meshes, within 30 µm all eight.
//!
//! Merging is a union of vertices within `w` of each other (transitively: a chain may move a
//! vertex farther than `w`, and the move measured is the one reported). A triangle whose
//! corners merge collapses to a segment or a point; it is dropped only if that segment is an
//! edge (that point a vertex) of a triangle kept, so the welded mesh still passes through
//! every collapsed triangle's image. Every point of an original triangle then lies within
//! [`displacement`](VertexWeld::displacement) of the welded mesh's surface (a convex
//! combination of corners moves by at most the largest corner move), and a cover of the
//! welded solid grown by that much contains the original mesh.

use std::collections::{HashMap, HashSet};

use glam::DVec3;

use super::spherise_error::SpheriseError;
use super::triangle_mesh::TriangleMesh;

/// Merge distances tried, as fractions of the largest one allowed (the smallest that closes
/// the mesh is kept).
const STEPS: [f64; 6] = [1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0];

/// A mesh closed by merging nearby vertices.
#[derive(Debug, Clone)]
pub(super) struct VertexWeld {
    /// The closed mesh.
    pub(super) mesh: TriangleMesh,
    /// The merge distance used.
    pub(super) distance: f64,
    /// The largest distance any vertex moved.
    pub(super) displacement: f64,
}

impl VertexWeld {
    /// The mesh closed by the smallest merge distance of a few tried up to `max_distance`
    /// (moving no vertex by more than twice that), or `None` if `mesh` is closed already or
    /// no distance tried closes it.
    ///
    /// # Errors
    /// [`SpheriseError::BadMesh`] only if a welded mesh is refused (it never is: it keeps a
    /// triangle of the original).
    pub(super) fn closing(
        mesh: &TriangleMesh,
        max_distance: f64,
    ) -> Result<Option<Self>, SpheriseError> {
        if mesh.is_closed() || !(max_distance.is_finite() && max_distance > 0.0) {
            return Ok(None);
        }
        for step in STEPS {
            let distance = max_distance * step;
            if let Some(weld) = Self::merged(mesh, distance)?
                && weld.mesh.is_closed()
                && weld.displacement <= 2.0 * max_distance
            {
                return Ok(Some(weld));
            }
        }
        Ok(None)
    }

    /// `mesh` with vertices within `distance` merged, or `None` if a collapsed triangle
    /// would be lost (its image is not part of a kept triangle) or nothing is left.
    fn merged(mesh: &TriangleMesh, distance: f64) -> Result<Option<Self>, SpheriseError> {
        let vertices = mesh.vertices();
        let mut parent: Vec<usize> = (0..vertices.len()).collect();
        fn root(parent: &mut [usize], mut v: usize) -> usize {
            while parent[v] != v {
                parent[v] = parent[parent[v]];
                v = parent[v];
            }
            v
        }
        // Vertices by cell of edge `distance`: a vertex's partners lie in the 27 cells about.
        let key = |p: DVec3| (p / distance).floor().as_i64vec3().to_array();
        let mut cells: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
        for (i, &p) in vertices.iter().enumerate() {
            cells.entry(key(p)).or_default().push(i);
        }
        let d2 = distance * distance;
        for (i, &p) in vertices.iter().enumerate() {
            let [x, y, z] = key(p);
            for dx in -1..=1 {
                for dy in -1..=1 {
                    for dz in -1..=1 {
                        let Some(near) = cells.get(&[x + dx, y + dy, z + dz]) else {
                            continue;
                        };
                        for &j in near {
                            if j > i && vertices[j].distance_squared(p) <= d2 {
                                let (a, b) = (root(&mut parent, i), root(&mut parent, j));
                                // The smaller index is the representative.
                                parent[a.max(b)] = a.min(b);
                            }
                        }
                    }
                }
            }
        }
        let rep: Vec<usize> = (0..vertices.len()).map(|v| root(&mut parent, v)).collect();
        let displacement = vertices
            .iter()
            .zip(&rep)
            .map(|(&p, &r)| p.distance(vertices[r]))
            .fold(0.0, f64::max);
        let mut kept: Vec<[u32; 3]> = Vec::new();
        let mut collapsed: Vec<[usize; 3]> = Vec::new();
        for t in mesh.triangles() {
            let w = t.map(|v| rep[v as usize]);
            if w[0] == w[1] || w[1] == w[2] || w[0] == w[2] {
                collapsed.push(w);
            } else {
                kept.push(w.map(|v| u32::try_from(v).unwrap_or(u32::MAX)));
            }
        }
        if kept.is_empty() {
            return Ok(None);
        }
        let edge = |a: usize, b: usize| (a.min(b), a.max(b));
        let mut edges: HashSet<(usize, usize)> = HashSet::new();
        let mut corners: HashSet<usize> = HashSet::new();
        for t in &kept {
            let t = t.map(|v| v as usize);
            for k in 0..3 {
                edges.insert(edge(t[k], t[(k + 1) % 3]));
                corners.insert(t[k]);
            }
        }
        let lost = collapsed.iter().any(|&[a, b, c]| {
            let (u, v) = if a == b { (a, c) } else { (a, b) };
            if u == v {
                !corners.contains(&u)
            } else {
                !edges.contains(&edge(u, v))
            }
        });
        if lost {
            return Ok(None);
        }
        // Only the vertices kept triangles use, renumbered.
        let mut index: HashMap<u32, u32> = HashMap::new();
        let mut used = Vec::new();
        let triangles = kept
            .iter()
            .map(|t| {
                t.map(|v| {
                    *index.entry(v).or_insert_with(|| {
                        used.push(vertices[v as usize]);
                        u32::try_from(used.len() - 1).unwrap_or(u32::MAX)
                    })
                })
            })
            .collect();
        Ok(Some(Self {
            mesh: TriangleMesh::new(used, triangles)?,
            distance,
            displacement,
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cube whose every triangle has its own corners, each moved by up to `noise`.
    fn cracked_cube(noise: f64) -> TriangleMesh {
        let cube = TriangleMesh::cuboid(DVec3::splat(0.1)).unwrap();
        let mut soup = Vec::new();
        for (t, _) in cube.triangles().iter().enumerate() {
            let corners = cube.corners(t);
            soup.push(corners.map(|c| {
                // A deterministic jitter per corner and triangle.
                let s = (c.x * 7.0 + c.y * 13.0 + c.z * 17.0 + t as f64).sin();
                c + DVec3::new(s, -s, 0.5 * s) * noise
            }));
        }
        TriangleMesh::from_soup(&soup).unwrap()
    }

    #[test]
    fn a_cracked_cube_is_closed_by_the_smallest_distance_that_does() {
        let cracked = cracked_cube(1e-6);
        assert!(!cracked.is_closed());
        let weld = VertexWeld::closing(&cracked, 1e-3).unwrap().unwrap();
        assert!(weld.mesh.is_closed());
        assert_eq!(weld.mesh.triangles().len(), 12);
        assert_eq!(weld.mesh.vertices().len(), 8);
        // The jitter moves corners by up to 1.5e-6 each, so pairs lie within 3e-6 +: the
        // first distance tried that is above that (1e-5) closes it.
        assert!((weld.distance - 1e-5).abs() < 1e-12, "{}", weld.distance);
        assert!(weld.displacement <= weld.distance * 3.0 && weld.displacement > 0.0);
        // A closed mesh is left alone; a crack wider than the distances allowed stays open.
        assert!(
            VertexWeld::closing(&TriangleMesh::cuboid(DVec3::ONE).unwrap(), 1e-3)
                .unwrap()
                .is_none()
        );
        assert!(
            VertexWeld::closing(&cracked_cube(1e-2), 1e-3)
                .unwrap()
                .is_none()
        );
    }

    #[test]
    fn a_lone_sliver_is_never_dropped() {
        // A single thin triangle: merging its two close corners would leave nothing of it.
        let sliver = TriangleMesh::new(
            vec![DVec3::ZERO, DVec3::new(1e-7, 0.0, 0.0), DVec3::Y],
            vec![[0, 1, 2]],
        )
        .unwrap();
        assert!(VertexWeld::merged(&sliver, 1e-6).unwrap().is_none());
    }
}
