//! The reliability issue's cases, as a new user meets them on the command line: extreme and
//! malformed input is a clear error with exit code 2 — never a panic, an abort or a false
//! "validated".

use std::path::PathBuf;
use std::process::{Command, Output};

fn mit_star(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mit-star"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// A fresh scratch folder for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mit-star-rel-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The issue's problem: a wall 1e-6 thick spans the square, so there is no solution.
const THIN_WALL: &str = r#"
name = "tw"
start = [-0.3, 0.0]
goal = [0.3, 0.0]
[bounds]
lower = [-0.5, -0.5]
upper = [0.5, 0.5]
[[obstacles]]
center = [0.0, 0.0]
widths = [1e-6, 1.0]
"#;

fn write(dir: &std::path::Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

/// Runs a command that must fail with exit code 2 and say every `needle` on stderr.
fn refused(args: &[&str], needles: &[&str]) -> String {
    let out = mit_star(args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    for needle in needles {
        assert!(
            stderr.contains(needle),
            "{args:?}: `{needle}` not in: {stderr}"
        );
    }
    assert!(
        stderr.len() < 700,
        "{args:?}: the message is a wall of text: {stderr}"
    );
    stderr
}

#[test]
fn a_step_coarser_than_the_thinnest_obstacle_is_refused() {
    let dir = scratch("thin");
    let file = write(&dir, "tw.toml", THIN_WALL);
    refused(
        &["plan", "--problem-file", &file, "--no-picture"],
        &[
            "thinnest obstacle (1e-6)",
            "--allow-coarse-step",
            "7.071e-6",
        ],
    );
    refused(
        &[
            "plan",
            "--problem",
            "wall-gap",
            "--resolution",
            "0.5",
            "--no-picture",
        ],
        &["thinnest obstacle (0.2)", "anti-obstacle (0.04)"],
    );
    // With an explicit permission the run happens, with a warning. The grid misses the thin
    // wall, but certification decides every tree edge exactly (the world's slab tests), so no
    // path through the wall is ever returned: no solution, and never "validated".
    let out = mit_star(&[
        "plan",
        "--problem-file",
        &file,
        "--no-picture",
        "--allow-coarse-step",
        "--time",
        "0.2",
    ]);
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert!(stderr.contains("warning"), "{stderr}");
    assert!(!stdout.contains("validated"), "{stdout}");
    assert!(stdout.contains("no solution"), "{stdout}{stderr}");
    let failures: u64 = stdout
        .lines()
        .find_map(|l| l.trim().strip_prefix("certification_failures"))
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(0);
    assert!(failures > 0, "certification found the wall: {stdout}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn resolutions_outside_zero_one_are_refused() {
    for bad in ["1e300", "0", "-0.5", "1", "nan", "inf"] {
        refused(
            &[
                "plan",
                "--problem",
                "wall-gap",
                "--resolution",
                bad,
                "--no-picture",
            ],
            &["strictly between 0 and 1"],
        );
    }
}

#[test]
fn budgets_no_clock_can_hold_are_refused() {
    for bad in ["1e308", "1e19", "nan", "inf", "-1", "0", "-0", "5e-324"] {
        refused(
            &[
                "plan",
                "--problem",
                "dividing-walls",
                "--time",
                bad,
                "--no-picture",
            ],
            &["--time: ", "not a usable time budget"],
        );
    }
}

#[test]
fn sizes_beyond_the_machine_are_refused_before_allocating() {
    refused(
        &[
            "plan",
            "--problem",
            "goal-enclosure",
            "--dim",
            "100000",
            "--no-picture",
        ],
        &["100000 dimensions", "memory", "available"],
    );
    refused(
        &[
            "plan",
            "--problem",
            "dividing-walls",
            "--set",
            "batch_size=1000000000000",
            "--no-picture",
        ],
        &["batch of 1000000000000 samples", "memory"],
    );
}

#[test]
fn malformed_files_and_folders_are_named() {
    let dir = scratch("files");
    refused(
        &[
            "plan",
            "--problem-file",
            &dir.display().to_string(),
            "--no-picture",
        ],
        &["is a folder, not a problem file"],
    );
    refused(
        &[
            "plan",
            "--problem",
            &dir.display().to_string(),
            "--no-picture",
        ],
        &["is a folder, not a problem file"],
    );
    let huge = THIN_WALL
        .replace("[-0.5, -0.5]", "[-1e308, -1e308]")
        .replace("[0.5, 0.5]", "[1e308, 1e308]");
    let file = write(&dir, "huge.toml", &huge);
    refused(
        &["plan", "--problem-file", &file, "--no-picture"],
        &["diagonal is inf", "rescale"],
    );
    let one = THIN_WALL.replace("widths = [1e-6, 1.0]", "widths = [1e-6]");
    let file = write(&dir, "one.toml", &one);
    let message = refused(
        &["plan", "--problem-file", &file, "--no-picture"],
        &["has 1 value,"],
    );
    assert!(!message.contains("1 values"), "{message}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn large_bounds_need_an_explicit_coarse_step() {
    let dir = scratch("bounds");
    let wide = THIN_WALL
        .replace("[-0.5, -0.5]", "[-5e11, -5e11]")
        .replace("[0.5, 0.5]", "[5e11, 5e11]")
        .replace("widths = [1e-6, 1.0]", "widths = [1e-6, 1e12]");
    let file = write(&dir, "wide.toml", &wide);
    refused(
        &["plan", "--problem-file", &file, "--no-picture"],
        &["thinnest obstacle (1e-6)"],
    );
    let _ = std::fs::remove_dir_all(&dir);
}
