//! A box world's exact certification of an edge polls its stop condition in proportion to the
//! boxes it examines (issue 28: with a coarse step, a deadline slipped while a certification
//! went through every box of a large world without a poll), goes on where a stop left it, and
//! answers what [`World::segment_verdict`] answers, stopped or not.

use std::cell::Cell;

use mit_star_spaces::{Never, RealVectorSpace, Stop};
use mit_star_validity::{
    AxisBox, EdgeProgress, EdgeStatus, GridWalker, Lattice, MotionProgress, Segment, StateValidity,
    World,
};

/// Counts its polls; fires from poll number `fires_at` (1-based) of each slice on.
struct Polls {
    polls: Cell<u64>,
    in_slice: Cell<u64>,
    fires_at: u64,
}

impl Polls {
    fn firing_at(fires_at: u64) -> Self {
        Self {
            polls: Cell::new(0),
            in_slice: Cell::new(0),
            fires_at,
        }
    }

    fn never() -> Self {
        Self::firing_at(u64::MAX)
    }

    /// Begins a new slice (the poll count of the slice starts again).
    fn rearm(&self) {
        self.in_slice.set(0);
    }
}

impl Stop for Polls {
    fn should_stop(&self) -> bool {
        self.polls.set(self.polls.get() + 1);
        self.in_slice.set(self.in_slice.get() + 1);
        self.in_slice.get() >= self.fires_at
    }
}

/// A deterministic generator of floats in `[0, 1)`.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1_u64 << 53) as f64
    }

    fn point(&mut self, n: usize, scale: f64) -> Vec<f64> {
        (0..n).map(|_| scale * (self.next() - 0.5)).collect()
    }
}

/// `count` random boxes of sides up to `side` in `[-0.5, 0.5]^n`, and `antis` anti-obstacles.
fn world(n: usize, count: usize, side: f64, antis: usize, seed: u64) -> World {
    let mut rng = Lcg(seed);
    let mut world = World::new(vec![-0.5; n], vec![0.5; n]);
    for _ in 0..count {
        let widths = (0..n).map(|_| side * rng.next()).collect();
        world
            .add_obstacle(AxisBox::new(rng.point(n, 1.0), widths))
            .unwrap();
    }
    for _ in 0..antis {
        let widths = (0..n).map(|_| 2.0 * side * rng.next()).collect();
        world
            .add_anti_obstacle(AxisBox::new(rng.point(n, 1.0), widths))
            .unwrap();
    }
    world
}

/// Certifies `a → b` in slices, each stopped at its `fires_at`-th poll, with one scratch;
/// returns the status and the number of calls.
fn certify_in_slices(world: &World, a: &[f64], b: &[f64], fires_at: u64) -> (EdgeStatus, u64) {
    let space = RealVectorSpace::cube(world.dimension(), -0.5, 0.5).unwrap();
    let mut scratch = Segment::default();
    let mut progress = MotionProgress::default();
    let stop = Polls::firing_at(fires_at);
    for calls in 1..1_000_000 {
        stop.rearm();
        let status = world
            .certify_motion_in(&space, (a, b), &mut scratch, &mut progress, &stop)
            .unwrap();
        if status != EdgeStatus::Unknown {
            assert_eq!(progress.evaluations(), 1, "one certification, resumed");
            return (status, calls);
        }
    }
    panic!("no decision");
}

#[test]
fn a_certification_polls_at_least_once_per_thousand_boxes() {
    // A short edge near the origin in a world of 20 000 boxes, none near it: certified valid,
    // every box examined once per parametrization. Before issue 28's fix: one poll in all.
    let boxes = 20_000;
    let world = world_far_from_origin(boxes);
    let space = RealVectorSpace::cube(4, -0.5, 0.5).unwrap();
    let (a, b) = ([-0.05, 0.0, 0.0, 0.0], [0.05, 0.01, 0.0, 0.0]);
    let mut walker = GridWalker::new(0.5).unwrap();
    let stop = Polls::never();
    let status = walker.certify(&space, &world, (&a, &b), 2, &stop);
    assert_eq!(status, EdgeStatus::Valid);
    assert!(world.segment_verdict(&a, &b).is_valid());
    let examined = 2 * boxes as u64;
    assert!(
        stop.polls.get() >= examined / 1024,
        "{} polls for {examined} boxes examined",
        stop.polls.get()
    );
    // An edge through the boxes: invalid, and polled as it goes too.
    let (a, b) = ([-0.45, -0.4, 0.3, 0.0], [0.45, 0.4, -0.3, 0.1]);
    let stop = Polls::never();
    let status = walker.certify(&space, &world, (&a, &b), 2, &stop);
    assert_eq!(
        status == EdgeStatus::Valid,
        world.segment_verdict(&a, &b).is_valid()
    );
    assert!(stop.polls.get() >= 1);
}

/// `count` small boxes, none within 0.2 of the origin.
fn world_far_from_origin(count: usize) -> World {
    let mut rng = Lcg(9);
    let mut world = World::new(vec![-0.5; 4], vec![0.5; 4]);
    while world.obstacles().len() < count {
        let c = rng.point(4, 1.0);
        if c.iter().map(|x| x.abs()).fold(0.0, f64::max) > 0.2 {
            world.add_obstacle(AxisBox::cube(c, 0.01)).unwrap();
        }
    }
    world
}

#[test]
fn a_stop_ends_a_certification_within_one_poll_period() {
    // 50 000 boxes: the whole certification is about 200 poll periods. A stop firing at the
    // second poll (the first comes before any work) ends it after one period.
    let boxes = 50_000;
    let far = {
        let mut rng = Lcg(5);
        let mut world = World::new(vec![-0.5; 4], vec![0.5; 4]);
        while world.obstacles().len() < boxes {
            let c = rng.point(4, 1.0);
            if c.iter().map(|x| x.abs()).fold(0.0, f64::max) > 0.2 {
                world.add_obstacle(AxisBox::cube(c, 0.01)).unwrap();
            }
        }
        world
    };
    let space = RealVectorSpace::cube(4, -0.5, 0.5).unwrap();
    let (a, b) = ([-0.05, 0.0, 0.0, 0.0], [0.05, 0.01, 0.0, 0.0]);
    let mut scratch = Segment::default();
    let mut progress = MotionProgress::default();
    let stop = Polls::firing_at(2);
    let status = far
        .certify_motion_in(&space, (&a, &b), &mut scratch, &mut progress, &stop)
        .unwrap();
    assert_eq!(status, EdgeStatus::Unknown);
    assert_eq!(stop.polls.get(), 2);
    // The work done before the stop is the cursor: one poll period, not the world.
    assert!(
        progress.cursor() > 0.0 && progress.cursor() < 2048.0,
        "{progress:?}"
    );
    // Begun after the stop fired: nothing done.
    let fired = Polls::firing_at(1);
    let mut fresh = MotionProgress::default();
    let status = far
        .certify_motion_in(
            &space,
            (&a, &b),
            &mut Segment::default(),
            &mut fresh,
            &fired,
        )
        .unwrap();
    assert_eq!((status, fresh.evaluations()), (EdgeStatus::Unknown, 0));
    // Resumed slice by slice, it finishes, having examined every box once per pass.
    let (status, calls) = certify_in_slices(&far, &a, &b, 2);
    assert_eq!(status, EdgeStatus::Valid);
    assert!(calls >= (2 * boxes / 512) as u64 / 2, "{calls} calls");
    assert!(
        calls <= (2 * boxes / 512) as u64 + 2,
        "{calls} calls: started over?"
    );
}

#[test]
fn stopped_and_resumed_certifications_answer_what_the_verdict_answers() {
    let mut rng = Lcg(17);
    let mut decided = [0_u32; 2];
    for case in 0..60_u64 {
        let n = 2 + (case % 4) as usize;
        // Many obstacles and anti-obstacles (so that their stages are stopped mid-way), and
        // every third world a lattice.
        let mut w = world(n, 1500, 0.15, 600, case);
        if case % 3 == 0 {
            w = w
                .with_lattice(Lattice {
                    count: 400,
                    spacing: 1.0 / 401.0,
                    side: 0.5 / 401.0,
                })
                .unwrap();
        }
        for _ in 0..4 {
            let (a, b) = (rng.point(n, 1.1), rng.point(n, 1.1));
            let expected = w.segment_verdict(&a, &b).is_valid();
            let (whole, _) = certify_in_slices(&w, &a, &b, u64::MAX);
            let (sliced, calls) = certify_in_slices(&w, &a, &b, 2);
            assert_eq!(
                whole == EdgeStatus::Valid,
                expected,
                "case {case}: {a:?} → {b:?}"
            );
            assert_eq!(
                sliced, whole,
                "case {case}: {a:?} → {b:?} in {calls} slices"
            );
            decided[usize::from(expected)] += 1;
        }
    }
    // Both answers occur.
    assert!(decided.iter().all(|&d| d > 10), "{decided:?}");
}

#[test]
fn a_walker_resumes_a_stopped_certification_across_other_walks() {
    // The walker's own segment is reset by every walk; the certification's scratch is not.
    let boxes = 30_000;
    let world = world_far_from_origin(boxes);
    let space = RealVectorSpace::cube(4, -0.5, 0.5).unwrap();
    let (a, b) = ([-0.05, 0.0, 0.0, 0.0], [0.05, 0.01, 0.0, 0.0]);
    let mut walker = GridWalker::new(1e-3).unwrap();
    let stop = Polls::firing_at(2);
    let mut calls = 0;
    let status = loop {
        calls += 1;
        stop.rearm();
        let status = walker.certify(&space, &world, (&b, &a), 2, &stop);
        if status != EdgeStatus::Unknown {
            break status;
        }
        // Another edge walked in between, through the world's prepared segments.
        let (c, d) = ([0.3, 0.3, 0.3, 0.3], [0.35, 0.3, 0.3, 0.31]);
        let grid = walker.grid(&space, &c, &d);
        let mut progress = EdgeProgress::default();
        walker.advance(
            &space,
            &world,
            (&c, &d, grid),
            u64::MAX,
            &mut progress,
            &Never,
        );
    };
    assert_eq!(status, EdgeStatus::Valid);
    assert!(calls > 10, "{calls}");
    assert!(
        calls <= (2 * boxes / 512) as u64 + 2,
        "{calls} calls: started over?"
    );
    let counters = walker.counters();
    assert_eq!(
        (counters.certifications, counters.certification_points),
        (1, 1)
    );
}

#[test]
fn a_lattice_of_many_cubes_is_certified_in_slices() {
    // 3000 cubes per coordinate: an edge along x meets about 2700 slabs of them, far more than
    // one poll period of work.
    let count = 3000;
    let spacing = 1.0 / (count as f64 + 1.0);
    let lattice = World::new(vec![-0.5; 2], vec![0.5; 2])
        .with_lattice(Lattice {
            count,
            spacing,
            side: 0.1 * spacing,
        })
        .unwrap();
    let row = -0.5 + 1000.0 * spacing;
    for (y, valid) in [(row + 0.5 * spacing, true), (row, false)] {
        let (a, b) = ([-0.45, y], [0.45, y]);
        assert_eq!(lattice.segment_verdict(&a, &b).is_valid(), valid);
        assert_eq!(
            certify_in_slices(&lattice, &a, &b, u64::MAX).0,
            status(valid)
        );
        let (sliced, calls) = certify_in_slices(&lattice, &a, &b, 2);
        assert_eq!(sliced, status(valid));
        assert!(calls > 20, "{calls} slices");
    }
}

fn status(valid: bool) -> EdgeStatus {
    if valid {
        EdgeStatus::Valid
    } else {
        EdgeStatus::Invalid
    }
}
