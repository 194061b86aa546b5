//! The Rust side of the Python-overhead benchmark (`python/benchmarks/overhead.py`): builds and
//! runs the same plans the benchmark runs through `mit_star`, straight from Rust, and prints
//! the seconds each plan took (construction and `solve`), one line per seed.
//!
//! ```sh
//! cargo run --release -p mit-star-python --example rust_baseline -- \
//!     dividing-walls 4 mit-star 20000 0..10
//! cargo run --release -p mit-star-python --example rust_baseline -- \
//!     mbm:target/box_panda 1 mit-star 3000 0..10
//! ```
//!
//! Arguments: the problem (`--problem` of `mit-star plan`), the dimension of a family or the
//! instance of a MotionBenchMaker folder, the planner, the iterations per plan, the seeds.

use std::process::ExitCode;
use std::time::Instant;

use mit_star::{IterationLimit, Planner};
use mit_star_benches::commands::{CloudArgs, ProblemArgs};
use mit_star_benches::{ParameterOverrides, PlannerSpec, parse_configuration};

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("rust_baseline: {message}");
            ExitCode::FAILURE
        }
    }
}

/// Parses the arguments and prints one `seed seconds cost` line per seed.
fn run(args: &[String]) -> Result<(), String> {
    let [problem, number, planner, iterations, seeds] = args else {
        return Err(
            "usage: rust_baseline PROBLEM DIM|INSTANCE PLANNER ITERATIONS FIRST..END".into(),
        );
    };
    let number: u64 = number.parse().map_err(|e| format!("{number}: {e}"))?;
    let iterations: u64 = iterations
        .parse()
        .map_err(|e| format!("{iterations}: {e}"))?;
    let (first, end) = seeds
        .split_once("..")
        .and_then(|(a, b)| Some((a.parse::<u64>().ok()?, b.parse::<u64>().ok()?)))
        .ok_or_else(|| format!("seeds `{seeds}`: give FIRST..END"))?;
    let arm = problem.starts_with("mbm:");
    let instance = ProblemArgs {
        problem: Some(problem.clone()),
        problem_file: None,
        robot: None,
        group: None,
        strict_robot: false,
        dim: (!arm).then_some(number as usize),
        instance: arm.then_some(number),
        resolution: None,
        allow_coarse_step: false,
        padding: None,
        clouds: CloudArgs::default(),
    }
    .build(1.0)
    .map_err(|e| e.to_string())?;
    let configuration = parse_configuration(planner).map_err(|e| e.to_string())?;
    let spec = PlannerSpec::new(configuration, None, &ParameterOverrides::default())
        .map_err(|e| e.to_string())?;
    for seed in first..end {
        let started = Instant::now();
        let mut built = instance
            .problem
            .build_planner(configuration, &spec.parameters_for_seed(seed))
            .map_err(|e| e.to_string())?;
        let outcome = built
            .solve(&IterationLimit::new(iterations))
            .map_err(|e| e.to_string())?;
        let seconds = started.elapsed().as_secs_f64();
        println!("{seed} {seconds:.6} {:.9}", outcome.cost());
    }
    Ok(())
}
