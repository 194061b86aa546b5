//! [`KdTree`]: a static, bucketed kd-tree over points of any dimension, with exact k-nearest and
//! radius queries that never allocate once their buffers are warm.

use crate::nearest::lanes::{GROUP, group_distances};
use crate::nearest::neighbours::Neighbours;

/// Points per leaf bucket. Small enough that leaves are scanned quickly, large enough that the
/// tree stays shallow.
pub(crate) const BUCKET: usize = 12;

/// Marks a leaf in [`Node::dim`].
pub(crate) const LEAF: u32 = u32::MAX;

/// From this dimension on, a k-nearest query scans the tree's points instead of descending it.
/// Uniform samples in 12 or more dimensions leave the cells' bounds too loose to prune: the
/// descent visits nearly every leaf and pays for the bookkeeping on top. Measured with
/// `anytime_rate` (MIT*, same runs both ways, this constant set to 2 and to 100): the scan costs
/// 4–8 % more time in R^8, the same in R^10, and saves 10–12 % in R^12 and 10–20 % in R^16
/// (`docs/guide/src/reference/hot-primitives.md`, "The anytime phase").
const SCAN_DIMENSION: usize = 12;

/// Points between two polls of a scanning query.
const SCAN_BLOCK: usize = 1024;

use crate::nearest::chunked::Chunked;

/// Which points a query may return: all, or those whose birth stamp is still current
/// (`births[id] == birth`), so removed points can stay in a tree until it is rebuilt.
#[derive(Clone, Copy)]
pub(crate) enum Alive<'a> {
    /// Every point.
    All,
    /// Points whose stamp equals the current stamp of their id.
    Current(&'a Chunked<u32>),
}

impl Alive<'_> {
    #[inline]
    pub(crate) fn contains(self, id: u32, birth: u32) -> bool {
        match self {
            Self::All => true,
            Self::Current(births) => births.get(id as usize) == Some(&birth),
        }
    }
}

/// One node: a leaf owns the points `start..end` (in tree order); an inner node splits along
/// `dim` with every left point `≤ low` and every right point `≥ high` on that coordinate.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Node {
    pub(crate) start: u32,
    pub(crate) end: u32,
    pub(crate) dim: u32,
    pub(crate) low: f64,
    pub(crate) high: f64,
    pub(crate) left: u32,
    pub(crate) right: u32,
}

/// A static kd-tree over a set of points identified by `u32` ids.
///
/// Built once in `O(q log q)` (median splits along the widest coordinate of each cell, the
/// points partitioned in place so every pass is sequential; the shape is a deterministic
/// function of the input), then
/// queried for exact Euclidean k-nearest neighbours ([`nearest`](Self::nearest)) or every point
/// within a radius ([`within`](Self::within)). The points' coordinates are copied into the tree
/// in leaf order, so a leaf scan reads contiguous memory. Queries use the incremental
/// cell-distance bound of Arya and Mount (exact squared distance from the query to each cell),
/// which keeps pruning effective up to a few dozen dimensions.
///
/// Ties are broken by id: among points at equal distance the smaller id is nearer. Results are
/// therefore a deterministic function of the point set, whatever order the points came in.
///
/// ```
/// use mit_star::{KdTree, Neighbours};
/// let points = [[0.0, 0.0], [1.0, 0.0], [0.0, 2.0], [5.0, 5.0]];
/// let tree = KdTree::build(2, points.iter().enumerate().map(|(i, p)| (i as u32, &p[..])));
/// let mut found = Neighbours::new();
/// tree.nearest(&[0.9, 0.1], 2, &mut found);
/// let ids: Vec<u32> = found.iter().map(|&(_, id)| id).collect();
/// assert_eq!(ids, [1, 0]);
/// ```
#[derive(Debug, Clone)]
pub struct KdTree {
    pub(crate) dimension: usize,
    pub(crate) ids: Vec<u32>,
    /// Birth stamp of each point: a query skips points whose stamp is no longer current.
    pub(crate) births: Vec<u32>,
    pub(crate) coordinates: Vec<f64>,
    /// The same coordinates by group of four positions, one row per coordinate (row
    /// `g · dimension + c` holds coordinate `c` of positions `4g .. 4g + 4`; unused places
    /// NaN), so that a leaf scan computes four distances at once.
    pub(crate) lanes: Vec<[f64; GROUP]>,
    pub(crate) nodes: Vec<Node>,
    pub(crate) lower: Vec<f64>,
    pub(crate) upper: Vec<f64>,
}

/// Squared Euclidean distance of two coordinate slices, summed in four independent lanes
/// (coordinates `i`, `i + 4`, … in lane `i mod 4`), which in high dimensions cuts the chain of
/// dependent additions that bounds a scan to a quarter. Every structure that ranks points by
/// distance (the trees' leaves, the pending buffer, radius queries) uses this function or the
/// four-point kernels of `lanes.rs`, which return the same bits, so their rankings agree.
#[inline]
pub(crate) fn squared_distance(a: &[f64], b: &[f64]) -> f64 {
    let mut sums = [0.0_f64; 4];
    let (a4, b4) = (a.chunks_exact(4), b.chunks_exact(4));
    let (ra, rb) = (a4.remainder(), b4.remainder());
    for (x, y) in a4.zip(b4) {
        for i in 0..4 {
            let t = x[i] - y[i];
            sums[i] += t * t;
        }
    }
    for (i, (x, y)) in ra.iter().zip(rb).enumerate() {
        let t = x - y;
        sums[i] += t * t;
    }
    (sums[0] + sums[1]) + (sums[2] + sums[3])
}

impl KdTree {
    /// Builds a tree over `points`, each an `(id, coordinates)` pair of length `dimension`.
    ///
    /// # Panics
    /// If a point's length differs from `dimension` (the planner only passes its own states).
    pub fn build<'a>(dimension: usize, points: impl IntoIterator<Item = (u32, &'a [f64])>) -> Self {
        let mut ids = Vec::new();
        let mut coordinates = Vec::new();
        for (id, point) in points {
            assert_eq!(point.len(), dimension, "point of wrong dimension");
            ids.push(id);
            coordinates.extend_from_slice(point);
        }
        let births = vec![0; ids.len()];
        let mut spare = crate::nearest::kd_tree_build::Spare::default();
        Self::from_parts(
            dimension,
            &[(&ids, &births, &coordinates)],
            &mit_star_spaces::Never,
            &mut spare,
        )
        .unwrap_or_else(|| Self::empty(dimension))
    }

    /// A tree with no point.
    pub(crate) fn empty(dimension: usize) -> Self {
        Self {
            dimension,
            ids: Vec::new(),
            births: Vec::new(),
            coordinates: Vec::new(),
            lanes: Vec::new(),
            nodes: Vec::new(),
            lower: vec![f64::INFINITY; dimension],
            upper: vec![f64::NEG_INFINITY; dimension],
        }
    }

    /// Number of points in the tree.
    pub fn len(&self) -> usize {
        self.ids.len()
    }

    /// `true` if the tree holds no point.
    pub fn is_empty(&self) -> bool {
        self.ids.is_empty()
    }

    /// Coordinate dimension of the points.
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// The ids, birth stamps and coordinates of every point, in tree order.
    pub(crate) fn parts(&self) -> (&[u32], &[u32], &[f64]) {
        (&self.ids, &self.births, &self.coordinates)
    }

    /// Squared distance from `query` to the tree's bounding box, with the per-dimension
    /// offsets written to `offsets`.
    fn box_distance(&self, query: &[f64], offsets: &mut Vec<f64>) -> f64 {
        offsets.clear();
        let mut total = 0.0;
        for ((&q, &lo), &hi) in query.iter().zip(&self.lower).zip(&self.upper) {
            let o = if q < lo {
                lo - q
            } else if q > hi {
                q - hi
            } else {
                0.0
            };
            offsets.push(o * o);
            total += o * o;
        }
        total
    }

    /// Adds this tree's points to a k-nearest query already in progress in `found` (so several
    /// trees can share one query). Use [`nearest`](Self::nearest) for a fresh query. Stops early,
    /// leaving `poll.stopped` set and `found` incomplete, if `poll`'s condition fires.
    pub(crate) fn nearest_into(
        &self,
        query: &[f64],
        found: &mut Neighbours,
        alive: Alive<'_>,
        poll: &mut Poll<'_>,
    ) {
        if self.is_empty() || found.k == 0 {
            return;
        }
        if self.dimension >= SCAN_DIMENSION {
            self.scan_nearest(query, found, alive, poll);
            return;
        }
        let mut offsets = std::mem::take(&mut found.offsets);
        let bound = self.box_distance(query, &mut offsets);
        if bound <= found.worst() {
            self.search_nearest(0, query, bound, &mut offsets, found, (alive, poll));
        }
        found.offsets = offsets;
    }

    /// [`nearest_into`](Self::nearest_into) by one pass over the points in storage order,
    /// polling every [`SCAN_BLOCK`] points: the same result (the `k` nearest live points, ties
    /// by id), without the descent.
    fn scan_nearest(
        &self,
        query: &[f64],
        found: &mut Neighbours,
        alive: Alive<'_>,
        poll: &mut Poll<'_>,
    ) {
        for start in (0..self.ids.len()).step_by(SCAN_BLOCK) {
            let end = (start + SCAN_BLOCK).min(self.ids.len());
            if poll.tick((end - start) as u32) {
                return;
            }
            self.offer_points(start..end, query, found, alive);
        }
    }

    /// Offers the live points at storage positions `range` to a k-nearest query.
    #[inline]
    fn offer_points(
        &self,
        range: std::ops::Range<usize>,
        query: &[f64],
        found: &mut Neighbours,
        alive: Alive<'_>,
    ) {
        let n = self.dimension;
        let mut worst = found.worst();
        for group in range.start / GROUP..range.end.div_ceil(GROUP) {
            let distances = group_distances(&self.lanes[group * n..(group + 1) * n], query);
            for (place, &d) in distances.iter().enumerate() {
                let position = group * GROUP + place;
                if d <= worst && range.contains(&position) {
                    let (id, birth) = (self.ids[position], self.births[position]);
                    if alive.contains(id, birth) {
                        found.offer(d, id);
                        worst = found.worst();
                    }
                }
            }
        }
    }

    /// The `k` points nearest to `query` (Euclidean), written to `found` nearest first.
    pub fn nearest(&self, query: &[f64], k: usize, found: &mut Neighbours) {
        found.reset(k);
        self.nearest_into(
            query,
            found,
            Alive::All,
            &mut Poll::new(&mit_star_spaces::Never, self.dimension),
        );
    }

    fn search_nearest(
        &self,
        node: u32,
        query: &[f64],
        bound: f64,
        offsets: &mut [f64],
        found: &mut Neighbours,
        (alive, poll): (Alive<'_>, &mut Poll<'_>),
    ) {
        let node = self.nodes[node as usize];
        if node.dim == LEAF {
            if poll.tick(node.end - node.start) {
                return;
            }
            self.offer_points(node.start as usize..node.end as usize, query, found, alive);
            return;
        }
        let dim = node.dim as usize;
        let q = query[dim];
        // Nearer child first; the far cell's offset along `dim` is to its boundary.
        let (near, far, cut) = if (q - node.low) + (q - node.high) < 0.0 {
            (node.left, node.right, (node.high - q) * (node.high - q))
        } else {
            (node.right, node.left, (q - node.low) * (q - node.low))
        };
        self.search_nearest(near, query, bound, offsets, found, (alive, &mut *poll));
        let saved = offsets[dim];
        let far_bound = bound + cut - saved;
        if far_bound <= found.worst() && !poll.stopped {
            offsets[dim] = cut;
            self.search_nearest(far, query, far_bound, offsets, found, (alive, poll));
            offsets[dim] = saved;
        }
    }

    /// Adds every point within squared distance `radius2` of `query` to `found` (unsorted).
    pub(crate) fn within_into(
        &self,
        query: &[f64],
        radius2: f64,
        found: &mut Neighbours,
        alive: Alive<'_>,
        poll: &mut Poll<'_>,
    ) {
        if self.is_empty() {
            return;
        }
        let mut offsets = std::mem::take(&mut found.offsets);
        let bound = self.box_distance(query, &mut offsets);
        if bound <= radius2 {
            self.search_within(0, query, bound, radius2, &mut offsets, found, (alive, poll));
        }
        found.offsets = offsets;
    }

    /// Every point within distance `radius` of `query`, written to `found` nearest first.
    pub fn within(&self, query: &[f64], radius: f64, found: &mut Neighbours) {
        found.reset(usize::MAX);
        self.within_into(
            query,
            radius * radius,
            found,
            Alive::All,
            &mut Poll::new(&mit_star_spaces::Never, self.dimension),
        );
        found.sort();
    }

    #[allow(clippy::too_many_arguments)]
    fn search_within(
        &self,
        node: u32,
        query: &[f64],
        bound: f64,
        radius2: f64,
        offsets: &mut [f64],
        found: &mut Neighbours,
        (alive, poll): (Alive<'_>, &mut Poll<'_>),
    ) {
        let node = self.nodes[node as usize];
        if node.dim == LEAF {
            if poll.tick(node.end - node.start) {
                return;
            }
            let n = self.dimension;
            for p in node.start as usize..node.end as usize {
                let d = squared_distance(query, &self.coordinates[p * n..(p + 1) * n]);
                if d <= radius2 && alive.contains(self.ids[p], self.births[p]) {
                    found.push_unordered(d, self.ids[p]);
                }
            }
            return;
        }
        let dim = node.dim as usize;
        let q = query[dim];
        let (near, far, cut) = if (q - node.low) + (q - node.high) < 0.0 {
            (node.left, node.right, (node.high - q) * (node.high - q))
        } else {
            (node.right, node.left, (q - node.low) * (q - node.low))
        };
        self.search_within(
            near,
            query,
            bound,
            radius2,
            offsets,
            found,
            (alive, &mut *poll),
        );
        let saved = offsets[dim];
        let far_bound = bound + cut - saved;
        if far_bound <= radius2 && !poll.stopped {
            offsets[dim] = cut;
            self.search_within(
                far,
                query,
                far_bound,
                radius2,
                offsets,
                found,
                (alive, poll),
            );
            offsets[dim] = saved;
        }
    }
}

/// Coordinates a query reads (points examined × dimension) between two polls of its stop
/// condition: 8192 points in `R^2`, 512 in `R^32` — tens of microseconds of work either way.
const QUERY_POLL: u32 = 16_384;

/// The stop condition of a query and the work since it was last polled. A query over hundreds
/// of thousands of points in high dimension (where trees prune little) takes milliseconds, so
/// the planner's queries can be abandoned — and the expansion that asked retried later.
pub(crate) struct Poll<'a> {
    stop: &'a dyn mit_star_spaces::Stop,
    /// Coordinates per point.
    dimension: u32,
    work: u32,
    /// Set once the condition fired: the query's answer is incomplete.
    pub(crate) stopped: bool,
}

impl<'a> Poll<'a> {
    /// A fresh poll of `stop` for queries over points of `dimension` coordinates.
    pub(crate) fn new(stop: &'a dyn mit_star_spaces::Stop, dimension: usize) -> Self {
        Self {
            stop,
            dimension: u32::try_from(dimension.max(1)).unwrap_or(u32::MAX),
            work: 0,
            stopped: false,
        }
    }

    /// Counts `points` of work; `true` if the query must stop (now or before).
    #[inline]
    pub(crate) fn tick(&mut self, points: u32) -> bool {
        if self.stopped {
            return true;
        }
        self.work = self
            .work
            .saturating_add(points.saturating_mul(self.dimension));
        if self.work >= QUERY_POLL {
            self.work = 0;
            self.stopped = self.stop.should_stop();
        }
        self.stopped
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star_spaces::SeededRng;
    use mit_star_spaces::rand::{RngExt, SeedableRng};

    fn random_points(n: usize, count: usize, seed: u64) -> Vec<f64> {
        let mut rng = SeededRng::seed_from_u64(seed);
        (0..n * count)
            .map(|_| rng.random_range(-1.0..1.0))
            .collect()
    }

    fn brute_nearest(points: &[f64], n: usize, query: &[f64], k: usize) -> Vec<(f64, u32)> {
        let mut all: Vec<(f64, u32)> = points
            .chunks_exact(n)
            .enumerate()
            .map(|(i, p)| (squared_distance(query, p), i as u32))
            .collect();
        all.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        all.truncate(k);
        all
    }

    #[test]
    fn nearest_matches_brute_force_in_2_to_32_dimensions() {
        let mut found = Neighbours::new();
        // Below SCAN_DIMENSION the tree is descended, from it on scanned.
        for n in [2, 3, 4, 8, 11, SCAN_DIMENSION, 16, 32] {
            let points = random_points(n, 700, n as u64);
            let tree = KdTree::build(
                n,
                points
                    .chunks_exact(n)
                    .enumerate()
                    .map(|(i, p)| (i as u32, p)),
            );
            assert_eq!(tree.len(), 700);
            let queries = random_points(n, 40, 1000 + n as u64);
            for query in queries.chunks_exact(n) {
                for k in [1, 7, 25, 800] {
                    tree.nearest(query, k, &mut found);
                    let expected = brute_nearest(&points, n, query, k);
                    let got: Vec<(f64, u32)> = found.iter().copied().collect();
                    assert_eq!(got, expected, "n={n} k={k}");
                }
            }
        }
    }

    #[test]
    fn within_matches_brute_force() {
        let mut found = Neighbours::new();
        for n in [2, 5, 12] {
            let points = random_points(n, 500, 77 + n as u64);
            let tree = KdTree::build(
                n,
                points
                    .chunks_exact(n)
                    .enumerate()
                    .map(|(i, p)| (i as u32, p)),
            );
            for query in random_points(n, 30, 5 + n as u64).chunks_exact(n) {
                for radius in [0.1, 0.5, 1.2] {
                    tree.within(query, radius, &mut found);
                    let mut expected = brute_nearest(&points, n, query, usize::MAX);
                    expected.retain(|&(d, _)| d <= radius * radius);
                    assert_eq!(found.iter().copied().collect::<Vec<_>>(), expected);
                }
            }
        }
    }

    #[test]
    fn duplicate_points_and_ties_break_by_id() {
        let mut found = Neighbours::new();
        for n in [2, SCAN_DIMENSION + 4] {
            let points = vec![vec![0.5; n]; 40];
            let tree = KdTree::build(
                n,
                points
                    .iter()
                    .enumerate()
                    .rev()
                    .map(|(i, p)| (i as u32, &p[..])),
            );
            tree.nearest(&vec![0.0; n], 3, &mut found);
            let ids: Vec<u32> = found.iter().map(|&(_, id)| id).collect();
            assert_eq!(ids, [0, 1, 2], "n={n}");
        }
        let empty = KdTree::build(2, std::iter::empty());
        empty.nearest(&[0.0, 0.0], 3, &mut found);
        assert!(found.is_empty());
    }
}
