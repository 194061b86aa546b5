//! Durable results: every finished run is on disk when a signal arrives; SIGTERM and SIGINT
//! exit 143 and 130 after writing; a second `bench` resumes instead of overwriting; headers and
//! `runcount` tell the recorded truth; nothing is written outside the output folder.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn binary() -> Command {
    Command::new(env!("CARGO_BIN_EXE_mit-star"))
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mit-star-dur-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// `bench` arguments: 2 planners × 20 runs of 0.15 s on one thread (6 s in all).
fn bench_args(output: &Path) -> Vec<String> {
    [
        "bench",
        "--planners",
        "mit-star,eit-star",
        "--problem",
        "dividing-walls",
        "--dims",
        "2",
        "--runs",
        "20",
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

fn lines(path: &Path) -> usize {
    std::fs::read_to_string(path).map_or(0, |t| t.lines().count())
}

/// Starts a bench, waits until `runs` runs are on disk, sends `signal`, returns the exit code.
fn interrupted(output: &Path, signal: &str, runs: usize) -> i32 {
    let mut child = binary()
        .args(bench_args(output))
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let jsonl = output.join("runs.jsonl");
    let deadline = Instant::now() + Duration::from_secs(60);
    while lines(&jsonl) < runs {
        assert!(Instant::now() < deadline, "no runs written");
        std::thread::sleep(Duration::from_millis(20));
    }
    let kill = Command::new("kill")
        .args([&format!("-{signal}"), &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    child.wait().unwrap().code().unwrap_or(-1)
}

/// The recorded run count of the database's experiments, and its number of runs.
fn database(output: &Path) -> (Vec<i64>, i64) {
    let c = rusqlite::Connection::open(output.join("benchmark.db")).unwrap();
    let counts = c
        .prepare("SELECT runcount FROM experiments")
        .unwrap()
        .query_map([], |r| r.get(0))
        .unwrap()
        .collect::<Result<Vec<i64>, _>>()
        .unwrap();
    let runs = c
        .query_row("SELECT count(*) FROM runs", [], |r| r.get(0))
        .unwrap();
    (counts, runs)
}

#[test]
fn sigterm_and_sigint_keep_every_finished_run_then_a_rerun_resumes() {
    for (signal, code) in [("TERM", 143), ("INT", 130)] {
        let output = scratch(signal);
        assert_eq!(interrupted(&output, signal, 3), code, "SIG{signal}");
        let recorded = lines(&output.join("runs.jsonl"));
        assert!(recorded >= 3, "SIG{signal}: {recorded} runs");
        assert_eq!(
            lines(&output.join("runs.csv")),
            recorded + 1,
            "header + rows"
        );
        let (counts, runs) = database(&output);
        assert_eq!(
            runs as usize, recorded,
            "every recorded run is in the database"
        );
        assert_eq!(counts.len(), 1);
        assert!(
            (counts[0] as usize) < 20,
            "runcount {counts:?} is the recorded truth"
        );
        let log = std::fs::read_to_string(output.join("logs/dividing-walls-n2.log")).unwrap();
        assert!(
            log.contains(&format!("{} runs per planner", counts[0])),
            "{log}"
        );

        // The same experiment again resumes: only the missing runs, appended.
        let status = binary().args(bench_args(&output)).output().unwrap();
        assert!(
            status.status.success(),
            "{}",
            String::from_utf8_lossy(&status.stderr)
        );
        assert!(String::from_utf8_lossy(&status.stderr).contains("resuming"));
        assert_eq!(lines(&output.join("runs.jsonl")), 40);
        assert_eq!(lines(&output.join("runs.csv")), 41);
        assert_eq!(database(&output), (vec![20], 40));
        let _ = std::fs::remove_dir_all(&output);
    }
}

#[test]
fn another_experiment_never_overwrites_a_folder() {
    let output = scratch("other");
    let mut first = bench_args(&output);
    first[8] = "2".into(); // --runs 2
    assert!(binary().args(&first).output().unwrap().status.success());
    let before = std::fs::read_to_string(output.join("runs.csv")).unwrap();
    let mut other = first.clone();
    other[4] = "wall-gap".into();
    let out = binary().args(&other).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("holds the results of experiment"));
    assert_eq!(
        std::fs::read_to_string(output.join("runs.csv")).unwrap(),
        before
    );
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
        "a/b",
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
        assert!(
            String::from_utf8_lossy(&out.stderr).contains("`name`"),
            "{name:?}"
        );
    }
    assert!(
        !dir.join("results").exists(),
        "nothing written for refused names"
    );
    let out = binary()
        .args(["bench", "/definitely/not/here.toml"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn impossible_run_counts_are_refused_before_allocating() {
    // `--runs 1000000000000` aborted on allocation; now it is an input error naming memory.
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
    assert_eq!(
        out.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stderr).contains("memory"));
    let _ = std::fs::remove_dir_all(&output);
}
