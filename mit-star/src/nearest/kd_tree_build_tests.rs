//! Tests of `kd_tree_build.rs`: how often a build polls its stop condition, and what an
//! abandoned build leaves behind.

use std::cell::Cell;

use mit_star_spaces::Stop;

use crate::nearest::KdTree;
use crate::nearest::kd_tree_build::{POLL_WORK, Spare};

thread_local! {
    /// Points the splits of this thread's builds have read or moved so far.
    static VISITED: Cell<usize> = const { Cell::new(0) };
}

/// Counts `points` read or moved by a split.
pub(crate) fn visited(points: usize) {
    VISITED.with(|v| v.set(v.get() + points));
}

/// A stop condition that never fires and records the most points visited between two of
/// its polls.
#[derive(Default)]
struct GapMeter {
    last: Cell<usize>,
    widest: Cell<usize>,
}

impl Stop for GapMeter {
    fn should_stop(&self) -> bool {
        let now = VISITED.with(Cell::get);
        self.widest
            .set(self.widest.get().max(now - self.last.get()));
        self.last.set(now);
        false
    }
}

/// `count` points of `dimension` coordinates, spread by a fixed recurrence.
fn points(count: usize, dimension: usize) -> (Vec<u32>, Vec<u32>, Vec<f64>) {
    let coordinates = (0..count * dimension)
        .map(|i| ((i as f64) * 0.618_033_988_749).fract())
        .collect();
    ((0..count as u32).collect(), vec![0; count], coordinates)
}

#[test]
fn a_large_cell_polls_while_its_points_are_read_and_moved() {
    // The root's cell alone is 200 000 point visits (read, then partitioned; polled only
    // between cells, it was one stretch); the stop condition must be polled every few
    // thousand of them, or a deadline waits milliseconds.
    let (dimension, count) = (8, 100_000);
    let meter = GapMeter::default();
    meter.last.set(VISITED.with(Cell::get));
    let tree = KdTree::from_owned(
        dimension,
        points(count, dimension),
        &meter,
        &mut Spare::default(),
    )
    .expect("a stop that never fires lets the build finish");
    assert_eq!(tree.ids.len(), count);
    // A cell just too small to poll inside itself, and the small cells after it before the
    // work they add up to reaches the next poll: a few `POLL_WORK`s of coordinates.
    let limit = 4 * POLL_WORK / dimension;
    assert!(
        meter.widest.get() <= limit,
        "{} points visited between two polls (at most {limit} allowed)",
        meter.widest.get()
    );
}

#[test]
fn a_build_stopped_inside_a_partition_is_abandoned_and_the_next_one_is_exact() {
    /// Fires at its `at`-th poll and after.
    struct FiresAt {
        at: usize,
        calls: Cell<usize>,
    }
    impl Stop for FiresAt {
        fn should_stop(&self) -> bool {
            self.calls.set(self.calls.get() + 1);
            self.calls.get() >= self.at
        }
    }
    let (dimension, count) = (3, 20_000);
    let mut spare = Spare::default();
    // Every poll of a whole build, from the bounding box to the last leaf.
    let polls = {
        let counter = FiresAt {
            at: usize::MAX,
            calls: Cell::new(0),
        };
        KdTree::from_owned(dimension, points(count, dimension), &counter, &mut spare)
            .expect("built");
        counter.calls.get()
    };
    assert!(polls > 20, "{polls} polls");
    for at in 1..=polls {
        let stop = FiresAt {
            at,
            calls: Cell::new(0),
        };
        let built = KdTree::from_owned(dimension, points(count, dimension), &stop, &mut spare);
        assert!(
            built.is_none(),
            "a stop firing at poll {at} abandons the build"
        );
    }
    let (ids, births, coordinates) = points(count, dimension);
    let tree = KdTree::from_owned(
        dimension,
        (ids, births, coordinates.clone()),
        &mit_star_spaces::Never,
        &mut spare,
    )
    .expect("built");
    let query = [0.31, 0.72, 0.05];
    let mut found = crate::nearest::Neighbours::new();
    tree.nearest(&query, 5, &mut found);
    let mut brute: Vec<(f64, u32)> = coordinates
        .chunks_exact(dimension)
        .enumerate()
        .map(|(i, p)| {
            (
                crate::nearest::kd_tree::squared_distance(&query, p),
                i as u32,
            )
        })
        .collect();
    brute.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    let ids: Vec<u32> = found.iter().map(|&(_, id)| id).collect();
    let expected: Vec<u32> = brute[..5].iter().map(|&(_, id)| id).collect();
    assert_eq!(ids, expected);
}
