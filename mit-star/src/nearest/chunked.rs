//! [`Chunked`]: a growable array in fixed-size chunks, so that growing it never moves (copies)
//! what it already holds.

use std::ops::{Index, IndexMut};

/// Items per chunk (a power of two: the chunk of item `i` is `i >> SHIFT`).
const SHIFT: usize = 10;
const CHUNK: usize = 1 << SHIFT;

/// A per-vertex array of the random geometric graph, in chunks of 1024 items, each allocated
/// once at its full size.
///
/// A `Vec` doubles its buffer as it grows and copies everything into the new one, page faults
/// included, in one step no termination condition can interrupt: in a graph of tens of
/// thousands of vertices that is milliseconds, the late runs of the deadline stress matrix
/// (`docs/guide/src/reference/reliability.md`, "Unpolled work at the start of a batch"). Here a push costs at most one
/// chunk allocation (of at most 1024 items), and an index one more load than a `Vec`'s.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Chunked<T> {
    chunks: Vec<Vec<T>>,
    len: usize,
}

impl<T> Default for Chunked<T> {
    fn default() -> Self {
        Self {
            chunks: Vec::new(),
            len: 0,
        }
    }
}

impl<T> Chunked<T> {
    /// An empty array.
    pub(crate) fn new() -> Self {
        Self::default()
    }

    /// Number of items.
    #[inline]
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Appends `item`; returns its index.
    #[inline]
    pub(crate) fn push(&mut self, item: T) -> usize {
        if self.len >> SHIFT == self.chunks.len() {
            self.chunks.push(Vec::with_capacity(CHUNK));
        }
        self.chunks[self.len >> SHIFT].push(item);
        self.len += 1;
        self.len - 1
    }

    /// The item at `index`, if there is one.
    #[inline]
    pub(crate) fn get(&self, index: usize) -> Option<&T> {
        self.chunks
            .get(index >> SHIFT)
            .and_then(|c| c.get(index & (CHUNK - 1)))
    }

    /// Makes room for `additional` more items in the list of chunks (the chunks themselves are
    /// allocated as items arrive: allocating a million items' chunks at once is itself a stall).
    pub(crate) fn reserve(&mut self, additional: usize) {
        let chunks = (self.len + additional).div_ceil(CHUNK);
        self.chunks
            .reserve(chunks.saturating_sub(self.chunks.len()));
    }

    /// The items from `start` on, in order.
    pub(crate) fn iter_from(&self, start: usize) -> impl Iterator<Item = &T> + '_ {
        let first = start >> SHIFT;
        self.chunks
            .iter()
            .skip(first)
            .enumerate()
            .flat_map(move |(i, c)| {
                let skip = if i == 0 { start & (CHUNK - 1) } else { 0 };
                c.iter().skip(skip)
            })
    }
}

impl<T> FromIterator<T> for Chunked<T> {
    fn from_iter<I: IntoIterator<Item = T>>(items: I) -> Self {
        let mut c = Self::new();
        for item in items {
            c.push(item);
        }
        c
    }
}

impl<T> Extend<T> for Chunked<T> {
    fn extend<I: IntoIterator<Item = T>>(&mut self, items: I) {
        for item in items {
            self.push(item);
        }
    }
}

impl<T> Index<usize> for Chunked<T> {
    type Output = T;

    #[inline]
    fn index(&self, index: usize) -> &T {
        &self.chunks[index >> SHIFT][index & (CHUNK - 1)]
    }
}

impl<T> IndexMut<usize> for Chunked<T> {
    #[inline]
    fn index_mut(&mut self, index: usize) -> &mut T {
        &mut self.chunks[index >> SHIFT][index & (CHUNK - 1)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn items_across_chunks_stay_where_they_were_put() {
        let mut c: Chunked<u64> = Chunked::new();
        for i in 0..3000 {
            assert_eq!(c.push(i * 7), i as usize);
        }
        assert_eq!(c.len(), 3000);
        assert_eq!(c[0], 0);
        assert_eq!(c[1024], 7168);
        assert_eq!(c[2999], 20993);
        c[1500] = 1;
        assert_eq!(c[1500], 1);
        assert_eq!(c.get(2999), Some(&20993));
        assert_eq!(c.get(3000), None);
        assert_eq!(c.get(1 << 40), None);
        assert!(c.chunks.iter().all(|v| v.capacity() == CHUNK));
    }

    #[test]
    fn growing_moves_nothing() {
        let mut c: Chunked<u32> = (0..1000).collect();
        let first = c.chunks[0].as_ptr();
        c.reserve(5000);
        assert!(c.chunks.capacity() >= 6);
        assert_eq!(c.len(), 1000);
        c.extend(1000..6000);
        assert_eq!(c.chunks.len(), 6);
        assert_eq!(c.chunks[0].as_ptr(), first);
        assert!((0..6000).all(|i| c[i] == i as u32));
    }

    #[test]
    fn iterating_from_any_start_yields_the_tail() {
        let c: Chunked<u32> = (0..2500).collect();
        for start in [0, 1, 1023, 1024, 1025, 2047, 2048, 2499, 2500, 9999] {
            let tail: Vec<u32> = c.iter_from(start).copied().collect();
            let expected: Vec<u32> = (start.min(2500) as u32..2500).collect();
            assert_eq!(tail, expected, "from {start}");
        }
    }
}
