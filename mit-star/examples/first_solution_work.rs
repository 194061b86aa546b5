//! `first_solution_work`: the work a planner does before its first solution — grid points
//! tested and wall time, per seed — for comparing with another implementation's validity-call
//! counts (`docs/scripts/ompl-peer`).
//!
//! ```text
//! cargo run --release -p mit-star --example first_solution_work -- goal-enclosure 4 bit-star 30
//! ```
//!
//! Arguments: problem family, dimension, configuration, number of seeds (1..=N), and
//! optionally `one-at-a-time` to turn accelerated point checks off (the layout number of
//! `random-rectangles` goes after the family: `random-rectangles:2`). Each run stops at its
//! first solution or after 3 s. Prints the first five runs, then the medians over the solved
//! runs: points tested (and culled), time, and time per point. With `--csv` anywhere among
//! the arguments it prints one line per run instead, in the columns of the OMPL peer driver
//! (`docs/scripts/ompl-peer`), so both sides go through one summary. Switches such as
//! `repair_reverse_search=true` or `cascading_rewirings=true` anywhere among the arguments
//! set those parameters.

use std::time::Instant;

use mit_star::{FirstSolution, Parameters, TerminationExt, TimeLimit, build_planner};

#[path = "support/arguments.rs"]
mod arguments;

fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(f64::NAN)
}

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let csv = args.iter().any(|a| a == "--csv");
    args.retain(|a| a != "--csv");
    let mut switches = Parameters::default();
    arguments::take_switches(&mut args, &mut switches);
    let family = args.first().map_or("goal-enclosure", String::as_str);
    let dimension: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(4);
    let configuration = arguments::configuration(args.get(2).map_or("bit-star", String::as_str));
    let seeds: u64 = args.get(3).and_then(|a| a.parse().ok()).unwrap_or(30);
    let accelerated = args.get(4).is_none_or(|a| a != "one-at-a-time");
    let problem = arguments::problem(family, dimension);
    let (mut points, mut times, mut per_point) = (Vec::new(), Vec::new(), Vec::new());
    let mut culled = Vec::new();
    for seed in 1..=seeds {
        let parameters = Parameters {
            seed,
            accelerated_checks: accelerated && switches.accelerated_checks,
            ..switches.clone()
        };
        let mut planner = build_planner(configuration, &problem, &parameters).expect("a planner");
        let started = Instant::now();
        let outcome = planner
            .solve(&FirstSolution.or(TimeLimit::seconds(3.0)))
            .expect("a query the problem family guarantees");
        let seconds = started.elapsed().as_secs_f64();
        let c = planner.counters();
        if csv {
            // problem,n,planner,seed,exact,callback,t_first_ms,calls_first,t_total_ms,calls_total,cost,setup_ms
            let cost = outcome.cost();
            println!(
                "{},{dimension},{}{},{seed},{},1,{:.4},{},{:.4},{},{cost:.6},0",
                problem.name(),
                configuration.label(),
                if accelerated { "" } else { " one at a time" },
                u8::from(outcome.is_solved()),
                seconds * 1e3,
                c.points_tested,
                seconds * 1e3,
                c.points_tested,
            );
        } else if seed <= 5 {
            println!(
                "seed {seed}: {} in {:.1} ms, {} points, {} full checks, {} batches",
                if outcome.is_solved() {
                    "solved"
                } else {
                    "unsolved"
                },
                seconds * 1e3,
                c.points_tested,
                c.full_checks,
                c.batches
            );
        }
        if outcome.is_solved() {
            points.push(c.points_tested as f64);
            culled.push(c.points_culled as f64);
            times.push(seconds);
            per_point.push(seconds * 1e9 / c.points_tested.max(1) as f64);
        }
    }
    if csv {
        return;
    }
    println!(
        "{} on {family} R^{dimension}{}: {} of {seeds} solved; median {:.0} points ({:.0} culled), {:.2} ms, {:.2} ns per point",
        configuration.label(),
        if accelerated { "" } else { " (one at a time)" },
        points.len(),
        median(&mut points),
        median(&mut culled),
        median(&mut times) * 1e3,
        median(&mut per_point)
    );
}
