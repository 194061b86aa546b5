//! [`TriangleMesh`]: triangles over shared vertices, as read from a mesh file or made for a
//! URDF primitive.

use std::collections::HashMap;

use glam::{DMat3, DVec3};

use super::spherise_error::SpheriseError;

/// A triangle mesh: vertices and triangles indexing them. It may be open (a surface) or
/// closed (every edge shared by an even number of triangles: the boundary of a solid).
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleMesh {
    vertices: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
}

impl TriangleMesh {
    /// A mesh from vertices and triangles.
    ///
    /// # Errors
    /// [`SpheriseError::BadMesh`] if there is no triangle, an index is out of range or a
    /// coordinate is not finite.
    pub fn new(vertices: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Result<Self, SpheriseError> {
        let bad = |why: String| SpheriseError::BadMesh {
            what: "mesh".into(),
            why,
        };
        if triangles.is_empty() {
            return Err(bad("no triangle".into()));
        }
        if let Some(v) = vertices.iter().find(|v| !v.is_finite()) {
            return Err(bad(format!("vertex {v} is not finite")));
        }
        if let Some(t) = triangles
            .iter()
            .find(|t| t.iter().any(|&i| i as usize >= vertices.len()))
        {
            return Err(bad(format!(
                "triangle {t:?} indexes past the {} vertices",
                vertices.len()
            )));
        }
        Ok(Self {
            vertices,
            triangles,
        })
    }

    /// A mesh from a "soup" of triangles given by their corners (as STL stores them):
    /// corners with identical coordinates become one vertex.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub fn from_soup(soup: &[[DVec3; 3]]) -> Result<Self, SpheriseError> {
        let mut index: HashMap<[u64; 3], u32> = HashMap::new();
        let mut vertices = Vec::new();
        let mut triangles = Vec::with_capacity(soup.len());
        for corners in soup {
            let mut t = [0_u32; 3];
            for (slot, &v) in t.iter_mut().zip(corners) {
                // +0.0 turns -0.0 into 0.0, so the two zeros are one vertex.
                let key = (v + DVec3::ZERO).to_array().map(f64::to_bits);
                *slot = *index.entry(key).or_insert_with(|| {
                    vertices.push(v);
                    u32::try_from(vertices.len() - 1).unwrap_or(u32::MAX)
                });
            }
            triangles.push(t);
        }
        Self::new(vertices, triangles)
    }

    /// The closed box `[-h, h]` (12 triangles).
    ///
    /// # Errors
    /// [`SpheriseError::BadMesh`] if a half extent is not finite.
    pub fn cuboid(half_extents: DVec3) -> Result<Self, SpheriseError> {
        let vertices = (0..8)
            .map(|i| {
                let sign = |bit: u32| if i & (1 << bit) == 0 { -1.0 } else { 1.0 };
                half_extents * DVec3::new(sign(0), sign(1), sign(2))
            })
            .collect();
        // Two triangles per face, outward facing; corner i has bit k set for +axis k.
        let faces: [[u32; 4]; 6] = [
            [0, 2, 6, 4],
            [1, 5, 7, 3],
            [0, 4, 5, 1],
            [2, 3, 7, 6],
            [0, 1, 3, 2],
            [4, 6, 7, 5],
        ];
        let triangles = faces
            .iter()
            .flat_map(|&[a, b, c, d]| [[a, b, c], [a, c, d]])
            .collect();
        Self::new(vertices, triangles)
    }

    /// A closed prism along `z`, centred at the origin, that contains the cylinder of the
    /// given radius and length: its `segments`-gon is circumscribed about the circle.
    ///
    /// # Errors
    /// [`SpheriseError::BadMesh`] if the radius or length is not finite, or fewer than 3
    /// segments.
    pub fn cylinder(radius: f64, length: f64, segments: u32) -> Result<Self, SpheriseError> {
        if segments < 3 {
            return Err(SpheriseError::BadMesh {
                what: "cylinder".into(),
                why: format!("{segments} segments (at least 3)"),
            });
        }
        let step = std::f64::consts::TAU / f64::from(segments);
        let outer = radius / (step / 2.0).cos();
        let half = length / 2.0;
        let mut vertices = vec![DVec3::new(0.0, 0.0, -half), DVec3::new(0.0, 0.0, half)];
        for i in 0..segments {
            let (s, c) = (step * f64::from(i)).sin_cos();
            vertices.push(DVec3::new(outer * c, outer * s, -half));
            vertices.push(DVec3::new(outer * c, outer * s, half));
        }
        let ring = |i: u32| 2 + 2 * (i % segments);
        let mut triangles = Vec::new();
        for i in 0..segments {
            let (b0, t0, b1, t1) = (ring(i), ring(i) + 1, ring(i + 1), ring(i + 1) + 1);
            triangles.extend([[0, b1, b0], [1, t0, t1], [b0, b1, t1], [b0, t1, t0]]);
        }
        Self::new(vertices, triangles)
    }

    /// The vertices.
    pub fn vertices(&self) -> &[DVec3] {
        &self.vertices
    }

    /// The triangles, as indices into [`vertices`](Self::vertices).
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// The corners of triangle `t`.
    pub fn corners(&self, t: usize) -> [DVec3; 3] {
        self.triangles[t].map(|i| self.vertices[i as usize])
    }

    /// The mesh scaled per axis, then rotated, then translated: `p ↦ R (s ⊙ p) + t`, as a
    /// URDF places a `<mesh scale>` by its `<collision><origin>`. A scale with an odd number
    /// of negative factors flips the triangles' orientation, which no query here depends on.
    pub fn transformed(&self, rotation: DMat3, translation: DVec3, scale: DVec3) -> Self {
        Self {
            vertices: self
                .vertices
                .iter()
                .map(|&v| rotation * (v * scale) + translation)
                .collect(),
            triangles: self.triangles.clone(),
        }
    }

    /// Whether every edge is shared by an even number of triangles: then the mesh bounds a
    /// solid and the ray-parity test of inside is well defined.
    pub fn is_closed(&self) -> bool {
        let mut edges: HashMap<(u32, u32), u32> = HashMap::new();
        for t in &self.triangles {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                *edges.entry((a.min(b), a.max(b))).or_default() += 1;
            }
        }
        edges.values().all(|n| n % 2 == 0)
    }

    /// The connected components (triangles sharing vertices, transitively), each with only
    /// its own vertices, in the order of their first triangle.
    pub fn components(&self) -> Vec<TriangleMesh> {
        let mut parent: Vec<usize> = (0..self.vertices.len()).collect();
        fn root(parent: &mut [usize], mut v: usize) -> usize {
            while parent[v] != v {
                parent[v] = parent[parent[v]];
                v = parent[v];
            }
            v
        }
        for t in &self.triangles {
            for k in 1..3 {
                let (a, b) = (
                    root(&mut parent, t[0] as usize),
                    root(&mut parent, t[k] as usize),
                );
                parent[a] = b;
            }
        }
        let mut which: HashMap<usize, usize> = HashMap::new();
        let mut parts: Vec<(HashMap<u32, u32>, TriangleMesh)> = Vec::new();
        for t in &self.triangles {
            let r = root(&mut parent, t[0] as usize);
            let index = *which.entry(r).or_insert_with(|| {
                parts.push((
                    HashMap::new(),
                    TriangleMesh {
                        vertices: Vec::new(),
                        triangles: Vec::new(),
                    },
                ));
                parts.len() - 1
            });
            let (map, part) = &mut parts[index];
            let local = t.map(|v| {
                *map.entry(v).or_insert_with(|| {
                    part.vertices.push(self.vertices[v as usize]);
                    u32::try_from(part.vertices.len() - 1).unwrap_or(u32::MAX)
                })
            });
            part.triangles.push(local);
        }
        parts.into_iter().map(|(_, part)| part).collect()
    }

    /// The smallest and largest coordinates of the vertices.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        self.vertices.iter().fold(
            (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
            |(lo, hi), &v| (lo.min(v), hi.max(v)),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn primitives_are_closed_and_contain_their_shape() {
        let cube = TriangleMesh::cuboid(DVec3::new(1.0, 2.0, 3.0)).unwrap();
        assert_eq!(cube.triangles().len(), 12);
        assert!(cube.is_closed());
        assert_eq!(
            cube.bounds(),
            (DVec3::new(-1.0, -2.0, -3.0), DVec3::new(1.0, 2.0, 3.0))
        );
        let cylinder = TriangleMesh::cylinder(0.5, 2.0, 16).unwrap();
        assert!(cylinder.is_closed());
        // Each rim edge's midpoint lies on or outside the circle: the prism contains it.
        for (i, _) in cylinder.triangles().iter().enumerate() {
            let [a, b, _] = cylinder.corners(i);
            if (a.z - b.z).abs() < 1e-12
                && a.truncate().length() > 0.1
                && b.truncate().length() > 0.1
            {
                assert!(((a + b) / 2.0).truncate().length() >= 0.5 - 1e-12);
            }
        }
        assert!(TriangleMesh::cylinder(0.5, 1.0, 2).is_err());
    }

    #[test]
    fn an_open_mesh_is_not_closed_and_bad_meshes_are_refused() {
        let open =
            TriangleMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]).unwrap();
        assert!(!open.is_closed());
        assert_eq!(open.components(), std::slice::from_ref(&open));
        let cube = TriangleMesh::cuboid(DVec3::ONE).unwrap();
        let mut vertices = cube.vertices().to_vec();
        vertices.extend(open.vertices());
        let mut triangles = cube.triangles().to_vec();
        triangles.push([8, 9, 10]);
        let parts = TriangleMesh::new(vertices, triangles).unwrap().components();
        assert_eq!(parts.len(), 2);
        assert_eq!(parts[0].triangles().len(), 12);
        assert!(parts[0].is_closed());
        assert_eq!(parts[0].bounds(), cube.bounds());
        assert_eq!(parts[1], open);
        assert!(TriangleMesh::new(vec![DVec3::ZERO], vec![[0, 0, 1]]).is_err());
        assert!(TriangleMesh::new(vec![DVec3::ZERO], vec![]).is_err());
        assert!(TriangleMesh::new(vec![DVec3::NAN; 3], vec![[0, 1, 2]]).is_err());
    }

    #[test]
    fn transforms_scale_then_rotate_then_translate() {
        let mesh = TriangleMesh::new(vec![DVec3::X, DVec3::Y, DVec3::Z], vec![[0, 1, 2]]).unwrap();
        let quarter = DMat3::from_rotation_z(std::f64::consts::FRAC_PI_2);
        let moved = mesh.transformed(quarter, DVec3::new(0.0, 0.0, 1.0), DVec3::splat(2.0));
        assert!((moved.vertices()[0] - DVec3::new(0.0, 2.0, 1.0)).length() < 1e-12);
        assert!((moved.vertices()[2] - DVec3::new(0.0, 0.0, 3.0)).length() < 1e-12);
    }
}
