//! The reverse search's frontier: the states it reached farthest from the goals, handed to the
//! sampler at the end of a batch without a solution
//! ([`Sampler::observe_frontier`](mit_star_samplers::Sampler::observe_frontier)).

use std::cmp::{Ordering, Reverse};

use mit_star_heuristics::Heuristic;
use mit_star_samplers::Sampler;
use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::{Counted, EdgeChecker, EdgeStatus, StateValidity};

use crate::Parameters;
use crate::informed_trees::NeighbourRule;
use crate::informed_trees::eit::Eit;
use crate::informed_trees::forward_queue::bits;
use crate::informed_trees::guidance::{Guidance, ReverseSearch};

/// Vertices of the reverse tree walked between two polls of the stop condition.
const FRONTIER_POLL: usize = 4096;

/// Keeps `entry` in `best`, the at most `wanted` entries with the largest cost, farthest
/// first, ties by id (so the result does not depend on the order entries come in).
pub(crate) fn keep_farthest(best: &mut Vec<(f64, u32)>, wanted: usize, entry: (f64, u32)) {
    let farther = |a: &(f64, u32), b: &(f64, u32)| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1));
    if best.len() == wanted && farther(&entry, &best[wanted - 1]) != Ordering::Less {
        return;
    }
    let at = best.partition_point(|kept| farther(kept, &entry) == Ordering::Less);
    if best.len() == wanted {
        best.pop();
    }
    best.insert(at, entry);
}

impl<S, V, Smp, E, H, G, N> Eit<S, V, Smp, E, H, G, N>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
    H: Heuristic<S>,
    G: Guidance,
    N: NeighbourRule,
{
    /// Hands the sampler the frontier of the reverse search that just ended: without a
    /// solution, the [`near_frontier`](crate::Parameters::near_frontier) samples of the reverse
    /// tree with the largest cost-to-go `ĥ`, farthest first; with one (or with the count 0, or
    /// without a reverse search), nothing, once, so that the sampler drops what it kept.
    ///
    /// If the reverse tree holds more than half of the graph's vertices but not the start
    /// ([`start_frontier`](crate::Parameters::start_frontier), MIT* and EIT*), the start is
    /// the end in a pocket: the states the start's side reached farthest are sent instead
    /// ([`reach_from_start`](Self::reach_from_start), capped at the vertices outside the
    /// reverse tree). Otherwise, with
    /// [`validated_frontier`](crate::Parameters::validated_frontier), the farthest states of
    /// the part of the reverse tree that full checks confirm are sent
    /// ([`validated_farthest`](Self::validated_farthest)).
    ///
    /// Walks the reverse tree from the goals through its child lists, keeping the best
    /// `near_frontier` in a small sorted buffer. Allocates nothing once the buffers have grown.
    /// Polls `stop` every [`FRONTIER_POLL`] vertices; if it fires, the walk is abandoned and
    /// the sampler keeps the frontier it had (`frontier_states` is always what it holds).
    ///
    /// Complexity: O(t · f) for a reverse tree of `t` vertices and a frontier of `f` states
    /// (the search that built the tree touched each of them already).
    pub(crate) fn send_frontier(&mut self, solved: bool, stop: &dyn Stop) {
        let wanted = self.parameters.near_frontier;
        let held = !self.frontier_states.is_empty();
        if solved || wanted == 0 || G::REVERSE == ReverseSearch::None {
            if held {
                self.frontier_states.clear();
                self.sampler.observe_frontier(&[]);
            }
            return;
        }
        let tag = self.reverse_tag;
        let mut best = std::mem::take(&mut self.frontier);
        best.clear();
        let mut walk = std::mem::take(&mut self.branch);
        walk.clear();
        walk.extend(
            self.goal_ids
                .iter()
                .copied()
                .filter(|&g| self.graph.vertex(g).h(tag).is_finite()),
        );
        let mut walked = 0_usize;
        let mut stopped = false;
        while let Some(v) = walk.pop() {
            walked += 1;
            if walked.is_multiple_of(FRONTIER_POLL) && stop.should_stop() {
                stopped = true;
                break;
            }
            self.push_reverse_children(v, &mut walk);
            let vertex = self.graph.vertex(v);
            let h = vertex.h(tag);
            if vertex.is_terminal() || !h.is_finite() {
                continue;
            }
            keep_farthest(&mut best, wanted, (h, v));
        }
        self.branch = walk;
        // The reverse tree holds most of the graph but not the start: the goals are not the
        // ones in a pocket, the start is, and the states its side reached farthest are the
        // frontier instead.
        let vertices = self.graph.vertex_count();
        if !stopped
            && self.parameters.start_frontier
            && G::REVERSE == ReverseSearch::SparseChecked
            && 2 * walked > vertices
            && !self.graph.vertex(self.start_id).h(tag).is_finite()
            && self.reach_from_start(vertices.saturating_sub(walked), wanted, stop)
        {
            std::mem::swap(&mut best, &mut self.start_reach.farthest);
            self.counters.start_frontiers += 1;
        } else if !stopped && self.parameters.validated_frontier {
            stopped = !self.validated_farthest(wanted, &mut best, stop);
        }
        if !stopped {
            self.frontier_states.clear();
            for &(_, v) in &best {
                self.frontier_states.extend_from_slice(self.graph.state(v));
            }
            if held || !best.is_empty() {
                self.sampler.observe_frontier(&self.frontier_states);
            }
        }
        self.frontier = best;
    }

    /// Keeps in `best` the `wanted` vertices farthest from the goals (largest `ĥ`, farthest
    /// first) among those the goals reach through reverse-tree edges that pass a full check
    /// ([`validated_frontier`](crate::Parameters::validated_frontier)). The walk goes nearest
    /// first; a tree edge not yet decided is fully checked (what the check learns is stored,
    /// so an invalid edge is blacklisted for the searches too) while fewer than
    /// [`VALIDATED_FRONTIER_CHECKS`](Parameters::VALIDATED_FRONTIER_CHECKS) checks were made,
    /// and left unwalked after. Returns `false` if the stop condition fired (polled every
    /// [`FRONTIER_POLL`] vertices and inside the checks).
    ///
    /// Complexity: O(t log t) for the `t` tree vertices walked, plus the checks.
    fn validated_farthest(
        &mut self,
        wanted: usize,
        best: &mut Vec<(f64, u32)>,
        stop: &dyn Stop,
    ) -> bool {
        let tag = self.reverse_tag;
        best.clear();
        // The start's search is not running: its heap is free scratch here (a cheapest-first
        // queue of vertex ids, as this walk needs).
        let mut heap = std::mem::take(&mut self.start_reach.heap);
        heap.clear();
        for &g in &self.goal_ids {
            let h = self.graph.vertex(g).h(tag);
            if h.is_finite() {
                heap.push(Reverse((bits(h), g)));
            }
        }
        let mut children = std::mem::take(&mut self.branch);
        let (mut checks, mut settled, mut complete) = (0_usize, 0_usize, true);
        'walk: while let Some(Reverse((_, v))) = heap.pop() {
            settled += 1;
            if settled % FRONTIER_POLL == 0 && stop.should_stop() {
                complete = false;
                break;
            }
            let vertex = self.graph.vertex(v);
            if !vertex.is_terminal() {
                keep_farthest(best, wanted, (vertex.h(tag), v));
            }
            children.clear();
            self.push_reverse_children(v, &mut children);
            for &w in &children {
                let h = self.graph.vertex(w).h(tag);
                if !h.is_finite() {
                    continue;
                }
                let status = match self.graph.edge(v, w).map(|r| r.status) {
                    Some(known @ (EdgeStatus::Valid | EdgeStatus::Invalid)) => known,
                    _ if checks >= Parameters::VALIDATED_FRONTIER_CHECKS => continue,
                    _ => {
                        checks += 1;
                        self.full_check(v, w, stop)
                    }
                };
                match status {
                    EdgeStatus::Valid => heap.push(Reverse((bits(h), w))),
                    EdgeStatus::Invalid => {}
                    EdgeStatus::Unknown => {
                        complete = false;
                        break 'walk;
                    }
                }
            }
        }
        self.branch = children;
        self.start_reach.heap = heap;
        complete
    }
}
