//! [`PointTree`]: points arranged for sphere queries — a balanced binary tree of axis-aligned
//! boxes over the points, laid out implicitly, with leaves of at most sixteen points.

use std::ops::Range;

use glam::Vec3;
use mit_star_spaces::Stop;

use crate::lane_f32::LaneF32;

/// Most points in a leaf. Sixteen rather than eight: one level fewer to walk for a leaf scan
/// twice as long, and RRT-Connect among the seven Panda scenes' clouds 7 % faster in all
/// (`cloud_profile`; 32 is no faster).
const LEAF: usize = 16;

/// Deepest traversal stack: a tree of [`PointCloud::MAX_POINTS`](crate::PointCloud::MAX_POINTS)
/// points is at most 21 levels deep, and a depth-first walk holds at most one entry per level
/// plus one — or, where it pushes four grandchildren for one node, three per two levels plus
/// one: 33 at most.
const STACK: usize = 48;

/// What a computed distance is multiplied by before it is handed out as a lower bound: covers
/// the `f32` rounding of the squared distance (a few units in the last place) with room.
pub(crate) const LOWER: f32 = 1.0 - 1e-6;

/// Nodes built between two polls of the stop condition.
const POLL_NODES: usize = 1 << 12;

/// The point structure of cloud obstacles, built for the queries the arm checker asks:
/// *is any point within `reach` of this centre* (one centre, or one per lane of a batch of
/// configurations), *how far is the nearest point, at least*, and *which points are within
/// this reach of these centres* (both for certified motion).
///
/// # Layout
/// The points are reordered by recursive median splits along the longest side of their box
/// (a kd-tree whose splits halve the count), so that every node is a contiguous range of the
/// array: node `i` covers `[lo, hi)`, its children `2i + 1` and `2i + 2` the halves
/// `[lo, mid)` and `[mid, hi)` with `mid = lo + (hi − lo) / 2`, and ranges of at most
/// sixteen points are leaves. Nothing but one box per node is stored (six `f32`, 24 bytes,
/// one node per four to eight points): the points themselves in three coordinate arrays (12
/// bytes a point) and their indices in the cloud (4 bytes). 19–22 bytes a point in all
/// (`tests/cloud_structure.rs` measures it at 10⁶ points).
///
/// # Queries
/// A walk from the root skips every node whose box is farther than the query asks (nearer
/// child first), and tests the points of the leaves it reaches. The batched queries walk once
/// for a batch of `LANES` centres (the arm checker's configurations): a node is visited if
/// its box is near for some lane still undecided, its points tested in every lane at once.
///
/// The answers are exact for the `f32` arithmetic of `|c − p|² ≤ reach²` (the box of a node
/// is never computed nearer than its points, as rounding is monotonic, so pruning never
/// changes an answer), and the batched answers are the single queries' answers bit for bit.
/// The distance lower bounds are shrunk by a millionth to cover rounding.
///
/// This is our own structure, written from reading VAMP's CAPT (Ramsey et al., RSS 2024),
/// which precomputes per leaf of a kd-tree the points a sphere of the robot's radii could
/// touch; the plain tree keeps memory small, answers any radius, distances as well as
/// booleans, and a batch of lanes in one walk. The precomputed sets are the
/// [`AffordanceTree`](crate::AffordanceTree), which a cloud obstacle may add beside it.
#[derive(Debug, Clone)]
pub struct PointTree {
    xs: Vec<f32>,
    ys: Vec<f32>,
    zs: Vec<f32>,
    /// Per stored point: its index in the cloud it came from.
    order: Vec<u32>,
    /// Per node (implicit layout): its box, `[min x, min y, min z, max x, max y, max z]`.
    boxes: Vec<[f32; 6]>,
}

impl PointTree {
    /// The tree of `points` (finite: a [`PointCloud`](crate::PointCloud)'s points; at least
    /// one). `O(n log n)`.
    ///
    /// # Panics
    /// If `points` is empty or holds more than `u32::MAX` points (a
    /// [`PointCloud`](crate::PointCloud) holds neither).
    pub fn new(points: &[Vec3]) -> Self {
        Self::new_polled(points, &mit_star_spaces::Never).expect("never stopped")
    }

    /// As [`new`](Self::new), polling `stop` every few thousand nodes: `None` if it said to
    /// stop (for clouds of millions of points built under a time limit).
    pub fn new_polled(points: &[Vec3], stop: &dyn Stop) -> Option<Self> {
        assert!(!points.is_empty() && u32::try_from(points.len()).is_ok());
        let n = points.len();
        let mut items: Vec<(Vec3, u32)> = points
            .iter()
            .enumerate()
            .map(|(i, p)| (*p, i as u32))
            .collect();
        let mut boxes = vec![[0.0_f32; 6]; node_count(n)];
        let mut stack = vec![(0_usize, 0_usize, n)];
        let mut built = 0;
        while let Some((node, lo, hi)) = stack.pop() {
            built += 1;
            if built % POLL_NODES == 0 && stop.should_stop() {
                return None;
            }
            let range = &mut items[lo..hi];
            let (min, max) = range.iter().fold(
                (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
                |(min, max), (p, _)| (min.min(*p), max.max(*p)),
            );
            boxes[node] = [min.x, min.y, min.z, max.x, max.y, max.z];
            if hi - lo <= LEAF {
                continue;
            }
            let side = max - min;
            let axis = if side.x >= side.y && side.x >= side.z {
                0
            } else if side.y >= side.z {
                1
            } else {
                2
            };
            let mid = split(lo, hi);
            range.select_nth_unstable_by(mid - lo, |a, b| a.0[axis].total_cmp(&b.0[axis]));
            stack.push((2 * node + 2, mid, hi));
            stack.push((2 * node + 1, lo, mid));
        }
        Some(Self {
            xs: items.iter().map(|(p, _)| p.x).collect(),
            ys: items.iter().map(|(p, _)| p.y).collect(),
            zs: items.iter().map(|(p, _)| p.z).collect(),
            order: items.iter().map(|&(_, i)| i).collect(),
            boxes,
        })
    }

    /// The points, in the tree's order.
    pub(crate) fn points(&self) -> Vec<Vec3> {
        (0..self.len())
            .map(|j| Vec3::new(self.xs[j], self.ys[j], self.zs[j]))
            .collect()
    }

    /// How many points.
    pub fn len(&self) -> usize {
        self.xs.len()
    }

    /// Always `false`: a tree has at least one point.
    pub fn is_empty(&self) -> bool {
        self.xs.is_empty()
    }

    /// The box of all the points: minimum and maximum corners.
    pub fn bounds(&self) -> (Vec3, Vec3) {
        let b = &self.boxes[0];
        (Vec3::new(b[0], b[1], b[2]), Vec3::new(b[3], b[4], b[5]))
    }

    /// Bytes the structure holds (its arrays' capacities).
    pub fn memory_bytes(&self) -> usize {
        4 * (self.xs.capacity() + self.ys.capacity() + self.zs.capacity())
            + 4 * self.order.capacity()
            + 24 * self.boxes.capacity()
            + std::mem::size_of::<Self>()
    }

    /// `true` if some point is within `reach` of `center` (`|c − p|² ≤ reach²` in `f32`).
    pub fn any_within(&self, center: Vec3, reach: f32) -> bool {
        let r2 = reach * reach;
        let mut walk = Walk::new(self.len());
        while let Some((node, lo, hi)) = walk.pop() {
            if box_distance_squared(&self.boxes[node], center) > r2 {
                continue;
            }
            if hi - lo <= LEAF {
                for j in lo..hi {
                    if self.distance_squared(j, center) <= r2 {
                        return true;
                    }
                }
                continue;
            }
            self.push_children(&mut walk, (node, lo, hi), center);
        }
        false
    }

    /// A lower bound of the distance from `point` to the nearest point, or `limit` if none is
    /// nearer than that (a walk that looks no further than `limit`; `f32::INFINITY` for the
    /// exact nearest distance). Never above the true distance; below it by at most a
    /// millionth when at most `limit`.
    pub fn distance_lower_bound(&self, point: Vec3, limit: f32) -> f32 {
        self.nearest_squared(point, limit).0.sqrt() * LOWER
    }

    /// The nearest point to `point` if one is within `limit`: its index in the cloud and its
    /// distance (`f32`).
    pub fn nearest(&self, point: Vec3, limit: f32) -> Option<(usize, f32)> {
        let (d2, j) = self.nearest_squared(point, limit);
        j.map(|j| (self.order[j] as usize, d2.sqrt()))
    }

    /// The smallest squared distance below `limit²` and the stored point at it.
    fn nearest_squared(&self, point: Vec3, limit: f32) -> (f32, Option<usize>) {
        let mut best = limit * limit;
        let mut at = None;
        let mut walk = Walk::new(self.len());
        while let Some((node, lo, hi)) = walk.pop() {
            if box_distance_squared(&self.boxes[node], point) >= best {
                continue;
            }
            if hi - lo <= LEAF {
                for j in lo..hi {
                    let d2 = self.distance_squared(j, point);
                    if d2 < best {
                        best = d2;
                        at = Some(j);
                    }
                }
                continue;
            }
            self.push_children(&mut walk, (node, lo, hi), point);
        }
        (best, at)
    }

    /// Pushes the two children of an inner node, the nearer to `point` last (popped first).
    #[inline]
    fn push_children(&self, walk: &mut Walk, (node, lo, hi): (usize, usize, usize), point: Vec3) {
        let mid = split(lo, hi);
        let (left, right) = (2 * node + 1, 2 * node + 2);
        let near_left = box_distance_squared(&self.boxes[left], point)
            <= box_distance_squared(&self.boxes[right], point);
        if near_left {
            walk.push(right, mid, hi);
            walk.push(left, lo, mid);
        } else {
            walk.push(left, lo, mid);
            walk.push(right, mid, hi);
        }
    }

    /// The lane walks' step at an inner node: tests both children's boxes in every lane at
    /// once (`near` says, from a child's squared box distances, whether some lane needs it)
    /// and pushes the near ones, the nearer for lane `first` last (popped first).
    #[inline(always)]
    fn push_near_children(
        &self,
        walk: &mut Walk,
        (node, lo, hi): (usize, usize, usize),
        point: &[LaneF32; 3],
        first: usize,
        near: impl Fn(LaneF32) -> bool,
    ) {
        let mid = split(lo, hi);
        let (left, right) = (2 * node + 1, 2 * node + 2);
        let to_left = box_lanes(&self.boxes[left], point);
        let to_right = box_lanes(&self.boxes[right], point);
        match (near(to_left), near(to_right)) {
            (true, true) => {
                // Lane `first`'s order, read off one comparison of every lane.
                if to_left.simd_le(to_right).to_bitmask() >> first & 1 != 0 {
                    walk.push(right, mid, hi);
                    walk.push(left, lo, mid);
                } else {
                    walk.push(left, lo, mid);
                    walk.push(right, mid, hi);
                }
            }
            (true, false) => walk.push(left, lo, mid),
            (false, true) => walk.push(right, mid, hi),
            (false, false) => {}
        }
    }

    /// The contact walk's step at a node whose children are both inner nodes: its four
    /// grandchildren's boxes tested at once, and the near ones pushed, leftmost popped first.
    /// Four independent tests instead of two levels of two, each level waiting on the last: a
    /// walk is a chain of dependent box tests, and this halves its length (a grandchild's box
    /// lies inside its parent's, so it prunes at least as much). RRT-Connect among the cage
    /// scene's clouds 9 % faster (`cloud_profile`); three levels at once (eight boxes) are
    /// slower than two, and the certification walk, whose nearest-first order needs the
    /// distances sorted, gains nothing from it.
    #[inline(always)]
    fn push_near_grandchildren(
        &self,
        walk: &mut Walk,
        (node, lo, hi): (usize, usize, usize),
        point: &[LaneF32; 3],
        near: impl Fn(LaneF32) -> bool,
    ) {
        let mid = split(lo, hi);
        let cuts = [lo, split(lo, mid), mid, split(mid, hi), hi];
        // Node `i`'s grandchildren are `4i + 3 .. 4i + 7`, side by side in the array.
        let base = 4 * node + 3;
        let boxes = &self.boxes[base..base + 4];
        let hits: [bool; 4] = std::array::from_fn(|g| near(box_lanes(&boxes[g], point)));
        for g in (0..4).rev() {
            if hits[g] {
                walk.push(base + g, cuts[g], cuts[g + 1]);
            }
        }
    }

    #[inline(always)]
    fn distance_squared(&self, j: usize, c: Vec3) -> f32 {
        let (dx, dy, dz) = (c.x - self.xs[j], c.y - self.ys[j], c.z - self.zs[j]);
        dx * dx + dy * dy + dz * dz
    }

    /// Bit `l` set if lane `l` of `active` has a point within `reach[l]` of its centre: the
    /// answers of [`any_within`](Self::any_within), a batch at once.
    pub(crate) fn any_within_lanes(
        &self,
        center: &[LaneF32; 3],
        reach: LaneF32,
        active: u32,
    ) -> u32 {
        let r2 = reach * reach;
        let mut open = active;
        if box_lanes(&self.boxes[0], center).simd_le(r2).to_bitmask() & open == 0 {
            return 0;
        }
        let mut found = 0;
        // A node's grandchildren are tested when it is reached, their four boxes at once in
        // every lane, and only the near ones pushed (leftmost first); where a child is a leaf,
        // its two children (the nearer first for the first open lane).
        let mut walk = Walk::new(self.len());
        while let Some((node, lo, hi)) = walk.pop() {
            if hi - lo <= LEAF {
                // The leaf's nearest point per lane, then one test (a NaN centre's lane stays
                // infinite: no contact, as `NaN ≤ r²` is not).
                let nearest = self.leaf_nearest(lo..hi, center, LaneF32::splat(f32::INFINITY));
                let hit = nearest.simd_le(r2).to_bitmask() & open;
                if hit != 0 {
                    found |= hit;
                    open &= !hit;
                    if open == 0 {
                        return found;
                    }
                }
                continue;
            }
            let near = |d: LaneF32| d.simd_le(r2).to_bitmask() & open != 0;
            // Both children inner nodes: the left, the smaller, holds more than a leaf.
            if split(lo, hi) - lo > LEAF {
                self.push_near_grandchildren(&mut walk, (node, lo, hi), center, near);
            } else {
                let first = open.trailing_zeros() as usize;
                self.push_near_children(&mut walk, (node, lo, hi), center, first, near);
            }
        }
        found
    }

    /// Per lane, [`distance_lower_bound`](Self::distance_lower_bound) of its point with its
    /// limit; the walk follows the lanes of `live` (others get a value no smaller than theirs
    /// would be, but no larger than their limit).
    pub(crate) fn lower_bounds_lanes(
        &self,
        point: &[LaneF32; 3],
        limit: LaneF32,
        live: u32,
    ) -> LaneF32 {
        let mut best = limit * limit;
        if box_lanes(&self.boxes[0], point).simd_lt(best).to_bitmask() & live == 0 {
            return best.sqrt() * LaneF32::splat(LOWER);
        }
        // A lane of `live` passed the root's test: `first` is one of the lanes.
        let first = live.trailing_zeros() as usize;
        // Children are tested when their parent is reached, in every lane against the best so
        // far, and only the near ones pushed (the nearer first for the first live lane).
        let mut walk = Walk::new(self.len());
        while let Some((node, lo, hi)) = walk.pop() {
            if hi - lo <= LEAF {
                best = self.leaf_nearest(lo..hi, point, best);
                continue;
            }
            self.push_near_children(&mut walk, (node, lo, hi), point, first, |d| {
                d.simd_lt(best).to_bitmask() & live != 0
            });
        }
        best.sqrt() * LaneF32::splat(LOWER)
    }

    /// Calls `visit` for each stored point within `reach` of the centre of a lane of `live`
    /// (`reach[l]` for lane `l`; squared distances compared in `f32`), with the point, every
    /// lane's squared distance to it, and the mask (all bits set) of the lanes of `live`
    /// within reach; `visit` returns the reach for the rest of the walk, which may only shrink
    /// (a larger one is not honoured). Nodes whose boxes lie beyond the reach in every lane of
    /// `live` are skipped (never computed nearer than their points, so no point within the
    /// reach is missed).
    pub(crate) fn visit_within_lanes(
        &self,
        center: &[LaneF32; 3],
        reach: LaneF32,
        live: u32,
        mut visit: impl FnMut(Vec3, LaneF32, LaneF32) -> LaneF32,
    ) {
        let mut r2 = reach * reach;
        if live == 0 || box_lanes(&self.boxes[0], center).simd_lt(r2).to_bitmask() & live == 0 {
            return;
        }
        let lanes = LaneF32::new(std::array::from_fn(|l| {
            f32::from_bits(if live >> l & 1 != 0 { u32::MAX } else { 0 })
        }));
        let first = live.trailing_zeros() as usize;
        let mut walk = Walk::new(self.len());
        while let Some((node, lo, hi)) = walk.pop() {
            if hi - lo <= LEAF {
                for j in lo..hi {
                    let d2 = self.distance_lanes(j, center);
                    let within = d2.simd_lt(r2) & lanes;
                    if within.to_bitmask() != 0 {
                        let point = Vec3::new(self.xs[j], self.ys[j], self.zs[j]);
                        let next = visit(point, d2, within);
                        r2 = r2.min(next * next);
                    }
                }
                continue;
            }
            self.push_near_children(&mut walk, (node, lo, hi), center, first, |d| {
                d.simd_lt(r2).to_bitmask() & live != 0
            });
        }
    }

    /// Appends to `out` every point whose squared distance to the box `cell`
    /// (`[min x, min y, min z, max x, max y, max z]`, infinite sides allowed) is at most `r2`
    /// in `f32`: a walk skipping the nodes whose boxes are farther (never computed nearer than
    /// their points, so none is missed).
    pub(crate) fn points_near_box(&self, cell: &[f32; 6], r2: f32, out: &mut Vec<Vec3>) {
        let mut walk = Walk::new(self.len());
        while let Some((node, lo, hi)) = walk.pop() {
            if box_box_squared(&self.boxes[node], cell) > r2 {
                continue;
            }
            if hi - lo <= LEAF {
                for j in lo..hi {
                    let p = Vec3::new(self.xs[j], self.ys[j], self.zs[j]);
                    if box_distance_squared(cell, p) <= r2 {
                        out.push(p);
                    }
                }
                continue;
            }
            let mid = split(lo, hi);
            walk.push(2 * node + 2, mid, hi);
            walk.push(2 * node + 1, lo, mid);
        }
    }

    /// Per lane, the least of `init` and the squared distances to the stored points `range`
    /// (a leaf's). `fast_min` keeps its right-hand side where the distance is NaN (a NaN
    /// centre): that lane keeps `init`'s value, as `min` would give for an `init` that is
    /// not NaN.
    #[inline(always)]
    fn leaf_nearest(&self, range: Range<usize>, point: &[LaneF32; 3], init: LaneF32) -> LaneF32 {
        range.fold(init, |least, j| {
            self.distance_lanes(j, point).fast_min(least)
        })
    }

    #[inline(always)]
    fn distance_lanes(&self, j: usize, [x, y, z]: &[LaneF32; 3]) -> LaneF32 {
        let dx = *x - LaneF32::splat(self.xs[j]);
        let dy = *y - LaneF32::splat(self.ys[j]);
        let dz = *z - LaneF32::splat(self.zs[j]);
        dx * dx + dy * dy + dz * dz
    }
}

/// Where a node of the points `[lo, hi)` splits: its children hold `[lo, mid)` and `[mid, hi)`.
/// The build and every walk share it, so that a walk's ranges are the build's.
#[inline(always)]
fn split(lo: usize, hi: usize) -> usize {
    lo + (hi - lo) / 2
}

/// Nodes of the implicit tree of `n` points: a complete tree as deep as the deepest leaf.
fn node_count(n: usize) -> usize {
    let (mut depth, mut m) = (0, n);
    while m > LEAF {
        m = m.div_ceil(2);
        depth += 1;
    }
    (1 << (depth + 1)) - 1
}

/// The squared distance from `c` to the box (0 inside).
#[inline(always)]
fn box_distance_squared(b: &[f32; 6], c: Vec3) -> f32 {
    let dx = (b[0] - c.x).max(c.x - b[3]).max(0.0);
    let dy = (b[1] - c.y).max(c.y - b[4]).max(0.0);
    let dz = (b[2] - c.z).max(c.z - b[5]).max(0.0);
    dx * dx + dy * dy + dz * dz
}

/// The squared distance between two boxes (0 if they meet), never above the squared
/// distance from a point of `a` to the box `b`.
#[inline(always)]
fn box_box_squared(a: &[f32; 6], b: &[f32; 6]) -> f32 {
    let dx = (b[0] - a[3]).max(a[0] - b[3]).max(0.0);
    let dy = (b[1] - a[4]).max(a[1] - b[4]).max(0.0);
    let dz = (b[2] - a[5]).max(a[2] - b[5]).max(0.0);
    dx * dx + dy * dy + dz * dz
}

/// Per lane, [`box_distance_squared`].
#[inline(always)]
fn box_lanes(b: &[f32; 6], [x, y, z]: &[LaneF32; 3]) -> LaneF32 {
    let zero = LaneF32::ZERO;
    // `fast_max` is `max` wherever its right-hand side is not NaN (`max` spends two more
    // instructions a call to prefer the left side then): `c − hi` is NaN only where the
    // centre is, and then both sides are, and the final maximum with zero gives zero either
    // way — the box counts as near, so a NaN centre is still decided by the points.
    let axis = |lo: f32, hi: f32, c: LaneF32| {
        (LaneF32::splat(lo) - c)
            .fast_max(c - LaneF32::splat(hi))
            .fast_max(zero)
    };
    let (dx, dy, dz) = (
        axis(b[0], b[3], *x),
        axis(b[1], b[4], *y),
        axis(b[2], b[5], *z),
    );
    dx * dx + dy * dy + dz * dz
}

/// A depth-first walk's stack of nodes (node, first point, end), without allocation.
struct Walk {
    entries: [(u32, u32, u32); STACK],
    len: usize,
}

impl Walk {
    #[inline(always)]
    fn new(n: usize) -> Self {
        let mut walk = Self {
            entries: [(0, 0, 0); STACK],
            len: 0,
        };
        walk.push(0, 0, n);
        walk
    }

    #[inline(always)]
    fn push(&mut self, node: usize, lo: usize, hi: usize) {
        self.entries[self.len] = (node as u32, lo as u32, hi as u32);
        self.len += 1;
    }

    #[inline(always)]
    fn pop(&mut self) -> Option<(usize, usize, usize)> {
        self.len = self.len.checked_sub(1)?;
        let (node, lo, hi) = self.entries[self.len];
        Some((node as usize, lo as usize, hi as usize))
    }
}

/// `n` points on a jittered curve about the origin (within a unit box): the point queries'
/// test cloud.
#[cfg(test)]
pub(crate) fn curve_points(n: usize) -> Vec<Vec3> {
    (0..n)
        .map(|i| {
            let f = i as f32;
            Vec3::new((f * 0.37).sin(), (f * 0.71).cos(), (f * 0.13).sin() * 0.5)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points on a jittered grid, and queries around them: every answer is brute force's.
    #[test]
    fn queries_are_brute_force() {
        let points = curve_points(1000);
        let tree = PointTree::new(&points);
        assert_eq!(tree.len(), 1000);
        for q in 0..300 {
            let f = q as f32;
            let c = Vec3::new(
                (f * 1.1).cos() * 1.2,
                (f * 0.3).sin(),
                (f * 0.77).cos() * 0.6,
            );
            let reach = 0.01 + 0.002 * (q % 17) as f32;
            let brute = points
                .iter()
                .map(|p| p.distance_squared(c))
                .fold(f32::INFINITY, f32::min);
            assert_eq!(tree.any_within(c, reach), brute <= reach * reach);
            let (index, _) = tree.nearest(c, f32::INFINITY).unwrap();
            assert_eq!(points[index].distance_squared(c), brute);
            let lower = tree.distance_lower_bound(c, 0.05);
            assert!(lower <= brute.sqrt() && lower >= brute.sqrt().min(0.05) * 0.99999);
        }
    }

    /// The visit of a batch reaches every point within each live lane's reach, marks exactly
    /// the live lanes within it, and honours a reach that shrinks on the way.
    #[test]
    fn the_visit_meets_every_point_within_reach() {
        use crate::lane_f32::LANES;
        let points = curve_points(2000);
        let tree = PointTree::new(&points);
        for q in 0..40 {
            let centre = |l: usize| {
                let f = (q * LANES + l) as f32;
                Vec3::new((f * 1.1).cos(), (f * 0.3).sin(), (f * 0.77).cos() * 0.5)
            };
            let lanes = [
                LaneF32::new(std::array::from_fn(|l| centre(l).x)),
                LaneF32::new(std::array::from_fn(|l| centre(l).y)),
                LaneF32::new(std::array::from_fn(|l| centre(l).z)),
            ];
            let reach: [f32; LANES] = std::array::from_fn(|l| 0.05 + 0.01 * (l % 5) as f32);
            let live = 0b1011_0110_1101_0111 & ((1u32 << LANES) - 1);
            let mut seen = vec![0u32; points.len()];
            tree.visit_within_lanes(&lanes, LaneF32::new(reach), live, |p, d2, within| {
                let i = points.iter().position(|&x| x == p).unwrap();
                let mask = within.to_bitmask();
                assert_eq!(mask & !live, 0);
                for (l, (reach, d2)) in reach.iter().zip(d2.to_array()).enumerate() {
                    let inside = points[i].distance_squared(centre(l)) < reach * reach;
                    assert_eq!(mask >> l & 1 != 0, inside && live >> l & 1 != 0);
                    assert_eq!(d2, points[i].distance_squared(centre(l)));
                }
                seen[i] |= mask;
                LaneF32::new(reach)
            });
            for (i, p) in points.iter().enumerate() {
                let wanted = (0..LANES)
                    .filter(|&l| live >> l & 1 != 0)
                    .filter(|&l| p.distance_squared(centre(l)) < reach[l] * reach[l])
                    .fold(0, |m, l| m | 1 << l);
                assert_eq!(seen[i], wanted, "point {i}");
            }
            // A reach that shrinks to a tenth after the first point: every later point
            // visited is within it.
            let mut first = true;
            tree.visit_within_lanes(&lanes, LaneF32::new(reach), live, |_, d2, within| {
                if !first {
                    let small = LaneF32::new(reach) * LaneF32::splat(0.1);
                    let ok = d2.simd_lt(small * small).to_bitmask();
                    assert_eq!(within.to_bitmask() & !ok, 0);
                }
                first = false;
                LaneF32::new(reach) * LaneF32::splat(0.1)
            });
        }
    }
}
