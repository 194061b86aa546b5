//! `trajectory_peers`: our trajectories beside TOPP-RA's on simplified Panda paths.
//!
//! ```text
//! mkdir -p target/mbm && tar xjf robot/data/panda/mbm_problems.tar.bz2 -C target/mbm
//! cargo run --release -p mit-star-robot --example trajectory_peers -- plan target/mbm 20 target/peers
//! /work/venv/bin/python benches/peers/toppra/compare.py target/peers
//! cargo run --release -p mit-star-robot --example trajectory_peers -- check target/mbm target/peers
//! /work/venv/bin/python benches/peers/toppra/compare.py target/peers --table
//! ```
//!
//! `plan`: on the first `N` problems of each of the seven MotionBenchMaker Panda scenes,
//! plans with RRT-Connect (range 1, first solution, 1 s), simplifies the path (0.1 s), times
//! it (stop at corners, and blended with certified blends) under the Panda URDF's velocity
//! limits and MoveIt's Panda acceleration limits ([`mit_star_robot::PANDA_JOINT_LIMITS`]), checks our
//! trajectory with [`mit_star_robot::check_trajectory`] at 1 ms samples, and writes per path
//! `SCENE/NNNN.path.json` (waypoints, limits, our durations, computation times and check) and
//! `SCENE/NNNN.ours.json` (our blended trajectory sampled every 1 ms).
//!
//! `plan ... ROOM` (metres, e.g. `0.01`): room for the blends, as `mit-star plan --blend-room`
//! makes it — the path is simplified on the problem [padded](ArmProblem::with_padding) by
//! `ROOM`, so every edge the simplifier adds keeps that much more from obstacles, and the blends
//! are certified against the scene as it is. Planning is unchanged; with `PLAN_ROOMY=1` the
//! path is also planned on the padded problem where its ends keep the room (the table counts
//! the problems whose ends do not). Both sides time the same (roomy) paths.
//!
//! `check`: certifies each `SCENE/NNNN.toppra.json` (TOPP-RA's trajectory sampled by
//! `compare.py`) as a polyline against the problem's scene, and writes
//! `SCENE/NNNN.toppra_check.json`.
//!
//! `retime`: times again the paths of a `plan` output (after `compare.py`'s TOPP-RA pass) with
//! the current `Trajectory::blended`, and prints per scene the median and largest ratio of
//! our durations to TOPP-RA's, for trying a change of the timing without planning again.
//! `RETIME_VERBOSE=1` prints each path; `RETIME_EMPTY=1` certifies blends against an empty
//! scene (self-collisions only: what the obstacles cost); `RETIME_FREE=1` also prints the
//! certifications each path took.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use mit_star::{
    Configuration, FirstSolution, Parameters, PathSimplifier, TerminationExt, TimeLimit,
    build_planner,
};
use mit_star_robot::{
    ArmProblem, BlendCertifier, JointLimitsYaml, MotionLimits, PANDA_JOINT_LIMITS, Padding,
    Trajectory, TrajectoryFile, check_trajectory,
};
use mit_star_spaces::StateSpace as _;

#[path = "support/mbm_scenes.rs"]
mod mbm_scenes;
use mbm_scenes::SEVEN_SCENES;

/// The sample period of the files, in seconds.
const PERIOD: f64 = 1e-3;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("plan") => plan(
            Path::new(&args[1]),
            args[2].parse().expect("a problem count"),
            Path::new(&args[3]),
            args.get(4).map(|r| {
                Padding::new(r.parse().expect("a room in metres")).expect("a room in metres")
            }),
        ),
        Some("check") => check(Path::new(&args[1]), Path::new(&args[2])),
        Some("retime") => retime(Path::new(&args[1]), Path::new(&args[2])),
        _ => panic!(
            "usage: trajectory_peers plan MBM_FOLDER N OUT [ROOM] | check MBM_FOLDER OUT | retime MBM_FOLDER OUT"
        ),
    }
}

fn limits(problem: &ArmProblem) -> MotionLimits {
    let yaml = JointLimitsYaml::parse(PANDA_JOINT_LIMITS, "panda").expect("the Panda's limits");
    MotionLimits::for_robot(problem.robot(), Some(&yaml), None).expect("the Panda's limits")
}

fn plan(folder: &Path, count: usize, out: &Path, room: Option<Padding>) {
    println!(
        "| scene | paths | median length (rad) | ends within the room | median waypoints | median stop (s) | median blended (s) | blends certified / shrunk / stopped | median timing (ms) | median certifier build (ms) | failed checks |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for scene in SEVEN_SCENES {
        let scene = format!("{scene}_panda");
        let dir = out.join(&scene);
        std::fs::create_dir_all(&dir).expect("an output folder");
        let (mut stops, mut blends, mut points, mut took, mut builds) =
            (vec![], vec![], vec![], vec![], vec![]);
        let (mut corners, mut failed, mut ends_within, mut lengths) = ([0; 3], 0, 0, vec![]);
        for index in 1..=count {
            let Ok(problem) = ArmProblem::panda_mbm(&folder.join(&scene), index) else {
                continue;
            };
            if !problem.ends_are_valid() {
                continue;
            }
            let parameters = Parameters {
                seed: index as u64,
                range: Some(1.0),
                ..Parameters::default()
            };
            // With room: the path simplified (and with `PLAN_ROOMY`, planned when its ends keep
            // the room) on the padded problem; the blends certified against the scene as it is.
            let roomy = room.map(|r| problem.clone().with_padding(r));
            let planned_on = match &roomy {
                Some(roomy) if !roomy.ends_are_valid() => {
                    ends_within += 1;
                    &problem
                }
                Some(roomy) if std::env::var_os("PLAN_ROOMY").is_some() => roomy,
                _ => &problem,
            };
            let mut planner =
                build_planner(Configuration::RrtConnect, planned_on, &parameters).expect("builds");
            let outcome = planner.solve(&FirstSolution.or(TimeLimit::seconds(1.0)));
            let Some(solution) = outcome.ok().and_then(|o| o.solution().cloned()) else {
                continue;
            };
            let path: Vec<Vec<f64>> = solution.path.iter().map(<[f64]>::to_vec).collect();
            let simplified = PathSimplifier::new()
                .seed(index as u64)
                .simplify(
                    roomy.as_ref().unwrap_or(&problem),
                    &path,
                    &mit_star_spaces::Deadline::after(Duration::from_secs_f64(0.1)),
                )
                .expect("a path of the problem");
            let path = mit_star_robot::merge_repeated_waypoints(&simplified.path);
            if path.len() < 2 {
                continue;
            }
            let limits = limits(&problem);
            let started = Instant::now();
            let certifier = BlendCertifier::new(problem.robot(), problem.scene());
            let build = started.elapsed().as_secs_f64();
            let started = Instant::now();
            let (blended, report) = Trajectory::blended(&path, &limits, &certifier).expect("timed");
            let timing = started.elapsed().as_secs_f64();
            let stop = Trajectory::stop_at_corners(&path, &limits).expect("timed");
            let file = TrajectoryFile::of(&blended, Some(PERIOD)).expect("sampled");
            let verdict = check_trajectory(
                &file,
                problem.robot(),
                problem.scene(),
                &limits,
                &mit_star_robot::ArmChecker::new(problem.robot(), problem.scene()),
            )
            .expect("checked");
            if !verdict.is_valid() {
                failed += 1;
                eprintln!(
                    "{scene} {index}: {:?}",
                    &verdict.violations[..verdict.violations.len().min(3)]
                );
            }
            file.write(&dir.join(format!("{index:04}.ours.json")))
                .expect("written");
            let record = serde_json::json!({
                "scene": scene,
                "index": index,
                "joints": limits.names(),
                "waypoints": path,
                "velocity_limits": limits.velocity(),
                "acceleration_limits": limits.acceleration(),
                "stop_duration": stop.duration(),
                "blended_duration": blended.duration(),
                "timing_seconds": timing,
                "certifier_build_seconds": build,
                "blends": [report.blended, report.shrunk, report.stopped],
                "room": room.map_or(0.0, mit_star_robot::Padding::metres),
                "length": simplified.cost,
                "check_valid": verdict.is_valid(),
                "check_velocity_excess": verdict.velocity_excess,
                "check_acceleration_excess": verdict.acceleration_excess,
            });
            std::fs::write(
                dir.join(format!("{index:04}.path.json")),
                record.to_string(),
            )
            .expect("written");
            stops.push(stop.duration());
            lengths.push(simplified.cost);
            blends.push(blended.duration());
            points.push(path.len() as f64);
            took.push(timing * 1e3);
            builds.push(build * 1e3);
            corners[0] += report.blended;
            corners[1] += report.shrunk;
            corners[2] += report.stopped;
        }
        println!(
            "| {} | {} | {:.3} | {ends_within} | {} | {:.3} | {:.3} | {} / {} / {} | {:.3} | {:.1} | {failed} |",
            scene.trim_end_matches("_panda"),
            stops.len(),
            mbm_scenes::median(&mut lengths),
            mbm_scenes::median(&mut points),
            mbm_scenes::median(&mut stops),
            mbm_scenes::median(&mut blends),
            corners[0],
            corners[1],
            corners[2],
            mbm_scenes::median(&mut took),
            mbm_scenes::median(&mut builds),
        );
    }
}

fn check(folder: &Path, out: &Path) {
    for scene in SEVEN_SCENES {
        let scene = format!("{scene}_panda");
        let dir = out.join(&scene);
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        let mut files: Vec<PathBuf> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.to_string_lossy().ends_with(".toppra.json"))
            .collect();
        files.sort();
        let (mut checked, mut colliding) = (0, 0);
        for file in files {
            let name = file.file_name().unwrap().to_string_lossy().into_owned();
            let index: usize = name[..4].parse().expect("NNNN.toppra.json");
            let problem = ArmProblem::panda_mbm(&folder.join(&scene), index).expect("the problem");
            let samples = TrajectoryFile::read(&file).expect("TOPP-RA's samples");
            let checker = mit_star_robot::ArmChecker::new(problem.robot(), problem.scene());
            let space = problem.robot().joint_space();
            let mut first = None;
            let mut outside = 0;
            for (i, w) in samples.samples.windows(2).enumerate() {
                if !space.contains(&w[1].position) {
                    outside += 1;
                }
                let mut progress = mit_star_validity::MotionProgress::default();
                let status = mit_star_validity::StateValidity::certify_motion(
                    &checker,
                    space,
                    &w[0].position,
                    &w[1].position,
                    &mut progress,
                    &mit_star_spaces::Never,
                );
                if first.is_none() && status != Some(mit_star_validity::EdgeStatus::Valid) {
                    first = Some(i + 1);
                }
            }
            checked += 1;
            colliding += usize::from(first.is_some());
            let record = serde_json::json!({"collision_free": first.is_none(), "first_failure": first, "outside_position_limits": outside});
            std::fs::write(
                dir.join(format!("{index:04}.toppra_check.json")),
                record.to_string(),
            )
            .expect("written");
        }
        println!(
            "{scene}: {checked} TOPP-RA trajectories certified, {colliding} not collision-free"
        );
    }
}

/// `retime`: times again the paths of a `plan` output whose TOPP-RA runs `compare.py` wrote,
/// and prints per scene the median and largest ratio of our blended durations to TOPP-RA's
/// and our median timing (for trying timing changes without planning again).
fn retime(folder: &Path, out: &Path) {
    let read = |p: &Path| -> serde_json::Value {
        serde_json::from_str(&std::fs::read_to_string(p).expect("readable")).expect("JSON")
    };
    let (mut all, mut all_ms) = (vec![], vec![]);
    for scene in SEVEN_SCENES {
        let scene = format!("{scene}_panda");
        let dir = out.join(&scene);
        let (mut ratios, mut took) = (vec![], vec![]);
        for index in 1..=1000 {
            let path_file = dir.join(format!("{index:04}.path.json"));
            let run_file = dir.join(format!("{index:04}.toppra_run.json"));
            if !path_file.exists() || !run_file.exists() {
                continue;
            }
            let (record, run) = (read(&path_file), read(&run_file));
            let Some(toppra) = run["toppra_duration"].as_f64() else {
                continue;
            };
            let path: Vec<Vec<f64>> =
                serde_json::from_value(record["waypoints"].clone()).expect("waypoints");
            let problem = ArmProblem::panda_mbm(&folder.join(&scene), index).expect("problem");
            let limits = limits(&problem);
            let scene_of = if std::env::var_os("RETIME_EMPTY").is_some() {
                mit_star_robot::Scene::new(vec![])
            } else {
                problem.scene().clone()
            };
            let certifier = BlendCertifier::new(problem.robot(), &scene_of);
            let started = Instant::now();
            let (blended, _) = Trajectory::blended(&path, &limits, &certifier).expect("timed");
            took.push(started.elapsed().as_secs_f64() * 1e3);
            ratios.push(blended.duration() / toppra);
            if std::env::var_os("RETIME_CHECK").is_some() {
                let checker = mit_star_robot::ArmChecker::new(problem.robot(), problem.scene());
                for period in [None, Some(PERIOD)] {
                    let file = TrajectoryFile::of(&blended, period).expect("sampled");
                    let verdict = check_trajectory(
                        &file,
                        problem.robot(),
                        problem.scene(),
                        &limits,
                        &checker,
                    )
                    .expect("checked");
                    if !verdict.is_valid() {
                        let gaps: Vec<f64> = blended
                            .knots()
                            .windows(2)
                            .map(|w| w[1].time - w[0].time)
                            .collect();
                        println!(
                            "{scene} {index}: period {period:?}: {:?}; knots at {:?}; gaps {gaps:?}",
                            &verdict.violations[..verdict.violations.len().min(3)],
                            blended.knots().iter().map(|k| k.time).collect::<Vec<_>>()
                        );
                    }
                }
            }
            if std::env::var_os("RETIME_FREE").is_some() {
                let free =
                    BlendCertifier::new(problem.robot(), &mit_star_robot::Scene::new(vec![]));
                let started = Instant::now();
                let (_, report) = Trajectory::blended(&path, &limits, &free).expect("timed");
                println!(
                    "{scene} {index}: {} waypoints, {:.3} ms in free space ({} certifications), {} certifications in the scene",
                    path.len(),
                    started.elapsed().as_secs_f64() * 1e3,
                    report.certifications,
                    Trajectory::blended(&path, &limits, &certifier)
                        .expect("timed")
                        .1
                        .certifications,
                );
            }
            if std::env::var_os("RETIME_VERBOSE").is_some() {
                println!(
                    "{scene} {index}: {} waypoints, ratio {:.3}",
                    path.len(),
                    blended.duration() / toppra
                );
            }
        }
        all.extend(&ratios);
        all_ms.extend(&took);
        let max = ratios.iter().copied().fold(0.0, f64::max);
        println!(
            "{scene}: {} paths, median ratio {:.3}, max {max:.3}, median timing {:.3} ms",
            ratios.len(),
            mbm_scenes::median(&mut ratios),
            mbm_scenes::median(&mut took)
        );
    }
    let max = all.iter().copied().fold(0.0, f64::max);
    let over = all.iter().filter(|&&r| r > 1.05).count();
    println!(
        "all: {} paths, median ratio {:.4}, max {max:.3}, > 1.05: {over}, median timing {:.3} ms",
        all.len(),
        mbm_scenes::median(&mut all),
        mbm_scenes::median(&mut all_ms)
    );
}
