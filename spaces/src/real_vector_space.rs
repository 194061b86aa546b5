//! [`RealVectorSpace`]: `R^n` with box bounds.

use rand::{Rng, RngExt};

use crate::{SpaceError, StateSpace, reflect_into_interval};

/// `R^n` restricted to an axis-aligned box, with the Euclidean metric and linear interpolation.
///
/// The dimension is chosen at run time (any `n ≥ 1`); states are `&[f64]` of length `n`.
///
/// ```
/// use mit_star_spaces::{RealVectorSpace, StateSpace};
/// let space = RealVectorSpace::cube(4, -0.5, 0.5)?;
/// assert_eq!(space.dimension(), 4);
/// assert!((space.maximum_extent() - 2.0).abs() < 1e-12); // diagonal of the unit 4-cube
/// assert!((space.distance(&[0.0; 4], &[0.5, 0.0, 0.0, 0.0]) - 0.5).abs() < 1e-12);
/// # Ok::<(), mit_star_spaces::SpaceError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct RealVectorSpace {
    lower: Vec<f64>,
    upper: Vec<f64>,
    measure: f64,
    extent: f64,
}

impl RealVectorSpace {
    /// A box with the given lower and upper corners.
    ///
    /// # Errors
    /// [`SpaceError`] if the dimension is zero, the lengths differ, a bound is not finite, a
    /// lower bound is not strictly below its upper bound, or the diagonal or volume of the box
    /// overflows or underflows `f64`.
    pub fn new(lower: Vec<f64>, upper: Vec<f64>) -> Result<Self, SpaceError> {
        if lower.len() != upper.len() {
            return Err(SpaceError::BoundsLength {
                lower: lower.len(),
                upper: upper.len(),
            });
        }
        if lower.is_empty() {
            return Err(SpaceError::ZeroDimension);
        }
        for (index, (&lo, &hi)) in lower.iter().zip(&upper).enumerate() {
            for value in [lo, hi] {
                if !value.is_finite() {
                    return Err(SpaceError::NonFiniteBound { index, value });
                }
            }
            if lo >= hi {
                return Err(SpaceError::EmptyInterval {
                    index,
                    lower: lo,
                    upper: hi,
                });
            }
        }
        let measure = lower.iter().zip(&upper).map(|(lo, hi)| hi - lo).product();
        let extent = lower
            .iter()
            .zip(&upper)
            .map(|(lo, hi)| (hi - lo) * (hi - lo))
            .sum::<f64>()
            .sqrt();
        for (quantity, value) in [("diagonal", extent), ("volume", measure)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(SpaceError::UnrepresentableSize { quantity, value });
            }
        }
        Ok(Self {
            lower,
            upper,
            measure,
            extent,
        })
    }

    /// The cube `[lower, upper]^n`.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub fn cube(n: usize, lower: f64, upper: f64) -> Result<Self, SpaceError> {
        Self::new(vec![lower; n], vec![upper; n])
    }
}

impl StateSpace for RealVectorSpace {
    #[inline]
    fn dimension(&self) -> usize {
        self.lower.len()
    }

    #[inline]
    fn distance(&self, a: &[f64], b: &[f64]) -> f64 {
        euclidean_distance(a, b)
    }

    #[inline]
    fn interpolate(&self, a: &[f64], b: &[f64], t: f64, out: &mut [f64]) {
        for ((o, &x), &y) in out.iter_mut().zip(a).zip(b) {
            *o = x + (y - x) * t;
        }
    }

    fn lower(&self) -> &[f64] {
        &self.lower
    }

    fn upper(&self) -> &[f64] {
        &self.upper
    }

    #[inline]
    fn contains(&self, state: &[f64]) -> bool {
        state
            .iter()
            .zip(self.lower.iter().zip(&self.upper))
            .all(|(&x, (&lo, &hi))| x >= lo && x <= hi)
    }

    fn enforce_bounds(&self, state: &mut [f64]) {
        for (x, (&lo, &hi)) in state.iter_mut().zip(self.lower.iter().zip(&self.upper)) {
            *x = x.clamp(lo, hi);
        }
    }

    fn reflect_into_bounds(&self, state: &mut [f64]) {
        for (x, (&lo, &hi)) in state.iter_mut().zip(self.lower.iter().zip(&self.upper)) {
            *x = reflect_into_interval(*x, lo, hi);
        }
    }

    fn measure(&self) -> f64 {
        self.measure
    }

    fn maximum_extent(&self) -> f64 {
        self.extent
    }

    fn sample_uniform(&self, rng: &mut dyn Rng, out: &mut [f64]) {
        for (x, (&lo, &hi)) in out.iter_mut().zip(self.lower.iter().zip(&self.upper)) {
            *x = lo + (hi - lo) * rng.random::<f64>();
        }
    }

    fn is_euclidean(&self) -> bool {
        true
    }
}

/// Euclidean distance between two coordinate slices of equal length.
#[inline]
pub fn euclidean_distance(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    // The squares four at a time (vectorised), added one by one in coordinate order from
    // `-0.0`, as `Iterator::sum` adds them: the same number to the last bit, with fewer
    // instructions.
    let mut sum = -0.0;
    let (mut left, mut right) = (a.chunks_exact(4), b.chunks_exact(4));
    for (x, y) in (&mut left).zip(&mut right) {
        let d = [x[0] - y[0], x[1] - y[1], x[2] - y[2], x[3] - y[3]];
        let squares = [d[0] * d[0], d[1] * d[1], d[2] * d[2], d[3] * d[3]];
        sum += squares[0];
        sum += squares[1];
        sum += squares[2];
        sum += squares[3];
    }
    for (x, y) in left.remainder().iter().zip(right.remainder()) {
        sum += (x - y) * (x - y);
    }
    sum.sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};

    #[test]
    fn euclidean_distance_adds_the_squares_in_order_to_the_last_bit() {
        let plain = |a: &[f64], b: &[f64]| {
            a.iter()
                .zip(b)
                .map(|(x, y)| (x - y) * (x - y))
                .sum::<f64>()
                .sqrt()
        };
        let mut rng = rand_pcg::Pcg64::seed_from_u64(7);
        for n in 0..=13 {
            for _ in 0..200 {
                let mut draw = || -> Vec<f64> {
                    (0..n)
                        .map(|_| rng.random_range(-4.0..4.0) * 10f64.powi(rng.random_range(-8..3)))
                        .collect()
                };
                let (a, b) = (draw(), draw());
                let (got, want) = (euclidean_distance(&a, &b), plain(&a, &b));
                assert_eq!(got.to_bits(), want.to_bits(), "{a:?} {b:?}");
            }
        }
        assert_eq!(euclidean_distance(&[], &[]).to_bits(), (-0.0f64).to_bits());
        assert_eq!(
            euclidean_distance(&[-0.0], &[0.0]).to_bits(),
            0.0f64.to_bits()
        );
    }

    #[test]
    fn rejects_malformed_bounds() {
        assert_eq!(
            RealVectorSpace::new(vec![], vec![]),
            Err(SpaceError::ZeroDimension)
        );
        assert!(matches!(
            RealVectorSpace::new(vec![0.0], vec![1.0, 2.0]),
            Err(SpaceError::BoundsLength { lower: 1, upper: 2 })
        ));
        assert!(matches!(
            RealVectorSpace::new(vec![0.0, 1.0], vec![1.0, 1.0]),
            Err(SpaceError::EmptyInterval { index: 1, .. })
        ));
        assert!(matches!(
            RealVectorSpace::new(vec![f64::NAN], vec![1.0]),
            Err(SpaceError::NonFiniteBound { index: 0, .. })
        ));
    }

    #[test]
    fn measure_and_extent_of_a_box() {
        let space = RealVectorSpace::new(vec![0.0, -1.0, 2.0], vec![2.0, 1.0, 5.0]).unwrap();
        assert!((space.measure() - 12.0).abs() < 1e-12);
        assert!((space.maximum_extent() - 17.0f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn check_state_names_the_problem() {
        let space = RealVectorSpace::cube(3, -0.5, 0.5).unwrap();
        assert!(space.check_state(&[0.0, 0.1, -0.2]).is_ok());
        assert!(matches!(
            space.check_state(&[0.0, 0.1]),
            Err(SpaceError::DimensionMismatch {
                expected: 3,
                got: 2
            })
        ));
        assert!(matches!(
            space.check_state(&[0.0, f64::NAN, 0.0]),
            Err(SpaceError::NonFiniteState { index: 1, .. })
        ));
        assert!(matches!(
            space.check_state(&[0.0, 0.0, 0.7]),
            Err(SpaceError::OutOfBounds { index: 2, .. })
        ));
    }
}
