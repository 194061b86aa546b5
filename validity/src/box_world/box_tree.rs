//! [`BoxTree`]: a bounding-volume hierarchy over axis-aligned boxes in any dimension, so that a
//! world of 100 000 boxes answers "is this point in some box" in about a microsecond instead of
//! a linear scan.

use std::ops::ControlFlow;

/// Boxes per leaf: scanned linearly, like a small world.
const LEAF: usize = 8;

/// Deepest traversal stack: the tree is balanced (median splits), so its depth is
/// `⌈log₂(count / LEAF)⌉ + 1`, far below this for any count that fits in memory.
const STACK: usize = 64;

/// One node: its boxes (a range of the reordered rows) or its two children.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Node {
    /// First box (leaves) or left child (inner nodes).
    first: u32,
    /// Box count (leaves), or 0 for inner nodes (whose right child is `first + 1`'s sibling,
    /// stored in `right`).
    count: u32,
    /// Right child of an inner node.
    right: u32,
}

/// A bounding-volume hierarchy over boxes given as `[lo₀, hi₀, lo₁, hi₁, …]` rows (the world's
/// storage): median splits along the widest extent of the box centres, 8 boxes per leaf, every
/// node's bounds in one contiguous array. A query walks the nodes whose bounds contain the
/// point with a fixed-size stack (no allocation) and stops at the first containing box.
///
/// Built in `O(N log N)`; a query costs `O(log N)` node tests plus the boxes of the leaves whose
/// bounds contain the point — a few, for boxes that overlap little.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct BoxTree {
    dimension: usize,
    nodes: Vec<Node>,
    /// Per node, `2n` bounds `[lo₀, hi₀, …]`.
    bounds: Vec<f64>,
    /// The boxes' rows, reordered so that every leaf's boxes are contiguous.
    rows: Vec<f64>,
}

impl BoxTree {
    /// The hierarchy over `rows` (each box `2 · dimension` values).
    pub(crate) fn build(rows: &[f64], dimension: usize) -> Self {
        let width = 2 * dimension;
        let count = rows.len().checked_div(width).unwrap_or(0);
        let mut order: Vec<u32> = (0..count as u32).collect();
        let mut tree = Self {
            dimension,
            nodes: Vec::with_capacity(2 * count / LEAF + 1),
            bounds: Vec::with_capacity((2 * count / LEAF + 1) * width),
            rows: Vec::with_capacity(rows.len()),
        };
        if count > 0 {
            tree.split(rows, &mut order, 0, count);
        }
        tree
    }

    /// Builds the node over boxes `order[start..end]`; returns its index.
    fn split(&mut self, rows: &[f64], order: &mut [u32], start: usize, end: usize) -> u32 {
        let n = self.dimension;
        let width = 2 * n;
        let index = self.nodes.len() as u32;
        // Bounds of the boxes, and the spread of their centres per coordinate.
        let mut bounds: Vec<f64> = (0..width)
            .map(|i| {
                if i % 2 == 0 {
                    f64::INFINITY
                } else {
                    f64::NEG_INFINITY
                }
            })
            .collect();
        let mut centres = vec![(f64::INFINITY, f64::NEG_INFINITY); n];
        for &b in &order[start..end] {
            let row = &rows[b as usize * width..(b as usize + 1) * width];
            for d in 0..n {
                let (lo, hi) = (row[2 * d], row[2 * d + 1]);
                bounds[2 * d] = bounds[2 * d].min(lo);
                bounds[2 * d + 1] = bounds[2 * d + 1].max(hi);
                let c = 0.5 * (lo + hi);
                centres[d] = (centres[d].0.min(c), centres[d].1.max(c));
            }
        }
        self.bounds.extend_from_slice(&bounds);
        let count = end - start;
        if count <= LEAF {
            let first = (self.rows.len() / width) as u32;
            for &b in &order[start..end] {
                self.rows
                    .extend_from_slice(&rows[b as usize * width..(b as usize + 1) * width]);
            }
            self.nodes.push(Node {
                first,
                count: count as u32,
                right: 0,
            });
            return index;
        }
        let axis = (0..n)
            .max_by(|&a, &b| {
                let (x, y) = (centres[a].1 - centres[a].0, centres[b].1 - centres[b].0);
                x.total_cmp(&y)
            })
            .unwrap_or(0);
        let mid = start + count / 2;
        let centre = |b: &u32| {
            let row = &rows[*b as usize * width..];
            row[2 * axis] + row[2 * axis + 1]
        };
        order[start..end].select_nth_unstable_by(count / 2, |a, b| centre(a).total_cmp(&centre(b)));
        self.nodes.push(Node {
            first: 0,
            count: 0,
            right: 0,
        });
        let left = self.split(rows, order, start, mid);
        let right = self.split(rows, order, mid, end);
        self.nodes[index as usize] = Node {
            first: left,
            count: 0,
            right,
        };
        index
    }

    /// `true` if `point` lies in some box (closed, as the rows say).
    #[inline]
    pub(crate) fn contains(&self, point: &[f64]) -> bool {
        let inside = |bounds: &[f64]| {
            bounds
                .chunks_exact(2)
                .zip(point)
                .all(|(b, &x)| x >= b[0] && x <= b[1])
        };
        let width = 2 * self.dimension;
        match self.traverse(inside, |rows| {
            if rows.chunks_exact(width).any(inside) {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        }) {
            Traversal::Stopped(()) => true,
            Traversal::Complete => false,
            // Unreachable for a balanced tree; answer correctly anyway.
            Traversal::TooDeep => self.rows.chunks_exact(width).any(inside),
        }
    }

    /// Appends to `kept` the rows of every box that meets `reach` (`[lo, hi]` per coordinate,
    /// closed) and returns `true` — or returns `false`, with `kept` holding a partial list, as
    /// soon as more than `cap` boxes meet it (a per-edge broad phase that keeps that many boxes
    /// would gain nothing over the hierarchy per point).
    pub(crate) fn collect_meeting(&self, reach: &[f64], kept: &mut Vec<f64>, cap: usize) -> bool {
        let meets = |bounds: &[f64]| {
            bounds
                .chunks_exact(2)
                .zip(reach.chunks_exact(2))
                .all(|(b, r)| b[0] <= r[1] && b[1] >= r[0])
        };
        let width = 2 * self.dimension;
        let mut count = 0;
        let traversal = self.traverse(meets, |rows| {
            for row in rows.chunks_exact(width).filter(|row| meets(row)) {
                count += 1;
                if count > cap {
                    return ControlFlow::Break(());
                }
                kept.extend_from_slice(row);
            }
            ControlFlow::Continue(())
        });
        matches!(traversal, Traversal::Complete)
    }

    /// Visits, depth first with a fixed-size stack, every leaf whose bounds and whose
    /// ancestors' bounds pass `enters`, handing its rows to `visit` until that breaks.
    #[inline]
    fn traverse<B>(
        &self,
        enters: impl Fn(&[f64]) -> bool,
        mut visit: impl FnMut(&[f64]) -> ControlFlow<B>,
    ) -> Traversal<B> {
        if self.nodes.is_empty() {
            return Traversal::Complete;
        }
        let width = 2 * self.dimension;
        let mut stack = [0_u32; STACK];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let index = stack[top] as usize;
            if !enters(&self.bounds[index * width..(index + 1) * width]) {
                continue;
            }
            let node = self.nodes[index];
            if node.count > 0 {
                let first = node.first as usize;
                let leaf = &self.rows[first * width..(first + node.count as usize) * width];
                if let ControlFlow::Break(value) = visit(leaf) {
                    return Traversal::Stopped(value);
                }
            } else if top + 2 <= STACK {
                stack[top] = node.right;
                stack[top + 1] = node.first;
                top += 2;
            } else {
                return Traversal::TooDeep;
            }
        }
        Traversal::Complete
    }
}

/// How a [`BoxTree::traverse`] ended.
enum Traversal<B> {
    /// Every leaf it entered was visited.
    Complete,
    /// A visit broke with this value.
    Stopped(B),
    /// The stack was too small (not for a balanced tree).
    TooDeep,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agrees_with_a_scan_on_a_grid_of_points() {
        let n = 3;
        let mut rows = Vec::new();
        let mut seed = 7_u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..500 {
            for _ in 0..n {
                let (c, w) = (next() - 0.5, 0.1 * next());
                rows.extend([c - w, c + w]);
            }
        }
        let tree = BoxTree::build(&rows, n);
        let scan = |p: &[f64]| {
            rows.chunks_exact(2 * n).any(|r| {
                r.chunks_exact(2)
                    .zip(p)
                    .all(|(b, &x)| x >= b[0] && x <= b[1])
            })
        };
        for _ in 0..5000 {
            let p = [next() - 0.5, next() - 0.5, next() - 0.5];
            assert_eq!(tree.contains(&p), scan(&p), "{p:?}");
        }
        assert!(!BoxTree::build(&[], n).contains(&[0.0; 3]));
    }
}
