//! [`StateChunks`]: the graph's states in fixed-size contiguous chunks, so adding a state never
//! moves the others.

use std::ops::{Index, IndexMut};

/// States per chunk (a power of two: the chunk of state `i` is `i >> SHIFT`).
const SHIFT: usize = 10;
const CHUNK: usize = 1 << SHIFT;

/// The random geometric graph's states, by vertex id: contiguous within chunks of 1024 states,
/// each chunk allocated once at its full size. A `Vec<f64>` of every state would double its
/// buffer as samples arrive, copying tens of megabytes (page faults included) in one piece that
/// no termination condition can interrupt — 1 to 11 ms past a 0.1 s deadline in `R^32`, as the
/// deadline stress matrix measured. Here a new state costs at most one chunk allocation.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct StateChunks {
    dimension: usize,
    chunks: Vec<Vec<f64>>,
    len: usize,
}

impl StateChunks {
    /// No states, of `dimension` coordinates each.
    pub(crate) fn new(dimension: usize) -> Self {
        Self {
            dimension,
            chunks: Vec::new(),
            len: 0,
        }
    }

    /// Number of states.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Appends a state; returns its index.
    pub(crate) fn push(&mut self, state: &[f64]) -> usize {
        debug_assert_eq!(state.len(), self.dimension);
        if self.len >> SHIFT == self.chunks.len() {
            self.chunks.push(Vec::with_capacity(CHUNK * self.dimension));
        }
        self.chunks[self.len >> SHIFT].extend_from_slice(state);
        self.len += 1;
        self.len - 1
    }
}

impl Index<usize> for StateChunks {
    type Output = [f64];

    #[inline]
    fn index(&self, index: usize) -> &[f64] {
        let n = self.dimension;
        let start = (index & (CHUNK - 1)) * n;
        &self.chunks[index >> SHIFT][start..start + n]
    }
}

impl IndexMut<usize> for StateChunks {
    #[inline]
    fn index_mut(&mut self, index: usize) -> &mut [f64] {
        let n = self.dimension;
        let start = (index & (CHUNK - 1)) * n;
        &mut self.chunks[index >> SHIFT][start..start + n]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn states_across_chunks_stay_where_they_were_put() {
        let mut s = StateChunks::new(3);
        for i in 0..3000 {
            let x = f64::from(i);
            assert_eq!(s.push(&[x, -x, 0.5 * x]), i as usize);
        }
        assert_eq!(s.len(), 3000);
        assert_eq!(&s[0], &[0.0, -0.0, 0.0]);
        assert_eq!(&s[1024], &[1024.0, -1024.0, 512.0]);
        assert_eq!(&s[2999], &[2999.0, -2999.0, 1499.5]);
        s[1500].copy_from_slice(&[1.0, 2.0, 3.0]);
        assert_eq!(&s[1500], &[1.0, 2.0, 3.0]);
        assert_eq!(s.chunks.len(), 3);
        assert!(s.chunks.iter().all(|c| c.capacity() == CHUNK * 3));
    }
}
