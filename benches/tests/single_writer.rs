//! A results folder nothing can corrupt: one process writes it at a time (a second writer,
//! `merge` reading a part being written and `compare` are refused, naming the writer), a
//! writer killed with SIGKILL at any point leaves no stale lock and loses no recorded run, a
//! folder in which a run was recorded twice is healed by the next `bench`, and readers refuse
//! a folder whose files disagree instead of reporting inconsistent numbers.

use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

use mit_star_benches::BenchmarkLog;

use crate::common;

fn binary() -> Command {
    Command::new(env!("CARGO_BIN_EXE_mit-star"))
}

fn scratch(name: &str) -> PathBuf {
    common::scratch("single-writer", name)
}

/// `bench` of 2 planners × `runs` runs of `time` seconds on dividing walls in R², as strings.
fn bench_args(output: &Path, runs: usize, time: &str, threads: usize) -> Vec<String> {
    let (runs, threads) = (runs.to_string(), threads.to_string());
    [
        "bench",
        "--planners",
        "mit-star,eit-star",
        "--problem",
        "dividing-walls",
        "--dim",
        "2",
        "--runs",
        &runs,
        "--time",
        time,
        "--threads",
        &threads,
        "--name",
        "single-writer",
        "--no-plots",
        "-q",
        "--output",
    ]
    .iter()
    .map(|s| (*s).to_owned())
    .chain([output.display().to_string()])
    .collect()
}

fn run(args: &[String]) -> Output {
    binary().args(args).output().unwrap()
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

fn text(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_default()
}

/// The whole lines of a file (a last line without its line break is an append cut short).
fn whole_lines(path: &Path) -> Vec<String> {
    let text = text(path);
    let end = text.rfind('\n').map_or(0, |i| i + 1);
    text[..end].lines().map(str::to_owned).collect()
}

/// Starts `args` in the background and waits until `runs` runs are in `runs.jsonl`.
fn start(args: &[String], output: &Path, runs: usize) -> Child {
    let child = binary()
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let deadline = Instant::now() + Duration::from_secs(60);
    while whole_lines(&output.join("runs.jsonl")).len() < runs {
        assert!(Instant::now() < deadline, "no runs written");
        std::thread::sleep(Duration::from_millis(10));
    }
    child
}

/// A run's identity: instance, planner, run index.
type Key = (String, String, u64);

/// What the raw files and the database of `folder` hold, read independently of the harness:
/// `Ok(runs per planner)` if `runs.jsonl` and `runs.csv` hold the same runs, each once, and the
/// database as many per planner; `Err(the difference)` otherwise.
fn agreement(folder: &Path) -> Result<HashMap<String, i64>, String> {
    let mut journal = HashSet::new();
    let mut per_planner = HashMap::new();
    for line in whole_lines(&folder.join("runs.jsonl")) {
        let v: serde_json::Value = serde_json::from_str(&line).map_err(|e| e.to_string())?;
        let key: Key = (
            v["instance"].as_str().unwrap().to_owned(),
            v["planner"].as_str().unwrap().to_owned(),
            v["run"].as_u64().unwrap(),
        );
        if !journal.insert(key.clone()) {
            return Err(format!("{key:?} twice in runs.jsonl"));
        }
        *per_planner.entry(key.1).or_insert(0) += 1;
    }
    let csv_text = whole_lines(&folder.join("runs.csv")).join("\n");
    let mut rows = csv::Reader::from_reader(csv_text.as_bytes());
    let mut in_csv = HashSet::new();
    for row in rows.records() {
        let row = row.map_err(|e| e.to_string())?;
        let key: Key = (
            row[0].to_owned(),
            row[6].to_owned(),
            row[8].parse().unwrap(),
        );
        if !in_csv.insert(key.clone()) {
            return Err(format!("{key:?} twice in runs.csv"));
        }
    }
    if in_csv != journal {
        return Err(format!(
            "runs.csv has {} runs, runs.jsonl {}",
            in_csv.len(),
            journal.len()
        ));
    }
    let database = rusqlite::Connection::open_with_flags(
        folder.join("benchmark.db"),
        rusqlite::OpenFlags::SQLITE_OPEN_READ_ONLY,
    )
    .map_err(|e| e.to_string())?;
    let in_database: HashMap<String, i64> = database
        .prepare(
            "SELECT p.name, count(*) FROM runs r JOIN plannerConfigs p ON r.plannerid = p.id \
             GROUP BY p.name",
        )
        .and_then(|mut s| {
            s.query_map([], |r| Ok((r.get(0)?, r.get(1)?)))?
                .collect::<Result<_, _>>()
        })
        .map_err(|e| e.to_string())?;
    if in_database != per_planner {
        return Err(format!(
            "database {in_database:?}, runs.jsonl {per_planner:?}"
        ));
    }
    Ok(per_planner)
}

/// A finished folder: every file agrees — raw files, database rows and `runcount`, the OMPL
/// log, `kpi.md` (which counts the runs of `planned`) — and no run is recorded twice. Returns
/// the recorded runs.
fn finished(folder: &Path, planned: i64) -> i64 {
    let per_planner = agreement(folder).unwrap_or_else(|e| panic!("{e}"));
    let most = per_planner.values().copied().max().unwrap_or(0);
    let database = rusqlite::Connection::open(folder.join("benchmark.db")).unwrap();
    let counts: Vec<i64> = database
        .prepare("SELECT runcount FROM experiments")
        .unwrap()
        .query_map([], |r| r.get(0))
        .unwrap()
        .collect::<Result<_, _>>()
        .unwrap();
    assert_eq!(
        counts,
        [most],
        "one experiment row, runcount = most runs of a planner"
    );
    let log = BenchmarkLog::parse(&text(&folder.join("logs/dividing-walls-n2.log"))).unwrap();
    assert_eq!(log.runs_per_planner, Some(most as usize), "the log header");
    let in_log: HashMap<String, i64> = log
        .planners
        .iter()
        .filter(|p| !p.runs.is_empty())
        .map(|p| (p.name.clone(), p.runs.len() as i64))
        .collect();
    assert_eq!(
        in_log, per_planner,
        "the log holds exactly the recorded runs"
    );
    let total: i64 = per_planner.values().sum();
    let kpi = text(&folder.join("kpi.md"));
    assert!(
        kpi.contains(&format!("{total} of {planned} runs recorded")),
        "{kpi}"
    );
    total
}

/// `compare A B` (and extra arguments).
fn compare(a: &Path, b: &Path, extra: &[&str]) -> Output {
    binary()
        .args(["compare", a.to_str().unwrap(), b.to_str().unwrap()])
        .args(extra)
        .output()
        .unwrap()
}

#[test]
fn a_folder_being_written_refuses_every_other_process() {
    // Two shards of one experiment; the first is being written while the others try.
    let parts: Vec<PathBuf> = (1..=2).map(|k| scratch(&format!("part-{k}"))).collect();
    let shard = |k: usize| {
        let mut args = bench_args(&parts[k - 1], 10, "0.3", 1);
        args.extend(["--shard".to_owned(), format!("{k}/2")]);
        args
    };
    let out = run(&shard(2));
    assert!(out.status.success(), "{}", stderr(&out));
    let mut writer = start(&shard(1), &parts[0], 1);
    let pid = writer.id();
    let folder = parts[0].display().to_string();

    // A second writer: refused before it writes anything, naming the folder and the writer.
    let before = text(&parts[0].join("runs.jsonl"));
    let second = run(&shard(1));
    let message = stderr(&second);
    assert_eq!(second.status.code(), Some(2), "{message}");
    for needle in [
        format!("results folder `{folder}` is in use by mit-star process {pid} ("),
        "which is writing it".to_owned(),
        "or write to another --output folder".to_owned(),
    ] {
        assert!(message.contains(&needle), "`{needle}` not in: {message}");
    }
    assert!(!message.contains("database is locked"), "{message}");
    assert!(text(&parts[0].join("runs.jsonl")).starts_with(&before));

    // `merge` does not read a part being written, nor `compare` a folder.
    let merged = scratch("merged");
    let out = binary()
        .args(["merge", &folder, parts[1].to_str().unwrap(), "--no-plots"])
        .args(["--output", merged.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(
        stderr(&out).contains(&format!("is in use by mit-star process {pid}")),
        "{}",
        stderr(&out)
    );
    let out = compare(&parts[0], &parts[1], &["--allow-mismatch"]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("read it when it has finished"));
    assert!(
        writer.try_wait().unwrap().is_none(),
        "the writer was still running throughout"
    );

    // The writer finishes undisturbed; then the parts merge and the folder is free again.
    let out = writer.wait_with_output().unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(finished(&parts[0], 20), 10);
    let out = binary()
        .args(["merge", &folder, parts[1].to_str().unwrap(), "--no-plots"])
        .args(["--output", merged.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(finished(&merged, 20), 20);
    let out = run(&shard(1));
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(stdout(&out).contains("(0 runs added, 10 recorded)"));
    for dir in parts.iter().chain([&merged]) {
        let _ = std::fs::remove_dir_all(dir);
    }
}

/// A small generator for the kill times (xorshift64*), seeded from the clock and printed.
struct Random(u64);

impl Random {
    fn below(&mut self, bound: u64) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) % bound
    }
}

#[test]
fn sigkill_at_random_points_then_resume_records_every_run_once() {
    let folder = scratch("sigkill");
    let args = bench_args(&folder, 15, "0.01", 2);
    let seed = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .unwrap()
        .as_nanos() as u64
        | 1;
    eprintln!("kill times from seed {seed}");
    let mut random = Random(seed);
    let mut killed = 0;
    for iteration in 0..8 {
        let mut child = binary()
            .args(&args)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let delay = Duration::from_millis(20 + random.below(400));
        std::thread::sleep(delay);
        if let Some(status) = child.try_wait().unwrap() {
            // It finished first: it must have succeeded (no stale lock refused it).
            let out = child.wait_with_output().unwrap();
            assert!(status.success(), "iteration {iteration}: {}", stderr(&out));
            continue;
        }
        child.kill().unwrap();
        let out = child.wait_with_output().unwrap();
        if out.status.success() {
            continue; // It finished just before the signal.
        }
        assert_eq!(
            out.status.code(),
            None,
            "killed by a signal: {}",
            stderr(&out)
        );
        killed += 1;
        // Whatever the kill interrupted, no run is recorded twice, and a reader either finds
        // every file in agreement or refuses the folder, naming the files.
        let independent = agreement(&folder);
        if let Err(difference) = &independent {
            assert!(
                !difference.contains("twice in runs.jsonl"),
                "iteration {iteration} after {delay:?}: {difference}"
            );
        }
        if !whole_lines(&folder.join("runs.jsonl")).is_empty() {
            let out = compare(&folder, &folder, &["--allow-mismatch"]);
            match &independent {
                Ok(_) => assert!(
                    out.status.success(),
                    "iteration {iteration}: the files agree, yet: {}",
                    stderr(&out)
                ),
                Err(difference) => {
                    assert_eq!(out.status.code(), Some(2), "{difference}: {}", stderr(&out));
                    assert!(
                        stderr(&out).contains("disagrees with itself"),
                        "{difference}: {}",
                        stderr(&out)
                    );
                }
            }
        }
    }
    eprintln!("{killed} of 8 benches killed");
    // The last resume finishes the experiment: every run once, every file in agreement.
    let out = run(&args);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(finished(&folder, 30), 30);
    let out = compare(&folder, &folder, &[]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(stdout(&out).contains("(30 runs) →"), "{}", stdout(&out));
    let _ = std::fs::remove_dir_all(&folder);
}

/// Appends a copy of the first run's line to `runs.jsonl` and its row to `runs.csv`, as a
/// second, unlocked writer did.
fn record_first_run_again(folder: &Path) {
    let jsonl = folder.join("runs.jsonl");
    let first = whole_lines(&jsonl)[0].clone();
    std::fs::write(&jsonl, format!("{}{first}\n", text(&jsonl))).unwrap();
    let csv = folder.join("runs.csv");
    let row = whole_lines(&csv)[1].clone();
    std::fs::write(&csv, format!("{}{row}\n", text(&csv))).unwrap();
}

#[test]
fn a_run_recorded_twice_is_refused_by_readers_and_healed_by_the_next_bench() {
    let folder = scratch("twice");
    let args = bench_args(&folder, 4, "0.02", 1);
    let out = run(&args);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(finished(&folder, 8), 8);
    let first: serde_json::Value =
        serde_json::from_str(&whole_lines(&folder.join("runs.jsonl"))[0]).unwrap();
    let key = format!(
        "run {} of {} on `{}` twice",
        first["run"],
        first["planner"].as_str().unwrap(),
        first["instance"].as_str().unwrap()
    );
    // The tester's folder: 9 lines for 8 runs (and here a database of 8).
    record_first_run_again(&folder);

    let out = compare(&folder, &folder, &[]);
    let message = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{message}");
    for needle in [
        format!(
            "results folder `{}` disagrees with itself",
            folder.display()
        ),
        "`runs.jsonl` 9 lines (8 distinct runs), `runs.csv` 9 rows, `benchmark.db` 8 runs".into(),
        key,
        "runs.csv` has".into(),
        format!(
            "mit-star bench {}/experiment.toml --output",
            folder.display()
        ),
    ] {
        assert!(message.contains(&needle), "`{needle}` not in: {message}");
    }

    // Resuming heals it: the first record of each run, distinct counts everywhere.
    let out = run(&args);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("recorded 1 runs a second time"),
        "{}",
        stderr(&out)
    );
    assert!(
        stdout(&out).contains("(0 runs added, 8 recorded)"),
        "{}",
        stdout(&out)
    );
    assert!(!stdout(&out).contains("9 of 8"));
    assert_eq!(finished(&folder, 8), 8);
    assert!(compare(&folder, &folder, &[]).status.success());
    let _ = std::fs::remove_dir_all(&folder);
}

#[test]
fn readers_refuse_files_that_disagree_until_a_resume_repairs_them() {
    let folder = scratch("disagree");
    let args = bench_args(&folder, 2, "0.02", 1);
    assert!(run(&args).status.success());
    let csv = folder.join("runs.csv");
    let whole = text(&csv);
    // A row missing from runs.csv (a writer killed between its two appends).
    let rows = whole_lines(&csv);
    std::fs::write(&csv, rows[..rows.len() - 1].join("\n") + "\n").unwrap();
    let out = compare(&folder, &folder, &[]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("`runs.jsonl` 4 lines (4 distinct runs), `runs.csv` 3 rows")
            && stderr(&out).contains("`runs.csv` lacks run"),
        "{}",
        stderr(&out)
    );
    std::fs::write(&csv, &whole).unwrap();
    // A database without the runs (removed, or killed before its first commit).
    std::fs::remove_file(folder.join("benchmark.db")).unwrap();
    let out = compare(&folder, &folder, &[]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("`benchmark.db` is missing"),
        "{}",
        stderr(&out)
    );
    // The resume the message names repairs both.
    std::fs::write(&csv, rows[..rows.len() - 1].join("\n") + "\n").unwrap();
    assert!(run(&args).status.success());
    assert_eq!(finished(&folder, 4), 4);
    assert!(compare(&folder, &folder, &[]).status.success());
    let _ = std::fs::remove_dir_all(&folder);
}

#[test]
fn compare_refuses_folders_that_measure_different_things() {
    let a = scratch("budget-a");
    let b = scratch("budget-b");
    assert!(run(&bench_args(&a, 2, "0.02", 1)).status.success());
    assert!(run(&bench_args(&b, 2, "0.04", 1)).status.success());
    let out = compare(&a, &b, &[]);
    let message = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{message}");
    assert!(
        message.contains(&format!(
            "`{}` and `{}` cannot be compared: the time budgets per run differ: \
             dividing-walls-n2 0.02 s in A, 0.04 s in B",
            a.display(),
            b.display()
        )) && message.contains("pass --allow-mismatch"),
        "{message}"
    );
    let out = compare(&a, &b, &["--allow-mismatch"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("warning: comparing anyway (--allow-mismatch), but the time budgets")
    );
    assert!(stdout(&out).contains("| dividing-walls R^2 | MIT* |"));

    // A shard against the whole experiment.
    let shard = scratch("shard");
    let mut args = bench_args(&shard, 2, "0.02", 1);
    args.extend(["--shard".to_owned(), "1/2".to_owned()]);
    assert!(run(&args).status.success());
    let out = compare(&a, &shard, &[]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("A holds the whole experiment and B shard 1/2 of its experiment"),
        "{}",
        stderr(&out)
    );

    // A folder without all its runs (its experiment asks for 4 runs per planner, it has 2).
    let partial = scratch("partial");
    std::fs::create_dir_all(partial.join("logs")).unwrap();
    for file in ["runs.jsonl", "runs.csv", "benchmark.db", "kpi.md"] {
        std::fs::copy(a.join(file), partial.join(file)).unwrap();
    }
    let toml = text(&a.join("experiment.toml"));
    assert!(toml.contains("\nruns = 2\n"), "{toml}");
    std::fs::write(
        partial.join("experiment.toml"),
        toml.replace("\nruns = 2\n", "\nruns = 4\n"),
    )
    .unwrap();
    let out = compare(&a, &partial, &[]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("B holds 4 of the 8 runs its experiment schedules"),
        "{}",
        stderr(&out)
    );
    assert!(compare(&a, &a, &[]).status.success());
    for dir in [a, b, shard, partial] {
        let _ = std::fs::remove_dir_all(dir);
    }
}
