//! Tests of [`NearTerminals`]: its fraction, its fallback to the wrapped sampler, its settings,
//! and that its draws respect the effective bound and are reflected, not clamped, at the bounds.

use spaces::{Never, RealVectorSpace, euclidean_distance};
use validity::{AxisBox, Counted, World};

use super::*;
use crate::{Estimated, InformedSampler, UniformSampler};

fn square() -> (RealVectorSpace, [f64; 2], [f64; 2]) {
    let space = RealVectorSpace::cube(2, 0.0, 1.0).unwrap();
    (space, [0.1, 0.5], [0.9, 0.5])
}

#[test]
fn a_fraction_of_zero_leaves_the_wrapped_sequence_untouched() {
    let (space, start, goal) = square();
    let world = World::in_space(&space);
    let mut bare = UniformSampler::new(4);
    let mut wrapped = NearTerminals::new(UniformSampler::new(4), &space, &start, &[goal], 4)
        .unwrap()
        .with_fraction(0.0)
        .unwrap();
    let (mut a, mut b) = ([0.0; 2], [0.0; 2]);
    for _ in 0..50 {
        bare.sample(&space, &world, CostBound::Unbounded, &Never, &mut a)
            .unwrap();
        wrapped
            .sample(&space, &world, CostBound::Unbounded, &Never, &mut b)
            .unwrap();
        assert_eq!(a, b);
    }
    let c = Sampler::<RealVectorSpace, World>::counters(&wrapped);
    assert_eq!((c.near_terminals, c.returned), (0, 50));
}

#[test]
fn invalid_or_uninformed_draws_fall_back_to_the_wrapped_sampler() {
    let (space, start, goal) = square();
    // A box over the goal: every draw near it is invalid, and only the start's count.
    let world = Counted::new(
        World::in_space(&space)
            .with_obstacle(AxisBox::new(vec![0.9, 0.5], vec![0.6, 1.0]))
            .unwrap(),
    );
    let informed = InformedSampler::new(&space, &start, &[goal], 1).unwrap();
    let goal_in_box = [0.9, 0.5];
    let mut sampler = NearTerminals::new(informed, &space, &start, &[goal_in_box], 1)
        .unwrap()
        .with_fraction(0.9)
        .unwrap()
        .with_scales(0.01, 0.05)
        .unwrap();
    let mut x = [0.0; 2];
    let bound = CostBound::Solution(0.85);
    for _ in 0..400 {
        sampler
            .sample(&space, &world, bound, &Never, &mut x)
            .unwrap();
        assert!(world.is_valid(&x), "{x:?}");
        assert!(sampler.draws.set.contains(&space, Some(0.85), &x), "{x:?}");
    }
    let c = Sampler::<RealVectorSpace, Counted<World>>::counters(&sampler);
    // About half of the 360 near draws are at the start, and most of those lie in the
    // informed set; the ones at the goal are all invalid or outside it.
    assert!((60..250).contains(&c.near_terminals), "{c:?}");
    assert_eq!(c.returned, 400);
    assert!(c.rejected + c.validity_checks > c.returned, "{c:?}");
}

#[test]
fn out_of_range_settings_are_refused() {
    let (space, start, goal) = square();
    let make = || NearTerminals::new(UniformSampler::new(0), &space, &start, &[goal], 0);
    for fraction in [1.0, -0.1, f64::NAN] {
        let error = make().unwrap().with_fraction(fraction).unwrap_err();
        assert!(matches!(error, SamplerError::Fraction { .. }), "{error}");
    }
    for (small, large) in [(0.0, 1.0), (0.5, 0.1), (0.1, f64::INFINITY)] {
        assert!(make().unwrap().with_scales(small, large).is_err());
    }
    assert!(make().unwrap().with_scales(0.1, 0.1).is_ok());
}

#[test]
fn before_a_solution_near_draws_stay_in_the_wrapped_estimate() {
    // NearTerminals around MIT*'s Estimated: the planner asks without a bound, and the
    // estimate bounds the wrapped sampler's draws; the draws near the terminals must keep
    // inside it too.
    let (space, start, goal) = square();
    let world = World::in_space(&space);
    let informed = InformedSampler::new(&space, &start, &[goal], 2).unwrap();
    let mut sampler = NearTerminals::new(Estimated::new(informed), &space, &start, &[goal], 2)
        .unwrap()
        .with_fraction(0.9)
        .unwrap()
        .with_scales(0.1, 0.4)
        .unwrap();
    type Plain = dyn Sampler<RealVectorSpace, World>;
    let set = sampler.draws.set.clone();
    let dynamic: &mut Plain = &mut sampler;
    // ŝ_adm = 0.9 with a third verified: s̃_est = 0.9 · √(1 + 4/9) ≈ 1.08 (foci 0.8 apart).
    dynamic.observe_invalid_lazy_edge(LazyPathFailure {
        cost_to_come: 0.3,
        edge_estimate: 0.1,
        cost_to_go: 0.5,
    });
    let estimate = dynamic.estimated_cost().unwrap();
    assert!((estimate - 0.9 * (13.0f64 / 9.0).sqrt()).abs() < 1e-12);
    let mut x = [0.0; 2];
    let mut near = 0;
    for _ in 0..400 {
        dynamic
            .sample(&space, &world, CostBound::Unbounded, &Never, &mut x)
            .unwrap();
        near += usize::from(dynamic.last_origin() == SampleOrigin::NearTerminal);
        // Every state, near a terminal or not, lies in the estimated informed set.
        assert!(
            set.contains(&space, Some(estimate), &x),
            "{x:?} outside the estimate {estimate}"
        );
    }
    assert!(near > 100, "{near}");
}

#[test]
fn near_draws_are_reflected_at_the_bounds_not_piled_onto_them() {
    // A start on the lower bound of x: clamping would put about half of its draws exactly
    // on that bound.
    let space = RealVectorSpace::cube(2, 0.0, 1.0).unwrap();
    let world = World::in_space(&space);
    let (start, goal) = ([0.0, 0.5], [1.0, 0.5]);
    let mut sampler = NearTerminals::new(UniformSampler::new(6), &space, &start, &[goal], 6)
        .unwrap()
        .with_fraction(0.9)
        .unwrap()
        .with_scales(0.05, 0.3)
        .unwrap();
    let mut x = [0.0; 2];
    let mut near = 0;
    for _ in 0..400 {
        sampler
            .sample(&space, &world, CostBound::Unbounded, &Never, &mut x)
            .unwrap();
        assert!(space.contains(&x));
        if Sampler::<RealVectorSpace, World>::last_origin(&sampler) == SampleOrigin::NearTerminal {
            near += 1;
            assert!(
                x.iter().all(|&c| c > 0.0 && c < 1.0),
                "{x:?}: a draw on the bounds"
            );
        }
    }
    assert!(near > 300, "{near}");
}

#[test]
fn half_of_the_near_draws_centre_on_the_frontier_while_there_is_one() {
    let (space, start, goal) = square();
    let world = World::in_space(&space);
    let mut sampler = NearTerminals::new(UniformSampler::new(8), &space, &start, &[goal], 8)
        .unwrap()
        .with_fraction(0.8)
        .unwrap()
        .with_scales(0.005, 0.01)
        .unwrap();
    let counters = |s: &NearTerminals<UniformSampler>| {
        let c = Sampler::<RealVectorSpace, World>::counters(s);
        (c.near_terminals, c.near_frontier)
    };
    let frontier = [0.5, 0.9];
    let mut x = [0.0; 2];
    let mut draw = |sampler: &mut NearTerminals<UniformSampler>| {
        sampler
            .sample(&space, &world, CostBound::Unbounded, &Never, &mut x)
            .unwrap();
        let near =
            Sampler::<RealVectorSpace, World>::last_origin(sampler) == SampleOrigin::NearTerminal;
        (near, euclidean_distance(&x, &frontier) < 0.05)
    };
    // Before any frontier: no draw centres on it.
    for _ in 0..200 {
        draw(&mut sampler);
    }
    assert_eq!(counters(&sampler).1, 0);
    Sampler::<RealVectorSpace, World>::observe_frontier(&mut sampler, &frontier);
    let (before, _) = counters(&sampler);
    let mut near_frontier = 0;
    for _ in 0..1000 {
        let (near, close) = draw(&mut sampler);
        near_frontier += u64::from(near && close);
    }
    let (near_terminals, counted) = counters(&sampler);
    // 0.8 · 0.5 of 1 000 requests, every one of them valid in an empty world.
    assert!((330..470).contains(&counted), "{counted}");
    assert_eq!(counted, near_frontier);
    assert!(
        near_terminals - before > counted,
        "the terminals keep the other half"
    );
    // An empty frontier ends them.
    Sampler::<RealVectorSpace, World>::observe_frontier(&mut sampler, &[]);
    for _ in 0..300 {
        draw(&mut sampler);
    }
    assert_eq!(counters(&sampler).1, counted);
    // So does a reseed.
    Sampler::<RealVectorSpace, World>::observe_frontier(&mut sampler, &frontier);
    Sampler::<RealVectorSpace, World>::reseed(&mut sampler, 9);
    for _ in 0..300 {
        draw(&mut sampler);
    }
    assert_eq!(counters(&sampler).1, 0);
}
