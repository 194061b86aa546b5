//! `cloud_profile`: a planner's time among point clouds and nothing else — each problem's cloud
//! prepared once, then solved again and again — for profiles and before/after comparisons of
//! the cloud queries (`cloud_loop` runs `plan`'s whole pipeline, where the brute-force audit and
//! the cloud's sampling and filters take nearly all of the time).
//!
//! ```text
//! cargo build --release -p mit-star-benches --example cloud_profile
//! echo "box_0001 --problem mbm:target/box_panda --instance 1 --scene-as-cloud 10000 \
//!   --crop-reach --min-distance 0.02" \
//!   | target/release/examples/cloud_profile rrt-connect 10 --set range=1.0
//! ```
//!
//! Each line of standard input is a problem, as `cloud_loop` reads them: a name, then `plan`'s
//! problem options (no spaces inside an option's value). Each problem is solved with seeds
//! `0..SEEDS` to its first solution (1 s at most), the named planner and the `--set`
//! overrides, and its line gives the median solve time; the last line gives the pooled median
//! and the total. A problem whose start or goal touches the cloud is skipped, named. Only the
//! solve is timed (the planner's construction is not).

use std::io::BufRead;
use std::time::Instant;

use mit_star::{FirstSolution, TerminationExt as _, TimeLimit, build_planner};
use mit_star_benches::{HarnessError, PlannerSpec};

#[path = "support/cloud_runs.rs"]
mod cloud_runs;

/// The median of `values` (sorted in place; 0 if empty).
fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(0.0)
}

/// The solve times (µs) of the problem `words` give, with seeds `0..seeds`.
///
/// # Errors
/// What `plan` refuses (options, problem, cloud, an end touching the cloud), and a problem
/// that is not an arm's.
fn solves<'a>(
    words: impl Iterator<Item = &'a str>,
    spec: &PlannerSpec,
    seeds: u64,
) -> Result<Vec<f64>, HarnessError> {
    let (instance, _) = cloud_runs::problem_with_cloud("cloud_profile", words)?;
    let arm = instance
        .problem
        .as_arm()
        .ok_or_else(|| HarnessError::Usage("point clouds need an arm problem".into()))?;
    let mut times = Vec::new();
    for seed in 0..seeds {
        let parameters = spec.parameters_for_seed(seed);
        let mut planner =
            build_planner(spec.configuration(), &**arm, &parameters).map_err(|source| {
                HarnessError::Build {
                    planner: spec.name().to_owned(),
                    source,
                }
            })?;
        let started = Instant::now();
        let _ = planner.solve(&FirstSolution.or(TimeLimit::seconds(1.0)));
        times.push(started.elapsed().as_secs_f64() * 1e6);
    }
    Ok(times)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(planner), Some(seeds)) = (args.first(), args.get(1)) else {
        eprintln!("usage: cloud_profile PLANNER SEEDS [--set KEY=VALUE]… < PROBLEMS");
        std::process::exit(2);
    };
    let seeds: u64 = seeds.parse().expect("SEEDS, a count");
    let spec = cloud_runs::planner_spec(planner, &args[2..]);
    let mut all = Vec::new();
    for line in std::io::stdin().lock().lines() {
        let line = line.expect("standard input");
        let mut words = line.split_whitespace();
        let Some(name) = words.next() else { continue };
        match solves(words, &spec, seeds) {
            Ok(mut times) => {
                all.extend_from_slice(&times);
                println!(
                    "{name}: median {:.0} µs over {seeds} seeds",
                    median(&mut times)
                );
            }
            Err(e) => println!("{name}: skipped ({e})"),
        }
    }
    let total: f64 = all.iter().sum();
    println!(
        "pooled median {:.0} µs over {} solves; total {:.0} µs",
        median(&mut all),
        all.len(),
        total
    );
}
