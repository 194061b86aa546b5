//! The regularised incomplete beta function and its inverse (the beta distribution's
//! quantile), for Clopper–Pearson intervals.

/// `ln Γ(x)` for `x > 0` (Lanczos approximation, `g = 7`, nine terms; relative error below
/// `1e-14` over the range the harness uses).
pub fn ln_gamma(x: f64) -> f64 {
    const G: f64 = 7.0;
    const COEFFICIENTS: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        // Reflection: Γ(x) Γ(1 − x) = π / sin(πx).
        let pi = std::f64::consts::PI;
        return (pi / (pi * x).sin()).abs().ln() - ln_gamma(1.0 - x);
    }
    let x = x - 1.0;
    let mut sum = COEFFICIENTS[0];
    for (i, &c) in COEFFICIENTS.iter().enumerate().skip(1) {
        sum += c / (x + i as f64);
    }
    let t = x + G + 0.5;
    0.5 * (2.0 * std::f64::consts::PI).ln() + (x + 0.5) * t.ln() - t + sum.ln()
}

/// The regularised incomplete beta function `I_x(a, b)` for `a, b > 0` and `x ∈ [0, 1]`:
/// the cumulative distribution function of `Beta(a, b)` at `x`.
///
/// Evaluated with the continued fraction of the incomplete beta function (modified Lentz
/// method), on the side of `x = (a + 1) / (a + b + 2)` where it converges fast.
///
/// ```
/// use mit_star_benches::statistics::regularized_incomplete_beta;
/// // Beta(1, 1) is uniform; Beta(1, b) has CDF 1 − (1 − x)^b.
/// assert!((regularized_incomplete_beta(0.3, 1.0, 1.0) - 0.3).abs() < 1e-14);
/// assert!((regularized_incomplete_beta(0.2, 1.0, 3.0) - (1.0 - 0.8f64.powi(3))).abs() < 1e-14);
/// ```
pub fn regularized_incomplete_beta(x: f64, a: f64, b: f64) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    if x >= 1.0 {
        return 1.0;
    }
    let ln_front = ln_gamma(a + b) - ln_gamma(a) - ln_gamma(b) + a * x.ln() + b * (-x).ln_1p();
    if x < (a + 1.0) / (a + b + 2.0) {
        ln_front.exp() * continued_fraction(x, a, b) / a
    } else {
        1.0 - ln_front.exp() * continued_fraction(1.0 - x, b, a) / b
    }
}

/// The continued fraction of `I_x(a, b)` (without its front factor).
fn continued_fraction(x: f64, a: f64, b: f64) -> f64 {
    const TINY: f64 = 1e-300;
    const EPSILON: f64 = 1e-16;
    let (qab, qap, qam) = (a + b, a + 1.0, a - 1.0);
    let mut c = 1.0;
    let mut d = 1.0 - qab * x / qap;
    if d.abs() < TINY {
        d = TINY;
    }
    d = 1.0 / d;
    let mut h = d;
    for m in 1..=10_000 {
        let m = f64::from(m);
        let m2 = 2.0 * m;
        // Even step.
        let aa = m * (b - m) * x / ((qam + m2) * (a + m2));
        d = 1.0 + aa * d;
        if d.abs() < TINY {
            d = TINY;
        }
        c = 1.0 + aa / c;
        if c.abs() < TINY {
            c = TINY;
        }
        d = 1.0 / d;
        h *= d * c;
        // Odd step.
        let aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
        d = 1.0 + aa * d;
        if d.abs() < TINY {
            d = TINY;
        }
        c = 1.0 + aa / c;
        if c.abs() < TINY {
            c = TINY;
        }
        d = 1.0 / d;
        let delta = d * c;
        h *= delta;
        if (delta - 1.0).abs() < EPSILON {
            break;
        }
    }
    h
}

/// The `p`-quantile of `Beta(a, b)`: the `x` with `I_x(a, b) = p`, found by bisection (to
/// `1e-15`, or 200 halvings).
///
/// ```
/// use mit_star_benches::statistics::beta_quantile;
/// // Beta(1, 10): I_x = 1 − (1 − x)^10 = 0.975 at x = 1 − 0.025^(1/10).
/// let x = beta_quantile(0.975, 1.0, 10.0);
/// assert!((x - (1.0 - 0.025f64.powf(0.1))).abs() < 1e-12);
/// ```
pub fn beta_quantile(p: f64, a: f64, b: f64) -> f64 {
    if p <= 0.0 {
        return 0.0;
    }
    if p >= 1.0 {
        return 1.0;
    }
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if regularized_incomplete_beta(mid, a, b) < p {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo < 1e-15 {
            break;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::statistics::binomial_cdf;

    #[test]
    fn ln_gamma_matches_factorials() {
        let mut factorial = 1.0_f64;
        for n in 1..30 {
            // Γ(n) = (n − 1)!
            assert!(
                (ln_gamma(f64::from(n)) - factorial.ln()).abs() < 1e-12 * factorial.ln().max(1.0),
                "{n}"
            );
            factorial *= f64::from(n);
        }
        // Γ(1/2) = √π.
        assert!((ln_gamma(0.5) - std::f64::consts::PI.sqrt().ln()).abs() < 1e-14);
        assert!((ln_gamma(0.25) - 3.625_609_908_221_908_f64.ln()).abs() < 1e-13);
    }

    #[test]
    fn incomplete_beta_equals_binomial_tails_for_integer_parameters() {
        // I_x(k, n − k + 1) = P(Binomial(n, x) ≥ k).
        for n in [1_usize, 5, 10, 37, 100] {
            for k in 1..=n {
                for x in [0.01, 0.2, 0.5, 0.77, 0.99] {
                    let beta = regularized_incomplete_beta(x, k as f64, (n - k + 1) as f64);
                    let tail = 1.0 - binomial_cdf(k - 1, n, x);
                    assert!(
                        (beta - tail).abs() < 1e-10,
                        "n={n} k={k} x={x}: {beta} vs {tail}"
                    );
                }
            }
        }
    }

    #[test]
    fn quantile_inverts_the_cdf() {
        for (a, b) in [(0.5, 0.5), (2.0, 3.0), (30.0, 71.0), (100.0, 1.0)] {
            for p in [0.005, 0.025, 0.5, 0.975, 0.995] {
                let x = beta_quantile(p, a, b);
                assert!((regularized_incomplete_beta(x, a, b) - p).abs() < 1e-10);
            }
        }
        assert_eq!(beta_quantile(0.0, 2.0, 2.0), 0.0);
        assert_eq!(beta_quantile(1.0, 2.0, 2.0), 1.0);
    }
}
