//! [`ObstacleGrid`]: a uniform grid over one link's reachable obstacles, so that a check of
//! that link in a scene of thousands of obstacles looks only at those near its lanes.
//!
//! # What it may skip
//! Each obstacle whose bounding radius is at most the cell size ("small") sits in the cell of
//! its bounding sphere's centre; the others ("large") are always returned. A query names the
//! lanes' points (a link's bounding-sphere centre in each configuration of a batch) and a
//! reach; it visits the cells that overlap the box around those points grown by the reach,
//! the largest small bounding radius and a slack, and returns the small obstacles found there
//! and every large one, in their original order. An obstacle it leaves out has its bounding
//! sphere's centre beyond that box along some axis, so farther than the reach plus its bounding
//! radius (plus the slack) from every lane's point: each loop that uses the grid skips exactly
//! such obstacles itself (`Obstacle::contacts_lanes`, `Obstacle::may_be_within_lanes`), and
//! the slack covers the `f32` rounding of the box and of those tests, so the answers are those
//! of the linear scan, bit for bit. Cells are found by `floor((x − origin) / cell)`, clamped
//! to the grid, the same monotone arithmetic for obstacles and queries: an obstacle inside the
//! box is in a visited cell.
//!
//! A query that would visit more cells than there are obstacles is not worth it: it answers
//! `false` and the caller scans the list.

use glam::Vec3A;

use crate::Obstacle;
use crate::checking::lanes::{LANES, LaneF32, LanePoint};

/// Reachable lists shorter than this are scanned without a grid: the MotionBenchMaker scenes
/// (10–40 obstacles) keep the linear scan, where a query costs more than the tests it saves
/// (example `crowded_check`: a grid on every link slows their checks by two thirds, and is
/// still slower with 200 cubes added; with 700, lists of 256–512 on the outer links, it
/// halves a valid state's check).
pub(crate) const GRID_THRESHOLD: usize = 256;

/// At most this many cells per obstacle (the cell grows to keep within it).
const CELLS_PER_OBSTACLE: f32 = 8.0;

/// The largest of the lanes' values, NaN if any is NaN (so that a query given it scans the
/// list instead).
#[inline]
pub(crate) fn widest(values: LaneF32) -> f32 {
    values
        .to_array()
        .into_iter()
        .fold(f32::NEG_INFINITY, |m, x| {
            if m.is_nan() || x.is_nan() {
                f32::NAN
            } else {
                m.max(x)
            }
        })
}

/// The buffer a query writes into, with room for every obstacle of the longest list that has
/// a grid: a clone keeps that room (a plain `Vec`'s clone would not), so no check allocates.
#[derive(Debug, Default)]
pub(crate) struct Candidates(pub(crate) Vec<u32>);

impl Candidates {
    /// Room for `count` indices.
    pub(crate) fn with_capacity(count: usize) -> Self {
        Self(Vec::with_capacity(count))
    }
}

impl Clone for Candidates {
    fn clone(&self) -> Self {
        Self::with_capacity(self.0.capacity())
    }
}

/// A uniform grid over a list of obstacles (see the module documentation).
#[derive(Debug, Clone)]
pub(crate) struct ObstacleGrid {
    /// The lowest corner of cell `(0, 0, 0)`: the smallest coordinates of an obstacle's
    /// centre.
    origin: Vec3A,
    /// The largest coordinates of an obstacle's centre.
    top: Vec3A,
    /// One over the cell size.
    inverse: f32,
    /// Cells along x, y and z.
    dims: [usize; 3],
    /// Per cell (x fastest, then y, then z), where its entries of `items` begin; one more entry
    /// for the end.
    starts: Vec<u32>,
    /// Indices of the small obstacles, by cell, ascending within a cell.
    items: Vec<u32>,
    /// Indices of the large obstacles, ascending.
    large: Vec<u32>,
    /// The largest bounding radius of a small obstacle.
    small_bound: f32,
}

impl ObstacleGrid {
    /// The grid of `obstacles`, queried with reaches of about `reach` (a link's bounding
    /// radius): cells of half that, or larger so that nine in ten obstacles are small and the
    /// grid has at most eight cells per obstacle. `None` for an empty list.
    pub(crate) fn new(obstacles: &[Obstacle], reach: f32) -> Option<Self> {
        if obstacles.is_empty() {
            return None;
        }
        let mut bounds: Vec<f32> = obstacles.iter().map(|o| o.bounding_sphere().1).collect();
        let at = (bounds.len() * 9 / 10).min(bounds.len() - 1);
        let ninetieth = *bounds.select_nth_unstable_by(at, f32::total_cmp).1;
        let (mut low, mut high) = (Vec3A::splat(f32::INFINITY), Vec3A::splat(f32::NEG_INFINITY));
        for o in obstacles {
            let (c, _) = o.bounding_sphere();
            low = low.min(c);
            high = high.max(c);
        }
        let extent = (high - low).max(Vec3A::splat(1e-3));
        let sparse =
            (extent.x * extent.y * extent.z / (CELLS_PER_OBSTACLE * obstacles.len() as f32)).cbrt();
        let cell = (0.5 * reach).max(ninetieth).max(sparse).max(1e-3);
        let inverse = 1.0 / cell;
        let dims = (extent * inverse).to_array().map(|e| e as usize + 1);
        let mut grid = Self {
            origin: low,
            top: high,
            inverse,
            dims,
            starts: vec![0; dims[0] * dims[1] * dims[2] + 1],
            items: Vec::new(),
            large: Vec::new(),
            small_bound: 0.0,
        };
        // Counting sort by cell: indices stay ascending within a cell.
        let mut cells = Vec::with_capacity(obstacles.len());
        for (i, o) in obstacles.iter().enumerate() {
            let (c, r) = o.bounding_sphere();
            if r <= cell {
                grid.small_bound = grid.small_bound.max(r);
                let at = grid.cell_of(c.to_array());
                grid.starts[at + 1] += 1;
                cells.push((i as u32, at));
            } else {
                grid.large.push(i as u32);
            }
        }
        for at in 1..grid.starts.len() {
            grid.starts[at] += grid.starts[at - 1];
        }
        let mut next = grid.starts.clone();
        grid.items = vec![0; cells.len()];
        for (i, at) in cells {
            grid.items[next[at] as usize] = i;
            next[at] += 1;
        }
        Some(grid)
    }

    /// How many obstacles the grid holds, small and large.
    pub(crate) fn len(&self) -> usize {
        self.items.len() + self.large.len()
    }

    /// Along each axis, the cell of a coordinate (clamped to the grid).
    #[inline]
    fn axis_cell(&self, axis: usize, x: f32) -> usize {
        let t = ((x - self.origin.to_array()[axis]) * self.inverse).floor();
        // `as` saturates: below the grid (or NaN) is 0, above it the last cell.
        (t as usize).min(self.dims[axis] - 1)
    }

    /// The index into `starts` of the cell holding the point.
    fn cell_of(&self, p: [f32; 3]) -> usize {
        let [x, y, z] = [0, 1, 2].map(|a| self.axis_cell(a, p[a]));
        x + self.dims[0] * (y + self.dims[1] * z)
    }

    /// Writes into `out` (cleared first; it must hold [`len`](Self::len) entries without
    /// growing, so a query never allocates), in ascending order, the indices of the obstacles
    /// whose bounding sphere may come within `reach` of one of the points of `points` in the
    /// lanes of `lanes`, and every large obstacle. `false` (and `out` left as it is) if the
    /// query would visit more cells than the grid holds obstacles, or no lane is named: the
    /// caller then scans the whole list.
    pub(crate) fn candidates(
        &self,
        points: &LanePoint,
        lanes: u32,
        reach: f32,
        out: &mut Vec<u32>,
    ) -> bool {
        // A NaN reach (`f32::max` would skip it) comes here as NaN: scan the list.
        if lanes == 0 || !reach.is_finite() {
            return false;
        }
        let [xs, ys, zs] = points.map(|p| p.to_array());
        let (mut low, mut high) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        for l in (0..LANES).filter(|l| lanes >> l & 1 != 0) {
            for (a, x) in [xs[l], ys[l], zs[l]].into_iter().enumerate() {
                // A lane with a NaN coordinate meets nothing in the tests: `min` and `max` skip
                // it here.
                low[a] = low[a].min(x);
                high[a] = high[a].max(x);
            }
        }
        let magnitude = low
            .iter()
            .chain(&high)
            .map(|x| x.abs())
            .filter(|x| x.is_finite())
            .fold(0.0_f32, f32::max);
        // The reach, the largest small radius and the slack: relative rounding of both, and
        // of the coordinates' subtraction.
        let grow = (reach.max(0.0) + self.small_bound) * (1.0 + 1e-5) + 1e-5 + 1e-6 * magnitude;
        let mut range = [(0, 0); 3];
        let mut cells = 1_usize;
        for a in 0..3 {
            if low[a] > high[a] {
                // Every named lane is NaN: none can meet a small obstacle.
                cells = 0;
                break;
            }
            let (below, above) = (low[a] - grow, high[a] + grow);
            if above < self.origin.to_array()[a] || below > self.top.to_array()[a] {
                // The box misses every small obstacle's centre along this axis.
                cells = 0;
                break;
            }
            range[a] = (self.axis_cell(a, below), self.axis_cell(a, above));
            cells *= range[a].1 - range[a].0 + 1;
        }
        if cells > self.len() {
            return false;
        }
        out.clear();
        if cells > 0 {
            for z in range[2].0..=range[2].1 {
                for y in range[1].0..=range[1].1 {
                    let row = self.dims[0] * (y + self.dims[1] * z);
                    let (from, to) = (
                        self.starts[row + range[0].0] as usize,
                        self.starts[row + range[0].1 + 1] as usize,
                    );
                    out.extend_from_slice(&self.items[from..to]);
                }
            }
        }
        out.extend_from_slice(&self.large);
        out.sort_unstable();
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{ArmChecker, Scene, Shape};
    use glam::{DQuat, DVec3};

    /// Cubes of 1–4 cm and a few 30 cm boxes, from a seed.
    fn boxes(count: usize, mut state: u64) -> Vec<Obstacle> {
        let mut uniform = move |low: f64, high: f64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            low + (high - low) * (state >> 11) as f64 / (1_u64 << 53) as f64
        };
        (0..count)
            .map(|i| {
                let half = if i % 97 == 0 {
                    0.3
                } else {
                    uniform(0.005, 0.02)
                };
                let at = DVec3::new(uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(0.0, 1.5));
                let shape = Shape::Cuboid {
                    half_extents: DVec3::splat(half),
                };
                Obstacle::new(shape, at, DQuat::from_rotation_z(uniform(0.0, 3.0)))
            })
            .collect()
    }

    /// Every obstacle whose bounding sphere comes within the reach of a named lane's point is
    /// returned, once, in ascending order; those far from every lane are left out.
    #[test]
    fn a_query_returns_every_obstacle_near_a_lane_in_order() {
        let obstacles = boxes(3000, 9);
        let grid = ObstacleGrid::new(&obstacles, 0.12).unwrap();
        assert!(!grid.large.is_empty() && grid.items.len() > 2900);
        let mut out = Vec::with_capacity(grid.len());
        let mut state = 5_u64;
        let mut next = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 40) as f32 / (1 << 24) as f32
        };
        let mut skipped = 0;
        for trial in 0..200 {
            let centre = [next() * 2.4 - 1.2, next() * 2.4 - 1.2, next() * 1.8 - 0.2];
            let spread = if trial % 2 == 0 { 0.0 } else { 0.3 };
            let points: LanePoint = std::array::from_fn(|a| {
                LaneF32::new(std::array::from_fn(|_| centre[a] + spread * (next() - 0.5)))
            });
            let lanes = if trial % 3 == 0 {
                0b101
            } else {
                (1 << LANES) - 1
            };
            let reach = 0.05 + 0.1 * next();
            assert!(grid.candidates(&points, lanes, reach, &mut out));
            assert!(out.windows(2).all(|w| w[0] < w[1]), "{out:?}");
            let coordinates = points.map(|p| p.to_array());
            for (i, o) in obstacles.iter().enumerate() {
                let (c, r) = o.bounding_sphere();
                let near = (0..LANES).filter(|l| lanes >> l & 1 != 0).any(|l| {
                    let p = Vec3A::new(coordinates[0][l], coordinates[1][l], coordinates[2][l]);
                    p.distance(c) <= reach + r
                });
                let found = out.binary_search(&(i as u32)).is_ok();
                assert!(found || !near, "obstacle {i} missed");
                skipped += usize::from(!found);
            }
        }
        // The grid leaves out nearly everything.
        assert!(skipped > 150 * obstacles.len(), "{skipped}");
    }

    /// Lists shorter than the threshold get no grid (the MotionBenchMaker scenes keep the
    /// linear scan); a scene of thousands gets one on the links that reach them.
    #[test]
    fn only_long_reachable_lists_get_a_grid() {
        let robot = crate::ArmProblem::panda().unwrap();
        let few = ArmChecker::new(&robot, &Scene::new(boxes(40, 3)));
        assert!(few.shared.grids.iter().all(Option::is_none));
        let many = ArmChecker::new(&robot, &Scene::new(boxes(5000, 3)));
        let gridded = many.shared.grids.iter().flatten().count();
        assert!(gridded >= 5, "{gridded}");
        for (grid, list) in many.shared.grids.iter().zip(&many.shared.reachable) {
            assert_eq!(grid.is_some(), list.len() >= GRID_THRESHOLD);
        }
    }
}
