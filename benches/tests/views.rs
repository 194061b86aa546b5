//! `--view FILE.html`: `plan`, `check-path` and `replan` write one self-contained page holding
//! the scene, the robot and the motions, and `bench` writes `report.html` with a view of each
//! instance's best and worst run.

use crate::common;
use common::{mit_star, refused, succeeded};

/// The document a page embeds, parsed.
fn document(page: &std::path::Path) -> serde_json::Value {
    let text = std::fs::read_to_string(page).unwrap();
    let open = r#"<script type="application/json" id="mit-star-view-data">"#;
    let start = text.find(open).expect("the page embeds its document") + open.len();
    let end = start + text[start..].find("</script>").unwrap();
    serde_json::from_str(&text[start..end].replace("<\\/", "</")).unwrap()
}

fn panda_problem() -> String {
    format!(
        "mbm:{}",
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../robot/tests/data/mbm/table_pick_panda"
        )
    )
}

#[test]
fn an_arm_plan_with_its_trajectory_and_search() {
    let dir = common::scratch("views", "arm");
    std::fs::create_dir_all(&dir).unwrap();
    let page = dir.join("plan.html");
    let trajectory = dir.join("plan.json");
    let problem = panda_problem();
    let stdout = succeeded(&[
        "plan",
        "--planner",
        "eit-star",
        "--problem",
        &problem,
        "--time",
        "2",
        "--simplify",
        "--no-picture",
        "--trajectory",
        trajectory.to_str().unwrap(),
        "--joint-limits",
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../robot/data/panda/joint_limits.yaml"
        ),
        "--view",
        page.to_str().unwrap(),
        "--view-search",
    ]);
    assert!(stdout.contains("plan.html"), "{stdout}");
    let doc = document(&page);
    assert_eq!(doc["kind"], "arm");
    let labels: Vec<&str> = doc["motions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["label"].as_str().unwrap())
        .collect();
    assert_eq!(
        labels,
        ["simplified path", "path as planned", "timed trajectory"]
    );
    for motion in doc["motions"].as_array().unwrap() {
        assert_eq!(motion["colliding"].as_array().unwrap().len(), 0);
        assert_eq!(motion["joint_names"].as_array().unwrap().len(), 7);
    }
    let robot = &doc["robot"];
    assert_eq!(robot["name"], "panda");
    assert!(
        doc["search"]["label"]
            .as_str()
            .unwrap()
            .starts_with("forward tree")
    );
    assert!(doc["motions"][2]["times"].as_array().unwrap().len() > 100);
}

#[test]
fn a_refused_path_is_drawn_red() {
    let dir = common::scratch("views", "refused");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("through.txt");
    std::fs::write(&path, "-0.3 0\n0.3 0\n").unwrap();
    let page = dir.join("refused.html");
    let out = mit_star(&[
        "check-path",
        "--problem",
        "wall-gap",
        "--dim",
        "2",
        "--path",
        path.to_str().unwrap(),
        "--view",
        page.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(3), "an invalid path exits 3");
    let doc = document(&page);
    assert_eq!(doc["kind"], "world2d");
    let motion = &doc["motions"][0];
    assert!(motion["label"].as_str().unwrap().contains("INVALID"));
    assert!(!motion["colliding"].as_array().unwrap().is_empty());
}

#[test]
fn views_are_refused_where_they_cannot_be_drawn() {
    refused(
        &[
            "plan",
            "--problem",
            "wall-gap",
            "--dim",
            "2",
            "--view",
            "plan.png",
        ],
        &["--view plan.png", ".html"],
    );
    let page = common::scratch("views", "four").join("four.html");
    refused(
        &[
            "plan",
            "--problem",
            "obstacle-free",
            "--dim",
            "4",
            "--time",
            "0.05",
            "--no-picture",
            "--view",
            page.to_str().unwrap(),
        ],
        &["4 dimensions"],
    );
}

#[test]
fn a_report_links_each_instance_to_its_view() {
    let dir = common::scratch("views", "report");
    let _ = std::fs::remove_dir_all(&dir);
    succeeded(&[
        "bench",
        "--planners",
        "rrt-connect,mit-star",
        "--problem",
        "wall-gap",
        "--dims",
        "2",
        "--runs",
        "2",
        "--time",
        "0.1",
        "--output",
        dir.to_str().unwrap(),
        "-q",
    ]);
    let report = std::fs::read_to_string(dir.join("report.html")).unwrap();
    assert!(report.contains("<table>"), "the KPI tables");
    let link = "views/wall-gap-n2.html";
    assert!(
        report.contains(&format!("<a href=\"{link}\">3-D view</a>")),
        "{report}"
    );
    assert!(report.contains("plots/wall-gap-n2.svg"));
    let page = std::fs::read_to_string(dir.join(link)).unwrap();
    assert!(
        page.contains(r#"<script src="viewer.js"></script>"#),
        "one shared viewer"
    );
    let viewer = std::fs::read_to_string(dir.join("views/viewer.js")).unwrap();
    assert!(viewer.starts_with("/* Drawn with three.js"));
    let doc = document(&dir.join(link));
    let motions = doc["motions"].as_array().unwrap();
    assert_eq!(motions.len(), 2, "the best and the worst run");
    assert!(motions[0]["label"].as_str().unwrap().starts_with("best: "));
}
