//! `bench` summarises by scene by default — one table row per planner and scene, one figure
//! per scene — and gives every problem's detail with `--per-problem`.

use std::path::Path;

use crate::common::{scratch, succeeded};

/// `bench` on layouts 1 to 3 of random rectangles (one scene) into `dir`, with `extra` flags.
fn bench_three_layouts(dir: &Path, extra: &[&str]) -> String {
    let mut args = vec![
        "bench",
        "--planners",
        "mit-star,rrt-connect",
        "--problem",
        "random-rectangles",
        "--dim",
        "2",
        "--instances",
        "1-3",
        "--runs",
        "2",
        "--time",
        "0.2",
        "-q",
        "-o",
        dir.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    succeeded(&args)
}

/// The files of `dir` (none if it does not exist), sorted.
fn files(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .map(|entries| {
            entries
                .filter_map(Result::ok)
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    names
}

#[test]
fn a_scene_gets_one_row_per_planner_and_one_figure_by_default() {
    let dir = scratch("scenes", "default");
    let stdout = bench_three_layouts(&dir, &[]);
    assert!(stdout.contains("## Summary by scene"), "{stdout}");
    let row = stdout
        .lines()
        .find(|l| l.starts_with("| random-rectangles R^2 | MIT* | 3 | "))
        .unwrap_or_else(|| panic!("{stdout}"));
    assert!(row.contains("/6 | 0 |"), "{row}");
    assert!(stdout.contains("| random-rectangles R^2 | RRT-Connect | 3 |"));
    // No per-layout rows on the terminal, nor the Table I layout (no EIT*).
    assert!(!stdout.contains("R^2 #1"), "{stdout}");
    assert!(!stdout.contains("## All KPIs"), "{stdout}");
    assert!(stdout.contains("--per-problem"), "{stdout}");
    assert_eq!(
        files(&dir.join("plots")),
        ["random-rectangles-n2.png", "random-rectangles-n2.svg"]
    );
    // The scene's hardest layout's view and the viewer.
    assert_eq!(files(&dir.join("views")).len(), 2);
    // kpi.md keeps every layout's KPIs.
    let kpi = std::fs::read_to_string(dir.join("kpi.md")).unwrap();
    assert!(kpi.contains("## Summary by scene") && kpi.contains("## All KPIs"));
    assert!(kpi.contains("| random-rectangles R^2 #3 | MIT* |"), "{kpi}");
    let report = std::fs::read_to_string(dir.join("report.html")).unwrap();
    assert!(report.contains("plots/random-rectangles-n2.svg"));
    assert!(report.contains("its hardest layout"), "{report}");
}

#[test]
fn per_problem_prints_every_kpi_and_draws_every_layout() {
    let dir = scratch("scenes", "per-problem");
    let stdout = bench_three_layouts(&dir, &["--per-problem"]);
    assert!(stdout.contains("## Summary by scene") && stdout.contains("## All KPIs"));
    assert!(
        stdout.contains("| random-rectangles R^2 #2 | MIT* |"),
        "{stdout}"
    );
    let plots = files(&dir.join("plots"));
    assert_eq!(plots.len(), 2 * 4, "{plots:?}");
    assert!(plots.contains(&"random-rectangles-n2-i2.png".to_owned()));
    // Every layout's view and the viewer.
    assert_eq!(files(&dir.join("views")).len(), 3 + 1);
    // The listing names every file.
    assert!(
        stdout.contains("plots/random-rectangles-n2-i3.svg"),
        "{stdout}"
    );
}

#[test]
fn the_default_listing_counts_a_folder_of_many_files() {
    let dir = scratch("scenes", "listing");
    let stdout = succeeded(&[
        "bench",
        "--planners",
        "rrt-connect",
        "--problem",
        "random-rectangles",
        "--dim",
        "2",
        "--instances",
        "9",
        "--runs",
        "1",
        "--time",
        "0.02",
        "--no-plots",
        "-q",
        "-o",
        dir.to_str().unwrap(),
    ]);
    assert!(stdout.contains("/logs/ (9 files)"), "{stdout}");
    assert!(!stdout.contains("random-rectangles-n2-i4.log"), "{stdout}");
    assert!(stdout.contains("/kpi.md"), "{stdout}");
}
