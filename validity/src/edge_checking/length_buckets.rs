//! [`LengthBuckets`]: edge checks and the grid points they tested, by edge length.

/// Upper bounds (exclusive) of the first four length buckets, in an edge's grid points (the
/// interior points of its grid, `⌈d / L⌉ − 1`);
/// the fifth bucket holds everything longer. At the paper's resolution (`L = 5·10⁻⁶` of the
/// maximum extent) they are edges shorter than 1 %, 5 %, 25 % and 125 % of the maximum extent;
/// 2 000 points is also the length-related checker's initial spacing `Δ₀ = 2000 L`, so the
/// first bucket holds the edges it checks once at level 0.
pub const LENGTH_BUCKET_BOUNDS: [u64; 4] = [2_000, 10_000, 50_000, 250_000];

/// Labels of the five buckets, for output columns ("sparse checks of edges {label}"); numbers
/// without decimal points, since OMPL's log reader makes SQL column names of them.
pub const LENGTH_BUCKET_LABELS: [&str; 5] = [
    "under 2e3 points",
    "of 2e3 to 1e4 points",
    "of 1e4 to 5e4 points",
    "of 5e4 to 25e4 points",
    "of 25e4 points and more",
];

/// Sparse and full edge checks and the grid points they tested, by the edge's length in grid
/// points ([`LENGTH_BUCKET_BOUNDS`]): where a checker spends its work.
///
/// ```
/// use mit_star_validity::LengthBuckets;
/// let mut buckets = LengthBuckets::default();
/// buckets.count_sparse(1_500, 1);
/// buckets.count_sparse(30_000, 15);
/// buckets.count_full(30_000, 29_985);
/// assert_eq!(buckets.sparse_checks, [1, 0, 1, 0, 0]);
/// assert_eq!(buckets.sparse_points, [1, 0, 15, 0, 0]);
/// assert_eq!(buckets.full_points[2], 29_985);
/// assert_eq!(LengthBuckets::bucket(250_000), 4);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LengthBuckets {
    /// Sparse checks per bucket.
    pub sparse_checks: [u64; 5],
    /// Grid points tested by sparse checks per bucket.
    pub sparse_points: [u64; 5],
    /// Full checks per bucket.
    pub full_checks: [u64; 5],
    /// Grid points tested by full checks per bucket.
    pub full_points: [u64; 5],
}

impl LengthBuckets {
    /// The bucket of an edge of `points` grid points.
    #[inline]
    pub fn bucket(points: u64) -> usize {
        LENGTH_BUCKET_BOUNDS
            .iter()
            .position(|&bound| points < bound)
            .unwrap_or(LENGTH_BUCKET_BOUNDS.len())
    }

    /// Counts a sparse check of an edge of `points` grid points that tested `tested` of them.
    #[inline]
    pub fn count_sparse(&mut self, points: u64, tested: u64) {
        let b = Self::bucket(points);
        self.sparse_checks[b] += 1;
        self.sparse_points[b] += tested;
    }

    /// Counts a full check of an edge of `points` grid points that tested `tested` of them.
    #[inline]
    pub fn count_full(&mut self, points: u64, tested: u64) {
        let b = Self::bucket(points);
        self.full_checks[b] += 1;
        self.full_points[b] += tested;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_split_the_buckets() {
        assert_eq!(LengthBuckets::bucket(0), 0);
        assert_eq!(LengthBuckets::bucket(1_999), 0);
        assert_eq!(LengthBuckets::bucket(2_000), 1);
        assert_eq!(LengthBuckets::bucket(49_999), 2);
        assert_eq!(LengthBuckets::bucket(u64::MAX), 4);
        assert_eq!(LENGTH_BUCKET_LABELS.len(), LENGTH_BUCKET_BOUNDS.len() + 1);
    }
}
