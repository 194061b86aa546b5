//! `anytime_rate`: the planner's own speed in the anytime phase, as a fixed amount of work —
//! seeded runs stopped after a set number of iterations — timed, so two builds that make the
//! same decisions (`iteration_digest`) can be compared on identical work.
//!
//! ```text
//! cargo run --release -p mit-star --example anytime_rate -- dividing-walls 8 mit-star 200000 5
//! ```
//!
//! Arguments: problem family (a seeded family's layout after a colon, `random-rectangles:2`),
//! dimension, configuration, iterations per run, number of seeds
//! (1..=N), and optionally the number of rounds (default 3; each round runs every seed once,
//! and each seed keeps its fastest round, which filters out a shared machine's hiccups). Prints
//! per seed the batches, the reverse and forward iterations, the final cost and the best time;
//! then the totals as iterations and batches per second of the summed best times. Switches
//! such as `repair_reverse_search=true` anywhere among the arguments set those parameters.

use std::time::Instant;

use mit_star::{IterationLimit, Parameters, build_planner};

#[path = "support/arguments.rs"]
mod arguments;

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut switches = Parameters::default();
    arguments::take_switches(&mut args, &mut switches);
    let family = args.first().map_or("dividing-walls", String::as_str);
    let dimension: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(8);
    let configuration = arguments::configuration(args.get(2).map_or("mit-star", String::as_str));
    let iterations: u64 = args.get(3).and_then(|a| a.parse().ok()).unwrap_or(200_000);
    let seeds: u64 = args.get(4).and_then(|a| a.parse().ok()).unwrap_or(5);
    let rounds: usize = args.get(5).and_then(|a| a.parse().ok()).unwrap_or(3);
    let problem = arguments::problem(family, dimension);
    let mut best = vec![f64::INFINITY; seeds as usize];
    let mut work = vec![(0u64, 0u64, 0u64, 0u64, f64::NAN); seeds as usize];
    for _ in 0..rounds {
        for seed in 1..=seeds {
            let parameters = Parameters {
                seed,
                ..switches.clone()
            };
            let mut planner =
                build_planner(configuration, &problem, &parameters).expect("a planner");
            let started = Instant::now();
            let outcome = planner
                .solve(&IterationLimit::new(iterations))
                .expect("a query the problem family guarantees");
            let seconds = started.elapsed().as_secs_f64();
            let c = planner.counters();
            let i = (seed - 1) as usize;
            best[i] = best[i].min(seconds);
            work[i] = (
                c.iterations,
                c.batches,
                c.reverse_iterations,
                c.forward_iterations,
                outcome.cost(),
            );
        }
    }
    for (i, (&(iterations, batches, reverse, forward, cost), seconds)) in
        work.iter().zip(&best).enumerate()
    {
        println!(
            "seed {}: {iterations} iterations, {batches} batches, {reverse} reverse, {forward} forward, cost {cost:.6}, {:.1} ms",
            i + 1,
            seconds * 1e3
        );
    }
    let seconds: f64 = best.iter().sum();
    let iterations: u64 = work.iter().map(|w| w.0).sum();
    let batches: u64 = work.iter().map(|w| w.1).sum();
    println!(
        "{} on {family} R^{dimension}: {:.0} iterations/s, {:.1} batches/s ({iterations} iterations, {batches} batches in {:.3} s, best of {rounds} rounds)",
        configuration.label(),
        iterations as f64 / seconds,
        batches as f64 / seconds,
        seconds
    );
}
