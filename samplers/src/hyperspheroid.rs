//! Geometry of one prolate hyperspheroid (spec §7): its rotation, its measure, and uniform
//! samples of the unit ball it is mapped from.

use faer::Mat;
use rand::{Rng, RngExt};
use rand_distr::{Distribution, StandardNormal};
use spaces::unit_ball_measure;

/// Appends the row-major rotation taking `e1` onto the unit vector `k1` (spec §7).
pub(crate) fn push_rotation(rotations: &mut Vec<f64>, k1: &[f64]) -> Result<(), ()> {
    let n = k1.len();
    let b = Mat::<f64>::from_fn(n, n, |i, j| if j == 0 { k1[i] } else { 0.0 });
    let svd = b.svd().map_err(|_| ())?;
    let (u, v) = (svd.U(), svd.V());
    let sign = (u.determinant() * v.determinant()).signum();
    for i in 0..n {
        for j in 0..n {
            let mut r = 0.0;
            for k in 0..n {
                let lambda = if k + 1 == n { sign } else { 1.0 };
                r += u[(i, k)] * lambda * v[(j, k)];
            }
            rotations.push(r);
        }
    }
    Ok(())
}

/// `ln ζ_n` by the recurrence `ζ_n = ζ_{n−2} · 2π / n`, summed in log space (no underflow in
/// high dimension).
pub(crate) fn ln_unit_ball_measure(n: usize) -> f64 {
    let (mut ln, mut k) = if n % 2 == 0 { (0.0, 2) } else { (2f64.ln(), 3) };
    while k <= n {
        ln += (2.0 * std::f64::consts::PI / k as f64).ln();
        k += 2;
    }
    ln
}

/// Lebesgue measure of the prolate hyperspheroid `{x ∈ R^n : ‖x − a‖ + ‖x − b‖ < cost}` with
/// foci `s_min = ‖a − b‖` apart: `ζ_n · (c/2) · (√(c² − s_min²)/2)^(n−1)`.
///
/// 0 when `cost ≤ s_min` (the set is empty) or `n = 0`; ∞ for an infinite cost; NaN for a NaN
/// input or a negative `s_min`.
pub fn prolate_hyperspheroid_measure(n: usize, s_min: f64, cost: f64) -> f64 {
    if s_min.is_nan() || cost.is_nan() || s_min < 0.0 {
        return f64::NAN;
    }
    if n == 0 || cost <= s_min {
        return 0.0;
    }
    if cost == f64::INFINITY {
        return f64::INFINITY;
    }
    let minor = ((cost - s_min) * (cost + s_min)).sqrt() / 2.0;
    let power = match i32::try_from(n - 1) {
        Ok(p) => minor.powi(p),
        Err(_) => minor.powf(n as f64 - 1.0),
    };
    unit_ball_measure(n) * (cost / 2.0) * power
}

/// Fills `ball` with a state uniform in the open unit ball of its dimension: a standard normal
/// vector scaled to radius `U^(1/n)`.
pub(crate) fn sample_unit_ball(rng: &mut dyn Rng, ball: &mut [f64]) {
    let n = ball.len();
    loop {
        let mut norm_sq = 0.0;
        for v in ball.iter_mut() {
            *v = StandardNormal.sample(rng);
            norm_sq += *v * *v;
        }
        if norm_sq > 0.0 {
            let radius = rng.random::<f64>().powf(1.0 / n as f64);
            let scale = radius / norm_sq.sqrt();
            ball.iter_mut().for_each(|v| *v *= scale);
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use spaces::SeededRng;
    use std::f64::consts::PI;

    #[test]
    fn measure_matches_closed_forms() {
        // Ellipse with semi-axes a = c/2, b = √(c² − s²)/2.
        let (s, c) = (0.6, 1.0);
        let expected = PI * 0.5 * 0.4;
        assert!((prolate_hyperspheroid_measure(2, s, c) - expected).abs() < 1e-12);
        // Spheroid in 3D: 4/3 π a b².
        let expected = 4.0 / 3.0 * PI * 0.5 * 0.4 * 0.4;
        assert!((prolate_hyperspheroid_measure(3, s, c) - expected).abs() < 1e-12);
        // Start = goal: a ball of radius c/2.
        assert!((prolate_hyperspheroid_measure(4, 0.0, 2.0) - PI * PI / 2.0).abs() < 1e-12);
        assert_eq!(prolate_hyperspheroid_measure(3, 1.0, 1.0), 0.0);
        assert!(prolate_hyperspheroid_measure(3, -1.0, 1.0).is_nan());
    }

    #[test]
    fn log_unit_ball_measure_matches_and_does_not_underflow() {
        for n in 0..40 {
            assert!(
                (ln_unit_ball_measure(n) - unit_ball_measure(n).ln()).abs() < 1e-10,
                "n = {n}"
            );
        }
        // ζ_1000 ≈ 10^-1000 underflows as a float; its logarithm does not.
        assert!(ln_unit_ball_measure(1000).is_finite());
    }

    #[test]
    fn unit_ball_samples_are_inside_and_fill_the_radius_uniformly() {
        // In 3D a uniform ball sample has |x| ≤ 1/2 with probability 1/8.
        let mut rng = SeededRng::seed_from_u64(21);
        let mut ball = [0.0; 3];
        let draws = 16_000u32;
        let mut inner = 0u32;
        for _ in 0..draws {
            sample_unit_ball(&mut rng, &mut ball);
            let r = ball.iter().map(|v| v * v).sum::<f64>().sqrt();
            assert!(r < 1.0);
            inner += u32::from(r <= 0.5);
        }
        let p = f64::from(inner) / f64::from(draws);
        // Binomial standard error ≈ 0.0026.
        assert!((p - 0.125).abs() < 0.013, "{p}");
    }
}
