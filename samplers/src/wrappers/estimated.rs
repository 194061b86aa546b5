//! [`Estimated`]: the sampler wrapper that gives any sampler MIT*'s estimated informed set.

use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::StateValidity;

use crate::{
    CostBound, EstimatedInformedSet, ExpansionForm, ExpansionRule, LazyPathFailure, SampleError,
    SampleOrigin, Sampler, SamplerCounters, SamplerError,
};

/// Wraps a sampler and steers it with MIT*'s estimated informed set (spec §6, paper Alg. 3).
///
/// The planner reports its search through the [`Sampler`] feedback hooks; the wrapper keeps an
/// [`EstimatedInformedSet`] and swaps the bound it passes on:
///
/// - [`observe_invalid_lazy_edge`](Sampler::observe_invalid_lazy_edge): the first invalid lazy
///   edge creates the estimate `s̃_est` — which bounds the planner's next batch, as the paper's
///   Alg. 1 has it, or with [`with_immediate_batch`](Self::with_immediate_batch)`(true)` (the
///   MIT* authors' code) also raises [`wants_batch`](Sampler::wants_batch) to ask for a batch
///   at once; under [`ExpansionRule::PerInvalidEdge`] later failures expand it.
/// - [`sample`](Sampler::sample): a [`CostBound::Unbounded`] request becomes
///   [`CostBound::Estimated`]`(s̃_est)` while an estimate exists; a solution bound passes through
///   unchanged (the informed set of `c_best` replaces the estimate).
/// - [`observe_batch_end`](Sampler::observe_batch_end)`(false)`: under the default
///   [`ExpansionRule::PerBatch`], a batch drawn inside the estimate that ended without a solution
///   expands it, `s̃_est ← s̃_est · e_γ` (case 3).
///
/// Without the wrapper the inner sampler is the ablation without an estimated informed set:
/// `Estimated<AdaptiveSampler>` is MIT*'s sampler, `AdaptiveSampler` MIT*-AS's,
/// `Estimated<InformedSampler>` MIT*-EIS's.
///
/// ```
/// use mit_star_samplers::{CostBound, Estimated, InformedSampler, LazyPathFailure, Sampler};
/// use mit_star_spaces::{Never, RealVectorSpace};
/// use mit_star_validity::AllValid;
///
/// let space = RealVectorSpace::cube(2, -1.0, 1.0)?;
/// let inner = InformedSampler::new(&space, &[-0.5, 0.0], &[[0.5, 0.0]], 3)?;
/// let mut sampler = Estimated::new(inner);
/// let mut x = [0.0; 2];
/// // A lazy path of admissible cost 1.2, of which 0.6 was verified, failed: γ = 0.5.
/// Sampler::<RealVectorSpace, AllValid>::observe_invalid_lazy_edge(
///     &mut sampler,
///     LazyPathFailure { cost_to_come: 0.6, edge_estimate: 0.1, cost_to_go: 0.5 },
/// );
/// let estimate = 1.2 * 1.25f64.sqrt();
/// let cost = Sampler::<RealVectorSpace, AllValid>::estimated_cost(&sampler).unwrap();
/// assert!((cost - estimate).abs() < 1e-12);
/// sampler.sample(&space, &AllValid, CostBound::Unbounded, &Never, &mut x)?;
/// let through = mit_star_spaces::euclidean_distance(&x, &[-0.5, 0.0]) + mit_star_spaces::euclidean_distance(&x, &[0.5, 0.0]);
/// assert!(through < cost);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Estimated<T> {
    inner: T,
    estimate: EstimatedInformedSet,
    /// The estimate was just created and no sample has been drawn in it yet.
    wants_batch: bool,
    /// A sample has been drawn inside the current estimate since it last changed.
    sampled_inside: bool,
    /// Ask for a batch as soon as an estimate is created (spec §3.1, step 1).
    immediate_batch: bool,
    /// A sample has been drawn inside the estimate since the last batch ended.
    drawn_this_batch: bool,
    /// The estimate's first cost, its expansions and the batches drawn under it.
    initial: Option<f64>,
    expansions: u64,
    batches: u64,
    /// The last feedback that could not be turned into an estimate.
    last_error: Option<SamplerError>,
}

impl<T> Estimated<T> {
    /// Wraps `inner` with no estimate yet, the paper's expansion form and per-batch expansion.
    pub fn new(inner: T) -> Self {
        Self {
            inner,
            estimate: EstimatedInformedSet::new(),
            wants_batch: false,
            sampled_inside: false,
            immediate_batch: false,
            drawn_this_batch: false,
            initial: None,
            expansions: 0,
            batches: 0,
            last_error: None,
        }
    }

    /// Sets how `e_γ` is computed.
    #[must_use]
    pub fn with_form(mut self, form: ExpansionForm) -> Self {
        self.estimate = self.estimate.with_form(form);
        self
    }

    /// Sets when the estimate expands.
    #[must_use]
    pub fn with_rule(mut self, rule: ExpansionRule) -> Self {
        self.estimate = self.estimate.with_rule(rule);
        self
    }

    /// Whether a new estimate asks the planner for a batch at once
    /// ([`wants_batch`](Sampler::wants_batch); `true` is the MIT* authors' code and spec §3.1
    /// step 1). The default, `false`, lets the estimate bound the batch the planner adds when
    /// its search of the current one is exhausted, as the paper's Alg. 1 reads (and as
    /// `Parameters::eis_immediate_batch` defaults; `docs/guide/src/reference/ablation-study.md` has the evidence).
    #[must_use]
    pub fn with_immediate_batch(mut self, immediate: bool) -> Self {
        self.immediate_batch = immediate;
        self
    }

    /// The estimate and its parameters.
    pub fn estimated_informed_set(&self) -> &EstimatedInformedSet {
        &self.estimate
    }

    /// The wrapped sampler.
    pub fn inner(&self) -> &T {
        &self.inner
    }

    /// Unwraps the sampler.
    pub fn into_inner(self) -> T {
        self.inner
    }

    /// Forgets the estimate (a planner reset).
    pub fn clear(&mut self) {
        self.estimate.clear();
        self.wants_batch = false;
        self.sampled_inside = false;
        self.drawn_this_batch = false;
        self.initial = None;
        self.expansions = 0;
        self.batches = 0;
        self.last_error = None;
    }

    /// The last lazy-path failure that could not create an estimate (negative or non-finite
    /// costs, or a zero admissible cost), if any. The hooks cannot return errors, so malformed
    /// feedback is recorded here instead of silently dropped.
    pub fn last_error(&self) -> Option<&SamplerError> {
        self.last_error.as_ref()
    }

    /// The bound actually used for a request under `bound`.
    fn effective(&self, bound: CostBound) -> CostBound {
        match bound {
            CostBound::Unbounded => self.estimate.bound(),
            other => other,
        }
    }
}

impl<S, V, T> Sampler<S, V> for Estimated<T>
where
    S: StateSpace + ?Sized,
    V: StateValidity + ?Sized,
    T: Sampler<S, V>,
{
    fn sample(
        &mut self,
        space: &S,
        validity: &V,
        bound: CostBound,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<(), SampleError> {
        let effective = self.effective(bound);
        let mut result = self.inner.sample(space, validity, effective, stop, out);
        if matches!(result, Err(SampleError::EmptySet { .. }))
            && matches!(effective, CostBound::Estimated(_))
        {
            // An estimate at or below the straight-line cost holds no state: it is a guess, not
            // a bound, so sample as if there were none rather than stop the planner.
            result = self.inner.sample(space, validity, bound, stop, out);
        }
        if result.is_ok()
            && matches!(effective, CostBound::Estimated(_))
            && self.estimate.is_active()
        {
            self.wants_batch = false;
            self.sampled_inside = true;
            if !self.drawn_this_batch {
                self.drawn_this_batch = true;
                self.batches += 1;
            }
        }
        result
    }

    fn sampled_measure(&self, space: &S, bound: CostBound) -> f64 {
        self.inner.sampled_measure(space, self.effective(bound))
    }

    fn reseed(&mut self, seed: u64) {
        self.inner.reseed(seed);
        self.clear();
    }

    fn counters(&self) -> SamplerCounters {
        SamplerCounters {
            estimate_initial: self.initial,
            estimate_current: self.estimate.cost(),
            estimate_expansions: self.expansions,
            estimate_batches: self.batches,
            ..self.inner.counters()
        }
    }

    fn observe_invalid_lazy_edge(&mut self, failure: LazyPathFailure) {
        self.inner.observe_invalid_lazy_edge(failure);
        if self.estimate.is_active() {
            if self.estimate.rule() == ExpansionRule::PerInvalidEdge
                && self.estimate.expand().is_some()
            {
                self.expansions += 1;
                self.sampled_inside = false;
            }
            return;
        }
        match self.estimate.create(
            failure.cost_to_come,
            failure.edge_estimate,
            failure.cost_to_go,
        ) {
            Ok(cost) => {
                self.initial = Some(cost);
                self.wants_batch = self.immediate_batch;
                self.sampled_inside = false;
            }
            Err(error) => self.last_error = Some(error),
        }
    }

    fn observe_frontier(&mut self, states: &[f64]) {
        self.inner.observe_frontier(states);
    }

    fn observe_batch_end(&mut self, solved: bool) {
        self.inner.observe_batch_end(solved);
        self.drawn_this_batch = false;
        if !solved
            && self.sampled_inside
            && self.estimate.rule() == ExpansionRule::PerBatch
            && self.estimate.expand().is_some()
        {
            self.expansions += 1;
            self.sampled_inside = false;
        }
    }

    fn wants_batch(&self) -> bool {
        self.wants_batch || self.inner.wants_batch()
    }

    fn estimated_cost(&self) -> Option<f64> {
        self.estimate.cost().or_else(|| self.inner.estimated_cost())
    }

    fn last_origin(&self) -> SampleOrigin {
        self.inner.last_origin()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{InformedSampler, UniformSampler};
    use mit_star_spaces::{Never, RealVectorSpace};
    use mit_star_validity::AllValid;

    type Dyn = dyn Sampler<RealVectorSpace, AllValid>;

    const FAILURE: LazyPathFailure = LazyPathFailure {
        cost_to_come: 0.5,
        edge_estimate: 0.5,
        cost_to_go: 0.5,
    };

    fn wrapped(rule: ExpansionRule) -> (RealVectorSpace, Box<Dyn>) {
        let space = RealVectorSpace::cube(2, -1.0, 1.0).unwrap();
        let inner = InformedSampler::new(&space, &[-0.5, 0.0], &[[0.5, 0.0]], 1).unwrap();
        let wrapper = Estimated::new(inner)
            .with_rule(rule)
            .with_immediate_batch(true);
        (space, Box::new(wrapper))
    }

    #[test]
    fn first_failure_creates_the_estimate_and_asks_for_a_batch() {
        let (space, mut sampler) = wrapped(ExpansionRule::PerBatch);
        assert!(!sampler.wants_batch());
        assert_eq!(sampler.sampled_measure(&space, CostBound::Unbounded), 4.0);
        sampler.observe_invalid_lazy_edge(FAILURE);
        // γ = 1/3, e_γ = √(1 + 4/9).
        let expected = 1.5 * (1.0 + 4.0 / 9.0f64).sqrt();
        let cost = sampler.estimated_cost().unwrap();
        assert!((cost - expected).abs() < 1e-12);
        assert!(sampler.wants_batch());
        let measure = crate::prolate_hyperspheroid_measure(2, 1.0, cost);
        assert!((sampler.sampled_measure(&space, CostBound::Unbounded) - measure).abs() < 1e-12);
        // A second failure under the per-batch rule changes nothing.
        sampler.observe_invalid_lazy_edge(FAILURE);
        assert_eq!(sampler.estimated_cost(), Some(cost));
        let mut x = [0.0; 2];
        sampler
            .sample(&space, &AllValid, CostBound::Unbounded, &Never, &mut x)
            .unwrap();
        assert!(!sampler.wants_batch());
        let through = mit_star_spaces::euclidean_distance(&x, &[-0.5, 0.0])
            + mit_star_spaces::euclidean_distance(&x, &[0.5, 0.0]);
        assert!(through < cost);
    }

    #[test]
    fn batches_inside_the_estimate_expand_it_until_solved() {
        let (space, mut sampler) = wrapped(ExpansionRule::PerBatch);
        sampler.observe_invalid_lazy_edge(FAILURE);
        let created = sampler.estimated_cost().unwrap();
        let factor = (1.0 + 4.0 / 9.0f64).sqrt();
        // No sample inside yet (the batch that found the failure was drawn before): no expansion.
        sampler.observe_batch_end(false);
        assert_eq!(sampler.estimated_cost(), Some(created));
        let mut x = [0.0; 2];
        sampler
            .sample(&space, &AllValid, CostBound::Unbounded, &Never, &mut x)
            .unwrap();
        sampler.observe_batch_end(false);
        let expanded = sampler.estimated_cost().unwrap();
        assert!((expanded - created * factor).abs() < 1e-12);
        // A batch drawn under a solution bound is not drawn inside the estimate.
        sampler
            .sample(&space, &AllValid, CostBound::Solution(1.2), &Never, &mut x)
            .unwrap();
        sampler.observe_batch_end(true);
        assert_eq!(sampler.estimated_cost(), Some(expanded));
    }

    #[test]
    fn per_invalid_edge_rule_expands_on_each_failure() {
        let (_, mut sampler) = wrapped(ExpansionRule::PerInvalidEdge);
        sampler.observe_invalid_lazy_edge(FAILURE);
        let created = sampler.estimated_cost().unwrap();
        sampler.observe_invalid_lazy_edge(FAILURE);
        sampler.observe_invalid_lazy_edge(FAILURE);
        let factor = (1.0 + 4.0 / 9.0f64).sqrt();
        let cost = sampler.estimated_cost().unwrap();
        assert!((cost - created * factor * factor).abs() < 1e-12);
    }

    #[test]
    fn malformed_feedback_is_recorded_not_used() {
        let mut sampler = Estimated::new(UniformSampler::new(0));
        let bad = LazyPathFailure {
            cost_to_come: f64::NAN,
            ..FAILURE
        };
        Sampler::<RealVectorSpace, AllValid>::observe_invalid_lazy_edge(&mut sampler, bad);
        assert_eq!(
            Sampler::<RealVectorSpace, AllValid>::estimated_cost(&sampler),
            None
        );
        assert!(matches!(
            sampler.last_error(),
            Some(SamplerError::NegativeCost { .. })
        ));
        sampler.clear();
        assert!(sampler.last_error().is_none());
    }

    #[test]
    fn counters_report_the_estimate_and_the_batches_drawn_under_it() {
        let (space, mut sampler) = wrapped(ExpansionRule::PerBatch);
        assert_eq!(sampler.counters().estimate_initial, None);
        sampler.observe_invalid_lazy_edge(FAILURE);
        let created = sampler.estimated_cost().unwrap();
        let mut x = [0.0; 2];
        for _ in 0..3 {
            sampler
                .sample(&space, &AllValid, CostBound::Unbounded, &Never, &mut x)
                .unwrap();
        }
        // Three samples in one batch: one batch under the estimate, counted at once.
        let c = sampler.counters();
        assert_eq!((c.estimate_batches, c.estimate_expansions), (1, 0));
        sampler.observe_batch_end(false);
        let c = sampler.counters();
        assert_eq!(c.estimate_initial, Some(created));
        assert_eq!(c.estimate_current, sampler.estimated_cost());
        assert_eq!((c.estimate_batches, c.estimate_expansions), (1, 1));
        assert_eq!(c.returned, 3);
    }

    #[test]
    fn without_an_immediate_batch_a_new_estimate_waits_for_the_next_batch() {
        let space = RealVectorSpace::cube(2, -1.0, 1.0).unwrap();
        let inner = InformedSampler::new(&space, &[-0.5, 0.0], &[[0.5, 0.0]], 1).unwrap();
        // The default: the paper's Alg. 1.
        let mut sampler: Box<Dyn> = Box::new(Estimated::new(inner));
        sampler.observe_invalid_lazy_edge(FAILURE);
        assert!(sampler.estimated_cost().is_some());
        assert!(!sampler.wants_batch());
    }

    #[test]
    fn an_estimate_at_the_straight_line_cost_falls_back_to_the_whole_space() {
        let space = RealVectorSpace::cube(2, -1.0, 1.0).unwrap();
        let inner = InformedSampler::new(&space, &[-0.5, 0.0], &[[0.5, 0.0]], 1).unwrap();
        let mut sampler: Box<Dyn> = Box::new(Estimated::new(inner));
        // The whole lazy path was verified up to the goal: γ = 1, e_γ = 1, and s̃_est is the
        // straight-line cost, whose informed set is empty.
        sampler.observe_invalid_lazy_edge(LazyPathFailure {
            cost_to_come: 1.0,
            edge_estimate: 0.0,
            cost_to_go: 0.0,
        });
        assert_eq!(sampler.estimated_cost(), Some(1.0));
        let mut x = [0.0; 2];
        sampler
            .sample(&space, &AllValid, CostBound::Unbounded, &Never, &mut x)
            .expect("an estimate is no bound: sampling goes on");
        // A solution's empty set is final.
        assert!(matches!(
            sampler.sample(&space, &AllValid, CostBound::Solution(1.0), &Never, &mut x),
            Err(SampleError::EmptySet { .. })
        ));
    }

    #[test]
    fn reseed_forgets_the_estimate() {
        let (space, mut sampler) = wrapped(ExpansionRule::PerBatch);
        sampler.observe_invalid_lazy_edge(FAILURE);
        assert!(sampler.estimated_cost().is_some());
        sampler.reseed(1);
        assert_eq!(sampler.estimated_cost(), None);
        assert!(!sampler.wants_batch());
        assert_eq!(sampler.sampled_measure(&space, CostBound::Unbounded), 4.0);
    }
}
