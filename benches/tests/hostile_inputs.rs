//! Hostile inputs to the command line (issue 74): tolerances that would let any path through,
//! foreign runs in a results folder, devices and binary files as inputs, absurd sizes and
//! parameter values, and signals during long work. Each is a typed error (exit code 2) naming
//! what is wrong, or a kept promise.

use crate::common;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use common::{mit_star, refused, scratch};

/// Runs `mit-star` with `args` under an address-space limit of 4 GB, so that an input read
/// or allocated without bound fails the test (an abort) instead of exhausting the machine.
fn mit_star_limited(args: &[&str]) -> Output {
    Command::new("sh")
        .arg("-c")
        .arg("ulimit -v 4000000; exec \"$0\" \"$@\"")
        .arg(env!("CARGO_BIN_EXE_mit-star"))
        .args(args)
        .current_dir(env!("CARGO_TARGET_TMPDIR"))
        .output()
        .unwrap()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn folder(name: &str) -> PathBuf {
    let dir = scratch("hostile", name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn state(x: &[f64]) -> String {
    x.iter()
        .map(|v| format!("{v:e}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// A small deterministic generator (SplitMix64) for the random tolerances.
struct Draws(u64);

impl Draws {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Item 3: whatever `--tolerance` is given, a path whose start lies farther from the
/// problem's start than the bound (1e-3 per coordinate) or than the tolerance never exits 0;
/// a tolerance outside [0, 1e-3] is refused naming the flag and the bound.
#[test]
fn check_path_never_passes_a_path_that_misses_the_start() {
    let dir = folder("tolerance");
    let problem = mit_star_problems::builtin("obstacle-free", 2, 0).unwrap();
    let (start, goal) = (problem.start().to_vec(), problem.goals()[0].clone());
    let file = dir.join("path.txt");
    let mut draws = Draws(74);
    let mut tolerances: Vec<f64> = vec![100.0, 1e-3, 0.0, -1.0, f64::NAN, f64::INFINITY, 0.5];
    for _ in 0..24 {
        // Log-uniform over 1e-9 … 1e3, either side of the bound.
        tolerances.push(10f64.powf(-9.0 + 12.0 * draws.unit()));
    }
    for tolerance in tolerances {
        let accepted = (0.0..=1e-3).contains(&tolerance);
        // An offset beyond what may be snapped: more than the tolerance (if accepted) and
        // more than the bound, at most 0.1 (inside the bounds).
        let least = if accepted { tolerance.max(1e-9) } else { 1e-3 };
        let offset = least * (1.01 + 50.0 * draws.unit()).min(0.1 / least);
        let offset = offset.max(least * 1.001);
        let mut first = start.clone();
        first[0] += offset;
        std::fs::write(&file, format!("{}\n{}\n", state(&first), state(&goal))).unwrap();
        let value = format!("{tolerance}");
        let args = [
            "check-path",
            "--problem",
            "obstacle-free",
            "--path",
            file.to_str().unwrap(),
            "--tolerance",
            &value,
        ];
        let out = mit_star(&args);
        assert_ne!(
            out.status.code(),
            Some(0),
            "tolerance {tolerance}, start {offset} away: {}",
            String::from_utf8_lossy(&out.stdout)
        );
        if accepted {
            assert_eq!(out.status.code(), Some(3), "{args:?}: {}", stderr(&out));
        } else {
            assert_eq!(out.status.code(), Some(2), "{args:?}: {}", stderr(&out));
            let text = stderr(&out);
            assert!(
                text.contains("--tolerance") && text.contains("1e-3"),
                "{text}"
            );
        }
    }
    // Ends within an accepted tolerance are snapped and the path passes.
    let mut first = start;
    first[0] += 5e-5;
    std::fs::write(&file, format!("{}\n{}\n", state(&first), state(&goal))).unwrap();
    let out = mit_star(&[
        "check-path",
        "--problem",
        "obstacle-free",
        "--path",
        file.to_str().unwrap(),
        "--tolerance",
        "1e-4",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
}

/// Item 18: a NaN coordinate is reported with its line and coordinate, as an input error;
/// so is a state of the wrong dimension and a binary file (exit 2, not 1).
#[test]
fn check_path_names_the_line_of_a_bad_state_and_refuses_binary_files() {
    let dir = folder("bad-states");
    let problem = mit_star_problems::builtin("obstacle-free", 2, 0).unwrap();
    let (start, goal) = (problem.start().to_vec(), problem.goals()[0].clone());
    let file = dir.join("path.txt");
    let path = file.to_str().unwrap();
    let args = ["check-path", "--problem", "obstacle-free", "--path", path];
    std::fs::write(
        &file,
        format!("# a path\n{}\n0.1 NaN\n{}\n", state(&start), state(&goal)),
    )
    .unwrap();
    refused(&args, &["line 3, coordinate 2", "NaN", "path.txt"]);
    let out = mit_star(&args);
    assert!(!stderr(&out).contains("planner"), "{}", stderr(&out));
    std::fs::write(&file, format!("{}\n0 0 0\n", state(&start))).unwrap();
    refused(&args, &["line 2 has 3 coordinates", "have 2"]);
    std::fs::write(&file, [0x7f, b'E', b'L', b'F', 0xff, 0xfe, 0x00, 0x01]).unwrap();
    refused(&args, &["path file", "not text"]);
}

/// Item 16: devices and folders where a file is needed are refused before reading: a path
/// file, a problem file (command line and experiment file) and an experiment file of
/// `/dev/zero` never end, and were read until the kernel killed the process.
#[test]
fn devices_are_refused_before_reading() {
    let dir = folder("devices");
    refused(
        &[
            "check-path",
            "--problem",
            "obstacle-free",
            "--path",
            "/dev/zero",
        ],
        &["/dev/zero", "not a regular file"],
    );
    let out = mit_star_limited(&[
        "plan",
        "--problem-file",
        "/dev/zero",
        "--time",
        "0.01",
        "--no-picture",
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("not a regular file"),
        "{}",
        stderr(&out)
    );
    let experiment = dir.join("zero.toml");
    std::fs::write(
        &experiment,
        "name = \"zero\"\nruns = 1\nplanners = [\"rrt-connect\"]\n[[problems]]\n\
         file = \"/dev/zero\"\ntime = 0.01\n",
    )
    .unwrap();
    let output = dir.join("out");
    let out = mit_star_limited(&[
        "bench",
        experiment.to_str().unwrap(),
        "-q",
        "--no-plots",
        "--output",
        output.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("not a regular file"),
        "{}",
        stderr(&out)
    );
    let out = mit_star_limited(&["bench", "/dev/zero", "--output", output.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("not a regular file"),
        "{}",
        stderr(&out)
    );
}

/// Item 18: a parser error quotes at most a short excerpt of a 200 KB line.
#[test]
fn errors_quote_a_short_excerpt_of_a_huge_line() {
    let dir = folder("huge-line");
    let depth = 100_000;
    let experiment = dir.join("nested.toml");
    std::fs::write(
        &experiment,
        format!(
            "name = \"n\"\nruns = {}{}\n",
            "[".repeat(depth),
            "]".repeat(depth)
        ),
    )
    .unwrap();
    let out = mit_star(&["bench", experiment.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2), "{}", &stderr(&out)[..200]);
    assert!(stderr(&out).len() < 2_000, "{} bytes", stderr(&out).len());
    let problem = dir.join("long.toml");
    std::fs::write(
        &problem,
        format!(
            "name = \"p\"\nstart = [0.0, \"{}\"]\ngoal = [0.1, 0.1]\n[bounds]\nlower = [0, 0]\nupper = [1, 1]\n",
            "x".repeat(200_000)
        ),
    )
    .unwrap();
    let out = mit_star(&["plan", "--problem-file", problem.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2), "{}", &stderr(&out)[..200]);
    assert!(stderr(&out).len() < 2_000, "{} bytes", stderr(&out).len());
}

fn bench_args<'a>(output: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![
        "bench",
        "--planners",
        "rrt-connect",
        "--problem",
        "obstacle-free",
        "--dim",
        "2",
        "--time",
        "0.01",
        "--threads",
        "1",
        "-q",
        "--no-plots",
        "--output",
        output,
    ];
    args.extend_from_slice(extra);
    args
}

/// Item 15 (and 18): a line of `runs.jsonl` with a run the experiment does not schedule is
/// refused on resume, naming the line, the run, the planner and the instance; resuming with
/// another `--runs` says what differs.
#[test]
fn resume_refuses_a_foreign_run_and_says_what_differs() {
    let dir = folder("foreign-run");
    let output = dir.join("out");
    let out_text = output.to_str().unwrap();
    let out = mit_star(&bench_args(out_text, &["--runs", "2"]));
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let jsonl = output.join("runs.jsonl");
    let text = std::fs::read_to_string(&jsonl).unwrap();
    let first = text.lines().next().unwrap();
    let mut value: serde_json::Value = serde_json::from_str(first).unwrap();
    value["run"] = 99.into();
    std::fs::write(&jsonl, format!("{text}{value}\n")).unwrap();
    refused(
        &bench_args(out_text, &["--runs", "2"]),
        &["line 3", "run 99", "RRT-Connect", "obstacle-free"],
    );
    let csv = std::fs::read_to_string(output.join("runs.csv")).unwrap();
    assert_eq!(csv.lines().count(), 3, "nothing was copied: {csv}");
    // The foreign line removed, a changed --runs is refused saying what differs.
    std::fs::write(&jsonl, &text).unwrap();
    refused(
        &bench_args(out_text, &["--runs", "3"]),
        &["`runs = 2` in the folder, `runs = 3` now"],
    );
}

/// Items 11 and 17: a million instances, or a count past `u64`, are refused before anything
/// is built, from the flags and from a file, naming the limit; a folder's count past its
/// problems is refused like a range past them.
#[test]
fn absurd_instance_counts_are_refused_before_building() {
    let dir = folder("instances");
    let output = dir.join("out");
    let out_text = output.to_str().unwrap();
    for count in ["1000000", "18446744073709551615", "0-18446744073709551615"] {
        let mut args = bench_args(out_text, &["--instances", count, "--runs", "1"]);
        args[4] = "random-rectangles";
        let out = mit_star_limited(&args);
        assert_eq!(out.status.code(), Some(2), "{count}: {}", stderr(&out));
        assert!(stderr(&out).contains("at most 10000"), "{}", stderr(&out));
    }
    let file = dir.join("million.toml");
    std::fs::write(
        &file,
        "name = \"m\"\nruns = 1\nplanners = [\"rrt-connect\"]\n[[problems]]\n\
         name = \"random-rectangles\"\ndimensions = [2]\ntime = 0.01\ninstances = 1000000\n",
    )
    .unwrap();
    let out = mit_star_limited(&["bench", file.to_str().unwrap(), "--output", out_text]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("problems[0].instances") && stderr(&out).contains("at most 10000"),
        "{}",
        stderr(&out)
    );
    // Runs × instances past the schedule's cap.
    std::fs::write(
        &file,
        "name = \"m\"\nruns = 10000\nplanners = [\"rrt-connect\", \"mit-star\"]\n[[problems]]\n\
         name = \"random-rectangles\"\ndimensions = [2, 4]\ntime = 0.01\ninstances = 1000\n",
    )
    .unwrap();
    refused(
        &["bench", file.to_str().unwrap(), "--output", out_text],
        &["`runs`", "40000000 runs", "at most 10000000"],
    );
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robot/tests/data/mbm/box_panda");
    let problem = format!("mbm:{}", folder.display());
    for count in ["3", "18446744073709551615"] {
        let mut args = bench_args(out_text, &["--instances", count]);
        args[4] = &problem;
        args.retain(|a| *a != "--dim" && *a != "2");
        let out = mit_star(&args);
        assert_eq!(out.status.code(), Some(2), "{count}: {}", stderr(&out));
        assert!(
            stderr(&out).contains("holds 2 problems"),
            "{}",
            stderr(&out)
        );
    }
}

/// Item 17: `--set` values far outside a parameter's sane range are refused, naming the
/// parameter and its range.
#[test]
fn absurd_parameter_values_are_refused_with_their_range() {
    for (key, range) in [
        ("rewire_factor", "(0, 100]"),
        ("gaussian_std_fraction", "(0, 10]"),
        ("sparse_initial_steps", "(0, 1e9]"),
        ("range", "(0, 1e6]"),
    ] {
        let assignment = format!("{key}=1e300");
        refused(
            &[
                "plan",
                "--planner",
                "mit-star",
                "--problem",
                "wall-gap",
                "--time",
                "0.01",
                "--no-picture",
                "--set",
                &assignment,
            ],
            &[key, range],
        );
    }
}

/// Item 16: `replan` with a huge iteration count is refused naming the limit, and one with
/// the largest count stops at the first SIGTERM (it went on for 11–15 minutes).
#[test]
#[cfg(unix)]
fn replan_refuses_absurd_iterations_and_honours_the_first_sigterm() {
    use std::time::{Duration, Instant};
    let dir = folder("replan");
    let output = dir.join("out");
    refused(
        &[
            "replan",
            "--iterations",
            "1000000000000",
            "--output",
            output.to_str().unwrap(),
        ],
        &["1000000000000 iterations", "at most 1000000"],
    );
    let mut child = Command::new(env!("CARGO_BIN_EXE_mit-star"))
        .args([
            "replan",
            "--scenes",
            "horizontal",
            "--planners",
            "mit-star",
            "--iterations",
            "1000000",
            "--no-picture",
            "--output",
            output.to_str().unwrap(),
        ])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    common::wait_for_sigterm_handler(child.id());
    std::thread::sleep(Duration::from_secs(1));
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
        // Generous: a stopped plan returns within milliseconds; before, minutes passed.
        if sent.elapsed() > Duration::from_secs(60) {
            child.kill().unwrap();
            panic!("replan still running 60 s after SIGTERM");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    assert_eq!(status.code(), Some(128 + 15), "{status:?}");
}
