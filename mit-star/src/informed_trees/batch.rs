//! Adding a batch of samples — EIT*'s "improve approximation" (spec §3.4): prune, sample under
//! the current bound, reconnect, restart both searches.

use mit_star_heuristics::Heuristic;
use mit_star_samplers::{CostBound, SampleError, Sampler};
use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::{Counted, EdgeChecker, StateValidity};

use crate::graph::{NONE, Neighbourhood, Pruning};
use crate::informed_trees::NeighbourRule;
use crate::informed_trees::eit::Eit;
use crate::informed_trees::guidance::{Guidance, ReverseSearch};
use crate::informed_trees::{BatchDensity, Connectivity};
use crate::{BatchEvent, Connection, VertexKind};

/// Samples of a batch made visible to neighbour queries (and indexed) at a time.
const INDEX_CHUNK: usize = 4096;

/// The most coordinate bytes committed at a time (fewer samples a chunk in high dimensions).
/// A commit copies the samples into fresh memory (the nearest-neighbour buffer, the recent
/// states' pages) whose page faults cost microseconds each under a hypervisor; in R^1000 one
/// commit of a 100-sample batch took 0.6–1.8 ms without polling the deadline.
const COMMIT_BYTES: usize = 64 * 1024;

/// Samples committed at a time in `dimension` coordinates: [`INDEX_CHUNK`], or fewer so that
/// their coordinates take at most [`COMMIT_BYTES`].
pub(crate) fn commit_chunk(dimension: usize) -> usize {
    (COMMIT_BYTES / (dimension.max(1) * size_of::<f64>())).clamp(1, INDEX_CHUNK)
}

/// The most vertices a batch reserves room for before it samples (see `add_batch`).
const RESERVE_AHEAD: usize = 1 << 16;

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
    /// The bound samples are drawn under: the best solution's cost if there is one; otherwise
    /// unbounded (an estimated-informed-set sampler substitutes its estimate).
    pub(crate) fn sampling_bound(&self) -> CostBound {
        if self.best_cost.is_finite() {
            CostBound::Solution(self.best_cost)
        } else {
            CostBound::Unbounded
        }
    }

    /// Sets the current batch's neighbourhood — `k`, `r` or a complete graph, as the
    /// [`NeighbourRule`] decides it — for the current number of vertices `q` (start and goals
    /// included), counting only the vertices that stand for the sampler's coverage of its set:
    /// states drawn near the terminals ([`NearTerminals`](mit_star_samplers::NearTerminals)) are left
    /// out, so the rules keep the rewire factor `η` they are given for the wrapped sampler's
    /// density. Returns `k`, `r`, or `∞` for a complete graph (the observer's
    /// [`BatchEvent::connection`]).
    pub(crate) fn update_neighbourhood(&mut self) -> f64 {
        let density = BatchDensity {
            vertices: self.graph.density_count(),
            dimension: self.space.dimension(),
            rewire_factor: self.parameters.rewire_factor,
            connection: self.parameters.connection.unwrap_or(Connection::KNearest),
            neighbour_cap: self.parameters.neighbour_cap,
        };
        let measure = || {
            let bound = self.sampling_bound();
            self.sampler
                .sampled_measure(&self.space, bound)
                .min(self.space.measure())
        };
        match self.neighbour_rule.connectivity(&density, &measure) {
            Connectivity::Nearest(k) => {
                self.graph.set_neighbourhood(Neighbourhood::Nearest(k));
                k as f64
            }
            Connectivity::Radius { radius, cap } => {
                self.graph.set_neighbourhood(Neighbourhood::Radius(radius));
                self.graph.set_neighbour_cap(cap);
                radius
            }
            Connectivity::Complete => {
                // Every vertex within an infinite radius: the cached lists, their incremental
                // updates and the searches need nothing else.
                self.graph
                    .set_neighbourhood(Neighbourhood::Radius(f64::INFINITY));
                self.graph.set_neighbour_cap(usize::MAX);
                f64::INFINITY
            }
        }
    }

    /// Resets the sparse level, clears the forward queue and restarts both searches: the
    /// reverse search from the goals, the forward search from the start.
    pub(crate) fn restart_searches(&mut self, stop: &crate::termination::SolveStop<'_>) {
        self.restart_pending = false;
        self.reverse_restart_pending = false;
        // Deferred expansions would only have queued edges these restarts discard.
        self.deferred.clear();
        self.checker.reset();
        self.forward.clear();
        self.graph.compact_outside();
        self.restart_reverse(stop);
        self.expand_forward(self.start_id, NONE, stop);
    }

    /// Neither search can improve on this batch: with the a-priori guidance and a solution,
    /// first search the batch once more with the final, least inflation `1 + s/q` (ABIT*; BIT*'s
    /// `s = 0` needs no second search), else add a batch.
    pub(crate) fn search_exhausted(&mut self, stop: &crate::termination::SolveStop<'_>) {
        if G::REVERSE == ReverseSearch::None && self.best_cost.is_finite() && !self.final_search {
            self.final_search = true;
            let q = self.graph.vertex_count() as f64;
            let inflation = 1.0 + self.parameters.inflation_scaling.unwrap_or(0.0) / q;
            if inflation < self.inflation {
                self.inflation = inflation;
                if stop.should_stop() {
                    self.restart_pending = true;
                } else {
                    self.restart_searches(stop);
                }
                return;
            }
        }
        self.add_batch(stop);
    }

    /// Adds a batch of samples (spec §3.4).
    pub(crate) fn add_batch(&mut self, stop: &crate::termination::SolveStop<'_>) {
        let solved = self.best_cost.is_finite();
        // 1. MIT*: the estimated informed set expands if a batch in it found no solution.
        self.sampler.observe_batch_end(solved);
        self.send_frontier(solved, stop);
        // 2. Prune with the true solution cost only.
        let mut pruned = 0;
        // Pruning polls the termination condition. If it fires before or during the scan,
        // pruning waits for the next batch (the bound it would prune with is kept); if it
        // fires during the removal, the next iteration finishes it and samples the batch.
        if self.parameters.pruning
            && solved
            && self.best_cost < self.last_prune_cost
            && !stop.should_stop()
        {
            let protected: Vec<u32> = self.solution_vertices().iter().map(|v| v.0).collect();
            match self.graph.prune(self.best_cost, &protected, stop) {
                Pruning::Done(removed) => pruned = self.record_pruning(removed),
                Pruning::Abandoned => {}
                Pruning::Interrupted => return,
            }
        }
        self.sample_batch(pruned, stop);
    }

    /// Finishes a pruning interrupted during its removal, then samples the batch it began.
    pub(crate) fn continue_batch(&mut self, stop: &crate::termination::SolveStop<'_>) {
        if let Pruning::Done(removed) = self.graph.continue_pruning(stop) {
            let pruned = self.record_pruning(removed);
            self.sample_batch(pruned, stop);
        }
    }

    /// Books a completed pruning that removed `removed` vertices; returns that number.
    fn record_pruning(&mut self, removed: usize) -> usize {
        self.last_prune_cost = self.best_cost;
        self.counters.pruned += removed as u64;
        removed
    }

    /// Steps 3 and 4 of a batch: samples it and makes it visible to the searches (`pruned`
    /// vertices were removed before it, for the observer).
    fn sample_batch(&mut self, pruned: usize, stop: &crate::termination::SolveStop<'_>) {
        // 3. Sample under the current bound (reported as the sampler applies it: an
        //    estimated-informed-set sampler replaces "unbounded" by its estimate).
        let bound = self.sampling_bound();
        let effective = match (bound, self.sampler.estimated_cost()) {
            (CostBound::Unbounded, Some(estimate)) => CostBound::Estimated(estimate),
            _ => bound,
        };
        // MIT*'s batches under an estimated informed set may have a size of their own.
        let size = match effective {
            CostBound::Estimated(_) => self
                .parameters
                .eis_batch_size
                .unwrap_or_else(|| self.parameters.samples_per_batch()),
            _ => self.parameters.samples_per_batch(),
        };
        let size = size.max(self.parameters.grown_batch(self.graph.vertex_count()));
        let mut ids = std::mem::take(&mut self.batch_ids);
        ids.clear();
        // Grow the per-vertex arrays once, here, rather than by copies mid-batch — but by at
        // most `RESERVE_AHEAD` vertices: reserving for a batch of a million costs milliseconds
        // on its own, and an array that grows beyond by doubling copies no more than the
        // vertices added so far (time already spent, within the budget's 1 %).
        let ahead = size.min(RESERVE_AHEAD);
        ids.reserve(ahead);
        self.graph.reserve(ahead);
        // Once a solution exists, part of the batch lies along its path.
        let along = self.solution_sample_count(size);
        let placed = self.add_solution_samples(along, stop, &mut ids);
        let mut sample = std::mem::take(&mut self.sample);
        let mut committed = 0;
        let chunk = commit_chunk(self.space.dimension());
        for _ in placed..size {
            match self
                .sampler
                .sample(&self.space, &self.validity, bound, stop, &mut sample)
            {
                Ok(()) => {
                    let mut vertex = self.new_vertex(VertexKind::Sample, &sample);
                    vertex.origin = self.sampler.last_origin();
                    ids.push(self.graph.add_vertex(&sample, vertex));
                    // Large batches are committed and indexed as they grow (nearest-neighbour
                    // trees built in polled steps), not in one unpolled piece at the end.
                    if ids.len() - committed >= chunk {
                        self.graph.commit(&ids[committed..]);
                        self.graph.index_pending(stop);
                        committed = ids.len();
                    }
                }
                // Only a solution's informed set can be empty for good (its cost is the
                // straight-line cost); an estimate is no bound.
                Err(SampleError::EmptySet { .. }) if matches!(bound, CostBound::Solution(_)) => {
                    self.exhausted = true;
                    break;
                }
                Err(_) => break,
            }
        }
        self.sample = sample;
        self.counters.samples += ids.len() as u64;
        // 4. Reconnect: new vertices visible, caches dropped, k or r for the new q.
        self.graph.commit(&ids[committed..]);
        let samples = ids.len();
        self.batch_ids = ids;
        let connection = self.update_neighbourhood();
        // The a-priori guidance's factors for the new batch (ABIT*; 1 for BIT*).
        let q = self.graph.vertex_count() as f64;
        self.inflation = self.parameters.initial_inflation.unwrap_or(1.0);
        self.truncation = 1.0 + self.parameters.truncation_scaling.unwrap_or(0.0) / q;
        self.final_search = false;
        // 5. Reset the sparse level, restart the reverse search, re-seed the forward search —
        //    in the next iteration if the termination condition fired meanwhile (the restart
        //    queries the neighbours of the goals and the start over every new sample).
        if stop.should_stop() {
            self.restart_pending = true;
        } else {
            self.restart_searches(stop);
        }
        self.counters.batches += 1;
        let vertices = self.graph.vertex_count() as u64;
        let edges = self.graph.edge_count() as u64;
        self.counters.peak_vertices = self.counters.peak_vertices.max(vertices);
        self.counters.peak_edges = self.counters.peak_edges.max(edges);
        if let Some(observer) = self.observer.as_mut() {
            observer.on_batch(&BatchEvent {
                batch: self.counters.batches,
                samples,
                pruned,
                vertices: vertices as usize,
                bound: effective,
                connection,
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn commits_hold_at_most_their_bytes_of_coordinates() {
        assert_eq!(
            commit_chunk(2),
            INDEX_CHUNK,
            "low dimensions: the index chunk"
        );
        assert_eq!(commit_chunk(1000), 8);
        assert_eq!(commit_chunk(10_000_000), 1, "at least one sample");
        for dimension in [7, 32, 333, 4096] {
            assert!(commit_chunk(dimension) * dimension * size_of::<f64>() <= COMMIT_BYTES);
        }
    }
}
