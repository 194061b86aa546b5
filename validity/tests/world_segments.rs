//! The per-edge broad phase and the batched SIMD point checks of a box world change no answer.
//!
//! For random worlds (small ones scanned, large ones through their hierarchy; boxes that cross
//! the bounds, thin boxes, boxes whose faces lie exactly on an edge's ends) and random edges
//! (ends on the bounds, on box faces, inside obstacles), every grid point gets the same answer
//! from a prepared segment as from interpolating it and testing it on its own; a box the
//! broad phase drops contains no grid point; and whole walks — sparse checks, then a full check
//! — give the same statuses, progress and point counts with acceleration on and off.

use mit_star_spaces::{Never, RealVectorSpace, StateSpace};
use mit_star_validity::{
    AxisBox, DenseChecker, EdgeChecker, EdgeGrid, EdgeProgress, LengthAdaptiveChecker, Preparation,
    Segment, StateValidity, World, canonical_ends,
};
use proptest::prelude::*;

/// A coordinate: on a coarse lattice (so that box faces and edge ends coincide exactly) or
/// anywhere in `[-0.6, 0.6]` (beyond the bounds of `[-0.5, 0.5]` too).
fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![(-4_i32..=4).prop_map(|k| f64::from(k) / 8.0), -0.6..0.6_f64,]
}

/// A width: thin, lattice-aligned, or anything up to the whole space.
fn width() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(1e-9),
        (1_i32..=8).prop_map(|k| f64::from(k) / 8.0),
        0.0..1.2_f64,
    ]
}

fn boxes(n: usize, most: usize) -> impl Strategy<Value = Vec<AxisBox>> {
    prop::collection::vec(
        (
            prop::collection::vec(coordinate(), n),
            prop::collection::vec(width(), n),
        )
            .prop_map(|(center, widths)| AxisBox::new(center, widths)),
        0..most,
    )
}

/// A world of up to `most` obstacles and anti-obstacles, and an edge with ends in the bounds
/// or on them.
fn world_and_edge(most: usize) -> impl Strategy<Value = (World, Vec<f64>, Vec<f64>)> {
    (1_usize..=5).prop_flat_map(move |n| {
        let end = prop::collection::vec(
            prop_oneof![coordinate().prop_map(|x| x.clamp(-0.5, 0.5)), Just(0.5)],
            n,
        );
        // Some edges are nearly parallel to axes: `b` is `a` moved by a few nanometres along
        // some coordinates and freely along others.
        let nudges = prop::collection::vec(prop_oneof![Just(None), (-3_i32..=3).prop_map(Some)], n);
        (
            boxes(n, most),
            boxes(n, most / 2 + 1),
            end.clone(),
            end,
            nudges,
        )
            .prop_map(move |(obstacles, antis, a, mut b, nudges)| {
                for ((y, &x), nudge) in b.iter_mut().zip(&a).zip(nudges) {
                    if let Some(k) = nudge {
                        *y = (x + f64::from(k) * 1e-9).clamp(-0.5, 0.5);
                    }
                }
                let mut world = World::new(vec![-0.5; n], vec![0.5; n]);
                for o in obstacles {
                    world.add_obstacle(o).unwrap();
                }
                for anti in antis {
                    world.add_anti_obstacle(anti).unwrap();
                }
                (world, a, b)
            })
    })
}

/// Every grid point of `a — b` with `intervals` intervals: the answer of a prepared segment,
/// point by point and in one batch, against interpolating and testing each point alone.
fn compare_points(
    world: &World,
    a: &[f64],
    b: &[f64],
    intervals: u64,
) -> Result<(), TestCaseError> {
    let space = RealVectorSpace::cube(a.len(), -0.5, 0.5).unwrap();
    let (a, b) = canonical_ends(a, b);
    let grid = EdgeGrid::with_intervals(intervals);
    let fractions: Vec<f64> = (1..intervals).map(|i| grid.fraction(i)).collect();
    let mut state = vec![0.0; a.len()];
    let alone: Vec<bool> = fractions
        .iter()
        .map(|&t| {
            space.interpolate(a, b, t, &mut state);
            world.is_valid(&state)
        })
        .collect();
    let mut segment = Segment::default();
    segment.set(a, b);
    match world.prepare_segment(&mut segment) {
        Preparation::Unprepared => {}
        Preparation::AllValid => {
            prop_assert!(alone.iter().all(|&v| v), "a free edge has an invalid point");
        }
        Preparation::Prepared => {
            for (i, (&t, &valid)) in fractions.iter().zip(&alone).enumerate() {
                let prepared = world.first_invalid_on(&mut segment, &[t]).is_none();
                prop_assert_eq!(prepared, valid, "grid point {} of {}", i + 1, intervals);
            }
            for chunk in [1, 3, 4, 5, 32] {
                for (k, (ts, valid)) in fractions.chunks(chunk).zip(alone.chunks(chunk)).enumerate()
                {
                    let expected = valid.iter().position(|&v| !v);
                    prop_assert_eq!(
                        world.first_invalid_on(&mut segment, ts),
                        expected,
                        "batch {} of width {}",
                        k,
                        chunk
                    );
                }
            }
        }
    }
    Ok(())
}

/// A box `width` wide along `d` whose lower (or upper) face, as the world stores it, passes
/// exactly through `x`, and that spans everything along the other coordinates; `None` if no
/// centre within a few ulps gives exactly that face.
fn face_through(n: usize, d: usize, x: f64, width: f64, upper: bool) -> Option<AxisBox> {
    let half = 0.5 * width + f64::EPSILON;
    let mut center = if upper { x - half } else { x + half };
    for _ in 0..8 {
        let face = if upper { center + half } else { center - half };
        if face == x {
            let mut c = vec![0.0; n];
            let mut w = vec![2.0; n];
            c[d] = center;
            w[d] = width;
            return Some(AxisBox::new(c, w));
        }
        center = next_toward(center, face < x);
    }
    None
}

/// The neighbouring float of a finite `x`, above (`up`) or below.
fn next_toward(x: f64, up: bool) -> f64 {
    if x == 0.0 {
        let tiny = f64::from_bits(1);
        return if up { tiny } else { -tiny };
    }
    let bits = x.to_bits();
    f64::from_bits(if (x > 0.0) == up { bits + 1 } else { bits - 1 })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    /// Boxes whose faces pass exactly through a grid point: closed membership (`≥`, `≤`) is
    /// kept to the last bit, for obstacles and for anti-obstacles cut into them.
    #[test]
    fn faces_exactly_through_grid_points(
        (world, a, b) in world_and_edge(3),
        intervals in 2_u64..200,
        pick in any::<prop::sample::Index>(),
        coordinate in any::<prop::sample::Index>(),
        width in 1e-6..0.5_f64,
        upper in any::<bool>(),
        anti in any::<bool>(),
    ) {
        let n = a.len();
        let space = RealVectorSpace::cube(n, -0.5, 0.5).unwrap();
        let (u, v) = canonical_ends(&a, &b);
        let grid = EdgeGrid::with_intervals(intervals);
        let i = 1 + pick.index(intervals as usize - 1) as u64;
        let mut p = vec![0.0; n];
        space.interpolate(u, v, grid.fraction(i), &mut p);
        let d = coordinate.index(n);
        let Some(face) = face_through(n, d, p[d], width, upper) else {
            return Ok(());
        };
        let world = if anti {
            world
                .with_obstacle(AxisBox::new(vec![0.0; n], vec![2.0; n]))
                .unwrap()
                .with_anti_obstacle(face)
                .unwrap()
        } else {
            world.with_obstacle(face).unwrap()
        };
        compare_points(&world, &a, &b, intervals)?;
    }

    #[test]
    fn every_grid_point_gets_the_same_answer(
        (world, a, b) in world_and_edge(10),
        intervals in prop_oneof![1_u64..40, 40_u64..600],
    ) {
        compare_points(&world, &a, &b, intervals)?;
    }

    #[test]
    fn every_grid_point_gets_the_same_answer_in_large_worlds(
        (world, a, b) in world_and_edge(90),
        intervals in 1_u64..300,
    ) {
        compare_points(&world, &a, &b, intervals)?;
    }

    /// A box the broad phase drops contains no point of the edge: a world made of the dropped
    /// boxes alone has every grid point valid.
    #[test]
    fn dropped_boxes_contain_no_grid_point(
        (world, a, b) in world_and_edge(10),
        intervals in 2_u64..400,
    ) {
        let n = a.len();
        let space = RealVectorSpace::cube(n, -0.5, 0.5).unwrap();
        let (a, b) = canonical_ends(&a, &b);
        let mut segment = Segment::default();
        segment.set(a, b);
        let mut single = Segment::default();
        let grid = EdgeGrid::with_intervals(intervals);
        let mut state = vec![0.0; n];
        for obstacle in world.obstacles() {
            let alone = World::new(vec![-1.0; n], vec![1.0; n])
                .with_obstacle(obstacle.clone())
                .unwrap();
            single.set(a, b);
            if alone.prepare_segment(&mut single) != Preparation::AllValid {
                continue;
            }
            for i in 1..intervals {
                space.interpolate(a, b, grid.fraction(i), &mut state);
                prop_assert!(!obstacle.contains(&state), "dropped box holds grid point {}", i);
            }
        }
    }

    /// Sparse checks at rising levels and a final full check, from either end: accelerated and
    /// one state at a time agree on every status, the progress and the points counted.
    #[test]
    fn walks_agree_with_acceleration_on_and_off(
        (world, a, b) in world_and_edge(12),
        step in prop_oneof![1e-3..0.05_f64, 2e-4..1e-3_f64],
        flips in prop::collection::vec(any::<bool>(), 4),
    ) {
        let space = RealVectorSpace::cube(a.len(), -0.5, 0.5).unwrap();
        let fast = LengthAdaptiveChecker::new(step).unwrap();
        let slow = fast.clone().with_acceleration(false);
        let mut results = Vec::new();
        for mut checker in [fast, slow] {
            let c: &mut dyn EdgeChecker<RealVectorSpace, World> = &mut checker;
            let mut progress = EdgeProgress::default();
            let mut statuses = Vec::new();
            for &flip in &flips[..3] {
                let (u, v) = if flip { (&b, &a) } else { (&a, &b) };
                statuses.push(c.check_sparse(&space, &world, u, v, &mut progress, &Never));
                c.refine();
            }
            let (u, v) = if flips[3] { (&b, &a) } else { (&a, &b) };
            statuses.push(c.check_full(&space, &world, u, v, &mut progress, &Never));
            results.push((statuses, progress, c.counters().points_tested));
        }
        prop_assert_eq!(&results[0], &results[1]);
        let mut dense = DenseChecker::new(step).unwrap();
        let mut slow = DenseChecker::new(step).unwrap().with_acceleration(false);
        let (mut p, mut q) = (EdgeProgress::default(), EdgeProgress::default());
        let fast_status = dense.check_full(&space, &world, &a, &b, &mut p, &Never);
        let slow_status = slow.check_full(&space, &world, &a, &b, &mut q, &Never);
        prop_assert_eq!((fast_status, p), (slow_status, q));
    }
}

/// A wall ten grid steps thin, off the edge's middle: the bisection head of a scanning full
/// check misses it, the ascending scan finds it, and the walk that follows reports what the
/// one-by-one walk does — the same status, progress and points, whatever was tested before.
#[test]
fn a_thin_wall_missed_by_the_head_is_found_exactly() {
    let space = RealVectorSpace::cube(2, -0.5, 0.5).unwrap();
    let world = World::in_space(&space)
        .with_obstacle(AxisBox::new(vec![0.123, 0.0], vec![1e-4, 1.0]))
        .unwrap();
    let (a, b) = ([-0.4, 0.01], [0.4, -0.02]);
    for sparse_first in [0_u32, 1, 3] {
        let mut results = Vec::new();
        for accelerated in [true, false] {
            let mut checker = LengthAdaptiveChecker::new(1e-5)
                .unwrap()
                .with_acceleration(accelerated);
            let c: &mut dyn EdgeChecker<RealVectorSpace, World> = &mut checker;
            let mut progress = EdgeProgress::default();
            for _ in 0..sparse_first {
                c.check_sparse(&space, &world, &b, &a, &mut progress, &Never);
                c.refine();
            }
            let status = c.check_full(&space, &world, &a, &b, &mut progress, &Never);
            results.push((status, progress, c.counters().points_tested));
        }
        assert_eq!(results[0], results[1], "after {sparse_first} sparse checks");
        assert_eq!(results[0].0, mit_star_validity::EdgeStatus::Invalid);
        assert!(results[0].2 > 255, "the head alone found the wall");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Not only grid fractions: at the exact floats where the one-by-one answer changes along
    /// the edge (found by bisecting on the floats' bits) and at their neighbours, a prepared
    /// segment answers as testing the point does — membership is decided to the last ulp of `t`.
    #[test]
    fn answers_agree_at_the_floats_where_they_change((world, a, b) in world_and_edge(6)) {
        compare_at_changes(&world, &a, &b)?;
    }

    /// Far from the origin (offsets 1e6–1e9, boxes of at most 1e-3, where computed points lie
    /// on a lattice of ulps up to 1e-7 apart): the same agreement at grid points and at the
    /// floats where the answer changes.
    #[test]
    fn far_from_the_origin_answers_agree(
        (world, a, b) in far_world_and_edge(),
        intervals in prop_oneof![2_u64..40, 40_u64..2000],
    ) {
        compare_points(&world, &a, &b, intervals)?;
        compare_at_changes(&world, &a, &b)?;
    }
}

/// At the floats where the one-by-one answer changes along `a — b`, and their neighbours, a
/// prepared segment answers as testing the point does.
fn compare_at_changes(world: &World, a: &[f64], b: &[f64]) -> Result<(), TestCaseError> {
    let n = a.len();
    let space = RealVectorSpace::cube(n, -0.5, 0.5).unwrap();
    let (a, b) = canonical_ends(a, b);
    let mut state = vec![0.0; n];
    let mut alone = |t: f64| {
        space.interpolate(a, b, t, &mut state);
        world.is_valid(&state)
    };
    let mut segment = Segment::default();
    segment.set(a, b);
    if world.prepare_segment(&mut segment) != Preparation::Prepared {
        return Ok(());
    }
    let coarse: Vec<f64> = (0..=256).map(|i| f64::from(i) / 256.0).collect();
    for pair in coarse.windows(2) {
        let (mut lo, mut hi) = (pair[0].to_bits(), pair[1].to_bits());
        let at_lo = alone(pair[0]);
        if at_lo == alone(pair[1]) {
            continue;
        }
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if alone(f64::from_bits(mid)) == at_lo {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        for bits in lo.saturating_sub(2)..=hi + 2 {
            let t = f64::from_bits(bits);
            if !(0.0..=1.0).contains(&t) {
                continue;
            }
            let prepared = world.first_invalid_on(&mut segment, &[t]).is_none();
            prop_assert_eq!(prepared, alone(t), "t = {} ({:#x})", t, bits);
        }
    }
    Ok(())
}

/// A world far from the origin — tiny obstacles and anti-obstacles (some cut from an obstacle)
/// around an offset of 1e6–1e9 per coordinate, bounds a unit away or through an end — and an
/// edge among them, random or aimed within a few ulps of a box's corner.
fn far_world_and_edge() -> impl Strategy<Value = (World, Vec<f64>, Vec<f64>)> {
    (1_usize..=3).prop_flat_map(|n| {
        let offset = prop::collection::vec(
            (6.0_f64..9.0, any::<bool>())
                .prop_map(|(e, neg)| 10_f64.powf(e) * if neg { -1.0 } else { 1.0 }),
            n,
        );
        let local = move || prop::collection::vec(-1e-3_f64..1e-3, n);
        let width = prop_oneof![Just(0.0), (-9.0_f64..-3.0).prop_map(|e| 10_f64.powf(e))];
        let boxes = prop::collection::vec((local(), prop::collection::vec(width, n)), 1..6);
        let slots = prop::collection::vec(
            (any::<prop::sample::Index>(), 0_usize..3, 0.1_f64..0.9),
            0..3,
        );
        let graze = prop::option::of((
            any::<prop::sample::Index>(),
            prop::collection::vec((any::<bool>(), -4_i32..=4), n),
            (local(), -4.0_f64..0.0),
            0.0_f64..1.0,
        ));
        (
            offset,
            boxes,
            slots,
            (local(), local()),
            graze,
            prop::collection::vec(0_u8..4, n),
        )
            .prop_map(move |(offset, boxes, slots, (u, v), graze, tight)| {
                let place =
                    |x: &[f64]| -> Vec<f64> { offset.iter().zip(x).map(|(o, x)| o + x).collect() };
                let obstacles: Vec<AxisBox> = boxes
                    .iter()
                    .map(|(c, w)| AxisBox::new(place(c), w.clone()))
                    .collect();
                let antis: Vec<AxisBox> = slots
                    .iter()
                    .map(|(pick, d, shrink)| {
                        let mut slot = pick.get(&obstacles).clone();
                        slot.widths[d % n] *= shrink;
                        slot
                    })
                    .collect();
                let (mut a, mut b) = (place(&u), place(&v));
                if let Some((pick, corner, (direction, scale), at)) = graze {
                    let all: Vec<&AxisBox> = obstacles.iter().chain(&antis).collect();
                    let target = pick.get(&all);
                    let scale = 10_f64.powf(scale);
                    for (d, &(upper, nudge)) in corner.iter().enumerate() {
                        let half = 0.5 * target.widths[d] + f64::EPSILON;
                        let face = if upper {
                            target.center[d] + half
                        } else {
                            target.center[d] - half
                        };
                        let mut p = face;
                        for _ in 0..nudge.unsigned_abs() {
                            p = next_toward(p, nudge > 0);
                        }
                        a[d] = p - at * scale * direction[d];
                        b[d] = p + (1.0 - at) * scale * direction[d];
                    }
                }
                let lower = (0..n).map(|d| {
                    if tight[d] == 1 {
                        a[d].min(b[d])
                    } else {
                        offset[d] - 1.0
                    }
                });
                let upper = (0..n).map(|d| {
                    if tight[d] == 2 {
                        a[d].max(b[d])
                    } else {
                        offset[d] + 1.0
                    }
                });
                let mut world = World::new(lower.collect(), upper.collect());
                for o in obstacles {
                    world.add_obstacle(o).unwrap();
                }
                for anti in antis {
                    world.add_anti_obstacle(anti).unwrap();
                }
                (world, a, b)
            })
    })
}

/// A full check whose scan is interrupted again and again (a planner given many short time
/// slices) resumes its scan where it stopped, so it finishes — with the one-by-one answer.
#[test]
fn an_interrupted_scan_resumes_where_it_stopped() {
    let space = RealVectorSpace::cube(2, -0.5, 0.5).unwrap();
    let world = World::in_space(&space)
        .with_obstacle(AxisBox::new(vec![0.0, 0.0], vec![0.1, 1.0]))
        .unwrap()
        .with_anti_obstacle(AxisBox::new(vec![0.0, 0.0], vec![0.2, 0.1]))
        .unwrap();
    let (a, b) = ([-0.4, 0.001], [0.4, -0.002]); // through the gap: valid, crosses the wall
    let mut slow = DenseChecker::new(2e-5).unwrap().with_acceleration(false);
    let mut p = EdgeProgress::default();
    let expected = slow.check_full(&space, &world, &a, &b, &mut p, &Never);
    assert_eq!(expected, mit_star_validity::EdgeStatus::Valid);
    let mut checker = DenseChecker::new(2e-5).unwrap();
    let mut progress = EdgeProgress::default();
    let polls = std::cell::Cell::new(0);
    let mut calls = 0;
    loop {
        calls += 1;
        assert!(calls < 200, "no end after {calls} interrupted checks");
        polls.set(0);
        // Each call may pass one poll: 32 points of a walk, or 1024 of a scan.
        let stop = || {
            polls.set(polls.get() + 1);
            polls.get() >= 2
        };
        let status = checker.check_full(&space, &world, &a, &b, &mut progress, &stop);
        if status != mit_star_validity::EdgeStatus::Unknown {
            assert_eq!((status, progress), (expected, p));
            break;
        }
    }
    assert!(calls > 10, "the check was not interrupted ({calls} calls)");
}
