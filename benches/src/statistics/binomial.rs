//! The binomial distribution's cumulative distribution function.

/// `P(K ≤ k)` for `K ~ Binomial(n, p)`, computed from log-probabilities so that it stays
/// accurate for any `n` (no underflow of `pⁿ`).
///
/// ```
/// use mit_star_benches::statistics::binomial_cdf;
/// assert!((binomial_cdf(1, 2, 0.5) - 0.75).abs() < 1e-15);
/// assert_eq!(binomial_cdf(10, 10, 0.3), 1.0);
/// ```
pub fn binomial_cdf(k: usize, n: usize, p: f64) -> f64 {
    if k >= n {
        return 1.0;
    }
    if p <= 0.0 {
        return 1.0;
    }
    if p >= 1.0 {
        return 0.0;
    }
    let (ln_p, ln_q) = (p.ln(), (-p).ln_1p());
    // ln C(n, i) built up term by term: C(n, i) = C(n, i − 1) · (n − i + 1) / i.
    let mut ln_choose = 0.0;
    let mut sum = 0.0;
    for i in 0..=k {
        if i > 0 {
            ln_choose += ((n - i + 1) as f64).ln() - (i as f64).ln();
        }
        sum += (ln_choose + i as f64 * ln_p + (n - i) as f64 * ln_q).exp();
    }
    sum.min(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_direct_sums() {
        // n = 5, p = 0.3: P(K ≤ 2) = 0.16807 + 0.36015 + 0.3087 = 0.83692.
        assert!((binomial_cdf(2, 5, 0.3) - 0.83692).abs() < 1e-12);
        assert!((binomial_cdf(0, 5, 0.3) - 0.7f64.powi(5)).abs() < 1e-15);
        assert_eq!(binomial_cdf(3, 3, 0.9), 1.0);
        assert_eq!(binomial_cdf(2, 3, 0.0), 1.0);
        assert_eq!(binomial_cdf(2, 3, 1.0), 0.0);
        // Symmetry at p = 1/2: P(K ≤ k) = 1 − P(K ≤ n − k − 1).
        for k in 0..20 {
            let a = binomial_cdf(k, 20, 0.5);
            let b = 1.0 - binomial_cdf(19 - k, 20, 0.5);
            assert!((a - b).abs() < 1e-12, "{k}");
        }
    }

    #[test]
    fn large_n_does_not_underflow() {
        // 0.5^2000 underflows to 0; the median of Binomial(2000, 0.5) is 1000.
        let c = binomial_cdf(1000, 2000, 0.5);
        assert!((c - 0.5089).abs() < 1e-3, "{c}");
    }
}
