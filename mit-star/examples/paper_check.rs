//! `paper_check`: MIT* against EIT* on the paper's benchmark problems, with the paper's budgets,
//! one planner run at a time (as the paper ran them).
//!
//! ```text
//! cargo run --release -p mit-star --example paper_check -- --runs 100
//! cargo run --release -p mit-star --example paper_check -- --runs 20 --table
//! cargo run --release -p mit-star --example paper_check -- --problem dividing-walls:8:0.6 --planners mit-star,eit-star,mit-star-sc
//! ```
//!
//! Prints per problem and planner: success rate, median time to the first solution (planner
//! construction included), median initial and final cost, validity checks per run, the share of
//! run time spent in state-validity calls (measured in the run: every 64th call is timed, minus
//! the clock's own overhead), the share spent in edge checking as a whole (estimated: grid
//! points × the cost per point of a full check measured on the same problem, plus the sampler's
//! checks), and the worst deadline overshoot. Medians are PDT's (index ⌈(N−1)/2⌉, unsolved
//! runs count as ∞). Also prints a nearest-neighbour micro-measurement.

use std::cell::Cell;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

use mit_star::{
    Configuration, Counters, KdTree, NearestNeighbors, Neighbours, Parameters, TimeLimit,
    build_planner_with, k_nearest,
};
use mit_star_problems::Problem;
use mit_star_spaces::rand::{RngExt, SeedableRng};
use mit_star_spaces::{SeededRng, StateSpace};
use mit_star_validity::{DenseChecker, EdgeChecker, EdgeProgress, StateValidity, World};

/// One validity call in this many is timed.
const SAMPLE: u64 = 64;

/// The problem's world with every `SAMPLE`-th validity call timed: the in-run measurement of
/// the time spent in state-validity checks (only in this binary; planners never pay for it).
struct Timed {
    world: World,
    calls: Cell<u64>,
    /// Nanoseconds of the timed calls, times `SAMPLE`, minus the clock's own overhead.
    nanos: Arc<AtomicU64>,
    overhead: u64,
}

impl StateValidity for Timed {
    #[inline]
    fn is_valid(&self, state: &[f64]) -> bool {
        let calls = self.calls.get();
        self.calls.set(calls + 1);
        if !calls.is_multiple_of(SAMPLE) {
            return self.world.is_valid(state);
        }
        let started = Instant::now();
        let valid = self.world.is_valid(state);
        let ns = (started.elapsed().as_nanos() as u64).saturating_sub(self.overhead);
        self.nanos.fetch_add(ns * SAMPLE, Ordering::Relaxed);
        valid
    }
}

/// Nanoseconds an empty `Instant::now()` … `elapsed()` interval reads (median of many).
fn clock_overhead() -> u64 {
    let mut samples: Vec<u64> = (0..20_001)
        .map(|_| {
            let t = Instant::now();
            t.elapsed().as_nanos() as u64
        })
        .collect();
    samples.sort_unstable();
    samples[samples.len() / 2]
}

/// One experiment: a problem and its time budget.
struct Experiment {
    family: String,
    n: usize,
    budget: f64,
}

/// What one run produced.
struct Run {
    t_init: f64,
    c_init: f64,
    c_final: f64,
    wall: f64,
    overshoot: f64,
    counters: Counters,
    /// Seconds spent in state-validity calls (sampled timing).
    validity: f64,
}

struct Options {
    runs: usize,
    seed: u64,
    planners: Vec<Configuration>,
    experiments: Vec<Experiment>,
    nn: bool,
    planning: bool,
}

fn usage() -> ! {
    eprintln!(
        "usage: paper_check [--runs N] [--seed S] [--planners a,b,…] [--problem FAMILY:DIM:BUDGET]… \
         [--table] [--no-nn] [--nn-only]\n  planners: mit-star, eit-star, mit-star-as, mit-star-eis, mit-star-sc"
    );
    std::process::exit(2)
}

fn parse() -> Options {
    let mut options = Options {
        runs: 100,
        seed: 0,
        planners: vec![Configuration::MitStar, Configuration::EitStar],
        experiments: Vec::new(),
        nn: true,
        planning: true,
    };
    let mut args = std::env::args().skip(1);
    let mut table = false;
    while let Some(arg) = args.next() {
        let mut value = || args.next().unwrap_or_else(|| usage());
        match arg.as_str() {
            "--runs" => options.runs = value().parse().unwrap_or_else(|_| usage()),
            "--seed" => options.seed = value().parse().unwrap_or_else(|_| usage()),
            "--planners" => {
                options.planners = value()
                    .split(',')
                    .map(|s| {
                        s.parse().unwrap_or_else(|e| {
                            eprintln!("{e}");
                            usage()
                        })
                    })
                    .collect();
            }
            "--problem" => {
                let v = value();
                let parts: Vec<&str> = v.split(':').collect();
                if parts.len() != 3 {
                    usage();
                }
                options.experiments.push(Experiment {
                    family: parts[0].to_string(),
                    n: parts[1].parse().unwrap_or_else(|_| usage()),
                    budget: parts[2].parse().unwrap_or_else(|_| usage()),
                });
            }
            "--table" => table = true,
            "--no-nn" => options.nn = false,
            "--nn-only" => options.planning = false,
            _ => usage(),
        }
    }
    let paper = |family: &str, n, budget| Experiment {
        family: family.to_string(),
        n,
        budget,
    };
    if table {
        // The paper's Table I problems and budgets (random rectangles: the cluttered variant
        // `paper-table` uses, instance 0; PDT's own layout leaves the straight line free).
        options.experiments.extend([
            paper("flanking-gap", 4, 0.08),
            paper("flanking-gap", 8, 0.12),
            paper("flanking-gap", 16, 0.20),
            paper("cluttered-rectangles", 4, 0.8),
            paper("cluttered-rectangles", 8, 2.0),
            paper("cluttered-rectangles", 16, 4.0),
            paper("dividing-walls", 4, 0.3),
            paper("dividing-walls", 8, 0.6),
            paper("dividing-walls", 16, 1.5),
            paper("goal-enclosure", 2, 0.05),
            paper("goal-enclosure", 4, 0.1),
            paper("goal-enclosure", 8, 2.0),
        ]);
    }
    if options.experiments.is_empty() {
        options.experiments = vec![
            paper("dividing-walls", 4, 0.3),
            paper("goal-enclosure", 8, 2.0),
        ];
    }
    options
}

/// PDT's median: the order statistic at index ⌈(N − 1)/2⌉ (∞ for unsolved runs).
fn median(mut values: Vec<f64>) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    values.sort_by(f64::total_cmp);
    values[(values.len() - 1).div_ceil(2)]
}

/// Nanoseconds per state check and per edge grid point on this problem: states along random
/// edges between random states, as edge checks see them.
fn check_costs(problem: &Problem) -> (f64, f64) {
    let space = problem.space();
    let world = problem.world();
    let mut rng = SeededRng::seed_from_u64(99);
    let n = space.dimension();
    let (mut a, mut b, mut x) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut states = Vec::new();
    for _ in 0..2000 {
        space.sample_uniform(&mut rng, &mut a);
        space.sample_uniform(&mut rng, &mut b);
        for _ in 0..50 {
            let t: f64 = rng.random();
            space.interpolate(&a, &b, t, &mut x);
            states.extend_from_slice(&x);
        }
    }
    let started = Instant::now();
    let mut valid = 0usize;
    for _ in 0..5 {
        for s in states.chunks_exact(n) {
            valid += usize::from(world.is_valid(std::hint::black_box(s)));
        }
    }
    let per_state = started.elapsed().as_secs_f64() * 1e9 / (5 * states.len() / n) as f64;
    std::hint::black_box(valid);
    // Full checks of edges between valid states, through the same edge checker the planners use.
    let mut checker = DenseChecker::from_resolution(space, problem.resolution()).expect("step");
    let mut points = 0u64;
    let started = Instant::now();
    while points < 2_000_000 {
        loop {
            space.sample_uniform(&mut rng, &mut a);
            space.sample_uniform(&mut rng, &mut b);
            if world.is_valid(&a) && world.is_valid(&b) {
                break;
            }
        }
        let mut progress = EdgeProgress::default();
        checker.check_full(space, world, &a, &b, &mut progress, &mit_star_spaces::Never);
        points =
            EdgeChecker::<mit_star_spaces::RealVectorSpace, mit_star_validity::World>::counters(
                &checker,
            )
            .points_tested;
    }
    let per_point = started.elapsed().as_secs_f64() * 1e9 / points as f64;
    (per_state, per_point)
}

fn run_once(
    configuration: Configuration,
    problem: &Problem,
    seed: u64,
    budget: f64,
    overhead: u64,
) -> Run {
    let parameters = Parameters {
        seed,
        ..Parameters::default()
    };
    let nanos = Arc::new(AtomicU64::new(0));
    let timed = Timed {
        world: problem.world().clone(),
        calls: Cell::new(0),
        nanos: Arc::clone(&nanos),
        overhead,
    };
    let started = Instant::now();
    let deadline = started + Duration::from_secs_f64(budget);
    let mut planner =
        build_planner_with(configuration, problem, &parameters, timed).expect("planner");
    let built = started.elapsed().as_secs_f64();
    let outcome = planner.solve(&TimeLimit::until(deadline)).expect("solve");
    let finished = Instant::now();
    let overshoot = finished.saturating_duration_since(deadline).as_secs_f64();
    let wall = (finished - started).as_secs_f64();
    let initial = planner.trace().initial();
    Run {
        t_init: initial.map_or(f64::INFINITY, |p| built + p.time),
        c_init: initial.map_or(f64::INFINITY, |p| p.cost),
        c_final: outcome.cost(),
        wall,
        overshoot,
        counters: planner.counters(),
        validity: nanos.load(Ordering::Relaxed) as f64 * 1e-9,
    }
}

fn nearest_neighbour_check() {
    println!("\n## Nearest neighbours (exact k-NN, k = k_nearest(q, n), 2000 queries)");
    println!(
        "| n | points | k | linear scan µs/query | kd-tree µs/query | speedup | batched forest µs/query |"
    );
    println!("|---|---|---|---|---|---|---|");
    for (n, count) in [(4, 5000), (8, 5000), (16, 5000), (32, 5000)] {
        let mut rng = SeededRng::seed_from_u64(n as u64);
        let points: Vec<f64> = (0..n * count)
            .map(|_| rng.random_range(-0.5..0.5))
            .collect();
        let queries: Vec<f64> = (0..n * 2000).map(|_| rng.random_range(-0.5..0.5)).collect();
        let k = k_nearest(count, n, 1.001);
        let tree = KdTree::build(
            n,
            points
                .chunks_exact(n)
                .enumerate()
                .map(|(i, p)| (i as u32, p)),
        );
        let mut forest = NearestNeighbors::new(n);
        for (b, chunk) in points.chunks(100 * n).enumerate() {
            forest.insert(
                chunk
                    .chunks_exact(n)
                    .enumerate()
                    .map(|(i, p)| ((b * 100 + i) as u32, p)),
            );
        }
        let mut found = Neighbours::new();
        let mut heap: Vec<(f64, u32)> = Vec::with_capacity(count);
        let started = Instant::now();
        let mut checksum = 0u64;
        for q in queries.chunks_exact(n) {
            heap.clear();
            for (i, p) in points.chunks_exact(n).enumerate() {
                let d: f64 = p.iter().zip(q).map(|(a, b)| (a - b) * (a - b)).sum();
                heap.push((d, i as u32));
            }
            heap.select_nth_unstable_by(k - 1, |a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            checksum += u64::from(heap[k - 1].1);
        }
        let linear = started.elapsed().as_secs_f64() * 1e6 / 2000.0;
        let started = Instant::now();
        for q in queries.chunks_exact(n) {
            tree.nearest(q, k, &mut found);
            checksum += u64::from(found.iter().last().map_or(0, |&(_, id)| id));
        }
        let kd = started.elapsed().as_secs_f64() * 1e6 / 2000.0;
        let started = Instant::now();
        for q in queries.chunks_exact(n) {
            forest.nearest(q, k, &mut found);
            checksum += u64::from(found.iter().last().map_or(0, |&(_, id)| id));
        }
        let batched = started.elapsed().as_secs_f64() * 1e6 / 2000.0;
        std::hint::black_box(checksum);
        println!(
            "| {n} | {count} | {k} | {linear:.1} | {kd:.2} | {:.1}× | {batched:.2} |",
            linear / kd
        );
    }
}

fn main() {
    let options = parse();
    println!(
        "# paper_check: {} runs per planner and problem, sequential (one planner at a time)",
        options.runs
    );
    if options.planning {
        println!(
            "\nParameters (besides the seed, = base seed + run index {}):",
            options.seed
        );
        for (k, v) in Parameters::default().settings() {
            if k != "seed" {
                print!("{k}={v} ");
            }
        }
        println!();
    }
    for experiment in options.experiments.iter().filter(|_| options.planning) {
        let problem = mit_star_problems::builtin(&experiment.family, experiment.n, 0)
            .unwrap_or_else(|e| {
                eprintln!("{e}");
                std::process::exit(2)
            });
        let (per_state, per_point) = check_costs(&problem);
        let overhead = clock_overhead();
        println!(
            "\n## {} R^{} — budget {} s; measured {per_state:.1} ns per state check, {per_point:.1} ns per edge grid point",
            experiment.family, experiment.n, experiment.budget
        );
        let mut results: Vec<Vec<Run>> = options.planners.iter().map(|_| Vec::new()).collect();
        for i in 0..options.runs {
            // Rotate the planner order per run to spread machine drift (as PDT shuffles).
            for j in 0..options.planners.len() {
                let p = (i + j) % options.planners.len();
                let run = run_once(
                    options.planners[p],
                    &problem,
                    options.seed + i as u64,
                    experiment.budget,
                    overhead,
                );
                results[p].push(run);
            }
        }
        println!(
            "| planner | success | t_init median (s) | c_init median | c_final median | checks/run | points/run | restarts/run | batches/run | validity share | edge-check share (est.) | max overshoot (ms) |"
        );
        println!("|---|---|---|---|---|---|---|---|---|---|---|---|");
        let mut t_medians = Vec::new();
        for (configuration, runs) in options.planners.iter().zip(&results) {
            let count = runs.len() as f64;
            let solved = runs.iter().filter(|r| r.t_init.is_finite()).count();
            let t = median(runs.iter().map(|r| r.t_init).collect());
            t_medians.push(t);
            let mean = |f: &dyn Fn(&Run) -> f64| runs.iter().map(f).sum::<f64>() / count;
            let validity_share = mean(&|r| r.validity / r.wall);
            let share = mean(&|r| {
                let c = &r.counters;
                let sampler_checks = c.validity_checks.saturating_sub(c.points_tested) as f64;
                (c.points_tested as f64 * per_point + sampler_checks * per_state) * 1e-9 / r.wall
            });
            println!(
                "| {} | {:.0} % | {:.4} | {:.4} | {:.4} | {:.0} | {:.0} | {:.1} | {:.1} | {:.0} % | {:.0} % | {:.2} |",
                configuration.label(),
                100.0 * solved as f64 / count,
                t,
                median(runs.iter().map(|r| r.c_init).collect()),
                median(runs.iter().map(|r| r.c_final).collect()),
                mean(&|r| r.counters.validity_checks as f64),
                mean(&|r| r.counters.points_tested as f64),
                mean(&|r| r.counters.reverse_restarts as f64),
                mean(&|r| r.counters.batches as f64),
                100.0 * validity_share,
                100.0 * share,
                1e3 * runs.iter().map(|r| r.overshoot).fold(0.0, f64::max),
            );
        }
        if let (Some(m), Some(e)) = (
            options
                .planners
                .iter()
                .position(|&c| c == Configuration::MitStar),
            options
                .planners
                .iter()
                .position(|&c| c == Configuration::EitStar),
        ) {
            println!(
                "t_init gain of MIT* over EIT* (1 − t_MIT/t_EIT): {:.1} %",
                100.0 * (1.0 - t_medians[m] / t_medians[e])
            );
        }
    }
    if options.nn {
        nearest_neighbour_check();
    }
}
