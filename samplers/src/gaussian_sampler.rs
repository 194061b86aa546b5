//! [`GaussianSampler`]: Boor et al.'s Gaussian sampling, restricted to the informed set.

use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::StateValidity;

use crate::sampling_steps::InformedDraws;
use crate::{
    CostBound, GaussianStep, InformedSet, SampleError, SampleOrigin, Sampler, SamplerCounters,
    SamplerError,
};

/// Gaussian sampling (Boor, Overmars & van der Stappen 1999; OMPL's
/// `GaussianValidStateSampler`): concentrates samples near obstacle boundaries.
///
/// Draw `x1` uniformly from the informed set of the bound (the whole space when unbounded) and
/// `x2 ~ N(x1, σ² I)` clamped into the bounds. If exactly one of them is valid — and, for `x2`,
/// inside the informed set of the bound — return it; otherwise draw again. `σ` defaults to 10 %
/// of the space's maximum extent.
///
/// It returns nothing in regions without obstacles (both states valid); the stop condition ends
/// the search there.
///
/// ```
/// use mit_star_samplers::{CostBound, GaussianSampler, Sampler};
/// use mit_star_spaces::{Never, RealVectorSpace};
/// use mit_star_validity::{AxisBox, StateValidity, World};
///
/// let space = RealVectorSpace::cube(2, 0.0, 1.0)?;
/// let world = World::new(vec![0.0; 2], vec![1.0; 2])
///     .with_obstacle(AxisBox::cube(vec![0.5, 0.5], 0.4))?;
/// let mut sampler = GaussianSampler::new(&space, &[0.1, 0.1], &[[0.9, 0.9]], 3)?.with_std_dev(0.05)?;
/// let mut x = [0.0; 2];
/// sampler.sample(&space, &world, CostBound::Unbounded, &Never, &mut x)?;
/// assert!(world.is_valid(&x));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct GaussianSampler {
    draws: InformedDraws,
    step: GaussianStep,
    /// Scratch: the Gaussian neighbour `x2`.
    neighbour: Vec<f64>,
}

impl GaussianSampler {
    /// A Gaussian sampler for `start` and `goals` in `space`, seeded with `seed`, with
    /// `σ = 0.1 ·` the space's maximum extent.
    ///
    /// # Errors
    /// As [`InformedSet::new`] and [`GaussianStep::for_space`].
    pub fn new<S, G>(space: &S, start: &[f64], goals: &[G], seed: u64) -> Result<Self, SamplerError>
    where
        S: StateSpace + ?Sized,
        G: AsRef<[f64]>,
    {
        let draws = InformedDraws::new(space, start, goals, seed)?;
        Ok(Self {
            neighbour: vec![0.0; draws.set.dimension()],
            draws,
            step: GaussianStep::for_space(space)?,
        })
    }

    /// Sets the standard deviation `σ` of the neighbour.
    ///
    /// # Errors
    /// [`SamplerError::NotPositive`] if `std_dev` is not finite and positive.
    pub fn with_std_dev(mut self, std_dev: f64) -> Result<Self, SamplerError> {
        self.step = GaussianStep::new(std_dev)?;
        Ok(self)
    }

    /// The standard deviation `σ`.
    pub fn std_dev(&self) -> f64 {
        self.step.std_dev()
    }

    /// The informed-set geometry this sampler draws from.
    pub fn informed_set(&self) -> &InformedSet {
        &self.draws.set
    }
}

impl<S, V> Sampler<S, V> for GaussianSampler
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
        let cost = bound.cost();
        // `draw` polls `stop` before every candidate.
        loop {
            let here = self.draws.draw_checked(space, validity, cost, stop, out)?;
            self.draws
                .perturb(&self.step, space, out, &mut self.neighbour);
            let there = self.draws.check(validity, &self.neighbour);
            match (here, there) {
                (true, false) => {
                    self.draws.origin = SampleOrigin::Drawn;
                    return self.draws.returned();
                }
                (false, true) => {
                    if self.draws.set.contains(space, cost, &self.neighbour) {
                        out.copy_from_slice(&self.neighbour);
                        self.draws.origin = SampleOrigin::Gaussian;
                        return self.draws.returned();
                    }
                    self.draws.reject();
                }
                _ => {}
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

    fn last_origin(&self) -> SampleOrigin {
        self.draws.origin
    }
}
