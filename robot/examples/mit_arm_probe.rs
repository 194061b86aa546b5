//! `mit_arm_probe`: what MIT* (or another planner) did on the Panda in a fixed time — its
//! counters and the cost over time, problem by problem, to see where its anytime search spends
//! the budget.
//!
//! ```text
//! cargo run --release -p mit-star-robot --example mit_arm_probe -- target 5 mit-star 1.0 scenes=cage
//! ```
//!
//! Arguments as `anytime_arm`'s (folder, problems per scene, one configuration, seconds, then
//! `key=value` parameters, `scenes=` and `robot=ur5|fetch` for another shipped robot's problems,
//! read from `FOLDER/<scene>_<robot>`). Prints per problem the first-solution time, the
//! cost at 10 ms, 100 ms and the end, the number of improvements, and the counters: batches,
//! samples, vertices, pruned, reverse and forward iterations, reverse restarts and repairs,
//! sparse and full checks, grid points tested, validity checks (sampler's apart) and
//! neighbour queries, and the solve's wall time in seconds.
//!
//! `PROBE_FIXED_ITERATIONS=N` stops each solve after `N` iterations instead of the time (the
//! cost at the end is then the cost after them, however long they took): a build that takes
//! the same decisions prints the same counters, and its wall time compares the two builds'
//! speed on exactly the same work (`PROBE_ITERATIONS=N` prints the first `N`
//! iterations one by one).

use mit_star::{Configuration, Parameters, TimeLimit, build_planner};

#[path = "support/mbm_scenes.rs"]
mod mbm_scenes;
#[path = "support/parameter_switches.rs"]
mod parameter_switches;
use mbm_scenes::problems_of;
use parameter_switches::set_parameter;

fn main() {
    let mut args = std::env::args().skip(1);
    let folder = args.next().unwrap_or_else(|| "target".into());
    let count: usize = args.next().map_or(5, |a| a.parse().expect("a count"));
    let name = args.next().unwrap_or_else(|| "mit-star".into());
    let seconds: f64 = args.next().map_or(1.0, |a| a.parse().expect("seconds"));
    let mut base = Parameters::default();
    let mut scenes = vec!["cage".to_owned()];
    let mut robot = (
        "panda".to_owned(),
        mit_star_robot::ArmProblem::panda().expect("the shipped Panda loads"),
    );
    for setting in args {
        let (key, value) = setting.split_once('=').expect("key=value");
        if key == "scenes" {
            scenes = value.split(',').map(str::to_owned).collect();
            continue;
        }
        if key == "robot" {
            robot = mbm_scenes::shipped_robot(value);
            continue;
        }
        assert!(set_parameter(&mut base, key, value), "unknown {key}");
    }
    let configuration: Configuration = name.parse().expect("a configuration");
    println!(
        "scene idx first_ms c10 c100 cend line impr batches samples verts pruned rev_it fwd_it restarts repairs sparse full points vchecks smp_checks nn solve_s"
    );
    let fixed: Option<u64> = std::env::var("PROBE_FIXED_ITERATIONS")
        .ok()
        .map(|n| n.parse().expect("a count"));
    for scene in &scenes {
        let folder_name = format!("{scene}_{}", robot.0);
        for (index, problem) in problems_of(&robot.1, &folder, &folder_name, count) {
            let parameters = Parameters {
                seed: index as u64,
                range: base.range.or(matches!(
                    configuration,
                    Configuration::RrtConnect | Configuration::Aorrtc
                )
                .then_some(1.0)),
                ..base.clone()
            };
            let mut planner = build_planner(configuration, &problem, &parameters).expect("builds");
            if let Ok(limit) = std::env::var("PROBE_ITERATIONS") {
                // Step by step: what each of the first iterations did.
                for i in 1..=limit.parse::<u64>().expect("a count") {
                    planner
                        .solve(&mit_star::IterationLimit::new(1))
                        .expect("plans");
                    let c = planner.counters();
                    println!(
                        "  iteration {i}: best {:.3} samples {} rev {} fwd {} batches {} full {} sparse {}",
                        planner.best_cost(),
                        c.samples,
                        c.reverse_iterations,
                        c.forward_iterations,
                        c.batches,
                        c.full_checks,
                        c.sparse_checks
                    );
                }
            }
            let started = std::time::Instant::now();
            match fixed {
                Some(n) => planner.solve(&mit_star::IterationLimit::new(n)),
                None => planner.solve(&TimeLimit::seconds(seconds)),
            }
            .expect("plans");
            let solve_s = started.elapsed().as_secs_f64();
            let trace = planner.trace();
            // The cost at the end: at `seconds`, or after the fixed iterations however long
            // they took.
            let end = if fixed.is_some() {
                f64::INFINITY
            } else {
                seconds
            };
            let c = planner.counters();
            let line = {
                use mit_star_problems::PlanningProblem;
                use mit_star_spaces::StateSpace;
                problem
                    .space()
                    .distance(problem.start(), &problem.goals()[0])
            };
            println!(
                "{} {index} {:.3} {:.3} {:.3} {:.3} {:.3} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {solve_s:.4}",
                scene,
                trace.initial().map_or(f64::INFINITY, |p| p.time * 1e3),
                trace.cost_at(0.01),
                trace.cost_at(0.1),
                trace.cost_at(end),
                line,
                trace.points().len(),
                c.batches,
                c.samples,
                c.vertices,
                c.pruned,
                c.reverse_iterations,
                c.forward_iterations,
                c.reverse_restarts,
                c.reverse_repairs,
                c.sparse_checks,
                c.full_checks,
                c.points_tested,
                c.validity_checks,
                c.sampler_checks,
                c.neighbour_queries,
            );
        }
    }
}
