//! Criterion benchmarks of the hot primitives, per problem and dimension.
//!
//! Run: `cargo bench -p mit-star-benches --bench primitives`. Figures are recorded in
//! `docs/guide/src/reference/hot-primitives.md`; compare ratios measured in one run, not absolute numbers across machines.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use mit_star_problems::Problem;
use mit_star_samplers::{AdaptiveSampler, CostBound, InformedSampler, Sampler};
use mit_star_spaces::{Never, SeededRng, StateSpace, States};
use mit_star_validity::{DenseChecker, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity};
use rand::{RngExt, SeedableRng};

const DIMENSIONS: [usize; 4] = [2, 4, 8, 16];
const PROBLEMS: [&str; 4] = [
    "flanking-gap",
    "dividing-walls",
    "goal-enclosure",
    "random-rectangles",
];
/// The paper's simulation resolution (fraction of the maximum extent).
const RESOLUTION: f64 = 5e-6;

fn problem(name: &str, n: usize) -> Problem {
    mit_star_problems::builtin(name, n, 1).expect("built-in problem")
}

/// 1024 states drawn uniformly in the problem's space (valid or not), for validity checks.
fn uniform_states(problem: &Problem, seed: u64) -> States {
    let space = problem.space();
    let mut rng = SeededRng::seed_from_u64(seed);
    let mut states = States::with_capacity(space.dimension(), 1024);
    for _ in 0..1024 {
        space.sample_uniform(&mut rng, states.push_zeroed());
    }
    states
}

/// A valid edge of length 0.1 in the problem's free space (found by seeded search).
fn free_edge(problem: &Problem, checker: &mut DenseChecker) -> (Vec<f64>, Vec<f64>) {
    let (space, world) = (problem.space(), problem.world());
    let n = space.dimension();
    let mut rng = SeededRng::seed_from_u64(7);
    let (mut a, mut dir, mut b) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    loop {
        space.sample_uniform(&mut rng, &mut a);
        space.sample_uniform(&mut rng, &mut dir);
        let norm = mit_star_spaces::euclidean_distance(&dir, &vec![0.0; n]);
        for i in 0..n {
            b[i] = a[i] + 0.1 * dir[i] / norm;
        }
        if !(world.is_valid(&a) && world.is_valid(&b)) {
            continue;
        }
        let mut progress = EdgeProgress::default();
        if checker.check_full(space, world, &a, &b, &mut progress, &Never) == EdgeStatus::Valid {
            return (a, b);
        }
    }
}

fn distance(c: &mut Criterion) {
    let mut group = c.benchmark_group("distance");
    for n in DIMENSIONS {
        let p = problem("dividing-walls", n);
        let states = uniform_states(&p, 3);
        let space = p.space();
        group.bench_function(BenchmarkId::from_parameter(n), |bench| {
            let mut i = 0;
            bench.iter(|| {
                i = (i + 1) & 1023;
                black_box(space.distance(&states[i], &states[(i + 1) & 1023]))
            });
        });
    }
    group.finish();
}

fn state_validity(c: &mut Criterion) {
    let mut group = c.benchmark_group("validity_check");
    for name in PROBLEMS {
        for n in DIMENSIONS {
            let p = problem(name, n);
            let states = uniform_states(&p, 5);
            let world = p.world();
            group.bench_function(BenchmarkId::new(name, n), |bench| {
                let mut i = 0;
                bench.iter(|| {
                    i = (i + 1) & 1023;
                    black_box(world.is_valid(&states[i]))
                });
            });
        }
    }
    group.finish();
}

fn full_edge_check(c: &mut Criterion) {
    let mut group = c.benchmark_group("edge_check_0.1_at_5e-6");
    for name in PROBLEMS {
        for n in DIMENSIONS {
            let p = problem(name, n);
            let mut checker = DenseChecker::from_resolution(p.space(), RESOLUTION).unwrap();
            let (a, b) = free_edge(&p, &mut checker);
            let (space, world) = (p.space(), p.world());
            // One state at a time (OMPL's way), then accelerated (broad phase, SIMD lanes).
            for (mode, accelerated) in [("one-at-a-time", false), ("accelerated", true)] {
                let mut checker = checker.clone().with_acceleration(accelerated);
                let id = BenchmarkId::new(format!("{name}/{mode}"), n);
                group.bench_function(id, |bench| {
                    bench.iter(|| {
                        let mut progress = EdgeProgress::default();
                        let status =
                            checker.check_full(space, world, &a, &b, &mut progress, &Never);
                        assert_eq!(status, EdgeStatus::Valid);
                        black_box(progress)
                    });
                });
            }
        }
    }
    group.finish();
}

fn informed_sample(c: &mut Criterion) {
    let mut group = c.benchmark_group("informed_sample");
    for n in DIMENSIONS {
        let p = problem("dividing-walls", n);
        let (space, world) = (p.space(), p.world());
        // The informed set of a solution 20 % above the straight line.
        let bound = CostBound::Solution(1.2 * p.straight_line_cost());
        let mut sampler = InformedSampler::new(space, p.start(), p.goals(), 11).unwrap();
        let mut out = vec![0.0; n];
        group.bench_function(BenchmarkId::from_parameter(n), |bench| {
            bench.iter(|| {
                sampler
                    .sample(space, world, bound, &Never, &mut out)
                    .unwrap();
                black_box(out[0])
            });
        });
    }
    group.finish();
}

fn adaptive_sample(c: &mut Criterion) {
    let mut group = c.benchmark_group("adaptive_sample");
    for n in DIMENSIONS {
        let p = problem("dividing-walls", n);
        let (space, world) = (p.space(), p.world());
        let mut sampler = AdaptiveSampler::new(space, p.start(), p.goals(), 13).unwrap();
        let mut out = vec![0.0; n];
        for (case, bound) in [
            ("uniform", CostBound::Unbounded),
            (
                "estimated",
                CostBound::Estimated(1.5 * p.straight_line_cost()),
            ),
        ] {
            group.bench_function(BenchmarkId::new(case, n), |bench| {
                bench.iter(|| {
                    sampler
                        .sample(space, world, bound, &Never, &mut out)
                        .unwrap();
                    black_box(out[0])
                });
            });
        }
    }
    group.finish();
}

/// A k-nearest query (k = 34, the EIT* family's k for about 60 000 states in 8 dimensions) over
/// 60 000 states drawn uniformly in `[-π, π]^n` and inserted 100 at a time, as a planner's
/// batches arrive (so the structure holds several trees and a buffer, as in a run).
fn nearest_neighbours(c: &mut Criterion) {
    let mut group = c.benchmark_group("nearest_k34_of_60000");
    for n in [7, 8] {
        let mut rng = SeededRng::seed_from_u64(11);
        let mut nn = mit_star::NearestNeighbors::new(n);
        let mut point = vec![0.0; n];
        let mut batch: Vec<f64> = Vec::with_capacity(100 * n);
        let mut found = mit_star::Neighbours::new();
        for b in 0..600_u32 {
            batch.clear();
            for _ in 0..100 {
                for x in &mut point {
                    *x = rng.random_range(-std::f64::consts::PI..std::f64::consts::PI);
                }
                batch.extend_from_slice(&point);
            }
            nn.insert(
                batch
                    .chunks_exact(n)
                    .enumerate()
                    .map(|(i, p)| (b * 100 + i as u32, p)),
            );
            // A query per batch, as expansions interleave with batches in a run.
            nn.nearest(&batch[..n], 34, &mut found);
        }
        let queries: Vec<f64> = (0..256 * n)
            .map(|_| rng.random_range(-std::f64::consts::PI..std::f64::consts::PI))
            .collect();
        let mut at = 0;
        group.bench_function(BenchmarkId::from_parameter(n), |bench| {
            bench.iter(|| {
                at = (at + n) % queries.len();
                nn.nearest(black_box(&queries[at..at + n]), 34, &mut found);
                black_box(found.len())
            });
        });
    }
    group.finish();
}

criterion_group! {
    name = primitives;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .sample_size(30);
    targets = distance, state_validity, full_edge_check, informed_sample, adaptive_sample, nearest_neighbours
}
criterion_main!(primitives);
