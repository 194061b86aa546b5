//! Point clouds in experiments: `bench` plans two MotionBenchMaker problems among their scenes
//! sampled as clouds — from the command line and from an experiment file — validates every
//! path against the cloud and records its preparation; a changed cloud option does not
//! resume an old folder; `replan` runs among a static cloud and audits the motion against it;
//! bad cloud settings are refused by problem entry and option before any run.

use std::path::{Path, PathBuf};

use crate::common::{self, refused, scratch};

fn table_pick() -> String {
    concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../robot/tests/data/mbm/table_pick_panda"
    )
    .to_owned()
}

/// `bench` on the first two table_pick problems among their scene as a 500-point-per-primitive
/// cloud, cropped to the reach, RRT-Connect, two runs each; `extra` after.
fn bench_args(output: &Path, extra: &[&str]) -> Vec<String> {
    let mut args: Vec<String> = [
        "bench",
        "--planners",
        "rrt-connect",
        "--problem",
        &format!("mbm:{}", table_pick()),
        "--instances",
        "2",
        "--time",
        "2",
        "--runs",
        "2",
        "--threads",
        "1",
        "--scene-as-cloud",
        "500",
        "--crop-reach",
        "--no-plots",
        "--quiet",
        "--output",
        output.to_str().unwrap(),
    ]
    .iter()
    .map(|s| (*s).to_owned())
    .collect();
    args.extend(extra.iter().map(|s| (*s).to_owned()));
    args
}

fn run(args: &[String]) -> (i32, String, String) {
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = common::mit_star(&refs);
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Checks a finished folder: 2 problems × 2 runs, every run solved with a path validated
/// continuously, the cloud's row in kpi.md for each problem and its steps in each log.
fn check_folder(dir: &Path) {
    let journal = std::fs::read_to_string(dir.join("runs.jsonl")).unwrap();
    let runs: Vec<serde_json::Value> = journal
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(runs.len(), 4, "{journal}");
    for run in &runs {
        let validation = &run["validation"];
        assert_eq!(validation["valid"], true, "{run}");
        assert_eq!(validation["method"]["kind"], "continuous-arm", "{run}");
    }
    let kpi = std::fs::read_to_string(dir.join("kpi.md")).unwrap();
    assert!(kpi.contains("## Point clouds"), "{kpi}");
    for id in ["table_pick_panda-n7-i1", "table_pick_panda-n7-i2"] {
        // table_pick's scenes: 500 points on each primitive, before the crop.
        let row = kpi
            .lines()
            .find(|l| l.starts_with(&format!("| {id} |")) && l.contains(" | 2.5 | "))
            .unwrap_or_else(|| panic!("no cloud row for {id} in {kpi}"));
        let cells: Vec<&str> = row.split('|').map(str::trim).collect();
        let read: usize = cells[2].parse().unwrap();
        let kept: usize = cells[3].parse().unwrap();
        assert!(read > 0 && read.is_multiple_of(500), "{row}");
        assert!(kept > 0 && kept <= read, "{row}");
        let times: Vec<f64> = cells[5..7].iter().map(|c| c.parse().unwrap()).collect();
        assert!(times.iter().all(|&t| t > 0.0), "{row}");
        let log = std::fs::read_to_string(dir.join("logs").join(format!("{id}.log"))).unwrap();
        assert!(log.contains("point cloud: "), "{log}");
        assert!(log.contains("cloud: crop to the robot's reach"), "{log}");
        assert!(log.contains("clouds = [{ points = "), "{log}");
    }
}

#[test]
fn bench_plans_among_a_scene_as_cloud_and_validates_every_path() {
    let dir = scratch("cloud-bench", "flags");
    let (code, stdout, stderr) = run(&bench_args(&dir, &[]));
    assert_eq!(code, 0, "{stdout}{stderr}");
    // Prepared once per problem, before the runs: one line each.
    assert_eq!(
        stderr.matches("cloud: `table_pick_panda-n7-i").count(),
        2,
        "{stderr}"
    );
    assert!(stdout.contains("Independent audit of 4 paths"), "{stdout}");
    check_folder(&dir);
    let recorded = std::fs::read_to_string(dir.join("experiment.toml")).unwrap();
    assert!(
        recorded.contains("[problems.cloud]") && recorded.contains("scene_as_cloud = 500"),
        "{recorded}"
    );
    // Run again, the same options: resumed, nothing to add.
    let (code, stdout, stderr) = run(&bench_args(&dir, &[]));
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(stderr.contains("4 already recorded"), "{stderr}");
    // A changed cloud option is another experiment: refused, the change named.
    let (code, _, stderr) = run(&bench_args(&dir, &["--voxel", "0.02"]));
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("voxel = 0.02"), "{stderr}");
    let (code, _, stderr) = run(&bench_args(&dir, &["--cloud-seed", "9"]));
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("seed = 9"), "{stderr}");
}

#[test]
fn an_experiment_file_takes_a_cloud_table() {
    let dir = scratch("cloud-bench", "file");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("clouds.toml");
    std::fs::write(
        &file,
        format!(
            "name = \"clouds\"\nruns = 2\nplanners = [\"rrt-connect\"]\n\n[[problems]]\n\
             name = \"mbm:{}\"\ntime = 2\ninstance_seeds = [1, 2]\n\n[problems.cloud]\n\
             scene_as_cloud = 500\ncrop_reach = true\n",
            table_pick()
        ),
    )
    .unwrap();
    let output = dir.join("results");
    let args: Vec<String> = [
        "bench",
        file.to_str().unwrap(),
        "--threads",
        "1",
        "--no-plots",
        "--quiet",
        "--output",
        output.to_str().unwrap(),
    ]
    .iter()
    .map(|s| (*s).to_owned())
    .collect();
    let (code, stdout, stderr) = run(&args);
    assert_eq!(code, 0, "{stdout}{stderr}");
    check_folder(&output);
    // The folder's experiment.toml is an experiment file again: it resumes the folder.
    let again: Vec<String> = [
        "bench",
        output.join("experiment.toml").to_str().unwrap(),
        "--quiet",
        "--no-plots",
        "--output",
        output.to_str().unwrap(),
    ]
    .iter()
    .map(|s| (*s).to_owned())
    .collect();
    let (code, stdout, stderr) = run(&again);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(stderr.contains("4 already recorded"), "{stderr}");
}

#[test]
fn a_cloud_file_changed_under_its_name_is_never_resumed() {
    // Before contents were recorded, the folder's experiment.toml named the file only, and a
    // re-run after the file changed resumed the old folder: runs among two different clouds.
    let dir = scratch("cloud-bench", "changed");
    std::fs::create_dir_all(&dir).unwrap();
    let cloud = dir.join("scan.ply");
    let ply = |points: &[[f64; 3]]| {
        let mut text = format!(
            "ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\n\
             property float z\nend_header\n",
            points.len()
        );
        for p in points {
            text.push_str(&format!("{} {} {}\n", p[0], p[1], p[2]));
        }
        text
    };
    // Points far behind the robot: they change nothing but the file.
    std::fs::write(&cloud, ply(&[[-2.0, 0.0, 0.5], [-2.0, 0.1, 0.5]])).unwrap();
    let output = dir.join("results");
    let args = |extra: &[&str]| -> Vec<String> {
        let mut a: Vec<String> = [
            "bench",
            "--planners",
            "rrt-connect",
            "--problem",
            &format!("mbm:{}", table_pick()),
            "--instances",
            "1",
            "--time",
            "2",
            "--runs",
            "1",
            "--threads",
            "1",
            "--no-plots",
            "--quiet",
            "--output",
            output.to_str().unwrap(),
        ]
        .iter()
        .map(|s| (*s).to_owned())
        .collect();
        a.extend(extra.iter().map(|s| (*s).to_owned()));
        a
    };
    let with_cloud = ["--cloud", cloud.to_str().unwrap()];
    let (code, stdout, stderr) = run(&args(&with_cloud));
    assert_eq!(code, 0, "{stdout}{stderr}");
    let recorded = std::fs::read_to_string(output.join("experiment.toml")).unwrap();
    let length = std::fs::metadata(&cloud).unwrap().len();
    assert!(
        recorded.contains(&format!("contents = [\"{length} bytes, crc32 ")),
        "{recorded}"
    );
    // The same flags, the same file: resumed.
    let (code, _, stderr) = run(&args(&with_cloud));
    assert_eq!(code, 0, "{stderr}");
    assert!(stderr.contains("1 already recorded"), "{stderr}");
    // The file changes under its name: another experiment, refused with the line named.
    std::fs::write(&cloud, ply(&[[-2.0, 0.0, 0.5], [-2.0, 0.2, 0.5]])).unwrap();
    let (code, _, stderr) = run(&args(&with_cloud));
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("contents = ["), "{stderr}");
    // Resumed from the folder's own experiment.toml: the file is checked against it.
    let again: Vec<String> = [
        "bench",
        output.join("experiment.toml").to_str().unwrap(),
        "--quiet",
        "--no-plots",
        "--output",
        output.to_str().unwrap(),
    ]
    .iter()
    .map(|s| (*s).to_owned())
    .collect();
    let (code, _, stderr) = run(&again);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("`cloud.contents`") && stderr.contains("changed since the experiment"),
        "{stderr}"
    );
    assert!(stderr.contains("scan.ply"), "{stderr}");
}

/// An experiment file holding one problem entry `entry` (TOML lines) in a fresh folder.
fn experiment_file(name: &str, entry: &str) -> PathBuf {
    let dir = scratch("cloud-bench", name);
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join(format!("{name}.toml"));
    std::fs::write(
        &file,
        format!("planners = [\"rrt-connect\"]\nruns = 1\n\n[[problems]]\n{entry}"),
    )
    .unwrap();
    file
}

#[test]
fn bad_cloud_settings_are_refused_by_entry_and_option_before_any_run() {
    let bench_file = |file: &Path| {
        let output = file.with_extension("out");
        refused_with(&[
            "bench",
            file.to_str().unwrap(),
            "--output",
            output.to_str().unwrap(),
        ])
    };
    // A cloud on a box world, in a file and on the command line.
    let file = experiment_file(
        "box-world",
        "name = \"dividing-walls\"\ndimensions = [2]\ntime = 0.1\n[problems.cloud]\nscene_as_cloud = 100\n",
    );
    let stderr = bench_file(&file);
    assert!(
        stderr.contains("`problems[0].cloud`") && stderr.contains("arm problems"),
        "{stderr}"
    );
    refused(
        &[
            "bench",
            "--problem",
            "dividing-walls",
            "--dim",
            "2",
            "--time",
            "0.1",
            "--voxel",
            "0.02",
        ],
        &[
            "`dividing-walls`",
            "`cloud.voxel` (--voxel)",
            "arm problems",
        ],
    );
    // A missing cloud file, relative to the experiment file.
    let file = experiment_file(
        "missing-file",
        &format!(
            "name = \"mbm:{}\"\ntime = 0.1\ninstance_seeds = [1]\n[problems.cloud]\nfiles = [\"no-such-scan.ply\"]\n",
            table_pick()
        ),
    );
    let stderr = bench_file(&file);
    assert!(
        stderr.contains("`table_pick_panda` (problems[0])")
            && stderr.contains("`cloud.files` (--cloud)")
            && stderr.contains("no-such-scan.ply"),
        "{stderr}"
    );
    // A cloud the filters empty: the robot's reach holds none of these points.
    let far = file.with_file_name("far.ply");
    std::fs::write(
        &far,
        "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n\
         property float z\nend_header\n30 0 0\n30 0.1 0\n",
    )
    .unwrap();
    let file = experiment_file(
        "emptied",
        &format!(
            "name = \"mbm:{}\"\ntime = 0.1\ninstance_seeds = [1]\n[problems.cloud]\nfiles = [\"{}\"]\ncrop_reach = true\n",
            table_pick(),
            far.display()
        ),
    );
    let stderr = bench_file(&file);
    assert!(
        stderr.contains("`table_pick_panda` #1 (problems[0])")
            && stderr.contains("`cloud.crop_reach` (--crop-reach) leaves none of the 2 points"),
        "{stderr}"
    );
    // An unknown key in the table is named.
    let file = experiment_file(
        "unknown-key",
        &format!(
            "name = \"mbm:{}\"\ntime = 0.1\ninstance_seeds = [1]\n[problems.cloud]\nscene_as_cloud = 10\nvoxle = 0.02\n",
            table_pick()
        ),
    );
    assert!(bench_file(&file).contains("voxle"));
}

/// Runs a command that must be refused (exit 2) before any run; returns its stderr.
fn refused_with(args: &[&str]) -> String {
    let out = common::mit_star(args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(!stderr.contains("runs;"), "a run was scheduled: {stderr}");
    stderr
}

#[test]
fn replan_runs_among_a_static_cloud_and_audits_the_motion() {
    let out = scratch("cloud-replan", "horizontal");
    let stdout = common::succeeded(&[
        "replan",
        "--scenes",
        "horizontal",
        "--planners",
        "rrt-connect",
        "--trials",
        "1",
        "--legs",
        "2",
        "--iterations",
        "150",
        "--scene-as-cloud",
        "500",
        "--crop-reach",
        "--no-picture",
        "--output",
        out.to_str().unwrap(),
    ]);
    assert!(
        stdout.contains("| horizontal | RRT-Connect | 1/1 = 100.0 ["),
        "{stdout}"
    );
    assert!(
        stdout.contains(
            "horizontal: Executed motion audited against the fixed obstacles and the cloud"
        ) && stdout.contains("0 not proven clear"),
        "{stdout}"
    );
    // A cloud on the arm at the start is refused before any trial, named.
    let on_arm = out.join("on-arm.ply");
    std::fs::write(
        &on_arm,
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n\
         property float z\nend_header\n0 0 0.1\n",
    )
    .unwrap();
    refused(
        &[
            "replan",
            "--scenes",
            "horizontal",
            "--trials",
            "1",
            "--cloud",
            on_arm.to_str().unwrap(),
        ],
        &["cloud point"],
    );
}
