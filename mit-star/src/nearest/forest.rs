//! [`NearestNeighbors`]: exact nearest-neighbour search over points that arrive in batches and
//! are removed by pruning.

use mit_star_spaces::{Never, Stop};

use crate::nearest::kd_tree::{Alive, KdTree, Poll};
use crate::nearest::kd_tree_build::{Parts, Spare, fresh};
use crate::nearest::neighbours::Neighbours;
use crate::nearest::pending_points::PendingPoints;

/// Points that may wait in the linear buffer before a query builds them into a tree (the
/// buffer may also hold up to a quarter of the points already in trees). For the twenty-odd
/// nearest of a few thousand points in 7 dimensions, a scan four points at a time costs about
/// what a kd-tree's query does, and the trees' builds come on top: MIT* on the Panda's `cage`
/// (callgrind, `ARM_PROFILE_TIME=60 ARM_PROFILE_SCENES=cage arm_profile target 20 mit-star 1`)
/// takes 3.2 % fewer instructions per solve at 1 024 than at 256 (median of the per-solve
/// ratios), and no solve more; the same at 2 048. RRT-Connect's trees stay below either.
const PENDING_LIMIT: usize = 1024;

/// Points gathered between two polls of the stop condition when rebuilding.
const POLL_POINTS: usize = 4096;

/// A set of points, growing in batches, with exact Euclidean k-nearest and radius queries.
///
/// Samples arrive a batch at a time and leave only when the planner prunes, so static
/// [`KdTree`]s fit — except that rebuilding one over every point after each batch of 100 would
/// cost `O(q log q)` per batch. This structure keeps a few static trees of doubling sizes
/// (Bentley and Saxe's logarithmic method): new points wait in a buffer that queries scan
/// linearly; when a query finds the buffer large (more than 1 024 points and a quarter of the
/// points in trees) it is built into a tree, two trees of similar size being merged. Insertion
/// costs `O(log² q)` amortised per point (nothing while nobody queries) and a query visits
/// `O(log q)` trees sharing one result bound.
///
/// Removal is lazy: every point carries a birth stamp, and the planner's queries skip points
/// whose stamp is no longer current (removed, or their id reused); the trees are rebuilt once
/// dead points outnumber live ones. Builds poll a stop condition and are abandoned (the buffer
/// stays linear, results stay exact) if it fires, so a deadline is never held up by a rebuild.
///
/// Results are exact and a deterministic function of the live point set: ties are broken by id.
///
/// ```
/// use mit_star::{NearestNeighbors, Neighbours};
/// let mut nn = NearestNeighbors::new(2);
/// nn.insert([(0u32, &[0.0, 0.0][..]), (1, &[1.0, 0.0][..])]);
/// nn.insert([(2u32, &[0.2, 0.1][..])]);
/// let mut found = Neighbours::new();
/// nn.nearest(&[0.25, 0.0], 2, &mut found);
/// assert_eq!(found.iter().map(|&(_, id)| id).collect::<Vec<_>>(), [2, 0]);
/// ```
#[derive(Debug, Clone)]
pub struct NearestNeighbors {
    dimension: usize,
    trees: Vec<KdTree>,
    /// Points not yet in a tree (a query scans them a block at a time, polling in between).
    pending: PendingPoints,
    /// Points stored (live or dead).
    stored: usize,
    /// Stored points known to be dead.
    dead: usize,
    queries: u64,
    /// The arrays of the last abandoned build, reused by the next one.
    spare: Spare,
    /// Per-coordinate scales of a weighted Euclidean metric (empty: plain Euclidean): points
    /// and queries are indexed as `s ⊙ x` ([`with_scales`](Self::with_scales)).
    scales: Vec<f64>,
    /// A point or query scaled, for the call at hand.
    scaled: Vec<f64>,
}

impl NearestNeighbors {
    /// An empty set of points of `dimension` coordinates.
    pub fn new(dimension: usize) -> Self {
        Self {
            dimension,
            trees: Vec::new(),
            pending: PendingPoints::new(dimension),
            stored: 0,
            dead: 0,
            queries: 0,
            spare: Spare::default(),
            scales: Vec::new(),
            scaled: Vec::new(),
        }
    }

    /// An empty set of points under the weighted Euclidean metric `‖s ⊙ (a − b)‖` of
    /// `scales` (one per coordinate): points and queries are indexed as `s ⊙ x`, so the trees
    /// answer for the weighted metric (a joint space's weights), up to the rounding of the
    /// products. Distances in the results are the weighted ones.
    ///
    /// ```
    /// use mit_star::{NearestNeighbors, Neighbours};
    /// // The second coordinate counts ten times the first.
    /// let mut nn = NearestNeighbors::with_scales(&[1.0, 10.0]);
    /// nn.insert([(0u32, &[0.0, 0.1][..]), (1, &[0.5, 0.0][..])]);
    /// let mut found = Neighbours::new();
    /// nn.nearest(&[0.0, 0.0], 1, &mut found);
    /// assert_eq!(found.iter().map(|&(_, id)| id).collect::<Vec<_>>(), [1]);
    /// ```
    pub fn with_scales(scales: &[f64]) -> Self {
        Self {
            scales: scales.to_vec(),
            scaled: vec![0.0; scales.len()],
            ..Self::new(scales.len())
        }
    }

    /// `x` scaled by `scales` into `scaled`, or `x` itself for a plain Euclidean metric
    /// (`scales` empty).
    fn scale<'a>(scales: &[f64], scaled: &'a mut Vec<f64>, x: &'a [f64]) -> &'a [f64] {
        if scales.is_empty() {
            return x;
        }
        scaled.clear();
        scaled.extend(scales.iter().zip(x).map(|(s, v)| s * v));
        scaled
    }

    /// Number of live points.
    pub fn len(&self) -> usize {
        self.stored - self.dead
    }

    /// `true` if there is no live point.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Number of static trees currently held (logarithmic in the number of points).
    pub fn tree_count(&self) -> usize {
        self.trees.len()
    }

    /// Queries answered so far.
    pub fn queries(&self) -> u64 {
        self.queries
    }

    /// Adds a batch of `(id, coordinates)` points.
    ///
    /// # Panics
    /// If a point's length differs from the dimension.
    pub fn insert<'a>(&mut self, points: impl IntoIterator<Item = (u32, &'a [f64])>) {
        self.insert_born(points.into_iter().map(|(id, x)| (id, 0, x)));
    }

    /// Adds points with their birth stamps.
    pub(crate) fn insert_born<'a>(
        &mut self,
        points: impl IntoIterator<Item = (u32, u32, &'a [f64])>,
    ) {
        for (id, birth, point) in points {
            assert_eq!(point.len(), self.dimension, "point of wrong dimension");
            let point = Self::scale(&self.scales, &mut self.scaled, point);
            self.pending.push(id, birth, point);
            self.stored += 1;
        }
    }

    /// Makes room for `additional` more pending points.
    pub(crate) fn reserve_pending(&mut self, additional: usize) {
        self.pending.reserve(additional);
    }

    /// Records that `count` stored points died (their stamps are no longer current).
    pub(crate) fn note_removed(&mut self, count: usize) {
        self.dead = (self.dead + count).min(self.stored);
    }

    /// Keeps the structure efficient: rebuilds without dead points once they outnumber live
    /// ones, and builds the buffer into trees once it is large. Either is skipped if `stop`
    /// fires during the build.
    ///
    /// A build first copies the points it indexes, so once `stop` has fired no build is even
    /// started: every query after a deadline would otherwise copy the whole set again only to
    /// abandon the build at its first poll.
    pub(crate) fn maintain(&mut self, alive: Alive<'_>, stop: &dyn Stop) {
        let rebuild = self.dead > 0 && 2 * self.dead > self.stored;
        if !(rebuild || self.buffer_is_large()) || stop.should_stop() {
            return;
        }
        if rebuild {
            self.rebuild_alive(alive, stop);
        }
        if self.buffer_is_large() {
            self.flush(stop);
        }
    }

    /// `true` if the buffer holds more than [`PENDING_LIMIT`] points and a quarter of the
    /// points in trees.
    fn buffer_is_large(&self) -> bool {
        let in_trees = self.stored - self.pending.len();
        self.pending.len() > PENDING_LIMIT.max(in_trees / 4)
    }

    /// One tree over the live points (trees and buffer); nothing changes if `stop` fires.
    fn rebuild_alive(&mut self, alive: Alive<'_>, stop: &dyn Stop) {
        let n = self.dimension;
        let (mut ids, mut births, mut xs) = self.spare.take();
        // Sized once: growing would copy what was gathered in one unpolled step.
        fresh(&mut ids, self.stored);
        fresh(&mut births, self.stored);
        fresh(&mut xs, self.stored * n);
        let mut stopped = false;
        let parts = self.trees.iter().map(KdTree::parts);
        'gather: for (i, b, x) in parts.chain(self.pending.blocks()) {
            for j in 0..i.len() {
                if alive.contains(i[j], b[j]) {
                    ids.push(i[j]);
                    births.push(b[j]);
                    xs.extend_from_slice(&x[j * n..(j + 1) * n]);
                }
                if j % POLL_POINTS == POLL_POINTS - 1 && stop.should_stop() {
                    stopped = true;
                    break 'gather;
                }
            }
        }
        if stopped {
            self.spare.keep(ids, births, xs);
            return;
        }
        let live = ids.len();
        if let Some(tree) = KdTree::from_owned(n, (ids, births, xs), stop, &mut self.spare) {
            self.trees = vec![tree];
            self.pending.clear();
            self.stored = live;
            self.dead = 0;
        }
    }

    /// Builds the waiting points into a tree and merges trees of similar size.
    fn flush(&mut self, stop: &dyn Stop) {
        if self.pending.is_empty() {
            return;
        }
        let parts: Vec<Parts<'_>> = self.pending.blocks().collect();
        let built = KdTree::from_parts(self.dimension, &parts, stop, &mut self.spare);
        match built {
            Some(tree) => {
                self.trees.push(tree);
                self.pending.clear();
            }
            None => return,
        }
        // Merge while the newest tree is at least half the size of the one before it.
        while self.trees.len() >= 2 {
            let last = self.trees.len() - 1;
            if self.trees[last - 1].len() > 2 * self.trees[last].len() {
                break;
            }
            match merge(
                self.dimension,
                (&self.trees[last - 1], &self.trees[last]),
                stop,
                &mut self.spare,
            ) {
                Some(tree) => {
                    self.trees.truncate(last - 1);
                    self.trees.push(tree);
                }
                None => break,
            }
        }
    }

    /// The `k` points nearest to `query`, nearest first, in `found`.
    pub fn nearest(&mut self, query: &[f64], k: usize, found: &mut Neighbours) {
        self.nearest_alive(query, k, found, Alive::All, &Never);
    }

    /// Every point within `radius` of `query`, nearest first, in `found`.
    pub fn within(&mut self, query: &[f64], radius: f64, found: &mut Neighbours) {
        self.within_alive(query, radius, found, Alive::All, &Never);
    }

    /// The `k` nearest live points; `false` (and `found` incomplete) if `stop` fired first.
    pub(crate) fn nearest_alive(
        &mut self,
        query: &[f64],
        k: usize,
        found: &mut Neighbours,
        alive: Alive<'_>,
        stop: &dyn Stop,
    ) -> bool {
        found.reset(k);
        self.query_with(query, alive, stop, |nn, query| {
            nn.nearest_scaled(query, found, alive, stop)
        })
    }

    /// [`nearest_alive`](Self::nearest_alive) for a query already scaled, after maintenance.
    fn nearest_scaled(
        &self,
        query: &[f64],
        found: &mut Neighbours,
        alive: Alive<'_>,
        stop: &dyn Stop,
    ) -> bool {
        let mut poll = Poll::new(stop, self.dimension);
        // Largest tree first: it holds most of the neighbours, so the bound tightens early.
        for tree in &self.trees {
            tree.nearest_into(query, found, alive, &mut poll);
        }
        if found.k == 1 {
            // The nearest alone: kept in locals, offered once at the end.
            let mut best = found
                .iter()
                .next()
                .copied()
                .unwrap_or((f64::INFINITY, u32::MAX));
            let complete = self.pending.scan(query, &mut poll, |ids, births, d| {
                if !d.iter().any(|&d| d <= best.0) {
                    return;
                }
                for ((&id, &birth), &d) in ids.iter().zip(births).zip(&d) {
                    if d <= best.0 && (d, id) < best && alive.contains(id, birth) {
                        best = (d, id);
                    }
                }
            });
            if best.1 != u32::MAX {
                found.offer(best.0, best.1);
            }
            return complete && !poll.stopped;
        }
        // Four distances at a time; a group none of whose points would enter is passed over
        // with one comparison per point.
        let mut worst = found.worst();
        self.pending.scan(query, &mut poll, |ids, births, d| {
            if !d.iter().any(|&d| d <= worst) {
                return;
            }
            for ((&id, &birth), &d) in ids.iter().zip(births).zip(&d) {
                if d <= worst && alive.contains(id, birth) {
                    found.offer(d, id);
                    worst = found.worst();
                }
            }
        }) && !poll.stopped
    }

    /// Every live point within `radius`; `false` (and `found` incomplete) if `stop` fired first.
    pub(crate) fn within_alive(
        &mut self,
        query: &[f64],
        radius: f64,
        found: &mut Neighbours,
        alive: Alive<'_>,
        stop: &dyn Stop,
    ) -> bool {
        found.reset(usize::MAX);
        self.query_with(query, alive, stop, |nn, query| {
            nn.within_scaled(query, radius, found, alive, stop)
        })
    }

    /// What every query does first — counts it, maintains the trees, scales the query under
    /// a weighted metric — then `ask` with the query as the trees hold their points.
    fn query_with<R>(
        &mut self,
        query: &[f64],
        alive: Alive<'_>,
        stop: &dyn Stop,
        ask: impl FnOnce(&Self, &[f64]) -> R,
    ) -> R {
        self.queries += 1;
        self.maintain(alive, stop);
        let mut scaled = std::mem::take(&mut self.scaled);
        let answer = ask(self, Self::scale(&self.scales, &mut scaled, query));
        self.scaled = scaled;
        answer
    }

    /// [`within_alive`](Self::within_alive) for a query already scaled, after maintenance.
    fn within_scaled(
        &self,
        query: &[f64],
        radius: f64,
        found: &mut Neighbours,
        alive: Alive<'_>,
        stop: &dyn Stop,
    ) -> bool {
        let radius2 = radius * radius;
        let mut poll = Poll::new(stop, self.dimension);
        for tree in &self.trees {
            tree.within_into(query, radius2, found, alive, &mut poll);
        }
        let complete = self.pending.scan(query, &mut poll, |ids, births, d| {
            for ((&id, &birth), &d) in ids.iter().zip(births).zip(&d) {
                if d <= radius2 && alive.contains(id, birth) {
                    found.push_unordered(d, id);
                }
            }
        });
        found.sort();
        complete && !poll.stopped
    }
}

/// One tree holding the points of two (`None` if `stop` fired; the copies stay in `spare`).
fn merge(
    dimension: usize,
    (a, b): (&KdTree, &KdTree),
    stop: &dyn Stop,
    spare: &mut Spare,
) -> Option<KdTree> {
    KdTree::from_parts(dimension, &[a.parts(), b.parts()], stop, spare)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nearest::kd_tree::squared_distance;
    use mit_star_spaces::SeededRng;
    use mit_star_spaces::rand::{RngExt, SeedableRng};

    fn brute(
        points: &[f64],
        n: usize,
        query: &[f64],
        live: impl Fn(u32) -> bool,
    ) -> Vec<(f64, u32)> {
        let mut all: Vec<(f64, u32)> = points
            .chunks_exact(n)
            .enumerate()
            .map(|(i, p)| (squared_distance(query, p), i as u32))
            .filter(|&(_, i)| live(i))
            .collect();
        all.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        all
    }

    /// Fires from its `fires_at`-th poll on.
    struct FiresAt {
        polls: std::cell::Cell<u32>,
        fires_at: u32,
    }

    impl Stop for FiresAt {
        fn should_stop(&self) -> bool {
            self.polls.set(self.polls.get() + 1);
            self.polls.get() >= self.fires_at
        }
    }

    #[test]
    fn an_abandoned_build_keeps_its_arrays_and_answers_stay_exact() {
        let n = 8;
        let mut rng = SeededRng::seed_from_u64(5);
        let points: Vec<f64> = (0..20_000 * n).map(|_| rng.random::<f64>()).collect();
        let mut nn = NearestNeighbors::new(n);
        nn.insert(
            points
                .chunks_exact(n)
                .enumerate()
                .map(|(i, p)| (i as u32, p)),
        );
        let mut found = Neighbours::new();
        let query = vec![0.5; n];
        for fires_at in [2, 3, 5, 9] {
            let stop = FiresAt {
                polls: std::cell::Cell::new(0),
                fires_at,
            };
            // The build is abandoned part way: its copies are kept, not freed.
            nn.nearest_alive(&query, 5, &mut found, Alive::All, &stop);
            assert!(nn.spare.take().2.capacity() >= n, "fires at {fires_at}");
            assert!(nn.trees.is_empty());
        }
        // A query that may finish builds the tree, reusing the spare arrays, and is exact.
        nn.nearest(&query, 5, &mut found);
        assert_eq!(nn.trees.len(), 1);
        let expected: Vec<u32> = brute(&points, n, &query, |_| true)
            .iter()
            .take(5)
            .map(|&(_, id)| id)
            .collect();
        let got: Vec<u32> = found.iter().map(|&(_, id)| id).collect();
        assert_eq!(got, expected);
    }

    #[test]
    fn batches_and_removals_match_brute_force() {
        let n = 6;
        let mut rng = SeededRng::seed_from_u64(3);
        let mut points: Vec<f64> = Vec::new();
        let mut births: Vec<u32> = Vec::new();
        let mut nn = NearestNeighbors::new(n);
        let mut found = Neighbours::new();
        for batch in 0..40u32 {
            let first = points.len() / n;
            for _ in 0..(37 * n) {
                points.push(rng.random_range(-0.5..0.5));
            }
            births.resize(points.len() / n, batch);
            let slice = &points[first * n..];
            nn.insert_born(
                slice
                    .chunks_exact(n)
                    .enumerate()
                    .map(|(i, p)| ((first + i) as u32, batch, p)),
            );
            // Kill every third point of an earlier batch now and then.
            if batch % 7 == 6 {
                let mut killed = 0;
                for b in births.iter_mut().step_by(3) {
                    if *b != u32::MAX {
                        *b = u32::MAX;
                        killed += 1;
                    }
                }
                nn.note_removed(killed);
            }
            let live = |i: u32| births[i as usize] != u32::MAX;
            assert!(
                nn.tree_count() <= 8,
                "batch {batch}: {} trees",
                nn.tree_count()
            );
            let query: Vec<f64> = (0..n).map(|_| rng.random_range(-0.5..0.5)).collect();
            let stamps: crate::nearest::chunked::Chunked<u32> = births.iter().copied().collect();
            let alive = Alive::Current(&stamps);
            nn.nearest_alive(&query, 10, &mut found, alive, &Never);
            let expected = brute(&points, n, &query, live);
            assert_eq!(
                found.iter().copied().collect::<Vec<_>>(),
                expected[..10.min(expected.len())]
            );
            nn.within_alive(&query, 0.4, &mut found, alive, &Never);
            let within: Vec<_> = expected.into_iter().filter(|&(d, _)| d <= 0.16).collect();
            assert_eq!(found.iter().copied().collect::<Vec<_>>(), within);
        }
        assert_eq!(nn.len(), births.iter().filter(|&&b| b != u32::MAX).count());
        assert!(nn.queries() > 0);
    }

    #[test]
    fn buffered_points_give_the_distances_and_ties_of_brute_force_in_every_dimension() {
        // Dimensions with a kernel of their own (3, 7, 16) and without (1, 17); point counts
        // that leave the last group of four partly empty; every second point dead in the
        // second half; duplicates, so that ties are broken by id.
        let mut rng = SeededRng::seed_from_u64(11);
        for n in [1, 3, 7, 16, 17] {
            for count in [1, 2, 5, 8, 9, 30] {
                let mut points: Vec<f64> = (0..count * n)
                    .map(|_| rng.random_range(-1.0..1.0))
                    .collect();
                points.extend_from_within(..n.min(points.len()));
                let total = points.len() / n;
                let mut nn = NearestNeighbors::new(n);
                nn.insert_born(
                    points
                        .chunks_exact(n)
                        .enumerate()
                        .map(|(i, p)| (i as u32, 0, p)),
                );
                let births: Vec<u32> = (0..total)
                    .map(|i| u32::from(i > total / 2 && i % 2 == 0))
                    .collect();
                let stamps: crate::nearest::chunked::Chunked<u32> =
                    births.iter().copied().collect();
                let mut found = Neighbours::new();
                for _ in 0..5 {
                    let query: Vec<f64> = (0..n).map(|_| rng.random_range(-1.0..1.0)).collect();
                    for k in [1, 3] {
                        nn.nearest_alive(&query, k, &mut found, Alive::All, &Never);
                        let all = brute(&points, n, &query, |_| true);
                        assert_eq!(
                            found.iter().copied().collect::<Vec<_>>(),
                            all[..k.min(total)]
                        );
                        // Stamps of 1 no longer match the stored births of 0: dead.
                        nn.nearest_alive(&query, k, &mut found, Alive::Current(&stamps), &Never);
                        let live = brute(&points, n, &query, |i| births[i as usize] == 0);
                        assert_eq!(
                            found.iter().copied().collect::<Vec<_>>(),
                            live[..k.min(live.len())]
                        );
                    }
                    // The duplicate of point 0 ties with it; the lower id wins.
                    nn.nearest_alive(&points[..n], 1, &mut found, Alive::All, &Never);
                    assert_eq!(found.iter().copied().collect::<Vec<_>>(), [(0.0, 0)]);
                }
            }
        }
    }

    #[test]
    fn a_stopped_build_keeps_answers_exact() {
        let n = 3;
        let mut rng = SeededRng::seed_from_u64(5);
        let points: Vec<f64> = (0..3000 * n).map(|_| rng.random_range(-1.0..1.0)).collect();
        let mut nn = NearestNeighbors::new(n);
        nn.insert(
            points
                .chunks_exact(n)
                .enumerate()
                .map(|(i, p)| (i as u32, p)),
        );
        let always = || true;
        let mut found = Neighbours::new();
        nn.nearest_alive(&[0.1, 0.2, 0.3], 5, &mut found, Alive::All, &always);
        assert_eq!(nn.tree_count(), 0, "the build was abandoned");
        let expected = brute(&points, n, &[0.1, 0.2, 0.3], |_| true);
        assert_eq!(found.iter().copied().collect::<Vec<_>>(), expected[..5]);
        nn.nearest(&[0.1, 0.2, 0.3], 5, &mut found);
        assert_eq!(nn.tree_count(), 1, "built once nothing stops it");
        assert_eq!(found.iter().copied().collect::<Vec<_>>(), expected[..5]);
    }

    #[test]
    fn a_stopped_query_says_it_is_incomplete() {
        let n = 4;
        let mut rng = SeededRng::seed_from_u64(6);
        let points: Vec<f64> = (0..40_000 * n)
            .map(|_| rng.random_range(-1.0..1.0))
            .collect();
        let mut nn = NearestNeighbors::new(n);
        nn.insert(
            points
                .chunks_exact(n)
                .enumerate()
                .map(|(i, p)| (i as u32, p)),
        );
        let always = || true;
        let mut found = Neighbours::new();
        let query = [0.1, 0.2, 0.3, 0.4];
        assert!(!nn.nearest_alive(&query, 5, &mut found, Alive::All, &always));
        assert!(!nn.within_alive(&query, 0.3, &mut found, Alive::All, &always));
        assert_eq!(
            nn.tree_count(),
            0,
            "no build starts once the condition fired"
        );
        // Trees answer in polled pieces too.
        nn.nearest(&query, 5, &mut found);
        assert!(nn.tree_count() > 0);
        assert!(!nn.nearest_alive(&query, 40_000, &mut found, Alive::All, &always));
        assert!(nn.nearest_alive(&query, 5, &mut found, Alive::All, &Never));
        let expected = brute(&points, n, &query, |_| true);
        assert_eq!(found.iter().copied().collect::<Vec<_>>(), expected[..5]);
    }
}
