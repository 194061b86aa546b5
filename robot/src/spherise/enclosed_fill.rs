//! [`EnclosedFill`]: the space a mesh walls in — a hollow housing's inside — counted as part
//! of the solid a cover fills.
//!
//! Why: CAD exports of robot links are often thin-walled shells. The Kinova Gen3's arm
//! meshes bound 60 to 200 cm³ of wall each, inside tubes of 92 mm whose volume is ten times
//! that; as solids they are walls, and a sphere spanning the tube would reach "beyond the
//! solid" into the hollow by the tube's radius, so only small spheres hugging the walls fit.
//! For a planner the hollow is robot: no obstacle gets in. So the cover fills the solid `F`:
//! every point that the outside cannot reach.
//!
//! `F` is the complement of `E`, the union of the balls of radius `seal` about the *exterior*
//! corners of a grid of edge `h ≤ 2·seal`: corners farther than `seal` from the surface,
//! outside every closed shell, and joined to the grid's boundary through such corners along
//! grid edges. (An edge between two corners farther than `h/2` from the surface cannot cross
//! it, so the outside reached is really outside; the balls do not touch the surface either.)
//! Openings narrower than about `2·seal` are sealed. `F` contains the mesh's own solid, and
//! the distance from a point `p` to `E` is at least `max_q (r(q) − |p − q|) − seal` over the
//! corners `q` of `p`'s cell, where `r(q)` is the distance from `q` to the nearest exterior
//! corner (an exact distance transform): a rigorous lower bound on `p`'s depth in `F`.

use std::collections::VecDeque;
use std::sync::atomic::AtomicBool;

use glam::DVec3;

use super::cell_grid::check;
use super::solid::Solid;
use super::spherise_error::SpheriseError;

/// The most grid corners a fill takes: a finer grid is coarsened (and the seal widened).
const MAX_FILL_CORNERS: f64 = 2_000_000.0;

/// Empty grid layers about the mesh's bounds (the exterior's start).
const PAD: f64 = 2.0;

/// The solid a mesh walls in, beyond its own (see the module's doc).
#[derive(Debug, Clone)]
pub(super) struct EnclosedFill {
    origin: DVec3,
    h: f64,
    /// Corners per axis.
    n: [usize; 3],
    seal: f64,
    /// Per corner: the distance to the nearest exterior corner.
    reach: Vec<f64>,
}

impl EnclosedFill {
    /// The fill of `solid` sealing openings narrower than about `2·seal`, or `None` if the
    /// outside reaches every corner outside the solid (nothing is walled in).
    ///
    /// # Errors
    /// [`SpheriseError::Stopped`] once `stop` is raised (polled per column).
    pub(super) fn new(
        solid: &Solid,
        seal: f64,
        stop: &AtomicBool,
    ) -> Result<Option<Self>, SpheriseError> {
        let (lo, hi) = solid.mesh().bounds();
        let mut seal = seal;
        let corners_for =
            |h: f64| (((hi - lo) / h).ceil() + DVec3::splat(2.0 * PAD + 2.0)).element_product();
        while corners_for(seal) > MAX_FILL_CORNERS {
            seal *= 1.25;
        }
        let h = seal;
        let origin = lo - h * (DVec3::splat(PAD) + DVec3::new(0.371, 0.419, 0.443));
        let n = (((hi - origin) / h).ceil() + DVec3::splat(PAD + 1.0))
            .as_usizevec3()
            .to_array();
        let index = |[i, j, k]: [usize; 3]| (i * n[1] + j) * n[2] + k;
        let corner = |[i, j, k]: [usize; 3]| origin + h * DVec3::new(i as f64, j as f64, k as f64);
        // Open corners: outside every closed shell (decided) and farther than the seal.
        let mut open = vec![false; n[0] * n[1] * n[2]];
        for i in 0..n[0] {
            for j in 0..n[1] {
                check(stop)?;
                let base = corner([i, j, 0]);
                let Some(column) = solid.column_crossings(base.x, base.y) else {
                    continue;
                };
                for k in 0..n[2] {
                    let p = corner([i, j, k]);
                    open[index([i, j, k])] =
                        !column.inside(p.z) && solid.surface_distance(p) > seal;
                }
            }
        }
        // The exterior: open corners reached from the grid's boundary.
        let mut exterior = vec![false; open.len()];
        let mut queue = VecDeque::new();
        for i in 0..n[0] {
            for j in 0..n[1] {
                for k in 0..n[2] {
                    let edge = [i, j, k].iter().zip(n).any(|(&c, m)| c == 0 || c + 1 == m);
                    if edge && open[index([i, j, k])] {
                        exterior[index([i, j, k])] = true;
                        queue.push_back([i, j, k]);
                    }
                }
            }
        }
        while let Some(c) = queue.pop_front() {
            for axis in 0..3 {
                for up in [false, true] {
                    let mut d = c;
                    if up && d[axis] + 1 < n[axis] {
                        d[axis] += 1;
                    } else if !up && d[axis] > 0 {
                        d[axis] -= 1;
                    } else {
                        continue;
                    }
                    let at = index(d);
                    if open[at] && !exterior[at] {
                        exterior[at] = true;
                        queue.push_back(d);
                    }
                }
            }
        }
        // Nothing walled in: every open corner is exterior.
        if open.iter().zip(&exterior).all(|(o, e)| o == e) {
            return Ok(None);
        }
        check(stop)?;
        let reach = distance_transform(&exterior, n)
            .into_iter()
            .map(|d2| d2.sqrt() * h)
            .collect();
        Ok(Some(Self {
            origin,
            h,
            n,
            seal,
            reach,
        }))
    }

    /// A lower bound on `p`'s depth in the filled solid (positive only where `p` is in it);
    /// `f64::NEG_INFINITY` outside the grid.
    pub(super) fn depth(&self, p: DVec3) -> f64 {
        let cell = (p - self.origin) / self.h;
        if cell.cmplt(DVec3::ZERO).any() {
            return f64::NEG_INFINITY;
        }
        let base = cell.floor().as_usizevec3().to_array();
        if (0..3).any(|a| base[a] + 1 >= self.n[a]) {
            return f64::NEG_INFINITY;
        }
        let mut best = f64::NEG_INFINITY;
        for corner in 0..8 {
            let c = [
                base[0] + (corner & 1),
                base[1] + ((corner >> 1) & 1),
                base[2] + (corner >> 2),
            ];
            let q = self.origin + self.h * DVec3::new(c[0] as f64, c[1] as f64, c[2] as f64);
            let r = self.reach[(c[0] * self.n[1] + c[1]) * self.n[2] + c[2]];
            best = best.max(r - p.distance(q));
        }
        best - self.seal
    }
}

/// The squared distance (in grid steps) from each corner to the nearest `true` one: exact,
/// one axis at a time (the lower envelope of parabolas per line).
fn distance_transform(target: &[bool], n: [usize; 3]) -> Vec<f64> {
    const FAR: f64 = 1e20;
    let mut d: Vec<f64> = target.iter().map(|&t| if t { 0.0 } else { FAR }).collect();
    let stride = [n[1] * n[2], n[2], 1];
    let mut line = Vec::new();
    let mut out = Vec::new();
    for axis in 0..3 {
        let (a, b) = match axis {
            0 => (1, 2),
            1 => (0, 2),
            _ => (0, 1),
        };
        for x in 0..n[a] {
            for y in 0..n[b] {
                let start = x * stride[a] + y * stride[b];
                line.clear();
                line.extend((0..n[axis]).map(|k| d[start + k * stride[axis]]));
                envelope(&line, &mut out);
                for (k, &v) in out.iter().enumerate() {
                    d[start + k * stride[axis]] = v;
                }
            }
        }
    }
    d
}

/// `out[q] = min_p (f[p] + (q − p)²)` (Felzenszwalb and Huttenlocher's lower envelope).
fn envelope(f: &[f64], out: &mut Vec<f64>) {
    let m = f.len();
    out.clear();
    out.resize(m, 0.0);
    let mut v = vec![0_usize; m];
    let mut z = vec![0.0_f64; m + 1];
    let mut k = 0;
    z[0] = f64::NEG_INFINITY;
    z[1] = f64::INFINITY;
    let meet = |p: usize, q: usize| {
        ((f[q] + (q * q) as f64) - (f[p] + (p * p) as f64)) / (2.0 * (q as f64 - p as f64))
    };
    for q in 1..m {
        let mut s = meet(v[k], q);
        while s <= z[k] {
            k -= 1;
            s = meet(v[k], q);
        }
        k += 1;
        v[k] = q;
        z[k] = s;
        z[k + 1] = f64::INFINITY;
    }
    k = 0;
    for (q, o) in out.iter_mut().enumerate() {
        while z[k + 1] < q as f64 {
            k += 1;
        }
        let p = v[k];
        *o = f[p] + ((q as f64 - p as f64).powi(2));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spherise::triangle_mesh::TriangleMesh;

    #[test]
    fn the_distance_transform_is_exact_on_a_line_and_a_grid() {
        let mut out = Vec::new();
        envelope(&[1e20, 0.0, 1e20, 1e20, 0.0], &mut out);
        assert_eq!(out, vec![1.0, 0.0, 1.0, 1.0, 0.0]);
        let n = [5, 6, 7];
        let mut target = vec![false; 5 * 6 * 7];
        target[(2 * 6 + 3) * 7 + 1] = true;
        let d = distance_transform(&target, n);
        for i in 0..5 {
            for j in 0..6 {
                for k in 0..7 {
                    let want = (i as f64 - 2.0).powi(2)
                        + (j as f64 - 3.0).powi(2)
                        + (k as f64 - 1.0).powi(2);
                    assert_eq!(d[(i * 6 + j) * 7 + k], want);
                }
            }
        }
    }

    /// A hollow box of half edge 0.1 made of six closed plates 1 cm thick, each `gap` short
    /// of the box's edges: slots `gap − 1 cm` wide along the edges join the hollow to the
    /// outside.
    fn box_of_plates(gap: f64) -> TriangleMesh {
        let (mut vertices, mut triangles) = (Vec::new(), Vec::new());
        for axis in 0..3 {
            for sign in [-1.0, 1.0] {
                let mut half = DVec3::splat(0.1 - gap);
                half[axis] = 0.005;
                let mut at = DVec3::ZERO;
                at[axis] = sign * 0.095;
                let plate = TriangleMesh::cuboid(half).unwrap().transformed(
                    glam::DMat3::IDENTITY,
                    at,
                    DVec3::ONE,
                );
                let base = vertices.len() as u32;
                vertices.extend(plate.vertices());
                triangles.extend(plate.triangles().iter().map(|t| t.map(|v| v + base)));
            }
        }
        TriangleMesh::new(vertices, triangles).unwrap()
    }

    #[test]
    fn a_hollow_box_is_filled_and_its_depth_bounded() {
        let stop = AtomicBool::new(false);
        let solid = Solid::new(box_of_plates(0.013)).unwrap();
        let fill = EnclosedFill::new(&solid, 0.005, &stop).unwrap().unwrap();
        // The slots (3 mm) are sealed: the centre is 0.1 deep in the filled cube, and the
        // bound is within a few grid steps of that.
        let d = fill.depth(DVec3::ZERO);
        assert!(d <= 0.1 + 1e-12 && d > 0.1 - 4.0 * 0.005, "{d}");
        // Outside, no depth.
        assert!(fill.depth(DVec3::new(0.12, 0.0, 0.0)) <= 0.0);
        assert!(fill.depth(DVec3::new(1.0, 0.0, 0.0)) == f64::NEG_INFINITY);
        // Anywhere, the bound stays below the depth in the filled cube (the exterior comes
        // within a grid step of the faces, no nearer than the surface).
        for i in -12..=12 {
            let p = DVec3::new(f64::from(i) * 0.01, 0.03, -0.02);
            let truth = 0.1 - p.abs().max_element();
            assert!(fill.depth(p) <= truth + 0.005, "{p} {}", fill.depth(p));
        }
        // Slots of 2 cm, wider than twice the seal, let the outside in.
        let open = Solid::new(box_of_plates(0.03)).unwrap();
        assert!(EnclosedFill::new(&open, 0.005, &stop).unwrap().is_none());
        // A solid cube walls nothing in.
        let cube = Solid::new(TriangleMesh::cuboid(DVec3::splat(0.1)).unwrap()).unwrap();
        assert!(EnclosedFill::new(&cube, 0.005, &stop).unwrap().is_none());
    }
}
