//! `deadline_stress`: does every planner return on time, whatever the dimension, batch size and
//! budget? The stress matrix of the reliability issue.
//!
//! ```text
//! cargo run --release -p mit-star --example deadline_stress
//! cargo run --release -p mit-star --example deadline_stress -- --problem dividing-walls --seeds 3
//! cargo run --release -p mit-star --example deadline_stress -- \
//!     --problem random-rectangles,cluttered-rectangles,repeating-rectangles --resolutions 0.05,0.2
//! ```
//!
//! For every problem × resolution × configuration × dimension (2, 4, 8, 16, 32) × batch size
//! (1, 100, 10⁴, 10⁶) × budget (1 ms, 10 ms, 100 ms, 1 s) it takes the clock, builds the
//! planner (construction counts
//! against the budget, as in the harness), solves until the deadline and measures how late
//! `solve` returned, on the time the thread was scheduled (wall-clock less its run-queue wait,
//! so that another process on the core does not make a run late; wall-clock where Linux's
//! scheduler statistics cannot be read). A run is on time if it returned within
//! `max(1 ms, 1 % of the budget)` of its deadline. Prints the worst overshoot per configuration and budget, every late run with the
//! planner frames of the polls that ended its longest gaps after the deadline, and exits with
//! code 1 if any run was late. With `--trace`, the polls of each run's last 30 % also record
//! where they were made, so a late run's gaps name where they began (slower: a diagnostic),
//! and every run more than 1 ms late is reported, within its allowance or not.
//!
//! `--confirm K` measures a late run again, up to `K` more times (same planner, seed and
//! budget): it counts as late only if every attempt is. A run's work up to its deadline does
//! not depend on the clock, so a stall of the planner's own comes back, while a machine's
//! (another process on the core, a scheduler tick: gaps of about 4 ms) rarely does; both
//! counts are printed.
//!
//! `--problem` takes a comma-separated list of built-in problems (default: goal enclosure);
//! `many-rectangles:COUNT` is a random-rectangles layout of `COUNT` small boxes,
//! `many-goals:COUNT` dividing walls with `COUNT` goals (e.g. `--problem many-goals:5000`).
//! `--resolutions` plans each problem at these collision-check resolutions (fractions of the
//! maximum extent, as `plan --resolution`) with a coarse step allowed (`allow_coarse_step`):
//! a step of 0.05 or 0.2 of the extent is coarser than most obstacles, so edges have few grid
//! points and the exact box certification decides most of them. Without it, each problem's
//! own resolution. Arm problems have a sibling matrix, `robot/examples/arm_deadline_stress.rs`.

use std::time::Instant;

use mit_star::{Configuration, Parameters};

#[path = "support/gaps.rs"]
mod gaps;
use gaps::measure;

/// One measured run.
struct Run {
    problem: String,
    resolution: Option<f64>,
    configuration: Configuration,
    dimension: usize,
    batch: usize,
    budget: f64,
    seed: u64,
    /// How late it returned: the least lateness of its attempts (see `--confirm`).
    late: f64,
    /// How late its first attempt returned.
    first: f64,
    /// Attempts made (more than one if the first was late and `--confirm` allows).
    attempts: u32,
    solved: bool,
    /// Where the polls after the deadline came from (late runs only).
    stalls: String,
}

fn main() {
    let mut problem_names = vec!["goal-enclosure".to_owned()];
    let mut resolutions: Vec<Option<f64>> = vec![None];
    let mut seeds = 1_u64;
    let mut dimensions = vec![2, 4, 8, 16, 32];
    let mut batches = vec![1_usize, 100, 10_000, 1_000_000];
    let mut budgets = vec![0.001, 0.01, 0.1, 1.0];
    let mut configurations = Configuration::ALL.to_vec();
    let mut trace = false;
    let mut confirm = 0_u32;
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        if arg == "--trace" {
            trace = true;
            continue;
        }
        let value = args.next().unwrap_or_default();
        match arg.as_str() {
            "--problem" | "--problems" => problem_names = list(&value),
            "--resolutions" => resolutions = list(&value).into_iter().map(Some).collect(),
            "--seeds" => seeds = value.parse().unwrap_or(1).max(1),
            "--confirm" => confirm = value.parse().unwrap_or(0),
            "--dims" => dimensions = list(&value),
            "--batches" => batches = list(&value),
            "--budgets" => budgets = list(&value),
            "--planners" => {
                configurations = value
                    .split(',')
                    .filter_map(|name| name.parse::<Configuration>().ok())
                    .collect();
            }
            other => {
                eprintln!(
                    "unknown option {other}; options: --problem NAME,NAME --resolutions 0.05,0.2 \
                     --seeds N --confirm K --dims 2,4,8 \
                     --batches 1,100 --budgets 0.01,0.1 --planners mit-star,eit-star --trace"
                );
                std::process::exit(2);
            }
        }
    }
    let mut runs = Vec::new();
    let clock = Instant::now();
    for (problem, &resolution, &dimension) in problem_names
        .iter()
        .flat_map(|p| resolutions.iter().map(move |r| (p, r)))
        .flat_map(|(p, r)| dimensions.iter().map(move |d| (p, r, d)))
    {
        let base = match built(problem, dimension).and_then(|p| match resolution {
            Some(r) => Ok(p.with_resolution(r)?.allowing_coarse_step(true)),
            None => Ok(p),
        }) {
            Ok(p) => p,
            Err(e) => {
                eprintln!("{problem} in {dimension} dimensions: {e}");
                std::process::exit(2);
            }
        };
        for &configuration in &configurations {
            for &batch in &batches {
                for &budget in &budgets {
                    for seed in 0..seeds {
                        let parameters = Parameters {
                            batch_size: Some(batch),
                            seed,
                            ..Parameters::default()
                        };
                        let (solved, mut late, gaps) =
                            measure(configuration, &base, &parameters, budget, trace);
                        // Traced runs report every stall over 1 ms, late or not.
                        let stalls = if late > allowed(budget) || (trace && late > 0.001) {
                            gaps.report(2)
                        } else {
                            String::new()
                        };
                        let first = late;
                        let mut attempts = 1;
                        while late > allowed(budget) && attempts <= confirm {
                            attempts += 1;
                            late = late
                                .min(measure(configuration, &base, &parameters, budget, false).1);
                        }
                        runs.push(Run {
                            problem: problem.clone(),
                            resolution,
                            configuration,
                            dimension,
                            batch,
                            budget,
                            seed,
                            late,
                            first,
                            attempts,
                            solved,
                            stalls,
                        });
                    }
                }
            }
        }
    }
    let resolutions_text = match resolutions.as_slice() {
        [None] => "the problems' own".to_owned(),
        _ => format!(
            "{:?}, coarse steps allowed",
            resolutions.iter().flatten().collect::<Vec<_>>()
        ),
    };
    println!(
        "## deadline stress on {}: {} runs in {:.1} s (dimensions {dimensions:?}, batch sizes {batches:?}, resolutions {resolutions_text})\n",
        problem_names.join(", "),
        runs.len(),
        clock.elapsed().as_secs_f64()
    );
    print!("| configuration |");
    for budget in &budgets {
        print!(" worst overshoot, {budget} s budget (ms) |");
    }
    println!(" late runs | solved |");
    println!("|---|{}---|---|", "---|".repeat(budgets.len()));
    for &configuration in &configurations {
        let mine: Vec<&Run> = runs
            .iter()
            .filter(|r| r.configuration == configuration)
            .collect();
        print!("| {} |", configuration.label());
        for &budget in &budgets {
            let worst = mine
                .iter()
                .filter(|r| r.budget == budget)
                .map(|r| r.late)
                .fold(f64::NEG_INFINITY, f64::max);
            print!(" {:.3} |", 1e3 * worst);
        }
        let late = mine.iter().filter(|r| r.late > allowed(r.budget)).count();
        let first = mine.iter().filter(|r| r.first > allowed(r.budget)).count();
        let solved = mine.iter().filter(|r| r.solved).count();
        println!(" {late} of {} ({first} at first) | {solved} |", mine.len());
    }
    if problem_names.len() > 1 || resolutions.len() > 1 {
        println!(
            "\n| problem | resolution | dimension | runs | late runs | late at first | worst \
             overshoot (ms) | worst at first (ms) |"
        );
        println!("|---|---|---|---|---|---|---|---|");
        for problem in &problem_names {
            for &resolution in &resolutions {
                for &dimension in &dimensions {
                    let mine: Vec<&Run> = runs
                        .iter()
                        .filter(|r| {
                            &r.problem == problem
                                && r.resolution == resolution
                                && r.dimension == dimension
                        })
                        .collect();
                    let worst = |f: fn(&Run) -> f64| {
                        mine.iter().map(|r| f(r)).fold(f64::NEG_INFINITY, f64::max)
                    };
                    let count = |f: fn(&Run) -> f64| {
                        mine.iter().filter(|r| f(r) > allowed(r.budget)).count()
                    };
                    let resolution = resolution.map_or("own".to_owned(), |v| v.to_string());
                    println!(
                        "| {problem} | {resolution} | {dimension} | {} | {} | {} | {:.3} | {:.3} |",
                        mine.len(),
                        count(|r| r.late),
                        count(|r| r.first),
                        1e3 * worst(|r| r.late),
                        1e3 * worst(|r| r.first)
                    );
                }
            }
        }
    }
    let late: Vec<&Run> = runs.iter().filter(|r| r.late > allowed(r.budget)).collect();
    let first = runs.iter().filter(|r| r.first > allowed(r.budget)).count();
    println!(
        "\non time (within max(1 ms, 1 % of the budget)): {} of {} runs; {} of {} at the \
         first attempt (a late run is measured again up to {confirm} times: late only if \
         every attempt is)",
        runs.len() - late.len(),
        runs.len(),
        runs.len() - first,
        runs.len()
    );
    for r in runs.iter().filter(|r| !r.stalls.is_empty()) {
        let resolution = r
            .resolution
            .map_or(String::new(), |v| format!(" resolution {v}"));
        let again = if r.attempts > 1 {
            format!(
                " at first, {:.3} ms at best of {} attempts",
                1e3 * r.late,
                r.attempts
            )
        } else {
            String::new()
        };
        println!(
            "{}: {} on {}{resolution} R^{} batch {} budget {} s seed {}: {:.3} ms late{again}",
            if r.late > allowed(r.budget) {
                "LATE"
            } else if r.first > allowed(r.budget) {
                "late once"
            } else {
                "over 1 ms"
            },
            r.configuration.label(),
            r.problem,
            r.dimension,
            r.batch,
            r.budget,
            r.seed,
            1e3 * r.first
        );
        print!("{}", r.stalls);
    }
    if !late.is_empty() {
        std::process::exit(1);
    }
}

/// The built-in problem `name` in `dimension` dimensions, or, for `many-rectangles:COUNT`, a
/// random-rectangles layout of `COUNT` boxes (sides between half and all of
/// `(0.3 / COUNT)^(1/n)`, so that about as much of the space is covered whatever the count): a
/// world large enough that one exact certification of a long edge is real work; for
/// `many-goals:COUNT`, dividing walls with `COUNT` goals drawn (deterministically) among the
/// valid states of the space's far half instead of its one goal.
fn built(
    name: &str,
    dimension: usize,
) -> Result<mit_star_problems::Problem, mit_star_problems::ProblemError> {
    if let Some(count) = name.strip_prefix("many-goals:") {
        let count: usize = count.parse().unwrap_or(5_000).max(1);
        return many_goals(count, dimension);
    }
    let Some(count) = name.strip_prefix("many-rectangles:") else {
        return mit_star_problems::builtin(name, dimension, 0);
    };
    let count: usize = count.parse().unwrap_or(10_000).max(1);
    let side = (0.3 / count as f64).powf(1.0 / dimension as f64).min(0.5);
    mit_star_problems::RandomRectangles::new(dimension)
        .count(count)
        .min_side(0.5 * side)
        .max_side(side)
        .max_attempts(100 * count)
        .build()
}

/// Dividing walls in `dimension` dimensions with `count` goals: valid states of the half of the
/// space beyond the middle of the first axis, drawn by a fixed linear congruential sequence.
fn many_goals(
    count: usize,
    dimension: usize,
) -> Result<mit_star_problems::Problem, mit_star_problems::ProblemError> {
    use mit_star_validity::StateValidity;
    let walls = mit_star_problems::builtin("dividing-walls", dimension, 0)?;
    let (lower, upper) = (
        walls.world().lower().to_vec(),
        walls.world().upper().to_vec(),
    );
    let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = move || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (seed >> 11) as f64 / (1_u64 << 53) as f64
    };
    let mut goals = Vec::with_capacity(count);
    while goals.len() < count {
        let mut goal: Vec<f64> = (0..dimension)
            .map(|i| lower[i] + next() * (upper[i] - lower[i]))
            .collect();
        goal[0] = 0.5 * (lower[0] + upper[0]) + next() * 0.5 * (upper[0] - lower[0]);
        if walls.world().is_valid(&goal) {
            goals.push(goal);
        }
    }
    let name = format!("many-goals:{count}");
    mit_star_problems::Problem::new(name, walls.world().clone(), walls.start().to_vec(), goals)
}

/// How late a run with `budget` seconds may return: `max(1 ms, 1 % of the budget)`.
fn allowed(budget: f64) -> f64 {
    (0.01 * budget).max(0.001)
}

/// A comma-separated list of numbers (unparsable entries are skipped).
fn list<T: std::str::FromStr>(text: &str) -> Vec<T> {
    text.split(',')
        .filter_map(|v| v.trim().parse().ok())
        .collect()
}
