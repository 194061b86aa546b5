//! `plan --trajectory` times the arm path and writes it; `check-path --trajectory` checks it,
//! with `check-path`'s exit codes: 0 valid, 3 invalid, 2 for files or options refused.

use std::path::PathBuf;

use crate::common;
use common::{mit_star, refused, succeeded};

fn problem() -> String {
    format!(
        "mbm:{}",
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../robot/tests/data/mbm/table_pick_panda"
        )
    )
}

fn limits() -> &'static str {
    concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../robot/data/panda/joint_limits.yaml"
    )
}

/// Plans, simplifies and writes the trajectory `name` with `extra` options; its path.
fn planned(name: &str, extra: &[&str]) -> PathBuf {
    let dir = common::scratch("trajectories", name);
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join(name);
    let problem = problem();
    let mut args = vec![
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        &problem,
        "--time",
        "5",
        "--seed",
        "2",
        "--simplify",
        "--no-picture",
        "--joint-limits",
        limits(),
    ];
    let file_text = file.to_string_lossy().into_owned();
    args.extend(["--trajectory", &file_text]);
    args.extend(extra);
    let stdout = succeeded(&args);
    assert!(
        stdout.contains("trajectory: ") && stdout.contains(" knots, "),
        "{stdout}"
    );
    file
}

fn check(file: &std::path::Path) -> std::process::Output {
    let problem = problem();
    mit_star(&[
        "check-path",
        "--problem",
        &problem,
        "--trajectory",
        &file.to_string_lossy(),
        "--joint-limits",
        limits(),
    ])
}

#[test]
fn planned_trajectories_pass_the_check_and_tampered_ones_do_not() {
    let blended = planned("blended.json", &["--sample-period", "0.002"]);
    let out = check(&blended);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("  valid"), "{stdout}");
    let stopping = planned(
        "stopping.csv",
        &["--corners", "stop", "--velocity-scaling", "0.5"],
    );
    let out = check(&stopping);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    // Blended, at the knots: the motion between two knots is a parabola the check finds
    // (a straight line between them cuts a blend's corner, which may touch an obstacle).
    let knots = planned("knots.json", &[]);
    let out = check(&knots);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    // A velocity beyond its limit: invalid (exit code 3), named.
    let mut json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&blended).unwrap()).unwrap();
    json["samples"][3]["velocity"][0] = serde_json::json!(9.0);
    let fast = blended.with_file_name("fast.json");
    std::fs::write(&fast, json.to_string()).unwrap();
    let out = check(&fast);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(3), "{stdout}");
    assert!(
        stdout.contains("INVALID") && stdout.contains("panda_joint1"),
        "{stdout}"
    );
    // Times going backwards: refused (exit code 2), naming the sample.
    json["samples"][5]["time"] = json["samples"][2]["time"].clone();
    let backwards = blended.with_file_name("backwards.json");
    std::fs::write(&backwards, json.to_string()).unwrap();
    let problem = problem();
    refused(
        &[
            "check-path",
            "--problem",
            &problem,
            "--trajectory",
            &backwards.to_string_lossy(),
            "--joint-limits",
            limits(),
        ],
        &["sample 5", "does not come after"],
    );
}

/// Whether `file` is a PNG of some substance: its signature, and over 20 kB (an empty
/// 1400 × 1120 white picture compresses to a few kB).
fn is_a_drawn_png(file: &std::path::Path) -> bool {
    let bytes = std::fs::read(file).unwrap_or_default();
    bytes.starts_with(b"\x89PNG\r\n\x1a\n") && bytes.len() > 20_000
}

#[test]
fn trajectories_are_plotted_by_plan_and_check_path() {
    let dir = common::scratch("trajectory-plots", "plan");
    std::fs::create_dir_all(&dir).unwrap();
    let plot = dir.join("plan.png");
    let blended = planned(
        "plotted.json",
        &["--trajectory-plot", &plot.to_string_lossy()],
    );
    assert!(is_a_drawn_png(&plot), "{}", plot.display());
    let problem = problem();
    let checked = blended.with_file_name("checked.png");
    let stdout = succeeded(&[
        "check-path",
        "--problem",
        &problem,
        "--trajectory",
        &blended.to_string_lossy(),
        "--joint-limits",
        limits(),
        "--plot",
        &checked.to_string_lossy(),
    ]);
    assert!(stdout.contains("plot: "), "{stdout}");
    assert!(is_a_drawn_png(&checked), "{}", checked.display());
    // A plot without a trajectory, or of another format: refused before planning.
    refused(
        &[
            "plan",
            "--planner",
            "rrt-connect",
            "--problem",
            &problem,
            "--no-picture",
            "--trajectory-plot",
            "t.png",
        ],
        &["--trajectory"],
    );
    refused(
        &[
            "plan",
            "--planner",
            "rrt-connect",
            "--problem",
            &problem,
            "--no-picture",
            "--trajectory",
            "t.json",
            "--max-acceleration",
            "2",
            "--trajectory-plot",
            "t.jpg",
        ],
        &["--trajectory-plot t.jpg", ".png or .svg"],
    );
}

#[test]
fn trajectory_options_are_checked_before_planning() {
    let problem = problem();
    let base = [
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        problem.as_str(),
        "--no-picture",
        "--trajectory",
        "t.json",
    ];
    let with = |extra: &[&'static str]| {
        let mut args = base.to_vec();
        args.extend_from_slice(extra);
        args
    };
    refused(&with(&[]), &["panda_joint1", "no acceleration limit"]);
    refused(
        &with(&["--max-acceleration", "2", "--velocity-scaling", "1.5"]),
        &["velocity scaling 1.5"],
    );
    refused(
        &with(&["--max-acceleration", "-2"]),
        &["panda_joint1", "acceleration limit -2"],
    );
    refused(
        &with(&["--max-acceleration", "2", "--sample-period", "0"]),
        &["--sample-period 0"],
    );
    refused(
        &[
            "plan",
            "--problem",
            "dividing-walls",
            "--no-picture",
            "--trajectory",
            "t.json",
            "--max-acceleration",
            "1",
        ],
        &["arm problems"],
    );
}

#[test]
fn blend_room_simplifies_with_room_and_is_refused_where_meaningless() {
    let roomy = planned("roomy.json", &["--blend-room", "0.005"]);
    assert!(roomy.exists());
    let out = check(&roomy);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}");
    let problem = problem();
    let base = [
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        &problem,
        "--no-picture",
        "--trajectory",
        "t.json",
    ];
    let with = |extra: &[&'static str]| -> Vec<&str> {
        base.iter().copied().chain(extra.iter().copied()).collect()
    };
    // Not a padding, with stops (no blends), or without `--simplify`: refused.
    refused(
        &with(&["--simplify", "--blend-room", "-0.01"]),
        &["--blend-room -0.01", "negative"],
    );
    refused(
        &with(&["--simplify", "--blend-room", "0.01", "--corners", "stop"]),
        &["--blend-room", "--corners stop"],
    );
    refused(&with(&["--blend-room", "0.01"]), &["--simplify"]);
}
