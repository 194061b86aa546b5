//! [`Solid`]: the point set a mesh stands for — the enclosed solid of a closed mesh, the
//! surface of an open one — with distances (parry's bounding-volume tree) and a robust
//! ray-parity test of inside.

use glam::{DVec2, DVec3};
use parry3d_f64::query::PointQuery;
use parry3d_f64::shape::TriMesh;

use std::sync::atomic::AtomicBool;

use super::enclosed_fill::EnclosedFill;
use super::spherise_error::SpheriseError;
use super::triangle_mesh::TriangleMesh;

/// How many nearby rays a parity test tries before it gives up on a column whose rays all
/// graze an edge or a vertex.
const RAY_TRIES: u32 = 48;

/// A mesh as a point set: the union of the solids its closed shells bound (a shell is a
/// connected component; shells may overlap, as collision meshes made of parts do) and the
/// surfaces of its open ones.
pub(super) struct Solid {
    mesh: TriangleMesh,
    tree: TriMesh,
    shells: Vec<Shell>,
    /// Points this close to the surface count as part of the solid: the parity test may be
    /// wrong only within it (its rays are moved by less when they graze an edge).
    near: f64,
    /// A ray passing this close to a projected edge grazes it, and is moved.
    graze: f64,
    /// The space the mesh walls in, counted as solid ([`with_fill`](Self::with_fill)).
    fill: Option<EnclosedFill>,
}

/// One connected component of the mesh.
struct Shell {
    mesh: TriangleMesh,
    tree: TriMesh,
    closed: bool,
}

/// The crossings of a vertical line with each closed shell, sorted per shell.
pub(super) struct Column(Vec<Vec<f64>>);

impl Column {
    /// Whether height `z` of the column is inside some closed shell (an odd number of its
    /// crossings above).
    pub(super) fn inside(&self, z: f64) -> bool {
        self.0
            .iter()
            .any(|zs| (zs.len() - zs.partition_point(|&c| c <= z)) % 2 == 1)
    }

    /// The shells (indices among the closed ones) with `z` inside.
    fn shells_with(&self, z: f64) -> impl Iterator<Item = usize> + '_ {
        self.0
            .iter()
            .enumerate()
            .filter(move |(_, zs)| (zs.len() - zs.partition_point(|&c| c <= z)) % 2 == 1)
            .map(|(i, _)| i)
    }
}

fn tree(mesh: &TriangleMesh) -> Result<TriMesh, SpheriseError> {
    TriMesh::new(mesh.vertices().to_vec(), mesh.triangles().to_vec()).map_err(|e| {
        SpheriseError::BadMesh {
            what: "mesh".into(),
            why: e.to_string(),
        }
    })
}

impl Solid {
    /// The solid of `mesh`.
    ///
    /// # Errors
    /// [`SpheriseError::BadMesh`] if parry refuses the mesh (it has no triangle).
    pub(super) fn new(mesh: TriangleMesh) -> Result<Self, SpheriseError> {
        let shells = mesh
            .components()
            .into_iter()
            .map(|m| {
                Ok(Shell {
                    tree: tree(&m)?,
                    closed: m.is_closed(),
                    mesh: m,
                })
            })
            .collect::<Result<Vec<_>, SpheriseError>>()?;
        let (lo, hi) = mesh.bounds();
        let scale = 1.0 + (hi - lo).length() + lo.abs().max(hi.abs()).max_element();
        Ok(Self {
            tree: tree(&mesh)?,
            mesh,
            shells,
            near: 1e-8 * scale,
            graze: 1e-11 * scale,
            fill: None,
        })
    }

    /// The solid with the space its walls enclose filled, openings narrower than about
    /// `2·seal` sealed (`enclosed_fill.rs`): a hollow housing counts as its full volume.
    ///
    /// # Errors
    /// [`SpheriseError::Stopped`] once `stop` is raised.
    pub(super) fn with_fill(mut self, seal: f64, stop: &AtomicBool) -> Result<Self, SpheriseError> {
        self.fill = EnclosedFill::new(&self, seal, stop)?;
        Ok(self)
    }

    /// Whether some space walled in by the mesh is counted as solid.
    pub(super) fn is_filled(&self) -> bool {
        self.fill.is_some()
    }

    /// A lower bound on `p`'s depth in the filled space (positive only inside it).
    fn fill_depth(&self, p: DVec3) -> f64 {
        self.fill.as_ref().map_or(f64::NEG_INFINITY, |f| f.depth(p))
    }

    /// Whether `p` lies in the filled space beyond the mesh's own solid (certainly).
    pub(super) fn in_fill(&self, p: DVec3) -> bool {
        self.fill_depth(p) > 0.0
    }

    /// The mesh.
    pub(super) fn mesh(&self) -> &TriangleMesh {
        &self.mesh
    }

    /// Whether every shell is closed (otherwise the open ones stand for their surface only).
    pub(super) fn is_closed(&self) -> bool {
        self.shells.iter().all(|s| s.closed)
    }

    /// Whether some shell is closed (the solid has an inside).
    pub(super) fn has_inside(&self) -> bool {
        self.shells.iter().any(|s| s.closed)
    }

    /// The distance within which a point counts as on the surface
    /// ([`contains`](Self::contains) answers `Some(true)` there).
    pub(super) fn near(&self) -> f64 {
        self.near
    }

    /// The distance from `p` to the surface (every shell's).
    pub(super) fn surface_distance(&self, p: DVec3) -> f64 {
        self.tree.distance_to_local_point(p, false)
    }

    /// Whether `p` is in the solid: inside a closed shell by ray parity, or within
    /// [`near`](Self::near) of the surface. `None` if every ray tried grazed an edge.
    pub(super) fn contains(&self, p: DVec3) -> Option<bool> {
        if self.surface_distance(p) <= self.near || self.in_fill(p) {
            return Some(true);
        }
        if !self.has_inside() {
            return Some(false);
        }
        Some(self.column_crossings(p.x, p.y)?.inside(p.z))
    }

    /// How deep `p` lies in the solid: the radius of a ball about `p` inside one closed shell
    /// (the largest such shell distance), or, outside (or undecided, or within
    /// [`near`](Self::near) of the surface), minus the distance to the surface.
    pub(super) fn depth(&self, p: DVec3) -> f64 {
        let filled = self.fill_depth(p);
        let own = self.own_depth(p);
        if filled > 0.0 { own.max(filled) } else { own }
    }

    /// [`depth`](Self::depth) in the mesh's own solid (the fill left out).
    fn own_depth(&self, p: DVec3) -> f64 {
        let d = self.surface_distance(p);
        if d <= self.near || !self.has_inside() {
            return -d;
        }
        let Some(column) = self.column_crossings(p.x, p.y) else {
            return -d;
        };
        let closed: Vec<&Shell> = self.shells.iter().filter(|s| s.closed).collect();
        column
            .shells_with(p.z)
            .map(|i| closed[i].tree.distance_to_local_point(p, false) - self.near)
            .fold(-d, f64::max)
    }

    /// As [`depth`](Self::depth) for a point known to be inside by a decided parity test:
    /// with a single closed shell, its distance to the surface (no ray cast).
    pub(super) fn inside_depth(&self, p: DVec3) -> f64 {
        if let [shell] = &self.shells[..]
            && shell.closed
        {
            let d = self.surface_distance(p);
            let own = if d <= self.near { -d } else { d - self.near };
            return own.max(self.fill_depth(p));
        }
        self.depth(p)
    }

    /// The distance from `p` to the solid (0 inside it), conservative where parity is
    /// undecided (the distance to the surface).
    pub(super) fn distance(&self, p: DVec3) -> f64 {
        match self.contains(p) {
            Some(true) => 0.0,
            _ => self.surface_distance(p),
        }
    }

    /// The heights at which a ray parallel to `z` through `(x, y)`, moved by less than
    /// [`near`](Self::near) if it grazes an edge, crosses each closed shell. A point of that
    /// column farther than `near` from the surface is inside a shell iff an odd number of
    /// its crossings lie above it. `None` if every ray tried grazed an edge.
    pub(super) fn column_crossings(&self, x: f64, y: f64) -> Option<Column> {
        let step = self.near / f64::from(2 * RAY_TRIES);
        (0..RAY_TRIES).find_map(|k| {
            let shift = step * f64::from(k);
            let q = DVec2::new(x + 0.754_877_666 * shift, y + 0.569_840_291 * shift);
            let mut column = Vec::new();
            for shell in self.shells.iter().filter(|s| s.closed) {
                let mut crossings = Vec::new();
                for t in 0..shell.mesh.triangles().len() {
                    match crossing(shell.mesh.corners(t), q, self.graze) {
                        Crossing::Grazes => return None,
                        Crossing::At(z) => crossings.push(z),
                        Crossing::Misses => {}
                    }
                }
                crossings.sort_by(f64::total_cmp);
                column.push(crossings);
            }
            Some(Column(column))
        })
    }
}

enum Crossing {
    Misses,
    At(f64),
    Grazes,
}

/// Where the vertical line through `q` crosses the triangle, if it does; `Grazes` when it
/// passes within `graze` of a projected edge (the parity would be unreliable).
fn crossing([a, b, c]: [DVec3; 3], q: DVec2, graze: f64) -> Crossing {
    let (a2, b2, c2) = (a.truncate(), b.truncate(), c.truncate());
    let lo = a2.min(b2).min(c2) - DVec2::splat(graze);
    let hi = a2.max(b2).max(c2) + DVec2::splat(graze);
    if q.x < lo.x || q.y < lo.y || q.x > hi.x || q.y > hi.y {
        return Crossing::Misses;
    }
    if [(a2, b2), (b2, c2), (c2, a2)]
        .iter()
        .any(|&(u, v)| segment_distance(q, u, v) <= graze)
    {
        return Crossing::Grazes;
    }
    let orient = |u: DVec2, v: DVec2| (v - u).perp_dot(q - u);
    let (wa, wb, wc) = (orient(b2, c2), orient(c2, a2), orient(a2, b2));
    let area = wa + wb + wc;
    let same = |w: f64| (w > 0.0) == (area > 0.0);
    if area == 0.0 || !(same(wa) && same(wb) && same(wc)) {
        return Crossing::Misses;
    }
    Crossing::At((wa * a.z + wb * b.z + wc * c.z) / area)
}

/// The distance from `q` to the segment `uv` in the plane.
fn segment_distance(q: DVec2, u: DVec2, v: DVec2) -> f64 {
    let d = v - u;
    let length2 = d.length_squared();
    let t = if length2 > 0.0 {
        ((q - u).dot(d) / length2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (u + d * t - q).length()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overlapping_shells_make_one_solid() {
        // Two cubes overlapping in [0.5, 1]³-like slabs: the overlap is inside (parity over
        // the whole mesh would call it outside), and its depth counts one cube's inner ball.
        let a = TriangleMesh::cuboid(DVec3::splat(1.0)).unwrap();
        let b = a.transformed(glam::DMat3::IDENTITY, DVec3::new(1.5, 0.0, 0.0), DVec3::ONE);
        let mut vertices = a.vertices().to_vec();
        vertices.extend(b.vertices());
        let mut triangles = a.triangles().to_vec();
        triangles.extend(b.triangles().iter().map(|t| t.map(|i| i + 8)));
        let both = Solid::new(TriangleMesh::new(vertices, triangles).unwrap()).unwrap();
        assert_eq!(both.shells.len(), 2);
        let overlap = DVec3::new(0.75, 0.0, 0.0);
        assert_eq!(both.contains(overlap), Some(true));
        // In the overlap, 0.25 from the first cube's face x = 1 and the second's x = 0.5.
        assert!(
            (both.depth(overlap) - 0.25).abs() < 1e-6,
            "{}",
            both.depth(overlap)
        );
        assert!((both.depth(DVec3::new(2.0, 0.0, 0.0)) - 0.5).abs() < 1e-6);
        assert_eq!(both.contains(DVec3::new(2.6, 0.0, 0.0)), Some(false));
    }

    #[test]
    fn a_cube_contains_its_inside_and_measures_distances() {
        let cube = Solid::new(TriangleMesh::cuboid(DVec3::splat(1.0)).unwrap()).unwrap();
        assert!(cube.is_closed() && cube.has_inside());
        assert_eq!(cube.shells.len(), 1);
        assert!((cube.depth(DVec3::new(0.5, 0.0, 0.0)) - 0.5).abs() < 1e-6);
        assert!((cube.depth(DVec3::new(1.5, 0.0, 0.0)) + 0.5).abs() < 1e-12);
        // Points on the columns of the cube's edges and vertices graze and are moved.
        for p in [
            DVec3::ZERO,
            DVec3::new(0.9, -0.9, 0.5),
            DVec3::new(0.0, 0.0, 0.99),
        ] {
            assert_eq!(cube.contains(p), Some(true), "{p}");
        }
        for p in [
            DVec3::new(1.1, 0.0, 0.0),
            DVec3::new(0.0, 0.0, -1.5),
            DVec3::new(1.0, 1.0, 2.0),
        ] {
            assert_eq!(cube.contains(p), Some(false), "{p}");
        }
        assert!((cube.surface_distance(DVec3::new(0.5, 0.0, 0.0)) - 0.5).abs() < 1e-12);
        assert_eq!(cube.distance(DVec3::new(0.5, 0.0, 0.0)), 0.0);
        assert!((cube.distance(DVec3::new(3.0, 0.0, 0.0)) - 2.0).abs() < 1e-12);
        // On the surface counts as in.
        assert_eq!(cube.contains(DVec3::new(1.0, 0.3, 0.2)), Some(true));
    }

    #[test]
    fn an_open_mesh_is_its_surface() {
        let sheet =
            TriangleMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]).unwrap();
        let sheet = Solid::new(sheet).unwrap();
        assert!(!sheet.is_closed() && !sheet.has_inside());
        assert_eq!(sheet.contains(DVec3::new(0.2, 0.2, 0.0)), Some(true));
        assert_eq!(sheet.contains(DVec3::new(0.2, 0.2, 0.1)), Some(false));
        assert!((sheet.distance(DVec3::new(0.2, 0.2, -0.25)) - 0.25).abs() < 1e-12);
    }
}
