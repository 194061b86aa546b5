//! [`SegmentsAhead`]: the segment searches of a lookahead batch's failed repairs, decided
//! together.

use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::StateValidity;

use super::MOST_BATCHED;
use crate::{SampleError, SamplerCounters, SegmentSearch};

/// The adaptive sampler's step 4 for a whole batch of candidates at once: when the first
/// candidate of a [`Lookahead`](super::Lookahead) batch needs its segment `x_pre → x_temp`
/// searched (its Gaussian partner invalid or outside the informed set), the segments of the
/// batch's later candidates that will need a search too are searched with it, their points
/// packed into the checker's lanes by one batched call.
///
/// A segment search draws nothing at random: its outcome is a function of the segment's ends,
/// the cost bound and the checker. Searching ahead therefore changes no state the sampler
/// returns, only when the checks are made (the counters are charged then) and how full each
/// batch of the checker is. It pays where a checker's batch holds at least two searches'
/// points ([`pays`](Self::pays)): sixteen AVX-512 lanes against the default eight points,
/// where one search alone leaves half the lanes empty. Searches of candidates the sampler
/// never reaches (a batch dropped when the bound changes) are made for nothing, as their
/// partners were drawn for nothing.
#[derive(Debug, Clone, Default)]
pub(crate) struct SegmentsAhead {
    /// The batch searched (its lookahead generation).
    generation: Option<u64>,
    /// Per candidate of the batch: whether its search found a state (`None`: not searched).
    outcomes: [Option<bool>; MOST_BATCHED],
    /// Per candidate: the state found, `dimension` coordinates each.
    found: Vec<f64>,
    /// The admitted points of every segment searched, packed for the checker, with the
    /// candidate each belongs to and the checker's answers.
    points: Vec<f64>,
    owners: Vec<usize>,
    valid: Vec<bool>,
}

impl SegmentsAhead {
    /// Whether searching a batch's segments together pays with `validity`: its batches hold
    /// at least two of `search`'s points.
    pub(crate) fn pays<V: StateValidity + ?Sized>(search: &SegmentSearch, validity: &V) -> bool {
        validity.batch_width() >= 2 * search.checks()
    }

    /// The outcome of the search of candidate `index` of batch `generation`: whether a point
    /// of its segment is admitted by `accept` and valid, the first such in `search`'s order
    /// written into `out` ([`SegmentSearch::find`]'s answer). The first call for a batch
    /// searches every segment of `segments` (candidate index, `x_pre`, `x_temp`; `index`'s
    /// among them) with one call of `validity`, charging `counters` as `find` would. `None`
    /// when `index`'s segment was not among them.
    ///
    /// # Errors
    /// [`SampleError::Stopped`] if `stop` fires (polled before the batch is searched).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn outcome<'a, S, V, F>(
        &mut self,
        (generation, index): (u64, usize),
        segments: impl Iterator<Item = (usize, &'a [f64], &'a [f64])>,
        (search, space, validity): (&SegmentSearch, &S, &V),
        mut accept: F,
        stop: &dyn Stop,
        counters: &mut SamplerCounters,
        out: &mut [f64],
    ) -> Result<Option<bool>, SampleError>
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
        F: FnMut(&[f64]) -> bool,
    {
        let d = out.len();
        if index >= MOST_BATCHED || d == 0 {
            return Ok(None);
        }
        if self.generation != Some(generation) {
            if stop.should_stop() {
                return Err(SampleError::Stopped);
            }
            self.generation = Some(generation);
            self.search_all(segments, search, space, validity, &mut accept, counters, d);
        }
        let outcome = self.outcomes[index].take();
        if outcome == Some(true) {
            out.copy_from_slice(&self.found[index * d..(index + 1) * d]);
        }
        Ok(outcome)
    }

    /// Packs the admitted points of every segment, checks them in one call and keeps each
    /// segment's first valid point.
    #[allow(clippy::too_many_arguments)]
    fn search_all<'a, S, V, F>(
        &mut self,
        segments: impl Iterator<Item = (usize, &'a [f64], &'a [f64])>,
        search: &SegmentSearch,
        space: &S,
        validity: &V,
        accept: &mut F,
        counters: &mut SamplerCounters,
        d: usize,
    ) where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
        F: FnMut(&[f64]) -> bool,
    {
        self.outcomes = [None; MOST_BATCHED];
        self.found.resize(MOST_BATCHED * d, 0.0);
        self.points.clear();
        self.owners.clear();
        for (i, a, b) in segments.filter(|&(i, ..)| i < MOST_BATCHED) {
            self.outcomes[i] = Some(false);
            for t in search.fractions() {
                let start = self.points.len();
                self.points.resize(start + d, 0.0);
                let point = &mut self.points[start..];
                space.interpolate(a, b, t, point);
                counters.drawn += 1;
                if accept(point) {
                    self.owners.push(i);
                } else {
                    counters.rejected += 1;
                    self.points.truncate(start);
                }
            }
        }
        let count = self.owners.len();
        if count == 0 {
            return;
        }
        self.valid.resize(count, false);
        validity.are_valid(&self.points, d, &mut self.valid[..count]);
        counters.validity_checks += count as u64;
        // Points are packed segment by segment in search order: the first valid point of a
        // segment is the one its own search returns.
        for (k, (&i, &ok)) in self.owners.iter().zip(&self.valid).enumerate() {
            if ok && self.outcomes[i] == Some(false) {
                self.outcomes[i] = Some(true);
                self.found[i * d..(i + 1) * d].copy_from_slice(&self.points[k * d..(k + 1) * d]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling_steps::test_checkers::RightHalf;
    use mit_star_spaces::{Never, RealVectorSpace};

    #[test]
    fn a_batch_of_searches_answers_as_each_search_alone_in_one_call() {
        let space = RealVectorSpace::cube(2, 0.0, 1.0).unwrap();
        let search = SegmentSearch::new(8).unwrap();
        let wide = RightHalf::new(16);
        assert!(SegmentsAhead::pays(&search, &wide));
        assert!(!SegmentsAhead::pays(&search, &RightHalf::new(8)));
        // Valid where x ≥ 0.5; points with y > 0.9 are turned down unchecked.
        let accept = |p: &[f64]| p[1] <= 0.9;
        let segments: [(usize, [f64; 2], [f64; 2]); 4] = [
            (1, [0.0, 0.2], [1.0, 0.2]),  // 1/2 first
            (2, [0.0, 0.5], [0.3, 0.5]),  // nothing valid
            (4, [0.0, 0.1], [0.58, 1.2]), // 7/8 valid but above 0.9: turned down
            (5, [0.1, 0.3], [0.6, 0.3]),  // 7/8 the first valid in bisection order
        ];
        let mut ahead = SegmentsAhead::default();
        let mut counters = SamplerCounters::default();
        let mut out = [0.0; 2];
        let iter = segments.iter().map(|(i, a, b)| (*i, &a[..], &b[..]));
        let first = ahead
            .outcome(
                (3, 1),
                iter,
                (&search, &space, &wide),
                accept,
                &Never,
                &mut counters,
                &mut out,
            )
            .unwrap();
        assert_eq!(wide.batches().len(), 1);
        // Each answer and the work charged are those of the searches made one by one.
        let mut alone = SamplerCounters::default();
        let narrow = RightHalf::new(8);
        let mut points = Vec::new();
        let mut expected = [0.0; 2];
        for (k, (i, a, b)) in segments.iter().enumerate() {
            let found = search
                .find(
                    &space,
                    &narrow,
                    (a, b),
                    accept,
                    &Never,
                    &mut alone,
                    &mut points,
                    &mut expected,
                )
                .unwrap();
            let got = if k == 0 {
                first
            } else {
                let none = std::iter::empty();
                ahead
                    .outcome(
                        (3, *i),
                        none,
                        (&search, &space, &wide),
                        accept,
                        &Never,
                        &mut counters,
                        &mut out,
                    )
                    .unwrap()
            };
            assert_eq!(got, Some(found), "segment {i}");
            if found {
                assert_eq!(out, expected, "segment {i}");
            }
        }
        assert_eq!(
            (counters.drawn, counters.rejected, counters.validity_checks),
            (alone.drawn, alone.rejected, alone.validity_checks)
        );
        assert!(alone.rejected > 0);
        // An index not searched, or asked again, has no outcome; a new batch searches again.
        let none = std::iter::empty();
        let parts = (&search, &space, &wide);
        assert_eq!(
            ahead.outcome((3, 0), none, parts, accept, &Never, &mut counters, &mut out),
            Ok(None)
        );
        let iter = segments.iter().map(|(i, a, b)| (*i, &a[..], &b[..]));
        assert_eq!(
            ahead.outcome((4, 5), iter, parts, accept, &Never, &mut counters, &mut out),
            Ok(Some(true))
        );
        assert_eq!(wide.batches().len(), 2);
    }

    #[test]
    fn a_stop_that_has_fired_searches_nothing() {
        let space = RealVectorSpace::cube(1, 0.0, 1.0).unwrap();
        let search = SegmentSearch::new(8).unwrap();
        let wide = RightHalf::new(16);
        let mut ahead = SegmentsAhead::default();
        let mut counters = SamplerCounters::default();
        let segment = [(0, &[0.0][..], &[1.0][..])];
        let mut ask = |stop: &dyn Stop| {
            let parts = (&search, &space, &wide);
            let iter = segment.into_iter();
            ahead.outcome(
                (1, 0),
                iter,
                parts,
                |_| true,
                stop,
                &mut counters,
                &mut [0.0],
            )
        };
        assert_eq!(ask(&|| true), Err(SampleError::Stopped));
        assert!(wide.batches().is_empty());
        // The batch is searched when asked again without the stop.
        assert_eq!(ask(&Never), Ok(Some(true)));
    }
}
