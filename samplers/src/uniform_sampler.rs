//! [`UniformSampler`]: valid states uniform over the whole space.

use mit_star_spaces::{SeededRng, StateSpace, Stop};
use mit_star_validity::StateValidity;
use rand::SeedableRng;

use crate::sampling_steps::Lookahead;
use crate::{CostBound, HaltonSequence, SampleError, Sampler, SamplerCounters};

/// Uniform samples of the whole space, invalid ones rejected; the cost bound is ignored.
/// Independent random draws ([`new`](Self::new)), a Halton sequence shifted by the seed
/// ([`halton`](Self::halton)) or the plain one ([`unshifted_halton`](Self::unshifted_halton)).
///
/// The uninformed baseline (OMPL's `UniformValidStateSampler`). Its
/// [`sampled_measure`](Sampler::sampled_measure) is always the space's measure.
///
/// ```
/// use mit_star_samplers::{CostBound, Sampler, UniformSampler};
/// use mit_star_spaces::{Never, RealVectorSpace};
/// use mit_star_validity::{AxisBox, StateValidity, World};
///
/// let space = RealVectorSpace::cube(2, 0.0, 1.0)?;
/// let world = World::new(vec![0.0; 2], vec![1.0; 2])
///     .with_obstacle(AxisBox::cube(vec![0.5, 0.5], 0.5))?;
/// let mut sampler = UniformSampler::new(7);
/// let mut x = [0.0; 2];
/// sampler.sample(&space, &world, CostBound::Solution(0.1), &Never, &mut x)?;
/// assert!(world.is_valid(&x));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct UniformSampler {
    rng: SeededRng,
    seed: u64,
    /// Where the draws come from.
    draws: Draws,
    /// That sequence, made for the space's dimension at the first draw.
    sequence: Option<HaltonSequence>,
    counters: SamplerCounters,
    /// Draws checked ahead, a batch of the checker at a time.
    ahead: Lookahead,
}

/// Where a [`UniformSampler`]'s draws come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Draws {
    /// Independent random draws from the seeded generator.
    Random,
    /// A [`HaltonSequence`] shifted by the seed.
    ShiftedHalton,
    /// The plain [`HaltonSequence::unshifted`].
    PlainHalton,
}

impl UniformSampler {
    /// A uniform sampler seeded with `seed`.
    pub fn new(seed: u64) -> Self {
        Self {
            rng: SeededRng::seed_from_u64(seed),
            seed,
            draws: Draws::Random,
            sequence: None,
            counters: SamplerCounters::default(),
            ahead: Lookahead::default(),
        }
    }

    /// A sampler of the same states drawn from a [`HaltonSequence`] shifted by `seed` instead
    /// of independent random draws: low-discrepancy coverage of the space (VAMP's
    /// RRT-Connect samples this way).
    pub fn halton(seed: u64) -> Self {
        Self {
            draws: Draws::ShiftedHalton,
            ..Self::new(seed)
        }
    }

    /// A sampler drawing from the plain [`HaltonSequence::unshifted`], the same points for
    /// every seed (`seed` still seeds what else the sampler draws): VAMP's RRT-Connect samples
    /// this way, from the sequence restarted before each problem.
    pub fn unshifted_halton(seed: u64) -> Self {
        Self {
            draws: Draws::PlainHalton,
            ..Self::new(seed)
        }
    }

    /// Writes one draw (random or Halton) scaled to the space's bounds into `out`.
    fn draw<S: StateSpace + ?Sized>(&mut self, space: &S, out: &mut [f64]) {
        if self.draws == Draws::Random {
            space.sample_uniform(&mut self.rng, out);
            return;
        }
        let d = space.dimension();
        let halton = match &mut self.sequence {
            Some(h) if h.dimension() == d => h,
            slot if self.draws == Draws::ShiftedHalton => {
                slot.insert(HaltonSequence::new(d, self.seed))
            }
            slot => slot.insert(HaltonSequence::unshifted(d)),
        };
        halton.next_point(out);
        for ((x, lo), hi) in out.iter_mut().zip(space.lower()).zip(space.upper()) {
            *x = lo + *x * (hi - lo);
        }
    }
}

impl UniformSampler {
    /// Writes one state drawn uniformly from the whole space into `out`, valid or not (OMPL's
    /// plain state sampler, as RRT-Connect uses it): a draw and no validity check, counted
    /// as such.
    ///
    /// # Errors
    /// [`SampleError::DimensionMismatch`] if `out` does not have the space's dimension.
    pub fn draw_any<S: StateSpace + ?Sized>(
        &mut self,
        space: &S,
        out: &mut [f64],
    ) -> Result<(), SampleError> {
        fits(space, out)?;
        self.draw(space, out);
        self.counters.drawn += 1;
        self.counters.returned += 1;
        Ok(())
    }
}

impl<S, V> Sampler<S, V> for UniformSampler
where
    S: StateSpace + ?Sized,
    V: StateValidity + ?Sized,
{
    fn sample(
        &mut self,
        space: &S,
        validity: &V,
        _bound: CostBound,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<(), SampleError> {
        fits(space, out)?;
        // Candidates are drawn and checked a batch of the checker at a time, each draw
        // polling `stop` first.
        let mut ahead = std::mem::take(&mut self.ahead);
        let mut checks = 0;
        let found = loop {
            let valid = ahead.next(validity, None, &mut checks, out, |x| {
                if stop.should_stop() {
                    return Err(SampleError::Stopped);
                }
                self.draw(space, x);
                self.counters.drawn += 1;
                Ok(())
            });
            match valid {
                Ok(false) => {}
                Ok(true) => break Ok(()),
                Err(error) => break Err(error),
            }
        };
        self.ahead = ahead;
        self.counters.validity_checks += checks;
        if found.is_ok() {
            self.counters.returned += 1;
        }
        found
    }

    fn sampled_measure(&self, space: &S, _bound: CostBound) -> f64 {
        space.measure()
    }

    fn reseed(&mut self, seed: u64) {
        self.rng = SeededRng::seed_from_u64(seed);
        self.seed = seed;
        self.sequence = None;
        self.ahead.clear();
    }

    fn counters(&self) -> SamplerCounters {
        self.counters
    }
}

/// [`SampleError::DimensionMismatch`] unless `out` has the space's dimension.
fn fits<S: StateSpace + ?Sized>(space: &S, out: &[f64]) -> Result<(), SampleError> {
    if out.len() == space.dimension() {
        Ok(())
    } else {
        Err(SampleError::DimensionMismatch {
            expected: space.dimension(),
            got: out.len(),
        })
    }
}
