//! The [`Sampler`] trait, the [`CostBound`] a planner hands it, and [`SampleError`].

use spaces::{StateSpace, Stop};
use thiserror::Error;
use validity::StateValidity;

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
    #[error("the informed set is empty: cost bound {bound} is not above the minimum cost {minimum}")]
    EmptySet {
        /// The bound that was asked for.
        bound: f64,
        /// The straight-line lower bound of any solution.
        minimum: f64,
    },
}

/// Counters of sampling work, for benchmarks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct SamplerCounters {
    /// Valid states returned.
    pub returned: u64,
    /// Raw candidate states drawn (before validity and set tests).
    pub drawn: u64,
    /// Candidates rejected because they fell outside the bounds or the informed set.
    pub rejected: u64,
}

/// Draws valid states for a planner (OMPL's `ValidStateSampler`, made informed).
///
/// A sampler is seeded and owns its random generator: the same seed gives the same sequence of
/// states. It is told the current [`CostBound`] on every call and returns a state that is valid
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
    /// `bound` is empty.
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

    /// Restarts the random sequence from `seed`.
    fn reseed(&mut self, seed: u64);

    /// Work counters so far.
    fn counters(&self) -> SamplerCounters;
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
}
