//! `certification_cost`: what certifying arm motion costs, against the 4× grid it replaced.
//!
//! ```text
//! mkdir -p target && tar xjf robot/data/panda/mbm_problems.tar.bz2 -C target/
//! cargo run --release -p mit-star-robot --example certification_cost -- target 20
//! ```
//!
//! Collects the edges arm planners certify — the edges of MIT*'s and RRT-Connect's first
//! solutions, planned with certification off, on the first `N` problems of each of the five
//! MotionBenchMaker scenes under `FOLDER` — and then, on exactly those edges, times (1) the
//! continuous certification (`certify_motion`) and (2) the grid a quarter of the check step
//! apart that certification used to test (its points off the planning grid, a batch of the
//! checker's lanes at a time). Prints configurations evaluated and nanoseconds per edge for
//! both, per scene; the ratio is what the certification's cost target is judged by.

use std::time::Instant;

use mit_star::{
    Configuration, FirstSolution, Parameters, TerminationExt, TimeLimit, build_planner,
};
use mit_star_problems::PlanningProblem;
use mit_star_robot::ArmProblem;
use mit_star_spaces::{Never, StateSpace};
use mit_star_validity::{EdgeStatus, MotionProgress, StateValidity};

#[path = "support/mbm_scenes.rs"]
mod mbm_scenes;
use mbm_scenes::{SCENES, problems};

fn main() {
    let mut args = std::env::args().skip(1);
    let folder = args.next().unwrap_or_else(|| "target".into());
    let count: usize = args
        .next()
        .map_or(20, |a| a.parse().expect("a problem count"));
    let repeats: u32 = 5;
    println!(
        "| scene | edges | continuous: configurations | grid/4: points | continuous ns/edge | grid/4 ns/edge | ratio |"
    );
    println!("|---|---|---|---|---|---|---|");
    let (mut all_c, mut all_g) = (0.0, 0.0);
    for scene in SCENES {
        let mut edges: Vec<(ArmProblem, Vec<f64>, Vec<f64>)> = Vec::new();
        for (index, problem) in problems(&folder, scene, count) {
            let problem = problem.allowing_uncertified_motion(true);
            for configuration in [Configuration::MitStar, Configuration::RrtConnect] {
                let parameters = Parameters {
                    seed: index as u64,
                    certification: Some(1),
                    range: (configuration == Configuration::RrtConnect).then_some(1.0),
                    ..Parameters::default()
                };
                let mut planner =
                    build_planner(configuration, &problem, &parameters).expect("builds");
                let outcome = planner
                    .solve(&FirstSolution.or(TimeLimit::seconds(1.0)))
                    .expect("plans");
                if let Some(solution) = outcome.solution() {
                    let path: Vec<&[f64]> = solution.path.iter().collect();
                    for pair in path.windows(2) {
                        edges.push((problem.clone(), pair[0].to_vec(), pair[1].to_vec()));
                    }
                }
            }
        }
        let (mut configurations, mut points) = (0_u64, 0_u64);
        let started = Instant::now();
        for _ in 0..repeats {
            configurations = 0;
            for (problem, a, b) in &edges {
                let mut progress = MotionProgress::default();
                let status = problem
                    .validity()
                    .certify_motion(problem.space(), a, b, &mut progress, &Never)
                    .expect("arms certify motions");
                std::hint::black_box(status == EdgeStatus::Valid);
                configurations += progress.evaluations();
            }
        }
        let continuous = started.elapsed().as_secs_f64() / f64::from(repeats);
        let started = Instant::now();
        let mut batch = Vec::new();
        for _ in 0..repeats {
            points = 0;
            for (problem, a, b) in &edges {
                let step = problem.check_step().expect("a step") / 4.0;
                let n = ((problem.space().distance(a, b) / step).ceil() as usize).max(1);
                batch.clear();
                let mut q = vec![0.0; a.len()];
                let batch_len = problem.validity().batch_width() * a.len();
                let mut invalid = false;
                // The points of the finer grid not on the planning grid (every fourth is).
                for k in (1..n).filter(|k| k % 4 != 0) {
                    problem
                        .space()
                        .interpolate(a, b, k as f64 / n as f64, &mut q);
                    batch.extend_from_slice(&q);
                    points += 1;
                    if batch.len() == batch_len {
                        invalid |= problem.validity().first_invalid(&batch, a.len()).is_some();
                        batch.clear();
                    }
                }
                if !batch.is_empty() {
                    invalid |= problem.validity().first_invalid(&batch, a.len()).is_some();
                }
                std::hint::black_box(invalid);
            }
        }
        let grid = started.elapsed().as_secs_f64() / f64::from(repeats);
        let per = |s: f64| s * 1e9 / edges.len().max(1) as f64;
        all_c += continuous;
        all_g += grid;
        println!(
            "| {scene} | {} | {configurations} | {points} | {:.0} | {:.0} | {:.2} |",
            edges.len(),
            per(continuous),
            per(grid),
            continuous / grid
        );
    }
    println!("all scenes: continuous / grid = {:.2}", all_c / all_g);
}
