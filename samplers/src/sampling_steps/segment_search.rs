//! [`SegmentSearch`]: look for a valid state on the segment between two states, in bisection
//! order — the bridge test's midpoint and the adaptive sampler's repair step.

use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::{EdgeGrid, StateValidity};

use super::lookahead::MOST_BATCHED;
use crate::{SampleError, SamplerCounters, SamplerError};

/// Tests up to `checks` states of a segment `a → b` in bisection order — the midpoint, then the
/// quarter points, then the eighths, … — and returns the first that is accepted and valid.
///
/// The points are those of the canonical edge grid of `validity` ([`EdgeGrid`]) with
/// `N = 2^⌈log₂(checks + 1)⌉` intervals, visited in its breadth-first bisection order: with the
/// default 8 checks, the fractions `1/2, 1/4, 3/4, 1/8, 3/8, 5/8, 7/8, 1/16`. One check is the
/// bridge test's midpoint.
///
/// ```
/// use mit_star_samplers::SegmentSearch;
/// let search = SegmentSearch::new(8)?;
/// let fractions: Vec<f64> = search.fractions().collect();
/// assert_eq!(fractions, [0.5, 0.25, 0.75, 0.125, 0.375, 0.625, 0.875, 0.0625]);
/// assert_eq!(SegmentSearch::midpoint().fractions().collect::<Vec<_>>(), [0.5]);
/// # Ok::<(), mit_star_samplers::SamplerError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SegmentSearch {
    checks: usize,
    grid: EdgeGrid,
}

impl SegmentSearch {
    /// The largest accepted number of checks.
    pub const MAX_CHECKS: usize = 1 << 20;

    /// A search testing at most `checks` points.
    ///
    /// # Errors
    /// [`SamplerError::BridgeChecks`] unless `1 ≤ checks ≤ MAX_CHECKS`.
    pub fn new(checks: usize) -> Result<Self, SamplerError> {
        if !(1..=Self::MAX_CHECKS).contains(&checks) {
            return Err(SamplerError::BridgeChecks {
                got: checks,
                max: Self::MAX_CHECKS,
            });
        }
        // `checks + 1 ≤ 2^20 + 1`, so the power of two and the cast are exact.
        let intervals = (checks + 1).next_power_of_two() as u64;
        Ok(Self {
            checks,
            grid: EdgeGrid::with_intervals(intervals),
        })
    }

    /// The bridge test's single check: the midpoint.
    pub fn midpoint() -> Self {
        Self {
            checks: 1,
            grid: EdgeGrid::with_intervals(2),
        }
    }

    /// The maximum number of points tested.
    pub fn checks(&self) -> usize {
        self.checks
    }

    /// The fractions along the segment that are tested, in order.
    pub fn fractions(&self) -> impl Iterator<Item = f64> + '_ {
        self.grid
            .order(0, self.checks as u64)
            .map(|i| self.grid.fraction(i))
    }

    /// Searches the segment `a → b` (interpolated by the space) and writes into `out` the first
    /// point that `accept` admits and `validity` finds valid. Points `accept` turns down are
    /// counted as rejected and not validity-checked. Returns whether a point was found.
    ///
    /// The admitted points go to `validity` a [batch](StateValidity::batch_width) at a time
    /// ([`StateValidity::are_valid`], in `points`, a buffer the caller keeps so that a search
    /// does not allocate): the answer is the first valid point in the order above, as testing
    /// them one by one finds, though a batched checker may have decided points after it.
    ///
    /// # Errors
    /// [`SampleError::Stopped`] if `stop` fires (polled before every batch).
    #[allow(clippy::too_many_arguments)]
    pub fn find<S, V, F>(
        &self,
        space: &S,
        validity: &V,
        (a, b): (&[f64], &[f64]),
        mut accept: F,
        stop: &dyn Stop,
        counters: &mut SamplerCounters,
        points: &mut Vec<f64>,
        out: &mut [f64],
    ) -> Result<bool, SampleError>
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
        F: FnMut(&[f64]) -> bool,
    {
        let d = out.len();
        let width = validity.batch_width().clamp(1, MOST_BATCHED);
        points.resize(width * d.max(1), 0.0);
        let mut valid = [false; MOST_BATCHED];
        let mut fractions = self.fractions();
        loop {
            if stop.should_stop() {
                return Err(SampleError::Stopped);
            }
            let mut admitted = 0;
            for t in fractions.by_ref() {
                let point = &mut points[admitted * d..(admitted + 1) * d];
                space.interpolate(a, b, t, point);
                counters.drawn += 1;
                if !accept(point) {
                    counters.rejected += 1;
                    continue;
                }
                admitted += 1;
                if admitted == width {
                    break;
                }
            }
            if admitted == 0 {
                return Ok(false);
            }
            validity.are_valid(&points[..admitted * d], d, &mut valid[..admitted]);
            counters.validity_checks += admitted as u64;
            if let Some(i) = valid[..admitted].iter().position(|&v| v) {
                out.copy_from_slice(&points[i * d..(i + 1) * d]);
                return Ok(true);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star_spaces::{Never, RealVectorSpace};

    #[test]
    fn budget_is_validated() {
        assert!(matches!(
            SegmentSearch::new(0),
            Err(SamplerError::BridgeChecks { got: 0, .. })
        ));
        assert!(SegmentSearch::new(SegmentSearch::MAX_CHECKS + 1).is_err());
        assert_eq!(SegmentSearch::new(1).unwrap(), SegmentSearch::midpoint());
        assert_eq!(SegmentSearch::new(7).unwrap().fractions().count(), 7);
    }

    #[test]
    fn finds_the_first_valid_point_in_bisection_order() {
        // Valid only for x > 0.8: of the default order, 7/8 is the first such point.
        let valid = |s: &[f64]| s[0] > 0.8;
        struct Right<F>(F);
        impl<F: Fn(&[f64]) -> bool> StateValidity for Right<F> {
            fn is_valid(&self, s: &[f64]) -> bool {
                (self.0)(s)
            }
        }
        let space = RealVectorSpace::cube(1, 0.0, 1.0).unwrap();
        let search = SegmentSearch::new(8).unwrap();
        let mut counters = SamplerCounters::default();
        let (mut points, mut out) = (Vec::new(), [0.0]);
        let found = search
            .find(
                &space,
                &Right(valid),
                (&[0.0], &[1.0]),
                |_| true,
                &Never,
                &mut counters,
                &mut points,
                &mut out,
            )
            .unwrap();
        assert!(found);
        assert!((out[0] - 0.875).abs() < 1e-12);
        assert_eq!(counters.drawn, 7);
        // Rejecting x > 0.85 leaves no acceptable valid point among the 8.
        let found = search
            .find(
                &space,
                &Right(valid),
                (&[0.0], &[1.0]),
                |s| s[0] < 0.85,
                &Never,
                &mut counters,
                &mut points,
                &mut out,
            )
            .unwrap();
        assert!(!found);
        assert_eq!(counters.rejected, 1);
        // A stop that has fired ends the search before any point.
        assert_eq!(
            search.find(
                &space,
                &Right(valid),
                (&[0.0], &[1.0]),
                |_| true,
                &|| true,
                &mut counters,
                &mut points,
                &mut out
            ),
            Err(SampleError::Stopped)
        );
    }
}
