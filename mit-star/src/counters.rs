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
    /// Of those, the points decided without a test ([`mit_star_validity::Preparation::AllValid`]).
    pub points_culled: u64,
    /// Edges certified on the finer grid (the informed-trees family: a solution's path's edges
    /// and the edges that move a vertex of the forward tree; every edge that joins the tree
    /// without [`lazy_certification`](crate::Parameters::lazy_certification)).
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
    /// States placed along the best path
    /// ([`solution_samples`](crate::Parameters::solution_samples)).
    pub solution_samples: u64,
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
    /// States the [`NearTerminals`](mit_star_samplers::NearTerminals) wrapper drew near the start or a
    /// goal.
    pub sampler_near_terminals: u64,
    /// Of those, the states drawn near the reverse search's frontier
    /// ([`Parameters::near_frontier`](crate::Parameters::near_frontier)).
    pub sampler_near_frontier: u64,
    /// Batches whose frontier came from the start's side of the graph rather than the reverse
    /// search's ([`Parameters::start_frontier`](crate::Parameters::start_frontier)).
    pub start_frontiers: u64,
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
    /// Sparse checks by edge length ([`mit_star_validity::LENGTH_BUCKET_BOUNDS`]).
    pub sparse_checks_by_length: [u64; 5],
    /// Grid points tested by sparse checks, by edge length.
    pub sparse_points_by_length: [u64; 5],
    /// Full checks by edge length.
    pub full_checks_by_length: [u64; 5],
    /// Grid points tested by full checks, by edge length.
    pub full_points_by_length: [u64; 5],
}

impl Counters {
    /// The work of two planners together (a planner wrapping another, as
    /// [`WarmStarted`](crate::WarmStarted)): every count summed, the graph sizes too (both
    /// planners hold their graphs); the estimated informed set's costs are `self`'s when it
    /// has them, else `other`'s.
    #[must_use]
    pub fn merged(mut self, other: &Self) -> Self {
        // Destructured in full, so that a new counter cannot be left out.
        let Self {
            iterations,
            batches,
            samples,
            samples_drawn,
            validity_checks,
            sparse_checks,
            full_checks,
            points_tested,
            points_culled,
            certifications,
            certification_failures,
            neighbour_queries,
            reverse_restarts,
            reverse_repairs,
            reverse_iterations,
            forward_iterations,
            pruned,
            solution_samples,
            vertices,
            edges,
            peak_vertices,
            peak_edges,
            sampler_checks,
            sampler_pre_valid,
            sampler_gaussian,
            sampler_bridge,
            sampler_near_terminals,
            sampler_near_frontier,
            start_frontiers,
            sampler_restarts,
            estimate_initial,
            estimate_final,
            estimate_expansions,
            estimate_batches,
            sparse_checks_by_length,
            sparse_points_by_length,
            full_checks_by_length,
            full_points_by_length,
        } = *other;
        self.iterations += iterations;
        self.batches += batches;
        self.samples += samples;
        self.samples_drawn += samples_drawn;
        self.validity_checks += validity_checks;
        self.sparse_checks += sparse_checks;
        self.full_checks += full_checks;
        self.points_tested += points_tested;
        self.points_culled += points_culled;
        self.certifications += certifications;
        self.certification_failures += certification_failures;
        self.neighbour_queries += neighbour_queries;
        self.reverse_restarts += reverse_restarts;
        self.reverse_repairs += reverse_repairs;
        self.reverse_iterations += reverse_iterations;
        self.forward_iterations += forward_iterations;
        self.pruned += pruned;
        self.solution_samples += solution_samples;
        self.vertices += vertices;
        self.edges += edges;
        self.peak_vertices += peak_vertices;
        self.peak_edges += peak_edges;
        self.sampler_checks += sampler_checks;
        self.sampler_pre_valid += sampler_pre_valid;
        self.sampler_gaussian += sampler_gaussian;
        self.sampler_bridge += sampler_bridge;
        self.sampler_near_terminals += sampler_near_terminals;
        self.sampler_near_frontier += sampler_near_frontier;
        self.start_frontiers += start_frontiers;
        self.sampler_restarts += sampler_restarts;
        self.estimate_expansions += estimate_expansions;
        self.estimate_batches += estimate_batches;
        self.estimate_initial = self.estimate_initial.or(estimate_initial);
        self.estimate_final = self.estimate_final.or(estimate_final);
        for (mine, theirs) in self
            .sparse_checks_by_length
            .iter_mut()
            .zip(sparse_checks_by_length)
        {
            *mine += theirs;
        }
        for (mine, theirs) in self
            .sparse_points_by_length
            .iter_mut()
            .zip(sparse_points_by_length)
        {
            *mine += theirs;
        }
        for (mine, theirs) in self
            .full_checks_by_length
            .iter_mut()
            .zip(full_checks_by_length)
        {
            *mine += theirs;
        }
        for (mine, theirs) in self
            .full_points_by_length
            .iter_mut()
            .zip(full_points_by_length)
        {
            *mine += theirs;
        }
        self
    }

    /// These counters with the work the parts counted themselves: the edge checker's checks
    /// and certifications, the validity checker's state checks and the sampler's draws,
    /// branches and estimate.
    pub(crate) fn with_parts(
        mut self,
        edges: mit_star_validity::EdgeCounters,
        validity_checks: u64,
        sampler: &mit_star_samplers::SamplerCounters,
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
        self.sampler_near_frontier = sampler.near_frontier;
        self.sampler_restarts = sampler.repairs_failed;
        self.estimate_initial = sampler.estimate_initial;
        self.estimate_final = sampler.estimate_current;
        self.estimate_expansions = sampler.estimate_expansions;
        self.estimate_batches = sampler.estimate_batches;
        self
    }
}

/// How many integer counts [`Counters::counts`] lists.
pub const COUNT_NAMES_LEN: usize = 52;

/// The name of every integer count, as [`Counters::counts`] lists them: the field's name, and
/// for the per-length arrays the field's name and the bucket's index
/// (`sparse_checks_by_length_0` … `_4`, buckets of [`mit_star_validity::LENGTH_BUCKET_LABELS`]).
/// The same names key Python's `counters()` dictionary, `runs.jsonl`'s counters (arrays
/// there), the columns of `runs.csv` and `plan`'s listing.
pub const COUNT_NAMES: [&str; COUNT_NAMES_LEN] = [
    "iterations",
    "batches",
    "samples",
    "samples_drawn",
    "validity_checks",
    "sparse_checks",
    "full_checks",
    "points_tested",
    "points_culled",
    "certifications",
    "certification_failures",
    "neighbour_queries",
    "reverse_restarts",
    "reverse_repairs",
    "reverse_iterations",
    "forward_iterations",
    "pruned",
    "solution_samples",
    "vertices",
    "edges",
    "peak_vertices",
    "peak_edges",
    "sampler_checks",
    "sampler_pre_valid",
    "sampler_gaussian",
    "sampler_bridge",
    "sampler_near_terminals",
    "sampler_near_frontier",
    "start_frontiers",
    "sampler_restarts",
    "estimate_expansions",
    "estimate_batches",
    "sparse_checks_by_length_0",
    "sparse_checks_by_length_1",
    "sparse_checks_by_length_2",
    "sparse_checks_by_length_3",
    "sparse_checks_by_length_4",
    "sparse_points_by_length_0",
    "sparse_points_by_length_1",
    "sparse_points_by_length_2",
    "sparse_points_by_length_3",
    "sparse_points_by_length_4",
    "full_checks_by_length_0",
    "full_checks_by_length_1",
    "full_checks_by_length_2",
    "full_checks_by_length_3",
    "full_checks_by_length_4",
    "full_points_by_length_0",
    "full_points_by_length_1",
    "full_points_by_length_2",
    "full_points_by_length_3",
    "full_points_by_length_4",
];

/// The names of the real-valued counters, as [`Counters::reals`] lists them.
pub const REAL_NAMES: [&str; 2] = ["estimate_initial", "estimate_final"];

impl Counters {
    /// Every integer count with its name ([`COUNT_NAMES`]), in the struct's order, each
    /// per-length array spread over its five buckets.
    #[must_use]
    pub fn counts(&self) -> [(&'static str, u64); COUNT_NAMES_LEN] {
        // Destructured in full, so that a new counter cannot be left out.
        let Self {
            iterations,
            batches,
            samples,
            samples_drawn,
            validity_checks,
            sparse_checks,
            full_checks,
            points_tested,
            points_culled,
            certifications,
            certification_failures,
            neighbour_queries,
            reverse_restarts,
            reverse_repairs,
            reverse_iterations,
            forward_iterations,
            pruned,
            solution_samples,
            vertices,
            edges,
            peak_vertices,
            peak_edges,
            sampler_checks,
            sampler_pre_valid,
            sampler_gaussian,
            sampler_bridge,
            sampler_near_terminals,
            sampler_near_frontier,
            start_frontiers,
            sampler_restarts,
            estimate_expansions,
            estimate_batches,
            sparse_checks_by_length,
            sparse_points_by_length,
            full_checks_by_length,
            full_points_by_length,
            estimate_initial,
            estimate_final,
        } = *self;
        let _ = (estimate_initial, estimate_final);
        let scalars = [
            iterations,
            batches,
            samples,
            samples_drawn,
            validity_checks,
            sparse_checks,
            full_checks,
            points_tested,
            points_culled,
            certifications,
            certification_failures,
            neighbour_queries,
            reverse_restarts,
            reverse_repairs,
            reverse_iterations,
            forward_iterations,
            pruned,
            solution_samples,
            vertices,
            edges,
            peak_vertices,
            peak_edges,
            sampler_checks,
            sampler_pre_valid,
            sampler_gaussian,
            sampler_bridge,
            sampler_near_terminals,
            sampler_near_frontier,
            start_frontiers,
            sampler_restarts,
            estimate_expansions,
            estimate_batches,
        ];
        let mut values = [0; COUNT_NAMES_LEN];
        values[..scalars.len()].copy_from_slice(&scalars);
        let arrays = [
            sparse_checks_by_length,
            sparse_points_by_length,
            full_checks_by_length,
            full_points_by_length,
        ];
        for (i, value) in arrays.iter().flatten().enumerate() {
            values[scalars.len() + i] = *value;
        }
        let mut out = [("", 0); COUNT_NAMES_LEN];
        for (slot, (name, value)) in out.iter_mut().zip(COUNT_NAMES.iter().zip(values)) {
            *slot = (name, value);
        }
        out
    }

    /// The real-valued counters with their names ([`REAL_NAMES`]); `None` where not measured.
    #[must_use]
    pub fn reals(&self) -> [(&'static str, Option<f64>); 2] {
        [
            (REAL_NAMES[0], self.estimate_initial),
            (REAL_NAMES[1], self.estimate_final),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn merged_sums_counts_and_keeps_the_first_estimate() {
        let a = Counters {
            iterations: 3,
            vertices: 10,
            full_checks_by_length: [1, 2, 3, 4, 5],
            estimate_initial: Some(2.0),
            ..Counters::default()
        };
        let b = Counters {
            iterations: 4,
            vertices: 5,
            full_checks_by_length: [1, 1, 1, 1, 1],
            estimate_initial: Some(9.0),
            estimate_final: Some(3.0),
            ..Counters::default()
        };
        let m = a.merged(&b);
        assert_eq!(m.iterations, 7);
        assert_eq!(m.vertices, 15);
        assert_eq!(m.full_checks_by_length, [2, 3, 4, 5, 6]);
        assert_eq!(m.estimate_initial, Some(2.0));
        assert_eq!(m.estimate_final, Some(3.0));
        assert_eq!(Counters::default().merged(&b), b);
    }
    #[test]
    fn the_named_counts_are_the_serialised_fields_with_arrays_spread() {
        let mut c = Counters {
            estimate_initial: Some(2.5),
            ..Counters::default()
        };
        // Distinct values everywhere: a misplaced name would pair with the wrong value.
        let mut next = 1;
        let json = serde_json::to_value(c).unwrap();
        let mut expected = std::collections::BTreeMap::new();
        for (key, value) in json.as_object().unwrap() {
            match value {
                serde_json::Value::Array(items) => {
                    for i in 0..items.len() {
                        expected.insert(format!("{key}_{i}"), 0);
                    }
                }
                serde_json::Value::Number(_) if !REAL_NAMES.contains(&key.as_str()) => {
                    expected.insert(key.clone(), 0);
                }
                _ => assert!(REAL_NAMES.contains(&key.as_str()), "{key}"),
            }
        }
        let names: std::collections::BTreeSet<&str> = COUNT_NAMES.iter().copied().collect();
        assert_eq!(names.len(), COUNT_NAMES_LEN, "names repeat");
        assert_eq!(
            names,
            expected.keys().map(String::as_str).collect(),
            "COUNT_NAMES against the serialised fields"
        );
        for name in [
            "iterations",
            "solution_samples",
            "peak_edges",
            "estimate_batches",
        ] {
            let mut v = serde_json::to_value(c).unwrap();
            v[name] = serde_json::json!(next);
            c = serde_json::from_value(v).unwrap();
            next += 1;
        }
        let mut v = serde_json::to_value(c).unwrap();
        v["full_points_by_length"] = serde_json::json!([0, 0, 0, 7, 0]);
        c = serde_json::from_value(v).unwrap();
        let counts: std::collections::BTreeMap<_, _> = c.counts().into_iter().collect();
        assert_eq!(counts["iterations"], 1);
        assert_eq!(counts["solution_samples"], 2);
        assert_eq!(counts["peak_edges"], 3);
        assert_eq!(counts["estimate_batches"], 4);
        assert_eq!(counts["full_points_by_length_3"], 7);
        assert_eq!(counts.values().sum::<u64>(), 17);
        assert_eq!(
            c.reals(),
            [("estimate_initial", Some(2.5)), ("estimate_final", None)]
        );
    }
}
