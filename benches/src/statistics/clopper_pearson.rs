//! [`ClopperPearson`]: the exact binomial confidence interval of a success rate.

use serde::Serialize;

use crate::statistics::beta_quantile;

/// The Clopper–Pearson ("exact") confidence interval of a binomial proportion: the success
/// rate `k / n` of `n` runs of which `k` succeeded.
///
/// With `α = 1 − confidence`, the bounds are the beta quantiles
/// `B(α/2; k, n − k + 1)` (0 when `k = 0`) and `B(1 − α/2; k + 1, n − k)` (1 when `k = n`).
///
/// ```
/// use mit_star_benches::statistics::ClopperPearson;
/// let ci = ClopperPearson::new(5, 10, 0.95);
/// assert!((ci.lower - 0.1871).abs() < 1e-4 && (ci.upper - 0.8129).abs() < 1e-4);
/// assert_eq!(ci.rate, 0.5);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ClopperPearson {
    /// The observed rate `k / n` (0 when `n = 0`).
    pub rate: f64,
    /// Lower bound of the interval.
    pub lower: f64,
    /// Upper bound of the interval.
    pub upper: f64,
}

impl ClopperPearson {
    /// The interval for `successes` out of `trials` at `confidence` (e.g. `0.99`). With no
    /// trials the interval is `[0, 1]`; `successes` above `trials` are clamped.
    pub fn new(successes: usize, trials: usize, confidence: f64) -> Self {
        if trials == 0 {
            return Self {
                rate: 0.0,
                lower: 0.0,
                upper: 1.0,
            };
        }
        let k = successes.min(trials);
        let (k_f, n_f) = (k as f64, trials as f64);
        let alpha = 1.0 - confidence;
        let lower = if k == 0 {
            0.0
        } else {
            beta_quantile(alpha / 2.0, k_f, n_f - k_f + 1.0)
        };
        let upper = if k == trials {
            1.0
        } else {
            beta_quantile(1.0 - alpha / 2.0, k_f + 1.0, n_f - k_f)
        };
        Self {
            rate: k_f / n_f,
            lower,
            upper,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(ci: ClopperPearson, lower: f64, upper: f64) {
        assert!(
            (ci.lower - lower).abs() < 5e-5 && (ci.upper - upper).abs() < 5e-5,
            "{ci:?} vs ({lower}, {upper})"
        );
    }

    #[test]
    fn known_values() {
        close(ClopperPearson::new(0, 10, 0.95), 0.0, 0.3085);
        close(ClopperPearson::new(5, 10, 0.95), 0.1871, 0.8129);
        close(ClopperPearson::new(10, 10, 0.95), 0.6915, 1.0);
        // 1 of 10 at 95 %: (0.0025, 0.4450); 50 of 100 at 99 %: (0.3689, 0.6311).
        close(ClopperPearson::new(1, 10, 0.95), 0.0025, 0.4450);
        close(ClopperPearson::new(50, 100, 0.99), 0.3689, 0.6311);
        assert_eq!(ClopperPearson::new(0, 10, 0.95).lower, 0.0);
        assert_eq!(ClopperPearson::new(10, 10, 0.95).upper, 1.0);
    }

    #[test]
    fn degenerate_inputs() {
        let ci = ClopperPearson::new(0, 0, 0.99);
        assert_eq!((ci.lower, ci.upper), (0.0, 1.0));
        let ci = ClopperPearson::new(12, 10, 0.99);
        assert_eq!((ci.rate, ci.upper), (1.0, 1.0));
        // Higher confidence, wider interval.
        let a = ClopperPearson::new(30, 100, 0.95);
        let b = ClopperPearson::new(30, 100, 0.99);
        assert!(b.lower < a.lower && b.upper > a.upper);
    }
}
