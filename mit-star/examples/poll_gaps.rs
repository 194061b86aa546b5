//! `poll_gaps`: where a planner goes longest without polling its termination condition — the
//! diagnostic behind the deadline stress matrix's late runs.
//!
//! ```text
//! cargo run --release -p mit-star --example poll_gaps -- mit-star-sc 16 100 1 0
//! ```
//!
//! Arguments: configuration, dimension (goal enclosure), batch size, budget in seconds, seed.
//! Prints how late `solve` returned and how many polls came after the deadline; for a run more
//! than 1 ms late, the backtraces (planner frames only) of the poll that crossed the deadline
//! and of every later poll that ended a gap of more than 0.3 ms, longest gap first.

use std::time::{Duration, Instant};

use mit_star::{Configuration, Parameters, build_planner};

#[path = "support/gaps.rs"]
mod gaps;
use gaps::Gaps;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: poll_gaps CONFIGURATION DIMENSION BATCH BUDGET SEED";
    let [configuration, dimension, batch, budget, seed] = args.as_slice() else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let parsed = (
        configuration.parse::<Configuration>(),
        dimension.parse::<usize>(),
        batch.parse::<usize>(),
        budget.parse::<f64>(),
        seed.parse::<u64>(),
    );
    let (Ok(configuration), Ok(dimension), Ok(batch), Ok(budget), Ok(seed)) = parsed else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let problem = mit_star_problems::builtin("goal-enclosure", dimension, 0).unwrap();
    let parameters = Parameters {
        batch_size: Some(batch),
        seed,
        ..Parameters::default()
    };
    let started = Instant::now();
    let gaps = Gaps::new(started, Duration::from_secs_f64(budget), true);
    let mut planner = build_planner(configuration, &problem, &parameters).unwrap();
    planner.solve(&gaps).unwrap();
    let late = started
        .elapsed()
        .saturating_sub(Duration::from_secs_f64(budget));
    println!("late by {late:?}");
    let most = if late < Duration::from_millis(1) {
        0
    } else {
        4
    };
    print!("{}", gaps.report(most));
}
