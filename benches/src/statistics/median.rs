//! Medians as PDT computes them: [`median_index`], [`MedianInterval`] and [`MedianEstimate`].

use serde::Serialize;

use crate::statistics::binomial_cdf;

/// The 0-based index of the median among `n` sorted values: `⌈0.5 · (n − 1)⌉` (the upper of the
/// two middle values when `n` is even). `0` for `n = 0`.
///
/// ```
/// use mit_star_benches::statistics::median_index;
/// assert_eq!((median_index(100), median_index(101), median_index(1)), (50, 50, 0));
/// ```
pub fn median_index(n: usize) -> usize {
    n / 2
}

/// The order statistics bounding a nonparametric confidence interval of the median, and the
/// interval's exact coverage.
///
/// Starting at the median index `m`, the interval `(m − j, m + j)` (clamped to `[0, n − 1]`)
/// widens one step at a time until its coverage `P(m − j < K ≤ m + j)`, `K ~ Binomial(n, ½)`,
/// reaches the confidence. When even `[0, n − 1]` falls short (few runs), that widest
/// interval is returned with the coverage it has.
///
/// ```
/// use mit_star_benches::statistics::MedianInterval;
/// let ci = MedianInterval::new(100, 0.99).unwrap();
/// assert_eq!((ci.lower, ci.upper), (37, 63));
/// assert!((ci.coverage - 0.9907).abs() < 5e-5);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MedianInterval {
    /// Index of the lower bound's order statistic.
    pub lower: usize,
    /// Index of the upper bound's order statistic.
    pub upper: usize,
    /// The interval's coverage probability.
    pub coverage: f64,
}

impl MedianInterval {
    /// The interval for `n` values at `confidence` (e.g. `0.99`); `None` when `n = 0`.
    pub fn new(n: usize, confidence: f64) -> Option<Self> {
        if n == 0 {
            return None;
        }
        let m = median_index(n);
        let mut j = 0;
        loop {
            let lower = m.saturating_sub(j);
            let upper = (m + j).min(n - 1);
            let coverage = binomial_cdf(upper, n, 0.5) - binomial_cdf(lower, n, 0.5);
            if coverage >= confidence - 1e-12 || (lower == 0 && upper == n - 1) {
                return Some(Self {
                    lower,
                    upper,
                    coverage,
                });
            }
            j += 1;
        }
    }
}

/// The median of a sample with its nonparametric confidence interval. Values may be `+∞`
/// (unsolved runs), so the median is `∞` when more than half of the runs failed.
///
/// ```
/// use mit_star_benches::statistics::MedianEstimate;
/// let values = [3.0, 1.0, f64::INFINITY, 2.0];
/// let m = MedianEstimate::of(&values, 0.99).unwrap();
/// assert_eq!(m.median, 3.0); // sorted 1, 2, 3, ∞: index ⌈1.5⌉ = 2
/// assert_eq!((m.min, m.max), (1.0, f64::INFINITY));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MedianEstimate {
    /// The median.
    pub median: f64,
    /// Lower confidence bound.
    pub lower: f64,
    /// Upper confidence bound.
    pub upper: f64,
    /// Coverage of `[lower, upper]`.
    pub coverage: f64,
    /// The smallest value.
    pub min: f64,
    /// The largest value.
    pub max: f64,
}

impl MedianEstimate {
    /// The estimate for `values` (any order, NaN treated as `+∞`); `None` when empty.
    pub fn of(values: &[f64], confidence: f64) -> Option<Self> {
        let mut sorted: Vec<f64> = values
            .iter()
            .map(|&v| if v.is_nan() { f64::INFINITY } else { v })
            .collect();
        sorted.sort_by(f64::total_cmp);
        Self::of_sorted(&sorted, confidence)
    }

    /// The estimate for values already sorted ascending.
    pub fn of_sorted(sorted: &[f64], confidence: f64) -> Option<Self> {
        let interval = MedianInterval::new(sorted.len(), confidence)?;
        Some(Self {
            median: sorted[median_index(sorted.len())],
            lower: sorted[interval.lower],
            upper: sorted[interval.upper],
            coverage: interval.coverage,
            min: sorted[0],
            max: sorted[sorted.len() - 1],
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_spec_checks() {
        let ci = MedianInterval::new(100, 0.99).unwrap();
        assert_eq!((ci.lower, ci.upper), (37, 63));
        assert!((ci.coverage - 0.9907).abs() < 5e-5, "{}", ci.coverage);
        let ci = MedianInterval::new(100, 0.95).unwrap();
        assert_eq!((ci.lower, ci.upper), (40, 60));
        assert!((ci.coverage - 0.954).abs() < 5e-4, "{}", ci.coverage);
        let ci = MedianInterval::new(50, 0.99).unwrap();
        assert_eq!((ci.lower, ci.upper), (15, 35));
    }

    #[test]
    fn the_first_interval_reaching_the_confidence_is_taken() {
        for n in [5_usize, 20, 50, 100, 333] {
            let ci = MedianInterval::new(n, 0.99).unwrap();
            if ci.coverage >= 0.99 && ci.lower > 0 {
                // One step narrower falls short.
                let (lo, hi) = (ci.lower + 1, ci.upper - 1);
                let narrower = binomial_cdf(hi, n, 0.5) - binomial_cdf(lo, n, 0.5);
                assert!(narrower < 0.99, "n={n}");
            }
        }
    }

    #[test]
    fn few_values_give_the_widest_interval() {
        let ci = MedianInterval::new(2, 0.99).unwrap();
        assert_eq!((ci.lower, ci.upper), (0, 1));
        assert!(ci.coverage < 0.99);
        assert_eq!(MedianInterval::new(0, 0.99), None);
        assert_eq!(MedianEstimate::of(&[], 0.99), None);
    }

    #[test]
    fn infinities_dominate_when_most_runs_fail() {
        let mut values = vec![f64::INFINITY; 6];
        values.extend([1.0, 2.0, 3.0, 4.0]);
        let m = MedianEstimate::of(&values, 0.95).unwrap();
        assert_eq!(m.median, f64::INFINITY);
        assert_eq!(m.min, 1.0);
        let m = MedianEstimate::of(&[f64::NAN, 1.0, 2.0], 0.5).unwrap();
        assert_eq!(m.median, 2.0);
        assert_eq!(m.max, f64::INFINITY);
    }
}
