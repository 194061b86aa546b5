//! [`BridgeSampler`]: Hsu et al.'s bridge test, restricted to the informed set.

use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::StateValidity;

use crate::sampling_steps::InformedDraws;
use crate::{
    CostBound, GaussianStep, InformedSet, SampleError, SampleOrigin, Sampler, SamplerCounters,
    SamplerError, SegmentSearch,
};

/// The bridge test (Hsu, Jiang, Reif & Sun 2003; OMPL's `BridgeTestValidStateSampler`):
/// concentrates samples in narrow passages.
///
/// Draw `x1` uniformly from the informed set of the bound; if it is invalid, draw
/// `x2 ~ N(x1, σ² I)` clamped into the bounds; if that is invalid too, the midpoint of the
/// "bridge" `x1 → x2` is returned when it is valid and inside the informed set. Otherwise draw
/// again. `σ` defaults to 10 % of the space's maximum extent.
///
/// It returns nothing unless two obstacles leave a gap narrower than about `σ`; the stop
/// condition ends the search there.
///
/// ```
/// use mit_star_samplers::{BridgeSampler, CostBound, Sampler};
/// use mit_star_spaces::{Never, RealVectorSpace};
/// use mit_star_validity::{AxisBox, StateValidity, World};
///
/// // Two walls with a thin slot between them at x = 0.5.
/// let space = RealVectorSpace::cube(2, 0.0, 1.0)?;
/// let world = World::new(vec![0.0; 2], vec![1.0; 2])
///     .with_obstacle(AxisBox::new(vec![0.25, 0.5], vec![0.48, 1.0]))?
///     .with_obstacle(AxisBox::new(vec![0.75, 0.5], vec![0.48, 1.0]))?;
/// let mut sampler = BridgeSampler::new(&space, &[0.0, 0.0], &[[1.0, 1.0]], 5)?;
/// let mut x = [0.0; 2];
/// sampler.sample(&space, &world, CostBound::Unbounded, &Never, &mut x)?;
/// assert!(world.is_valid(&x));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct BridgeSampler {
    draws: InformedDraws,
    step: GaussianStep,
    /// Scratch: the bridge's ends `x1` and `x2`.
    first: Vec<f64>,
    second: Vec<f64>,
}

impl BridgeSampler {
    /// A bridge-test sampler for `start` and `goals` in `space`, seeded with `seed`, with
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
        let n = draws.set.dimension();
        Ok(Self {
            draws,
            step: GaussianStep::for_space(space)?,
            first: vec![0.0; n],
            second: vec![0.0; n],
        })
    }

    /// Sets the standard deviation `σ` of the bridge's second end.
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

impl<S, V> Sampler<S, V> for BridgeSampler
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
        self.draws.set.check_dimensions(space, out)?;
        let cost = bound.cost();
        let midpoint = SegmentSearch::midpoint();
        // `draw` polls `stop` before every candidate.
        loop {
            if self
                .draws
                .draw_checked(space, validity, cost, stop, &mut self.first)?
            {
                continue;
            }
            self.draws
                .perturb(&self.step, space, &self.first, &mut self.second);
            if self.draws.check(validity, &self.second) {
                continue;
            }
            let bridge = (self.first.as_slice(), self.second.as_slice());
            if self
                .draws
                .search_segment(&midpoint, space, validity, bridge, cost, stop, out)?
            {
                return Ok(());
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
        SampleOrigin::Bridge
    }
}
