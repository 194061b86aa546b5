//! Geometry of one prolate hyperspheroid (spec §7): its rotation, its measure, and uniform
//! samples of the unit ball it is mapped from.

use mit_star_spaces::unit_ball_measure;
use rand::{Rng, RngExt};
use rand_distr::{Distribution, StandardNormal};

/// The rotation taking `e1` onto a unit vector `k1` by turning in the plane of the two (the
/// identity on the orthogonal complement): `R = I + (c − 1)(e1 e1ᵀ + w wᵀ) + s (w e1ᵀ − e1 wᵀ)`
/// with `c = k1·e1`, `s = ‖k1 − c e1‖` and `w = (k1 − c e1) / s` (spec §7 asks for any proper
/// rotation with `R e1 = k1`; the hyperspheroid is symmetric about its axis, so every such
/// rotation gives the same distribution).
///
/// Stored as `(c, s)` and `w` (`n` values, `w₀ = 0`), it costs `O(n)` to build and to apply —
/// where the SVD construction costs `O(n³)` and a dense product `O(n²)` per sample, which made
/// building a planner in `R^1000` take seconds. When `k1 = −e1` the plane is `(e1, e2)` (a half
/// turn); in one dimension no proper rotation takes `e1` to `−e1`, and the identity's sign flip is
/// harmless because the unit interval is symmetric.
pub(crate) fn push_plane_rotation(axes: &mut Vec<f64>, k1: &[f64]) -> (f64, f64) {
    let n = k1.len();
    let c = k1.first().copied().unwrap_or(1.0);
    let s = k1.iter().skip(1).map(|v| v * v).sum::<f64>().sqrt();
    if s > 0.0 {
        axes.push(0.0);
        axes.extend(k1.iter().skip(1).map(|v| v / s));
        (c, s)
    } else {
        // k1 = ±e1: the identity, or a half turn in the (e1, e2) plane.
        axes.extend((0..n).map(|i| if i == 1 && c < 0.0 { 1.0 } else { 0.0 }));
        (c.signum(), 0.0)
    }
}

/// `out = centre + R x` for the plane rotation `(c, s, w)` of [`push_plane_rotation`], in `O(n)`.
#[inline]
pub(crate) fn rotate_about_centre(
    (c, s, w): (f64, f64, &[f64]),
    x: &[f64],
    centre: &[f64],
    out: &mut [f64],
) {
    let along = x[0];
    let across: f64 = w.iter().zip(x).skip(1).map(|(a, b)| a * b).sum();
    let shift = (c - 1.0) * across + s * along;
    out[0] = centre[0] + c * along - s * across;
    for (((o, &ci), &xi), &wi) in out.iter_mut().zip(centre).zip(x).zip(w).skip(1) {
        *o = ci + xi + shift * wi;
    }
}

/// The dense row-major `n × n` matrix of the plane rotation `(c, s, w)`.
pub(crate) fn dense_rotation((c, s, w): (f64, f64, &[f64])) -> Vec<f64> {
    let n = w.len();
    let mut r = vec![0.0; n * n];
    let e1 = |i: usize| if i == 0 { 1.0 } else { 0.0 };
    for i in 0..n {
        for j in 0..n {
            let identity = if i == j { 1.0 } else { 0.0 };
            r[i * n + j] = identity
                + (c - 1.0) * (e1(i) * e1(j) + w[i] * w[j])
                + s * (w[i] * e1(j) - e1(i) * w[j]);
        }
    }
    r
}

/// `ln ζ_n` by the recurrence `ζ_n = ζ_{n−2} · 2π / n`, summed in log space (no underflow in
/// high dimension).
pub(crate) fn ln_unit_ball_measure(n: usize) -> f64 {
    let (mut ln, mut k) = if n.is_multiple_of(2) {
        (0.0, 2)
    } else {
        (2f64.ln(), 3)
    };
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
    use mit_star_spaces::SeededRng;
    use rand::SeedableRng;
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

#[cfg(test)]
mod rotation_tests {
    use super::*;

    #[test]
    fn the_implicit_rotation_equals_the_dense_matrix() {
        for k1 in [
            vec![0.6, 0.8, 0.0],
            vec![-1.0, 0.0, 0.0],
            vec![1.0, 0.0, 0.0],
            vec![0.0, 0.0, 1.0],
            vec![-0.5, 0.5, -0.5, 0.5],
            vec![-1.0],
        ] {
            let n = k1.len();
            let mut axes = Vec::new();
            let (c, s) = push_plane_rotation(&mut axes, &k1);
            let r = dense_rotation((c, s, &axes));
            let x: Vec<f64> = (0..n).map(|i| 0.3 + 0.7 * i as f64).collect();
            let centre = vec![0.25; n];
            let mut out = vec![0.0; n];
            rotate_about_centre((c, s, &axes), &x, &centre, &mut out);
            for i in 0..n {
                let dense: f64 = 0.25 + (0..n).map(|j| r[i * n + j] * x[j]).sum::<f64>();
                assert!((out[i] - dense).abs() < 1e-12, "{k1:?}: {i}");
                if n > 1 {
                    assert!((r[i * n] - k1[i]).abs() < 1e-12, "{k1:?}: R e1 ≠ k1");
                }
            }
        }
    }
}
