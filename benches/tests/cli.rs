//! The `mit-star` binary: input errors are reported with a clear message and a non-zero exit
//! code before any work; the listings and `plan` work.

use std::path::{Path, PathBuf};

use crate::common;
use common::{refused, succeeded};

/// An empty scratch path for this test file.
fn scratch(name: &str) -> PathBuf {
    common::scratch("cli", name)
}

#[test]
fn unknown_names_list_the_valid_ones() {
    refused(
        &[
            "bench",
            "--planners",
            "mit-star,rrt-star",
            "--problem",
            "dividing-walls",
            "--dim",
            "2",
            "--time",
            "0.02",
        ],
        &[
            "unknown planner `rrt-star`",
            "mit-star, eit-star, mit-star-as, mit-star-eis, mit-star-sc",
        ],
    );
    refused(
        &[
            "bench",
            "--problem",
            "dividing-wall",
            "--dim",
            "2",
            "--time",
            "0.02",
        ],
        &[
            "unknown problem `dividing-wall`",
            "flanking-gap, dividing-walls, goal-enclosure",
        ],
    );
    refused(
        &["bench", "--experiment", "paper"],
        &[
            "unknown experiment `paper`",
            "paper-table, ablation, ablation-study, smoke",
        ],
    );
    refused(
        &["plan", "--planner", "prm", "--problem", "dividing-walls"],
        &["unknown planner `prm`"],
    );
}

#[test]
fn bad_values_are_refused_before_any_work() {
    let out = scratch("never-written");
    let o = out.to_str().unwrap();
    refused(
        &[
            "bench",
            "--problem",
            "dividing-walls",
            "--dim",
            "1",
            "--time",
            "0.02",
            "-o",
            o,
        ],
        &["dividing-walls", "1"],
    );
    refused(
        &[
            "bench",
            "--problem",
            "dividing-walls",
            "--dim",
            "2",
            "--time",
            "0.02",
            "--set",
            "batch_size=0",
            "-o",
            o,
        ],
        &["parameter `batch_size`"],
    );
    refused(
        &[
            "bench",
            "--problem",
            "dividing-walls",
            "--dim",
            "2",
            "--time",
            "0.02",
            "--set",
            "bach_size=3",
            "-o",
            o,
        ],
        &["parameter `bach_size`: unknown parameter"],
    );
    refused(
        &[
            "bench",
            "--problem",
            "dividing-walls",
            "--dim",
            "2",
            "--time",
            "-1",
            "-o",
            o,
        ],
        &["-1"],
    );
    refused(
        &[
            "bench",
            "--problem",
            "dividing-walls",
            "--dims",
            "2,4",
            "--time",
            "1,2,3",
            "-o",
            o,
        ],
        &["3 values for 2 dimensions"],
    );
    refused(
        &[
            "bench",
            "--problem",
            "dividing-walls",
            "--dim",
            "2",
            "-o",
            o,
        ],
        &["--time"],
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
            "--runs",
            "0",
            "-o",
            o,
        ],
        &["`runs`"],
    );
    refused(
        &["bench", "--experiment", "smoke", "--dim", "2"],
        &["cannot be combined"],
    );
    refused(
        &["plan", "--problem", "dividing-walls", "--time", "0"],
        &["--time: 0 is not a usable time budget"],
    );
    assert!(
        !out.exists(),
        "nothing may be written when the input is refused"
    );
}

#[test]
fn malformed_experiment_files_name_the_field() {
    let dir = scratch("files");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("bad.toml");
    std::fs::write(
        &file,
        "planners = ['mit-star']\n[[problems]]\nname = 'flanking-gap'\ndimensions = [4, 8]\ntime = [0.1, 0.2, 0.3]\n",
    )
    .unwrap();
    refused(
        &["bench", file.to_str().unwrap()],
        &["`problems[0].time`", "3 budgets for 2 dimensions"],
    );
    std::fs::write(&file, "planners = ['mit-star']\nrunz = 3\n").unwrap();
    refused(
        &["bench", file.to_str().unwrap()],
        &["unknown field `runz`"],
    );
}

#[test]
fn unwritable_output_folders_are_refused() {
    let dir = scratch("blocked");
    std::fs::create_dir_all(&dir).unwrap();
    let blocker = dir.join("a-file");
    std::fs::write(&blocker, "not a folder").unwrap();
    let inside = blocker.join("results");
    refused(
        &[
            "bench",
            "--problem",
            "dividing-walls",
            "--dim",
            "2",
            "--time",
            "0.02",
            "--runs",
            "1",
            "-o",
            inside.to_str().unwrap(),
        ],
        &["is not writable"],
    );
}

#[test]
fn spherise_refuses_an_output_it_cannot_write_before_covering_meshes() {
    let urdf = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robot/data/ur5/meshes/ur5.urdf");
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robot/data/ur5");
    let missing = scratch("spherise-missing").join("ur5_mesh_spherized.urdf");
    let folder = scratch("spherise-folder");
    std::fs::create_dir_all(&folder).unwrap();
    for (output, needles) in [
        (&missing, &["does not exist", "spherise-missing"][..]),
        (&folder, &["is a folder"][..]),
    ] {
        // The early refusal's own words: a write after the cover (over a minute for the UR5)
        // would fail with the system's message instead.
        refused(
            &[
                "spherise",
                urdf.to_str().unwrap(),
                "--package-root",
                root.to_str().unwrap(),
                "--output",
                output.to_str().unwrap(),
            ],
            needles,
        );
    }
}

#[test]
fn listings() {
    let text = succeeded(&["problems", "--dim", "4"]);
    for name in [
        "flanking-gap",
        "dividing-walls",
        "goal-enclosure",
        "random-rectangles",
        "repeating-rectangles",
    ] {
        assert!(text.contains(name), "{name}");
    }
    assert!(text.contains("wall_width"));
    let text = succeeded(&["planners"]);
    assert!(text.contains("mit-star-eis") && text.contains("batch_size"));
    // Each parameter names the planners that read it.
    let line = |name: &str| {
        text.lines()
            .find(|l| l.trim_start().starts_with(&format!("{name} ")))
            .unwrap_or_else(|| panic!("no line for {name}"))
            .to_owned()
    };
    assert!(
        line("rrt_balance").ends_with("rrt-connect, aorrtc"),
        "{}",
        line("rrt_balance")
    );
    assert!(line("batch_size").ends_with("the EIT* family"));
    assert!(line("seed").ends_with("every planner"));
    assert!(line("eis_expansion_rule").ends_with("mit-star, mit-star-eis"));
    assert!(succeeded(&["experiments", "--print", "smoke"]).contains("[[problems]]"));
}

#[test]
fn problems_write_prints_the_exact_problem_as_a_file_plan_reads() {
    let text = succeeded(&[
        "problems",
        "--write",
        "random-rectangles",
        "--dim",
        "4",
        "--instance",
        "2",
    ]);
    let built = mit_star_problems::builtin("random-rectangles", 4, 2).unwrap();
    assert_eq!(
        mit_star_problems::Problem::from_toml_str(&text).unwrap(),
        built
    );
    let dir = scratch("problems-write");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("rr4-2.toml");
    std::fs::write(&file, &text).unwrap();
    let stdout = succeeded(&[
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        file.to_str().unwrap(),
        "--time",
        "1",
        "--output",
        dir.to_str().unwrap(),
    ]);
    assert!(stdout.contains("solved; path validated"), "{stdout}");
    refused(
        &["problems", "--write", "dividing-wall", "--dim", "4"],
        &["dividing-wall", "unknown problem"],
    );
}

#[test]
fn plan_refuses_a_parameter_its_planner_does_not_read() {
    // Before, `--set range=0.5` on MIT* (which takes no range) was accepted and ignored.
    refused(
        &[
            "plan",
            "--problem",
            "wall-gap",
            "--time",
            "0.01",
            "--no-picture",
            "--set",
            "range=0.5",
        ],
        &[
            "MIT* does not read the parameter `range`",
            "RRT-Connect, AORRTC, Informed RRT*",
        ],
    );
    refused(
        &[
            "plan",
            "--planner",
            "rrt-connect",
            "--problem",
            "wall-gap",
            "--time",
            "0.01",
            "--no-picture",
            "--set",
            "batch_size=10",
        ],
        &["RRT-Connect does not read the parameter `batch_size`"],
    );
    // A parameter the planner reads is taken.
    let stdout = succeeded(&[
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        "wall-gap",
        "--time",
        "0.05",
        "--no-picture",
        "--set",
        "range=0.5",
    ]);
    assert!(stdout.contains("RRT-Connect on wall-gap"), "{stdout}");
}

#[test]
fn plan_prints_the_result_and_draws_2d_runs() {
    let dir = scratch("plan");
    let stdout = succeeded(&[
        "plan",
        "--planner",
        "eit-star",
        "--problem",
        "goal-enclosure",
        "--time",
        "0.05",
        "--seed",
        "3",
        "-o",
        dir.to_str().unwrap(),
    ]);
    assert!(
        stdout.contains("EIT* on goal-enclosure R^2 (seed 3, budget 0.05 s)"),
        "{stdout}"
    );
    assert!(stdout.contains("counters (zeros left out") && stdout.contains("validity_checks"));
    // The independent check's time is shown apart from planning, and what it covered in a
    // box world's units: segments and the path's states.
    assert!(stdout.contains("apart from planning)"), "{stdout}");
    let verdict = stdout.lines().find(|l| l.contains("validated")).unwrap();
    assert!(
        verdict.contains(" segments, ") && verdict.contains(" path states, "),
        "{verdict}"
    );
    // Named by instance, planner, seed and a tag of the other settings (here `--time 0.05`).
    let pictures = |dir: &std::path::Path| -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    };
    let names = pictures(&dir);
    assert_eq!(names.len(), 2, "{names:?}");
    for (name, ext) in names.iter().zip(["png", "svg"]) {
        let tag = name
            .strip_prefix("goal-enclosure-n2-eit-star-seed3-s")
            .and_then(|t| t.strip_suffix(&format!(".{ext}")))
            .unwrap_or_else(|| panic!("{name}"));
        assert!(
            tag.len() == 8 && tag.chars().all(|c| c.is_ascii_hexdigit()),
            "{name}"
        );
        assert!(
            std::fs::metadata(dir.join(name)).unwrap().len() > 5_000,
            "{name}"
        );
    }
    // Another setting, another pair of files; the same settings again replace theirs, saying so.
    // (Before, every run of a problem, planner and seed wrote the same two files, silently.)
    let again = |extra: &[&str]| {
        let mut args = vec![
            "plan",
            "--planner",
            "eit-star",
            "--problem",
            "goal-enclosure",
            "--time",
            "0.05",
            "--seed",
            "3",
            "-o",
        ];
        args.push(dir.to_str().unwrap());
        args.extend_from_slice(extra);
        succeeded(&args)
    };
    let stdout = again(&["--set", "batch_size=50"]);
    assert!(!stdout.contains("replaced"), "{stdout}");
    assert_eq!(pictures(&dir).len(), 4);
    let stdout = again(&[]);
    assert!(stdout.contains("(replaced "), "{stdout}");
    assert_eq!(pictures(&dir).len(), 4);
    // JSON output, and no picture in 4-D.
    let stdout = succeeded(&[
        "plan",
        "--problem",
        "obstacle-free",
        "--dim",
        "4",
        "--time",
        "0.02",
        "--json",
        "-o",
        dir.join("4d").to_str().unwrap(),
    ]);
    let value: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(value["status"], "solved");
    assert!(value["files"].as_array().unwrap().is_empty());
    assert!(!dir.join("4d").exists());
}

#[test]
fn plan_simplifies_and_revalidates_on_request() {
    let dir = scratch("plan-simplify");
    let stdout = succeeded(&[
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        "dividing-walls",
        "--dim",
        "4",
        "--time",
        "0.5",
        "--simplify",
        "--json",
        "-o",
        dir.to_str().unwrap(),
    ]);
    let value: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let simplified = &value["simplified"];
    assert_eq!(simplified["valid"], true, "{simplified}");
    let (before, after) = (
        simplified["original_cost"].as_f64().unwrap(),
        simplified["cost"].as_f64().unwrap(),
    );
    assert!(after < before, "{before} -> {after}");
    // A simplification time no clock holds is refused before planning.
    let out = common::mit_star(&[
        "plan",
        "--problem",
        "dividing-walls",
        "--simplify",
        "--simplify-time",
        "-1",
    ]);
    assert!(!out.status.success());
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("--simplify-time"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn check_path_judges_a_path_from_a_file() {
    let dir = scratch("check-path");
    std::fs::create_dir_all(&dir).unwrap();
    let stdout = succeeded(&[
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        "dividing-walls",
        "--time",
        "0.5",
        "--json",
        "--no-picture",
    ]);
    let value: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let rows: Vec<String> = value["path"]
        .as_array()
        .unwrap()
        .iter()
        .map(|state| {
            let xs: Vec<String> = state
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.to_string())
                .collect();
            xs.join(" ")
        })
        .collect();
    let (first, last) = (rows[0].clone(), rows[rows.len() - 1].clone());
    let file = dir.join("paths.txt");
    // The planner's path, then the straight line through the walls.
    std::fs::write(
        &file,
        format!("# from plan\n{}\n\n{first}\n{last}\n", rows.join("\n")),
    )
    .unwrap();
    let out = common::mit_star(&[
        "check-path",
        "--problem",
        "dividing-walls",
        "--path",
        file.to_str().unwrap(),
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(3), "{text}");
    assert!(
        text.contains("path 1:") && text.contains("path 2:"),
        "{text}"
    );
    let lines: Vec<&str> = text.lines().collect();
    assert!(
        lines[1].contains("certification): valid; independent check: valid"),
        "{text}"
    );
    assert!(lines[2].contains("1 of 1 edges fail"), "{text}");
    // Only the planner's path: success.
    std::fs::write(&file, rows.join("\n")).unwrap();
    succeeded(&[
        "check-path",
        "--problem",
        "dividing-walls",
        "--path",
        file.to_str().unwrap(),
    ]);
    // Not numbers: refused, naming the line.
    std::fs::write(&file, "0.1 0.5\n0.2 x\n").unwrap();
    refused(
        &[
            "check-path",
            "--problem",
            "dividing-walls",
            "--path",
            file.to_str().unwrap(),
        ],
        &["line 2"],
    );
}

#[test]
fn bench_with_flags_writes_a_results_folder() {
    let dir = scratch("bench");
    let stdout = succeeded(&[
        "bench",
        "--planners",
        "mit-star,eit-star",
        "--problem",
        "dividing-walls",
        "--dim",
        "2",
        "--runs",
        "2",
        "--time",
        "0.02",
        "--threads",
        "2",
        "--no-plots",
        "-q",
        "-o",
        dir.to_str().unwrap(),
    ]);
    assert!(stdout.contains("| dividing-walls R^2 |"), "{stdout}");
    assert!(stdout.contains("t_init gain"));
    for f in [
        "runs.csv",
        "runs.jsonl",
        "benchmark.db",
        "kpi.md",
        "experiment.toml",
        "logs/dividing-walls-n2.log",
    ] {
        assert!(dir.join(f).exists(), "{f}");
    }
}

#[test]
fn only_runs_some_planners_of_an_experiment_to_their_first_solution() {
    refused(
        &["bench", "--experiment", "ablation", "--only", "rrt-star"],
        &["--only rrt-star", "mit-star-sc (MIT*-SC)"],
    );
    let dir = scratch("only");
    succeeded(&[
        "bench",
        "--experiment",
        "ablation",
        "--only",
        "mit-star,EIT*",
        "--first-solution",
        "--runs",
        "2",
        "--no-plots",
        "-q",
        "-o",
        dir.to_str().unwrap(),
    ]);
    let recorded = std::fs::read_to_string(dir.join("experiment.toml")).unwrap();
    assert!(recorded.contains("first_solution = true"), "{recorded}");
    let csv = std::fs::read_to_string(dir.join("runs.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    // Two planners × two problems × two runs, none of them another planner.
    assert_eq!(rows.len(), 8, "{csv}");
    assert!(
        rows.iter()
            .all(|r| r.contains(",MIT*,") || r.contains(",EIT*,"))
    );
    let header = csv.lines().next().unwrap();
    for column in [
        "sampler_gaussian",
        "estimate_initial",
        "full_points_by_length_2",
    ] {
        assert!(header.contains(column), "{column} not in {header}");
    }
}

#[test]
fn plan_keeps_a_problem_files_allow_coarse_step() {
    let dir = scratch("coarse-file");
    std::fs::create_dir_all(&dir).unwrap();
    let text = succeeded(&["problems", "--write", "dividing-walls", "--dim", "2"]);
    // A step of 0.2 (a fifth of the extent) is coarser than the 0.03-wide gaps.
    let coarse = text.replace("resolution = 5e-6", "resolution = 0.2");
    let refused_file = dir.join("coarse.toml");
    std::fs::write(&refused_file, &coarse).unwrap();
    let args = |file: &std::path::Path| {
        [
            "plan",
            "--planner",
            "rrt-connect",
            "--problem",
            file.to_str().unwrap(),
            "--time",
            "0.2",
            "--output",
            dir.to_str().unwrap(),
        ]
        .map(str::to_owned)
    };
    let plan =
        |file: &std::path::Path| common::mit_star(&args(file).each_ref().map(String::as_str));
    let out = plan(&refused_file);
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    assert!(String::from_utf8_lossy(&out.stderr).contains("allow_coarse_step"));
    // The file says yes: the flag's absence does not overwrite it.
    let allowed_file = dir.join("allowed.toml");
    std::fs::write(&allowed_file, format!("allow_coarse_step = true\n{coarse}")).unwrap();
    let out = plan(&allowed_file);
    assert!(
        out.status.code().is_some_and(|c| c == 0 || c == 3),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
#[cfg(unix)]
fn a_signal_while_reading_a_fifo_leaves_at_once() {
    use std::os::unix::process::ExitStatusExt;
    use std::process::Command;
    use std::time::{Duration, Instant};
    let dir = scratch("fifo");
    std::fs::create_dir_all(&dir).unwrap();
    let fifo = dir.join("problem.toml");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    let mut child = Command::new(env!("CARGO_BIN_EXE_mit-star"))
        .args(["plan", "--problem", fifo.to_str().unwrap(), "--time", "1"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Let it block in the read (nobody writes the FIFO), then send SIGTERM.
    common::wait_for_sigterm_handler(child.id());
    std::thread::sleep(Duration::from_millis(500));
    let term = Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(term.success());
    let sent = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if sent.elapsed() > Duration::from_secs(20) {
            child.kill().unwrap();
            panic!("still blocked 20 s after SIGTERM");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    assert_eq!(
        status.code().or(status.signal()),
        Some(128 + 15),
        "{status:?}"
    );
}

#[test]
fn an_arm_without_certification_is_refused_unless_allowed() {
    let folder = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../robot/tests/data/mbm/box_panda"
    );
    let problem = format!("mbm:{folder}");
    let dir = scratch("uncertified");
    let plan = [
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        problem.as_str(),
        "--time",
        "1",
        "--set",
        "certification=1",
        "--output",
        dir.to_str().unwrap(),
    ];
    let out = common::mit_star(&plan);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{stderr}");
    for needle in ["certification = 1", "grid points", "--allow-coarse-step"] {
        assert!(stderr.contains(needle), "`{needle}` not in {stderr}");
    }
    let mut allowed = plan.to_vec();
    allowed.push("--allow-coarse-step");
    let stdout = succeeded(&allowed);
    assert!(
        stdout.contains("validated independently, continuously"),
        "{stdout}"
    );
    // Certification on (the default): any step is certified, however coarse.
    let coarse = [
        "plan",
        "--planner",
        "rrt-connect",
        "--problem",
        problem.as_str(),
        "--time",
        "1",
        "--resolution",
        "0.5",
        "--output",
        dir.to_str().unwrap(),
    ];
    let stdout = succeeded(&coarse);
    assert!(
        stdout.contains("validated independently, continuously"),
        "{stdout}"
    );
    // An arm's audit counts configurations (named once, in the method) and segments: no
    // second count of "states" that means something else than a box world's.
    let verdict = stdout.lines().find(|l| l.contains("validated")).unwrap();
    assert!(
        verdict.contains(" configurations, ") && !verdict.contains(" states"),
        "{verdict}"
    );
}

#[test]
fn check_state_names_what_a_configuration_touches() {
    let folder = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../robot/tests/data/mbm/box_panda"
    );
    let problem = format!("mbm:{folder}");
    // The problem's own start and goal: valid, with their nearest obstacles.
    let stdout = succeeded(&["check-state", "--problem", problem.as_str()]);
    assert!(
        stdout.contains("start: valid") && stdout.contains("goal 1: valid"),
        "{stdout}"
    );
    assert!(stdout.contains("nearest obstacle:"), "{stdout}");
    // Joint 1 past its limit, the hand folded into link 5: both named, exit code 3.
    let out = common::mit_star(&[
        "check-state",
        "--problem",
        problem.as_str(),
        "--state",
        "3,0,0,0,0,0,0",
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(3), "{text}");
    for needle in [
        "INVALID",
        "joint panda_joint1 = 3 is outside its limits",
        "link panda_link5 meets link panda_hand",
    ] {
        assert!(text.contains(needle), "`{needle}` not in {text}");
    }
    // A state of the wrong length is a usage error naming the joint count.
    let out = common::mit_star(&[
        "check-state",
        "--problem",
        problem.as_str(),
        "--state",
        "1,2",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("7 joints"), "{stderr}");
}

#[test]
fn bench_shows_the_independent_audits_time_apart_from_planning() {
    let dir = scratch("audit-time");
    let stdout = succeeded(&[
        "bench",
        "--planners",
        "eit-star",
        "--problem",
        "obstacle-free",
        "--dim",
        "2",
        "--runs",
        "2",
        "--time",
        "0.02",
        "--no-plots",
        "-o",
        dir.to_str().unwrap(),
    ]);
    assert!(
        stdout.contains("Independent audit of 2 paths:") && stdout.contains("x the planning time"),
        "{stdout}"
    );
    // Each run's record carries its audit time.
    let jsonl = std::fs::read_to_string(dir.join("runs.jsonl")).unwrap();
    for line in jsonl.lines() {
        let run: serde_json::Value = serde_json::from_str(line).unwrap();
        let seconds = run["validation"]["seconds"].as_f64().unwrap();
        assert!(seconds > 0.0 && seconds < 60.0, "{line}");
    }
}
