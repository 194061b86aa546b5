//! [`CellGrid`]: the solid cut into grid cells, each cell's part of the solid bounded by a
//! box that a covering sphere must contain.
//!
//! Why a few points per cell suffice: the part of the solid in a cell is contained in the
//! convex hull of the cell's corners inside the solid and the pieces of the surface inside the
//! cell (an extreme point of that part is either a corner of the cell or on the surface). The
//! element of a cell is the set of those corners and of the vertices of the surface triangles
//! clipped to the cell; a ball is convex, so a sphere that contains the element's points
//! contains their hull, and so the cell's part of the solid. For an open mesh the solid is the
//! surface, and only the clipped triangles count. The points' bounding box is kept too: a
//! sphere containing the box contains the points (a quick test), but the box reaches up to a
//! cell's diagonal beyond the solid where the points do not.

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};

use glam::DVec3;

use super::solid::Solid;
use super::spherise_error::SpheriseError;

/// The most cells a grid may have; a finer grid is coarsened to this (the cover refuses,
/// before building a grid, a tolerance that would need more: [`MAX_COVER_CELLS`]).
///
/// [`MAX_COVER_CELLS`]: super::MAX_COVER_CELLS
pub(super) const MAX_CELLS: usize = super::MAX_COVER_CELLS;

/// The cells of a grid of edge `h` over the box `[lo, hi]` (as `f64`: it may overflow any
/// integer).
pub(super) fn cells_over(lo: DVec3, hi: DVec3, h: f64) -> f64 {
    (((hi - lo) / h).floor() + DVec3::splat(2.0)).element_product()
}

/// [`SpheriseError::Stopped`] if `stop` is raised.
pub(super) fn check(stop: &AtomicBool) -> Result<(), SpheriseError> {
    if stop.load(Ordering::Relaxed) {
        Err(SpheriseError::Stopped)
    } else {
        Ok(())
    }
}

/// One cell's part of the solid: points whose convex hull contains it, and their box.
#[derive(Debug, Clone)]
pub(super) struct Element {
    /// The points (inside corners and clipped surface vertices), without repeats.
    pub(super) points: Vec<DVec3>,
    /// The box's lower corner.
    pub(super) lo: DVec3,
    /// The box's upper corner.
    pub(super) hi: DVec3,
    /// The cell's smallest corner index, per axis.
    pub(super) cell: [usize; 3],
    /// Whether the surface passes through the cell.
    pub(super) surface: bool,
}

impl Element {
    /// The distance from `c` to the element's farthest point: a sphere about `c` contains
    /// the element's hull iff its radius is at least this.
    pub(super) fn reach_from(&self, c: DVec3) -> f64 {
        self.points
            .iter()
            .map(|p| p.distance_squared(c))
            .fold(0.0, f64::max)
            .sqrt()
    }

    /// Whether the sphere of radius `r` about `c` contains every point of the element (the
    /// box first: containing its farthest corner settles it).
    pub(super) fn within(&self, c: DVec3, r: f64) -> bool {
        let r2 = r * r;
        if (c - self.lo)
            .abs()
            .max((c - self.hi).abs())
            .length_squared()
            <= r2
        {
            return true;
        }
        // The box's nearest point farther than r: so is every point.
        if (c.clamp(self.lo, self.hi) - c).length_squared() > r2 {
            return false;
        }
        self.points.iter().all(|p| p.distance_squared(c) <= r2)
    }

    /// The box's centre.
    pub(super) fn centre(&self) -> DVec3 {
        (self.lo + self.hi) / 2.0
    }
}

/// A grid over the mesh's bounds and the elements of its cells.
pub(super) struct CellGrid {
    /// The position of corner `(0, 0, 0)`.
    pub(super) origin: DVec3,
    /// The cells' edge length.
    pub(super) h: f64,
    /// Cells per axis.
    pub(super) n: [usize; 3],
    /// Per corner: inside the solid (or near its surface, or undecided).
    pub(super) inside: Vec<bool>,
    /// Per corner: inside by a decided parity test (usable as the centre of an inner ball).
    pub(super) trusted: Vec<bool>,
    /// The elements.
    pub(super) elements: Vec<Element>,
    /// Per cell: its element, or `u32::MAX`.
    pub(super) element_of: Vec<u32>,
}

impl CellGrid {
    /// The elements of `solid` on a grid of cells of edge about `h` (coarser if the grid
    /// would have more than [`MAX_CELLS`]).
    ///
    /// # Errors
    /// [`SpheriseError::Stopped`] once `stop` is raised (polled per column and per triangle).
    pub(super) fn new(solid: &Solid, h: f64, stop: &AtomicBool) -> Result<Self, SpheriseError> {
        let mesh = solid.mesh();
        let (lo, hi) = mesh.bounds();
        let mut h = h;
        while cells_over(lo, hi, h) > MAX_CELLS as f64 {
            h *= 1.25;
        }
        // An offset of the grid from the bounds, so that flat faces on round coordinates
        // do not lie on grid planes.
        let origin = lo - h * DVec3::new(0.513, 0.537, 0.571);
        let n = ((hi - origin) / h)
            .floor()
            .as_usizevec3()
            .to_array()
            .map(|v| v + 1);
        let mut grid = Self {
            origin,
            h,
            n,
            inside: Vec::new(),
            trusted: Vec::new(),
            elements: Vec::new(),
            element_of: Vec::new(),
        };
        grid.classify_corners(solid, stop)?;
        grid.make_elements(solid, stop)?;
        Ok(grid)
    }

    /// The position of corner `(i, j, k)`.
    pub(super) fn corner(&self, [i, j, k]: [usize; 3]) -> DVec3 {
        self.origin + self.h * DVec3::new(i as f64, j as f64, k as f64)
    }

    /// The index of corner `(i, j, k)` in [`inside`](Self::inside).
    pub(super) fn corner_index(&self, [i, j, k]: [usize; 3]) -> usize {
        (i * (self.n[1] + 1) + j) * (self.n[2] + 1) + k
    }

    /// The index of cell `(i, j, k)` in [`element_of`](Self::element_of).
    pub(super) fn cell_index(&self, [i, j, k]: [usize; 3]) -> usize {
        (i * self.n[1] + j) * self.n[2] + k
    }

    /// The range of cells, per axis, that meet the box `[lo, hi]`.
    pub(super) fn cell_range(&self, lo: DVec3, hi: DVec3) -> [std::ops::RangeInclusive<usize>; 3] {
        let index = |v: f64, axis: usize| {
            let cell = ((v - self.origin[axis]) / self.h).floor();
            cell.clamp(0.0, (self.n[axis] - 1) as f64) as usize
        };
        [0, 1, 2].map(|a| index(lo[a], a)..=index(hi[a], a))
    }

    fn classify_corners(&mut self, solid: &Solid, stop: &AtomicBool) -> Result<(), SpheriseError> {
        let count = (self.n[0] + 1) * (self.n[1] + 1) * (self.n[2] + 1);
        self.inside = vec![false; count];
        self.trusted = vec![false; count];
        if !solid.has_inside() && !solid.is_filled() {
            return Ok(());
        }
        for i in 0..=self.n[0] {
            for j in 0..=self.n[1] {
                check(stop)?;
                let base = self.corner([i, j, 0]);
                let crossings = solid.column_crossings(base.x, base.y);
                for k in 0..=self.n[2] {
                    let p = self.corner([i, j, k]);
                    let index = self.corner_index([i, j, k]);
                    let near = solid.surface_distance(p) <= solid.near();
                    match &crossings {
                        Some(column) => {
                            self.inside[index] = near || column.inside(p.z) || solid.in_fill(p);
                            self.trusted[index] = self.inside[index];
                        }
                        // Undecided: count the point as inside (the cover then contains
                        // it), but never centre an inner ball on it.
                        None => self.inside[index] = true,
                    }
                }
            }
        }
        Ok(())
    }

    fn make_elements(&mut self, solid: &Solid, stop: &AtomicBool) -> Result<(), SpheriseError> {
        let mesh = solid.mesh();
        let mut cells: HashMap<usize, Vec<DVec3>> = HashMap::new();
        let mut polygon = Vec::with_capacity(12);
        let mut scratch = Vec::with_capacity(12);
        for t in 0..mesh.triangles().len() {
            check(stop)?;
            let corners = mesh.corners(t);
            for &v in &corners {
                let [ri, rj, rk] = self.cell_range(v, v);
                let cell = self.cell_index([*ri.start(), *rj.start(), *rk.start()]);
                cells.entry(cell).or_default().push(v);
            }
            let lo = corners[0].min(corners[1]).min(corners[2]);
            let hi = corners[0].max(corners[1]).max(corners[2]);
            let [ri, rj, rk] = self.cell_range(lo, hi);
            for i in ri {
                for j in rj.clone() {
                    for k in rk.clone() {
                        let cell_lo = self.corner([i, j, k]);
                        let cell_hi = self.corner([i + 1, j + 1, k + 1]);
                        polygon.clear();
                        polygon.extend_from_slice(&corners);
                        clip_to_box(&mut polygon, &mut scratch, cell_lo, cell_hi);
                        if !polygon.is_empty() {
                            let points = cells.entry(self.cell_index([i, j, k])).or_default();
                            points.extend_from_slice(&polygon);
                        }
                    }
                }
            }
        }
        let cell_count = self.n[0] * self.n[1] * self.n[2];
        self.element_of = vec![u32::MAX; cell_count];
        for i in 0..self.n[0] {
            for j in 0..self.n[1] {
                check(stop)?;
                for k in 0..self.n[2] {
                    let cell = [i, j, k];
                    let index = self.cell_index(cell);
                    let mut points = cells.remove(&index).unwrap_or_default();
                    let surface = !points.is_empty();
                    for corner in 0..8 {
                        let c = [i + (corner & 1), j + ((corner >> 1) & 1), k + (corner >> 2)];
                        if self.inside[self.corner_index(c)] {
                            points.push(self.corner(c));
                        }
                    }
                    if points.is_empty() {
                        continue;
                    }
                    points.sort_by(|a, b| {
                        a.x.total_cmp(&b.x)
                            .then(a.y.total_cmp(&b.y))
                            .then(a.z.total_cmp(&b.z))
                    });
                    points.dedup();
                    points.shrink_to_fit();
                    let (lo, hi) = points.iter().fold((points[0], points[0]), |(lo, hi), &p| {
                        (lo.min(p), hi.max(p))
                    });
                    self.element_of[index] = u32::try_from(self.elements.len()).unwrap_or(u32::MAX);
                    self.elements.push(Element {
                        points,
                        lo,
                        hi,
                        cell,
                        surface,
                    });
                }
            }
        }
        Ok(())
    }
}

/// Clips the convex polygon to the box `[lo, hi]` (Sutherland–Hodgman, one plane at a time);
/// points made on a plane get the plane's coordinate exactly.
fn clip_to_box(polygon: &mut Vec<DVec3>, scratch: &mut Vec<DVec3>, lo: DVec3, hi: DVec3) {
    for axis in 0..3 {
        for (bound, keep_above) in [(lo[axis], true), (hi[axis], false)] {
            if polygon.is_empty() {
                return;
            }
            let inside = |p: DVec3| {
                if keep_above {
                    p[axis] >= bound
                } else {
                    p[axis] <= bound
                }
            };
            scratch.clear();
            for e in 0..polygon.len() {
                let (p, q) = (polygon[e], polygon[(e + 1) % polygon.len()]);
                if inside(p) {
                    scratch.push(p);
                }
                if inside(p) != inside(q) {
                    let t = (bound - p[axis]) / (q[axis] - p[axis]);
                    let mut x = p + (q - p) * t;
                    x[axis] = bound;
                    scratch.push(x);
                }
            }
            std::mem::swap(polygon, scratch);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spherise::triangle_mesh::TriangleMesh;

    #[test]
    fn clipping_keeps_the_part_in_the_box() {
        let mut polygon = vec![
            DVec3::ZERO,
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(0.0, 2.0, 0.0),
        ];
        let mut scratch = Vec::new();
        clip_to_box(
            &mut polygon,
            &mut scratch,
            DVec3::splat(-1.0),
            DVec3::splat(1.0),
        );
        // The triangle cut by x ≤ 1 and y ≤ 1: a quadrilateral (0,0), (1,0), (1,1), (0,1)
        // — (1,1) lies on the hypotenuse.
        let mut distinct = polygon.clone();
        distinct.dedup();
        assert_eq!(distinct.len(), 4, "{polygon:?}");
        for p in &polygon {
            assert!(p.x <= 1.0 && p.y <= 1.0 && p.x + p.y <= 2.0 + 1e-12);
        }
        clip_to_box(
            &mut polygon,
            &mut scratch,
            DVec3::splat(5.0),
            DVec3::splat(6.0),
        );
        assert!(polygon.is_empty());
    }

    #[test]
    fn a_cube_is_cut_into_interior_and_surface_elements() {
        let cube = Solid::new(TriangleMesh::cuboid(DVec3::splat(0.5)).unwrap()).unwrap();
        let grid = CellGrid::new(&cube, 0.1, &AtomicBool::new(false)).unwrap();
        assert!(grid.elements.iter().any(|e| e.surface));
        assert!(grid.elements.iter().any(|e| !e.surface));
        // Every element lies within the cube (its points are in the solid).
        for e in &grid.elements {
            assert!(e.lo.cmpge(DVec3::splat(-0.5 - 1e-12)).all(), "{e:?}");
            assert!(e.hi.cmple(DVec3::splat(0.5 + 1e-12)).all(), "{e:?}");
            // The points span the box, and a sphere holding the box holds them.
            assert!(!e.points.is_empty());
            let centre = e.centre();
            let far = e.reach_from(centre);
            assert!(far <= (e.hi - e.lo).length() / 2.0 + 1e-12);
            assert!(e.within(centre, far * (1.0 + 1e-12)));
            assert!(!e.within(centre, far * 0.999 - 1e-12));
        }
        // The boxes of the elements cover the cube's volume (a unit cube): their sum is at
        // least 1, less the sliver rounding takes.
        let volume: f64 = grid
            .elements
            .iter()
            .map(|e| (e.hi - e.lo).element_product())
            .sum();
        assert!((volume - 1.0).abs() < 1e-9, "{volume}");
    }
}
