//! Laws every `StateSpace` implementation must satisfy, checked on random spaces and states.
//!
//! This is the conformance harness for state spaces: a new implementation adds a strategy that
//! generates it and runs `check_laws` on it.

use std::f64::consts::PI;

use mit_star_spaces::{Joint, JointSpace, RealVectorSpace, SeededRng, StateSpace};
use proptest::prelude::*;
use rand::SeedableRng;

const TOL: f64 = 1e-9;

/// Checks the space laws on states `a`, `b` drawn inside the space and fractions `t`.
fn check_laws<S: StateSpace>(space: &S, a: &[f64], b: &[f64], t: f64) -> Result<(), TestCaseError> {
    let n = space.dimension();
    // Distance: symmetric, non-negative, zero on equal states, triangle inequality through a
    // point on the edge.
    let dab = space.distance(a, b);
    prop_assert!(dab >= 0.0);
    prop_assert!((dab - space.distance(b, a)).abs() <= TOL * (1.0 + dab));
    prop_assert!(space.distance(a, a) == 0.0);
    prop_assert!(dab <= space.maximum_extent() + TOL);

    // Interpolation hits both ends, stays in bounds, and splits the distance by t.
    let mut out = vec![0.0; n];
    space.interpolate(a, b, 0.0, &mut out);
    prop_assert!(
        space.distance(&out, a) <= TOL,
        "t=0 gives {out:?}, not {a:?}"
    );
    space.interpolate(a, b, 1.0, &mut out);
    prop_assert!(
        space.distance(&out, b) <= TOL,
        "t=1 gives {out:?}, not {b:?}"
    );
    space.interpolate(a, b, t, &mut out);
    prop_assert!(
        space.contains(&out),
        "interpolated state {out:?} out of bounds"
    );
    prop_assert!((space.distance(a, &out) - t * dab).abs() <= 1e-7 * (1.0 + dab));
    prop_assert!((space.distance(&out, b) - (1.0 - t) * dab).abs() <= 1e-7 * (1.0 + dab));
    Ok(())
}

/// A box space in 1..=32 dimensions with random bounds.
fn boxes() -> impl Strategy<Value = RealVectorSpace> {
    prop::collection::vec((-10.0f64..10.0, 0.01f64..5.0), 1..=32).prop_map(|dims| {
        let lower: Vec<f64> = dims.iter().map(|(lo, _)| *lo).collect();
        let upper: Vec<f64> = dims.iter().map(|(lo, w)| lo + w).collect();
        RealVectorSpace::new(lower, upper).expect("valid bounds")
    })
}

/// A joint space mixing limited and continuous joints, with random weights.
fn joint_spaces() -> impl Strategy<Value = JointSpace> {
    let joint =
        (0u8..3, -3.0f64..0.0, 0.1f64..3.0, 0.1f64..3.0).prop_map(|(kind, lo, w, weight)| {
            let joint = match kind {
                0 => Joint::revolute("r", lo, lo + w),
                1 => Joint::prismatic("p", lo, lo + w),
                _ => Joint::continuous("c"),
            };
            joint.weight(weight)
        });
    prop::collection::vec(joint, 1..=12).prop_map(|joints| JointSpace::new(joints).unwrap())
}

/// Two states sampled uniformly in `space` from a seed.
fn two_states<S: StateSpace>(space: &S, seed: u64) -> (Vec<f64>, Vec<f64>) {
    let mut rng = SeededRng::seed_from_u64(seed);
    let mut a = vec![0.0; space.dimension()];
    let mut b = a.clone();
    space.sample_uniform(&mut rng, &mut a);
    space.sample_uniform(&mut rng, &mut b);
    (a, b)
}

proptest! {
    #[test]
    fn real_vector_space_laws(space in boxes(), seed in any::<u64>(), t in 0.0f64..=1.0) {
        let (a, b) = two_states(&space, seed);
        prop_assert!(space.contains(&a) && space.contains(&b));
        check_laws(&space, &a, &b, t)?;
    }

    #[test]
    fn joint_space_laws(space in joint_spaces(), seed in any::<u64>(), t in 0.0f64..=1.0) {
        let (a, b) = two_states(&space, seed);
        prop_assert!(space.contains(&a) && space.contains(&b));
        check_laws(&space, &a, &b, t)?;
    }

    #[test]
    fn enforce_bounds_lands_inside(space in joint_spaces(), seed in any::<u64>(), push in -20.0f64..20.0) {
        let (mut a, _) = two_states(&space, seed);
        for x in &mut a {
            *x += push;
        }
        space.enforce_bounds(&mut a);
        prop_assert!(space.contains(&a), "{a:?} out of bounds after enforce_bounds");
    }

    #[test]
    fn reflect_into_bounds_lands_inside_and_keeps_inside_states(
        space in joint_spaces(),
        seed in any::<u64>(),
        push in -20.0f64..20.0,
    ) {
        let (inside, _) = two_states(&space, seed);
        let mut kept = inside.clone();
        space.reflect_into_bounds(&mut kept);
        for (i, joint) in space.joints().iter().enumerate() {
            if !matches!(joint.kind, mit_star_spaces::JointKind::Continuous) {
                prop_assert_eq!(kept[i], inside[i]);
            }
        }
        let mut pushed: Vec<f64> = inside.iter().map(|x| x + push).collect();
        space.reflect_into_bounds(&mut pushed);
        prop_assert!(space.contains(&pushed), "{pushed:?} out of bounds after reflect_into_bounds");
    }

    #[test]
    fn box_reflection_folds_the_overshoot_back(space in boxes(), seed in any::<u64>(), depth in 0.0f64..1.0) {
        // A state pushed past a bound by less than the interval comes back as far inside.
        let (mut a, _) = two_states(&space, seed);
        let (lower, upper) = (space.lower()[0], space.upper()[0]);
        let overshoot = depth * (upper - lower);
        a[0] = lower - overshoot;
        space.reflect_into_bounds(&mut a);
        prop_assert!((a[0] - (lower + overshoot)).abs() <= 1e-9 * (1.0 + lower.abs() + upper.abs()));
        a[0] = upper + overshoot;
        space.reflect_into_bounds(&mut a);
        prop_assert!((a[0] - (upper - overshoot)).abs() <= 1e-9 * (1.0 + lower.abs() + upper.abs()));
        prop_assert!(space.contains(&a));
    }

    #[test]
    fn continuous_joints_wrap(x in -PI..PI, turns in -5i32..5, weight in 0.1f64..3.0) {
        let space = JointSpace::new(vec![Joint::continuous("c").weight(weight)]).unwrap();
        // Adding whole turns does not move the joint.
        let shifted = x + f64::from(turns) * 2.0 * PI;
        prop_assert!(space.distance(&[x], &[shifted]) <= 1e-9);
        let mut wrapped = [shifted];
        space.enforce_bounds(&mut wrapped);
        prop_assert!((wrapped[0] - x).abs() <= 1e-9 || (wrapped[0] - x).abs() >= 2.0 * PI - 1e-9);
        // No two angles are further apart than half a turn.
        prop_assert!(space.distance(&[x], &[0.0]) <= weight * PI + 1e-12);
    }

    #[test]
    fn joint_space_without_wrapping_is_euclidean(space in boxes(), seed in any::<u64>()) {
        // A joint space of unit-weight limited joints is the same geometry as the box.
        let joints = space
            .lower()
            .iter()
            .zip(space.upper())
            .map(|(&lo, &hi)| Joint::prismatic("p", lo, hi))
            .collect();
        let joint_space = JointSpace::new(joints).unwrap();
        prop_assert!(joint_space.is_euclidean());
        let (a, b) = two_states(&space, seed);
        prop_assert!((space.distance(&a, &b) - joint_space.distance(&a, &b)).abs() <= 1e-12);
        prop_assert!((space.measure() - joint_space.measure()).abs() <= 1e-9 * space.measure());
    }
}
