//! [`AffordanceTree`]: per cell of a kd-tree, the points a query sphere centred in the cell
//! could touch, so that a contact query is a short descent and one contiguous scan.

use glam::Vec3;
use mit_star_spaces::Stop;

use crate::PointTree;
use crate::lane_f32::{LANES, LaneF32};

/// Most points of the cloud in one leaf cell.
const LEAF: usize = 8;

/// Leaves emitted between two polls of the stop condition.
const POLL_LEAVES: usize = 1 << 10;

/// Bytes a point the structure may take (beside the [`PointTree`](crate::PointTree)'s 19–22:
/// both together stay within 64 bytes a point), unless the whole is below [`FLOOR_BYTES`].
const BYTES_PER_POINT: usize = 36;

/// Bytes any cloud's structure may take, however few its points (a cloud of ten thousand
/// points among the Panda's spheres takes about 2 MB).
const FLOOR_BYTES: usize = 8 << 20;

/// A chunk of listed points: `LANES` x, then y, then z coordinates.
type Chunk = [LaneF32; 3];

/// The contact structure of CAPT (Ramsey et al., "Collision-Affording Point Trees", RSS
/// 2024), as we understand it, for spheres of reach up to a bound fixed when it is built.
///
/// # Layout
/// A kd-tree splits the points at the median of the longest side of their box, every leaf at
/// the same depth, each holding at most eight points of the cloud. Its cells partition space:
/// a query centre `c` goes right at a node when `c[axis] ≥ split` (exact comparisons, no
/// rounding), so the cell it reaches is a box that contains it. Each leaf lists, contiguously,
/// its own points and every other point whose distance to the cell's box is at most
/// `reach_max` (`f32`, squared), padded with points at infinity to whole chunks of `LANES`;
/// and the box of the points it lists.
///
/// # Queries
/// `any_within(c, reach)` for `reach² ≤ reach_max²`: a fixed number of comparisons down to
/// the leaf of `c`, the listed points' box as a cull, then a SIMD scan of the list. A point
/// within `reach` of `c` is within `reach_max` of the cell (its distance to the box is never
/// computed above its distance to `c`, the rounding being monotonic), so it is listed: the
/// answers are exactly those of `|c − p|² ≤ reach²` in `f32` over every point, those of
/// [`PointTree::any_within`](crate::PointTree::any_within) bit for bit. A reach beyond the
/// bound gets `None`: the caller asks the tree.
///
/// # Cost
/// Built in `O(n log n)` for the splits, then per leaf a walk of the cloud's
/// [`PointTree`](crate::PointTree) for the points within `reach_max` of its cell (the tree's
/// boxes skip the rest): about `n/8` leaves listing `L` points in all. Its memory is `12 L`
/// bytes and 36 a leaf; a build that would take more than its budget (36 bytes a point, so
/// that with the tree's 19–22 a cloud takes at most 64; or 8 MiB for clouds of fewer than
/// 233 000 points) stops and returns `None` (dense clouds of millions of points, where the
/// lists grow with the density).
#[derive(Debug, Clone)]
pub struct AffordanceTree {
    /// Levels of inner nodes above the leaves.
    depth: u32,
    /// Per inner node (breadth-first): the split coordinate and its axis.
    splits: Vec<(f32, u32)>,
    /// Per leaf: the first chunk of its list (and one past the last: `leaves + 1` entries).
    starts: Vec<u32>,
    /// Per leaf: the box of the points it lists, `[min x, min y, min z, max x, max y, max z]`.
    boxes: Vec<[f32; 6]>,
    /// The lists, leaf after leaf, in chunks.
    chunks: Vec<Chunk>,
    /// The box of every point.
    bounds: [f32; 6],
    /// The largest reach answered, and its square.
    reach_max: f32,
    reach_max_squared: f32,
}

impl AffordanceTree {
    /// The structure of the points of `tree` for reaches up to `reach_max` (a sphere's radius
    /// and the points' radius together), each leaf's list found by a walk of `tree`, polling
    /// `stop` every thousand leaves: `None` if it said to stop, or if the lists outgrow the
    /// budget (see the type).
    pub fn new_polled(tree: &PointTree, reach_max: f32, stop: &dyn Stop) -> Option<Self> {
        let points = tree.points();
        let n = points.len();
        let mut depth = 0;
        while n.div_ceil(1 << depth) > LEAF {
            depth += 1;
        }
        let budget = (BYTES_PER_POINT * n).max(FLOOR_BYTES);
        let everywhere = [
            f32::NEG_INFINITY,
            f32::NEG_INFINITY,
            f32::NEG_INFINITY,
            f32::INFINITY,
            f32::INFINITY,
            f32::INFINITY,
        ];
        let bounds = bounds_of(&points);
        let reach_max_squared = reach_max * reach_max;
        let mut builder = Builder {
            tree,
            near: Vec::new(),
            points,
            depth,
            reach_max_squared,
            splits: vec![(0.0, 0); (1 << depth) - 1],
            starts: Vec::with_capacity((1 << depth) + 1),
            boxes: Vec::with_capacity(1 << depth),
            chunks: Vec::new(),
            budget_chunks: budget / std::mem::size_of::<Chunk>(),
            stop,
        };
        builder.starts.push(0);
        builder.node(0, 0, n, 0, everywhere)?;
        let Builder {
            splits,
            starts,
            boxes,
            mut chunks,
            ..
        } = builder;
        chunks.shrink_to_fit();
        Some(Self {
            depth: depth as u32,
            splits,
            starts,
            boxes,
            chunks,
            bounds,
            reach_max,
            reach_max_squared,
        })
    }

    /// The largest reach it answers.
    pub fn reach_max(&self) -> f32 {
        self.reach_max
    }

    /// `true` if it answers queries of `reach` (`reach² ≤ reach_max²`).
    #[inline]
    pub fn answers(&self, reach: f32) -> bool {
        reach * reach <= self.reach_max_squared
    }

    /// Points listed in all, padding included (each point of the cloud is listed by its own
    /// leaf, and by every other leaf whose cell it is within `reach_max` of).
    pub fn listed(&self) -> usize {
        self.chunks.len() * LANES
    }

    /// Bytes the structure holds (its arrays' capacities).
    pub fn memory_bytes(&self) -> usize {
        std::mem::size_of::<Chunk>() * self.chunks.capacity()
            + 8 * self.splits.capacity()
            + 4 * self.starts.capacity()
            + 24 * self.boxes.capacity()
            + std::mem::size_of::<Self>()
    }

    /// `Some(true)` if some point is within `reach` of `center` (`|c − p|² ≤ reach²` in
    /// `f32`), `Some(false)` if none is, `None` if `reach` is beyond the bound it was built
    /// for.
    #[inline]
    pub fn any_within(&self, center: Vec3, reach: f32) -> Option<bool> {
        let r2 = reach * reach;
        // `None` for a NaN reach too.
        self.answers(reach)
            .then(|| self.contact(center.to_array(), r2))
    }

    /// Bit `l` set if lane `l` of `active` has a point within `reach[l]` of its centre, or
    /// `None` if some lane of `active` asks beyond the bound.
    #[inline]
    pub(crate) fn any_within_lanes(
        &self,
        center: &[LaneF32; 3],
        reach: LaneF32,
        active: u32,
    ) -> Option<u32> {
        let r2 = reach * reach;
        if r2
            .simd_le(LaneF32::splat(self.reach_max_squared))
            .to_bitmask()
            & active
            != active
        {
            return None;
        }
        let (xs, ys, zs) = (
            center[0].to_array(),
            center[1].to_array(),
            center[2].to_array(),
        );
        let r2 = r2.to_array();
        let mut found = 0;
        let mut open = active;
        while open != 0 {
            let l = open.trailing_zeros() as usize;
            open &= open - 1;
            if self.contact([xs[l], ys[l], zs[l]], r2[l]) {
                found |= 1 << l;
            }
        }
        Some(found)
    }

    /// The answer for a centre and a squared reach within the bound.
    #[inline(always)]
    fn contact(&self, c: [f32; 3], r2: f32) -> bool {
        if box_distance_squared(&self.bounds, c) > r2 {
            return false;
        }
        let mut node = 0;
        for _ in 0..self.depth {
            let (split, axis) = self.splits[node];
            node = 2 * node + 1 + usize::from(c[axis as usize] >= split);
        }
        let leaf = node - self.splits.len();
        if box_distance_squared(&self.boxes[leaf], c) > r2 {
            return false;
        }
        let (start, end) = (self.starts[leaf] as usize, self.starts[leaf + 1] as usize);
        let (x, y, z) = (
            LaneF32::splat(c[0]),
            LaneF32::splat(c[1]),
            LaneF32::splat(c[2]),
        );
        let r2 = LaneF32::splat(r2);
        self.chunks[start..end].iter().any(|[px, py, pz]| {
            let (dx, dy, dz) = (x - *px, y - *py, z - *pz);
            (dx * dx + dy * dy + dz * dz).simd_le(r2).any()
        })
    }
}

/// The state of a build: the tree that finds the lists, the points (reordered in place), and
/// the arrays filled.
struct Builder<'a> {
    tree: &'a PointTree,
    /// The list being made.
    near: Vec<Vec3>,
    points: Vec<Vec3>,
    depth: usize,
    reach_max_squared: f32,
    splits: Vec<(f32, u32)>,
    starts: Vec<u32>,
    boxes: Vec<[f32; 6]>,
    chunks: Vec<Chunk>,
    budget_chunks: usize,
    stop: &'a dyn Stop,
}

impl Builder<'_> {
    /// Builds node `node` at `level` over `points[lo..hi]`, whose cell is `cell`. `None` if
    /// stopped or over budget.
    fn node(
        &mut self,
        node: usize,
        lo: usize,
        hi: usize,
        level: usize,
        cell: [f32; 6],
    ) -> Option<()> {
        if level == self.depth {
            return self.leaf(cell);
        }
        let b = bounds_of(&self.points[lo..hi]);
        let side = [b[3] - b[0], b[4] - b[1], b[5] - b[2]];
        let axis = if side[0] >= side[1] && side[0] >= side[2] {
            0
        } else if side[1] >= side[2] {
            1
        } else {
            2
        };
        let mid = lo + (hi - lo) / 2;
        self.points[lo..hi].select_nth_unstable_by(mid - lo, |a, b| a[axis].total_cmp(&b[axis]));
        // Left points are at most the split, right points at least (the right half's least).
        let split = self.points[mid][axis];
        self.splits[node] = (split, axis as u32);
        let (mut left, mut right) = (cell, cell);
        left[axis + 3] = split;
        right[axis] = split;
        self.node(2 * node + 1, lo, mid, level + 1, left)?;
        self.node(2 * node + 2, mid, hi, level + 1, right)
    }

    /// Lists the leaf whose cell is `cell`: every point within reach of it.
    fn leaf(&mut self, cell: [f32; 6]) -> Option<()> {
        let leaves = self.boxes.len();
        if leaves % POLL_LEAVES == POLL_LEAVES - 1 && self.stop.should_stop() {
            return None;
        }
        self.near.clear();
        self.tree
            .points_near_box(&cell, self.reach_max_squared, &mut self.near);
        let count = self.near.len();
        if self.chunks.len() + count.div_ceil(LANES) > self.budget_chunks {
            return None;
        }
        let mut lists = self.near.iter();
        let mut bounds = [
            f32::INFINITY,
            f32::INFINITY,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NEG_INFINITY,
            f32::NEG_INFINITY,
        ];
        for _ in 0..count.div_ceil(LANES) {
            let mut chunk = [[f32::INFINITY; LANES]; 3];
            for (l, p) in (0..LANES).zip(lists.by_ref()) {
                for k in 0..3 {
                    chunk[k][l] = p[k];
                    bounds[k] = bounds[k].min(p[k]);
                    bounds[k + 3] = bounds[k + 3].max(p[k]);
                }
            }
            self.chunks.push(chunk.map(LaneF32::new));
        }
        self.boxes.push(bounds);
        self.starts.push(u32::try_from(self.chunks.len()).ok()?);
        Some(())
    }
}

/// The box of `points`: `[min x, min y, min z, max x, max y, max z]`.
fn bounds_of(points: &[Vec3]) -> [f32; 6] {
    let (min, max) = points.iter().fold(
        (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
        |(min, max), p| (min.min(*p), max.max(*p)),
    );
    [min.x, min.y, min.z, max.x, max.y, max.z]
}

/// The squared distance from `c` to the box (0 inside), in the order of operations of a
/// point's squared distance, so that it is never above the squared distance to a point of the
/// box.
#[inline(always)]
fn box_distance_squared(b: &[f32; 6], c: [f32; 3]) -> f32 {
    let dx = (b[0] - c[0]).max(c[0] - b[3]).max(0.0);
    let dy = (b[1] - c[1]).max(c[1] - b[4]).max(0.0);
    let dz = (b[2] - c[2]).max(c[2] - b[5]).max(0.0);
    dx * dx + dy * dy + dz * dz
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points on a jittered curve, queries around them: every answer within the bound is
    /// brute force's, the batched ones too, and a reach beyond the bound is refused.
    #[test]
    fn queries_are_brute_force() {
        let points = crate::clouds::point_tree::curve_points(1000);
        let tree = AffordanceTree::new_polled(
            &crate::PointTree::new(&points),
            0.2,
            &mit_star_spaces::Never,
        )
        .unwrap();
        assert_eq!(tree.depth, 7);
        assert!(tree.listed() >= 1000);
        let brute = |c: Vec3, reach: f32| {
            points.iter().any(|p| {
                let (dx, dy, dz) = (c.x - p.x, c.y - p.y, c.z - p.z);
                dx * dx + dy * dy + dz * dz <= reach * reach
            })
        };
        let mut hits = 0;
        for q in 0..300 {
            let f = q as f32;
            let c = Vec3::new(
                (f * 1.1).cos() * 1.2,
                (f * 0.3).sin(),
                (f * 0.77).cos() * 0.6,
            );
            let reach = 0.05 + 0.009 * (q % 17) as f32;
            let answer = tree.any_within(c, reach).unwrap();
            assert_eq!(answer, brute(c, reach), "{c} {reach}");
            hits += usize::from(answer);
            assert_eq!(tree.any_within(c, 0.201), None);
            // Lanes: this centre and others nearby, every other lane active.
            let lanes = [0, 1, 2].map(|k| {
                LaneF32::new(std::array::from_fn(|l| {
                    c[k] + 0.003 * l as f32 * (k as f32 - 1.0)
                }))
            });
            let active = 0x5555_5555 & ((1_u64 << LANES) - 1) as u32;
            let found = tree
                .any_within_lanes(&lanes, LaneF32::splat(reach), active)
                .unwrap();
            for l in 0..LANES {
                let lane = Vec3::new(
                    lanes[0].to_array()[l],
                    lanes[1].to_array()[l],
                    lanes[2].to_array()[l],
                );
                let expected = active & (1 << l) != 0 && brute(lane, reach);
                assert_eq!(found & (1 << l) != 0, expected, "lane {l}");
            }
            assert_eq!(
                tree.any_within_lanes(&lanes, LaneF32::splat(0.25), active),
                None
            );
        }
        assert!(hits > 10 && hits < 290, "{hits}");
    }
}
