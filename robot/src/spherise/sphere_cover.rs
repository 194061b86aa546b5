//! [`SphereCover`]: few spheres whose union contains a mesh's solid, each protruding beyond
//! it by at most the tolerance.
//!
//! The solid is cut into cells ([`CellGrid`]); a sphere must contain each cell's element: a
//! few points of the solid whose convex hull holds the cell's part of it.
//! Candidate spheres protrude by at most the tolerance `t` by construction: a centre `c`
//! inside the solid at distance `D` from its surface has the inner ball `B(c, D)` in the
//! solid, so `B(c, D + t)` reaches at most `t` beyond it; a centre outside at distance `d`
//! gets radius `t − d`. Greedy set cover (lazy, by the number of elements still uncovered)
//! picks candidates until every element is covered; each picked sphere then shrinks to the
//! farthest point of the elements it was picked for, and spheres whose elements others
//! cover are dropped. Cells of edge `t/√3` make every element coverable by a candidate.

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::sync::atomic::AtomicBool;

use glam::DVec3;

use super::cell_grid::{CellGrid, Element, cells_over, check};
use super::cover_search::searched_cover;
use super::medial_cover::medial_cover;
use super::outward_error::{neighbours, outward_error};
use super::solid::Solid;
use super::spherise_error::SpheriseError;
use super::triangle_mesh::TriangleMesh;
use super::vertex_weld::VertexWeld;

/// The largest vertex-merge distance tried to close an open mesh, as a fraction of the
/// tolerance (`vertex_weld.rs`).
const WELD: f64 = 20.0;

/// The seal of a hollow mesh's fill (`enclosed_fill.rs`: openings narrower than about twice
/// it are closed), as a fraction of the tolerance. The fill's lids over sealed openings lie
/// up to about the seal from the mesh, which the outward error then pays: on the Kinova
/// Gen3's arm links at 15 mm, a seal of half the tolerance gave outward errors of 18.2 to
/// 19.5 mm, a tenth 15.8 to 16.4 mm, for as many spheres (±4 per link).
const SEAL: f64 = 0.1;

/// Samples per sphere for the measured protrusion.
const SAMPLES_PER_SPHERE: usize = 400;

/// How to cover a mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoverOptions {
    /// The most a sphere may protrude beyond the mesh's solid, in the mesh's units (metres).
    pub tolerance: f64,
    /// The most spheres per mesh: with more, the tolerance is raised by a quarter at a time
    /// until the cover fits (the cover reports the tolerance it used).
    pub max_spheres: Option<usize>,
}

impl Default for CoverOptions {
    fn default() -> Self {
        Self {
            tolerance: 0.01,
            max_spheres: None,
        }
    }
}

/// Where a cover's spheres are placed (both keep the guarantee: every point of the solid
/// inside, each sphere within its protrusion bound).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Placement {
    /// Greedy set cover over candidates at every inside corner of a grid of cells of edge
    /// `t/√3` (the unbudgeted default: quick, and as few spheres as the medial placement or
    /// fewer at fine tolerances).
    #[default]
    Grid,
    /// Candidates on an approximate medial axis, elements of a twice finer grid, and a merge
    /// of pairs of spheres (`medial_cover.rs`): fewer spheres at the coarse tolerances a
    /// sphere budget leads to.
    Medial,
    /// Grid and medial, keeping the cover with fewer spheres (then the smaller bound).
    Fewest,
    /// The medial placement's candidates and cells, the greedy cover then improved by a
    /// local search that swaps spheres until it finds a cover with fewer
    /// (`cover_search.rs`): the fewest spheres of the four, at a few times the medial
    /// placement's time. What a sphere budget uses.
    Searched,
}

/// One sphere of a cover.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoverSphere {
    /// The centre.
    pub centre: DVec3,
    /// The radius.
    pub radius: f64,
    /// A bound on how far any point of the sphere lies from the solid: the radius less the
    /// centre's distance to the surface if the centre is inside, plus it if outside.
    pub protrusion: f64,
}

/// Spheres whose union contains a mesh's solid (its surface if the mesh is open), with what
/// was measured of them.
#[derive(Debug, Clone, PartialEq)]
pub struct SphereCover {
    /// The spheres.
    pub spheres: Vec<CoverSphere>,
    /// Whether the mesh is closed (otherwise its surface is covered, with a warning).
    pub closed: bool,
    /// The mesh's triangle count.
    pub triangles: usize,
    /// The tolerance the cover was built for (above the one asked when `max_spheres` or the
    /// grid's cell limit raised it).
    pub tolerance: f64,
    /// The guaranteed bound per sphere: no point of the union lies farther than this from the
    /// solid (with the space a hollow mesh walls in counted as solid: see `filled`).
    pub max_protrusion: f64,
    /// The outward error, guaranteed: no point of the boundary of the spheres' union lies
    /// farther than this from the mesh's surface (measured by branch and bound to within
    /// 0.25 mm, `outward_error.rs`; the vertex merge's move added).
    pub outward_error: f64,
    /// The largest distance from the mesh's surface of a point found on the boundary of the
    /// spheres' union (within 0.25 mm of [`outward_error`](Self::outward_error)).
    pub measured_max: f64,
    /// The mean distance from the solid over points sampled on the union's boundary (400 per
    /// sphere).
    pub measured_mean: f64,
    /// Whether the mesh walls in space beyond its own solid (a hollow housing), which the
    /// cover fills (`enclosed_fill.rs`).
    pub filled: bool,
    /// The distance within which vertices were merged to close an open mesh (0 if none
    /// was): the cover is then of the closed mesh, every sphere grown by the largest
    /// vertex move so that it still contains the mesh as given (`vertex_weld.rs`).
    pub weld: f64,
}

impl SphereCover {
    /// Covers `mesh` with spheres.
    ///
    /// # Errors
    /// [`SpheriseError::BadOption`] for a tolerance that is not positive and finite or a
    /// sphere budget of 0; [`SpheriseError::TooMuchWork`] if the tolerance is so fine for the
    /// mesh's size that the grid would exceed [`MAX_COVER_CELLS`](super::MAX_COVER_CELLS)
    /// cells (checked before any work); [`SpheriseError::BadMesh`] if parry refuses the mesh.
    pub fn new(mesh: &TriangleMesh, options: &CoverOptions) -> Result<Self, SpheriseError> {
        Self::stoppable(mesh, options, &AtomicBool::new(false))
    }

    /// As [`new`](Self::new), polling `stop` in every long loop (a signal handler raises it).
    ///
    /// # Errors
    /// As [`new`](Self::new), and [`SpheriseError::Stopped`] once `stop` is raised.
    pub fn stoppable(
        mesh: &TriangleMesh,
        options: &CoverOptions,
        stop: &AtomicBool,
    ) -> Result<Self, SpheriseError> {
        let placement = if options.max_spheres.is_some() {
            Placement::Searched
        } else {
            Placement::Grid
        };
        Self::placed(mesh, options, placement, stop)
    }

    /// As [`stoppable`](Self::stoppable), with the spheres placed by `placement`
    /// ([`stoppable`](Self::stoppable) takes [`Placement::Searched`] under a sphere budget,
    /// [`Placement::Grid`] otherwise).
    ///
    /// # Errors
    /// As [`stoppable`](Self::stoppable).
    pub fn placed(
        mesh: &TriangleMesh,
        options: &CoverOptions,
        placement: Placement,
        stop: &AtomicBool,
    ) -> Result<Self, SpheriseError> {
        Self::check_options(options)?;
        check_work(mesh, options.tolerance, "the cover")?;
        // An open mesh that merging nearby vertices closes is covered as that solid, each
        // sphere grown by the largest vertex move.
        let (solid, grow, weld) = match VertexWeld::closing(mesh, options.tolerance / WELD)? {
            Some(w) => (Solid::new(w.mesh)?, w.displacement, w.distance),
            None => (Solid::new(mesh.clone())?, 0.0, 0.0),
        };
        // The space a hollow mesh walls in counts as solid (`enclosed_fill.rs`).
        let solid = solid.with_fill(options.tolerance * SEAL, stop)?;
        let mut tolerance = options.tolerance;
        loop {
            let mut spheres;
            (spheres, tolerance) = place(&solid, tolerance, placement, stop)?;
            let over_budget = options.max_spheres.is_some_and(|m| spheres.len() > m);
            if !over_budget || tolerance > 1e3 * options.tolerance {
                for s in &mut spheres {
                    s.radius += grow;
                    s.protrusion += grow;
                }
                let mut cover = Self::measured(&solid, spheres, tolerance, stop)?;
                cover.triangles = mesh.triangles().len();
                cover.weld = weld;
                // The welded surface lies within `grow` of the mesh as given.
                cover.outward_error += grow;
                return Ok(cover);
            }
            tolerance *= 1.25;
        }
    }

    /// [`SpheriseError::BadOption`] for a tolerance that is not positive and finite or a
    /// sphere budget of 0.
    pub(super) fn check_options(options: &CoverOptions) -> Result<(), SpheriseError> {
        if !(options.tolerance.is_finite() && options.tolerance > 0.0) {
            return Err(SpheriseError::BadOption {
                what: "the tolerance",
                rule: "positive and finite",
                value: options.tolerance.to_string(),
            });
        }
        if options.max_spheres == Some(0) {
            return Err(SpheriseError::BadOption {
                what: "the sphere budget",
                rule: "at least 1",
                value: "0".into(),
            });
        }
        Ok(())
    }

    fn measured(
        solid: &Solid,
        spheres: Vec<CoverSphere>,
        tolerance: f64,
        stop: &AtomicBool,
    ) -> Result<Self, SpheriseError> {
        let mut sum = 0.0;
        let mut count = 0_usize;
        let neighbours = neighbours(&spheres);
        for (i, s) in spheres.iter().enumerate() {
            check(stop)?;
            for p in fibonacci_sphere(SAMPLES_PER_SPHERE) {
                let p = s.centre + p * s.radius;
                let inside_other = neighbours[i]
                    .iter()
                    .map(|&j| spheres[j])
                    .any(|o| p.distance(o.centre) < o.radius);
                if !inside_other {
                    sum += solid.distance(p);
                    count += 1;
                }
            }
        }
        let error = outward_error(&spheres, solid, stop)?;
        Ok(Self {
            max_protrusion: spheres.iter().map(|s| s.protrusion).fold(0.0, f64::max),
            closed: solid.is_closed(),
            triangles: solid.mesh().triangles().len(),
            tolerance,
            measured_max: error.reached,
            outward_error: error.bound,
            filled: solid.is_filled(),
            measured_mean: if count > 0 { sum / count as f64 } else { 0.0 },
            weld: 0.0,
            spheres,
        })
    }
}

/// The spheres `placement` puts over `solid` for `tolerance`, and the tolerance they keep
/// (larger when a grid's cell cap coarsened it).
fn place(
    solid: &Solid,
    tolerance: f64,
    placement: Placement,
    stop: &AtomicBool,
) -> Result<(Vec<CoverSphere>, f64), SpheriseError> {
    let grid_placement = || -> Result<(Vec<CoverSphere>, f64), SpheriseError> {
        let grid = CellGrid::new(solid, cell_edge(tolerance), stop)?;
        // A coarsened grid needs a larger tolerance for every cell to be coverable.
        let tolerance = tolerance.max(grid.h * 3f64.sqrt());
        Ok((cover(solid, &grid, tolerance, stop)?, tolerance))
    };
    match placement {
        Placement::Grid => grid_placement(),
        Placement::Medial => medial_cover(solid, tolerance, stop),
        Placement::Searched => searched_cover(solid, tolerance, stop),
        Placement::Fewest => {
            let (a, b) = (grid_placement()?, medial_cover(solid, tolerance, stop)?);
            let bound = |s: &[CoverSphere]| s.iter().map(|s| s.protrusion).fold(0.0, f64::max);
            let key = |(s, _): &(Vec<CoverSphere>, f64)| (s.len(), bound(s));
            Ok(if key(&b) < key(&a) { b } else { a })
        }
    }
}

/// The cell edge for tolerance `t`: a little under `t/√3`, so a cell's diagonal stays below
/// `t` less rounding room.
pub(super) fn cell_edge(tolerance: f64) -> f64 {
    tolerance / 3f64.sqrt() * (1.0 - 1e-5)
}

/// [`SpheriseError::TooMuchWork`] (naming `what`) if covering `mesh` at `tolerance` would
/// take a grid of more than [`MAX_COVER_CELLS`](super::MAX_COVER_CELLS) cells.
pub(super) fn check_work(
    mesh: &TriangleMesh,
    tolerance: f64,
    what: &str,
) -> Result<(), SpheriseError> {
    let (lo, hi) = mesh.bounds();
    let cells = cells_over(lo, hi, cell_edge(tolerance));
    if cells <= super::MAX_COVER_CELLS as f64 {
        Ok(())
    } else {
        Err(SpheriseError::TooMuchWork {
            what: what.to_owned(),
            extent: (hi - lo).max_element(),
            tolerance,
            cells,
            cap: super::MAX_COVER_CELLS,
        })
    }
}

/// `n` points spread evenly over the unit sphere.
pub(super) fn fibonacci_sphere(n: usize) -> impl Iterator<Item = DVec3> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n).map(move |i| {
        let z = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
        let r = (1.0 - z * z).sqrt();
        let (s, c) = (golden * i as f64).sin_cos();
        DVec3::new(r * c, r * s, z)
    })
}

/// A candidate sphere: centre, largest radius, and the signed distance of the centre into
/// the solid (`D` inside, `−d` outside): the protrusion of radius `r` is `r −` that.
#[derive(Debug, Clone, Copy)]
pub(super) struct Candidate {
    /// The centre.
    pub(super) centre: DVec3,
    /// The largest radius (`depth` plus the tolerance).
    pub(super) reach: f64,
    /// The centre's signed depth in the solid.
    pub(super) depth: f64,
}

/// The candidate about `centre`: radius its depth plus `tolerance`.
pub(super) fn candidate(solid: &Solid, centre: DVec3, tolerance: f64) -> Candidate {
    let depth = solid.depth(centre);
    Candidate {
        centre,
        reach: depth + tolerance,
        depth,
    }
}

fn candidates(
    solid: &Solid,
    grid: &CellGrid,
    tolerance: f64,
    stop: &AtomicBool,
) -> Result<Vec<Candidate>, SpheriseError> {
    let mut out = Vec::new();
    // Every inside corner: its inner ball grown by t (radius ≥ t, a cell's diagonal) covers
    // the cells around it. (Every second corner per axis would do, one per cell; all of them
    // give the greedy choice finer positions: a quarter fewer spheres on the UR5.)
    for i in 0..=grid.n[0] {
        for j in 0..=grid.n[1] {
            check(stop)?;
            for k in 0..=grid.n[2] {
                if grid.trusted[grid.corner_index([i, j, k])] {
                    out.push(candidate(solid, grid.corner([i, j, k]), tolerance));
                }
            }
        }
    }
    // The centre of each element with surface, or whose own corner is not a trusted inside one: the
    // element's half diagonal is at most t/2, and so is the centre's distance to the solid.
    for (n, e) in grid.elements.iter().enumerate() {
        if n % 256 == 0 {
            check(stop)?;
        }
        let covered_by_corner = grid.trusted[grid.corner_index(e.cell)];
        if e.surface || !covered_by_corner {
            let c = e.centre();
            out.push(candidate(solid, c, tolerance));
        }
    }
    Ok(out)
}

/// The uncovered elements candidate `c` would cover.
fn gain(grid: &CellGrid, c: &Candidate, covered: &[bool], mut visit: impl FnMut(usize)) -> u32 {
    let mut n = 0;
    let r = DVec3::splat(c.reach);
    let [ri, rj, rk] = grid.cell_range(c.centre - r, c.centre + r);
    for i in ri {
        for j in rj.clone() {
            for k in rk.clone() {
                let e = grid.element_of[grid.cell_index([i, j, k])];
                if e != u32::MAX && !covered[e as usize] {
                    let element: &Element = &grid.elements[e as usize];
                    if element.within(c.centre, c.reach) {
                        n += 1;
                        visit(e as usize);
                    }
                }
            }
        }
    }
    n
}

fn cover(
    solid: &Solid,
    grid: &CellGrid,
    tolerance: f64,
    stop: &AtomicBool,
) -> Result<Vec<CoverSphere>, SpheriseError> {
    let candidates = candidates(solid, grid, tolerance, stop)?;
    let picked = greedy(solid, grid, &candidates, tolerance, stop)?;
    shrink_and_prune(solid, grid, &picked, stop)
}

/// The candidates a lazy greedy set cover picks until every element of `grid` is covered,
/// each with the elements it was picked for (an element no candidate covers gets a sphere of
/// its own).
pub(super) fn greedy(
    solid: &Solid,
    grid: &CellGrid,
    candidates: &[Candidate],
    tolerance: f64,
    stop: &AtomicBool,
) -> Result<Vec<(Candidate, Vec<usize>)>, SpheriseError> {
    let mut covered = vec![false; grid.elements.len()];
    let mut left = grid.elements.len();
    // Lazy greedy: gains only fall as elements get covered, so a popped candidate whose
    // fresh gain still tops the heap is the best one.
    let mut heap: BinaryHeap<(u32, Reverse<usize>)> = BinaryHeap::new();
    for (i, c) in candidates.iter().enumerate() {
        if i % 256 == 0 {
            check(stop)?;
        }
        heap.push((gain(grid, c, &covered, |_| {}), Reverse(i)));
    }
    let mut picked: Vec<(Candidate, Vec<usize>)> = Vec::new();
    while left > 0 {
        check(stop)?;
        let Some((stale, Reverse(i))) = heap.pop() else {
            break;
        };
        let fresh = gain(grid, &candidates[i], &covered, |_| {});
        if fresh == 0 {
            continue;
        }
        if fresh < stale && heap.peek().is_some_and(|&(top, _)| top > fresh) {
            heap.push((fresh, Reverse(i)));
            continue;
        }
        let mut mine = Vec::new();
        gain(grid, &candidates[i], &covered, |e| mine.push(e));
        for &e in &mine {
            covered[e] = true;
        }
        left -= mine.len();
        picked.push((candidates[i], mine));
    }
    // Elements no candidate covered (none, by the cell size; kept as a safety net): each
    // gets a sphere of its own, with its true protrusion.
    for (e, _) in covered.iter().enumerate().filter(|(_, c)| !**c) {
        let c = grid.elements[e].centre();
        let mut own = candidate(solid, c, tolerance);
        own.reach = grid.elements[e].reach_from(c);
        picked.push((own, vec![e]));
    }
    Ok(picked)
}

/// Drops spheres whose elements other spheres can take within their reach (fewest elements
/// first), handing each element to the sphere it enlarges least; then each sphere shrinks to
/// its elements' farthest point.
pub(super) fn shrink_and_prune(
    solid: &Solid,
    grid: &CellGrid,
    picked: &[(Candidate, Vec<usize>)],
    stop: &AtomicBool,
) -> Result<Vec<CoverSphere>, SpheriseError> {
    // A little room for rounding in the distances.
    let slack = solid.near();
    let reach = |c: &Candidate, e: usize| grid.elements[e].reach_from(c.centre);
    let mut radius: Vec<f64> = picked
        .iter()
        .map(|(c, mine)| mine.iter().map(|&e| reach(c, e)).fold(0.0, f64::max))
        .collect();
    let mut owned: Vec<Vec<usize>> = picked.iter().map(|(_, mine)| mine.clone()).collect();
    let mut kept = vec![true; picked.len()];
    let mut order: Vec<usize> = (0..picked.len()).collect();
    order.sort_by_key(|&i| owned[i].len());
    for i in order {
        check(stop)?;
        // For each element, the other sphere that takes it with the least growth.
        let mut moves = Vec::with_capacity(owned[i].len());
        for &e in &owned[i] {
            let best = (0..picked.len())
                .filter(|&j| j != i && kept[j])
                .filter(|&j| grid.elements[e].within(picked[j].0.centre, picked[j].0.reach))
                .map(|j| (j, (reach(&picked[j].0, e) - radius[j]).max(0.0)))
                .min_by(|a, b| a.1.total_cmp(&b.1));
            match best {
                Some((j, _)) => moves.push((e, j)),
                None => break,
            }
        }
        if moves.len() < owned[i].len() {
            continue;
        }
        kept[i] = false;
        owned[i].clear();
        for (e, j) in moves {
            radius[j] = radius[j].max(reach(&picked[j].0, e));
            owned[j].push(e);
        }
    }
    Ok(picked
        .iter()
        .zip(radius)
        .zip(kept)
        .filter(|(_, k)| *k)
        .map(|(((c, _), r), _)| CoverSphere {
            centre: c.centre,
            radius: r + slack,
            protrusion: r + slack - c.depth,
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn covered(spheres: &[CoverSphere], p: DVec3) -> bool {
        spheres.iter().any(|s| p.distance(s.centre) <= s.radius)
    }

    #[test]
    fn a_cube_is_covered_within_the_tolerance() {
        let cube = TriangleMesh::cuboid(DVec3::splat(0.1)).unwrap();
        let options = CoverOptions {
            tolerance: 0.02,
            max_spheres: None,
        };
        let cover = SphereCover::new(&cube, &options).unwrap();
        assert!(cover.closed);
        assert!(
            cover.max_protrusion <= 0.02 + 1e-6,
            "{}",
            cover.max_protrusion
        );
        assert!(cover.measured_max <= cover.max_protrusion);
        assert!(cover.measured_mean > 0.0 && cover.measured_mean <= cover.measured_max);
        // The cube's corners, edge midpoints and centre are covered.
        for i in 0..27 {
            let p = DVec3::new(f64::from(i % 3), f64::from((i / 3) % 3), f64::from(i / 9)) * 0.1
                - DVec3::splat(0.1);
            assert!(covered(&cover.spheres, p), "{p}");
        }
        // A tight tolerance takes more spheres than a loose one, which takes a few.
        let loose = SphereCover::new(
            &cube,
            &CoverOptions {
                tolerance: 0.1,
                max_spheres: None,
            },
        )
        .unwrap();
        assert!(loose.spheres.len() <= 3, "{}", loose.spheres.len());
        assert!(cover.spheres.len() > loose.spheres.len());
    }

    #[test]
    fn a_sphere_budget_raises_the_tolerance() {
        // At 10 mm (8 times fewer cells than 5 mm: quick in the test profile), with the grid
        // placement (the medial one is tested in `medial_cover.rs`).
        let cylinder = TriangleMesh::cylinder(0.05, 0.4, 24).unwrap();
        let stop = AtomicBool::new(false);
        let free = SphereCover::new(
            &cylinder,
            &CoverOptions {
                tolerance: 0.01,
                max_spheres: None,
            },
        )
        .unwrap();
        let budget = SphereCover::placed(
            &cylinder,
            &CoverOptions {
                tolerance: 0.01,
                max_spheres: Some(4),
            },
            Placement::Grid,
            &stop,
        )
        .unwrap();
        assert!(free.spheres.len() > 4, "{}", free.spheres.len());
        assert!(budget.spheres.len() <= 4);
        assert!(budget.tolerance > 0.01);
        assert!(budget.max_protrusion <= budget.tolerance + 1e-6);
        assert!(free.max_protrusion <= 0.01 + 1e-6);
        // Along its axis and on its rim, the cylinder is covered.
        for s in 0..=20 {
            let z = -0.2 + 0.02 * f64::from(s);
            for p in [
                DVec3::new(0.0, 0.0, z),
                DVec3::new(0.05, 0.0, z),
                DVec3::new(0.0, -0.05, z),
            ] {
                assert!(covered(&free.spheres, p), "{p}");
                assert!(covered(&budget.spheres, p), "{p}");
            }
        }
    }

    #[test]
    fn bad_options_are_refused() {
        let cube = TriangleMesh::cuboid(DVec3::splat(0.1)).unwrap();
        for tolerance in [0.0, -1.0, f64::NAN] {
            assert!(
                SphereCover::new(
                    &cube,
                    &CoverOptions {
                        tolerance,
                        max_spheres: None
                    }
                )
                .is_err()
            );
        }
        assert!(
            SphereCover::new(
                &cube,
                &CoverOptions {
                    tolerance: 0.01,
                    max_spheres: Some(0)
                }
            )
            .is_err()
        );
    }
}
