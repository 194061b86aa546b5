//! [`GaussianSampler`]: Boor et al.'s Gaussian sampling, restricted to the informed set.

use rand::SeedableRng;
use spaces::{SeededRng, StateSpace, Stop};
use validity::StateValidity;

use crate::{
    CostBound, GaussianStep, InformedSet, SampleError, Sampler, SamplerCounters, SamplerError,
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
/// use samplers::{CostBound, GaussianSampler, Sampler};
/// use spaces::{Never, RealVectorSpace};
/// use validity::{AxisBox, StateValidity, World};
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
    set: InformedSet,
    step: GaussianStep,
    rng: SeededRng,
    counters: SamplerCounters,
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
        let set = InformedSet::new(space, start, goals)?;
        Ok(Self {
            neighbour: vec![0.0; set.dimension()],
            set,
            step: GaussianStep::for_space(space)?,
            rng: SeededRng::seed_from_u64(seed),
            counters: SamplerCounters::default(),
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
        &self.set
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
            self.set.draw(space, &mut self.rng, cost, stop, out)?;
            self.step
                .perturb(space, &mut self.rng, out, &mut self.neighbour);
            self.counters.drawn += 1;
            match (validity.is_valid(out), validity.is_valid(&self.neighbour)) {
                (true, false) => {
                    self.counters.returned += 1;
                    return Ok(());
                }
                (false, true) => {
                    if self.set.contains(space, cost, &self.neighbour) {
                        out.copy_from_slice(&self.neighbour);
                        self.counters.returned += 1;
                        return Ok(());
                    }
                    self.counters.rejected += 1;
                }
                _ => {}
            }
        }
    }

    fn sampled_measure(&self, space: &S, bound: CostBound) -> f64 {
        self.set.measure(space, bound.cost())
    }

    fn reseed(&mut self, seed: u64) {
        self.rng = SeededRng::seed_from_u64(seed);
    }

    fn counters(&self) -> SamplerCounters {
        self.set.with_own(self.counters)
    }
}
