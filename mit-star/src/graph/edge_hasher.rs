//! [`EdgeHasher`]: a fast, deterministic hasher for the packed `(source, target)` keys of
//! queued edges.

use std::hash::{BuildHasherDefault, Hasher};

/// Multiplicative hashing of one `u64` (the packed vertex pair of an edge). Deterministic —
/// no per-process random state — so maps behave identically in every run and thread.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct EdgeHasher(u64);

impl Hasher for EdgeHasher {
    #[inline]
    fn finish(&self) -> u64 {
        self.0
    }

    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    #[inline]
    fn write_u64(&mut self, x: u64) {
        // Fold the halves, then a Fibonacci multiply spreads the bits into the high ones that
        // hashbrown uses for its control bytes.
        let folded = (self.0 ^ x ^ (x >> 29)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        self.0 = folded ^ (folded >> 32);
    }
}

/// Builds [`EdgeHasher`]s.
pub(crate) type BuildEdgeHasher = BuildHasherDefault<EdgeHasher>;

/// The key of the edge `source → target`.
#[inline]
pub(crate) fn edge_key(source: u32, target: u32) -> u64 {
    (u64::from(source) << 32) | u64::from(target)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    #[test]
    fn keys_are_distinct_and_maps_work() {
        assert_ne!(edge_key(1, 2), edge_key(2, 1));
        let mut map: HashMap<u64, u32, BuildEdgeHasher> = HashMap::default();
        for s in 0..200u32 {
            for t in 0..50u32 {
                map.insert(edge_key(s, t), s * 50 + t);
            }
        }
        assert_eq!(map.len(), 10_000);
        assert_eq!(map[&edge_key(199, 49)], 199 * 50 + 49);
    }
}
