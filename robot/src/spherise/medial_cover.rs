//! The medial placement of a cover: candidate spheres centred on an approximate medial axis
//! of the solid, chosen by greedy set cover over a finer grid's elements, then merged in
//! pairs where one candidate can take both spheres' elements.
//!
//! Written after reading foam (Coumar, Kingston et al., 2025), which approximates a robot's
//! meshes by spheres about their medial axis; this is not its algorithm. Here:
//!
//! 1. **A finer grid.** The grid placement's cells have edge `t/√3`, the coarsest for which
//!    every cell can be covered; a sphere is credited only with the cells it holds whole, so
//!    at a coarse tolerance up to a cell's diagonal of its reach goes unused at its rim. This
//!    placement cuts cells [`REFINE`] times finer (at most [`MAX_MEDIAL_CELLS`] cells).
//! 2. **Medial candidates.** The depth field `D` (distance to the surface inside the solid,
//!    minus it outside) is sampled at the grid's corners; away from the medial axis its
//!    gradient has length 1, and on a ridge of `D` the central differences across the ridge
//!    cancel. Inside corners whose central-difference gradient is shorter than
//!    [`RIDGE_GRADIENT`] lie within about a cell of the medial axis, where the largest
//!    spheres sit: each is a candidate of radius `D + t`, as in the grid placement (the inner
//!    ball `B(c, D)` lies in the solid, so `B(c, D + t)` reaches at most `t` beyond it). The
//!    centre of every element with surface is a candidate too, so that every element stays
//!    coverable (its half diagonal is below `t/2`).
//! 3. **Greedy set cover and merging.** The grid placement's lazy greedy picks candidates;
//!    then any two picked spheres whose elements one candidate holds whole are replaced by
//!    it, until no pair merges; the grid placement's pruning and shrinking end it.
//!
//! The guarantee is the grid placement's, by the same elements and the same containment
//! test: every element (so every point of the solid) lies in a picked sphere, and each
//! sphere's protrusion bound is its radius less its centre's depth.

use std::collections::HashSet;
use std::sync::atomic::AtomicBool;

use glam::DVec3;

use super::cell_grid::{CellGrid, cells_over, check};
use super::solid::Solid;
use super::sphere_cover::CoverSphere;
use super::sphere_cover::{Candidate, candidate, cell_edge, greedy, shrink_and_prune};
use super::spherise_error::SpheriseError;

/// How many times finer than the grid placement's the medial placement's cells are.
pub(super) const REFINE: f64 = 2.0;

/// The most cells of the medial placement's grid: a finer grid that would need more is
/// coarsened (down to the grid placement's cell), bounding the work of each cover.
pub(super) const MAX_MEDIAL_CELLS: f64 = 600_000.0;

/// A corner whose central-difference gradient of the depth field is shorter than this is
/// taken to lie on the medial axis (off it, the gradient has length 1).
pub(super) const RIDGE_GRADIENT: f64 = 0.9;

/// The most medial candidates: more are thinned evenly (bounding the greedy's work).
const MAX_MEDIAL_CANDIDATES: usize = 12_000;

/// The medial placement's spheres covering `solid` with protrusion at most `tolerance`.
///
/// # Errors
/// [`SpheriseError::Stopped`] once `stop` is raised.
pub(super) fn medial_cover(
    solid: &Solid,
    tolerance: f64,
    stop: &AtomicBool,
) -> Result<(Vec<CoverSphere>, f64), SpheriseError> {
    let (grid, candidates, tolerance) = medial_grid(solid, tolerance, stop)?;
    let mut picked = greedy(solid, &grid, &candidates, tolerance, stop)?;
    merge_pairs(&grid, &candidates, &mut picked, stop)?;
    Ok((shrink_and_prune(solid, &grid, &picked, stop)?, tolerance))
}

/// The medial placement's grid (cells [`REFINE`] times finer than the grid placement's, at
/// most [`MAX_MEDIAL_CELLS`]), its candidates, and the tolerance they keep (larger when the
/// cap coarsened the grid).
///
/// # Errors
/// [`SpheriseError::Stopped`] once `stop` is raised.
pub(super) fn medial_grid(
    solid: &Solid,
    tolerance: f64,
    stop: &AtomicBool,
) -> Result<(CellGrid, Vec<Candidate>, f64), SpheriseError> {
    let coarse = cell_edge(tolerance);
    let (lo, hi) = solid.mesh().bounds();
    let mut h = coarse / REFINE;
    while h < coarse && cells_over(lo, hi, h) > MAX_MEDIAL_CELLS {
        h = (h * 1.25).min(coarse);
    }
    let grid = CellGrid::new(solid, h, stop)?;
    // A grid coarsened by its own cap needs a larger tolerance for every cell to be coverable.
    let tolerance = tolerance.max(grid.h * 3f64.sqrt());
    let candidates = medial_candidates(solid, &grid, tolerance, stop)?;
    Ok((grid, candidates, tolerance))
}

/// The depth field at every corner of the grid: the depth of a trusted inside corner, minus
/// the distance to the surface elsewhere (undecided corners get 0: never a candidate).
fn depth_field(
    solid: &Solid,
    grid: &CellGrid,
    stop: &AtomicBool,
) -> Result<Vec<f64>, SpheriseError> {
    let mut depth = vec![0.0; grid.inside.len()];
    for i in 0..=grid.n[0] {
        for j in 0..=grid.n[1] {
            check(stop)?;
            for k in 0..=grid.n[2] {
                let index = grid.corner_index([i, j, k]);
                let p = grid.corner([i, j, k]);
                depth[index] = if grid.trusted[index] {
                    solid.inside_depth(p)
                } else if grid.inside[index] {
                    0.0
                } else {
                    -solid.surface_distance(p)
                };
            }
        }
    }
    Ok(depth)
}

/// Candidates on the approximate medial axis, and the centre of each element with surface.
fn medial_candidates(
    solid: &Solid,
    grid: &CellGrid,
    tolerance: f64,
    stop: &AtomicBool,
) -> Result<Vec<Candidate>, SpheriseError> {
    let depth = depth_field(solid, grid, stop)?;
    let mut medial = Vec::new();
    for i in 1..grid.n[0] {
        for j in 1..grid.n[1] {
            check(stop)?;
            for k in 1..grid.n[2] {
                let index = grid.corner_index([i, j, k]);
                if !grid.trusted[index] {
                    continue;
                }
                let at = |c: [usize; 3]| depth[grid.corner_index(c)];
                let gradient = DVec3::new(
                    at([i + 1, j, k]) - at([i - 1, j, k]),
                    at([i, j + 1, k]) - at([i, j - 1, k]),
                    at([i, j, k + 1]) - at([i, j, k - 1]),
                ) / (2.0 * grid.h);
                if gradient.length() < RIDGE_GRADIENT {
                    let centre = grid.corner([i, j, k]);
                    let d = depth[index];
                    medial.push(Candidate {
                        centre,
                        reach: d + tolerance,
                        depth: d,
                    });
                }
            }
        }
    }
    if medial.len() > MAX_MEDIAL_CANDIDATES {
        let stride = medial.len().div_ceil(MAX_MEDIAL_CANDIDATES);
        medial = medial.into_iter().step_by(stride).collect();
    }
    for (n, e) in grid.elements.iter().enumerate() {
        if n % 256 == 0 {
            check(stop)?;
        }
        if e.surface || !grid.trusted[grid.corner_index(e.cell)] {
            medial.push(candidate(solid, e.centre(), tolerance));
        }
    }
    Ok(medial)
}

/// Replaces two picked spheres by one candidate that holds both's elements, while any pair
/// does (pairs tried nearest first, candidates in order; a pair that failed is not tried
/// again).
fn merge_pairs(
    grid: &CellGrid,
    candidates: &[Candidate],
    picked: &mut Vec<(Candidate, Vec<usize>)>,
    stop: &AtomicBool,
) -> Result<(), SpheriseError> {
    let mut ids: Vec<usize> = (0..picked.len()).collect();
    let mut next_id = picked.len();
    let mut failed: HashSet<(usize, usize)> = HashSet::new();
    loop {
        let mut pairs = Vec::new();
        for a in 0..picked.len() {
            for b in a + 1..picked.len() {
                let (ca, cb) = (&picked[a].0, &picked[b].0);
                let apart = ca.centre.distance(cb.centre);
                let key = (ids[a].min(ids[b]), ids[a].max(ids[b]));
                if apart < ca.reach + cb.reach && !failed.contains(&key) {
                    pairs.push((apart, a, b, key));
                }
            }
        }
        pairs.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut merged = None;
        'pairs: for &(_, a, b, key) in &pairs {
            check(stop)?;
            let (ca, cb) = (picked[a].0, picked[b].0);
            for c in candidates {
                // A candidate holding both reaches each one's elements: a quick necessary
                // test on the spheres' own reach first.
                if c.centre.distance(ca.centre) > c.reach + ca.reach
                    || c.centre.distance(cb.centre) > c.reach + cb.reach
                {
                    continue;
                }
                let holds = |mine: &[usize]| {
                    mine.iter()
                        .all(|&e| grid.elements[e].within(c.centre, c.reach))
                };
                if holds(&picked[a].1) && holds(&picked[b].1) {
                    merged = Some((a, b, *c));
                    break 'pairs;
                }
            }
            failed.insert(key);
        }
        let Some((a, b, c)) = merged else {
            return Ok(());
        };
        let (_, mine) = picked.swap_remove(b);
        ids.swap_remove(b);
        picked[a].0 = c;
        picked[a].1.extend(mine);
        ids[a] = next_id;
        next_id += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spherise::sphere_cover::{CoverOptions, Placement, SphereCover};
    use crate::spherise::triangle_mesh::TriangleMesh;

    fn covered(spheres: &[CoverSphere], p: DVec3) -> bool {
        spheres.iter().any(|s| p.distance(s.centre) <= s.radius)
    }

    fn options(tolerance: f64, max_spheres: Option<usize>) -> CoverOptions {
        CoverOptions {
            tolerance,
            max_spheres,
        }
    }

    #[test]
    fn the_medial_placement_keeps_the_guarantee() {
        // A link-like cylinder: radius 5 cm, 30 cm long, 16 sides.
        let mesh = TriangleMesh::cylinder(0.05, 0.3, 16).unwrap();
        let stop = AtomicBool::new(false);
        let cover =
            SphereCover::placed(&mesh, &options(0.015, None), Placement::Medial, &stop).unwrap();
        assert!(cover.closed);
        assert!(
            cover.max_protrusion <= 0.015 + 1e-6,
            "{}",
            cover.max_protrusion
        );
        assert!(cover.measured_max <= cover.max_protrusion + 1e-9);
        // Every vertex, and points inside on a grid of 1 cm (within the inscribed radius,
        // 0.05 cos(π/16)), lie in some sphere.
        for &v in mesh.vertices() {
            assert!(covered(&cover.spheres, v), "{v}");
        }
        let inscribed = 0.05 * (std::f64::consts::PI / 16.0).cos();
        for i in -5..=5 {
            for j in -5..=5 {
                for k in -15..=15 {
                    let p = DVec3::new(f64::from(i), f64::from(j), f64::from(k)) * 0.01;
                    if p.truncate().length() <= inscribed {
                        assert!(covered(&cover.spheres, p), "{p}");
                    }
                }
            }
        }
        // Each sphere stays within its bound of the solid: points of its boundary lie at
        // most that far from the cylinder.
        let solid = Solid::new(mesh).unwrap();
        for s in &cover.spheres {
            assert!(s.protrusion <= 0.015 + 1e-6, "{s:?}");
            for u in super::super::sphere_cover::fibonacci_sphere(64) {
                let p = s.centre + u * s.radius;
                assert!(solid.distance(p) <= s.protrusion + 1e-9, "{s:?} {p}");
            }
        }
    }

    #[test]
    fn a_budget_keeps_a_tolerance_the_grid_placement_has_to_raise() {
        // The link-like cylinder at 30 mm: the grid placement takes 11 spheres, the medial
        // one 5 (its finer cells let each sphere be credited with more of its reach). Under
        // a budget of 6 the default (fewest) placement keeps the 30 mm bound, where the grid
        // placement, the only one before, has to raise its tolerance.
        let mesh = TriangleMesh::cylinder(0.05, 0.3, 16).unwrap();
        let stop = AtomicBool::new(false);
        let budget = options(0.03, Some(6));
        let cover = SphereCover::new(&mesh, &budget).unwrap();
        assert!(cover.spheres.len() <= 6, "{}", cover.spheres.len());
        assert!(
            cover.tolerance == 0.03 && cover.max_protrusion <= 0.03 + 1e-6,
            "tolerance {} bound {}",
            cover.tolerance,
            cover.max_protrusion
        );
        let grid = SphereCover::placed(&mesh, &budget, Placement::Grid, &stop).unwrap();
        assert!(grid.spheres.len() <= 6);
        assert!(grid.tolerance > 0.03, "{}", grid.tolerance);
        // The budgeted cover still holds the solid: the vertices and the axis.
        for &v in mesh.vertices() {
            assert!(covered(&cover.spheres, v), "{v}");
        }
        for k in -15..=15 {
            let p = DVec3::new(0.0, 0.0, f64::from(k) * 0.01);
            assert!(covered(&cover.spheres, p), "{p}");
        }
    }
}
