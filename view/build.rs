//! Bundles the page's JavaScript (view/web) with three.js into `$OUT_DIR/viewer.js`, and copies
//! three.js's licence to `$OUT_DIR/three-license.txt`.
//!
//! Needs Node.js (>= 18) and npm. In a git checkout, `npm ci` runs in view/web when its
//! node_modules is missing or holds other versions than package-lock.json pins. Built from a
//! package (a registry download, `cargo package`'s verification), the crate's source is never
//! written to: the page's sources are copied into `$OUT_DIR/web` and installed there.

use std::env;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

const HOW: &str = "the view crate bundles its page with esbuild at build time and needs Node.js \
(>= 18) and npm: install them (Debian/Ubuntu: `apt-get install -y nodejs npm`), then run \
`npm ci --no-audit --no-fund` in view/web";

/// The version a package.json or a package-lock.json entry gives.
fn version_of(value: &serde_json::Value) -> Option<String> {
    value.get("version")?.as_str().map(str::to_owned)
}

/// The versions of the packages the bundle is made with, as package-lock.json pins them.
fn pinned(web: &Path) -> Vec<(String, String)> {
    let text = fs::read_to_string(web.join("package-lock.json"))
        .unwrap_or_else(|e| panic!("view: cannot read view/web/package-lock.json: {e}"));
    let lock: serde_json::Value = serde_json::from_str(&text)
        .unwrap_or_else(|e| panic!("view: view/web/package-lock.json is not JSON: {e}"));
    ["three", "esbuild"]
        .iter()
        .map(|name| {
            let entry = &lock["packages"][format!("node_modules/{name}")];
            let version = version_of(entry)
                .unwrap_or_else(|| panic!("view: package-lock.json does not pin {name}"));
            ((*name).to_owned(), version)
        })
        .collect()
}

/// Whether node_modules holds exactly the pinned versions.
fn installed_matches(web: &Path, pins: &[(String, String)]) -> bool {
    pins.iter().all(|(name, version)| {
        let manifest = web.join("node_modules").join(name).join("package.json");
        fs::read_to_string(manifest)
            .ok()
            .and_then(|text| serde_json::from_str::<serde_json::Value>(&text).ok())
            .and_then(|json| version_of(&json))
            .is_some_and(|v| &v == version)
    })
}

fn run(command: &mut Command, what: &str) {
    match command.status() {
        Ok(status) if status.success() => {}
        Ok(status) => panic!("view: `{what}` failed ({status}); {HOW}"),
        Err(e) => panic!("view: cannot run `{what}` ({e}); {HOW}"),
    }
}

/// `npm ci` in `web`, then the check that it installed the pinned versions.
fn install(web: &Path, pins: &[(String, String)], shown: &str) {
    run(
        Command::new("npm")
            .args(["ci", "--no-audit", "--no-fund"])
            .current_dir(web),
        &format!("npm ci --no-audit --no-fund (in {shown})"),
    );
    assert!(
        installed_matches(web, pins),
        "view: after `npm ci`, {shown}/node_modules still differs from package-lock.json; {HOW}"
    );
}

/// Copies `names` (files or folders) of `from` into `to`, replacing what `to` held.
fn copy_tree(from: &Path, to: &Path, names: &[&str]) {
    fn copy(from: &Path, to: &Path) -> std::io::Result<()> {
        if from.is_dir() {
            fs::create_dir_all(to)?;
            for entry in fs::read_dir(from)? {
                let entry = entry?;
                copy(&entry.path(), &to.join(entry.file_name()))?;
            }
            Ok(())
        } else {
            fs::copy(from, to).map(drop)
        }
    }
    fs::create_dir_all(to).unwrap_or_else(|e| panic!("view: cannot create {}: {e}", to.display()));
    for name in names {
        copy(&from.join(name), &to.join(name))
            .unwrap_or_else(|e| panic!("view: cannot copy {} into {}: {e}", name, to.display()));
    }
}

fn main() {
    let manifest = PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets it"));
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets it"));
    let web = manifest.join("web");
    // npm's own record of what node_modules holds: a reinstall or a removal reruns this.
    for path in [
        "web/src",
        "web/package.json",
        "web/package-lock.json",
        "web/node_modules/.package-lock.json",
    ] {
        println!("cargo:rerun-if-changed={path}");
    }
    let pins = pinned(&web);
    for (name, version) in &pins {
        println!(
            "cargo:rustc-env=VIEW_{}_VERSION={version}",
            name.to_ascii_uppercase()
        );
    }
    let web = if installed_matches(&web, &pins) {
        web
    } else if manifest.join("../.git").exists() {
        install(&web, &pins, "view/web");
        web
    } else {
        let copy = out.join("web");
        copy_tree(&web, &copy, &["src", "package.json", "package-lock.json"]);
        install(&copy, &pins, "$OUT_DIR/web");
        copy
    };
    let bundle = out.join("viewer.js");
    run(
        Command::new(web.join("node_modules/.bin/esbuild"))
            .args([
                "src/main.js",
                "--bundle",
                "--minify",
                "--format=iife",
                "--target=es2020",
                "--legal-comments=none",
                "--log-level=warning",
            ])
            .arg(format!("--outfile={}", bundle.display()))
            .current_dir(&web),
        "esbuild src/main.js --bundle (in view/web)",
    );
    let script = fs::read_to_string(&bundle)
        .unwrap_or_else(|e| panic!("view: esbuild wrote no readable {}: {e}", bundle.display()));
    let lower = script.to_ascii_lowercase();
    assert!(
        !lower.contains("</script") && !lower.contains("<!--"),
        "view: the bundle contains `</script` or `<!--`, which would end its <script> element early"
    );
    fs::copy(
        web.join("node_modules/three/LICENSE"),
        out.join("three-license.txt"),
    )
    .unwrap_or_else(|e| panic!("view: cannot copy three.js's licence: {e}"));
}
