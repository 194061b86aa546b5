//! The RGG's neighbour lists: computed on first expansion, cached per vertex, and brought up
//! to date incrementally in later batches (dropping pruned vertices, merging new samples).

use mit_star_heuristics::Heuristic;
use mit_star_spaces::{StateSpace, Stop};

use crate::graph::random_geometric_graph::{DEAD, Neighbour, Neighbourhood, RandomGeometricGraph};
use crate::nearest::{Alive, Neighbours, Poll};

/// Extra nearest neighbours kept beyond `k`, so a list survives a few increments of `k` and a
/// few pruned neighbours.
const SLACK: usize = 4;

/// Above this many samples added since a list was made, the list is made afresh by a tree
/// query instead of measuring the vertex against each of them. In 7 or 8 dimensions, with the
/// arms' r-disc radius, a query over tens of thousands of vertices passes over few of them, and
/// the column pass over the recent states is a few vectorised operations per sample: on the
/// Fetch's bookshelf problems left unsolved for seconds, MIT* drew 10–35 % more samples in the
/// same time with 16 384 than with 400 (the lists, and so every decision, are the same).
pub(crate) const MERGE_LIMIT: usize = 16384;

/// Neighbours asked of the kd-trees beyond those wanted under a weighted Euclidean metric, so
/// that a neighbour the scaled coordinates rank a rounding error too far is still among them.
const WEIGHTED_EXTRA: usize = 2;

impl RandomGeometricGraph {
    /// The number of neighbours of `v` in this batch — entries `0..len` of its list, nearest
    /// first ([`neighbour`](Self::neighbour)) — computing or updating the cached list as needed.
    /// `None` if `stop` fired during a fresh query: then nothing changed (the cached list and
    /// its bookkeeping are as before), and the caller retries later.
    pub(crate) fn neighbours<S, H>(
        &mut self,
        v: u32,
        space: &S,
        heuristic: &H,
        stop: &dyn Stop,
    ) -> Option<usize>
    where
        S: StateSpace + ?Sized,
        H: Heuristic<S> + ?Sized,
    {
        let x = self.vertex(v);
        if x.neighbours_tag == self.tag {
            return Some(x.neighbours_len as usize);
        }
        let (had_list, from, wanted, radius, removals) = (
            x.neighbours_tag != 0,
            x.neighbours_log as usize,
            x.neighbours_wanted as usize,
            x.neighbours_radius,
            x.neighbours_removals,
        );
        let mut list = std::mem::take(&mut self.lists[v as usize]);
        // Pruned (or reused) neighbours leave; the rest are still the nearest survivors. Without
        // a removal since the list was made, every entry is alive.
        let before = list.len();
        if removals != self.removals {
            let births = &self.births;
            list.retain(|n| births[n.id as usize] == n.birth);
        }
        let wanted = wanted.saturating_sub(before - list.len());
        let added = self.log.len() - from;
        let reusable = had_list
            && added <= MERGE_LIMIT
            && match self.neighbourhood {
                Neighbourhood::Nearest(k) => k <= wanted,
                Neighbourhood::Radius(r) => r <= radius,
            };
        let wanted = if reusable {
            self.merge_added(v, from, wanted, space, heuristic, &mut list)
        } else {
            let mut fresh = std::mem::take(&mut self.scratch_list);
            fresh.clear();
            match self.query(v, space, heuristic, stop, &mut fresh) {
                Some(wanted) => {
                    self.scratch_list = std::mem::replace(&mut list, fresh);
                    wanted
                }
                None => {
                    // Interrupted: the old list and its bookkeeping stay as they were (the
                    // pruned entries dropped above are recomputed on the retry).
                    self.scratch_list = fresh;
                    self.lists[v as usize] = list;
                    self.vertex_mut(v).neighbours_tag = 0;
                    return None;
                }
            }
        };
        let used = match self.neighbourhood {
            Neighbourhood::Nearest(k) => k.min(list.len()),
            Neighbourhood::Radius(_) => list.len().min(self.neighbour_cap),
        };
        self.lists[v as usize] = list;
        let (tag, log, removals) = (self.tag, self.log.len() as u32, self.removals);
        let radius = match self.neighbourhood {
            Neighbourhood::Nearest(_) => 0.0,
            Neighbourhood::Radius(r) => r,
        };
        let x = self.vertex_mut(v);
        x.neighbours_tag = tag;
        x.neighbours_len = used as u32;
        x.neighbours_wanted = wanted as u32;
        x.neighbours_radius = radius;
        x.neighbours_log = log;
        x.neighbours_removals = removals;
        Some(used)
    }

    /// A fresh list for `v` in `out`; returns how many nearest neighbours it holds exactly
    /// (`k + SLACK`, or 0 for r-disc).
    fn query<S, H>(
        &mut self,
        v: u32,
        space: &S,
        heuristic: &H,
        stop: &dyn Stop,
        out: &mut Vec<Neighbour>,
    ) -> Option<usize>
    where
        S: StateSpace + ?Sized,
        H: Heuristic<S> + ?Sized,
    {
        if self.neighbourhood == Neighbourhood::Radius(f64::INFINITY) {
            return self
                .every_vertex(v, space, heuristic, stop, out)
                .then_some(0);
        }
        let mut found = std::mem::take(&mut self.found);
        let wanted = match self.neighbourhood {
            Neighbourhood::Nearest(k) => k + SLACK,
            Neighbourhood::Radius(_) => 0,
        };
        let query = &self.states[v as usize];
        let alive = Alive::Current(&self.births);
        // Under a weighted metric the trees hold scaled coordinates, whose distances round
        // differently from the space's: a little more is asked for, and the space's own
        // distances decide below.
        let (extra, grown) = if self.euclidean {
            (0, 1.0)
        } else {
            (WEIGHTED_EXTRA, 1.0 + 1e-9)
        };
        let complete = if self.indexed {
            match self.neighbourhood {
                // One more: the vertex itself is in the set.
                Neighbourhood::Nearest(_) => {
                    let k = wanted + 1 + extra;
                    self.nn.nearest_alive(query, k, &mut found, alive, stop)
                }
                Neighbourhood::Radius(r) => {
                    self.nn
                        .within_alive(query, r * grown, &mut found, alive, stop)
                }
            }
        } else {
            self.linear_query(v, space, wanted, &mut found, stop)
        };
        if !complete {
            self.found = found;
            return None;
        }
        let a = &self.states[v as usize];
        for &(_, w) in found.iter() {
            if w != v {
                out.push(self.entry(a, w, self.births[w as usize], space, heuristic));
            }
        }
        let capped = matches!(self.neighbourhood, Neighbourhood::Radius(_))
            && self.neighbour_cap != usize::MAX;
        if (self.indexed && !self.euclidean) || capped {
            out.sort_unstable_by(nearest_first);
            if let Neighbourhood::Radius(r) = self.neighbourhood {
                out.retain(|n| n.distance <= r);
            }
        }
        if let Neighbourhood::Nearest(_) = self.neighbourhood {
            out.truncate(wanted);
        }
        self.found = found;
        Some(wanted)
    }

    /// Merges into `list` (the surviving old neighbours of `v`, exact for the `wanted` nearest)
    /// the live samples added since log position `from`; returns how many nearest neighbours
    /// the result holds exactly.
    fn merge_added<S, H>(
        &mut self,
        v: u32,
        from: usize,
        wanted: usize,
        space: &S,
        heuristic: &H,
        list: &mut Vec<Neighbour>,
    ) -> usize
    where
        S: StateSpace + ?Sized,
        H: Heuristic<S> + ?Sized,
    {
        // A new sample farther than the radius, or than the farthest of the `wanted` old
        // neighbours, cannot enter the list.
        let bound = match self.neighbourhood {
            Neighbourhood::Radius(r) => r,
            Neighbourhood::Nearest(_) if list.len() >= wanted && wanted > 0 => {
                list[wanted - 1].distance
            }
            Neighbourhood::Nearest(_) => f64::INFINITY,
        };
        let complete = self.neighbourhood == Neighbourhood::Radius(f64::INFINITY);
        let mut squared = std::mem::take(&mut self.merge_distances);
        let mut entries = std::mem::take(&mut self.merge_entries);
        entries.clear();
        let x = &self.states[v as usize];
        let mut offer = |w: u32, birth: u32| {
            if w == v || self.births[w as usize] != birth {
                return;
            }
            // A complete graph (FCIT*): every sample enters, and its lists need no order.
            if complete || space.distance(x, &self.states[w as usize]) <= bound {
                entries.push(self.entry(x, w, birth, space, heuristic));
            }
        };
        // In a Euclidean space, plain or weighted, squared distances to the recent states,
        // column by column, rule out most samples before their log entries are even read; the
        // margins cover the rounding of both measures, and the space's own distance decides
        // every sample that passes, so the list is exactly the one it would give.
        // (A complete graph takes every sample: nothing to rule out.)
        let measured = if self.indexed && !complete {
            self.recent.squared_distances(from, x, &mut squared)
        } else {
            None
        };
        if let Some(slack) = measured {
            let limit = bound * (1.0 + 1e-9) + slack;
            let squared_bound = limit * limit;
            for (p, &d) in (from..).zip(&squared) {
                if d <= squared_bound {
                    let (w, birth) = self.log[p];
                    offer(w, birth);
                }
            }
        } else {
            for &(w, birth) in self.log.iter_from(from) {
                offer(w, birth);
            }
        }
        self.merge_distances = squared;
        if complete {
            list.extend_from_slice(&entries);
        } else {
            merge_sorted(list, &mut entries);
        }
        self.merge_entries = entries;
        match self.neighbourhood {
            Neighbourhood::Nearest(_) => {
                // The survivors held the `wanted` nearest old points, so the merge is exact up
                // to that many.
                list.truncate(wanted);
                wanted
            }
            Neighbourhood::Radius(r) => {
                if !complete {
                    list.retain(|n| n.distance <= r);
                }
                0
            }
        }
    }

    /// A complete graph's (FCIT*'s) list for `v` in `out`: every other live vertex the log
    /// holds (those committed, as a query would find them), in log order (ordered by distance
    /// only if the lists are capped), without a nearest-neighbour query. `false` if `stop`
    /// fired.
    fn every_vertex<S, H>(
        &self,
        v: u32,
        space: &S,
        heuristic: &H,
        stop: &dyn Stop,
        out: &mut Vec<Neighbour>,
    ) -> bool
    where
        S: StateSpace + ?Sized,
        H: Heuristic<S> + ?Sized,
    {
        let a = &self.states[v as usize];
        let mut poll = Poll::new(stop, a.len());
        out.reserve(self.graph.node_count());
        for &(w, birth) in self.log.iter_from(0) {
            if poll.tick(1) {
                return false;
            }
            if w != v && self.births[w as usize] == birth {
                out.push(self.entry(a, w, birth, space, heuristic));
            }
        }
        if self.neighbour_cap != usize::MAX {
            out.sort_unstable_by(nearest_first);
        }
        true
    }

    /// A list entry for the neighbour `w`, born `birth`, of the vertex at state `a`.
    #[inline]
    fn entry<S, H>(&self, a: &[f64], w: u32, birth: u32, space: &S, heuristic: &H) -> Neighbour
    where
        S: StateSpace + ?Sized,
        H: Heuristic<S> + ?Sized,
    {
        let (cost, distance) = self.measure(a, w, space, heuristic);
        Neighbour {
            id: w,
            birth,
            cost,
            distance,
        }
    }

    /// `ĉ` and the metric distance from the state `a` to vertex `w`, exactly as a list entry
    /// holds them.
    #[inline]
    pub(crate) fn measure<S, H>(&self, a: &[f64], w: u32, space: &S, heuristic: &H) -> (f64, f64)
    where
        S: StateSpace + ?Sized,
        H: Heuristic<S> + ?Sized,
    {
        let b = &self.states[w as usize];
        let distance = space.distance(a, b);
        (
            heuristic.edge_cost_given_distance(space, a, b, distance),
            distance,
        )
    }

    /// Neighbours of `v` by the space's own metric, by scanning every vertex.
    fn linear_query<S: StateSpace + ?Sized>(
        &mut self,
        v: u32,
        space: &S,
        wanted: usize,
        found: &mut Neighbours,
        stop: &dyn Stop,
    ) -> bool {
        self.linear_queries += 1;
        let query = &self.states[v as usize];
        let mut poll = Poll::new(stop, query.len());
        match self.neighbourhood {
            Neighbourhood::Nearest(_) => found.reset(wanted + 1),
            Neighbourhood::Radius(_) => found.reset(usize::MAX),
        }
        for node in self.graph.node_indices() {
            if poll.tick(1) {
                return false;
            }
            let id = node.index();
            debug_assert_ne!(self.births[id], DEAD);
            let d = space.distance(query, &self.states[id]);
            match self.neighbourhood {
                Neighbourhood::Nearest(_) => {
                    if d * d <= found.worst() {
                        found.offer(d * d, id as u32);
                    }
                }
                Neighbourhood::Radius(r) => {
                    if d <= r {
                        found.push_unordered(d * d, id as u32);
                    }
                }
            }
        }
        if let Neighbourhood::Radius(_) = self.neighbourhood {
            found.sort();
        }
        true
    }
}

/// Merges `added` (in any order, sorted here) into `list` (sorted [`nearest_first`], no entry
/// of `added` equal to one of it): one pass from the back, each entry moved once.
fn merge_sorted(list: &mut Vec<Neighbour>, added: &mut [Neighbour]) {
    if added.is_empty() {
        return;
    }
    added.sort_unstable_by(nearest_first);
    let old = list.len();
    list.extend_from_slice(added);
    let (mut i, mut j, mut k) = (old, added.len(), list.len());
    while j > 0 {
        k -= 1;
        if i > 0 && nearest_first(&list[i - 1], &added[j - 1]).is_gt() {
            list[k] = list[i - 1];
            i -= 1;
        } else {
            list[k] = added[j - 1];
            j -= 1;
        }
    }
}

/// The order of a list: nearest first, ties by id.
fn nearest_first(a: &Neighbour, b: &Neighbour) -> std::cmp::Ordering {
    a.distance.total_cmp(&b.distance).then(a.id.cmp(&b.id))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::graph::forward_tree::Pruning;
    use crate::graph::vertex::{Vertex, VertexKind};
    use mit_star_heuristics::Euclidean;
    use mit_star_spaces::rand::{RngExt, SeedableRng};
    use mit_star_spaces::{Never, RealVectorSpace, SeededRng, euclidean_distance};

    /// The ids of the `k` nearest vertices to `v` (or those within `r`), by brute force.
    fn brute(g: &RandomGeometricGraph, v: u32, rule: Neighbourhood) -> Vec<u32> {
        brute_with(g, v, rule, euclidean_distance)
    }

    /// [`brute`] under the metric `distance`.
    fn brute_with(
        g: &RandomGeometricGraph,
        v: u32,
        rule: Neighbourhood,
        distance: impl Fn(&[f64], &[f64]) -> f64,
    ) -> Vec<u32> {
        let x = g.state(v);
        let mut all: Vec<(f64, u32)> = g
            .graph
            .node_indices()
            .map(|n| n.index() as u32)
            .filter(|&w| w != v)
            .map(|w| (distance(x, g.state(w)), w))
            .collect();
        all.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        match rule {
            Neighbourhood::Nearest(k) => all.truncate(k),
            Neighbourhood::Radius(r) => all.retain(|&(d, _)| d <= r),
        }
        all.into_iter().map(|(_, w)| w).collect()
    }

    #[test]
    fn a_merge_gives_the_list_inserting_one_at_a_time_gives() {
        let mut rng = SeededRng::seed_from_u64(3);
        let entry = |id: u32, distance: f64| Neighbour {
            id,
            birth: 0,
            cost: distance,
            distance,
        };
        for _ in 0..500 {
            // Coarse distances, so that ties (broken by id) are common.
            let mut ids: Vec<u32> = (0..60).collect();
            let (mut list, mut added) = (Vec::new(), Vec::new());
            for _ in 0..rng.random_range(0..60usize) {
                let id = ids.swap_remove(rng.random_range(0..ids.len()));
                let n = entry(id, f64::from(rng.random_range(0..8u32)));
                if rng.random_bool(0.5) {
                    list.push(n);
                } else {
                    added.push(n);
                }
            }
            list.sort_unstable_by(nearest_first);
            let mut expected = list.clone();
            for n in &added {
                let at = expected.partition_point(|m| nearest_first(m, n).is_lt());
                expected.insert(at, *n);
            }
            merge_sorted(&mut list, &mut added);
            let key = |l: &[Neighbour]| l.iter().map(|n| (n.id, n.distance)).collect::<Vec<_>>();
            assert_eq!(key(&list), key(&expected));
        }
    }

    #[test]
    fn incremental_lists_equal_fresh_queries_across_batches_and_pruning() {
        for (n, euclidean) in [(3, true), (8, true), (4, false)] {
            let space = RealVectorSpace::cube(n, -0.5, 0.5).unwrap();
            let mut g = RandomGeometricGraph::new(n, euclidean);
            let mut rng = SeededRng::seed_from_u64(n as u64);
            let mut x = vec![0.0; n];
            for batch in 0..30 {
                let ids: Vec<u32> = (0..60)
                    .map(|_| {
                        x.iter_mut().for_each(|c| *c = rng.random_range(-0.5..0.5));
                        let cost = x[0] + 0.5;
                        g.add_vertex(&x, Vertex::new(VertexKind::Sample, cost, cost, 0))
                    })
                    .collect();
                g.commit(&ids);
                let rule = if batch % 3 == 2 {
                    Neighbourhood::Radius(0.6 - 0.01 * batch as f64)
                } else {
                    Neighbourhood::Nearest(5 + batch / 4)
                };
                g.set_neighbourhood(rule);
                // The same few vertices every batch exercise the incremental path.
                for v in [0u32, 7, 33, 70, ids[0]] {
                    if g.graph
                        .contains_node(petgraph::graph::NodeIndex::new(v as usize))
                    {
                        let len = g.neighbours(v, &space, &Euclidean, &Never).unwrap();
                        let got: Vec<u32> = (0..len).map(|i| g.neighbour(v, i).id).collect();
                        assert_eq!(got, brute(&g, v, rule), "n={n} batch={batch} v={v}");
                    }
                }
                // Prune a slice of the space now and then (ids get reused afterwards).
                if batch % 8 == 5 {
                    let bound = 1.6 - 0.1 * (batch / 8) as f64;
                    let outcome = g.prune(bound, &[], &mit_star_spaces::Never);
                    assert!(matches!(outcome, Pruning::Done(n) if n > 0));
                }
            }
        }
    }

    #[test]
    fn an_infinite_radius_joins_every_live_vertex_across_batches_and_pruning() {
        let space = RealVectorSpace::cube(3, -0.5, 0.5).unwrap();
        let mut g = RandomGeometricGraph::new(3, true);
        g.set_neighbourhood(Neighbourhood::Radius(f64::INFINITY));
        let mut rng = SeededRng::seed_from_u64(3);
        let mut x = vec![0.0; 3];
        for batch in 0..6 {
            let ids: Vec<u32> = (0..40)
                .map(|_| {
                    x.iter_mut().for_each(|c| *c = rng.random_range(-0.5..0.5));
                    let cost = x[0] + 0.5;
                    g.add_vertex(&x, Vertex::new(VertexKind::Sample, cost, cost, 0))
                })
                .collect();
            g.commit(&ids);
            g.new_batch();
            if batch == 3 {
                assert!(matches!(g.prune(1.4, &[], &Never), Pruning::Done(n) if n > 0));
                g.new_batch();
            }
            for v in [0u32, 5, ids[0]] {
                if !g
                    .graph
                    .contains_node(petgraph::graph::NodeIndex::new(v as usize))
                {
                    continue;
                }
                let len = g.neighbours(v, &space, &Euclidean, &Never).unwrap();
                let mut got: Vec<u32> = (0..len).map(|i| g.neighbour(v, i).id).collect();
                got.sort_unstable();
                let mut want = brute(&g, v, Neighbourhood::Radius(f64::INFINITY));
                want.sort_unstable();
                assert_eq!(got, want, "batch {batch} v {v}");
                assert_eq!(len, g.vertex_count() - 1);
            }
        }
    }

    #[test]
    fn weighted_joint_spaces_are_indexed_and_answer_as_a_scan() {
        use mit_star_spaces::{Joint, JointSpace, StateSpace};
        let weights = [1.0, 3.0, 0.5, 1.0, 2.0, 1.0, 0.7];
        let joints = weights
            .iter()
            .enumerate()
            .map(|(i, &w)| Joint::revolute(format!("j{i}"), -0.5, 0.5).weight(w))
            .collect();
        let space = JointSpace::new(joints).unwrap();
        assert!(!space.is_euclidean());
        assert_eq!(space.euclidean_scales(), Some(&weights[..]));
        let mut g = RandomGeometricGraph::for_space(&space);
        assert!(g.indexed && !g.euclidean);
        let mut rng = SeededRng::seed_from_u64(11);
        let mut x = vec![0.0; 7];
        for batch in 0..12 {
            let ids: Vec<u32> = (0..120)
                .map(|_| {
                    x.iter_mut().for_each(|c| *c = rng.random_range(-0.5..0.5));
                    g.add_vertex(&x, Vertex::new(VertexKind::Sample, 0.0, 0.0, 0))
                })
                .collect();
            g.commit(&ids);
            let rule = if batch % 3 == 2 {
                Neighbourhood::Radius(0.9)
            } else {
                Neighbourhood::Nearest(8 + batch)
            };
            g.set_neighbourhood(rule);
            for v in [0u32, 9, 100, ids[5]] {
                let len = g.neighbours(v, &space, &Euclidean, &Never).unwrap();
                let got: Vec<u32> = (0..len).map(|i| g.neighbour(v, i).id).collect();
                let want = brute_with(&g, v, rule, |a, b| space.distance(a, b));
                assert_eq!(got, want, "batch={batch} v={v}");
            }
        }
        // The kd-trees answered: nothing went to the linear scan.
        assert_eq!(g.linear_queries, 0);
        assert!(g.nn.queries() > 0);
    }
}
