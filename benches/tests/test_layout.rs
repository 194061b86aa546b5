//! Each crate's integration tests are one binary (`tests/integration.rs`, `autotests = false`):
//! a test file that is not declared there would never be compiled. This test finds such files.

use std::fs;
use std::path::Path;

#[test]
fn every_test_file_of_the_workspace_is_a_module_of_its_crates_test_binary() {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root");
    let mut roots = 0;
    let mut forgotten = Vec::new();
    for entry in fs::read_dir(workspace).expect("workspace root is readable") {
        let tests = entry.expect("workspace entry").path().join("tests");
        let Ok(root) = fs::read_to_string(tests.join("integration.rs")) else {
            continue;
        };
        roots += 1;
        for file in fs::read_dir(&tests).expect("tests folder is readable") {
            let path = file.expect("tests entry").path();
            let Some(stem) = path.file_stem().and_then(|s| s.to_str()) else {
                continue;
            };
            let is_rust = path.extension().is_some_and(|e| e == "rs");
            if is_rust && stem != "integration" && !root.contains(&format!("mod {stem};")) {
                forgotten.push(path.display().to_string());
            }
        }
    }
    assert!(
        roots >= 6,
        "found {roots} crates with one test binary, expected at least 6"
    );
    assert!(
        forgotten.is_empty(),
        "test files not declared in their crate's tests/integration.rs (never compiled): {forgotten:?}"
    );
}
