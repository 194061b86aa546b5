//! `simplify_paths`: what the path simplifier does to arm paths.
//!
//! ```text
//! mkdir -p target && tar xjf robot/data/panda/mbm_problems.tar.bz2 -C target/
//! cargo run --release -p mit-star-robot --example simplify_paths -- target 20 rrt-connect 0.1
//! ```
//!
//! Plans the named configuration on the first `N` problems of each of the five
//! MotionBenchMaker scenes (RRT-Connect with range 1 to its first solution, an asymptotically
//! optimal planner for 1 s), simplifies each path for at most `SECONDS` (`whole` after it:
//! without per-joint shortcuts; `attempts=N`: shortcuts end after `N` failures in a row;
//! `smooth=N`: `N` smoothing sweeps instead of the default;
//! `moves=relax|perturb|both`: the smoothing moves), and audits every
//! simplified edge continuously in `f64` with parry (`padding=M`: problems padded by `M`
//! metres, audited with that padding). Prints per scene the median path length before and
//! after, the median straight-line distance (a lower bound), the median time the
//! simplification took, how many simplified paths failed the audit, and the smallest distances
//! the audit met on the simplified paths: from a sphere to an obstacle, and overall (obstacles
//! less the padding, and the checked pairs of links), against the checker's margin.

use std::time::{Duration, Instant};

use mit_star::{
    Configuration, FirstSolution, Parameters, PathSimplifier, SmoothingMoves, TerminationExt,
    TimeLimit, build_planner,
};
use mit_star_problems::PlanningProblem;
use mit_star_robot::{AuditVerdict, MotionAudit};
use mit_star_spaces::StateSpace;

#[path = "support/mbm_scenes.rs"]
mod mbm_scenes;
use mbm_scenes::{SCENES, median, problems};

fn main() {
    let mut args = std::env::args().skip(1);
    let folder = args.next().unwrap_or_else(|| "target".into());
    let count: usize = args
        .next()
        .map_or(20, |a| a.parse().expect("a problem count"));
    let name = args.next().unwrap_or_else(|| "rrt-connect".into());
    let seconds: f64 = args.next().map_or(0.1, |a| a.parse().expect("seconds"));
    let mut partial = true;
    let mut padding = mit_star_robot::Padding::ZERO;
    let mut simplifier = PathSimplifier::new();
    for option in args {
        match option.split_once('=') {
            // Whole-configuration shortcuts only.
            None if option == "whole" => partial = false,
            Some(("attempts", n)) => {
                simplifier = simplifier.attempts(n.parse().expect("an attempt count"));
            }
            Some(("smooth", n)) => {
                simplifier = simplifier.smoothing_rounds(n.parse().expect("a sweep count"));
            }
            Some(("padding", metres)) => {
                padding = metres.parse().expect("a padding in metres");
            }
            Some(("moves", moves)) => {
                simplifier = simplifier.smoothing_moves(match moves {
                    "relax" => SmoothingMoves::Relax,
                    "perturb" => SmoothingMoves::Perturb,
                    "both" => SmoothingMoves::RelaxThenPerturb,
                    other => panic!("unknown smoothing moves {other}"),
                });
            }
            _ => panic!(
                "unknown option {option}: whole, attempts=N, smooth=N, padding=M or moves=relax|perturb|both"
            ),
        }
    }
    let configuration: Configuration = name.parse().expect("a planner configuration");
    println!(
        "| scene | problems | median length before | median after | mean after | median straight line | median simplification (ms) | median smoothing moves | failed audits | nearest obstacle (µm) | smallest clearance (µm) | margin (µm) |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|");
    for scene in SCENES {
        let (mut before, mut after, mut line, mut took) = (vec![], vec![], vec![], vec![]);
        let mut moves = vec![];
        let mut failed = 0;
        let (mut nearest, mut smallest, mut margin) = (f64::INFINITY, f64::INFINITY, 0.0_f64);
        for (index, problem) in problems(&folder, scene, count) {
            let problem = problem.with_padding(padding);
            if problem.check_ends().is_err() {
                continue;
            }
            margin = margin.max(problem.validity().margin());
            let parameters = Parameters {
                seed: index as u64,
                range: (configuration == Configuration::RrtConnect).then_some(1.0),
                ..Parameters::default()
            };
            let mut planner = build_planner(configuration, &problem, &parameters).expect("builds");
            let outcome = if configuration.is_asymptotically_optimal() {
                planner.solve(&TimeLimit::seconds(1.0))
            } else {
                planner.solve(&FirstSolution.or(TimeLimit::seconds(1.0)))
            };
            let Some(solution) = outcome.ok().and_then(|o| o.solution().cloned()) else {
                continue;
            };
            let path: Vec<Vec<f64>> = solution.path.iter().map(<[f64]>::to_vec).collect();
            let started = Instant::now();
            let simplified = simplifier
                .clone()
                .seed(index as u64)
                .partial_shortcuts(partial)
                .simplify(
                    &problem,
                    &path,
                    &mit_star_spaces::Deadline::after(Duration::from_secs_f64(seconds)),
                )
                .expect("a path of the problem");
            took.push(started.elapsed().as_secs_f64() * 1e3);
            before.push(simplified.original_cost);
            moves.push(simplified.smoothing_moves as f64);
            after.push(simplified.cost);
            line.push(problem.space().distance(&path[0], &path[path.len() - 1]));
            let audit = MotionAudit::padded(problem.robot(), problem.scene(), padding);
            let mut clear = true;
            for w in simplified.path.windows(2) {
                match audit.audit(&w[0], &w[1], 1_000_000) {
                    AuditVerdict::Clear {
                        clearance,
                        obstacle_clearance,
                        ..
                    } => {
                        nearest = nearest.min(obstacle_clearance);
                        smallest = smallest.min(clearance);
                    }
                    _ => clear = false,
                }
            }
            failed += usize::from(!clear);
        }
        println!(
            "| {} | {} | {:.2} | {:.2} | {:.3} | {:.2} | {:.1} | {:.0} | {failed} | {:.1} | {:.1} | {:.1} |",
            scene.trim_end_matches("_panda"),
            before.len(),
            median(&mut before),
            median(&mut after),
            after.iter().sum::<f64>() / after.len() as f64,
            median(&mut line),
            median(&mut took),
            median(&mut moves),
            nearest * 1e6,
            smallest * 1e6,
            margin * 1e6
        );
    }
}
