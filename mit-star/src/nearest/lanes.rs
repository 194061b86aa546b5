//! Coordinates by groups of four points, one row per coordinate, and the kernels that compute
//! a group's four squared distances to a query at once (one `f64x4` per coordinate). Used by
//! the kd-trees' leaf scans and the forest's buffer of pending points.

use wide::f64x4;

/// Points per group: one `f64x4` register under AVX.
pub(crate) const GROUP: usize = 4;

/// A group's four squared distances to `query`; `rows` holds one row per coordinate (unused
/// places of a group hold NaN, whose distance is NaN and compares false with everything).
/// Bit for bit what [`squared_distance`](crate::nearest::kd_tree::squared_distance) returns
/// for each point: coordinate `c` adds to partial sum `c mod 4`, in order, and the sums are
/// added pairwise. Common dimensions get a kernel whose loops unroll completely. This chooses
/// the kernel at every call, as a tree's leaf scan needs; the pending buffer's scan chooses
/// once per scan and calls [`distances_fixed`] and [`distances_any`] itself (choosing per
/// group there cost RRT-Connect 1.7 % more instructions on the Panda).
#[inline]
pub(crate) fn group_distances(rows: &[[f64; GROUP]], query: &[f64]) -> [f64; GROUP] {
    macro_rules! fixed {
        ($($n:literal)*) => {
            match query.len() {
                $($n => match <&[f64; $n]>::try_from(query) {
                    Ok(query) => distances_fixed(rows, query),
                    Err(_) => distances_any(rows, query),
                },)*
                _ => distances_any(rows, query),
            }
        };
    }
    fixed!(2 3 4 5 6 7 8 9 10 11 12 13 14 15 16)
}

/// [`group_distances`] for points of `N` coordinates: every sum stays in a register.
#[inline(always)]
pub(crate) fn distances_fixed<const N: usize>(
    rows: &[[f64; GROUP]],
    query: &[f64; N],
) -> [f64; GROUP] {
    let mut sums = [f64x4::ZERO; 4];
    for (c, (&row, &q)) in rows[..N].iter().zip(query).enumerate() {
        let t = f64x4::from(row) - f64x4::splat(q);
        sums[c % 4] += t * t;
    }
    total(sums)
}

/// [`group_distances`] for any number of coordinates.
#[inline(always)]
pub(crate) fn distances_any(rows: &[[f64; GROUP]], query: &[f64]) -> [f64; GROUP] {
    let mut sums = [f64x4::ZERO; 4];
    for (c, (&row, &q)) in rows.iter().zip(query).enumerate() {
        let t = f64x4::from(row) - f64x4::splat(q);
        sums[c % 4] += t * t;
    }
    total(sums)
}

/// The four squared distances from the partial sums, added pairwise.
#[inline(always)]
fn total(sums: [f64x4; 4]) -> [f64; GROUP] {
    ((sums[0] + sums[1]) + (sums[2] + sums[3])).to_array()
}

/// Appends point `position` (`point`, its coordinates) to `lanes`, the rows of the groups of
/// the positions before it: a new group (NaN-filled) starts at every fourth position.
#[inline]
pub(crate) fn push_point(lanes: &mut Vec<[f64; GROUP]>, position: usize, point: &[f64]) {
    let (group, place) = (position / GROUP, position % GROUP);
    let n = point.len();
    if place == 0 {
        lanes.resize((group + 1) * n, [f64::NAN; GROUP]);
    }
    for (row, &x) in lanes[group * n..(group + 1) * n].iter_mut().zip(point) {
        row[place] = x;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nearest::kd_tree::squared_distance;

    #[test]
    fn group_distances_are_the_pointwise_ones_bit_for_bit() {
        for n in [1_usize, 2, 3, 4, 7, 8, 12, 16, 17, 33] {
            let points: Vec<Vec<f64>> = (0..7)
                .map(|i| {
                    (0..n)
                        .map(|c| ((i * 31 + c * 17) as f64).sin() * 3.7)
                        .collect()
                })
                .collect();
            let query: Vec<f64> = (0..n).map(|c| (c as f64 * 0.37).cos()).collect();
            let mut lanes = Vec::new();
            for (i, p) in points.iter().enumerate() {
                push_point(&mut lanes, i, p);
            }
            assert_eq!(lanes.len(), 2 * n);
            for (g, rows) in lanes.chunks_exact(n).enumerate() {
                let d = group_distances(rows, &query);
                for (j, &dj) in d.iter().enumerate() {
                    match points.get(g * GROUP + j) {
                        Some(p) => {
                            assert_eq!(dj.to_bits(), squared_distance(&query, p).to_bits());
                        }
                        None => assert!(dj.is_nan(), "an unused place compares false"),
                    }
                }
            }
        }
    }
}
