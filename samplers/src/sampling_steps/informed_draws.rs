//! [`InformedDraws`]: what every informed sampler owns — the informed set, the seeded generator
//! and the work counters — and the steps they share.

use mit_star_spaces::{SeededRng, StateSpace, Stop};
use mit_star_validity::StateValidity;
use rand::SeedableRng;

use super::{GaussianPartners, Lookahead, Partner, PartnerDraw, SegmentsAhead};
use crate::{
    CostBound, GaussianStep, InformedSet, SampleError, SampleOrigin, SamplerCounters, SamplerError,
    SegmentSearch,
};

/// The informed set a sampler draws from, its seeded generator and its own counters (the set
/// counts its draws itself).
#[derive(Debug, Clone)]
pub(crate) struct InformedDraws {
    /// The informed-set geometry.
    pub(crate) set: InformedSet,
    rng: SeededRng,
    counters: SamplerCounters,
    /// Which step produced the last state returned (kept by samplers with several steps).
    pub(crate) origin: SampleOrigin,
    /// Candidates drawn and checked ahead ([`draw_checked`](Self::draw_checked)).
    ahead: Lookahead,
    /// The points of a segment search's batch ([`SegmentSearch::find`]).
    points: Vec<f64>,
}

impl InformedDraws {
    /// The informed set of `start` and `goals` in `space`, and a generator seeded with `seed`.
    ///
    /// # Errors
    /// As [`InformedSet::new`].
    pub(crate) fn new<S, G>(
        space: &S,
        start: &[f64],
        goals: &[G],
        seed: u64,
    ) -> Result<Self, SamplerError>
    where
        S: StateSpace + ?Sized,
        G: AsRef<[f64]>,
    {
        Ok(Self {
            set: InformedSet::new(space, start, goals)?,
            rng: SeededRng::seed_from_u64(seed),
            counters: SamplerCounters::default(),
            origin: SampleOrigin::Drawn,
            ahead: Lookahead::default(),
            points: Vec::new(),
        })
    }

    /// Draws `out` uniformly from the informed set of `cost` ([`InformedSet::draw`], which
    /// polls `stop`) and returns whether it is valid, counting the check: the candidates are
    /// drawn and checked a batch of `validity` at a time ([`Lookahead`]).
    ///
    /// # Errors
    /// As [`InformedSet::draw`].
    pub(crate) fn draw_checked<S, V>(
        &mut self,
        space: &S,
        validity: &V,
        cost: Option<f64>,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<bool, SampleError>
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        let Self {
            set,
            rng,
            counters,
            ahead,
            ..
        } = self;
        let checks = &mut counters.validity_checks;
        ahead.next(validity, cost, checks, out, |x| {
            set.draw(space, rng, cost, stop, x)
        })
    }

    /// Writes the next candidate of `draw` (given the generator; each counted as drawn) into
    /// `out` and returns whether it is valid, counting the check: as
    /// [`draw_checked`](Self::draw_checked), a batch of `validity` drawn and checked at a time.
    /// The candidates' law must not depend on anything that changes between the calls (or
    /// [`clear_ahead`](Self::clear_ahead) drops them when it does); their index in their batch
    /// is [`last_index`](Self::last_index).
    ///
    /// # Errors
    /// The first error of `draw`, as [`Lookahead::next`].
    pub(crate) fn next_checked<V: StateValidity + ?Sized>(
        &mut self,
        validity: &V,
        out: &mut [f64],
        mut draw: impl FnMut(&mut SeededRng, &mut [f64]) -> Result<(), SampleError>,
    ) -> Result<bool, SampleError> {
        let Self {
            rng,
            counters,
            ahead,
            ..
        } = self;
        let SamplerCounters {
            validity_checks,
            drawn,
            ..
        } = counters;
        ahead.next(validity, None, validity_checks, out, |x| {
            draw(rng, x)?;
            *drawn += 1;
            Ok(())
        })
    }

    /// The index, in the order of its batch's draws, of the candidate
    /// [`next_checked`](Self::next_checked) returned last.
    pub(crate) fn last_index(&self) -> usize {
        self.ahead.last_index()
    }

    /// Drops the candidates drawn ahead (what they were drawn from changed).
    pub(crate) fn clear_ahead(&mut self) {
        self.ahead.clear();
    }

    /// The Gaussian partner of the candidate [`draw_checked`](Self::draw_checked) returned
    /// last, drawn under `cost` with `step` ([`GaussianPartners::partner`]: the first call for
    /// a batch draws and checks the partners of its invalid candidates together), written
    /// into `out`; `None` where the batch does not hold it (then draw one with
    /// [`perturb`](Self::perturb)).
    pub(crate) fn partner<S, V>(
        &mut self,
        partners: &mut GaussianPartners,
        (step, space, validity): (&GaussianStep, &S, &V),
        cost: Option<f64>,
        out: &mut [f64],
    ) -> Option<Partner>
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        let Self {
            set,
            rng,
            counters,
            ahead,
            ..
        } = self;
        let draw = PartnerDraw {
            step,
            space,
            validity,
            set,
            cost,
            rng,
            counters,
        };
        partners.partner(ahead.batch(out.len()), ahead.last_index(), draw, out)
    }

    /// Writes a Gaussian neighbour of `from` into `to` and counts it as drawn.
    pub(crate) fn perturb<S: StateSpace + ?Sized>(
        &mut self,
        step: &GaussianStep,
        space: &S,
        from: &[f64],
        to: &mut [f64],
    ) {
        step.perturb(space, &mut self.rng, from, to);
        self.counters.drawn += 1;
    }

    /// Tests `x` with `validity`, counting the check.
    pub(crate) fn check<V: StateValidity + ?Sized>(&mut self, validity: &V, x: &[f64]) -> bool {
        self.counters.validity_checks += 1;
        validity.is_valid(x)
    }

    /// The seeded generator, for samplers that draw more than the set's states.
    pub(crate) fn rng(&mut self) -> &mut SeededRng {
        &mut self.rng
    }

    /// The sampler's own counters, without the set's draws.
    pub(crate) fn own(&self) -> SamplerCounters {
        self.counters
    }

    /// Mutable access to the sampler's own counters (branch counts).
    pub(crate) fn own_counters(&mut self) -> &mut SamplerCounters {
        &mut self.counters
    }

    /// Counts a candidate turned down for lying outside the informed set.
    pub(crate) fn reject(&mut self) {
        self.counters.rejected += 1;
    }

    /// Counts a state returned to the planner; `Ok(())` for the sampler to return.
    pub(crate) fn returned(&mut self) -> Result<(), SampleError> {
        self.counters.returned += 1;
        Ok(())
    }

    /// Searches the segment `a → b` with `search` for a valid state inside the informed set of
    /// `cost` and writes it into `out` ([`SegmentSearch::find`]); a state found is counted as
    /// returned. Returns whether one was found.
    ///
    /// # Errors
    /// As [`SegmentSearch::find`].
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn search_segment<S, V>(
        &mut self,
        search: &SegmentSearch,
        space: &S,
        validity: &V,
        (a, b): (&[f64], &[f64]),
        cost: Option<f64>,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<bool, SampleError>
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        let set = &self.set;
        let found = search.find(
            space,
            validity,
            (a, b),
            |x| set.contains(space, cost, x),
            stop,
            &mut self.counters,
            &mut self.points,
            out,
        )?;
        if found {
            self.counters.returned += 1;
        }
        Ok(found)
    }

    /// The search of the segment `x_pre → x_temp` of the candidate
    /// [`draw_checked`](Self::draw_checked) returned last, whose partner from `partners`
    /// failed: as [`search_segment`](Self::search_segment), but the first call for a batch
    /// searches the segments of its later failed repairs with it ([`SegmentsAhead`]). `None`
    /// where that does not apply (the checker's batch is too narrow for two searches, or the
    /// batch does not hold the candidate): then search alone.
    ///
    /// # Errors
    /// As [`SegmentSearch::find`].
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn search_ahead<S, V>(
        &mut self,
        (partners, ahead): (&GaussianPartners, &mut SegmentsAhead),
        search: &SegmentSearch,
        space: &S,
        validity: &V,
        cost: Option<f64>,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<Option<bool>, SampleError>
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        if !SegmentsAhead::pays(search, validity) {
            return Ok(None);
        }
        let d = out.len();
        let (generation, candidates, _) = self.ahead.batch(d);
        let index = self.ahead.last_index();
        let set = &self.set;
        let found = ahead.outcome(
            (generation, index),
            partners.failed((generation, candidates), index, d),
            (search, space, validity),
            |x| set.contains(space, cost, x),
            stop,
            &mut self.counters,
            out,
        )?;
        if found == Some(true) {
            self.counters.returned += 1;
        }
        Ok(found)
    }

    /// The measure of the informed set of `bound` ([`Sampler::sampled_measure`](crate::Sampler::sampled_measure)).
    pub(crate) fn measure<S: StateSpace + ?Sized>(&self, space: &S, bound: CostBound) -> f64 {
        self.set.measure(space, bound.cost())
    }

    /// Restarts the generator from `seed` ([`Sampler::reseed`](crate::Sampler::reseed)).
    pub(crate) fn reseed(&mut self, seed: u64) {
        self.rng = SeededRng::seed_from_u64(seed);
        self.ahead.clear();
    }

    /// The set's counters and the sampler's own, summed ([`Sampler::counters`](crate::Sampler::counters)).
    pub(crate) fn counters(&self) -> SamplerCounters {
        self.set.with_own(self.counters)
    }
}
