//! [`HaltonSequence`]: low-discrepancy points of the unit cube, randomly shifted per seed.

use mit_star_spaces::SeededRng;
use rand::{RngExt, SeedableRng};

/// The Halton sequence in `d` dimensions (coordinate `j` is the radical inverse of the point's
/// index in the `j`-th prime), shifted modulo 1 by an offset per coordinate drawn from a seed
/// (a Cranley–Patterson rotation), so that seeds give different sequences of the same
/// uniformity. Fills the unit cube more evenly than independent uniform draws (1024 points in
/// a 16 × 16 grid of the square: 1 to 7 in every cell, where uniform draws leave cells empty).
///
/// ```
/// use mit_star_samplers::HaltonSequence;
/// let mut halton = HaltonSequence::new(2, 7);
/// let mut p = [0.0; 2];
/// for _ in 0..100 {
///     halton.next_point(&mut p);
///     assert!(p.iter().all(|x| (0.0..1.0).contains(x)));
/// }
/// ```
#[derive(Debug, Clone)]
pub struct HaltonSequence {
    index: u64,
    bases: Vec<u64>,
    offsets: Vec<f64>,
}

impl HaltonSequence {
    /// The sequence in `dimension` coordinates, shifted by offsets drawn from `seed`.
    pub fn new(dimension: usize, seed: u64) -> Self {
        let mut rng = SeededRng::seed_from_u64(seed);
        Self {
            index: 0,
            bases: first_primes(dimension),
            offsets: (0..dimension).map(|_| rng.random::<f64>()).collect(),
        }
    }

    /// The plain sequence in `dimension` coordinates, without a shift: the same points for
    /// every seed, starting `(1/2, 1/3, 1/5, …)`. A planner drawing from it takes the same
    /// steps in every run (VAMP's planners draw this way, from its bases 3, 5, 7, …,
    /// restarting the sequence before each problem).
    pub fn unshifted(dimension: usize) -> Self {
        Self {
            index: 0,
            bases: first_primes(dimension),
            offsets: vec![0.0; dimension],
        }
    }

    /// Number of coordinates of a point.
    pub fn dimension(&self) -> usize {
        self.bases.len()
    }

    /// Writes the next point of `[0, 1)^d` into `out` (its first `d` entries).
    pub fn next_point(&mut self, out: &mut [f64]) {
        self.index += 1;
        for ((x, &base), offset) in out.iter_mut().zip(&self.bases).zip(&self.offsets) {
            let v = radical_inverse(self.index, base) + offset;
            *x = v - v.floor();
        }
    }
}

/// `i` written in `base` and mirrored about the point: `Σ digit_k · base^-(k+1)`.
fn radical_inverse(mut i: u64, base: u64) -> f64 {
    let step = 1.0 / base as f64;
    let (mut scale, mut value) = (step, 0.0);
    while i > 0 {
        value += (i % base) as f64 * scale;
        i /= base;
        scale *= step;
    }
    value
}

/// The first `n` primes.
fn first_primes(n: usize) -> Vec<u64> {
    let mut primes: Vec<u64> = Vec::with_capacity(n);
    let mut candidate = 2;
    while primes.len() < n {
        if primes
            .iter()
            .take_while(|&&p| p * p <= candidate)
            .all(|&p| candidate % p != 0)
        {
            primes.push(candidate);
        }
        candidate += 1;
    }
    primes
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radical_inverses_and_primes() {
        assert_eq!(first_primes(7), [2, 3, 5, 7, 11, 13, 17]);
        assert_eq!(radical_inverse(1, 2), 0.5);
        assert_eq!(radical_inverse(3, 2), 0.75);
        assert!((radical_inverse(5, 3) - (2.0 / 3.0 + 1.0 / 9.0)).abs() < 1e-15);
    }

    #[test]
    fn points_fill_the_cube_evenly() {
        // 1024 points of the unit square in a 16 × 16 grid of cells (4 expected per cell):
        // every cell gets 1 to 7, whatever the shift (independent uniform draws leave some
        // cells empty and others with 10 or more).
        for seed in 0..5 {
            let mut halton = HaltonSequence::new(2, seed);
            let mut cells = [0u32; 256];
            let mut p = [0.0; 2];
            for _ in 0..1024 {
                halton.next_point(&mut p);
                cells[(p[0] * 16.0) as usize * 16 + (p[1] * 16.0) as usize] += 1;
            }
            assert!(cells.iter().all(|&c| (1..=7).contains(&c)), "{cells:?}");
        }
    }

    #[test]
    fn the_unshifted_sequence_is_the_radical_inverses_of_the_point_index() {
        let mut halton = HaltonSequence::unshifted(3);
        let mut p = [0.0; 3];
        let expected = [
            [1.0 / 2.0, 1.0 / 3.0, 1.0 / 5.0],
            [1.0 / 4.0, 2.0 / 3.0, 2.0 / 5.0],
            [3.0 / 4.0, 1.0 / 9.0, 3.0 / 5.0],
        ];
        for point in expected {
            halton.next_point(&mut p);
            for (x, e) in p.iter().zip(point) {
                assert!((x - e).abs() < 1e-15, "{p:?} against {point:?}");
            }
        }
        // No seed and nothing shared: a second sequence starts again from the first point.
        let mut again = HaltonSequence::unshifted(3);
        again.next_point(&mut p);
        assert_eq!(p, [0.5, 1.0 / 3.0, 0.2]);
    }
}
