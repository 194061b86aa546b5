//! The lazy reverse search from the goals (spec §3.2): sparse checks only, keys `(k1, k2, k3)`.

use mit_star_heuristics::Heuristic;
use mit_star_samplers::Sampler;
use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::{Counted, EdgeChecker, EdgeGrid, EdgeProgress, EdgeStatus, StateValidity};

use crate::graph::{EdgeRecord, NO_EFFORT, NONE, RandomGeometricGraph};
use crate::informed_trees::NeighbourRule;
use crate::informed_trees::eit::Eit;
use crate::informed_trees::forward_queue::{ForwardEdge, ForwardKeys};
use crate::informed_trees::guidance::{Guidance, ReverseSearch};
use crate::informed_trees::reverse_queue::ReverseEdge;
use crate::termination::SolveStop;

/// Where the forward keys take the target's heuristic from.
#[derive(Debug, Clone, Copy)]
pub(crate) struct KeyRule {
    /// The reverse search tagged `tag` (or, with `a_priori`, no reverse search).
    pub(crate) tag: u32,
    /// The full-resolution check step (sizes an edge's remaining checks).
    pub(crate) step: f64,
    /// Use the a-priori `ĥ` (BIT*) instead of the reverse search's values.
    pub(crate) a_priori: bool,
    /// Inflation `ε ≥ 1` of the a-priori `ĥ` in the `estimated` key.
    pub(crate) inflation: f64,
}

/// The forward keys of `edge` under `rule`.
pub(crate) fn forward_keys(
    graph: &RandomGeometricGraph,
    rule: KeyRule,
    edge: &ForwardEdge,
) -> ForwardKeys {
    let (u, v) = (graph.vertex(edge.source), graph.vertex(edge.target));
    let through = u.g + edge.cost;
    let remaining = graph
        .progress(edge.source, edge.target)
        .remaining(&EdgeGrid::new(edge.distance, rule.step));
    if rule.a_priori {
        let h = v.cost_to_go_bound;
        return ForwardKeys {
            lower: through + h,
            estimated: through + rule.inflation * h,
            effort: remaining,
        };
    }
    let tag = rule.tag;
    ForwardKeys {
        lower: through + v.h(tag),
        estimated: through + v.h_estimate(tag),
        effort: remaining.saturating_add(v.effort(tag)),
    }
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
    /// `true` if a reverse-queue entry is still worth processing: its source has not been
    /// expanded again since, and it could lead to a better solution.
    fn reverse_current(&self, edge: &ReverseEdge) -> bool {
        let u = self.graph.vertex(edge.source);
        u.reverse_version == edge.version
            && u.reverse_tag == self.reverse_tag
            && edge.k1() < self.best_cost
    }

    /// How forward keys are computed now.
    pub(crate) fn key_rule(&self) -> KeyRule {
        KeyRule {
            tag: self.reverse_tag,
            step: self.step,
            a_priori: G::REVERSE == ReverseSearch::None,
            inflation: self.inflation,
        }
    }

    /// `ĥ(v)` as the forward search uses it: the reverse search's, or the a-priori one.
    pub(crate) fn forward_h(&self, v: u32) -> f64 {
        let x = self.graph.vertex(v);
        if G::REVERSE == ReverseSearch::None {
            x.cost_to_go_bound
        } else {
            x.h(self.reverse_tag)
        }
    }

    /// Restarts the reverse search from the goals: every vertex's `ĥ`, `h̃` and `e` are reset
    /// (by a new tag), the reverse tree and queue cleared, and the forward queue re-keyed.
    /// Without a reverse search (BIT*) only the forward queue is re-keyed. The re-key polls
    /// `stop`; if it fires, [`continue_reverse_restart`](Self::continue_reverse_restart)
    /// finishes the restart in the next iteration.
    pub(crate) fn restart_reverse(&mut self, stop: &dyn Stop) {
        self.reverse_tag = self.reverse_tag.wrapping_add(1).max(1);
        self.reverse.clear();
        // A deferred reverse expansion belongs to the search being discarded (its queue entries
        // would have been cleared just now).
        self.deferred.retain(|&(_, _, forward)| forward);
        let tag = self.reverse_tag;
        for i in 0..self.goal_ids.len() {
            let goal = self.graph.vertex_mut(self.goal_ids[i]);
            goal.touch_reverse(tag);
            goal.h = 0.0;
            goal.h_estimate = 0.0;
            goal.effort = 0;
        }
        self.forward.begin_rekey_all();
        self.continue_reverse_restart(stop);
    }

    /// The rest of a reverse restart: re-keys the forward queue (polling `stop`; if it fires,
    /// the next iteration resumes here), then seeds the reverse search from the goals.
    pub(crate) fn continue_reverse_restart(&mut self, stop: &dyn Stop) {
        let (graph, rule) = (&self.graph, self.key_rule());
        if !self
            .forward
            .rekey_all(|e| forward_keys(graph, rule, e), stop)
        {
            return;
        }
        if G::REVERSE == ReverseSearch::None {
            return;
        }
        for i in 0..self.goal_ids.len() {
            if stop.should_stop() {
                // The other goals' expansions wait for the next iterations, in order: with
                // thousands of goals, their neighbour queries are the restart's work.
                let rest = self.goal_ids[i..].iter().map(|&g| (g, NONE, false));
                self.deferred.extend(rest);
                return;
            }
            self.expand_reverse(self.goal_ids[i], NONE, stop);
        }
    }

    /// Marks `u` closed (expanded) in the current reverse search.
    fn close(&mut self, u: u32) {
        let tag = self.reverse_tag;
        let vertex = self.graph.vertex_mut(u);
        if vertex.closed_tag != tag {
            vertex.closed_tag = tag;
            self.forward.close_target(u);
        }
    }

    /// Queues the reverse edges out of `v` (except to `exclude`) that could improve their
    /// target and, once a solution exists, could lead to a better one.
    pub(crate) fn expand_reverse(&mut self, v: u32, exclude: u32, stop: &dyn Stop) {
        let Some(len) = self.graph.neighbours(v, &self.space, &self.heuristic, stop) else {
            // The termination condition fired during the neighbour query: the expansion waits
            // for the next iteration.
            self.deferred.push((v, exclude, false));
            return;
        };
        let tag = self.reverse_tag;
        let version = {
            let x = self.graph.vertex_mut(v);
            x.reverse_version = x.reverse_version.wrapping_add(1);
            x.reverse_version
        };
        let (h, effort) = (self.graph.vertex(v).h, self.graph.vertex(v).effort);
        let mut pushed = 0;
        for i in 0..len {
            let n = self.graph.neighbour(v, i);
            let edge = (v, n.id, i as u32, n.cost, n.distance);
            pushed += usize::from(self.queue_reverse(edge, h, effort, version, exclude, tag));
        }
        // Forward-tree edges are known valid: offer them to the reverse search too.
        self.collect_tree_extras(v, len, false);
        for j in 0..self.extras.len() {
            let w = self.extras[j];
            let (cost, distance) = self.edge_geometry(v, w, NONE);
            let edge = (v, w, NONE, cost, distance);
            pushed += usize::from(self.queue_reverse(edge, h, effort, version, exclude, tag));
        }
        if pushed == 0 {
            self.close(v);
        }
    }

    /// Queues the reverse edge `(v, w, hint, ĉ, distance)` out of `v` (with `ĥ(v) = h`,
    /// `e(v) = effort`) if it could improve `w` and, once a solution exists, a solution.
    pub(crate) fn queue_reverse(
        &mut self,
        (v, w, hint, cost, distance): (u32, u32, u32, f64, f64),
        h: f64,
        effort: u64,
        version: u32,
        exclude: u32,
        tag: u32,
    ) -> bool {
        if w == exclude {
            return false;
        }
        let target = self.graph.vertex(w);
        let k2 = h + cost;
        // An edge that cannot improve its target now never will (ĥ only decreases).
        if k2 >= target.h(tag) {
            return false;
        }
        let k1 = k2 + target.cost_to_come_bound;
        if k1 >= self.best_cost {
            return false;
        }
        let from_start = target.effort_from_start;
        let record = self.graph.edge(v, w);
        if record.is_some_and(|r| r.status == EdgeStatus::Invalid) {
            return false;
        }
        let progress = record.map_or(EdgeProgress::UNTESTED, |r| r.progress);
        let remaining = progress.remaining(&EdgeGrid::new(distance, self.step));
        let k3 = effort.saturating_add(remaining).saturating_add(from_start);
        self.reverse
            .push(ReverseEdge::new((k1, k2, k3), (v, w, cost), hint, version));
        true
    }

    /// Should the reverse search take the next step (spec §3.2)?
    pub(crate) fn continue_reverse(&mut self) -> bool {
        let Some(best_reverse) = self.peek_reverse() else {
            return false;
        };
        if self.forward.is_empty() {
            let suspend = self
                .parameters
                .suspend_reverse_when_forward_empty
                .unwrap_or(G::SUSPEND_WHEN_FORWARD_EMPTY);
            return !suspend;
        }
        let front = self.front();
        let Some((edge, _)) = self.forward.peek(front) else {
            return false;
        };
        let tag = self.reverse_tag;
        let target = self.graph.vertex(edge.target);
        let (closed, reached) = (target.is_closed(tag), target.in_reverse_tree(tag));
        if closed && self.forward.min_lower() < best_reverse.k1() {
            return false;
        }
        if !self.forward.has_open_targets() {
            return false;
        }
        if !self.best_cost.is_finite() && reached {
            return false;
        }
        true
    }

    pub(crate) fn peek_reverse(&mut self) -> Option<ReverseEdge> {
        let mut reverse = std::mem::take(&mut self.reverse);
        let top = reverse.peek(|e| self.reverse_current(e));
        self.reverse = reverse;
        top
    }

    /// One reverse-search step: pop the best edge, sparse-check it, and let it improve its
    /// target.
    pub(crate) fn reverse_step(&mut self, stop: &SolveStop<'_>) {
        self.counters.reverse_iterations += 1;
        let mut reverse = std::mem::take(&mut self.reverse);
        let edge = reverse.pop(|e| self.reverse_current(e));
        self.reverse = reverse;
        let Some(edge) = edge else {
            return;
        };
        let (u, v, tag) = (edge.source, edge.target, self.reverse_tag);
        self.close(u);
        if self.graph.vertex(v).reverse_parent(tag) == u {
            // Already the reverse-tree edge: just re-expand the target.
            self.expand_reverse(v, u, stop);
            return;
        }
        let (cost, h_u) = (edge.cost(), self.graph.vertex(u).h);
        if h_u + cost >= self.graph.vertex(v).h(tag) {
            return;
        }
        let (_, distance) = self.edge_geometry(u, v, edge.hint);
        // AIT*: the reverse search checks nothing.
        let (status, progress) =
            self.sparse_check(u, v, G::REVERSE != ReverseSearch::Unchecked, stop);
        if status == EdgeStatus::Invalid {
            return;
        }
        let remaining = progress.remaining(&EdgeGrid::new(distance, self.step));
        let (h_est_u, effort_u) = {
            let x = self.graph.vertex(u);
            (x.h_estimate, x.effort)
        };
        let target = self.graph.vertex_mut(v);
        target.touch_reverse(tag);
        target.h = h_u + cost;
        target.h_estimate = target.h_estimate.min(h_est_u + cost);
        let through = if effort_u == NO_EFFORT {
            NO_EFFORT
        } else {
            effort_u.saturating_add(remaining)
        };
        target.effort = target.effort.min(through);
        self.link_reverse(v, u);
        self.queue_lazy_edge(v, u);
        let (graph, rule) = (&self.graph, self.key_rule());
        self.forward
            .update_incoming(v, |e| forward_keys(graph, rule, e));
        self.expand_reverse(v, u, stop);
    }

    /// What the sparse check of the current level says of the edge `u — v`, and how far its
    /// grid is tested: a white- or blacklisted edge's status as stored; otherwise, with
    /// `check`, the check is run and what it learned stored, and without it the status is
    /// unknown. A check the stop condition interrupted answers unknown.
    pub(crate) fn sparse_check(
        &mut self,
        u: u32,
        v: u32,
        check: bool,
        stop: &dyn Stop,
    ) -> (EdgeStatus, EdgeProgress) {
        let record = self.graph.edge(u, v);
        let mut progress = record.map_or(EdgeProgress::UNTESTED, |r| r.progress);
        let status = match record.map(|r| r.status) {
            Some(status @ (EdgeStatus::Valid | EdgeStatus::Invalid)) => status,
            _ if !check => EdgeStatus::Unknown,
            _ => {
                let before = progress;
                let (a, b) = (self.graph.state(u), self.graph.state(v));
                let status = self.checker.check_sparse(
                    &self.space,
                    &self.validity,
                    a,
                    b,
                    &mut progress,
                    stop,
                );
                if progress != before {
                    self.store_checked(u, v, progress, status);
                }
                status
            }
        };
        (status, progress)
    }

    /// Stores what a sparse or full check of `u — v` learnt (the edge is not certified).
    pub(crate) fn store_checked(
        &mut self,
        u: u32,
        v: u32,
        progress: EdgeProgress,
        status: EdgeStatus,
    ) {
        let record = EdgeRecord {
            progress,
            status,
            certified: false,
        };
        self.graph.store_edge(u, v, record);
    }

    /// `ĉ` and the metric distance of `u — v`, from `u`'s cached neighbours when `hint` points
    /// there.
    pub(crate) fn edge_geometry(&self, u: u32, v: u32, hint: u32) -> (f64, f64) {
        if let Some(n) = self.graph.hinted(u, hint, v) {
            return (n.cost, n.distance);
        }
        let (a, b) = (self.graph.state(u), self.graph.state(v));
        (
            self.heuristic.edge_cost(&self.space, a, b),
            self.space.distance(a, b),
        )
    }

    /// Fills `self.extras` with the tree neighbours of `v` that are not among its first `len`
    /// cached neighbours: its forward parent and children, and (for the forward search) its
    /// reverse parent.
    pub(crate) fn collect_tree_extras(&mut self, v: u32, len: usize, forward: bool) {
        self.extras.clear();
        let x = self.graph.vertex(v);
        if x.parent != NONE {
            self.extras.push(x.parent);
        }
        let mut child = x.first_child;
        while child != NONE {
            self.extras.push(child);
            child = self.graph.vertex(child).next_sibling;
        }
        if forward {
            let p = x.reverse_parent(self.reverse_tag);
            if p != NONE {
                self.extras.push(p);
            }
        }
        let graph = &self.graph;
        if self.listless() {
            // The complete list `v` would have holds every committed vertex.
            self.extras
                .retain(|&w| w != v && graph.log_position(w).is_none());
        } else if self.extras.is_empty() || len + 1 == graph.vertex_count() {
            // A list of every other vertex (a complete graph's) holds them all already.
            self.extras.clear();
            return;
        } else {
            self.extras
                .retain(|&w| w != v && !(0..len).any(|i| graph.neighbour(v, i).id == w));
        }
        self.extras.sort_unstable();
        self.extras.dedup();
    }
}
