//! [`BoxSet`]: one kind of box of a [`World`](crate::World) — its obstacles or its
//! anti-obstacles — with the contiguous rows the checks scan and the hierarchy large sets use,
//! shared between clones.

use std::sync::{Arc, OnceLock};

use crate::box_world::box_tree::BoxTree;
use crate::box_world::slab_index::SlabIndex;
use crate::box_world::world::{AxisBox, TREE_THRESHOLD};

/// Boxes, their rows (`[lo, hi]` per dimension, box after box, widened by PDT's epsilon) and
/// the indices over the rows (a hierarchy or a slab index), built on first use after the last
/// change or by [`BoxSet::build_indices`].
///
/// Every planner clones its problem's world, and that clone counts against its budget; so the
/// three live behind one [`Arc`] and a clone costs the same for 35 boxes as for 100 000 (a deep
/// copy of 10⁵ boxes took 13 ms). A change to a shared set copies its boxes and rows and
/// leaves the other clones as they were.
#[derive(Debug, Clone, Default)]
pub(crate) struct BoxSet(Arc<Boxes>);

#[derive(Debug, Clone, Default)]
struct Boxes {
    boxes: Vec<AxisBox>,
    rows: Vec<f64>,
    /// The smallest full side of any box, kept as boxes are added: a planner's construction
    /// asks for it (is the step finer than every obstacle?), and a scan of 10⁵ boxes in 32
    /// dimensions took 3–6 ms of a 1 ms budget.
    thinnest: Option<f64>,
    tree: OnceLock<BoxTree>,
    slabs: OnceLock<Option<SlabIndex>>,
}

impl BoxSet {
    /// The boxes, in insertion order.
    pub(crate) fn boxes(&self) -> &[AxisBox] {
        &self.0.boxes
    }

    /// The boxes as rows of `2n` bounds.
    #[inline]
    pub(crate) fn rows(&self) -> &[f64] {
        &self.0.rows
    }

    /// The smallest full side of any box (`None` for no boxes, or boxes of no dimension).
    pub(crate) fn thinnest(&self) -> Option<f64> {
        self.0.thinnest
    }

    /// Appends a box (already validated); the hierarchy is rebuilt on its next use.
    pub(crate) fn push(&mut self, b: AxisBox) {
        if Arc::get_mut(&mut self.0).is_none() {
            // Shared: copy the boxes and rows, not the indices this change invalidates.
            self.0 = Arc::new(Boxes {
                boxes: self.0.boxes.clone(),
                rows: self.0.rows.clone(),
                thinnest: self.0.thinnest,
                ..Boxes::default()
            });
        }
        let inner = Arc::make_mut(&mut self.0);
        for (&c, &w) in b.center.iter().zip(&b.widths) {
            let half = 0.5 * w + f64::EPSILON;
            inner.rows.push(c - half);
            inner.rows.push(c + half);
        }
        inner.thinnest = inner
            .thinnest
            .into_iter()
            .chain(b.widths.iter().copied())
            .reduce(f64::min);
        inner.boxes.push(b);
        inner.tree = OnceLock::new();
        inner.slabs = OnceLock::new();
    }

    /// `true` for sets a scan of the rows checks as fast as an index: at most
    /// [`TREE_THRESHOLD`] boxes (or no dimension).
    #[inline]
    fn scanned(&self, dimension: usize) -> bool {
        dimension == 0 || self.0.rows.len() <= TREE_THRESHOLD * 2 * dimension
    }

    /// The hierarchy over the rows in `dimension` dimensions, built now if not yet; `None` for
    /// sets a scan checks as fast.
    #[inline]
    pub(crate) fn hierarchy(&self, dimension: usize) -> Option<&BoxTree> {
        if self.scanned(dimension) {
            return None;
        }
        Some(
            self.0
                .tree
                .get_or_init(|| BoxTree::build(&self.0.rows, dimension)),
        )
    }

    /// Builds now the slab index or the hierarchy that checks in `dimension` dimensions use.
    pub(crate) fn build_indices(&self, dimension: usize) {
        if self.slabs(dimension).is_none() {
            self.hierarchy(dimension);
        }
    }

    /// The slab index over the rows in `dimension` dimensions, built now if not yet, for sets
    /// it checks better than the hierarchy ([`SlabIndex::serves`]); `None` for the others.
    #[inline]
    pub(crate) fn slabs(&self, dimension: usize) -> Option<&SlabIndex> {
        if self.scanned(dimension) {
            return None;
        }
        self.0
            .slabs
            .get_or_init(|| SlabIndex::if_it_serves(&self.0.rows, dimension))
            .as_ref()
    }
}

/// Sets are equal when they hold the same boxes (rows and hierarchy follow from them).
impl PartialEq for BoxSet {
    fn eq(&self, other: &Self) -> bool {
        self.0.boxes == other.0.boxes
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clones_share_the_boxes_and_the_hierarchy_until_one_changes() {
        // A planner clones its problem's world; with 10⁵ boxes a deep copy took 13 ms of the
        // planning budget. Clones share the boxes, their rows and the built hierarchy.
        let mut set = BoxSet::default();
        let count = 2 * TREE_THRESHOLD;
        for i in 0..count {
            let x = -0.45 + 0.9 * i as f64 / count as f64;
            set.push(AxisBox::new(vec![x, 0.0], vec![0.001, 0.5]));
        }
        let built: *const BoxTree = set.hierarchy(2).expect("a hierarchy above the threshold");
        let copy = set.clone();
        assert!(Arc::ptr_eq(&set.0, &copy.0));
        assert!(std::ptr::eq(copy.0.tree.get().unwrap(), built));
        // Changing the copy leaves the original as it was.
        let mut copy = copy;
        copy.push(AxisBox::new(vec![0.0, 0.4], vec![0.9, 0.01]));
        assert!(copy.0.tree.get().is_none());
        assert!(copy.hierarchy(2).unwrap().contains(&[0.001, 0.4]));
        assert!(!set.hierarchy(2).unwrap().contains(&[0.001, 0.4]));
        assert_eq!((set.boxes().len(), copy.boxes().len()), (count, count + 1));
        assert_eq!(set.rows().len(), 4 * count);
        assert_eq!(
            (set.thinnest(), copy.thinnest()),
            (Some(0.001), Some(0.001))
        );
        assert_eq!(BoxSet::default().thinnest(), None);
        assert!(std::ptr::eq(set.hierarchy(2).unwrap(), built));
    }
}
