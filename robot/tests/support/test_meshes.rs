//! Meshes and geometry the spherise tests share (`budget_cover.rs`, `sphere_cover.rs`,
//! `searched_cover.rs`): boxes, prisms and hollow boxes as meshes (random unions of them
//! for property tests), and the tests' own point-triangle distance and ray parity, written
//! apart from the cover's so that they check it.

use glam::{DMat3, DVec3};
use mit_star_robot::TriangleMesh;
use proptest::prelude::*;

/// The closest point of triangle `abc` to `p` (Ericson, Real-Time Collision Detection 5.1.5).
pub(crate) fn closest_on_triangle(p: DVec3, [a, b, c]: [DVec3; 3]) -> DVec3 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let denominator = 1.0 / (va + vb + vc);
    a + ab * (vb * denominator) + ac * (vc * denominator)
}

pub(crate) fn surface_distance(mesh: &TriangleMesh, p: DVec3) -> f64 {
    (0..mesh.triangles().len())
        .map(|t| p.distance(closest_on_triangle(p, mesh.corners(t))))
        .fold(f64::INFINITY, f64::min)
}

/// Whether `p` is inside one of the mesh's closed shells (connected components, which may
/// overlap).
pub(crate) fn inside(mesh: &TriangleMesh, p: DVec3) -> Option<bool> {
    let mut undecided = false;
    for shell in mesh.components().iter().filter(|s| s.is_closed()) {
        match inside_shell(shell, p) {
            Some(true) => return Some(true),
            Some(false) => {}
            None => undecided = true,
        }
    }
    (!undecided).then_some(false)
}

/// Whether `p` is inside the closed shell: the parity of a ray's crossings, along the first
/// of several fixed directions whose ray passes clear of every edge (`None` if none does).
pub(crate) fn inside_shell(mesh: &TriangleMesh, p: DVec3) -> Option<bool> {
    let directions = [
        DVec3::new(0.267, 0.534, 0.802),
        DVec3::new(-0.613, 0.239, 0.753),
        DVec3::new(0.871, -0.402, 0.283),
        DVec3::new(-0.118, -0.929, -0.351),
    ];
    'direction: for d in directions {
        let d = d.normalize();
        let mut hits = 0;
        for t in 0..mesh.triangles().len() {
            let [a, b, c] = mesh.corners(t);
            let (e1, e2) = (b - a, c - a);
            let h = d.cross(e2);
            let det = e1.dot(h);
            if det.abs() < 1e-14 {
                continue;
            }
            let s = p - a;
            let u = s.dot(h) / det;
            let q = s.cross(e1);
            let v = d.dot(q) / det;
            let w = 1.0 - u - v;
            let t_hit = e2.dot(q) / det;
            let margin = 1e-9;
            let grazes = [u, v, w].iter().any(|x| x.abs() < margin) || t_hit.abs() < 1e-12;
            if grazes && u > -margin && v > -margin && w > -margin && t_hit > -1e-12 {
                continue 'direction;
            }
            if u > 0.0 && v > 0.0 && w > 0.0 && t_hit > 0.0 {
                hits += 1;
            }
        }
        return Some(hits % 2 == 1);
    }
    None
}

/// A box of half extents `half` about the origin.
pub(crate) fn cube(half: DVec3) -> TriangleMesh {
    TriangleMesh::cuboid(half).unwrap()
}

/// A prism of `sides` sides around a cylinder of `radius` and `length` along z.
pub(crate) fn prism(radius: f64, length: f64, sides: u32) -> TriangleMesh {
    TriangleMesh::cylinder(radius, length, sides).unwrap()
}

/// A box of half extents `half` without its last face (two triangles): an open mesh.
pub(crate) fn open_box(half: DVec3) -> TriangleMesh {
    let closed = cube(half);
    TriangleMesh::new(
        closed.vertices().to_vec(),
        closed.triangles()[..10].to_vec(),
    )
    .unwrap()
}

/// A shape: `kind` 0 a box, 1 a prism, 2 a hollow box of six plates.
#[derive(Debug, Clone)]
pub(crate) struct Part {
    /// 0 a box, 1 a prism, 2 a hollow box.
    pub(crate) kind: u8,
    /// Half extents (a prism: radius, unused, half length).
    pub(crate) size: [f64; 3],
    /// Where its centre is.
    pub(crate) at: [f64; 3],
    /// A turn about z, and 0.7 of it about x (radians).
    pub(crate) turn: f64,
}

/// One to three random parts within about 0.15 m of the origin.
pub(crate) fn parts() -> impl Strategy<Value = Vec<Part>> {
    prop::collection::vec(
        (
            0_u8..3,
            [0.02..0.09_f64, 0.02..0.09_f64, 0.02..0.12_f64],
            [-0.06..0.06_f64, -0.06..0.06_f64, -0.06..0.06_f64],
            0.0..3.0_f64,
        )
            .prop_map(|(kind, size, at, turn)| Part {
                kind,
                size,
                at,
                turn,
            }),
        1..4,
    )
}

/// The parts as one mesh; with `jitter`, as a triangle soup whose every corner is moved by
/// up to `jitter` (cracks a vertex merge closes).
pub(crate) fn mesh_of(parts: &[Part], jitter: f64) -> TriangleMesh {
    let (mut vertices, mut triangles): (Vec<DVec3>, Vec<[u32; 3]>) = (Vec::new(), Vec::new());
    let mut add = |m: TriangleMesh, rotation: DMat3, at: DVec3| {
        let m = m.transformed(rotation, at, DVec3::ONE);
        let base = u32::try_from(vertices.len()).unwrap();
        vertices.extend(m.vertices());
        triangles.extend(m.triangles().iter().map(|t| t.map(|v| v + base)));
    };
    for p in parts {
        let rotation = DMat3::from_rotation_z(p.turn) * DMat3::from_rotation_x(p.turn * 0.7);
        let [x, y, z] = p.size;
        let at = DVec3::from(p.at);
        match p.kind {
            0 => add(cube(DVec3::new(x, y, z)), rotation, at),
            1 => add(prism(x, 2.0 * z, 12), rotation, at),
            _ => {
                for axis in 0..3 {
                    for sign in [-1.0, 1.0] {
                        let mut half = DVec3::new(x, y, z) + DVec3::splat(0.01);
                        half[axis] = 0.004;
                        let mut offset = DVec3::ZERO;
                        offset[axis] = sign * (DVec3::new(x, y, z)[axis] + 0.006);
                        add(
                            TriangleMesh::cuboid(half).unwrap(),
                            rotation,
                            at + rotation * offset,
                        );
                    }
                }
            }
        }
    }
    let mesh = TriangleMesh::new(vertices, triangles).unwrap();
    if jitter == 0.0 {
        return mesh;
    }
    let soup: Vec<[DVec3; 3]> = (0..mesh.triangles().len())
        .map(|t| {
            mesh.corners(t).map(|c| {
                let s = (c.x * 71.0 + c.y * 113.0 + c.z * 37.0 + t as f64 * 0.1).sin();
                c + DVec3::new(s, -s, 0.5 * s) * jitter
            })
        })
        .collect();
    TriangleMesh::from_soup(&soup).unwrap()
}
