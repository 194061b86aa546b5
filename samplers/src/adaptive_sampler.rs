//! [`AdaptiveSampler`]: MIT*'s obstacle-based adaptive sampler (spec §4, paper Alg. 2).

use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::StateValidity;

use crate::sampling_steps::{GaussianPartners, InformedDraws, Partner, SegmentsAhead};
use crate::{
    CostBound, GaussianStep, InformedSet, SampleError, SampleOrigin, Sampler, SamplerCounters,
    SamplerError, SegmentSearch,
};

/// MIT*'s adaptive sampler: uniform informed samples, repaired near obstacles.
///
/// 1. Draw `x_pre` uniformly from the informed set of the bound the planner passes: the whole
///    space when [`CostBound::Unbounded`] (the paper's case 1), the estimated informed set under
///    [`CostBound::Estimated`] (case 2), the informed set of `c_best` under
///    [`CostBound::Solution`] (case 4).
/// 2. If `x_pre` is valid, return it.
/// 3. Else draw `x_temp ~ N(x_pre, δ² I)` clamped into the bounds; if it is valid, return it.
///    (Candidates are drawn and checked a batch of the checker at a time, and so are the
///    `x_temp` of a batch's invalid ones: each drawn from its own `x_pre`, the same in law.)
/// 4. Else search the segment `x_pre → x_temp` in bisection order (midpoint, quarter points, …)
///    for at most `bridge_checks` points and return the first valid one. (Where the checker's
///    batch holds two searches' points or more, sixteen AVX-512 lanes against eight points,
///    the segments of a batch's failed repairs are searched in one call: the same states.)
/// 5. Else start over.
///
/// A repaired state (`x_temp` or a segment point) must lie inside the informed set of the
/// bound: states outside it are skipped without a validity check (counted as rejected), so the
/// search returns the first point that is both inside the set and valid. Defaults: `δ = 0.1 ·`
/// the maximum extent, 8 bridge checks.
///
/// ```
/// use mit_star_samplers::{AdaptiveSampler, CostBound, Sampler};
/// use mit_star_spaces::{Never, RealVectorSpace};
/// use mit_star_validity::{AxisBox, StateValidity, World};
///
/// let space = RealVectorSpace::cube(2, 0.0, 1.0)?;
/// let world = World::new(vec![0.0; 2], vec![1.0; 2])
///     .with_obstacle(AxisBox::cube(vec![0.5, 0.5], 0.6))?;
/// let mut sampler = AdaptiveSampler::new(&space, &[0.1, 0.1], &[[0.9, 0.9]], 1)?
///     .with_std_dev(0.05)?
///     .with_bridge_checks(4)?;
/// let mut x = [0.0; 2];
/// sampler.sample(&space, &world, CostBound::Solution(1.5), &Never, &mut x)?;
/// assert!(world.is_valid(&x));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct AdaptiveSampler {
    draws: InformedDraws,
    step: GaussianStep,
    search: SegmentSearch,
    /// The `x_temp` of a batch's invalid candidates, drawn and checked together.
    partners: GaussianPartners,
    /// The segment searches of a batch's failed repairs, made together where the checker's
    /// batch holds several.
    segments: SegmentsAhead,
    /// Scratch: `x_pre` once found invalid, and `x_temp`.
    pre: Vec<f64>,
    temp: Vec<f64>,
}

impl AdaptiveSampler {
    /// Default maximum number of segment points tested per repair (spec §9).
    pub const DEFAULT_BRIDGE_CHECKS: usize = 8;

    /// An adaptive sampler for `start` and `goals` in `space`, seeded with `seed`, with the
    /// default `δ` and bridge checks.
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
            search: SegmentSearch::new(Self::DEFAULT_BRIDGE_CHECKS)?,
            partners: GaussianPartners::default(),
            segments: SegmentsAhead::default(),
            pre: vec![0.0; n],
            temp: vec![0.0; n],
        })
    }

    /// Sets the standard deviation `δ` of `x_temp`.
    ///
    /// # Errors
    /// [`SamplerError::NotPositive`] if `std_dev` is not finite and positive.
    pub fn with_std_dev(mut self, std_dev: f64) -> Result<Self, SamplerError> {
        self.step = GaussianStep::new(std_dev)?;
        Ok(self)
    }

    /// Sets the maximum number of segment points tested per repair.
    ///
    /// # Errors
    /// [`SamplerError::BridgeChecks`] unless `1 ≤ checks ≤ SegmentSearch::MAX_CHECKS`.
    pub fn with_bridge_checks(mut self, checks: usize) -> Result<Self, SamplerError> {
        self.search = SegmentSearch::new(checks)?;
        Ok(self)
    }

    /// The standard deviation `δ`.
    pub fn std_dev(&self) -> f64 {
        self.step.std_dev()
    }

    /// The maximum number of segment points tested per repair.
    pub fn bridge_checks(&self) -> usize {
        self.search.checks()
    }

    /// The informed-set geometry this sampler draws from.
    pub fn informed_set(&self) -> &InformedSet {
        &self.draws.set
    }
}

impl<S, V> Sampler<S, V> for AdaptiveSampler
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
        // `draw` polls `stop` before every candidate, the segment search before every point.
        loop {
            if self.draws.draw_checked(space, validity, cost, stop, out)? {
                self.draws.own_counters().pre_valid += 1;
                self.draws.origin = SampleOrigin::Drawn;
                return self.draws.returned();
            }
            self.pre.copy_from_slice(out);
            // `x_temp`: drawn with the batch's other invalid candidates' and checked with
            // them, or alone where no batch holds `x_pre`.
            let parts = (&self.step, space, validity);
            let (valid, batched) =
                match self
                    .draws
                    .partner(&mut self.partners, parts, cost, &mut self.temp)
                {
                    Some(Partner::Checked(valid)) => (valid, true),
                    Some(Partner::Outside) => {
                        self.draws.reject();
                        (false, true)
                    }
                    Some(Partner::None) | None => {
                        self.draws
                            .perturb(&self.step, space, &self.pre, &mut self.temp);
                        if self.draws.set.contains(space, cost, &self.temp) {
                            (self.draws.check(validity, &self.temp), false)
                        } else {
                            self.draws.reject();
                            (false, false)
                        }
                    }
                };
            if valid {
                out.copy_from_slice(&self.temp);
                self.draws.own_counters().gaussian_valid += 1;
                self.draws.origin = SampleOrigin::Gaussian;
                return self.draws.returned();
            }
            // The segment's search: with the batch's other failed repairs' where the checker
            // takes several at once (the same outcome), else alone.
            let ahead = if batched {
                let held = (&self.partners, &mut self.segments);
                self.draws
                    .search_ahead(held, &self.search, space, validity, cost, stop, out)?
            } else {
                None
            };
            let segment = (self.pre.as_slice(), self.temp.as_slice());
            let found = match ahead {
                Some(found) => found,
                None => self.draws.search_segment(
                    &self.search,
                    space,
                    validity,
                    segment,
                    cost,
                    stop,
                    out,
                )?,
            };
            if found {
                self.draws.own_counters().bridge_found += 1;
                self.draws.origin = SampleOrigin::Bridge;
                return Ok(());
            }
            self.draws.own_counters().repairs_failed += 1;
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

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star_spaces::{Never, RealVectorSpace};
    use mit_star_validity::{AxisBox, StateValidity, World};

    #[test]
    fn parameters_are_validated_once() {
        let space = RealVectorSpace::cube(2, 0.0, 1.0).unwrap();
        let sampler = AdaptiveSampler::new(&space, &[0.1, 0.1], &[[0.9, 0.9]], 0).unwrap();
        assert!((sampler.std_dev() - 0.1 * 2f64.sqrt()).abs() < 1e-12);
        assert_eq!(sampler.bridge_checks(), 8);
        assert!(matches!(
            sampler.clone().with_std_dev(-0.1),
            Err(SamplerError::NotPositive { .. })
        ));
        assert!(matches!(
            sampler.clone().with_bridge_checks(0),
            Err(SamplerError::BridgeChecks { got: 0, .. })
        ));
        let tuned = sampler
            .with_std_dev(0.02)
            .unwrap()
            .with_bridge_checks(3)
            .unwrap();
        assert_eq!((tuned.std_dev(), tuned.bridge_checks()), (0.02, 3));
    }

    /// The unit square, all blocked but for a horizontal slot 0.02 wide around `y = 0.5`.
    fn slot_world() -> World {
        World::new(vec![0.0; 2], vec![1.0; 2])
            .with_obstacle(AxisBox::new(vec![0.5, 0.245], vec![1.0, 0.49]))
            .unwrap()
            .with_obstacle(AxisBox::new(vec![0.5, 0.755], vec![1.0, 0.49]))
            .unwrap()
    }

    #[test]
    fn repairs_find_a_narrow_slot_far_more_often_than_uniform_draws() {
        // Everything is blocked but a horizontal slot 0.02 wide: uniform sampling needs about
        // 50 draws per valid state. The adaptive sampler repairs invalid draws whose Gaussian
        // neighbour or bridge segment reaches the slot, so it needs far fewer `x_pre` draws.
        let space = RealVectorSpace::cube(2, 0.0, 1.0).unwrap();
        let world = slot_world();
        let mut adaptive = AdaptiveSampler::new(&space, &[0.05, 0.5], &[[0.95, 0.5]], 4).unwrap();
        let mut uniform = crate::UniformSampler::new(4);
        let mut x = [0.0; 2];
        let samples = 300;
        let mut tally = [0u64; 3];
        for _ in 0..samples {
            adaptive
                .sample(&space, &world, CostBound::Unbounded, &Never, &mut x)
                .unwrap();
            match Sampler::<RealVectorSpace, World>::last_origin(&adaptive) {
                SampleOrigin::Drawn => tally[0] += 1,
                SampleOrigin::Gaussian => tally[1] += 1,
                SampleOrigin::Bridge => tally[2] += 1,
                SampleOrigin::NearTerminal | SampleOrigin::Offered | SampleOrigin::NearSolution => {
                    panic!("the adaptive sampler draws only Drawn, Gaussian and Bridge states")
                }
            }
            assert!(
                world.is_valid(&x) && (x[1] - 0.5).abs() <= 0.01 + 1e-9,
                "{x:?}"
            );
            uniform
                .sample(&space, &world, CostBound::Unbounded, &Never, &mut x)
                .unwrap();
        }
        let c = Sampler::<RealVectorSpace, World>::counters(&adaptive);
        assert_eq!(tally, [c.pre_valid, c.gaussian_valid, c.bridge_found]);
        assert!(c.gaussian_valid > 0 && c.bridge_found > 0, "{c:?}");
        assert!(c.validity_checks >= samples);
        let adaptive_draws = adaptive.informed_set().counters().drawn;
        let uniform_draws = Sampler::<RealVectorSpace, World>::counters(&uniform).drawn;
        assert_eq!(
            Sampler::<RealVectorSpace, World>::counters(&adaptive).returned,
            samples
        );
        // Uniform: ≈ 50 per sample (binomial, ±3 %); adaptive: ≈ 5–12.
        assert!(uniform_draws > 40 * samples, "uniform {uniform_draws}");
        assert!(
            adaptive_draws * 3 < uniform_draws,
            "adaptive {adaptive_draws}, uniform {uniform_draws}"
        );
    }

    /// A world's checker answering batches of a given width, counting its batched calls.
    struct Wide<'a> {
        world: &'a World,
        width: usize,
        calls: std::cell::Cell<usize>,
    }

    impl StateValidity for Wide<'_> {
        fn is_valid(&self, s: &[f64]) -> bool {
            self.world.is_valid(s)
        }
        fn batch_width(&self) -> usize {
            self.width
        }
        fn are_valid(&self, states: &[f64], dimension: usize, valid: &mut [bool]) {
            self.calls.set(self.calls.get() + 1);
            for (s, v) in states.chunks_exact(dimension).zip(valid) {
                *v = self.world.is_valid(s);
            }
        }
    }

    #[test]
    fn searching_a_batchs_segments_together_returns_the_same_states() {
        // Sixteen lanes search two or more failed repairs' segments per call, eight lanes one:
        // the same states, from the same origins, and the same work, in fewer calls.
        let space = RealVectorSpace::cube(2, 0.0, 1.0).unwrap();
        let world = slot_world();
        let run = |width: usize| {
            let checker = Wide {
                world: &world,
                width,
                calls: std::cell::Cell::new(0),
            };
            let mut sampler =
                AdaptiveSampler::new(&space, &[0.05, 0.5], &[[0.95, 0.5]], 9).unwrap();
            let mut x = [0.0; 2];
            let mut seen = Vec::new();
            for k in 0..400_u32 {
                // A bound that tightens now and then drops the batches held.
                let bound = if k < 200 {
                    CostBound::Unbounded
                } else {
                    CostBound::Solution(1.6 - f64::from(k) * 1e-3)
                };
                sampler
                    .sample(&space, &checker, bound, &Never, &mut x)
                    .unwrap();
                seen.push((
                    x,
                    Sampler::<RealVectorSpace, Wide<'_>>::last_origin(&sampler),
                ));
            }
            let counters = Sampler::<RealVectorSpace, Wide<'_>>::counters(&sampler);
            (seen, counters, checker.calls.get())
        };
        let (narrow, narrow_counters, narrow_calls) = run(8);
        let (wide, wide_counters, wide_calls) = run(16);
        assert_eq!(narrow, wide);
        assert!(wide_counters.bridge_found > 20, "{wide_counters:?}");
        assert_eq!(narrow_counters.returned, wide_counters.returned);
        assert_eq!(narrow_counters.bridge_found, wide_counters.bridge_found);
        assert_eq!(narrow_counters.repairs_failed, wide_counters.repairs_failed);
        // Searches ahead of a dropped batch are made for nothing: never fewer checks.
        assert!(wide_counters.validity_checks >= narrow_counters.validity_checks);
        assert!(
            wide_calls * 10 < narrow_calls * 9,
            "{wide_calls} calls against {narrow_calls}"
        );
    }
}
