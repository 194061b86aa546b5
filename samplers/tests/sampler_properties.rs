//! Properties every sampler must have: valid states in the bounds (and in the informed set),
//! determinism per seed, prompt stops, empty-set reports, object safety.

use std::cell::Cell;

use mit_star_samplers::{
    AdaptiveSampler, BridgeSampler, CostBound, Estimated, GaussianSampler, InformedSampler,
    LazyPathFailure, NearTerminals, SampleError, Sampler, UniformSampler,
    prolate_hyperspheroid_measure,
};
use mit_star_spaces::{
    Joint, JointSpace, Never, RealVectorSpace, StateSpace, Stop, euclidean_distance,
};
use mit_star_validity::{AxisBox, Counted, StateValidity, World};
use proptest::prelude::*;

/// The cube `[-1, 1]^n` with a wall `|x0| ≤ 0.1` pierced by a slot `|x1| ≤ 0.02`, start and goal
/// on either side of the wall, on the slot's axis: every informed set contains the slot, so
/// every sampler (the Gaussian and bridge tests included) finds states in it.
fn slotted(n: usize) -> (RealVectorSpace, World, Vec<f64>, Vec<f64>) {
    let space = RealVectorSpace::cube(n, -1.0, 1.0).unwrap();
    let mut wall = vec![2.0; n];
    wall[0] = 0.2;
    let mut slot = vec![2.0; n];
    slot[0] = 0.2;
    slot[1] = 0.04;
    let world = World::in_space(&space)
        .with_obstacle(AxisBox::new(vec![0.0; n], wall))
        .unwrap()
        .with_anti_obstacle(AxisBox::new(vec![0.0; n], slot))
        .unwrap();
    let mut start = vec![0.0; n];
    start[0] = -0.6;
    let mut goal = vec![0.0; n];
    goal[0] = 0.6;
    (space, world, start, goal)
}

/// A sampler as a trait object, with its name for messages.
type Named<V> = (&'static str, Box<dyn Sampler<RealVectorSpace, V>>);

/// Every sampler of the crate, as trait objects, with a small `σ` so the Gaussian and bridge
/// tests see the 0.2-thick wall.
fn all_samplers<V: StateValidity>(
    space: &RealVectorSpace,
    start: &[f64],
    goal: &[f64],
    seed: u64,
) -> Vec<Named<V>> {
    let goals = [goal];
    vec![
        ("uniform", Box::new(UniformSampler::new(seed))),
        (
            "informed",
            Box::new(InformedSampler::new(space, start, &goals, seed).unwrap()),
        ),
        (
            "gaussian",
            Box::new(
                GaussianSampler::new(space, start, &goals, seed)
                    .unwrap()
                    .with_std_dev(0.05)
                    .unwrap(),
            ),
        ),
        (
            "bridge",
            Box::new(
                BridgeSampler::new(space, start, &goals, seed)
                    .unwrap()
                    .with_std_dev(0.05)
                    .unwrap(),
            ),
        ),
        (
            "adaptive",
            Box::new(AdaptiveSampler::new(space, start, &goals, seed).unwrap()),
        ),
        (
            "estimated adaptive",
            Box::new(estimated_adaptive(space, start, goal, seed)),
        ),
        (
            "near terminals (adaptive)",
            Box::new(
                NearTerminals::new(
                    AdaptiveSampler::new(space, start, &goals, seed).unwrap(),
                    space,
                    start,
                    &goals,
                    seed,
                )
                .unwrap()
                .with_fraction(0.5)
                .unwrap()
                .with_scales(0.02, 0.5)
                .unwrap(),
            ),
        ),
    ]
}

/// Cost of the estimate [`estimated_adaptive`] holds: `ŝ_adm = 1.2`, `γ = 0.25`,
/// `e_γ = √(1 + 0.75²) = 1.25`.
const ESTIMATE: f64 = 1.5;

/// MIT*'s sampler, `Estimated<AdaptiveSampler>`, after a lazy path through the slot failed.
fn estimated_adaptive(
    space: &RealVectorSpace,
    start: &[f64],
    goal: &[f64],
    seed: u64,
) -> Estimated<AdaptiveSampler> {
    let mut sampler = Estimated::new(AdaptiveSampler::new(space, start, &[goal], seed).unwrap());
    fail_lazy_path(&mut sampler);
    sampler
}

/// Tells a sampler that a lazy path through the slot failed (`ŝ_adm = 1.2`, `γ = 0.25`).
fn fail_lazy_path(sampler: &mut dyn Sampler<RealVectorSpace, World>) {
    sampler.observe_invalid_lazy_edge(LazyPathFailure {
        cost_to_come: 0.3,
        edge_estimate: 0.6,
        cost_to_go: 0.3,
    });
}

/// Stops after `limit` polls, counting them.
struct AfterPolls {
    polls: Cell<u64>,
    limit: u64,
}

impl AfterPolls {
    fn new(limit: u64) -> Self {
        Self {
            polls: Cell::new(0),
            limit,
        }
    }
}

impl Stop for AfterPolls {
    fn should_stop(&self) -> bool {
        self.polls.set(self.polls.get() + 1);
        self.polls.get() > self.limit
    }
}

fn bound_of(kind: u8, cost: f64) -> CostBound {
    match kind {
        0 => CostBound::Unbounded,
        1 => CostBound::Estimated(cost),
        _ => CostBound::Solution(cost),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn every_sampler_returns_valid_states_in_the_bounds_and_the_set(
        n in 2usize..=6,
        stretch in 0.02f64..1.0,
        kind in 0u8..3,
        seed in any::<u64>(),
    ) {
        let (space, world, start, goal) = slotted(n);
        let cost = 1.2 * (1.0 + stretch);
        let bound = bound_of(kind, cost);
        // A guard against hangs, far above what the samplers need.
        let guard = AfterPolls::new(5_000_000);
        let mut x = vec![0.0; n];
        for (name, mut sampler) in all_samplers(&space, &start, &goal, seed) {
            for _ in 0..8 {
                let result = sampler.sample(&space, &world, bound, &guard, &mut x);
                prop_assert!(result.is_ok(), "{}: {:?}", name, result);
                prop_assert!(world.is_valid(&x), "{}: invalid {:?}", name, x);
                prop_assert!(space.contains(&x), "{}: out of bounds {:?}", name, x);
                let through = euclidean_distance(&start, &x) + euclidean_distance(&x, &goal);
                if name != "uniform" && kind != 0 {
                    prop_assert!(through < cost * (1.0 + 1e-12), "{}: {} ≥ {}", name, through, cost);
                }
                if name == "estimated adaptive" && kind == 0 {
                    prop_assert!(through < ESTIMATE * (1.0 + 1e-12), "{}: {} ≥ {}", name, through, ESTIMATE);
                }
            }
            let counters = sampler.counters();
            prop_assert_eq!(counters.returned, 8, "{}", name);
            prop_assert!(counters.drawn >= 8 && counters.rejected <= counters.drawn, "{}: {:?}", name, counters);
        }
    }

    #[test]
    fn same_seed_gives_the_same_states_and_reseed_restarts(
        n in 2usize..=4,
        kind in 0u8..3,
        seed in any::<u64>(),
    ) {
        let (space, world, start, goal) = slotted(n);
        let bound = bound_of(kind, 1.8);
        let mut first = all_samplers(&space, &start, &goal, seed);
        let mut second = all_samplers(&space, &start, &goal, seed);
        let (mut a, mut b) = (vec![0.0; n], vec![0.0; n]);
        for ((name, one), (_, two)) in first.iter_mut().zip(&mut second) {
            let mut sequence = Vec::new();
            for _ in 0..6 {
                one.sample(&space, &world, bound, &Never, &mut a).unwrap();
                two.sample(&space, &world, bound, &Never, &mut b).unwrap();
                prop_assert_eq!(&a, &b, "{}", name);
                sequence.push(a.clone());
            }
            // Reseeding forgets planner feedback too: replay it to replay the sequence.
            one.reseed(seed);
            prop_assert_eq!(one.estimated_cost(), None, "{} remembers feedback", name);
            if *name == "estimated adaptive" {
                fail_lazy_path(one.as_mut());
            }
            for expected in &sequence {
                one.sample(&space, &world, bound, &Never, &mut a).unwrap();
                prop_assert_eq!(&a, expected, "{} after reseed", name);
            }
            two.reseed(seed ^ 0x9e37_79b9_7f4a_7c15);
            two.sample(&space, &world, bound, &Never, &mut b).unwrap();
            prop_assert_ne!(&b, &sequence[0], "{}: another seed, same first state", name);
        }
    }

    #[test]
    fn empty_informed_sets_are_reported_by_every_informed_sampler(
        n in 2usize..=8,
        below in 0.0f64..1.0,
        estimated in any::<bool>(),
    ) {
        let (space, world, start, goal) = slotted(n);
        let cost = 1.2 * below;
        let bound = if estimated { CostBound::Estimated(cost) } else { CostBound::Solution(cost) };
        let mut x = vec![0.0; n];
        for (name, mut sampler) in all_samplers(&space, &start, &goal, 1).into_iter().skip(1) {
            let result = sampler.sample(&space, &world, bound, &Never, &mut x);
            let empty = matches!(result, Err(SampleError::EmptySet { .. }));
            prop_assert!(empty, "{}: {:?}", name, result);
            prop_assert_eq!(sampler.sampled_measure(&space, bound), 0.0, "{}", name);
        }
    }
}

/// A world in which every state is invalid.
fn blocked(space: &RealVectorSpace) -> Counted<World> {
    let n = space.dimension();
    Counted::new(
        World::in_space(space)
            .with_obstacle(AxisBox::new(vec![0.0; n], vec![3.0; n]))
            .unwrap(),
    )
}

#[test]
fn a_fired_stop_ends_every_sampler_before_any_work() {
    let space = RealVectorSpace::cube(3, -1.0, 1.0).unwrap();
    let world = blocked(&space);
    let (start, goal) = ([-0.5, 0.0, 0.0], [0.5, 0.0, 0.0]);
    let mut samplers: Vec<Named<Counted<World>>> = all_samplers(&space, &start, &goal, 0);
    let mut x = [0.0; 3];
    for bound in [
        CostBound::Unbounded,
        CostBound::Estimated(1.5),
        CostBound::Solution(1.2),
    ] {
        for (name, sampler) in &mut samplers {
            let result = sampler.sample(&space, &world, bound, &|| true, &mut x);
            assert_eq!(result, Err(SampleError::Stopped), "{name} under {bound:?}");
            assert_eq!(
                sampler.counters().drawn,
                0,
                "{name} drew after the stop fired"
            );
        }
    }
    assert_eq!(world.count(), 0);
}

#[test]
fn a_stop_that_fires_later_ends_every_sampler_promptly() {
    // Nothing is valid, so only the stop condition can end the search. Each poll may be
    // followed by at most a few validity checks (a draw, a Gaussian neighbour, one segment
    // point), so the checks are bounded by a small multiple of the polls.
    let space = RealVectorSpace::cube(3, -1.0, 1.0).unwrap();
    let world = blocked(&space);
    let (start, goal) = ([-0.5, 0.0, 0.0], [0.5, 0.0, 0.0]);
    let samplers: Vec<Named<Counted<World>>> = all_samplers(&space, &start, &goal, 0);
    let mut x = [0.0; 3];
    for (name, mut sampler) in samplers {
        for bound in [CostBound::Unbounded, CostBound::Solution(1.3)] {
            let stop = AfterPolls::new(1000);
            world.reset();
            let result = sampler.sample(&space, &world, bound, &stop, &mut x);
            assert_eq!(result, Err(SampleError::Stopped), "{name}");
            assert_eq!(
                stop.polls.get(),
                1001,
                "{name}: polled after the stop fired"
            );
            assert!(
                world.count() >= 500,
                "{name}: only {} checks",
                world.count()
            );
            assert!(
                world.count() <= 3 * 1000,
                "{name}: {} checks for 1000 polls",
                world.count()
            );
        }
    }
}

#[test]
fn boxed_samplers_are_interchangeable() {
    let (space, world, start, goal) = slotted(3);
    let named = all_samplers::<World>(&space, &start, &goal, 5);
    let names: Vec<&str> = named.iter().map(|(name, _)| *name).collect();
    let mut samplers: Vec<Box<dyn Sampler<RealVectorSpace, World>>> =
        named.into_iter().map(|(_, sampler)| sampler).collect();
    let mut x = [0.0; 3];
    let spheroid = prolate_hyperspheroid_measure(3, 1.2, ESTIMATE);
    for (name, sampler) in names.iter().zip(&mut samplers) {
        sampler
            .sample(&space, &world, CostBound::Solution(1.5), &Never, &mut x)
            .unwrap();
        assert!(world.is_valid(&x));
        // Unbounded means the whole space, except to the wrapper holding an estimate.
        let measure = sampler.sampled_measure(&space, CostBound::Unbounded);
        let expected = if *name == "estimated adaptive" {
            spheroid
        } else {
            space.measure()
        };
        assert!((measure - expected).abs() < 1e-12, "{name}: {measure}");
    }
    // A box of a box is still a sampler.
    let mut nested: Box<Box<dyn Sampler<RealVectorSpace, World>>> = Box::new(samplers.remove(0));
    nested
        .sample(&space, &world, CostBound::Unbounded, &Never, &mut x)
        .unwrap();
}

#[test]
fn non_euclidean_spaces_use_rejection_in_their_own_metric() {
    // A wrapping joint: the informed set wraps around ±π, which direct sampling cannot produce.
    let space = JointSpace::new(vec![
        Joint::continuous("c"),
        Joint::revolute("r", -1.0, 1.0).weight(2.0),
    ])
    .unwrap();
    let (start, goal) = ([3.0, 0.0], [-3.0, 0.0]);
    let mut sampler = InformedSampler::new(&space, &start, &[goal], 8).unwrap();
    let s_min = space.distance(&start, &goal);
    assert!(s_min < 0.3, "the short way round");
    let cost = s_min + 0.4;
    let mut x = [0.0; 2];
    let mut crossed = false;
    for _ in 0..300 {
        sampler
            .sample(
                &space,
                &mit_star_validity::AllValid,
                CostBound::Solution(cost),
                &Never,
                &mut x,
            )
            .unwrap();
        assert!(space.contains(&x));
        assert!(space.distance(&start, &x) + space.distance(&x, &goal) < cost);
        crossed |= x[0].abs() > 3.0;
    }
    assert!(crossed, "no sample near the seam at ±π");
    assert_eq!(
        Sampler::<JointSpace, mit_star_validity::AllValid>::sampled_measure(
            &sampler,
            &space,
            CostBound::Unbounded
        ),
        space.measure()
    );
}

#[test]
fn mismatched_buffers_are_reported() {
    let (space, world, start, goal) = slotted(3);
    let mut x = [0.0; 2];
    for (name, mut sampler) in all_samplers(&space, &start, &goal, 0) {
        let result = sampler.sample(&space, &world, CostBound::Unbounded, &Never, &mut x);
        assert_eq!(
            result,
            Err(SampleError::DimensionMismatch {
                expected: 3,
                got: 2
            }),
            "{name}"
        );
    }
}
