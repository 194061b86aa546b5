//! Helpers shared by the tests that drive the `mit-star` binary.

// Each test binary compiles its own copy and uses a subset.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs `mit-star` with `args` in the test's scratch directory.
pub(crate) fn mit_star(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mit-star"))
        .args(args)
        .current_dir(env!("CARGO_TARGET_TMPDIR"))
        .output()
        .unwrap()
}

/// An empty path `<scratch>/<prefix>-<name>` (removed if it exists).
pub(crate) fn scratch(prefix: &str, name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{prefix}-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// Runs a command that must succeed; returns its standard output.
pub(crate) fn succeeded(args: &[&str]) -> String {
    let out = mit_star(args);
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{args:?}: {stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    stdout
}

/// Runs a command that must fail with exit code 2 and a message containing every `needle`.
pub(crate) fn refused(args: &[&str], needles: &[&str]) {
    let out = mit_star(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    for needle in needles {
        assert!(
            stderr.contains(needle),
            "{args:?}: `{needle}` not in: {stderr}"
        );
    }
}

/// Waits until process `pid` catches SIGTERM (bit 15 of `SigCgt` in `/proc/PID/status`), so
/// that a SIGTERM sent next reaches its handler rather than the default action, which would
/// end it without an exit code. A fixed sleep is not enough on a loaded machine: a process
/// started right after a build may not have reached `main` seconds later.
pub(crate) fn wait_for_sigterm_handler(pid: u32) {
    let limit = std::time::Duration::from_secs(60);
    let deadline = std::time::Instant::now() + limit;
    loop {
        let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap_or_default();
        let caught = status
            .lines()
            .find_map(|line| line.strip_prefix("SigCgt:"))
            .and_then(|mask| u64::from_str_radix(mask.trim(), 16).ok());
        if caught.is_some_and(|mask| mask & (1 << (15 - 1)) != 0) {
            return;
        }
        assert!(
            std::time::Instant::now() < deadline,
            "process {pid} did not install a SIGTERM handler within {limit:?}"
        );
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
}
