//! [`InformedSampler`]: valid states uniform over the informed set of the cost bound.

use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::StateValidity;

use crate::sampling_steps::InformedDraws;
use crate::{CostBound, InformedSet, SampleError, Sampler, SamplerCounters, SamplerError};

/// Direct informed sampling (Gammell et al.; spec §7): states uniform over the informed set of
/// the bound, intersected with the bounds, invalid ones rejected.
///
/// Under [`CostBound::Solution`] this is Informed RRT*'s / BIT*'s sampler; under
/// [`CostBound::Estimated`] it is MIT*'s estimated-informed-set sampler (paper Alg. 4); under
/// [`CostBound::Unbounded`] it samples the whole space. Where direct sampling does not apply
/// (non-Euclidean metrics, sets larger than the space) the [`InformedSet`] falls back to
/// rejection sampling.
///
/// ```
/// use mit_star_samplers::{CostBound, InformedSampler, Sampler};
/// use mit_star_spaces::{Never, RealVectorSpace};
/// use mit_star_validity::AllValid;
///
/// let space = RealVectorSpace::cube(2, -1.0, 1.0)?;
/// let mut sampler = InformedSampler::new(&space, &[-0.5, 0.0], &[[0.5, 0.0]], 42)?;
/// let mut x = [0.0; 2];
/// sampler.sample(&space, &AllValid, CostBound::Estimated(1.2), &Never, &mut x)?;
/// let cost = mit_star_spaces::euclidean_distance(&x, &[-0.5, 0.0]) + mit_star_spaces::euclidean_distance(&x, &[0.5, 0.0]);
/// assert!(cost < 1.2);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct InformedSampler {
    draws: InformedDraws,
}

impl InformedSampler {
    /// An informed sampler for `start` and `goals` in `space`, seeded with `seed`.
    ///
    /// # Errors
    /// As [`InformedSet::new`].
    pub fn new<S, G>(space: &S, start: &[f64], goals: &[G], seed: u64) -> Result<Self, SamplerError>
    where
        S: StateSpace + ?Sized,
        G: AsRef<[f64]>,
    {
        Ok(Self {
            draws: InformedDraws::new(space, start, goals, seed)?,
        })
    }

    /// The informed-set geometry this sampler draws from.
    pub fn informed_set(&self) -> &InformedSet {
        &self.draws.set
    }
}

impl<S, V> Sampler<S, V> for InformedSampler
where
    S: StateSpace + ?Sized,
    V: StateValidity + ?Sized,
{
    fn sample(
        &mut self,
        space: &S,
        validity: &V,
        bound: CostBound,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<(), SampleError> {
        // `draw` polls `stop` before every candidate, so this loop needs no poll of its own.
        loop {
            if self
                .draws
                .draw_checked(space, validity, bound.cost(), stop, out)?
            {
                return self.draws.returned();
            }
        }
    }

    fn sampled_measure(&self, space: &S, bound: CostBound) -> f64 {
        self.draws.measure(space, bound)
    }

    fn reseed(&mut self, seed: u64) {
        self.draws.reseed(seed);
    }

    fn counters(&self) -> SamplerCounters {
        self.draws.counters()
    }
}
