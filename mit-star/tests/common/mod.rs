//! Helpers shared by the integration tests: an independent path validator and small queries.

#![allow(dead_code, unreachable_pub)]

pub mod scheduled;

use mit_star::{Counters, Eit, Outcome, Planner, Solution};
use mit_star_spaces::{StateSpace, euclidean_distance};
use mit_star_validity::{StateValidity, World};

/// Independently re-validates a path: every segment is interpolated densely at a step of at
/// most `step / 2` (endpoints included) and each point is tested with the world's own check.
/// Shares no code with the planner's edge checkers.
pub fn path_is_valid(world: &World, path: &mit_star_spaces::States, step: f64) -> bool {
    let fine = step / 2.0;
    if path.is_empty() {
        return false;
    }
    let mut x = vec![0.0; path.dimension()];
    for i in 0..path.len() {
        if !world.is_valid(&path[i]) {
            return false;
        }
        if i == 0 {
            continue;
        }
        let (a, b) = (&path[i - 1], &path[i]);
        let pieces = (euclidean_distance(a, b) / fine).ceil().max(1.0) as usize;
        for j in 1..pieces {
            let t = j as f64 / pieces as f64;
            for d in 0..x.len() {
                x[d] = a[d] + (b[d] - a[d]) * t;
            }
            if !world.is_valid(&x) {
                return false;
            }
        }
    }
    true
}

/// Length of a path.
pub fn path_length(path: &mit_star_spaces::States) -> f64 {
    (1..path.len())
        .map(|i| euclidean_distance(&path[i - 1], &path[i]))
        .sum()
}

/// Everything a test asserts about a reported solution: it starts at the start and ends at a
/// goal, its cost is its length and at least the straight-line bound, it is valid by the
/// independent check, and the planner full-checked (whitelisted) every edge of it.
pub fn assert_solution_sound<Smp, E, H, G, N>(
    planner: &Eit<mit_star_spaces::RealVectorSpace, World, Smp, E, H, G, N>,
    solution: &Solution,
    start: &[f64],
    goals: &[Vec<f64>],
) where
    Smp: mit_star_samplers::Sampler<
            mit_star_spaces::RealVectorSpace,
            mit_star_validity::Counted<World>,
        > + Clone,
    E: mit_star_validity::EdgeChecker<
            mit_star_spaces::RealVectorSpace,
            mit_star_validity::Counted<World>,
        > + Clone,
    H: mit_star_heuristics::Heuristic<mit_star_spaces::RealVectorSpace>,
    G: mit_star::Guidance,
    N: mit_star::NeighbourRule,
{
    let path = &solution.path;
    assert!(path.len() >= 2, "a path has at least two states");
    assert_eq!(&path[0], start, "the path starts at the start");
    assert!(
        goals.iter().any(|g| g.as_slice() == &path[path.len() - 1]),
        "the path ends at a goal"
    );
    let length = path_length(path);
    assert!(
        (length - solution.cost).abs() <= 1e-9 * length.max(1.0),
        "cost {} vs length {length}",
        solution.cost
    );
    let bound = goals
        .iter()
        .map(|g| euclidean_distance(start, g))
        .fold(f64::INFINITY, f64::min);
    assert!(
        solution.cost >= bound - 1e-12,
        "cost {} below the straight line {bound}",
        solution.cost
    );
    assert!(
        path_is_valid(planner.validity(), path, planner.step()),
        "independent check failed"
    );
    let vertices = planner.solution_vertices();
    assert_eq!(vertices.len(), path.len());
    for pair in vertices.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let xa = planner.graph().state_of(a).expect("live vertex");
        let xb = planner.graph().state_of(b).expect("live vertex");
        let d = planner.space().distance(xa, xb);
        assert_eq!(
            planner.graph().edge_status(a, b, d, planner.step()),
            mit_star_validity::EdgeStatus::Valid,
            "edge {a:?} → {b:?} of the path was not whitelisted"
        );
    }
}

/// Costs along a trace never increase (strictly decrease, in fact) and times never decrease.
pub fn assert_trace_monotone<P: Planner + ?Sized>(planner: &P) {
    let points = planner.trace().points();
    for w in points.windows(2) {
        assert!(w[1].cost < w[0].cost, "trace cost rose: {:?}", points);
        assert!(w[1].time >= w[0].time, "trace time went back: {:?}", points);
    }
    if let Some(last) = points.last() {
        assert_eq!(last.cost, planner.best_cost());
    }
}

/// Everything a run reports that must be bit-identical for equal seeds.
pub fn fingerprint(planner: &dyn Planner, outcome: &Outcome) -> (Vec<u64>, Vec<u64>, Counters) {
    let costs = planner
        .trace()
        .points()
        .iter()
        .map(|p| p.cost.to_bits())
        .collect();
    let path = outcome
        .solution()
        .map(|s| s.path.as_flat().iter().map(|x| x.to_bits()).collect())
        .unwrap_or_default();
    (costs, path, planner.counters())
}
