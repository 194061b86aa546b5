//! Point clouds from the command line: a scene seen as a cloud is planned in and validated,
//! a cloud on the robot is named, and bad cloud options are refused by name.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use crate::common::{self, refused, scratch};

fn table_pick() -> String {
    format!(
        "mbm:{}",
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../robot/tests/data/mbm/table_pick_panda"
        )
    )
}

/// An ASCII PLY file of `points` in a fresh scratch folder.
fn ply(name: &str, points: &[[f64; 3]]) -> PathBuf {
    let dir = scratch("clouds", name);
    std::fs::create_dir_all(&dir).unwrap();
    let mut text = format!(
        "ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\n\
         property float z\nend_header\n",
        points.len()
    );
    for [x, y, z] in points {
        writeln!(text, "{x} {y} {z}").unwrap();
    }
    let path = dir.join(format!("{name}.ply"));
    std::fs::write(&path, text).unwrap();
    path
}

/// A cube of points `side` metres wide around `center`, `n` a side.
fn cube(center: [f64; 3], side: f64, n: usize) -> Vec<[f64; 3]> {
    let at = |i: usize, c: f64| c - 0.5 * side + side * i as f64 / (n - 1) as f64;
    let mut points = Vec::new();
    for i in 0..n {
        for j in 0..n {
            for k in 0..n {
                points.push([at(i, center[0]), at(j, center[1]), at(k, center[2])]);
            }
        }
    }
    points
}

#[test]
fn a_scene_seen_as_a_cloud_is_planned_in_and_validated() {
    let problem = table_pick();
    let dir = scratch("clouds", "table-pick");
    let saved = scratch("clouds", "saved.ply");
    let out = common::mit_star(&[
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        &problem,
        "--scene-as-cloud",
        "2000",
        "--crop-reach",
        "--voxel",
        "0.02",
        "--save-cloud",
        saved.to_str().unwrap(),
        "--time",
        "5",
        "--output",
        dir.to_str().unwrap(),
    ]);
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert!(out.status.success(), "{stdout}{stderr}");
    for needle in [
        "primitives (2000 each, seed 1)",
        "cloud: crop to the robot's reach",
        "cloud: one point per 0.02 m voxel",
        "cloud: tree of",
    ] {
        assert!(stderr.contains(needle), "`{needle}` not in {stderr}");
    }
    assert!(
        stdout.contains("validated independently, continuously"),
        "{stdout}"
    );
    let svg = find(&dir, "svg").expect("a picture of the plan");
    let drawn = std::fs::read_to_string(svg).unwrap();
    assert!(drawn.contains("cloud ("), "the legend names the cloud");
    // The saved cloud, read back as a file, with the scene's primitives dropped.
    let again = common::succeeded(&[
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        &problem,
        "--cloud",
        saved.to_str().unwrap(),
        "--drop-primitives",
        "--time",
        "5",
        "--no-picture",
    ]);
    assert!(
        again.contains("validated independently, continuously"),
        "{again}"
    );
}

#[test]
fn an_anytime_planner_stops_at_its_first_solution_among_a_cloud() {
    // `plan --first-solution`: the time to MIT*'s first path among a sampled cloud, not the
    // whole budget (without the flag the run takes its 30 s).
    let problem = table_pick();
    let stdout = common::succeeded(&[
        "plan",
        "--planner",
        "mit-star",
        "--problem",
        &problem,
        "--scene-as-cloud",
        "2000",
        "--crop-reach",
        "--min-distance",
        "0.02",
        "--first-solution",
        "--time",
        "30",
        "--no-picture",
        "--json",
    ]);
    let record: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(record["status"], "solved", "{stdout}");
    let initial = record["initial_time"].as_f64().expect("a first solution");
    let run = record["run_time"].as_f64().unwrap();
    assert!(run < 15.0, "stopped at {run} s, not at the first solution");
    assert!(initial <= run, "{initial} > {run}");
    assert!(record["path"].as_array().is_some_and(|p| p.len() >= 2));
}

/// The first file under `dir` (recursively) ending in `.extension`.
fn find(dir: &Path, extension: &str) -> Option<PathBuf> {
    for entry in std::fs::read_dir(dir).ok()? {
        let path = entry.ok()?.path();
        if path.is_dir() {
            if let Some(found) = find(&path, extension) {
                return Some(found);
            }
        } else if path.extension().is_some_and(|e| e == extension) {
            return Some(path);
        }
    }
    None
}

#[test]
fn a_cloud_on_the_robots_base_is_named_where_it_touches() {
    let problem = table_pick();
    // Points through the Panda's base, which every configuration keeps there.
    // And a few far above the robot's reach, which stay when the robot's own are removed.
    let mut points = cube([0.0, 0.0, 0.1], 0.08, 5);
    points.extend(cube([0.0, 0.0, 3.0], 0.1, 2));
    let file = ply("base", &points);
    let file = file.to_str().unwrap();
    let out = common::mit_star(&["check-state", "--problem", &problem, "--cloud", file]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(3), "{stdout}");
    assert!(stdout.contains("cloud point"), "{stdout}");
    // The same points cleared away as the robot's own: the camera saw the arm.
    let out = common::mit_star(&[
        "check-state",
        "--problem",
        &problem,
        "--cloud",
        file,
        "--remove-robot",
        "0.02",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("the robot's own points at the start"),
        "{stderr}"
    );
    assert_eq!(out.status.code(), Some(0), "{stderr}");
}

#[test]
fn bad_cloud_options_are_refused_by_name() {
    let problem = table_pick();
    let plan = |extra: &[&str], needles: &[&str]| {
        let mut args = vec!["plan", "--planner", "rrt-connect", "--problem", &problem];
        args.extend_from_slice(extra);
        args.extend_from_slice(&["--time", "0.1", "--no-picture"]);
        refused(&args, needles);
    };
    plan(
        &["--cloud", "/nonexistent/cloud.ply"],
        &["/nonexistent/cloud.ply"],
    );
    plan(&["--voxel", "0.02"], &["--cloud FILE or --scene-as-cloud"]);
    plan(&["--scene-as-cloud", "--voxel", "-1"], &["voxel size"]);
    let far = ply("far", &cube([30.0, 0.0, 0.0], 0.1, 3));
    let far = far.to_str().unwrap();
    plan(
        &["--cloud", far, "--crop-reach"],
        &["`cloud.crop_reach` (--crop-reach) leaves none of the 27 points"],
    );
    plan(
        &["--cloud", far, "--sensor-pose", "1,2,3"],
        &["six numbers"],
    );
    plan(
        &["--cloud", far, "--point-radius", "0"],
        &["point cloud `cloud`"],
    );
    refused(
        &[
            "plan",
            "--problem",
            "dividing-walls",
            "--cloud",
            far,
            "--no-picture",
        ],
        &["arm problems"],
    );
}
