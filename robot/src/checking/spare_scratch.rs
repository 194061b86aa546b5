//! The scratch buffers of dropped [`ArmChecker`](crate::ArmChecker)s, kept on their thread
//! for the next clone.
//!
//! Building a planner clones its problem's checker, and a clone needs its own scratch (about
//! 23 KB on the Panda at sixteen lanes, in a dozen allocations, written through once). A
//! program that plans again and again on one thread — a benchmark, a robot's planning loop —
//! drops a planner, and with it a checker, before it builds the next one: the buffers of the
//! dropped checker are kept here and handed to the next clone of the same shape instead of
//! being freed and allocated again. On the Panda that took RRT-Connect's construction in
//! `mit-star bench` from 17.7 to 16.2 µs and its solve from 68.4 to 65.3 µs, with the same
//! decisions (`benches/tools/interleaved_bench.sh`; the figures and commands are in the arm
//! reference beside VAMP).
//!
//! A thread keeps at most [`KEPT`] spares; one taken from here is [reset](Scratch::reset), so
//! no check depends on what the previous owner did.

use std::cell::RefCell;

use crate::checking::arm_checker::{Scratch, ScratchShape};

/// Spare scratches a thread keeps at most: a few checkers of different robots planned on one
/// thread in turn each find theirs, and no more than about 100 KB are held.
const KEPT: usize = 4;

thread_local! {
    /// This thread's spares, most recently dropped last.
    static SPARES: RefCell<Vec<Scratch>> = const { RefCell::new(Vec::new()) };
}

/// A spare scratch of `shape` from this thread, reset, or new buffers of that shape if it
/// keeps none.
pub(crate) fn take(shape: ScratchShape) -> Scratch {
    let spare = SPARES
        .try_with(|spares| {
            let mut spares = spares.try_borrow_mut().ok()?;
            let at = spares.iter().rposition(|s| s.shape() == shape)?;
            Some(spares.swap_remove(at))
        })
        .ok()
        .flatten();
    match spare {
        Some(mut scratch) => {
            scratch.reset();
            scratch
        }
        None => Scratch::new(shape),
    }
}

/// Keeps `scratch` for a later [`take`] on this thread, unless the thread already keeps
/// [`KEPT`] (or is ending): then it is freed.
pub(crate) fn give(scratch: Scratch) {
    if scratch.shape() == ScratchShape::default() {
        return;
    }
    // Dropped here if the thread is ending or keeps enough.
    let _ = SPARES.try_with(|spares| {
        if let Ok(mut spares) = spares.try_borrow_mut()
            && spares.len() < KEPT
        {
            spares.push(scratch);
        }
    });
}

/// How many spares this thread keeps (tests).
#[cfg(test)]
pub(crate) fn kept() -> usize {
    SPARES.with(|spares| spares.borrow().len())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shape(dimension: usize) -> ScratchShape {
        ScratchShape {
            links: 10,
            spheres: 40,
            entries: 8,
            dimension,
            candidates: 3,
            pairs: 12,
        }
    }

    #[test]
    fn a_given_scratch_comes_back_for_its_shape_only() {
        std::thread::spawn(|| {
            give(Scratch::new(shape(7)));
            assert_eq!(kept(), 1);
            // Another shape: new buffers, the spare stays.
            assert_eq!(take(shape(6)).shape(), shape(6));
            assert_eq!(kept(), 1);
            assert_eq!(take(shape(7)).shape(), shape(7));
            assert_eq!(kept(), 0);
        })
        .join()
        .unwrap();
    }

    #[test]
    fn a_recycled_scratch_keeps_no_hint_of_its_previous_owner() {
        std::thread::spawn(|| {
            let mut used = Scratch::new(shape(7));
            used.lanes.last_hit = 5;
            used.certify.stop_at_for_tests((0.25, 0.5));
            give(used);
            let again = take(shape(7));
            assert_eq!(kept(), 0);
            assert_eq!(again.lanes.last_hit, usize::MAX);
            assert!(!again.certify.stopped_for_tests());
        })
        .join()
        .unwrap();
    }

    #[test]
    fn the_empty_scratch_holds_no_buffer() {
        let empty = Scratch::default();
        assert_eq!(empty.lanes.lane_centers.capacity(), 0);
        assert_eq!(empty.lanes.candidates.0.capacity(), 0);
        assert!(empty.certify.holds_nothing_for_tests());
    }

    #[test]
    fn a_thread_keeps_at_most_kept_spares_and_none_empty() {
        std::thread::spawn(|| {
            give(Scratch::default());
            assert_eq!(kept(), 0);
            for _ in 0..KEPT + 3 {
                give(Scratch::new(shape(7)));
            }
            assert_eq!(kept(), KEPT);
        })
        .join()
        .unwrap();
    }
}
