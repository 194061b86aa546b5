//! [`Neighbours`]: the reusable result buffer of nearest-neighbour queries.

/// The result buffer of a k-nearest query: `(squared distance, id)` pairs sorted nearest first.
///
/// Reuse one buffer across queries: it keeps its allocation, so warm queries do not allocate.
#[derive(Debug, Clone, Default)]
pub struct Neighbours {
    pub(crate) k: usize,
    items: Vec<(f64, u32)>,
    /// Per-dimension squared offsets of the current cell (scratch of the incremental bound).
    pub(crate) offsets: Vec<f64>,
}

impl Neighbours {
    /// An empty buffer.
    pub fn new() -> Self {
        Self::default()
    }

    /// Starts a query for the `k` nearest points.
    pub(crate) fn reset(&mut self, k: usize) {
        self.k = k;
        self.items.clear();
    }

    /// The squared distance a candidate must beat to enter (∞ while fewer than `k` are held).
    #[inline]
    pub(crate) fn worst(&self) -> f64 {
        if self.items.len() < self.k {
            f64::INFINITY
        } else {
            self.items[self.k - 1].0
        }
    }

    /// Offers a candidate; keeps the `k` nearest by `(distance, id)`.
    #[inline]
    pub(crate) fn offer(&mut self, distance: f64, id: u32) {
        if self.k == 0 {
            return;
        }
        let full = self.items.len() >= self.k;
        if full {
            let (d, i) = self.items[self.k - 1];
            if (distance, id) >= (d, i) {
                return;
            }
            self.items.pop();
        }
        // Insertion into a short sorted array: faster than a heap for the k of an RGG.
        let mut at = self.items.len();
        while at > 0 && (distance, id) < self.items[at - 1] {
            at -= 1;
        }
        self.items.insert(at, (distance, id));
    }

    /// The `(squared distance, id)` pairs found, nearest first.
    pub fn iter(&self) -> std::slice::Iter<'_, (f64, u32)> {
        self.items.iter()
    }

    /// Number of neighbours found.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    /// `true` if nothing was found.
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// Sorts the held items nearest first (radius queries collect them unsorted).
    pub(crate) fn sort(&mut self) {
        self.items
            .sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    }

    /// Appends an item without ordering (radius queries).
    #[inline]
    pub(crate) fn push_unordered(&mut self, distance: f64, id: u32) {
        self.items.push((distance, id));
    }
}
