//! A fast hash for grid cells (three `i64`): the filters' hash maps hash one small key per
//! point, where the standard library's DoS-resistant SipHash would cost more than the rest of
//! the filter. The keys come from the cloud's coordinates, so a hostile cloud could at worst
//! slow the map down, never make it wrong.

use std::collections::{HashMap, HashSet};
use std::hash::{BuildHasherDefault, Hasher};

/// A grid cell: the floor of each coordinate divided by the cell size.
pub(super) type Cell = [i64; 3];

/// The cell of `p` for cells of `size` (`inverse = 1 / size`). Saturating casts: coordinates
/// beyond ±9·10¹⁸ cells share the border cells, which only merges far-away points' cells.
#[inline]
pub(super) fn cell_of(p: glam::Vec3, inverse: f64) -> Cell {
    let c = p.as_dvec3() * inverse;
    [c.x.floor() as i64, c.y.floor() as i64, c.z.floor() as i64]
}

/// Multiply–rotate hashing (the scheme of rustc's `FxHasher`).
#[derive(Debug, Default, Clone, Copy)]
pub(super) struct CellHasher(u64);

impl Hasher for CellHasher {
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut word = [0_u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            self.write_u64(u64::from_le_bytes(word));
        }
    }

    #[inline]
    fn write_u64(&mut self, value: u64) {
        self.0 = (self.0.rotate_left(5) ^ value).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }

    #[inline]
    fn write_i64(&mut self, value: i64) {
        self.write_u64(value as u64);
    }

    #[inline]
    fn write_usize(&mut self, value: usize) {
        self.write_u64(value as u64);
    }

    /// The state with its high bits folded into the low ones, which pick the bucket: the
    /// last multiplication leaves the low bits depending on the keys' low bits only.
    #[inline]
    fn finish(&self) -> u64 {
        self.0 ^ (self.0 >> 32)
    }
}

/// A set of cells.
pub(super) type CellSet = HashSet<Cell, BuildHasherDefault<CellHasher>>;

/// A map from cells.
pub(super) type CellMap<V> = HashMap<Cell, V, BuildHasherDefault<CellHasher>>;
