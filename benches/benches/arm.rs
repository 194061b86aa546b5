//! Criterion benchmarks of arm collision checking (issue 7): the Panda in a MotionBenchMaker
//! scene.
//!
//! Run: `cargo bench -p mit-star-benches --bench arm`. Reports, per configuration: forward
//! kinematics plus the full collision check (scene and self) one configuration at a time, and
//! in batches of the checker's lanes (eight, or sixteen with AVX-512; finding the first invalid
//! one, or any); one full edge check of 1 rad, raked (its grid points in bisection order, a
//! batch at a time) and one by one; the certification of the edges of RRT-Connect's first
//! paths (twenty seeds on each scene's first problem, per edge); and a planner's construction.
//! Figures are recorded in
//! `docs/guide/src/reference/arm-planning.md`.

use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use mit_star::{
    Configuration, FirstSolution, Parameters, TerminationExt, TimeLimit, build_planner,
};
use mit_star_problems::PlanningProblem;
use mit_star_robot::ArmProblem;
use mit_star_spaces::{Never, SeededRng, StateSpace};
use mit_star_validity::{
    DenseChecker, EdgeChecker, EdgeProgress, EdgeStatus, MotionProgress, StateValidity,
};
use rand::{RngExt, SeedableRng};

const SCENES: [&str; 3] = ["bookshelf_small_panda", "cage_panda", "table_pick_panda"];
const COUNT: usize = 1024;

/// The same checker seen without batches: what an edge check did before them.
struct OneByOne<'a, V>(&'a V);

impl<V: StateValidity> StateValidity for OneByOne<'_, V> {
    fn is_valid(&self, state: &[f64]) -> bool {
        self.0.is_valid(state)
    }
}

fn problem(scene: &str) -> ArmProblem {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../robot/tests/data/mbm")
        .join(scene);
    ArmProblem::panda_mbm(&folder, 1).expect("sample problem")
}

/// `COUNT` configurations drawn uniformly within the limits: all of them, and the valid ones
/// only (the worst case: nothing ends a check early).
fn configurations(problem: &ArmProblem) -> (Vec<f64>, Vec<f64>) {
    let space = problem.space();
    let mut rng = SeededRng::seed_from_u64(11);
    let mut q = vec![0.0; space.dimension()];
    let (mut any, mut valid) = (Vec::new(), Vec::new());
    while any.len() < COUNT * q.len() || valid.len() < COUNT * q.len() {
        space.sample_uniform(&mut rng, &mut q);
        if any.len() < COUNT * q.len() {
            any.extend_from_slice(&q);
        }
        if valid.len() < COUNT * q.len() && problem.validity().is_valid(&q) {
            valid.extend_from_slice(&q);
        }
    }
    (any, valid)
}

fn configuration_check(c: &mut Criterion) {
    let mut group = c.benchmark_group("arm_check");
    group.throughput(Throughput::Elements(COUNT as u64));
    for scene in SCENES {
        let problem = problem(scene);
        let checker = problem.validity();
        // One call per batch of the checker's lanes (8, or 16 with AVX-512).
        let width = checker.batch_width();
        let (any, valid) = configurations(&problem);
        for (set, states) in [("uniform", &any), ("valid", &valid)] {
            let name = format!("{scene}/{set}");
            group.bench_function(BenchmarkId::new("scalar", &name), |b| {
                b.iter(|| {
                    states
                        .chunks_exact(7)
                        .filter(|q| checker.is_valid(black_box(q)))
                        .count()
                });
            });
            // Every configuration tested: batches resumed after each invalid one.
            group.bench_function(BenchmarkId::new("batched", &name), |b| {
                b.iter(|| {
                    let mut rest = &states[..];
                    let mut invalid = 0;
                    while !rest.is_empty() {
                        let take = rest.len().min(width * 7);
                        match checker.first_invalid(black_box(&rest[..take]), 7) {
                            Some(i) => {
                                invalid += 1;
                                rest = &rest[(i + 1) * 7..];
                            }
                            None => rest = &rest[take..],
                        }
                    }
                    invalid
                });
            });
            // Batches that only ask whether any is invalid (an edge check's question, and
            // VAMP's): a batch ends at its first contact in any lane, and the next batch follows.
            group.bench_function(BenchmarkId::new("batched_any", &name), |b| {
                b.iter(|| {
                    states
                        .chunks(width * 7)
                        .filter(|batch| checker.any_invalid(black_box(batch), 7).is_some())
                        .count()
                });
            });
        }
    }
    group.finish();
}

/// A valid edge of joint-space length `length` from a valid configuration (seeded search).
fn free_edge(problem: &ArmProblem, length: f64) -> (Vec<f64>, Vec<f64>) {
    let space = problem.space();
    let mut rng = SeededRng::seed_from_u64(5);
    let mut checker = DenseChecker::new(problem.check_step().unwrap()).unwrap();
    let n = space.dimension();
    let (mut a, mut b) = (vec![0.0; n], vec![0.0; n]);
    loop {
        space.sample_uniform(&mut rng, &mut a);
        let direction: Vec<f64> = (0..n).map(|_| 2.0 * rng.random::<f64>() - 1.0).collect();
        let norm = direction.iter().map(|d| d * d).sum::<f64>().sqrt();
        for i in 0..n {
            b[i] = a[i] + length * direction[i] / norm;
        }
        let v = problem.validity();
        if !(space.contains(&b) && v.is_valid(&a) && v.is_valid(&b)) {
            continue;
        }
        let mut progress = EdgeProgress::default();
        if checker.check_full(space, v, &a, &b, &mut progress, &Never) == EdgeStatus::Valid {
            return (a, b);
        }
    }
}

fn edge_check(c: &mut Criterion) {
    let mut group = c.benchmark_group("arm_edge");
    let problem = problem("bookshelf_small_panda");
    let space = problem.space();
    let checker = problem.validity();
    // A typical RGG edge for the Panda: about 1 rad (15 grid points at our 16 checks per unit;
    // VAMP checks 32 per unit).
    let (a, b) = free_edge(&problem, 1.0);
    let mut edges = DenseChecker::new(problem.check_step().unwrap()).unwrap();
    group.bench_function("one_by_one/1rad", |bench| {
        bench.iter(|| {
            let mut progress = EdgeProgress::default();
            edges.check_full(space, &OneByOne(checker), &a, &b, &mut progress, &Never)
        });
    });
    let mut edges = DenseChecker::new(problem.check_step().unwrap()).unwrap();
    group.bench_function("batched/1rad", |bench| {
        bench.iter(|| {
            let mut progress = EdgeProgress::default();
            edges.check_full(space, checker, &a, &b, &mut progress, &Never)
        });
    });
    group.finish();
}

/// The edges of RRT-Connect's first paths on `problem` (range 1, certification off), one path
/// per seed: the motions a solve certifies.
fn path_edges(problem: &ArmProblem, seeds: u64) -> Vec<(Vec<f64>, Vec<f64>)> {
    let uncertified = problem.clone().allowing_uncertified_motion(true);
    let mut edges = Vec::new();
    for seed in 0..seeds {
        let parameters = Parameters {
            seed,
            certification: Some(1),
            range: Some(1.0),
            ..Parameters::default()
        };
        let mut planner =
            build_planner(Configuration::RrtConnect, &uncertified, &parameters).expect("builds");
        let stop = FirstSolution.or(TimeLimit::seconds(1.0));
        let outcome = planner.solve(&stop).expect("plans");
        let path: Vec<&[f64]> = outcome
            .solution()
            .map(|solution| solution.path.iter().collect())
            .unwrap_or_default();
        edges.extend(path.windows(2).map(|w| (w[0].to_vec(), w[1].to_vec())));
    }
    edges
}

fn certification(c: &mut Criterion) {
    let mut group = c.benchmark_group("arm_certify");
    for scene in SCENES {
        let problem = problem(scene);
        let edges = path_edges(&problem, 20);
        let name = scene.trim_end_matches("_panda");
        group.throughput(Throughput::Elements(edges.len() as u64));
        group.bench_function(BenchmarkId::new("rrt_connect_paths", name), |bench| {
            bench.iter(|| {
                let mut valid = 0;
                for (a, b) in &edges {
                    let mut progress = MotionProgress::default();
                    let status = problem
                        .validity()
                        .certify_motion(problem.space(), a, b, &mut progress, &Never)
                        .expect("arms certify motions");
                    valid += usize::from(status == EdgeStatus::Valid);
                }
                black_box(valid)
            });
        });
    }
    group.finish();
}

fn construction(c: &mut Criterion) {
    let mut group = c.benchmark_group("arm_construction");
    let problem = problem("bookshelf_small_panda");
    for configuration in [Configuration::RrtConnect, Configuration::MitStar] {
        let parameters = Parameters {
            range: (configuration == Configuration::RrtConnect).then_some(1.0),
            ..Parameters::default()
        };
        group.bench_function(configuration.name(), |bench| {
            bench.iter(|| build_planner(configuration, &problem, &parameters).expect("builds"));
        });
    }
    group.finish();
}

criterion_group! {
    name = arm;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .sample_size(30);
    targets = configuration_check, edge_check, certification, construction
}
criterion_main!(arm);
