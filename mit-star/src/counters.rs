//! [`Counters`]: how much work a planner did, for benchmarks.

use serde::{Deserialize, Serialize};

/// Work counters of a planner since it was built or last [cleared](crate::Planner::clear).
///
/// Shared by every planner of the framework; a planner leaves at zero what it does not do.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
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
    /// Grid points tested by edge checks (certification included).
    pub points_tested: u64,
    /// Edges certified on the finer grid before joining the forward tree.
    pub certifications: u64,
    /// Certifications that found the edge invalid between its grid points.
    pub certification_failures: u64,
    /// Nearest-neighbour queries.
    pub neighbour_queries: u64,
    /// Restarts of the reverse search after an invalid lazy edge.
    pub reverse_restarts: u64,
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
}

impl Counters {
    /// These counters with the work the parts counted themselves: the edge checker's checks
    /// and certifications, the validity checker's state checks and the sampler's draws.
    pub(crate) fn with_parts(
        mut self,
        edges: validity::EdgeCounters,
        validity_checks: u64,
        samples_drawn: u64,
    ) -> Self {
        self.sparse_checks = edges.sparse_checks;
        self.full_checks = edges.full_checks;
        self.points_tested = edges.points_tested;
        self.certifications = edges.certifications;
        self.certification_failures = edges.certification_failures;
        self.validity_checks = validity_checks;
        self.samples_drawn = samples_drawn;
        self
    }
}
