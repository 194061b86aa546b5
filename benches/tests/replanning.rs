//! `mit-star replan`: a tiny re-planning experiment runs end to end (deterministic iteration
//! budgets), writes its tables and pictures, and bad options are refused before any trial.

use crate::common;
use common::{refused, succeeded};

/// Two trials of two planners, two legs each, on iteration budgets (deterministic).
const TINY: [&str; 11] = [
    "replan",
    "--scenes",
    "horizontal",
    "--planners",
    "rrt-connect,mit-star",
    "--trials",
    "2",
    "--legs",
    "2",
    "--iterations",
    "150",
];

#[test]
fn a_tiny_replanning_experiment_writes_its_table_and_pictures() {
    let out = common::scratch("replanning", "tiny");
    let text = succeeded(&[TINY.as_slice(), &["--output", out.to_str().unwrap()]].concat());
    assert!(
        text.contains("| horizontal | RRT-Connect | 2/2 = 100.0 ["),
        "{text}"
    );
    assert!(text.contains("| horizontal | MIT* | "), "{text}");
    let trials = std::fs::read_to_string(out.join("trials.csv")).unwrap();
    assert_eq!(trials.lines().count(), 5, "{trials}");
    assert!(
        trials
            .lines()
            .nth(1)
            .unwrap()
            .starts_with("horizontal,RRT-Connect,1,0,success,")
    );
    let summary = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    assert_eq!(summary.lines().count(), 3, "{summary}");
    for stem in [
        "horizontal-rrt-connect-trial1",
        "horizontal-mit-star-trial1",
    ] {
        for ext in ["svg", "png"] {
            let file = out.join(format!("{stem}.{ext}"));
            assert!(file.is_file(), "{} missing", file.display());
        }
    }
    // Iteration budgets are deterministic: the same command, the same trials.
    let again = common::scratch("replanning", "tiny-again");
    succeeded(
        &[
            TINY.as_slice(),
            &["--no-picture", "--output", again.to_str().unwrap()],
        ]
        .concat(),
    );
    let columns = |text: &str| -> Vec<String> {
        // Everything but the wall-clock seconds.
        text.lines()
            .map(|l| l.rsplit_once(',').map_or(l, |(a, _)| a).to_owned())
            .collect()
    };
    let repeated = std::fs::read_to_string(again.join("trials.csv")).unwrap();
    assert_eq!(columns(&trials), columns(&repeated));
    assert!(!again.join("horizontal-mit-star-trial1.png").exists());
}

#[test]
fn bad_options_are_refused_before_any_trial() {
    // The listing of shipped experiments points to the command.
    assert!(succeeded(&["experiments"]).contains("`mit-star replan`"));
    refused(
        &["replan", "--scenes", "diagonal"],
        &[
            "unknown re-planning scene `diagonal`",
            "horizontal, vertical",
        ],
    );
    refused(&["replan", "--planners", "prm"], &["unknown planner `prm`"]);
    refused(
        &["replan", "--cycle", "0"],
        &["re-planning rule `cycle`", "positive"],
    );
    refused(
        &["replan", "--velocity-scaling", "2"],
        &["velocity scaling", "at most 1"],
    );
    refused(&["replan", "--set", "batch_size=0"], &["batch_size"]);
}
