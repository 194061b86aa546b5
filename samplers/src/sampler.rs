//! The [`Sampler`] trait, the [`CostBound`] a planner hands it, and [`SampleError`].

use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::StateValidity;
use thiserror::Error;

/// The cost bound under which a planner asks for samples.
///
/// Informed samplers draw from the set of states that could lie on a path cheaper than the bound
/// (a prolate hyperspheroid for path length); uninformed samplers ignore it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CostBound {
    /// No solution and no estimate: sample the whole space.
    Unbounded,
    /// MIT*'s estimated informed set: the bound is an estimate `s̃_est`, not a solution cost.
    Estimated(f64),
    /// The cost `c_best` of the best valid solution.
    Solution(f64),
}

impl CostBound {
    /// The bound as a number, `None` when unbounded.
    pub fn cost(&self) -> Option<f64> {
        match *self {
            Self::Unbounded => None,
            Self::Estimated(c) | Self::Solution(c) => Some(c),
        }
    }
}

/// Why a sampler returned no state.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum SampleError {
    /// The stop condition fired before a valid state was found.
    #[error("sampling stopped by the termination condition")]
    Stopped,
    /// The informed set is empty: the bound is not above the smallest possible cost.
    #[error(
        "the informed set is empty: cost bound {bound} is not above the minimum cost {minimum}"
    )]
    EmptySet {
        /// The bound that was asked for.
        bound: f64,
        /// The straight-line lower bound of any solution.
        minimum: f64,
    },
    /// The space or the output buffer does not have the dimension the sampler was built for.
    #[error("the sampler was built for dimension {expected}, but was given {got} coordinates")]
    DimensionMismatch {
        /// The dimension the sampler was built for.
        expected: usize,
        /// The dimension of the space or the length of the output buffer.
        got: usize,
    },
}

/// Counters of sampling work, for benchmarks and for seeing inside the parts: every sampler
/// counts its draws and validity checks; the [`AdaptiveSampler`](crate::AdaptiveSampler) counts
/// which branch of the paper's Alg. 2 produced each state; the [`Estimated`](crate::Estimated)
/// wrapper reports its estimated informed set.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SamplerCounters {
    /// Valid states returned.
    pub returned: u64,
    /// Raw candidate states drawn (before validity and set tests).
    pub drawn: u64,
    /// Candidates rejected because they fell outside the bounds or the informed set.
    pub rejected: u64,
    /// State validity checks the sampler made.
    pub validity_checks: u64,
    /// Adaptive sampler: states returned because the uniform draw `x_pre` was valid.
    pub pre_valid: u64,
    /// Adaptive sampler: states returned because the Gaussian neighbour `x_temp` was valid.
    pub gaussian_valid: u64,
    /// Adaptive sampler: states returned from the segment `x_pre → x_temp` (`x_crit`).
    pub bridge_found: u64,
    /// Adaptive sampler: repairs that failed (`x_temp` and every segment point invalid or
    /// outside the set), after which it starts over from a new `x_pre`.
    pub repairs_failed: u64,
    /// [`NearTerminals`](crate::NearTerminals): states returned from near the start or a goal,
    /// or a state of the planner's frontier.
    pub near_terminals: u64,
    /// [`NearTerminals`](crate::NearTerminals): of those, the states returned from near a
    /// state of the planner's frontier ([`Sampler::observe_frontier`]).
    pub near_frontier: u64,
    /// Estimated informed set: its first cost `s̃_est = ŝ_adm · e_γ` (`None`: never created).
    pub estimate_initial: Option<f64>,
    /// Estimated informed set: its cost now, after every expansion.
    pub estimate_current: Option<f64>,
    /// Estimated informed set: expansions `s̃_est ← s̃_est · e_γ`.
    pub estimate_expansions: u64,
    /// Estimated informed set: batches with at least one state drawn under the estimate.
    pub estimate_batches: u64,
}

/// Which step of a sampler produced a state: for pictures and counters of what the obstacle-
/// based samplers do.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub enum SampleOrigin {
    /// Drawn (uniformly, or from an informed set) and valid as drawn: the adaptive sampler's
    /// `x_pre`, and every state of the uniform and informed samplers.
    #[default]
    Drawn,
    /// A Gaussian neighbour of an invalid draw: the adaptive sampler's `x_temp`, the Gaussian
    /// sampler's valid partner.
    Gaussian,
    /// A point between two states found on a segment: the adaptive sampler's `x_crit`, the
    /// bridge sampler's midpoint.
    Bridge,
    /// Drawn near the start or a goal by the [`NearTerminals`](crate::NearTerminals) wrapper.
    NearTerminal,
    /// Not drawn: a state of a path given to the planner from outside (a warm start's first
    /// path, a simplified solution), kept as a vertex so the search can improve on that path
    /// locally.
    Offered,
    /// Not drawn by a sampler: a state the planner placed along its best path (a shortcut
    /// between two of its vertices, perhaps displaced), strung along one path as offered
    /// states are.
    NearSolution,
}

impl SampleOrigin {
    /// `true` if a state of this origin counts in the sample number `q` of a planner's
    /// connection rules `k(q)` and `r(q)`: the states a sampler draws to cover its set —
    /// uniform and informed draws, and the obstacle-based samplers' states, which stand in for
    /// draws of the set as in MIT* — but not [`NearTerminal`](Self::NearTerminal) states,
    /// clustered around the start and the goals, nor [`Offered`](Self::Offered) and
    /// [`NearSolution`](Self::NearSolution) ones, strung along one path: any of them would
    /// make the set look more densely sampled than it is (and the radius too small for
    /// asymptotic optimality).
    ///
    /// ```
    /// use mit_star_samplers::SampleOrigin;
    /// assert!(SampleOrigin::Drawn.counts_toward_density());
    /// assert!(SampleOrigin::Gaussian.counts_toward_density());
    /// assert!(!SampleOrigin::NearTerminal.counts_toward_density());
    /// assert!(!SampleOrigin::Offered.counts_toward_density());
    /// assert!(!SampleOrigin::NearSolution.counts_toward_density());
    /// ```
    pub fn counts_toward_density(self) -> bool {
        !matches!(
            self,
            Self::NearTerminal | Self::Offered | Self::NearSolution
        )
    }
}

/// Draws valid states for a planner (OMPL's `ValidStateSampler`, made informed).
///
/// A sampler is seeded and owns its random generator: the same seed gives the same sequence of
/// states. Samplers that check what they draw may draw a checker's
/// [batch](StateValidity::batch_width) of candidates ahead and decide them in one call
/// ([`StateValidity::are_valid`]), so the sequence depends on the checker's batch width too
/// (its law does not). It is told the current [`CostBound`] on every call and returns a state that is valid
/// (per `validity`), inside the space's bounds, and — for informed samplers — inside the informed
/// set of the bound. It polls `stop` in every loop and returns [`SampleError::Stopped`] rather
/// than loop forever.
///
/// Generic over the space and the validity checker, object safe for fixed ones:
/// `Box<dyn Sampler<RealVectorSpace, World>>` works for configurations chosen at run time.
pub trait Sampler<S: StateSpace + ?Sized, V: StateValidity + ?Sized> {
    /// Writes one valid state drawn under `bound` into `out` (length = the space's dimension).
    ///
    /// # Errors
    /// [`SampleError::Stopped`] if `stop` fired; [`SampleError::EmptySet`] if the informed set of
    /// `bound` is empty; [`SampleError::DimensionMismatch`] if `space` or `out` does not have the
    /// dimension the sampler was built for.
    fn sample(
        &mut self,
        space: &S,
        validity: &V,
        bound: CostBound,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<(), SampleError>;

    /// Lebesgue measure of the set this sampler draws from under `bound` (at most the space's
    /// measure). Planners use it for the r-disc connection radius.
    fn sampled_measure(&self, space: &S, bound: CostBound) -> f64;

    /// Returns the sampler to its freshly built state with a new seed: the random sequence
    /// restarts from `seed` and anything learned from planner feedback (an estimated informed
    /// set) is forgotten. Planners call it from `clear()` so no state leaks between queries.
    fn reseed(&mut self, seed: u64);

    /// Work counters so far.
    fn counters(&self) -> SamplerCounters;

    /// Planner feedback: the forward search found an edge of the lazy (reverse-tree) path
    /// invalid while no valid solution exists. Samplers that estimate an informed set from
    /// failed lazy paths (MIT*'s [`Estimated`](crate::Estimated) wrapper) react; others ignore it.
    fn observe_invalid_lazy_edge(&mut self, _failure: LazyPathFailure) {}

    /// Planner feedback: a batch of samples has been searched and the planner is about to add
    /// the next one; `solved` tells whether a valid solution exists.
    fn observe_batch_end(&mut self, _solved: bool) {}

    /// Planner feedback, at the end of a batch: the states its reverse search reached farthest
    /// from the goals (by cost-to-go), `dimension` coordinates each, farthest first — the edge
    /// of what the goals are known to connect to — or an empty slice once a solution exists.
    /// Samplers that draw near the terminals ([`NearTerminals`](crate::NearTerminals)) draw
    /// near these too; others ignore it.
    fn observe_frontier(&mut self, _states: &[f64]) {}

    /// `true` if the set this sampler draws from has just changed and it asks the planner for a
    /// batch drawn in the new set before searching further (MIT*'s spec §3.1, step 1).
    fn wants_batch(&self) -> bool {
        false
    }

    /// The estimated solution cost the sampler currently uses as its bound when the planner has
    /// no solution (`None` if it has none).
    fn estimated_cost(&self) -> Option<f64> {
        None
    }

    /// Which step produced the state the last successful [`sample`](Self::sample) returned.
    fn last_origin(&self) -> SampleOrigin {
        SampleOrigin::Drawn
    }
}

/// Where a lazy path failed: the forward edge `x_s → x_t` found invalid by a full check.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LazyPathFailure {
    /// Cost-to-come `g(x_s)` of the edge's source in the forward tree.
    pub cost_to_come: f64,
    /// Admissible edge-cost estimate `ĉ(x_s, x_t)`.
    pub edge_estimate: f64,
    /// Admissible cost-to-go `ĥ(x_t)` of the edge's target in the reverse tree.
    pub cost_to_go: f64,
}

impl<S, V, T> Sampler<S, V> for Box<T>
where
    S: StateSpace + ?Sized,
    V: StateValidity + ?Sized,
    T: Sampler<S, V> + ?Sized,
{
    fn sample(
        &mut self,
        space: &S,
        validity: &V,
        bound: CostBound,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<(), SampleError> {
        (**self).sample(space, validity, bound, stop, out)
    }
    fn sampled_measure(&self, space: &S, bound: CostBound) -> f64 {
        (**self).sampled_measure(space, bound)
    }
    fn reseed(&mut self, seed: u64) {
        (**self).reseed(seed);
    }
    fn counters(&self) -> SamplerCounters {
        (**self).counters()
    }
    fn observe_invalid_lazy_edge(&mut self, failure: LazyPathFailure) {
        (**self).observe_invalid_lazy_edge(failure);
    }
    fn observe_batch_end(&mut self, solved: bool) {
        (**self).observe_batch_end(solved);
    }
    fn observe_frontier(&mut self, states: &[f64]) {
        (**self).observe_frontier(states);
    }
    fn wants_batch(&self) -> bool {
        (**self).wants_batch()
    }
    fn estimated_cost(&self) -> Option<f64> {
        (**self).estimated_cost()
    }
    fn last_origin(&self) -> SampleOrigin {
        (**self).last_origin()
    }
}
