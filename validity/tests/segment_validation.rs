//! Exact segment validation agrees with the world's point test: whatever a dense sampling of
//! the segment finds invalid, the exact verdict finds too; where the verdict says invalid, the
//! point test agrees next to that parameter.

use proptest::prelude::*;
use validity::{AxisBox, Lattice, SegmentCause, SegmentVerdict, StateValidity, World};

/// A random world in `[-0.5, 0.5]^n`: obstacles, anti-obstacles, sometimes a lattice.
fn world() -> impl Strategy<Value = World> {
    (1usize..=5).prop_flat_map(|n| {
        let boxes = |count| {
            prop::collection::vec(
                (
                    prop::collection::vec(-0.5f64..0.5, n),
                    prop::collection::vec(0.0f64..0.4, n),
                ),
                0..count,
            )
        };
        let lattice = prop::option::of((1usize..5, 0.05f64..0.3, 0.01f64..0.1));
        (boxes(12), boxes(5), lattice).prop_map(move |(obstacles, antis, lattice)| {
            let mut world = World::new(vec![-0.5; n], vec![0.5; n]);
            for (c, w) in obstacles {
                world.add_obstacle(AxisBox::new(c, w)).unwrap();
            }
            for (c, w) in antis {
                world.add_anti_obstacle(AxisBox::new(c, w)).unwrap();
            }
            if let Some((count, spacing, side)) = lattice {
                world = world
                    .with_lattice(Lattice {
                        count,
                        spacing,
                        side,
                    })
                    .unwrap();
            }
            world
        })
    })
}

fn point(a: &[f64], b: &[f64], t: f64) -> Vec<f64> {
    a.iter().zip(b).map(|(x, y)| x + t * (y - x)).collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn sampled_invalid_points_are_never_missed(
        world in world(),
        ends in prop::collection::vec(-0.6f64..0.6, 10),
        extra in prop::collection::vec(0.0f64..1.0, 200),
    ) {
        let n = world.dimension();
        let (a, b) = (&ends[..n], &ends[5..5 + n]);
        let verdict = world.segment_verdict(a, b);
        let samples = (0..=2000).map(|k| f64::from(k) / 2000.0).chain(extra);
        for t in samples {
            if !world.is_valid(&point(a, b, t)) {
                prop_assert!(!verdict.is_valid(), "t = {} is invalid but the verdict is valid", t);
                break;
            }
        }
        if let SegmentVerdict::Invalid { t, cause } = verdict {
            prop_assert!((0.0..=1.0).contains(&t));
            // The point test agrees at, or within a hair of, the reported parameter.
            let near = (-4..=4).map(|k| (t + f64::from(k) * 1e-9).clamp(0.0, 1.0));
            let agrees = near.into_iter().any(|s| !world.is_valid(&point(a, b, s)));
            prop_assert!(agrees, "invalid at t = {} ({:?}) but every point near it is valid", t, cause);
        }
    }

    #[test]
    fn segments_inside_one_anti_obstacle_or_an_empty_world_are_valid(
        n in 1usize..=5,
        raw in prop::collection::vec(-0.3f64..0.3, 10),
    ) {
        let (a, b) = (&raw[..n], &raw[5..5 + n]);
        let empty = World::new(vec![-0.5; n], vec![0.5; n]);
        prop_assert!(empty.segment_verdict(a, b).is_valid());
        let carved = empty
            .with_obstacle(AxisBox::cube(vec![0.0; n], 1.0)).unwrap()
            .with_anti_obstacle(AxisBox::cube(vec![0.0; n], 0.6)).unwrap();
        prop_assert!(carved.segment_verdict(a, b).is_valid());
    }
}

/// The cases.
#[test]
fn thin_walls_slivers_and_wide_boxes_are_found() {
    let square = || World::new(vec![-0.5; 2], vec![0.5; 2]);
    let (a, b) = ([-0.3, 0.0], [0.3, 0.0]);
    let thin = square()
        .with_obstacle(AxisBox::new(vec![0.0, 0.0], vec![1e-6, 1.0]))
        .unwrap();
    assert!(matches!(
        thin.segment_verdict(&a, &b),
        SegmentVerdict::Invalid {
            cause: SegmentCause::Obstacle(0),
            ..
        }
    ));
    let wide = square()
        .with_obstacle(AxisBox::new(vec![0.0, 0.0], vec![0.4, 0.4]))
        .unwrap();
    assert!(!wide.segment_verdict(&a, &b).is_valid());
    let slot = |dx: f64| {
        square()
            .with_obstacle(AxisBox::new(vec![0.0, 0.0], vec![0.1, 1.0]))
            .unwrap()
            .with_anti_obstacle(AxisBox::new(vec![dx, 0.0], vec![0.1, 0.04]))
            .unwrap()
    };
    assert!(slot(0.0).segment_verdict(&a, &b).is_valid());
    assert!(!slot(1.2e-7).segment_verdict(&a, &b).is_valid());
    assert!(!slot(-1.2e-7).segment_verdict(&a, &b).is_valid());
    let huge = World::new(vec![-5e11; 2], vec![5e11; 2])
        .with_obstacle(AxisBox::new(vec![0.0, 0.0], vec![1e-6, 1e12]))
        .unwrap();
    assert!(!huge.segment_verdict(&[-3e11, 0.0], &[3e11, 0.0]).is_valid());
}
