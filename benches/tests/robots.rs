//! `--robot` and `mit-star robots`: the shipped robots are listed, plan from the command line
//! and in experiments, and an unknown robot or an unknown link (in strict mode) is refused
//! with a message naming it. The UR5 problems are the two copies in `robot/tests/data/mbm`.

use std::path::Path;

mod common;
use common::{mit_star, refused, succeeded};

/// `mbm:` and the sample UR5 box folder.
fn ur5_box() -> String {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robot/tests/data/mbm/box_ur5");
    format!("mbm:{}", folder.display())
}

#[test]
fn robots_lists_the_shipped_ones() {
    let out = succeeded(&["robots"]);
    for needle in [
        "panda (default)",
        "ur5",
        "fetch",
        "6 joints (dimension 6)",
        "40 spheres",
        "ur5/problems.tar.bz2",
        "tar xjf",
        "--robot ur5 --problem mbm:target/problems/box_ur5",
    ] {
        assert!(out.contains(needle), "`{needle}` not in:\n{out}");
    }
}

#[test]
fn unknown_robots_and_links_are_refused_naming_them() {
    let problem = ur5_box();
    refused(
        &["plan", "--robot", "ur10", "--problem", &problem],
        &["`ur10`", "panda, ur5, fetch, baxter"],
    );
    refused(
        &[
            "plan",
            "--robot",
            "ur5",
            "--strict-robot",
            "--problem",
            &problem,
        ],
        &["`box_link`", "allowed-collision matrix"],
    );
    refused(
        &["plan", "--problem", &problem],
        &["no value for joint `panda_joint1`"],
    );
    refused(
        &["plan", "--robot", "ur5", "--problem", "dividing-walls"],
        &["--robot", "mbm:PATH"],
    );
}

#[test]
fn ur5_plans_from_the_command_line_and_in_experiments() {
    let problem = ur5_box();
    let out = mit_star(&[
        "plan",
        "--robot",
        "ur5",
        "--problem",
        &problem,
        "--planner",
        "rrt-connect",
        "--time",
        "5",
        "--no-picture",
    ]);
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert!(out.status.success(), "{stdout}{stderr}");
    assert!(stdout.contains("solved; path validated"), "{stdout}");
    assert!(
        stderr.contains("box_link") && stderr.contains("wrist_2_link/fts_robotside"),
        "{stderr}"
    );
    let folder = common::scratch("robots", "ur5-bench");
    let folder_text = folder.to_string_lossy().into_owned();
    succeeded(&[
        "bench",
        "--robot",
        "ur5",
        "--planners",
        "rrt-connect",
        "--problem",
        &problem,
        "--instances",
        "1-2",
        "--time",
        "2",
        "--runs",
        "1",
        "--threads",
        "1",
        "--no-plots",
        "--quiet",
        "-o",
        &folder_text,
    ]);
    let experiment = std::fs::read_to_string(folder.join("experiment.toml")).unwrap();
    assert!(experiment.contains("robot = \"ur5\""), "{experiment}");
    // The written experiment file runs again, robot included.
    let again = common::scratch("robots", "ur5-again");
    let file = folder.join("experiment.toml");
    succeeded(&[
        "bench",
        &file.to_string_lossy(),
        "--no-plots",
        "--quiet",
        "-o",
        &again.to_string_lossy(),
    ]);
    let runs = std::fs::read_to_string(again.join("runs.csv")).unwrap();
    assert_eq!(
        runs.lines()
            .filter(|l| l.contains(",solved,true,true,"))
            .count(),
        2,
        "{runs}"
    );
}

#[test]
fn a_planning_group_is_planned_with_the_other_joints_held() {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robot/tests/data/mbm/box_fetch");
    let problem = format!("mbm:{}", folder.display());
    let state = |group: Option<&str>| {
        let mut args = vec!["check-state", "--robot", "fetch", "--problem", &problem];
        args.extend(group.iter().flat_map(|g| ["--group", *g]));
        // `check-state` exits with 1 when a state is invalid.
        String::from_utf8_lossy(&mit_star(&args).stdout).into_owned()
    };
    // With the torso, the goal is free; the `arm` group holds the torso at the request's
    // start (0.1 m, where the goal wants 0.345 m), so the same arm goal hits the scene.
    let whole = state(None);
    assert!(
        whole.contains("R^8") && whole.contains("goal 1: valid"),
        "{whole}"
    );
    let arm = state(Some("arm"));
    assert!(
        arm.contains("R^7") && arm.contains("goal 1: INVALID"),
        "{arm}"
    );
    refused(
        &[
            "plan",
            "--robot",
            "fetch",
            "--group",
            "legs",
            "--problem",
            &problem,
        ],
        &["no planning group `legs`", "arm, arm_with_torso"],
    );
    refused(
        &["plan", "--group", "arm", "--problem", "dividing-walls"],
        &["--group", "mbm:PATH"],
    );
    let listed = succeeded(&["robots"]);
    assert!(
        listed.contains("groups:   left_arm, right_arm, both_arms"),
        "{listed}"
    );
}

/// A copy of the sample Fetch box folder whose requests name planning group `group`.
fn fetch_box_naming(group: &str) -> String {
    let from = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robot/tests/data/mbm/box_fetch");
    let dir = common::scratch("robots", &format!("box_fetch_{group}"));
    std::fs::create_dir_all(&dir).unwrap();
    for entry in std::fs::read_dir(&from).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        let name = path.file_name().unwrap();
        let text = if name.to_string_lossy().starts_with("request") {
            assert!(text.contains("group_name: arm_with_torso"), "{text}");
            text.replace(
                "group_name: arm_with_torso",
                &format!("group_name: {group}"),
            )
        } else {
            text
        };
        std::fs::write(dir.join(name), text).unwrap();
    }
    format!("mbm:{}", dir.display())
}

#[test]
fn the_requests_planning_group_is_planned_unless_another_is_named() {
    let state = |problem: &str, group: Option<&str>| {
        let mut args = vec!["check-state", "--robot", "fetch", "--problem", problem];
        args.extend(group.iter().flat_map(|g| ["--group", *g]));
        let out = mit_star(&args);
        (
            String::from_utf8_lossy(&out.stdout).into_owned(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    // Requests naming `arm`: the torso is held, as with `--group arm`.
    let arm = fetch_box_naming("arm");
    let (out, err) = state(&arm, None);
    assert!(out.contains("R^7"), "{out}");
    assert!(
        err.contains("planning group `arm` of robot `fetch`, as the requests name it"),
        "{err}"
    );
    // A group named on the command line wins.
    let (out, err) = state(&arm, Some("arm_with_torso"));
    assert!(out.contains("R^8"), "{out}");
    assert!(!err.contains("as the requests name it"), "{err}");
    // The shipped requests name the whole robot's joints: nothing to say.
    let (out, err) = state(&fetch_box_naming("arm_with_torso"), None);
    assert!(out.contains("R^8"), "{out}");
    assert!(!err.contains("planning group"), "{err}");
    // A group the SRDF lacks: a warning naming it, and every moving joint planned.
    let (out, err) = state(&fetch_box_naming("legs"), None);
    assert!(out.contains("R^8"), "{out}");
    assert!(
        err.contains("the requests name planning group `legs`")
            && err.contains("no planning group `legs`"),
        "{err}"
    );
}
