//! [`Counters`]: how much work a planner did, for benchmarks.

use serde::{Deserialize, Serialize};

/// Work counters of a planner since it was built or last [cleared](crate::Planner::clear).
///
/// Shared by every planner of the framework; a planner leaves at zero what it does not do.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(default)]
pub struct Counters {
    /// Iterations of the planner's main loop.
    pub iterations: u64,
    /// Batches of samples added.
    pub batches: u64,
    /// Valid samples added to the graph.
    pub samples: u64,
    /// Raw candidates the sampler drew (before validity and informed-set tests).
    pub samples_drawn: u64,
    /// State validity checks, by every part (sampler and edge checks).
    pub validity_checks: u64,
    /// Sparse edge checks requested.
    pub sparse_checks: u64,
    /// Full edge checks requested.
    pub full_checks: u64,
    /// Grid points tested by edge checks (certification included), the points the validity
    /// checker's per-edge broad phase decided without a test included.
    pub points_tested: u64,
    /// Of those, the points decided without a test ([`validity::Preparation::AllValid`]).
    pub points_culled: u64,
    /// Edges certified on the finer grid before joining the forward tree.
    pub certifications: u64,
    /// Certifications that found the edge invalid between its grid points.
    pub certification_failures: u64,
    /// Nearest-neighbour queries.
    pub neighbour_queries: u64,
    /// Restarts of the reverse search after an invalid lazy edge.
    pub reverse_restarts: u64,
    /// In-place repairs of the reverse search after an invalid lazy edge (AIT*), instead of
    /// restarts.
    pub reverse_repairs: u64,
    /// Reverse-search iterations.
    pub reverse_iterations: u64,
    /// Forward-search iterations.
    pub forward_iterations: u64,
    /// Vertices removed by pruning.
    pub pruned: u64,
    /// Vertices in the graph now.
    pub vertices: u64,
    /// Stored (checked) edges now.
    pub edges: u64,
    /// Most vertices the graph held at once.
    pub peak_vertices: u64,
    /// Most stored edges the graph held at once.
    pub peak_edges: u64,
    /// State validity checks made by the sampler (part of `validity_checks`).
    pub sampler_checks: u64,
    /// Adaptive sampler: samples that were valid as drawn (`x_pre`).
    pub sampler_pre_valid: u64,
    /// Adaptive sampler: samples repaired by the Gaussian step (`x_temp` valid).
    pub sampler_gaussian: u64,
    /// Adaptive sampler: samples repaired on the segment `x_pre → x_temp` (`x_crit`).
    pub sampler_bridge: u64,
    /// States the [`NearTerminals`](samplers::NearTerminals) wrapper drew near the start or a
    /// goal.
    pub sampler_near_terminals: u64,
    /// Adaptive sampler: failed repairs, after which it drew a new `x_pre`.
    pub sampler_restarts: u64,
    /// Estimated informed set: the cost `s̃_est` it was created with (`None`: never created).
    pub estimate_initial: Option<f64>,
    /// Estimated informed set: its cost at the end, after every expansion.
    pub estimate_final: Option<f64>,
    /// Estimated informed set: expansions.
    pub estimate_expansions: u64,
    /// Estimated informed set: batches with samples drawn under it.
    pub estimate_batches: u64,
    /// Sparse checks by edge length ([`validity::LENGTH_BUCKET_BOUNDS`]).
    pub sparse_checks_by_length: [u64; 5],
    /// Grid points tested by sparse checks, by edge length.
    pub sparse_points_by_length: [u64; 5],
    /// Full checks by edge length.
    pub full_checks_by_length: [u64; 5],
    /// Grid points tested by full checks, by edge length.
    pub full_points_by_length: [u64; 5],
}

impl Counters {
    /// These counters with the work the parts counted themselves: the edge checker's checks
    /// and certifications, the validity checker's state checks and the sampler's draws,
    /// branches and estimate.
    pub(crate) fn with_parts(
        mut self,
        edges: validity::EdgeCounters,
        validity_checks: u64,
        sampler: &samplers::SamplerCounters,
    ) -> Self {
        self.sparse_checks = edges.sparse_checks;
        self.full_checks = edges.full_checks;
        self.points_tested = edges.points_tested;
        self.points_culled = edges.points_culled;
        self.certifications = edges.certifications;
        self.certification_failures = edges.certification_failures;
        self.sparse_checks_by_length = edges.by_length.sparse_checks;
        self.sparse_points_by_length = edges.by_length.sparse_points;
        self.full_checks_by_length = edges.by_length.full_checks;
        self.full_points_by_length = edges.by_length.full_points;
        self.validity_checks = validity_checks;
        self.samples_drawn = sampler.drawn;
        self.sampler_checks = sampler.validity_checks;
        self.sampler_pre_valid = sampler.pre_valid;
        self.sampler_gaussian = sampler.gaussian_valid;
        self.sampler_bridge = sampler.bridge_found;
        self.sampler_near_terminals = sampler.near_terminals;
        self.sampler_restarts = sampler.repairs_failed;
        self.estimate_initial = sampler.estimate_initial;
        self.estimate_final = sampler.estimate_current;
        self.estimate_expansions = sampler.estimate_expansions;
        self.estimate_batches = sampler.estimate_batches;
        self
    }
}
