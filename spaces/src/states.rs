//! [`States`]: contiguous storage for many states of one dimension.

use std::ops::{Index, IndexMut};

/// Many states of one dimension in one `Vec<f64>` (row-major: state `i` is
/// `data[i·n .. (i+1)·n]`). Pushing amortises allocation; reading a state is a slice, so hot loops
/// over states never allocate or chase pointers.
///
/// ```
/// use mit_star_spaces::States;
/// let mut states = States::new(2);
/// let a = states.push(&[0.0, 1.0]);
/// let b = states.push(&[2.0, 3.0]);
/// assert_eq!(&states[b], &[2.0, 3.0]);
/// assert_eq!(states.len(), 2);
/// assert_eq!(states.iter().map(|s| s[0]).sum::<f64>(), 2.0);
/// # let _ = a;
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
pub struct States {
    dimension: usize,
    data: Vec<f64>,
}

impl States {
    /// Empty storage for states of `dimension` coordinates.
    pub fn new(dimension: usize) -> Self {
        Self {
            dimension,
            data: Vec::new(),
        }
    }

    /// Empty storage with room for `capacity` states.
    pub fn with_capacity(dimension: usize, capacity: usize) -> Self {
        Self {
            dimension,
            data: Vec::with_capacity(dimension * capacity),
        }
    }

    /// Coordinates per state.
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// Number of states stored.
    pub fn len(&self) -> usize {
        self.data.len().checked_div(self.dimension).unwrap_or(0)
    }

    /// `true` if no state is stored.
    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }

    /// Appends a state and returns its index.
    ///
    /// # Panics
    /// If `state.len()` differs from the dimension (a programming error, not bad input).
    pub fn push(&mut self, state: &[f64]) -> usize {
        assert_eq!(state.len(), self.dimension, "state of wrong dimension");
        self.data.extend_from_slice(state);
        self.len() - 1
    }

    /// Appends a zeroed state and returns a mutable view of it, for samplers that write in place.
    pub fn push_zeroed(&mut self) -> &mut [f64] {
        let start = self.data.len();
        self.data.resize(start + self.dimension, 0.0);
        &mut self.data[start..]
    }

    /// Removes the last state.
    pub fn pop(&mut self) {
        let len = self.data.len().saturating_sub(self.dimension);
        self.data.truncate(len);
    }

    /// The state at `index`, if any.
    pub fn get(&self, index: usize) -> Option<&[f64]> {
        let start = index.checked_mul(self.dimension)?;
        self.data.get(start..start + self.dimension)
    }

    /// Moves the last state into slot `index` and shrinks by one (O(n), order not kept).
    pub fn swap_remove(&mut self, index: usize) {
        let last = self.len() - 1;
        if index != last {
            let n = self.dimension;
            self.data.copy_within(last * n..(last + 1) * n, index * n);
        }
        self.pop();
    }

    /// Removes every state, keeping the allocation.
    pub fn clear(&mut self) {
        self.data.clear();
    }

    /// Iterates over the states in index order.
    pub fn iter(&self) -> std::slice::ChunksExact<'_, f64> {
        self.data.chunks_exact(self.dimension.max(1))
    }

    /// All coordinates, state after state.
    pub fn as_flat(&self) -> &[f64] {
        &self.data
    }
}

impl Index<usize> for States {
    type Output = [f64];
    #[inline]
    fn index(&self, index: usize) -> &[f64] {
        &self.data[index * self.dimension..(index + 1) * self.dimension]
    }
}

impl IndexMut<usize> for States {
    #[inline]
    fn index_mut(&mut self, index: usize) -> &mut [f64] {
        &mut self.data[index * self.dimension..(index + 1) * self.dimension]
    }
}

#[cfg(test)]
mod tests {
    use super::States;

    #[test]
    fn push_get_swap_remove() {
        let mut s = States::with_capacity(3, 4);
        for i in 0..4 {
            let i = f64::from(i);
            s.push(&[i, i + 0.5, -i]);
        }
        s.swap_remove(1);
        assert_eq!(s.len(), 3);
        assert_eq!(&s[1], &[3.0, 3.5, -3.0]);
        assert_eq!(s.get(3), None);
        s.push_zeroed()[2] = 7.0;
        assert_eq!(&s[3], &[0.0, 0.0, 7.0]);
        s.pop();
        assert_eq!(s.iter().count(), 3);
    }
}
