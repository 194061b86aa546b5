//! Tests of [`NearTerminals`]: its fraction, its fallback to the wrapped sampler, its settings,
//! and that its draws respect the effective bound and are reflected, not clamped, at the bounds.

use mit_star_spaces::{Never, RealVectorSpace, euclidean_distance};
use mit_star_validity::{AxisBox, Counted, World};

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

/// A sampler answering 80 % of requests near the terminals or the frontier, at scales 0.05 to
/// 0.2, with frontier rays `rays`.
fn ray_sampler(rays: bool) -> NearTerminals<UniformSampler> {
    let (space, start, goal) = square();
    NearTerminals::new(UniformSampler::new(5), &space, &start, &[goal], 5)
        .unwrap()
        .with_fraction(0.8)
        .unwrap()
        .with_scales(0.05, 0.2)
        .unwrap()
        .with_frontier_rays(rays)
}

#[test]
fn frontier_rays_return_the_midpoint_then_the_far_end_of_a_free_line() {
    let (space, _, _) = square();
    let world = World::in_space(&space);
    let mut sampler = ray_sampler(true);
    let frontier = [0.5, 0.5];
    Sampler::<RealVectorSpace, World>::observe_frontier(&mut sampler, &frontier);
    let mut x = [0.0; 2];
    let (mut midpoints, mut far_ends) = (0, 0);
    let mut pending: Option<[f64; 2]> = None;
    for _ in 0..2000 {
        sampler
            .sample(&space, &world, CostBound::Unbounded, &Never, &mut x)
            .unwrap();
        if Sampler::<RealVectorSpace, World>::last_origin(&sampler) != SampleOrigin::NearTerminal {
            continue;
        }
        let d = euclidean_distance(&x, &frontier);
        if let Some(m) = pending.take() {
            // The line's far end comes next, twice as far along the same line.
            for i in 0..2 {
                let expected = frontier[i] + 2.0 * (m[i] - frontier[i]);
                assert!((x[i] - expected).abs() < 1e-12, "{x:?} after {m:?}");
            }
            far_ends += 1;
        } else if (d - 0.1).abs() < 1e-12 {
            pending = Some(x);
            midpoints += 1;
        }
    }
    // Of the 1 600 near requests, those not returning a far end start a line half the time
    // (`L = 0.5 · (1 600 − L)`, about 530 lines); a target nearer than 0.2 (one in eight)
    // makes a shorter one.
    assert!((380..560).contains(&midpoints), "{midpoints}");
    assert!(far_ends + 1 >= midpoints, "{far_ends} of {midpoints}");
}

#[test]
fn blocked_lines_leave_the_gaussian_draws_and_no_frontier_leaves_the_sequence() {
    let (space, _, _) = square();
    // A free square of side 0.1 around the frontier state, in a ring of boxes: every line
    // of length 0.2 from its centre leaves it.
    let mut world = World::in_space(&space);
    for (c, w) in [
        ([0.5, 0.8], [1.0, 0.5]),
        ([0.5, 0.2], [1.0, 0.5]),
        ([0.2, 0.5], [0.5, 1.0]),
        ([0.8, 0.5], [0.5, 1.0]),
    ] {
        world = world
            .with_obstacle(AxisBox::new(c.to_vec(), w.to_vec()))
            .unwrap();
    }
    let world = Counted::new(world);
    let frontier = [0.5, 0.5];
    let mut x = [0.0; 2];
    // No frontier: rays or not, the same states.
    let (mut with, mut without) = (ray_sampler(true), ray_sampler(false));
    let mut y = [0.0; 2];
    for _ in 0..300 {
        with.sample(&space, &world, CostBound::Unbounded, &Never, &mut x)
            .unwrap();
        without
            .sample(&space, &world, CostBound::Unbounded, &Never, &mut y)
            .unwrap();
        assert_eq!(x, y);
    }
    // Blocked lines: tested (the checks grow), none returned.
    Sampler::<RealVectorSpace, Counted<World>>::observe_frontier(&mut with, &frontier);
    Sampler::<RealVectorSpace, Counted<World>>::observe_frontier(&mut without, &frontier);
    for _ in 0..600 {
        with.sample(&space, &world, CostBound::Unbounded, &Never, &mut x)
            .unwrap();
        without
            .sample(&space, &world, CostBound::Unbounded, &Never, &mut y)
            .unwrap();
        assert!(world.is_valid(&x), "{x:?}");
        let d = euclidean_distance(&x, &frontier);
        assert!((d - 0.2).abs() > 1e-9, "a line's far end: {x:?}");
    }
    // The wrapper's own checks (the wrapped sampler's rejections, many in this world, left out).
    let checks = |s: &NearTerminals<UniformSampler>| s.draws.own().validity_checks;
    assert!(
        checks(&with) > checks(&without) + 100,
        "{} {}",
        checks(&with),
        checks(&without)
    );
}

/// A world of the given batch width that records the sizes of the batches it decides (1 for
/// a state tested alone).
struct Recording {
    world: World,
    width: usize,
    sizes: std::cell::RefCell<Vec<usize>>,
}

impl StateValidity for Recording {
    fn is_valid(&self, s: &[f64]) -> bool {
        self.sizes.borrow_mut().push(1);
        self.world.is_valid(s)
    }
    fn batch_width(&self) -> usize {
        self.width
    }
    fn are_valid(&self, states: &[f64], dimension: usize, valid: &mut [bool]) {
        self.sizes.borrow_mut().push(states.len() / dimension);
        for (s, v) in states.chunks_exact(dimension).zip(valid) {
            *v = self.world.is_valid(s);
        }
    }
}

/// The near-terminal draws of 400 requests (half of them near a terminal) with a box over the
/// goal, against a checker of batch width `width`: checks that every call the checker got was
/// of `width` states and that the wrapper counted each state checked, and returns how many
/// states it handed out near a terminal — about half of the half of the requests answered
/// near a terminal are near the start, and only those are valid.
fn near_draws_with_width(width: usize) -> u64 {
    let (space, start, goal) = square();
    let world = World::in_space(&space)
        .with_obstacle(AxisBox::new(vec![0.9, 0.5], vec![0.6, 1.0]))
        .unwrap();
    let checker = Recording {
        world,
        width,
        sizes: Default::default(),
    };
    let mut near = NearTerminals::new(UniformSampler::new(2), &space, &start, &[goal], 2)
        .unwrap()
        .with_fraction(0.5)
        .unwrap()
        .with_scales(0.01, 0.05)
        .unwrap();
    let mut x = [0.0; 2];
    let mut returned_near = 0;
    for _ in 0..400 {
        near.sample(&space, &checker, CostBound::Unbounded, &Never, &mut x)
            .unwrap();
        if Sampler::<RealVectorSpace, Recording>::last_origin(&near) == SampleOrigin::NearTerminal {
            returned_near += 1;
            // Handed out only when valid: near the start, never in the box (x from 0.6).
            assert!(x[0] < 0.6, "{x:?}");
        }
    }
    let c = Sampler::<RealVectorSpace, Recording>::counters(&near);
    assert_eq!(c.near_terminals, returned_near);
    let sizes = checker.sizes.into_inner();
    assert!(
        !sizes.is_empty() && sizes.iter().all(|&n| n == width),
        "{sizes:?}"
    );
    assert_eq!(c.validity_checks, (width * sizes.len()) as u64);
    assert!((60..140).contains(&returned_near), "{returned_near}");
    returned_near
}

#[test]
fn a_batched_checker_decides_the_near_draws_eight_at_a_time() {
    // All in calls of eight: no state was tested alone.
    near_draws_with_width(8);
}

#[test]
fn a_checker_of_width_one_tests_the_near_draws_one_by_one() {
    near_draws_with_width(1);
}
