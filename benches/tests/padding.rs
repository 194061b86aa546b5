//! `--padding`: a plan keeps the padding from every obstacle and the independent check says
//! how far it stayed; bad values are refused naming the flag; an end within the padding is
//! refused naming the padding; a results folder is not resumed with another padding.

use std::path::Path;

use crate::common;
use common::{mit_star, refused, scratch, succeeded};

/// `mbm:` and a sample MotionBenchMaker folder of `robot/tests/data/mbm`.
fn sample(scene: &str) -> String {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../robot/tests/data/mbm")
        .join(scene);
    format!("mbm:{}", folder.display())
}

#[test]
fn a_padded_plan_keeps_the_padding_by_the_independent_check() {
    let problem = sample("box_panda");
    let out = succeeded(&[
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        &problem,
        "--padding",
        "0.01",
        "--simplify",
        "--no-picture",
    ]);
    assert!(out.contains("with a padding of 10 mm"), "{out}");
    // The audit's smallest distance to an obstacle, in millimetres.
    let at = out.find("every sphere ≥ ").unwrap() + "every sphere ≥ ".len();
    let mm: f64 = out[at..].split(' ').next().unwrap().parse().unwrap();
    assert!(mm >= 10.0, "{mm} mm: {out}");
    // Half a metre: the start and the goal are within it, said by name (exit code 3).
    let out = mit_star(&["check-state", "--problem", &problem, "--padding", "0.5"]);
    let state = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(3), "{state}");
    assert!(
        state.contains("is within the padding (500 mm) of obstacle"),
        "{state}"
    );
}

#[test]
fn bad_paddings_are_refused_naming_the_flag() {
    let problem = sample("box_panda");
    for (value, says) in [
        ("-0.01", "negative"),
        ("nan", "not a number"),
        ("2", "larger than 1 m"),
        ("ten", "not a number"),
    ] {
        refused(
            &["plan", "--problem", &problem, "--padding", value],
            &["--padding", says],
        );
    }
    refused(
        &["plan", "--problem", "dividing-walls", "--padding", "0.01"],
        &["padding", "arm problems"],
    );
    // The goal of cage_panda/1 is a grasp 9.4 mm from the object.
    refused(
        &[
            "plan",
            "--problem",
            &sample("cage_panda"),
            "--padding",
            "0.01",
        ],
        &["goal configuration is within the collision padding (10 mm)"],
    );
}

#[test]
fn a_folder_is_not_resumed_with_another_padding() {
    let dir = scratch("padding", "resume");
    let output = dir.to_string_lossy().into_owned();
    let problem = sample("box_panda");
    let bench = |padding: &str| {
        vec![
            "bench",
            "--planners",
            "rrt-connect",
            "--problem",
            &problem,
            "--time",
            "1",
            "--runs",
            "1",
            "--threads",
            "1",
            "--first-solution",
            "--no-plots",
            "--quiet",
            "--padding",
            padding,
            "-o",
            &output,
        ]
        .into_iter()
        .map(str::to_owned)
        .collect::<Vec<_>>()
    };
    let first = bench("0.01");
    let args: Vec<&str> = first.iter().map(String::as_str).collect();
    let out = mit_star(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let toml = std::fs::read_to_string(dir.join("experiment.toml")).unwrap();
    assert!(toml.contains("padding = 0.01"), "{toml}");
    let second = bench("0.02");
    let args: Vec<&str> = second.iter().map(String::as_str).collect();
    refused(
        &args,
        &["`padding = 0.01` in the folder, `padding = 0.02` now"],
    );
}
