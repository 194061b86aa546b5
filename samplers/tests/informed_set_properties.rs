//! Properties of the informed-set geometry: rotations, containment, measure, empty sets, unions.

use faer::Mat;
use mit_star_samplers::{
    CostBound, InformedSampler, InformedSet, SampleError, Sampler, prolate_hyperspheroid_measure,
};
use mit_star_spaces::{
    Joint, JointSpace, Never, RealVectorSpace, SeededRng, StateSpace, euclidean_distance,
};
use mit_star_validity::AllValid;
use proptest::prelude::*;
use rand::{RngExt, SeedableRng};

/// A state with coordinates in `[lo, hi]`.
fn state(n: usize, lo: f64, hi: f64) -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(lo..hi, n)
}

/// Dimension, start and goal with coordinates in `[-0.5, 0.5]`, at least 0.05 apart.
fn problem(
    dims: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = (usize, Vec<f64>, Vec<f64>)> {
    dims.prop_flat_map(|n| (Just(n), state(n, -0.5, 0.5), state(n, -0.5, 0.5)))
        .prop_filter("start and goal too close", |(_, s, g)| {
            euclidean_distance(s, g) > 0.05
        })
}

/// Path length through `x` from `start` to `goal`.
fn through(start: &[f64], x: &[f64], goal: &[f64]) -> f64 {
    euclidean_distance(start, x) + euclidean_distance(x, goal)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn rotation_is_a_proper_rotation_onto_the_major_axis((n, start, goal) in problem(2..=32)) {
        let space = RealVectorSpace::cube(n, -1.0, 1.0).unwrap();
        let set = InformedSet::new(&space, &start, &[&goal]).unwrap();
        let r = set.rotation(0).unwrap();
        prop_assert_eq!(r.len(), n * n);
        let rm = Mat::<f64>::from_fn(n, n, |i, j| r[i * n + j]);
        let det = rm.determinant();
        prop_assert!((det - 1.0).abs() < 1e-10, "det R = {}", det);
        for i in 0..n {
            for j in 0..n {
                let dot: f64 = (0..n).map(|k| r[i * n + k] * r[j * n + k]).sum();
                let expected = if i == j { 1.0 } else { 0.0 };
                prop_assert!((dot - expected).abs() < 1e-12, "(R Rᵀ)[{}][{}] = {}", i, j, dot);
            }
        }
        let s_min = euclidean_distance(&start, &goal);
        for i in 0..n {
            let k1 = (goal[i] - start[i]) / s_min;
            prop_assert!((r[i * n] - k1).abs() < 1e-12, "(R e1)[{}] = {} ≠ {}", i, r[i * n], k1);
        }
        prop_assert!((set.minimum_cost() - s_min).abs() < 1e-12);
    }

    #[test]
    fn informed_and_estimated_samples_lie_in_the_spheroid_and_the_bounds(
        (n, start, goal) in problem(2..=32),
        stretch in 0.01f64..0.5,
        seed in any::<u64>(),
        estimated in any::<bool>(),
    ) {
        let space = RealVectorSpace::cube(n, -1.0, 1.0).unwrap();
        let cost = euclidean_distance(&start, &goal) * (1.0 + stretch);
        let bound = if estimated { CostBound::Estimated(cost) } else { CostBound::Solution(cost) };
        let mut sampler = InformedSampler::new(&space, &start, &[&goal], seed).unwrap();
        let mut x = vec![0.0; n];
        for _ in 0..16 {
            sampler.sample(&space, &AllValid, bound, &Never, &mut x).unwrap();
            prop_assert!(space.contains(&x), "{:?} outside the bounds", x);
            let c = through(&start, &x, &goal);
            prop_assert!(c < cost * (1.0 + 1e-12), "path through sample costs {} ≥ {}", c, cost);
        }
    }

    #[test]
    fn wide_sets_are_clipped_to_the_bounds(
        (n, start, goal) in (2usize..=4).prop_flat_map(|n| (Just(n), state(n, -1.0, 1.0), state(n, -1.0, 1.0))),
        stretch in 0.01f64..4.0,
        seed in any::<u64>(),
    ) {
        let space = RealVectorSpace::cube(n, -1.0, 1.0).unwrap();
        let cost = euclidean_distance(&start, &goal) * (1.0 + stretch) + 1e-3;
        let mut set = InformedSet::new(&space, &start, &[&goal]).unwrap();
        let mut rng = SeededRng::seed_from_u64(seed);
        let mut x = vec![0.0; n];
        for _ in 0..32 {
            set.draw(&space, &mut rng, Some(cost), &Never, &mut x).unwrap();
            prop_assert!(space.contains(&x));
            prop_assert!(through(&start, &x, &goal) < cost * (1.0 + 1e-12));
        }
    }

    #[test]
    fn measure_formula_matches_monte_carlo(
        n in 2usize..=3,
        s_min in 0.1f64..1.0,
        stretch in 0.05f64..1.0,
        seed in any::<u64>(),
    ) {
        // Foci on the first axis; the spheroid lies within c/2 of the centre, so count hits in
        // the cube of half-side c/2 around it.
        let cost = s_min * (1.0 + stretch);
        let space = RealVectorSpace::cube(n, -10.0, 10.0).unwrap();
        let mut start = vec![0.0; n];
        start[0] = -s_min / 2.0;
        let mut goal = vec![0.0; n];
        goal[0] = s_min / 2.0;
        let set = InformedSet::new(&space, &start, &[&goal]).unwrap();
        let mut rng = SeededRng::seed_from_u64(seed);
        let trials = 20_000;
        let mut x = vec![0.0; n];
        let mut hits = 0u32;
        for _ in 0..trials {
            x.iter_mut().for_each(|v| *v = cost * (rng.random::<f64>() - 0.5));
            hits += u32::from(set.contains(&space, Some(cost), &x));
        }
        let p = f64::from(hits) / f64::from(trials);
        let cube = cost.powi(n as i32);
        let formula = prolate_hyperspheroid_measure(n, s_min, cost);
        let expected_p = formula / cube;
        // Five binomial standard errors.
        let tolerance = 5.0 * (expected_p * (1.0 - expected_p) / f64::from(trials)).sqrt();
        prop_assert!((p - expected_p).abs() < tolerance, "hit rate {} vs {} ± {}", p, expected_p, tolerance);
        prop_assert!((set.measure(&space, Some(cost)) - formula).abs() < 1e-12 * formula.max(1.0));
    }

    #[test]
    fn measure_in_2d_is_the_ellipse_area(s_min in 0.0f64..5.0, k in 1.0001f64..10.0) {
        let cost = s_min * k + if s_min == 0.0 { 1.0 } else { 0.0 };
        let (a, b) = (cost / 2.0, (cost * cost - s_min * s_min).sqrt() / 2.0);
        let area = std::f64::consts::PI * a * b;
        let formula = prolate_hyperspheroid_measure(2, s_min, cost);
        prop_assert!((formula - area).abs() <= 1e-12 * area.max(1.0));
    }

    #[test]
    fn empty_sets_are_reported_by_every_informed_draw(
        (n, start, goal) in problem(2..=16),
        below in 0.0f64..1.0,
        seed in any::<u64>(),
    ) {
        let space = RealVectorSpace::cube(n, -1.0, 1.0).unwrap();
        let s_min = euclidean_distance(&start, &goal);
        let cost = s_min * below;
        let mut set = InformedSet::new(&space, &start, &[&goal]).unwrap();
        let mut rng = SeededRng::seed_from_u64(seed);
        let mut x = vec![0.0; n];
        let empty = set.draw(&space, &mut rng, Some(cost), &Never, &mut x);
        let is_empty = matches!(empty, Err(SampleError::EmptySet { .. }));
        prop_assert!(is_empty, "{:?}", empty);
        prop_assert_eq!(set.measure(&space, Some(cost)), 0.0);
        let mut sampler = InformedSampler::new(&space, &start, &[&goal], seed).unwrap();
        let result = sampler.sample(&space, &AllValid, CostBound::Estimated(cost), &Never, &mut x);
        let is_empty = matches!(result, Err(SampleError::EmptySet { bound, minimum } ) if bound == cost && minimum == s_min);
        prop_assert!(is_empty, "{:?}", result);
    }

    #[test]
    fn samples_of_several_goals_lie_in_the_union(
        n in 2usize..=6,
        goals in 2usize..=4,
        stretch in 0.01f64..1.0,
        seed in any::<u64>(),
    ) {
        let space = RealVectorSpace::cube(n, -1.0, 1.0).unwrap();
        let mut rng = SeededRng::seed_from_u64(seed);
        let mut random_state = || -> Vec<f64> { (0..n).map(|_| rng.random_range(-0.6..0.6)).collect() };
        let start = random_state();
        let goals: Vec<Vec<f64>> = (0..goals).map(|_| random_state()).collect();
        let mut set = InformedSet::new(&space, &start, &goals).unwrap();
        // Above the nearest goal's minimum: some goals' sets may still be empty.
        let cost = set.minimum_cost() * (1.0 + stretch) + 1e-6;
        let mut x = vec![0.0; n];
        for _ in 0..32 {
            set.draw(&space, &mut rng, Some(cost), &Never, &mut x).unwrap();
            prop_assert!(space.contains(&x));
            let best = goals.iter().map(|g| through(&start, &x, g)).fold(f64::INFINITY, f64::min);
            prop_assert!(best < cost * (1.0 + 1e-12), "cheapest path through sample {} ≥ {}", best, cost);
        }
    }
}

#[test]
fn overlapping_goals_are_sampled_uniformly_over_the_union() {
    // Two ellipses sharing the start as a focus, mirrored about the y axis, overlapping
    // around the start. Uniform over the union puts a fraction |E1 ∩ E2| / |E1 ∪ E2| of the
    // samples in the overlap; a plain mixture without thinning would put |E1 ∩ E2| / |E1|
    // there (the overlap counted twice).
    let space = RealVectorSpace::cube(2, -1.0, 1.0).unwrap();
    let goals = [[0.3, 0.0], [-0.3, 0.0]];
    let mut set = InformedSet::new(&space, &[0.0, 0.0], &goals).unwrap();
    let cost = 0.5;
    let inside = |x: &[f64], g: &[f64; 2]| {
        euclidean_distance(x, &[0.0, 0.0]) + euclidean_distance(x, g) < cost
    };
    let (mut one, mut both, mut either) = (0u32, 0u32, 0u32);
    let steps = 800;
    for i in 0..steps {
        for j in 0..steps {
            let x = [
                -0.45 + 0.9 * (f64::from(i) + 0.5) / f64::from(steps),
                -0.25 + 0.5 * (f64::from(j) + 0.5) / f64::from(steps),
            ];
            let (a, b) = (inside(&x, &goals[0]), inside(&x, &goals[1]));
            one += u32::from(a);
            both += u32::from(a && b);
            either += u32::from(a || b);
        }
    }
    let uniform = f64::from(both) / f64::from(either);
    let mixture = f64::from(both) / f64::from(one);
    assert!(mixture - uniform > 0.05, "test cannot tell them apart");
    let mut rng = SeededRng::seed_from_u64(17);
    let mut x = [0.0; 2];
    let draws = 20_000u32;
    let (mut in_both, mut right) = (0u32, 0u32);
    for _ in 0..draws {
        set.draw(&space, &mut rng, Some(cost), &Never, &mut x)
            .unwrap();
        assert!(inside(&x, &goals[0]) || inside(&x, &goals[1]));
        in_both += u32::from(inside(&x, &goals[0]) && inside(&x, &goals[1]));
        right += u32::from(x[0] > 0.0);
    }
    let observed = f64::from(in_both) / f64::from(draws);
    // Binomial standard error ≈ 0.003.
    assert!(
        (observed - uniform).abs() < 0.015,
        "overlap {observed} vs {uniform}"
    );
    let half = f64::from(right) / f64::from(draws);
    assert!((half - 0.5).abs() < 0.02, "right half {half}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// A weighted Euclidean metric (a joint space with a weighted prismatic joint, as the
    /// Fetch's torso) is a hyperspheroid in the scaled coordinates: drawn directly, not by
    /// rejection from the whole space, and uniform there (for the unit ball in `n`
    /// dimensions, `E[u₁²] = 1/(n+2)` along the axis and `(n−1)/(n+2)` across it).
    #[test]
    fn weighted_metrics_are_sampled_directly_and_uniformly(
        weight in 0.25f64..8.0,
        start in state(4, -0.5, 0.5),
        goal in state(4, -0.5, 0.5),
        stretch in 1.01f64..1.1,
        seed in any::<u64>(),
    ) {
        let space = JointSpace::new(vec![
            Joint::prismatic("torso", -4.0, 4.0).weight(weight),
            Joint::revolute("a", -3.0, 3.0),
            Joint::revolute("b", -3.0, 3.0),
            Joint::revolute("c", -3.0, 3.0),
        ])
        .unwrap();
        prop_assume!((weight - 1.0).abs() > 1e-3);
        prop_assert!(!space.is_euclidean());
        let s_min = space.distance(&start, &goal);
        prop_assume!(s_min > 0.05);
        let cost = stretch * s_min;
        let mut set = InformedSet::new(&space, &start, &[&goal]).unwrap();
        let mut rng = SeededRng::seed_from_u64(seed);
        let scale = [weight, 1.0, 1.0, 1.0];
        let axis: Vec<f64> = (0..4).map(|i| scale[i] * (goal[i] - start[i]) / s_min).collect();
        let (major, minor) = (cost / 2.0, (cost * cost - s_min * s_min).sqrt() / 2.0);
        let draws = 3_000;
        let (mut along, mut across) = (0.0, 0.0);
        let mut x = [0.0; 4];
        for _ in 0..draws {
            set.draw(&space, &mut rng, Some(cost), &Never, &mut x).unwrap();
            prop_assert!(space.contains(&x));
            let through = space.distance(&start, &x) + space.distance(&x, &goal);
            prop_assert!(through < cost * (1.0 + 1e-12), "{} ≥ {}", through, cost);
            // Offset from the centre in scaled coordinates, split along and across the axis.
            let y: Vec<f64> = (0..4).map(|i| scale[i] * (x[i] - 0.5 * (start[i] + goal[i]))).collect();
            let t: f64 = y.iter().zip(&axis).map(|(a, b)| a * b).sum();
            let perp = y.iter().map(|v| v * v).sum::<f64>() - t * t;
            along += (t / major).powi(2);
            across += perp / (minor * minor);
        }
        // The set lies inside the bounds, so nothing is rejected (rejection from the whole
        // space would turn down all but a few per million here).
        let counters = set.counters();
        prop_assert_eq!(counters.rejected, 0);
        let (along, across) = (along / f64::from(draws), across / f64::from(draws));
        prop_assert!((along - 1.0 / 6.0).abs() < 0.02, "E[t²] = {}", along);
        prop_assert!((across - 0.5).abs() < 0.04, "E[|perp|²] = {}", across);
    }
}
