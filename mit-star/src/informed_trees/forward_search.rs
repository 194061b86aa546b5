//! The forward search from the start (spec §3.3): full edge checks, effort-greedy before the
//! first solution and A* after, and the reverse-search restart when a lazy edge is invalid.

use mit_star_heuristics::Heuristic;
use mit_star_samplers::{LazyPathFailure, Sampler};
use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::{Counted, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity};

use crate::RestartEvent;
use crate::graph::{EdgeRecord, NONE};
use crate::informed_trees::NeighbourRule;
use crate::informed_trees::eit::Eit;
use crate::informed_trees::forward_queue::{ForwardEdge, Front};
use crate::informed_trees::guidance::{Guidance, ReverseSearch};
use crate::informed_trees::reverse_search::forward_keys;
use crate::termination::SolveStop;

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
    /// The front selection: BIT*'s (inflated) cost order with the a-priori guidance; else
    /// `ε = ∞` (effort-greedy, EIT*) or A* before the first solution, A* after.
    pub(crate) fn front(&self) -> Front {
        if G::REVERSE == ReverseSearch::None {
            Front::Estimated
        } else if self.best_cost.is_finite() || !G::EFFORT_FIRST {
            Front::Optimal
        } else {
            Front::Greedy
        }
    }

    /// Should the forward search take the next step: is there an edge whose admissible key
    /// (times the truncation factor, 1 but for ABIT*) beats the current solution?
    pub(crate) fn continue_forward(&mut self) -> bool {
        !self.forward.is_empty() && self.forward.min_lower() * self.truncation < self.best_cost
    }

    /// `true` if the search of a batch ends at the first edge it takes that fails the
    /// truncation test `(g + ĉ + ĥ) · truncation < c_best`, as ABIT*'s does: the a-priori
    /// guidance with a truncation factor above 1. BIT* (factor 1) skips such an edge and
    /// goes on, as do the guidances with a reverse search, whose own rules end a search.
    fn truncates(&self) -> bool {
        G::REVERSE == ReverseSearch::None && self.truncation > 1.0
    }

    /// Queues `edge` with its current keys.
    pub(crate) fn queue_forward(&mut self, edge: ForwardEdge) {
        let keys = forward_keys(&self.graph, self.key_rule(), &edge);
        let open = !self.graph.vertex(edge.target).is_closed(self.reverse_tag);
        self.forward.insert_or_update(edge, keys, open);
    }

    /// Queues the forward edges out of `v` (except back to `exclude` and known-invalid ones):
    /// its cached neighbours plus its tree neighbours. Without cascading rewirings (BIT*'s
    /// default, [`Parameters::cascading_rewirings`](crate::Parameters)), edges to other tree
    /// vertices are queued only by `v`'s first expansion that meets any.
    pub(crate) fn expand_forward(&mut self, v: u32, exclude: u32, stop: &dyn Stop) {
        // FCIT*'s complete graph needs no lists (`lazy_successors.rs`).
        let listless = self.listless();
        let len = if listless {
            0
        } else if let Some(len) = self.graph.neighbours(v, &self.space, &self.heuristic, stop) {
            len
        } else {
            // The termination condition fired during the neighbour query: the expansion waits
            // for the next iteration.
            self.deferred.push((v, exclude, true));
            return;
        };
        let tag = self.graph.tag;
        let rewirings = G::REVERSE != ReverseSearch::None
            || self.parameters.cascading_rewirings.unwrap_or(false)
            || !self.graph.vertex(v).rewiring_expanded;
        let mut rewired = false;
        // FCIT*'s complete graph: one edge of the list queued at a time (`lazy_successors.rs`).
        let listed = if self.lazy_successors() {
            if !self.expand_forward_lazily(v, len, exclude, stop) {
                // The termination condition fired during the ranking: as above.
                self.deferred.push((v, exclude, true));
                return;
            }
            0
        } else {
            len
        };
        self.graph.vertex_mut(v).forward_expanded = tag;
        for i in 0..listed {
            let n = self.graph.neighbour(v, i);
            if n.id == exclude || self.is_blacklisted(v, n.id) {
                continue;
            }
            if self.is_rewiring(v, n.id) {
                if !rewirings {
                    continue;
                }
                rewired = true;
            }
            self.queue_forward(ForwardEdge {
                source: v,
                target: n.id,
                hint: i as u32,
                cost: n.cost,
                distance: n.distance,
            });
        }
        self.collect_tree_extras(v, len, true);
        for j in 0..self.extras.len() {
            let w = self.extras[j];
            if w == exclude || self.is_blacklisted(v, w) {
                continue;
            }
            if self.is_rewiring(v, w) {
                if !rewirings {
                    continue;
                }
                rewired = true;
            }
            let (cost, distance) = self.edge_geometry(v, w, NONE);
            self.queue_forward(ForwardEdge {
                source: v,
                target: w,
                hint: NONE,
                cost,
                distance,
            });
        }
        if rewired {
            self.graph.vertex_mut(v).rewiring_expanded = true;
        }
    }

    /// Queues the forward edge `v → u` when the reverse search has just made `u` the reverse
    /// parent of `v`, if `v`'s forward expansion in this batch cannot have queued it: `v` was
    /// expanded before `u` became its reverse parent (a reverse restart or repair after the
    /// expansion), and `u` is not among `v`'s cached neighbours (`k`-nearest neighbours are
    /// not symmetric: the reverse search reached `v` from `u`'s list). Without it the forward
    /// search never tries the first edge of `v`'s lazy path, and a batch whose lazy paths all
    /// run through such an edge searches every other edge of the graph instead.
    pub(crate) fn queue_lazy_edge(&mut self, v: u32, u: u32) {
        let x = self.graph.vertex(v);
        if x.forward_expanded != self.graph.tag
            || x.parent == u
            || x.is_goal()
            || self.graph.in_neighbour_list(v, u)
            || self.is_blacklisted(v, u)
        {
            return;
        }
        let (cost, distance) = self.edge_geometry(v, u, NONE);
        self.queue_forward(ForwardEdge {
            source: v,
            target: u,
            hint: NONE,
            cost,
            distance,
        });
    }

    /// `true` if the edge `v → w` would rewire the forward tree: `w` is in it, and not as a
    /// child of `v`.
    pub(crate) fn is_rewiring(&self, v: u32, w: u32) -> bool {
        self.graph.vertex(w).rewired_from(v)
    }

    /// `true` if the edge `v — w` is known invalid.
    pub(crate) fn is_blacklisted(&self, v: u32, w: u32) -> bool {
        self.graph
            .edge(v, w)
            .is_some_and(|r| r.status == EdgeStatus::Invalid)
    }

    /// Full check of the edge `u — v` (spec §3.3), reusing what earlier checks tested and
    /// storing what this one learns; a known status is returned without a check.
    /// [`EdgeStatus::Unknown`] only if `stop` fired mid-check (the progress is kept).
    pub(crate) fn full_check(&mut self, u: u32, v: u32, stop: &dyn Stop) -> EdgeStatus {
        let record = self.graph.edge(u, v);
        match record.map(|r| r.status) {
            Some(status @ (EdgeStatus::Valid | EdgeStatus::Invalid)) => status,
            _ => {
                let mut progress = record.map_or(EdgeProgress::UNTESTED, |r| r.progress);
                let before = progress;
                let (a, b) = (self.graph.state(u), self.graph.state(v));
                let status =
                    self.checker
                        .check_full(&self.space, &self.validity, a, b, &mut progress, stop);
                if progress != before || record.is_none() {
                    self.store_checked(u, v, progress, status);
                }
                status
            }
        }
    }

    /// One forward-search step.
    pub(crate) fn forward_step(&mut self, stop: &SolveStop<'_>) {
        self.counters.forward_iterations += 1;
        let front = self.front();
        let Some((edge, _)) = self.forward.pop(front) else {
            return;
        };
        let (u, v) = (edge.source, edge.target);
        if self.lazy_successors() {
            self.advance_successors(u, v);
        }
        let target = self.graph.vertex(v);
        // A forward-tree edge (the tree persists across batches): just continue through it.
        if target.parent == u {
            if !target.is_goal() {
                self.expand_forward(v, u, stop);
            }
            return;
        }
        let g_u = self.graph.vertex(u).g;
        let (g_v, h_v) = (target.g, self.forward_h(v));
        if self.best_cost.is_finite() && (g_u + edge.cost + h_v) * self.truncation >= self.best_cost
        {
            if self.truncates() {
                // ABIT* (OMPL's `isSearchDone_`): the queue is in order, so no later edge
                // passes either — the batch's search ends here.
                self.forward.clear();
            }
            return;
        }
        if g_u + edge.cost >= g_v {
            return;
        }
        let status = self.full_check(u, v, stop);
        match status {
            EdgeStatus::Valid => {
                let new_g = g_u + edge.distance;
                if new_g < g_v && (!self.best_cost.is_finite() || new_g + h_v < self.best_cost) {
                    // A vertex new to the tree may join through an uncertified edge, certified
                    // once a solution's path uses it (`settle_solutions`); one already in the
                    // tree moves only under a certified path, `u`'s and the edge, so that the
                    // best solution's path stays certified (`solution_certification.rs`).
                    // Without lazy certification `certify_path` has nothing to do.
                    let status = if !g_v.is_finite() && self.certifies_lazily() {
                        EdgeStatus::Valid
                    } else {
                        match self.certify_path(u, stop) {
                            EdgeStatus::Valid => self.certify(u, v, stop),
                            // `u` was cut out of the tree; the searches restart.
                            EdgeStatus::Invalid => return,
                            EdgeStatus::Unknown => {
                                self.queue_forward(edge);
                                return;
                            }
                        }
                    };
                    match status {
                        EdgeStatus::Valid => self.rewire(v, u, edge.distance, stop),
                        EdgeStatus::Invalid => self.invalid_edge(u, v, (g_u, edge.cost, h_v), stop),
                        EdgeStatus::Unknown => self.queue_forward(edge),
                    }
                }
            }
            EdgeStatus::Invalid => self.invalid_edge(u, v, (g_u, edge.cost, h_v), stop),
            // The termination condition fired mid-check: keep the edge (and its progress).
            EdgeStatus::Unknown => self.queue_forward(edge),
        }
    }

    /// The whitelisted edge `u — v` is invalid after all: if the lazy path went through it,
    /// repair the reverse search.
    fn invalid_edge(
        &mut self,
        u: u32,
        v: u32,
        (g_u, cost, h_v): (f64, f64, f64),
        stop: &SolveStop<'_>,
    ) {
        let tag = self.reverse_tag;
        let x = self.graph.vertex(u);
        let y = self.graph.vertex(v);
        if x.reverse_parent(tag) == v {
            // The lazy path u → v → … → goal: ŝ_adm = g(u) + ĉ(u, v) + ĥ(v); the reverse
            // branch from u down is wrong.
            self.repair_lazy_path((g_u, cost, h_v), u, stop);
        } else if y.reverse_parent(tag) == u {
            // The edge hangs below u in the reverse tree, so u's own lazy path does not use
            // it: ŝ_adm = g(u) + ĥ(u) (the authors' form), not g(u) + ĉ + ĥ(v) = g(u) + 2ĉ +
            // ĥ(u); the reverse branch from v down is wrong.
            let h_u = x.h(tag);
            self.repair_lazy_path((g_u, 0.0, h_u), v, stop);
        }
    }

    /// Certifies the whitelisted edge `u — v` (before it joins the forward tree, or when a
    /// solution's path first uses it: `solution_certification.rs`), on the grid
    /// [`Parameters::certification`](crate::Parameters) times finer than the check step
    /// (at once `Valid` without certification or if done before). A failure blacklists the
    /// edge; a stop mid-way leaves it uncertified (a later call starts over).
    pub(crate) fn certify(&mut self, u: u32, v: u32, stop: &SolveStop<'_>) -> EdgeStatus {
        let factor = self.parameters.certification.unwrap_or(1);
        // An edge shorter than the step has no grid points and perhaps no record yet.
        let record = self.graph.edge(u, v).unwrap_or(EdgeRecord {
            progress: EdgeProgress::UNTESTED,
            status: EdgeStatus::Valid,
            certified: false,
        });
        if factor <= 1 || record.certified {
            return EdgeStatus::Valid;
        }
        let (a, b) = (self.graph.state(u), self.graph.state(v));
        let status = self
            .checker
            .certify(&self.space, &self.validity, a, b, factor, stop);
        match status {
            EdgeStatus::Valid => self.graph.store_edge(
                u,
                v,
                EdgeRecord {
                    certified: true,
                    ..record
                },
            ),
            EdgeStatus::Invalid => self.graph.store_edge(
                u,
                v,
                EdgeRecord {
                    progress: EdgeProgress::FOUND_INVALID,
                    status: EdgeStatus::Invalid,
                    certified: false,
                },
            ),
            EdgeStatus::Unknown => {}
        }
        status
    }

    /// Makes `u` the forward parent of `v` through an edge of true cost `cost`, propagates the
    /// new cost-to-come through `v`'s subtree, records improved solutions and expands `v`.
    fn rewire(&mut self, v: u32, u: u32, cost: f64, stop: &SolveStop<'_>) {
        self.graph.set_forward_parent(v, u, cost);
        // Propagate to the subtree (iteratively; reuse the scratch stack).
        let mut stack = std::mem::take(&mut self.scratch);
        stack.clear();
        let mut child = self.graph.vertex(v).first_child;
        while child != NONE {
            stack.push(child);
            child = self.graph.vertex(child).next_sibling;
        }
        let batch = self.graph.tag;
        while let Some(d) = stack.pop() {
            let parent = self.graph.vertex(d).parent;
            let g = self.graph.vertex(parent).g + self.graph.vertex(d).parent_cost;
            self.graph.vertex_mut(d).g = g;
            let mut child = self.graph.vertex(d).first_child;
            while child != NONE {
                stack.push(child);
                child = self.graph.vertex(child).next_sibling;
            }
            if self.graph.vertex(d).is_goal() {
                self.solution_candidates.push(d);
            } else if self.graph.vertex(d).forward_expanded == batch {
                self.refresh_outgoing(d);
            }
        }
        self.scratch = stack;
        let reached_goal = self.graph.vertex(v).is_goal();
        if reached_goal {
            self.solution_candidates.push(v);
        }
        self.settle_solutions(stop);
        // A solution's certification may have cut `v` out of the tree again.
        if !reached_goal && self.graph.vertex(v).g.is_finite() {
            self.expand_forward(v, u, stop);
        }
    }

    /// Re-keys the queued forward edges out of `d` after its cost-to-come decreased.
    fn refresh_outgoing(&mut self, d: u32) {
        let x = self.graph.vertex(d);
        // Without lists, the caller's test (expanded in this batch) is the one that counts.
        let listless = self.listless();
        if !listless && x.neighbours_tag != self.graph.tag {
            return;
        }
        let len = if listless {
            0
        } else {
            x.neighbours_len as usize
        };
        // With lazy successors, one edge of the list is queued, and perhaps none yet.
        let listed = if self.lazy_successors() {
            self.refresh_successor(d);
            0
        } else {
            len
        };
        let (graph, rule) = (&self.graph, self.key_rule());
        for i in 0..listed {
            let n = graph.neighbour(d, i);
            let edge = ForwardEdge {
                source: d,
                target: n.id,
                hint: i as u32,
                cost: n.cost,
                distance: n.distance,
            };
            self.forward
                .update(d, n.id, forward_keys(graph, rule, &edge));
        }
        self.collect_tree_extras(d, len, true);
        for j in 0..self.extras.len() {
            let w = self.extras[j];
            let (cost, distance) = self.edge_geometry(d, w, NONE);
            let edge = ForwardEdge {
                source: d,
                target: w,
                hint: NONE,
                cost,
                distance,
            };
            let keys = forward_keys(&self.graph, self.key_rule(), &edge);
            self.forward.update(d, w, keys);
        }
    }

    /// The lazy path had an invalid edge `x_s → x_t` (spec §3.3), the reverse-tree edge above
    /// `branch`: tell the sampler (MIT*'s estimated informed set) while no solution exists,
    /// refine the sparse checks, and restart the reverse search and re-key the forward queue —
    /// or, where the reverse search is repaired in place (AIT*), search the branch again.
    fn repair_lazy_path(
        &mut self,
        (g_source, edge_estimate, h_target): (f64, f64, f64),
        branch: u32,
        stop: &dyn Stop,
    ) {
        if !self.best_cost.is_finite() {
            self.sampler.observe_invalid_lazy_edge(LazyPathFailure {
                cost_to_come: g_source,
                edge_estimate,
                cost_to_go: h_target,
            });
        }
        self.checker.refine();
        if self.repairs_reverse() {
            self.counters.reverse_repairs += 1;
            self.repair_reverse_branch(branch, stop);
            return;
        }
        self.counters.reverse_restarts += 1;
        // The restart re-keys the whole forward queue (polled, resumed by the next iteration if
        // interrupted); after the deadline it waits for the next iteration altogether.
        if stop.should_stop() {
            self.reverse_restart_pending = true;
        } else {
            self.restart_reverse(stop);
        }
        if let Some(observer) = self.observer.as_mut() {
            observer.on_reverse_restart(&RestartEvent {
                restarts: self.counters.reverse_restarts,
                sparse_level: <E as EdgeChecker<S, Counted<V>>>::level(&self.checker),
                solved: self.best_cost.is_finite(),
            });
        }
    }
}
