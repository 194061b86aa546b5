//! Spheres and capsules as closed triangle meshes (for visual elements).

use std::f64::consts::PI;

use glam::DVec3;

use crate::{SpheriseError, TriangleMesh};

/// A closed capsule along `z`, centred: a cylinder of `length` between two hemispheres of
/// `radius` (a sphere for `length = 0`), `segments` vertices a ring and `rings` bands from
/// pole to pole (made even). Vertices lie on the surface; triangles face outwards.
///
/// # Errors
/// [`SpheriseError::BadMesh`] for fewer than 3 segments or 2 rings, or a radius or length
/// that is not finite.
pub(super) fn capsule(
    radius: f64,
    length: f64,
    segments: u32,
    rings: u32,
) -> Result<TriangleMesh, SpheriseError> {
    if segments < 3 || rings < 2 {
        return Err(SpheriseError::BadMesh {
            what: "capsule".into(),
            why: format!("{segments} segments and {rings} rings (at least 3 and 2)"),
        });
    }
    let rings = rings + rings % 2;
    let half = length / 2.0;
    // (height, radius) of each ring, top to bottom; the equator twice when there is a length.
    let mut circles = Vec::new();
    for k in 1..rings {
        let (s, c) = (PI * f64::from(k) / f64::from(rings)).sin_cos();
        match (2 * k).cmp(&rings) {
            std::cmp::Ordering::Less => circles.push((half + radius * c, radius * s)),
            std::cmp::Ordering::Greater => circles.push((-half + radius * c, radius * s)),
            std::cmp::Ordering::Equal => {
                circles.push((half, radius));
                if length > 0.0 {
                    circles.push((-half, radius));
                }
            }
        }
    }
    let step = std::f64::consts::TAU / f64::from(segments);
    let mut vertices = vec![DVec3::new(0.0, 0.0, half + radius)];
    for &(z, r) in &circles {
        for i in 0..segments {
            let (s, c) = (step * f64::from(i)).sin_cos();
            vertices.push(DVec3::new(r * c, r * s, z));
        }
    }
    let bottom = u32::try_from(vertices.len()).unwrap_or(u32::MAX);
    vertices.push(DVec3::new(0.0, 0.0, -half - radius));
    let at = |ring: usize, i: u32| 1 + ring as u32 * segments + i % segments;
    let last = circles.len() - 1;
    let mut triangles = Vec::new();
    for i in 0..segments {
        triangles.push([0, at(0, i), at(0, i + 1)]);
        for ring in 0..last {
            let (a0, a1, b0, b1) = (
                at(ring, i),
                at(ring, i + 1),
                at(ring + 1, i),
                at(ring + 1, i + 1),
            );
            triangles.extend([[a0, b0, b1], [a0, b1, a1]]);
        }
        triangles.push([bottom, at(last, i + 1), at(last, i)]);
    }
    TriangleMesh::new(vertices, triangles)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The enclosed volume by the divergence theorem (positive when triangles face out).
    fn volume(mesh: &TriangleMesh) -> f64 {
        (0..mesh.triangles().len())
            .map(|t| {
                let [a, b, c] = mesh.corners(t);
                a.dot(b.cross(c)) / 6.0
            })
            .sum()
    }

    #[test]
    fn spheres_and_capsules_are_closed_outward_and_near_their_volume() {
        let sphere = capsule(0.5, 0.0, 32, 16).unwrap();
        assert!(sphere.is_closed());
        assert!(
            sphere
                .vertices()
                .iter()
                .all(|v| (v.length() - 0.5).abs() < 1e-12)
        );
        let exact = 4.0 / 3.0 * PI * 0.125;
        assert!(
            (volume(&sphere) / exact - 1.0).abs() < 0.03,
            "{}",
            volume(&sphere)
        );
        let pill = capsule(0.1, 1.0, 32, 15).unwrap();
        assert!(pill.is_closed());
        let exact = PI * 0.01 * 1.0 + 4.0 / 3.0 * PI * 0.001;
        assert!(
            (volume(&pill) / exact - 1.0).abs() < 0.03,
            "{}",
            volume(&pill)
        );
        let (lo, hi) = pill.bounds();
        assert!((hi.z - 0.6).abs() < 1e-12 && (lo.z + 0.6).abs() < 1e-12);
        assert!(capsule(0.1, 1.0, 2, 4).is_err());
        assert!(capsule(f64::NAN, 1.0, 8, 4).is_err());
    }
}
