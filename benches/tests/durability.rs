//! Durable results, at the level of the `mit-star` binary: every finished run is on disk when a
//! signal arrives; SIGTERM and SIGINT exit 143 and 130 after writing; a second `bench` resumes
//! or is refused instead of overwriting; headers and `runcount` tell the recorded truth;
//! recorded errors exit 1; nothing is written outside the output folder.

use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

use mit_star_benches::BenchmarkLog;

fn binary() -> Command {
    Command::new(env!("CARGO_BIN_EXE_mit-star"))
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mit-star-dur-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// `bench` arguments: 2 planners × `runs` runs of 0.15 s on dividing walls in R², one thread.
fn bench_args(output: &Path, runs: usize) -> Vec<String> {
    let runs = runs.to_string();
    [
        "bench",
        "--planners",
        "mit-star,eit-star",
        "--problem",
        "dividing-walls",
        "--dims",
        "2",
        "--runs",
        &runs,
        "--time",
        "0.15",
        "--threads",
        "1",
        "--no-plots",
        "-q",
        "--output",
    ]
    .iter()
    .map(|s| (*s).to_owned())
    .chain([output.display().to_string()])
    .collect()
}

fn text(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_default()
}

fn lines(path: &Path) -> usize {
    text(path).lines().count()
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// Starts a 20-run bench into `output`, waits until `runs` runs are on disk.
fn start(output: &Path, runs: usize) -> Child {
    let child = binary()
        .args(bench_args(output, 20))
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let jsonl = output.join("runs.jsonl");
    let deadline = Instant::now() + Duration::from_secs(120);
    while lines(&jsonl) < runs {
        assert!(Instant::now() < deadline, "no runs written");
        std::thread::sleep(Duration::from_millis(20));
    }
    child
}

/// Sends `signal` (`TERM`, `INT`) to `child` and waits for it.
fn signal(child: Child, signal: &str) -> Output {
    let kill = Command::new("kill")
        .args([&format!("-{signal}"), &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    child.wait_with_output().unwrap()
}

/// The database's experiment rows (`runcount` each) and its runs per planner name.
fn database(output: &Path) -> (Vec<i64>, HashMap<String, i64>) {
    let c = rusqlite::Connection::open(output.join("benchmark.db")).unwrap();
    let counts = c
        .prepare("SELECT runcount FROM experiments")
        .unwrap()
        .query_map([], |r| r.get(0))
        .unwrap()
        .collect::<Result<Vec<i64>, _>>()
        .unwrap();
    let runs = c
        .prepare(
            "SELECT p.name, count(*) FROM runs r JOIN plannerConfigs p ON r.plannerid = p.id \
             GROUP BY p.name",
        )
        .unwrap()
        .query_map([], |r| Ok((r.get(0)?, r.get(1)?)))
        .unwrap()
        .collect::<Result<HashMap<String, i64>, _>>()
        .unwrap();
    (counts, runs)
}

/// The runs of `runs.jsonl` per planner, checking that no run appears twice and that
/// `runs.csv` has exactly the same runs, one line each.
fn recorded_runs(output: &Path) -> HashMap<String, i64> {
    let mut keys = HashSet::new();
    let mut per_planner = HashMap::new();
    for line in text(&output.join("runs.jsonl")).lines() {
        let v: serde_json::Value = serde_json::from_str(line).unwrap();
        let key = (v["planner"].to_string(), v["run"].as_u64().unwrap());
        assert!(keys.insert(key.clone()), "{key:?} recorded twice");
        *per_planner
            .entry(v["planner"].as_str().unwrap().to_owned())
            .or_insert(0) += 1;
    }
    let csv = text(&output.join("runs.csv"));
    let mut csv_keys = HashSet::new();
    for line in csv.lines().skip(1) {
        let fields: Vec<&str> = line.split(',').collect();
        csv_keys.insert((
            format!("{:?}", fields[6]),
            fields[8].parse::<u64>().unwrap(),
        ));
    }
    assert_eq!(csv_keys, keys, "runs.csv and runs.jsonl hold the same runs");
    assert_eq!(
        csv.lines().count(),
        keys.len() + 1,
        "header + one line per run"
    );
    per_planner
}

/// Checks the OMPL logs of `output` against its database with the independent Python reader
/// (as CI does), when `python3` is available.
fn python_agrees(output: &Path) {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tools/check_ompl_log.py");
    let Ok(out) = Command::new("python3").arg(&script).arg(output).output() else {
        eprintln!("python3 not found: skipping the independent reader");
        return;
    };
    assert!(
        out.status.success(),
        "{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        stderr(&out)
    );
}

/// The recorded truth everywhere: raw files, database rows and `runcount`, the log header.
fn consistent(output: &Path) -> i64 {
    let recorded = recorded_runs(output);
    let (counts, runs) = database(output);
    assert_eq!(
        runs, recorded,
        "the database holds exactly the recorded runs"
    );
    let most = recorded.values().copied().max().unwrap_or(0);
    assert_eq!(
        counts,
        [most],
        "one experiment row, runcount = recorded runs"
    );
    let log = BenchmarkLog::parse(&text(&output.join("logs/dividing-walls-n2.log"))).unwrap();
    assert_eq!(log.runs_per_planner, Some(most as usize), "the log header");
    let in_log: HashMap<String, i64> = log
        .planners
        .iter()
        .filter(|p| !p.runs.is_empty())
        .map(|p| (p.name.clone(), p.runs.len() as i64))
        .collect();
    assert_eq!(in_log, recorded, "the log holds exactly the recorded runs");
    python_agrees(output);
    recorded.values().sum()
}

#[test]
fn sigterm_and_sigint_keep_exactly_the_finished_runs_then_a_rerun_resumes() {
    for (name, code) in [("TERM", 143), ("INT", 130)] {
        let output = scratch(name);
        let out = signal(start(&output, 3), name);
        let message = stderr(&out);
        assert_eq!(out.status.code(), Some(code), "SIG{name}: {message}");
        let recorded = consistent(&output);
        assert!(recorded >= 3, "SIG{name}: {recorded} runs");
        assert!(recorded < 40, "SIG{name}: the bench was cut short");
        assert!(
            message.contains(&format!(
                "interrupted: {recorded} runs finished in this session"
            )),
            "SIG{name}: {message}"
        );
        let kpi = text(&output.join("kpi.md"));
        assert!(
            kpi.contains(&format!("{recorded} of 40 runs recorded")),
            "{kpi}"
        );
        assert!(kpi.contains("Interrupted (SIGINT or SIGTERM)"));

        // The same experiment again resumes: only the missing runs, appended.
        let jsonl_before = text(&output.join("runs.jsonl"));
        let csv_before = text(&output.join("runs.csv"));
        let out = binary().args(bench_args(&output, 20)).output().unwrap();
        assert!(out.status.success(), "{}", stderr(&out));
        assert!(stderr(&out).contains(&format!(
            "({recorded} already recorded in the folder: resuming)"
        )));
        assert!(text(&output.join("runs.jsonl")).starts_with(&jsonl_before));
        assert!(text(&output.join("runs.csv")).starts_with(&csv_before));
        assert_eq!(consistent(&output), 40);
        assert_eq!(database(&output).0, [20]);
        let kpi = text(&output.join("kpi.md"));
        assert!(kpi.contains("40 of 40 runs recorded") && !kpi.contains("Interrupted"));
        let _ = std::fs::remove_dir_all(&output);
    }
}

#[test]
fn a_second_bench_of_a_finished_experiment_overwrites_nothing() {
    let output = scratch("twice");
    let first = binary().args(bench_args(&output, 2)).output().unwrap();
    assert!(first.status.success(), "{}", stderr(&first));
    let files = ["experiment.toml", "runs.csv", "runs.jsonl"];
    let before: Vec<String> = files.iter().map(|f| text(&output.join(f))).collect();
    assert_eq!(consistent(&output), 4);
    let second = binary().args(bench_args(&output, 2)).output().unwrap();
    assert!(second.status.success(), "{}", stderr(&second));
    assert!(String::from_utf8_lossy(&second.stdout).contains("(0 runs added, 4 recorded)"));
    let after: Vec<String> = files.iter().map(|f| text(&output.join(f))).collect();
    assert_eq!(after, before, "raw files and experiment.toml untouched");
    assert_eq!(consistent(&output), 4);
    let _ = std::fs::remove_dir_all(&output);
}

#[test]
fn another_experiment_never_overwrites_a_folder() {
    let output = scratch("other");
    assert!(
        binary()
            .args(bench_args(&output, 2))
            .output()
            .unwrap()
            .status
            .success()
    );
    let files = [
        "experiment.toml",
        "runs.csv",
        "runs.jsonl",
        "kpi.md",
        "logs/dividing-walls-n2.log",
    ];
    let before: Vec<String> = files.iter().map(|f| text(&output.join(f))).collect();
    for change in [["--problem", "wall-gap"], ["--runs", "3"], ["--seed", "7"]] {
        let mut other = bench_args(&output, 2);
        let at = other
            .iter()
            .position(|a| a == change[0])
            .unwrap_or(other.len());
        if at == other.len() {
            other.extend(change.map(str::to_owned));
        } else {
            other[at + 1] = change[1].to_owned();
        }
        let out = binary().args(&other).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{change:?}");
        assert!(
            stderr(&out).contains("holds the results of experiment"),
            "{change:?}"
        );
    }
    let after: Vec<String> = files.iter().map(|f| text(&output.join(f))).collect();
    assert_eq!(after, before);
    let _ = std::fs::remove_dir_all(&output);
}

#[test]
fn recorded_errors_exit_1_after_writing_everything() {
    let output = scratch("errors");
    assert!(
        binary()
            .args(bench_args(&output, 2))
            .output()
            .unwrap()
            .status
            .success()
    );
    // Make the first recorded run an error (as a planner panic records it), and drop runs.csv:
    // the next bench rebuilds its rows from runs.jsonl.
    let jsonl = output.join("runs.jsonl");
    let mut runs: Vec<serde_json::Value> = text(&jsonl)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    runs[0]["status"] = "error".into();
    runs[0]["error"] = "the planner panicked: injected\nsecond line".into();
    let edited: String = runs.iter().map(|r| format!("{r}\n")).collect();
    std::fs::write(&jsonl, edited).unwrap();
    std::fs::remove_file(output.join("runs.csv")).unwrap();

    let out = binary().args(bench_args(&output, 2)).output().unwrap();
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("ERROR: 1 of 4 recorded runs ended in an error"),
        "{}",
        stderr(&out)
    );
    let csv = text(&output.join("runs.csv"));
    assert!(
        csv.contains(",error,false,") && csv.contains("injected second line"),
        "{csv}"
    );
    assert_eq!(consistent(&output), 4);
    let _ = std::fs::remove_dir_all(&output);
}

#[test]
fn experiment_names_cannot_escape_and_missing_files_are_input_errors() {
    let dir = scratch("names");
    std::fs::create_dir_all(&dir).unwrap();
    for name in [
        "../../escape",
        "",
        ".hidden",
        "..",
        "a/b",
        "a..b",
        "x".repeat(101).as_str(),
    ] {
        let file = dir.join("e.toml");
        std::fs::write(
            &file,
            format!(
                "name = {name:?}\nplanners = [\"mit-star\"]\n[[problems]]\nname = \"wall-gap\"\ndimensions = [2]\ntime = 0.05\n"
            ),
        )
        .unwrap();
        let out = binary()
            .current_dir(&dir)
            .args(["bench", &file.display().to_string(), "-q"])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{name:?}");
        assert!(stderr(&out).contains("`name`"), "{name:?}");
        assert!(stderr(&out).contains("not starting with `.`"), "{name:?}");
    }
    let out = binary()
        .current_dir(&dir)
        .args([
            "bench",
            "--problem",
            "wall-gap",
            "--dim",
            "2",
            "--time",
            "0.05",
        ])
        .args(["--name", "../out", "-q"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(
        !dir.join("results").exists() && !dir.parent().unwrap().join("escape").exists(),
        "nothing written for refused names"
    );

    // Default names (a file's stem) are made safe instead: they stay inside results/.
    let problem =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../problems/examples/wall-with-slot-2d.toml");
    let weird = dir.join("..weird name.toml");
    std::fs::copy(&problem, &weird).unwrap();
    let out = binary()
        .current_dir(&dir)
        .args([
            "bench",
            "--problem",
            &weird.display().to_string(),
            "--time",
            "0.05",
        ])
        .args(["--planners", "mit-star", "--runs", "1", "--no-plots", "-q"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    let folders: Vec<String> = std::fs::read_dir(dir.join("results"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(folders, ["weird-name-n2"]);

    let out = binary()
        .args(["bench", "/definitely/not/here.toml"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn impossible_run_counts_are_refused_before_allocating() {
    // `--runs 1000000000000` aborted on allocation; now it is an input error naming the cap on
    // the runs an experiment may schedule, checked before anything is built.
    let output = scratch("huge");
    let out = binary()
        .args([
            "bench",
            "--planners",
            "mit-star",
            "--problem",
            "wall-gap",
            "--dims",
            "2",
            "--runs",
            "1000000000000",
            "--time",
            "0.01",
            "-q",
            "--output",
            &output.display().to_string(),
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    let text = stderr(&out);
    assert!(
        text.contains("schedules 1000000000000 runs") && text.contains("at most 10000000"),
        "{text}"
    );
    let _ = std::fs::remove_dir_all(&output);
}
