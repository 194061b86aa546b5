//! [`OutwardError`]: how far a cover's surface reaches beyond the mesh, measured — the
//! largest distance from a point of the boundary of the spheres' union to the mesh's surface
//! (a one-sided Hausdorff distance), bracketed to within [`RESOLUTION`] by branch and bound.
//!
//! Each sphere's surface is cut into patches by a cube's faces seen from its centre (a
//! gnomonic projection: a square of a face is a spherical quadrilateral with great-circle
//! sides, so its points lie within the largest chord `ρ` from its centre point to a corner).
//! The distance to the surface is 1-Lipschitz, so a patch whose centre point is at distance
//! `d` has no point farther than `d + ρ`. A patch inside another sphere (`|m − c| + ρ ≤ r`)
//! has no point on the union's boundary and is dropped; a centre point outside every other
//! sphere is on the boundary, and its distance is reached. Patches are split in four, the
//! one with the largest `d + ρ` first, until that bound is within [`RESOLUTION`] of the
//! largest distance reached: the bound is then a guaranteed upper bound, the reached value a
//! lower one.

use std::cmp::Ordering;
use std::collections::BinaryHeap;
use std::sync::atomic::AtomicBool;

use glam::DVec3;

use super::cell_grid::check;
use super::solid::Solid;
use super::sphere_cover::CoverSphere;
use super::spherise_error::SpheriseError;

/// How close the guaranteed bound is brought to the distance reached (metres).
pub(super) const RESOLUTION: f64 = 2.5e-4;

/// The most patches measured per cover: past it, the bound is what the patches left give
/// (still guaranteed, less tight).
const MAX_PATCHES: usize = 1_500_000;

/// The outward error of a cover.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct OutwardError {
    /// No point of the union's boundary lies farther than this from the mesh's surface.
    pub(super) bound: f64,
    /// A point of the union's boundary lies this far from the surface.
    pub(super) reached: f64,
}

/// A patch of sphere `sphere`'s surface: `[u0, u1] × [v0, v1]` of cube face `face`.
#[derive(Debug, Clone, Copy)]
struct Patch {
    upper: f64,
    sphere: usize,
    face: usize,
    u: [f64; 2],
    v: [f64; 2],
}

impl PartialEq for Patch {
    fn eq(&self, other: &Self) -> bool {
        self.upper == other.upper
    }
}
impl Eq for Patch {}
impl PartialOrd for Patch {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Patch {
    fn cmp(&self, other: &Self) -> Ordering {
        self.upper.total_cmp(&other.upper)
    }
}

/// The unit direction of point `(u, v)` of cube face `face` (`±x, ±y, ±z`).
fn direction(face: usize, u: f64, v: f64) -> DVec3 {
    let s = if face.is_multiple_of(2) { 1.0 } else { -1.0 };
    match face / 2 {
        0 => DVec3::new(s, u, v),
        1 => DVec3::new(u, s, v),
        _ => DVec3::new(u, v, s),
    }
    .normalize()
}

/// Measures the outward error of `spheres` over `solid`'s mesh.
///
/// # Errors
/// [`SpheriseError::Stopped`] once `stop` is raised.
pub(super) fn outward_error(
    spheres: &[CoverSphere],
    solid: &Solid,
    stop: &AtomicBool,
) -> Result<OutwardError, SpheriseError> {
    let neighbours = neighbours(spheres);
    let mut reached: f64 = 0.0;
    let mut settled: f64 = 0.0;
    let mut heap = BinaryHeap::new();
    let mut measured = 0_usize;
    // Measures a patch: `None` if it lies inside another sphere.
    let measure = |patch: Patch, reached: &mut f64, measured: &mut usize| -> Option<Patch> {
        *measured += 1;
        let s = spheres[patch.sphere];
        let (um, vm) = (
            (patch.u[0] + patch.u[1]) / 2.0,
            (patch.v[0] + patch.v[1]) / 2.0,
        );
        let centre = direction(patch.face, um, vm);
        let rho = patch
            .u
            .iter()
            .flat_map(|&u| patch.v.iter().map(move |&v| (u, v)))
            .map(|(u, v)| direction(patch.face, u, v).distance(centre))
            .fold(0.0, f64::max)
            * s.radius
            * (1.0 + 1e-9);
        let m = s.centre + centre * s.radius;
        let mut on_boundary = true;
        for &j in &neighbours[patch.sphere] {
            let o = spheres[j];
            let apart = m.distance(o.centre);
            if apart + rho <= o.radius {
                return None;
            }
            on_boundary &= apart >= o.radius;
        }
        let d = solid.surface_distance(m);
        if on_boundary {
            *reached = reached.max(d);
        }
        Some(Patch {
            upper: d + rho,
            ..patch
        })
    };
    for (sphere, _) in spheres.iter().enumerate() {
        check(stop)?;
        for face in 0..6 {
            for a in 0..4 {
                for b in 0..4 {
                    let cut = |i: i32| -1.0 + 0.5 * f64::from(i);
                    let patch = Patch {
                        upper: 0.0,
                        sphere,
                        face,
                        u: [cut(a), cut(a + 1)],
                        v: [cut(b), cut(b + 1)],
                    };
                    if let Some(p) = measure(patch, &mut reached, &mut measured) {
                        heap.push(p);
                    }
                }
            }
        }
    }
    while let Some(patch) = heap.pop() {
        if patch.upper <= reached + RESOLUTION {
            settled = settled.max(patch.upper);
            break;
        }
        if measured >= MAX_PATCHES {
            settled = settled.max(patch.upper);
            break;
        }
        if measured.is_multiple_of(4096) {
            check(stop)?;
        }
        let (um, vm) = (
            (patch.u[0] + patch.u[1]) / 2.0,
            (patch.v[0] + patch.v[1]) / 2.0,
        );
        for (u, v) in [
            ([patch.u[0], um], [patch.v[0], vm]),
            ([um, patch.u[1]], [patch.v[0], vm]),
            ([patch.u[0], um], [vm, patch.v[1]]),
            ([um, patch.u[1]], [vm, patch.v[1]]),
        ] {
            if let Some(p) = measure(Patch { u, v, ..patch }, &mut reached, &mut measured) {
                heap.push(p);
            }
        }
    }
    Ok(OutwardError {
        bound: settled.max(reached),
        reached,
    })
}

/// Each sphere's neighbours (the spheres it meets), by a sweep along x.
pub(super) fn neighbours(spheres: &[CoverSphere]) -> Vec<Vec<usize>> {
    let mut order: Vec<usize> = (0..spheres.len()).collect();
    order.sort_by(|&a, &b| {
        (spheres[a].centre.x - spheres[a].radius)
            .total_cmp(&(spheres[b].centre.x - spheres[b].radius))
    });
    let mut out: Vec<Vec<usize>> = vec![Vec::new(); spheres.len()];
    for (at, &i) in order.iter().enumerate() {
        let (a, right) = (spheres[i], spheres[i].centre.x + spheres[i].radius);
        for &j in &order[at + 1..] {
            let b = spheres[j];
            if b.centre.x - b.radius > right {
                break;
            }
            if a.centre.distance(b.centre) < a.radius + b.radius {
                out[i].push(j);
                out[j].push(i);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spherise::triangle_mesh::TriangleMesh;

    fn sphere(centre: DVec3, radius: f64) -> CoverSphere {
        CoverSphere {
            centre,
            radius,
            protrusion: 0.0,
        }
    }

    #[test]
    fn one_sphere_about_a_cube_reaches_its_radius_less_the_half_edge() {
        // A sphere of radius 0.3 about a cube of half edge 0.1: the boundary point farthest
        // from the cube is on an axis, 0.2 from the face.
        let cube = Solid::new(TriangleMesh::cuboid(DVec3::splat(0.1)).unwrap()).unwrap();
        let stop = AtomicBool::new(false);
        let e = outward_error(&[sphere(DVec3::ZERO, 0.3)], &cube, &stop).unwrap();
        brackets(e, 0.2);
    }

    /// `e` brackets `truth` within the resolution.
    fn brackets(e: OutwardError, truth: f64) {
        assert!(
            e.reached <= truth + 1e-12 && e.bound >= truth - 1e-12,
            "{e:?} {truth}"
        );
        assert!(e.bound <= e.reached + RESOLUTION, "{e:?}");
    }

    #[test]
    fn points_inside_other_spheres_do_not_count() {
        // A big sphere swallowing a small one far out: the small one's surface is not on the
        // union's boundary, so the error is the big sphere's (0.2), not the small one's.
        let cube = Solid::new(TriangleMesh::cuboid(DVec3::splat(0.1)).unwrap()).unwrap();
        let stop = AtomicBool::new(false);
        let spheres = [
            sphere(DVec3::ZERO, 0.3),
            sphere(DVec3::new(0.0, 0.0, 0.25), 0.04),
        ];
        brackets(outward_error(&spheres, &cube, &stop).unwrap(), 0.2);
        // Moved half out, its far point counts: 0.29 + 0.04 − 0.1.
        let spheres = [
            sphere(DVec3::ZERO, 0.3),
            sphere(DVec3::new(0.0, 0.0, 0.29), 0.04),
        ];
        brackets(outward_error(&spheres, &cube, &stop).unwrap(), 0.23);
    }
}
