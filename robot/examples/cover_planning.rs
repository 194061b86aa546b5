//! `cover_planning`: how a sphere model of the UR5 plans on the seven UR5 MotionBenchMaker
//! scenes — problems skipped (a start or goal in collision), and problems solved by MIT* and
//! RRT-Connect within a time budget.
//!
//! ```text
//! mkdir -p target && tar xjf robot/data/ur5/problems.tar.bz2 -C target/
//! cargo run --release -p mit-star-robot --example cover_planning -- ur5 target/problems 20 1
//! cargo run --release -p mit-star-robot --example cover_planning -- target/ur5_mesh target/problems 20 1
//! ```
//!
//! Arguments: the robot (`ur5`, or a folder with a spherised URDF and an SRDF, as `--robot`
//! takes), the folder holding `<scene>_ur5/`, the problems per scene (the first `N`), the
//! seconds per run, and optionally the scenes (comma separated; default all seven) and
//! `warm_start=true` (MIT* started from RRT-Connect's first path). One run per planner and
//! problem, seed 0, default parameters, one thread —
//! what `mit-star bench --planners mit-star,rrt-connect --runs 1 --time T` runs, without the
//! harness's independent re-check of each returned path (`MotionAudit`, in `f64` with parry,
//! whose cost grows with the product of the sphere counts of the checked link pairs: about
//! 30 s per path with two thousand spheres). A planner's paths are certified by its own
//! checker; this example counts a run as solved when the planner returns a path.
//!
//! Prints one row per scene and a total: problems, skipped, solved per planner; then each
//! skipped problem with the contact that makes its start or goal invalid.

use std::path::Path;

use mit_star::{Configuration, Parameters, TimeLimit, build_planner};
use mit_star_robot::{ArmProblem, RobotSource};

#[path = "support/mbm_scenes.rs"]
mod mbm_scenes;
use mbm_scenes::SEVEN_SCENES as SCENES;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let robot = args.first().map_or("ur5", String::as_str);
    let folder = args.get(1).map_or("target/problems", String::as_str);
    let count: usize = args
        .get(2)
        .map_or(20, |a| a.parse().expect("a problem count"));
    let seconds: f64 = args.get(3).map_or(1.0, |a| a.parse().expect("seconds"));
    let warm_start = args.iter().skip(4).any(|a| a == "warm_start=true");
    let scenes: Vec<&str> = args
        .get(4)
        .filter(|a| !a.contains('='))
        .map_or(SCENES.to_vec(), |a| a.split(',').collect());
    let model = RobotSource::parse(robot)
        .and_then(|s| s.load(false))
        .expect("a robot");
    let planners = [Configuration::MitStar, Configuration::RrtConnect];
    println!(
        "robot {robot}: {} spheres; {count} problems per scene, {seconds} s per run{}",
        model.spheres().len(),
        if warm_start {
            ", MIT* warm-started"
        } else {
            ""
        }
    );
    println!("| scene | problems | skipped | MIT* solved | RRT-Connect solved |");
    println!("|---|---|---|---|---|");
    let mut total = [0_usize; 4];
    let mut skipped_list = Vec::new();
    for scene in scenes {
        let dir = Path::new(folder).join(format!("{scene}_ur5"));
        let mut row = [0_usize; 4];
        for index in 1..=count {
            row[0] += 1;
            let problem = ArmProblem::mbm(model.clone(), &dir, index).expect("a problem");
            if let Err(e) = problem.check_ends() {
                row[1] += 1;
                skipped_list.push(format!("{scene} {index}: {e}"));
                continue;
            }
            for (p, configuration) in planners.iter().enumerate() {
                let parameters = Parameters {
                    seed: 0,
                    warm_start,
                    ..Parameters::default()
                };
                let mut planner =
                    build_planner(*configuration, &problem, &parameters).expect("a planner");
                let solved = planner
                    .solve(&TimeLimit::seconds(seconds))
                    .is_ok_and(|o| o.solution().is_some());
                if solved {
                    row[2 + p] += 1;
                } else {
                    eprintln!("{scene} {index}: {} found no path", configuration.name());
                }
            }
        }
        println!(
            "| {scene} | {} | {} | {} | {} |",
            row[0], row[1], row[2], row[3]
        );
        for (t, r) in total.iter_mut().zip(row) {
            *t += r;
        }
    }
    println!(
        "| all | {} | {} | {} | {} |",
        total[0], total[1], total[2], total[3]
    );
    for line in skipped_list {
        println!("skipped {line}");
    }
}
