//! `--robot` and `mit-star robots`: the shipped robots are listed, plan from the command line
//! and in experiments, and an unknown robot or an unknown link (in strict mode) is refused
//! with a message naming it. The UR5 problems are the two copies in `robot/tests/data/mbm`.

use std::path::Path;

use crate::common;
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

/// A copy of the sample folder `name` (`box_ur5`) with `edit` applied to each file's text
/// (given the file name), as `mbm:` + its path.
fn edited_folder(name: &str, tag: &str, edit: impl Fn(&str, String) -> String) -> String {
    let from = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../robot/tests/data/mbm")
        .join(name);
    let dir = common::scratch("robots", &format!("{name}-{tag}"));
    std::fs::create_dir_all(&dir).unwrap();
    for entry in std::fs::read_dir(&from).unwrap() {
        let path = entry.unwrap().path();
        let file = path.file_name().unwrap().to_string_lossy().into_owned();
        let text = edit(&file, std::fs::read_to_string(&path).unwrap());
        std::fs::write(dir.join(&file), text).unwrap();
    }
    format!("mbm:{}", dir.display())
}

/// The UR5's joints, in coordinate order.
const UR5_JOINTS: [&str; 6] = [
    "shoulder_pan_joint",
    "shoulder_lift_joint",
    "elbow_joint",
    "wrist_1_joint",
    "wrist_2_joint",
    "wrist_3_joint",
];

#[test]
fn paths_carry_their_joints_and_check_path_reorders_or_refuses_by_name() {
    let problem = ur5_box();
    let out = succeeded(&[
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
        "--json",
    ]);
    let record: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(record["joints"], serde_json::json!(UR5_JOINTS), "{out}");
    assert_eq!(
        record["wrapping"],
        serde_json::json!(vec![false; 6]),
        "{out}"
    );
    let path: Vec<Vec<f64>> = serde_json::from_value(record["path"].clone()).unwrap();
    assert!(path.len() >= 2, "{out}");
    let dir = common::scratch("robots", "named-paths");
    std::fs::create_dir_all(&dir).unwrap();
    // The JSON `plan --json` writes is read as it is.
    let json = dir.join("plan.json");
    std::fs::write(&json, &out).unwrap();
    let check = |file: &Path| {
        mit_star(&[
            "check-path",
            "--robot",
            "ur5",
            "--problem",
            &problem,
            "--path",
            &file.to_string_lossy(),
        ])
    };
    let judged = check(&json);
    let text = String::from_utf8_lossy(&judged.stdout);
    assert!(judged.status.success(), "{text}");
    assert!(!text.contains("reordered"), "{text}");
    // A text file naming the joints in reverse order, its values reversed too: reordered.
    let reversed: Vec<&str> = UR5_JOINTS.iter().rev().copied().collect();
    let mut lines = vec![format!("joints: {}", reversed.join(", "))];
    for state in &path {
        let values: Vec<String> = state.iter().rev().map(|x| format!("{x:?}")).collect();
        lines.push(values.join(" "));
    }
    let named = dir.join("reversed.txt");
    std::fs::write(&named, lines.join("\n")).unwrap();
    let judged = check(&named);
    let text = String::from_utf8_lossy(&judged.stdout);
    assert!(judged.status.success(), "{text}");
    assert!(
        text.contains("reordered by name into the robot's coordinate order"),
        "{text}"
    );
    // Without the names, the reversed values are read in the robot's order: not the path.
    std::fs::write(&named, lines[1..].join("\n")).unwrap();
    assert_eq!(check(&named).status.code(), Some(3));
    // Names that are not the robot's joints are refused, naming them.
    lines[0] =
        "joints: a, shoulder_lift_joint, elbow_joint, wrist_1_joint, wrist_2_joint, elbow_joint"
            .into();
    std::fs::write(&named, lines.join("\n")).unwrap();
    refused(
        &[
            "check-path",
            "--robot",
            "ur5",
            "--problem",
            &problem,
            "--path",
            &named.to_string_lossy(),
        ],
        &[
            "missing: shoulder_pan_joint, wrist_3_joint",
            "not the robot's: a",
            "named twice: elbow_joint",
            "in coordinate order: shoulder_pan_joint, shoulder_lift_joint",
        ],
    );
}

#[test]
fn a_value_outside_a_limit_names_the_joint() {
    let problem = edited_folder("box_ur5", "elbow", |file, text| {
        if file == "request0001.yaml" {
            text.replace("position: 1.373208815745217", "position: 4.0")
        } else {
            text
        }
    });
    refused(
        &["plan", "--robot", "ur5", "--problem", &problem],
        &["joint `elbow_joint` (coordinate 2) is 4, outside its limits"],
    );
}

#[test]
fn an_end_in_the_scene_names_link_obstacle_and_depth_and_the_problem_once() {
    let intruder = "  collision_objects:\n    - id: intruder\n      primitives:\n        - type: box\n          dimensions: [4, 4, 4]\n      primitive_poses:\n        - position: [0, 0, 0]\n          orientation: [0, 0, 0, 1]\n";
    let problem = edited_folder("box_ur5", "intruder", |file, text| {
        if file == "scene0001.yaml" {
            text.replacen("  collision_objects:\n", intruder, 1)
        } else {
            text
        }
    });
    let out = mit_star(&["plan", "--robot", "ur5", "--problem", &problem]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    for needle in [
        "the start configuration collides with the scene: link ",
        " meets obstacle intruder (overlap ",
        " mm)",
    ] {
        assert!(stderr.contains(needle), "`{needle}` not in: {stderr}");
    }
    assert_eq!(stderr.matches("/0001").count(), 1, "{stderr}");
    // `bench` skips the problem with the same diagnosis and plans the other.
    let folder = common::scratch("robots", "intruder-bench");
    let out = mit_star(&[
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
        &folder.to_string_lossy(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let note = stderr
        .lines()
        .find(|l| l.starts_with("note: skipped: "))
        .unwrap_or_else(|| panic!("{stderr}"));
    assert!(
        note.contains("meets obstacle intruder (overlap ") && note.matches("/0001").count() == 1,
        "{note}"
    );
}

#[test]
fn goals_of_held_joints_and_clamped_held_starts_get_a_note() {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robot/tests/data/mbm/box_fetch");
    let problem = format!("mbm:{}", folder.display());
    let out = mit_star(&[
        "check-state",
        "--robot",
        "fetch",
        "--group",
        "arm",
        "--problem",
        &problem,
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let note = "note: problem `box_fetch/0001`: the goal's values for joints outside the planned group are not planned: torso_lift_joint = 0.3448199338115123 (held at 0.1)";
    assert!(stderr.contains(note), "{stderr}");
    // A start above the torso's limit: held, it is clamped with a note; planned, it is
    // refused naming the joint.
    let high = edited_folder("box_fetch", "high-torso", |file, text| {
        if file.starts_with("request") {
            text.replace("position: [0, 0, 0.1,", "position: [0, 0, 0.5,")
        } else {
            text
        }
    });
    let out = mit_star(&[
        "check-state",
        "--robot",
        "fetch",
        "--group",
        "arm",
        "--problem",
        &high,
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains(
            "held joints' start values clamped into their limits: torso_lift_joint = 0.5 -> 0.38615"
        ),
        "{stderr}"
    );
    refused(
        &["plan", "--robot", "fetch", "--problem", &high],
        &["joint `torso_lift_joint` (coordinate 0) is 0.5, outside its limits [0, 0.3861]"],
    );
}

/// A copy of the UR5's spherised URDF in a scratch folder `tag`, its `wrist_3_joint` made
/// continuous, with the UR5's SRDF beside it as `srdf` (none if `None`); the URDF's path.
fn ur5_urdf(tag: &str, srdf: Option<&str>) -> std::path::PathBuf {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robot/data/ur5");
    let dir = common::scratch("robots", tag);
    std::fs::create_dir_all(&dir).unwrap();
    let urdf = std::fs::read_to_string(data.join("ur5_spherized.urdf")).unwrap();
    let wrist = "<joint name=\"wrist_3_joint\" type=\"revolute\">";
    assert!(urdf.contains(wrist));
    let urdf = urdf.replace(wrist, "<joint name=\"wrist_3_joint\" type=\"continuous\">");
    let path = dir.join("my_ur5.urdf");
    std::fs::write(&path, urdf).unwrap();
    if let Some(name) = srdf {
        std::fs::copy(data.join("ur5.srdf"), dir.join(name)).unwrap();
    }
    path
}

#[test]
fn a_urdf_path_is_a_robot_described_and_planned_with_its_continuous_joint_marked() {
    let urdf = ur5_urdf("urdf-with-srdf", Some("my_ur5.srdf"));
    let urdf_text = urdf.to_string_lossy().into_owned();
    let described = succeeded(&["robots", &urdf_text]);
    for needle in [
        "SRDF: ",
        "my_ur5.srdf",
        "6 joints, in coordinate order",
        " 0  shoulder_pan_joint ",
        "revolute    [-3.141593, 3.141593] rad",
        " 5  wrist_3_joint ",
        "continuous  wraps at ±π",
        "groups:   manipulator",
        "40 spheres on",
        "RRT range: 1.0471975",
    ] {
        assert!(
            described.contains(needle),
            "`{needle}` not in:\n{described}"
        );
    }
    let problem = ur5_box();
    let out = succeeded(&[
        "plan",
        "--robot",
        &urdf_text,
        "--problem",
        &problem,
        "--planner",
        "rrt-connect",
        "--time",
        "5",
        "--no-picture",
        "--json",
    ]);
    let record: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(record["joints"], serde_json::json!(UR5_JOINTS), "{out}");
    assert_eq!(
        record["wrapping"],
        serde_json::json!([false, false, false, false, false, true]),
        "{out}"
    );
    let text = succeeded(&[
        "plan",
        "--robot",
        &urdf_text,
        "--problem",
        &problem,
        "--planner",
        "rrt-connect",
        "--time",
        "5",
        "--no-picture",
    ]);
    assert!(
        text.contains("joints: shoulder_pan_joint, shoulder_lift_joint")
            && text.contains("(continuous, wrapping at ±π: wrist_3_joint;"),
        "{text}"
    );
    // The only SRDF of the folder is taken whatever its name.
    let other = ur5_urdf("urdf-other-srdf", Some("robot.srdf"));
    let described = succeeded(&["robots", &other.to_string_lossy()]);
    assert!(described.contains("robot.srdf"), "{described}");
}

#[test]
fn a_urdf_without_an_srdf_plans_with_the_generated_pairs_and_a_warning() {
    let urdf = ur5_urdf("urdf-alone", None);
    let urdf_text = urdf.to_string_lossy().into_owned();
    let described = succeeded(&["robots", &urdf_text]);
    assert!(
        described.contains("groups:   none (no SRDF)")
            && described.contains("warning:  no SRDF beside")
            && described.contains("adjacent in the sphere model"),
        "{described}"
    );
    let problem = ur5_box();
    let out = mit_star(&[
        "plan",
        "--robot",
        &urdf_text,
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
    assert!(stderr.contains("no SRDF beside"), "{stderr}");
    refused(
        &[
            "plan",
            "--robot",
            &urdf_text,
            "--group",
            "manipulator",
            "--problem",
            &problem,
        ],
        &["has no SRDF", "no planning group `manipulator`"],
    );
}
