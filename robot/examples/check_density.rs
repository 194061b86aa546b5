//! `check_density`: what certification and the check grid's density cost arm planning.
//!
//! ```text
//! mkdir -p target && tar xjf robot/data/panda/mbm_problems.tar.bz2 -C target/
//! cargo run --release -p mit-star-robot --example check_density -- target 40
//! ```
//!
//! Plans RRT-Connect (range 1, to its first solution) and MIT* (to its first solution) on the
//! first `N` problems of each of the five MotionBenchMaker scenes under `FOLDER`, three seeds
//! each, at 32 and 16 checks per unit of joint-space distance, with certification on (the
//! default) and off. Prints per planner and setting the total planning time, the median run
//! and the edges certified: the figures of the arm-planning reference page's "The check
//! grid's density".

use std::time::Instant;

use mit_star::{
    Configuration, FirstSolution, Parameters, TerminationExt, TimeLimit, build_planner,
};
use mit_star_problems::PlanningProblem;
use mit_star_spaces::StateSpace;

#[path = "support/mbm_scenes.rs"]
mod mbm_scenes;
use mbm_scenes::SCENES;

fn main() {
    let mut args = std::env::args().skip(1);
    let folder = args.next().unwrap_or_else(|| "target".into());
    let count: usize = args
        .next()
        .map_or(40, |a| a.parse().expect("a problem count"));
    let problems: Vec<_> = SCENES
        .iter()
        .flat_map(|scene| mbm_scenes::problems(&folder, scene, count))
        .map(|(_, problem)| problem.allowing_uncertified_motion(true))
        .collect();
    println!("{} problems × 3 seeds", problems.len());
    println!(
        "| planner | checks per unit | certification | total (s) | median run (ms) | edges certified |"
    );
    println!("|---|---|---|---|---|---|");
    for configuration in [Configuration::RrtConnect, Configuration::MitStar] {
        for per_unit in [32.0, 16.0] {
            for certification in [mit_star_robot::CERTIFICATION, 1] {
                let mut times = Vec::new();
                let mut certified = 0;
                let started = Instant::now();
                for seed in 0..3_u64 {
                    for (i, problem) in problems.iter().enumerate() {
                        let extent = problem.space().maximum_extent();
                        let problem = problem
                            .clone()
                            .with_resolution(1.0 / (per_unit * extent))
                            .expect("a resolution in (0, 1)");
                        let parameters = Parameters {
                            seed: seed * 1000 + i as u64,
                            certification: Some(certification),
                            range: (configuration == Configuration::RrtConnect).then_some(1.0),
                            ..Parameters::default()
                        };
                        let run = Instant::now();
                        let mut planner =
                            build_planner(configuration, &problem, &parameters).expect("builds");
                        let _ = planner.solve(&FirstSolution.or(TimeLimit::seconds(1.0)));
                        times.push(run.elapsed().as_secs_f64());
                        certified += planner.counters().certifications;
                    }
                }
                let total = started.elapsed().as_secs_f64();
                times.sort_by(f64::total_cmp);
                println!(
                    "| {} | {per_unit} | {} | {total:.3} | {:.3} | {certified} |",
                    configuration.name(),
                    if certification > 1 { "on" } else { "off" },
                    times[times.len() / 2] * 1e3
                );
            }
        }
    }
}
