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
