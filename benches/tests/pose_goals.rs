//! `plan --goal-pose` and `[problems.pose_goal]`: a link's pose as an arm problem's goal,
//! reached through goal configurations inverse kinematics draws while planning; bad poses
//! refused with a message naming what is wrong.

use std::path::Path;

use crate::common;
use common::{mit_star, refused, scratch, succeeded};

/// `mbm:` and a sample Panda folder.
fn panda(scene: &str) -> String {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../robot/tests/data/mbm")
        .join(format!("{scene}_panda"));
    format!("mbm:{}", folder.display())
}

#[test]
fn plan_reaches_the_hand_pose_of_the_goal_configuration() {
    let problem = panda("table_pick");
    for planner in ["rrt-connect", "aorrtc", "mit-star"] {
        let out = mit_star(&[
            "plan",
            "--planner",
            planner,
            "--problem",
            &problem,
            "--goal-pose",
            "goal",
            "--link",
            "panda_hand",
            "--time",
            "1",
            "--no-picture",
            "--json",
        ]);
        let stdout = String::from_utf8_lossy(&out.stdout);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{planner}: {stdout}\n{stderr}");
        let value: serde_json::Value = serde_json::from_str(stdout.trim()).expect("JSON");
        assert_eq!(value["status"], "solved", "{planner}: {stdout}");
        // The path was judged against the pose, and the goals drawn reported.
        assert!(value["validation"]["valid"].as_bool().unwrap_or(false));
        assert!(
            stderr.contains("goal configurations drawn by inverse kinematics"),
            "{stderr}"
        );
    }
}

#[test]
fn a_pose_with_tolerances_and_an_explicit_target() {
    // The Panda's hand above the box, pointing down, anywhere within 2 cm, turning freely
    // about its approach axis.
    let out = succeeded(&[
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        &panda("box"),
        "--goal-pose",
        "0.3,0.0,0.8,1,0,0,0",
        "--link",
        "panda_hand",
        "--position-tolerance",
        "0.02",
        "--orientation-tolerance",
        "axis:z",
        "--no-picture",
    ]);
    assert!(
        out.contains("solved; path validated independently"),
        "{out}"
    );
}

#[test]
fn bad_poses_are_refused_naming_them() {
    let problem = panda("box");
    let plan = |extra: &[&str]| {
        let mut args = vec!["plan", "--problem", problem.as_str(), "--no-picture"];
        args.extend_from_slice(extra);
        args.iter()
            .map(|s| (*s).to_owned())
            .collect::<Vec<String>>()
    };
    let cases: [(&[&str], &[&str]); 6] = [
        (
            &["--goal-pose", "goal", "--link", "panda_nose"],
            &["`panda_nose`"],
        ),
        (
            &["--goal-pose", "0,0,0.5,0,0,0,0", "--link", "panda_hand"],
            &["norm 0"],
        ),
        (
            &["--goal-pose", "0,0,NaN,0,0,0,1", "--link", "panda_hand"],
            &["`NaN`"],
        ),
        (
            &["--goal-pose", "0.5,0,0.5", "--link", "panda_hand"],
            &["x,y,z,qx,qy,qz,qw"],
        ),
        (
            &[
                "--goal-pose",
                "goal",
                "--link",
                "panda_hand",
                "--position-tolerance",
                "-0.1",
            ],
            &["ball radius", "-0.1"],
        ),
        (
            &[
                "--goal-pose",
                "goal",
                "--link",
                "panda_hand",
                "--orientation-tolerance",
                "cone:w:1",
            ],
            &["cone:AXIS:ANGLE"],
        ),
    ];
    for (extra, needles) in cases {
        let args = plan(extra);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        refused(&args, needles);
    }
    refused(
        &[
            "plan",
            "--problem",
            "dividing-walls",
            "--goal-pose",
            "goal",
            "--link",
            "x",
        ],
        &["arm problems"],
    );
}

#[test]
fn an_unreachable_pose_is_no_solution_with_the_reason() {
    // Two metres above the robot: out of the Panda's reach.
    let out = mit_star(&[
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        &panda("box"),
        "--goal-pose",
        "0,0,2.5,1,0,0,0",
        "--link",
        "panda_hand",
        "--time",
        "0.5",
        "--no-picture",
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stdout.contains("no solution within the budget"),
        "{stdout}\n{stderr}"
    );
    assert!(stderr.contains("0 goal configurations drawn"), "{stderr}");
    assert!(
        stderr.contains("no configuration reaches the pose"),
        "{stderr}"
    );
}

#[test]
fn experiments_take_a_pose_goal_table() {
    let folder = scratch("pose-goal", "experiment");
    std::fs::create_dir_all(&folder).expect("a scratch folder");
    let file = folder.join("pose.toml");
    let problem = panda("table_pick");
    let text = format!(
        "name = \"pose\"\nruns = 1\nplanners = [\"rrt-connect\"]\n\n[[problems]]\nname = \"{}\"\ntime = 1.0\ninstance_seeds = [1, 2]\n\n[problems.pose_goal]\nlink = \"panda_hand\"\npose = \"goal\"\nik_goals = 4\n",
        problem.replace('\\', "\\\\")
    );
    std::fs::write(&file, text).expect("writes");
    let results = folder.join("results");
    succeeded(&[
        "bench",
        file.to_str().expect("utf-8"),
        "--output",
        results.to_str().expect("utf-8"),
        "--no-plots",
    ]);
    let runs = std::fs::read_to_string(results.join("runs.jsonl")).expect("runs.jsonl");
    let solved = runs.matches("\"status\":\"solved\"").count();
    assert_eq!(solved, 2, "{runs}");
    // The results folder records the pose goal: resuming with another one is refused.
    let recorded = std::fs::read_to_string(results.join("experiment.toml")).expect("toml");
    assert!(recorded.contains("[problems.pose_goal]"), "{recorded}");
    let bad = folder.join("bad.toml");
    std::fs::write(
        &bad,
        "name = \"bad\"\nplanners = [\"rrt-connect\"]\n[[problems]]\nname = \"dividing-walls\"\ndimensions = [2]\ntime = 1.0\n[problems.pose_goal]\nlink = \"panda_hand\"\npose = \"goal\"\n",
    )
    .expect("writes");
    refused(
        &["bench", bad.to_str().expect("utf-8")],
        &["pose_goal", "box world"],
    );
}
