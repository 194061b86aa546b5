//! The bounding-volume hierarchy of large worlds answers exactly as a linear scan does: random
//! worlds above and below the threshold, random states and states on faces and corners.

use mit_star_validity::{AxisBox, StateValidity, TREE_THRESHOLD, World};
use proptest::prelude::*;

/// The world's rule, written out: in bounds and (in some anti-obstacle or in no obstacle).
fn reference(world: &World, x: &[f64]) -> bool {
    let inside = |b: &AxisBox| {
        x.iter()
            .zip(b.center.iter().zip(&b.widths))
            .all(|(&v, (&c, &w))| (v - c).abs() <= 0.5 * w + f64::EPSILON)
    };
    let in_bounds = x
        .iter()
        .zip(world.lower().iter().zip(world.upper()))
        .all(|(&v, (&lo, &hi))| v >= lo && v <= hi);
    in_bounds
        && (world.anti_obstacles().iter().any(inside) || !world.obstacles().iter().any(inside))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(60))]

    #[test]
    fn hierarchies_agree_with_the_scan(
        n in 1usize..=8,
        boxes in prop::collection::vec(
            (prop::collection::vec(-0.5f64..0.5, 8), prop::collection::vec(0.0f64..0.3, 8)),
            0..300,
        ),
        antis in prop::collection::vec(
            (prop::collection::vec(-0.5f64..0.5, 8), prop::collection::vec(0.0f64..0.2, 8)),
            0..80,
        ),
        states in prop::collection::vec(prop::collection::vec(-0.55f64..0.55, 8), 200),
    ) {
        let mut world = World::new(vec![-0.5; n], vec![0.5; n]);
        for (c, w) in &boxes {
            world.add_obstacle(AxisBox::new(c[..n].to_vec(), w[..n].to_vec())).unwrap();
        }
        for (c, w) in &antis {
            world.add_anti_obstacle(AxisBox::new(c[..n].to_vec(), w[..n].to_vec())).unwrap();
        }
        let large = boxes.len() > TREE_THRESHOLD;
        for x in &states {
            prop_assert_eq!(world.is_valid(&x[..n]), reference(&world, &x[..n]), "large: {}", large);
        }
        // On faces and corners of the boxes themselves.
        for (c, w) in boxes.iter().take(40) {
            let corner: Vec<f64> = (0..n).map(|d| c[d] + 0.5 * w[d]).collect();
            let face: Vec<f64> = (0..n).map(|d| if d == 0 { c[d] - 0.5 * w[d] } else { c[d] }).collect();
            prop_assert_eq!(world.is_valid(&corner), reference(&world, &corner));
            prop_assert_eq!(world.is_valid(&face), reference(&world, &face));
        }
    }
}

#[test]
fn adding_a_box_after_a_query_rebuilds_the_hierarchy() {
    let mut world = World::new(vec![-0.5; 2], vec![0.5; 2]);
    for i in 0..100 {
        let x = -0.45 + 0.009 * f64::from(i);
        world
            .add_obstacle(AxisBox::new(vec![x, 0.4], vec![0.001, 0.001]))
            .unwrap();
    }
    assert!(world.is_valid(&[0.0, 0.0]));
    world
        .add_obstacle(AxisBox::new(vec![0.0, 0.0], vec![0.1, 0.1]))
        .unwrap();
    assert!(!world.is_valid(&[0.0, 0.0]), "the new box is seen");
    let copy = world.clone();
    assert_eq!(copy, world);
    assert_eq!(world.thinnest_obstacle(), Some(0.001));
    assert_eq!(world.thinnest_anti_obstacle(), None);
}
