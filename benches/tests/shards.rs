//! Campaigns across machines: an experiment run as shards (`bench --shard K/N`) and merged
//! (`merge`) is the experiment run whole — the same runs, seeds and outcomes — and `merge`
//! refuses parts that do not make up one whole experiment; `compare` reads two folders back.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use crate::common;
use common::{refused, succeeded};

/// An empty scratch path for this test file.
fn scratch(name: &str) -> PathBuf {
    common::scratch("shards", name)
}

/// The experiment: runs that stop at their first solution, which on these problems comes
/// long before the budget — so each run's outcome depends on its seed only.
const EXPERIMENT: &[&str] = &[
    "bench",
    "--planners",
    "rrt-connect,mit-star,eit-star",
    "--problem",
    "dividing-walls,goal-enclosure",
    "--dim",
    "2",
    "--time",
    "5",
    "--runs",
    "5",
    "--seed",
    "40",
    "--first-solution",
    "--name",
    "sharded",
    "--no-plots",
    "--quiet",
];

/// One run as recorded: seed, status, first-solution cost bits, path length.
type Outcome = (u64, String, Option<u64>, usize);

/// Runs by (instance, planner, run index).
type Runs = BTreeMap<(String, String, u64), Outcome>;

/// Every run of a folder's `runs.jsonl`, by (instance, planner, run), and the order of the file.
fn runs(folder: &Path) -> (Runs, Vec<String>) {
    let text = std::fs::read_to_string(folder.join("runs.jsonl")).unwrap();
    let mut map = BTreeMap::new();
    let mut order = Vec::new();
    for line in text.lines() {
        let r: serde_json::Value = serde_json::from_str(line).unwrap();
        let key = (
            r["instance"].as_str().unwrap().to_owned(),
            r["planner"].as_str().unwrap().to_owned(),
            r["run"].as_u64().unwrap(),
        );
        let outcome = (
            r["seed"].as_u64().unwrap(),
            r["status"].as_str().unwrap().to_owned(),
            r["initial_cost"].as_f64().map(f64::to_bits),
            r["path"].as_array().map_or(0, Vec::len),
        );
        order.push(format!("{key:?}"));
        assert!(map.insert(key, outcome).is_none(), "a run recorded twice");
    }
    (map, order)
}

/// `mit-star merge PARTS… --output OUTPUT --no-plots`, which must succeed; its output.
fn merge(parts: &[&PathBuf], output: &Path) -> String {
    let mut args = vec!["merge"];
    args.extend(parts.iter().map(|p| p.to_str().unwrap()));
    args.extend(["--output", output.to_str().unwrap(), "--no-plots"]);
    succeeded(&args)
}

fn bench(output: &Path, shard: Option<&str>) {
    let mut args = EXPERIMENT.to_vec();
    let output = output.to_str().unwrap();
    args.extend(["--output", output]);
    if let Some(shard) = shard {
        args.extend(["--shard", shard]);
    }
    succeeded(&args);
}

#[test]
fn three_shards_merged_are_the_whole_experiment() {
    let whole = scratch("whole");
    bench(&whole, None);
    let parts: Vec<PathBuf> = (1..=3).map(|k| scratch(&format!("part-{k}"))).collect();
    for (k, part) in parts.iter().enumerate() {
        bench(part, Some(&format!("{}/3", k + 1)));
    }
    let (whole_runs, _) = runs(&whole);
    assert_eq!(whole_runs.len(), 3 * 2 * 5);
    // The parts are disjoint, and none is empty.
    let mut union = BTreeMap::new();
    for part in &parts {
        let (mine, _) = runs(part);
        assert!(mine.len() >= 9, "{} runs in a part", mine.len());
        for (key, outcome) in mine {
            assert!(union.insert(key, outcome).is_none(), "a run in two parts");
        }
    }
    assert_eq!(
        union, whole_runs,
        "the parts' runs are the whole experiment's"
    );
    // Merged in any order, the folder holds the same runs, in schedule order.
    let merged = scratch("merged");
    let out = merge(&[&parts[2], &parts[0], &parts[1]], &merged);
    assert!(out.contains("Merged 3 shards (30 runs"), "{out}");
    let (merged_runs, order) = runs(&merged);
    assert_eq!(merged_runs, whole_runs);
    let again = scratch("merged-again");
    merge(&[&parts[0], &parts[1], &parts[2]], &again);
    assert_eq!(
        runs(&again).1,
        order,
        "the merged order does not depend on the parts' order"
    );
    // One OMPL log per instance, the database and the KPI table, as a whole run writes them.
    for file in [
        "experiment.toml",
        "runs.csv",
        "benchmark.db",
        "kpi.md",
        "logs/dividing-walls-n2.log",
        "logs/goal-enclosure-n2.log",
    ] {
        assert!(merged.join(file).is_file(), "{file}");
    }
    assert_eq!(
        std::fs::read_to_string(merged.join("experiment.toml")).unwrap(),
        std::fs::read_to_string(whole.join("experiment.toml")).unwrap()
    );
    let csv_rows = |f: &Path| {
        std::fs::read_to_string(f.join("runs.csv"))
            .unwrap()
            .lines()
            .count()
    };
    assert_eq!(csv_rows(&merged), csv_rows(&whole));
    let log = std::fs::read_to_string(merged.join("logs/goal-enclosure-n2.log")).unwrap();
    // Per planner, 5 runs and their 5 progress series.
    assert_eq!(log.matches("\n5 runs\n").count(), 6, "{log}");
    // `compare` reads both folders back: the same experiment, rows matched one to one, the
    // same success rates and first-solution costs.
    let out = succeeded(&["compare", whole.to_str().unwrap(), merged.to_str().unwrap()]);
    assert!(out.contains("(30 runs) →"), "{out}");
    for problem in ["dividing-walls R^2", "goal-enclosure R^2"] {
        for planner in ["RRT-Connect", "MIT*", "EIT*"] {
            let row = out
                .lines()
                .find(|l| l.starts_with(&format!("| {problem} | {planner} |")))
                .unwrap_or_else(|| panic!("no row for {planner} on {problem}: {out}"));
            let cells: Vec<&str> = row.split(" | ").collect();
            assert_eq!(cells[6], cells[7], "success rates: {row}");
            assert_eq!(cells[8], "≈", "{row}");
        }
    }
    assert!(!out.contains("Only in"), "{out}");
    refused(
        &["compare", whole.to_str().unwrap(), "/nonexistent-folder"],
        &["not a results folder"],
    );
    // Merging into a finished merge adds nothing.
    merge(&[&parts[0], &parts[1], &parts[2]], &merged);
    assert_eq!(runs(&merged).1, order);

    // Refusals, each naming what is wrong.
    let p = |i: usize| parts[i].to_str().unwrap().to_owned();
    let target = scratch("refused");
    let target = target.to_str().unwrap();
    refused(
        &["merge", &p(0), &p(1), "--output", target],
        &["shard 3/3 is missing"],
    );
    refused(
        &["merge", &p(0), &p(0), &p(1), "--output", target],
        &["are both shard 1/3"],
    );
    refused(
        &["merge", whole.to_str().unwrap(), &p(1), "--output", target],
        &["not a shard's folder"],
    );
    refused(
        &["merge", &p(0), &p(1), &p(2), "--output", &p(0)],
        &["is a shard's folder"],
    );
    // A shard of another experiment (other runs per planner).
    let other = scratch("other");
    let mut args = EXPERIMENT.to_vec();
    args[10] = "4";
    args.extend(["--output", other.to_str().unwrap(), "--shard", "3/3"]);
    succeeded(&args);
    refused(
        &[
            "merge",
            &p(0),
            &p(1),
            other.to_str().unwrap(),
            "--output",
            target,
        ],
        &["hold different experiments"],
    );
    // A part with a run missing (an interrupted shard) and one with a duplicate.
    let cut = scratch("cut");
    std::fs::create_dir_all(&cut).unwrap();
    for file in ["experiment.toml", "shard.toml"] {
        std::fs::copy(parts[1].join(file), cut.join(file)).unwrap();
    }
    let lines = std::fs::read_to_string(parts[1].join("runs.jsonl")).unwrap();
    let lines: Vec<&str> = lines.lines().collect();
    let kept = lines[..lines.len() - 1].join("\n") + "\n";
    std::fs::write(cut.join("runs.jsonl"), &kept).unwrap();
    let (first, last) = (p(0), p(2));
    let with_cut = [
        "merge",
        &first,
        cut.to_str().unwrap(),
        &last,
        "--output",
        target,
    ];
    refused(
        &with_cut,
        &["1 of the experiment's 30 runs is missing", "--shard 2/3"],
    );
    std::fs::write(
        cut.join("runs.jsonl"),
        kept + lines[0] + "\n" + lines[0] + "\n",
    )
    .unwrap();
    refused(&with_cut, &["twice"]);
    // A shard's folder is resumed only by the same shard, and bad shards are refused.
    let mut args = EXPERIMENT.to_vec();
    args.extend(["--output", &first, "--shard", "2/3"]);
    refused(&args, &["holds shard 1/3", "not 2/3"]);
    let mut args = EXPERIMENT.to_vec();
    args.extend(["--output", &first]);
    refused(&args, &["holds shard 1/3"]);
    for bad in ["0/3", "4/3", "3", "x/y"] {
        let mut args = EXPERIMENT.to_vec();
        args.extend(["--output", target, "--shard", bad]);
        refused(&args, &["--shard"]);
    }
}
