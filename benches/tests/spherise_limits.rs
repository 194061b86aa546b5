//! `mit-star spherise` on hostile inputs (issue 74, item 14): a tolerance of 10⁻⁹ m or a mesh
//! scaled by 10³⁰ is refused with a named error before any work, and the first SIGTERM stops
//! a long cover within seconds. Each command runs with a deadline: past it the test kills the
//! process and fails (the old code covered for minutes, the first SIGTERM ignored).

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

/// How long a refusal or a stop may take: generous for a loaded machine, far below the
/// minutes the work would take.
const DEADLINE: Duration = Duration::from_secs(60);

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("spherise-limits-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn ur5() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../robot/data/ur5")
}

fn spawn(args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_mit-star"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

/// Waits for `child` until `deadline`; kills it and fails past that.
fn finish(mut child: Child, deadline: Instant, what: &str) -> Output {
    while child.try_wait().unwrap().is_none() {
        if Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{what}: still running after the deadline");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    child.wait_with_output().unwrap()
}

/// A one-link URDF with `geometry` as its collision.
fn urdf(dir: &Path, geometry: &str) -> PathBuf {
    let path = dir.join("robot.urdf");
    std::fs::write(
        &path,
        format!(
            r#"<robot name="r">
  <link name="big"><collision><geometry>{geometry}</geometry></collision></link>
  <link name="tip"/>
  <joint name="j" type="revolute"><parent link="big"/><child link="tip"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>"#
        ),
    )
    .unwrap();
    path
}

#[test]
fn a_tolerance_or_scale_beyond_the_work_cap_is_refused_at_once() {
    let dir = scratch("cap");
    let wrist = ur5().join("meshes/ur5/collision/wrist3.stl");
    let cases = [
        (
            r#"<box size="0.3 0.2 0.1"/>"#.to_owned(),
            "1e-9",
            "link `big`: a mesh 3.000e-1 m across",
        ),
        (
            format!(
                r#"<mesh filename="{}" scale="1e30 1e30 1e30"/>"#,
                wrist.display()
            ),
            "0.01",
            "link `big`: a mesh",
        ),
    ];
    for (geometry, tolerance, named) in cases {
        let input = urdf(&dir, &geometry);
        let output = dir.join("out.urdf");
        let child = spawn(&[
            "spherise",
            input.to_str().unwrap(),
            "--tolerance",
            tolerance,
            "-o",
            output.to_str().unwrap(),
        ]);
        let out = finish(child, Instant::now() + DEADLINE, &geometry);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{geometry}: {stderr}");
        for needle in [named, "grid cells (at most 4000000)", "raise --tolerance"] {
            assert!(stderr.contains(needle), "`{needle}` not in: {stderr}");
        }
        assert!(!output.exists());
    }
}

#[test]
fn the_first_sigterm_stops_a_long_cover_within_seconds() {
    let dir = scratch("sigterm");
    let output = dir.join("ur5_spherized.urdf");
    // The UR5's meshes at 3 mm: minutes of covering, even in a release build.
    let child = spawn(&[
        "spherise",
        ur5().join("meshes/ur5.urdf").to_str().unwrap(),
        "--package-root",
        ur5().to_str().unwrap(),
        "--fallback",
        ur5().join("ur5_spherized.urdf").to_str().unwrap(),
        "--tolerance",
        "0.003",
        "-o",
        output.to_str().unwrap(),
    ]);
    // The handler installed, then a second to begin covering.
    crate::common::wait_for_sigterm_handler(child.id());
    std::thread::sleep(Duration::from_secs(1));
    assert!(
        Command::new("kill")
            .args(["-TERM", &child.id().to_string()])
            .status()
            .unwrap()
            .success()
    );
    let out = finish(child, Instant::now() + DEADLINE, "spherise after SIGTERM");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(143), "{stderr}");
    assert!(stderr.contains("SIGTERM"), "{stderr}");
    assert!(!output.exists(), "nothing is written when stopped");
}
