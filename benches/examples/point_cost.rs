//! `point_cost`: what one grid point of an edge check costs, on the benchmark problems.
//!
//! ```text
//! cargo run --release -p mit-star-benches --example point_cost -- [EDGES] [DIMENSION]
//! ```
//!
//! For each problem it draws `EDGES` (default 400) seeded edges between valid states, 0.05 to
//! 0.5 long in random directions (valid and invalid ones, as a planner meets them), and fully
//! checks each from scratch at the paper's resolution (5e-6 of the extent), once one state at a
//! time (OMPL's way: interpolate, test every box) and once accelerated (the per-edge broad
//! phase and batched SIMD point checks). It prints the grid points decided and the
//! nanoseconds per point of each mode, best of five rounds, and checks that both modes give
//! every edge the same status after the same number of points.

use std::hint::black_box;
use std::time::Instant;

use mit_star_problems::Problem;
use mit_star_spaces::{Never, SeededRng, StateSpace};
use mit_star_validity::{DenseChecker, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity};
use rand::{RngExt, SeedableRng};

const RESOLUTION: f64 = 5e-6;
const ROUNDS: usize = 5;

/// `count` seeded edges between valid states of `problem`.
fn edges(problem: &Problem, count: usize) -> Vec<(Vec<f64>, Vec<f64>)> {
    let (space, world) = (problem.space(), problem.world());
    let n = space.dimension();
    let mut rng = SeededRng::seed_from_u64(11);
    let mut out = Vec::with_capacity(count);
    let (mut a, mut b) = (vec![0.0; n], vec![0.0; n]);
    while out.len() < count {
        space.sample_uniform(&mut rng, &mut a);
        let direction: Vec<f64> = (0..n).map(|_| rng.random::<f64>() - 0.5).collect();
        let norm = direction.iter().map(|x| x * x).sum::<f64>().sqrt();
        let length = 0.05 + 0.45 * rng.random::<f64>();
        for i in 0..n {
            b[i] = a[i] + length * direction[i] / norm;
        }
        if space.contains(&b) && world.is_valid(&a) && world.is_valid(&b) {
            out.push((a.clone(), b.clone()));
        }
    }
    out
}

/// Checks every edge fully from scratch; returns (statuses, points decided, seconds).
fn check_all(
    problem: &Problem,
    edges: &[(Vec<f64>, Vec<f64>)],
    accelerated: bool,
) -> (Vec<EdgeStatus>, u64, f64) {
    let (space, world) = (problem.space(), problem.world());
    let mut checker = DenseChecker::from_resolution(space, RESOLUTION)
        .expect("a valid resolution")
        .with_acceleration(accelerated);
    let mut statuses = Vec::with_capacity(edges.len());
    let started = Instant::now();
    for (a, b) in edges {
        let mut progress = EdgeProgress::default();
        statuses.push(black_box(checker.check_full(
            space,
            world,
            a,
            b,
            &mut progress,
            &Never,
        )));
    }
    let seconds = started.elapsed().as_secs_f64();
    let counters =
        EdgeChecker::<mit_star_spaces::RealVectorSpace, mit_star_validity::World>::counters(
            &checker,
        );
    (statuses, counters.points_tested, seconds)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let count: usize = args.first().and_then(|a| a.parse().ok()).unwrap_or(400);
    let n: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(4);
    println!(
        "{count} edges per problem in R^{n}, resolution {RESOLUTION}, best of {ROUNDS} rounds"
    );
    println!(
        "| problem | valid edges | points | one at a time (ns/point) | accelerated (ns/point) | ratio |"
    );
    println!("|---|---|---|---|---|---|");
    let problems = [
        ("FG", "flanking-gap", 1),
        ("DW", "dividing-walls", 1),
        ("GE", "goal-enclosure", 1),
        ("RR #1", "random-rectangles", 1),
        ("RR #2", "random-rectangles", 2),
        ("RR #3", "random-rectangles", 3),
    ];
    for (label, name, seed) in problems {
        let problem = mit_star_problems::builtin(name, n, seed).expect("a built-in problem");
        let edges = edges(&problem, count);
        let mut best = [f64::INFINITY; 2];
        let mut reference: Option<(Vec<EdgeStatus>, u64)> = None;
        for _ in 0..ROUNDS {
            for (slot, accelerated) in [false, true].into_iter().enumerate() {
                let (statuses, points, seconds) = check_all(&problem, &edges, accelerated);
                best[slot] = best[slot].min(seconds * 1e9 / points.max(1) as f64);
                match &reference {
                    None => reference = Some((statuses, points)),
                    Some((s, p)) => {
                        assert!(
                            *s == statuses && *p == points,
                            "{label}: the accelerated check disagrees"
                        );
                    }
                }
            }
        }
        let (statuses, points) = reference.expect("at least one round");
        let valid = statuses.iter().filter(|s| **s == EdgeStatus::Valid).count();
        println!(
            "| {label} R^{n} | {valid}/{count} | {points} | {:.1} | {:.2} | {:.1}× |",
            best[0],
            best[1],
            best[0] / best[1]
        );
    }
}
