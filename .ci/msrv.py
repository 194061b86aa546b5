#!/usr/bin/env python3
"""Checks that the workspace's `rust-version` (its minimum supported Rust) is honest.

This machine has one Rust toolchain and can fetch no other, so `cargo +<msrv> check` cannot
run here. What is checked instead:
1. no locked dependency (any target, any kind) declares a `rust-version` above ours: cargo
   would refuse to build it with our minimum;
2. the toolchain running CI is not older than our minimum;
3. (in `cargo clippy`, with `incompatible_msrv = "deny"`) no standard-library item newer than
   our minimum is used.
What is not checked: language features stabilised after the minimum.
"""
import json
import re
import subprocess
import sys


def version(text):
    parts = [int(p) for p in text.split(".")]
    return tuple(parts + [0] * (3 - len(parts)))


def main():
    meta = json.loads(subprocess.run(
        ["cargo", "metadata", "--format-version", "1", "--locked"],
        check=True, capture_output=True, text=True).stdout)
    ours = {p["id"] for p in meta["packages"] if p["id"] in meta["workspace_members"]}
    msrvs = {p["rust_version"] for p in meta["packages"] if p["id"] in ours}
    if len(msrvs) != 1 or None in msrvs:
        sys.exit(f"msrv: workspace crates must share one rust-version, found {sorted(map(str, msrvs))}")
    msrv = msrvs.pop()
    above = sorted(
        (p["rust_version"], p["name"], p["version"]) for p in meta["packages"]
        if p["id"] not in ours and p.get("rust_version")
        and version(p["rust_version"]) > version(msrv))
    if above:
        listed = ", ".join(f"{n} {v} (rust {r})" for r, n, v in above)
        sys.exit(f"msrv: rust-version {msrv} is below what locked dependencies need: {listed}")
    rustc = subprocess.run(["rustc", "--version"], check=True, capture_output=True, text=True).stdout
    found = re.search(r"rustc (\d+\.\d+\.\d+)", rustc).group(1)
    if version(found) < version(msrv):
        sys.exit(f"msrv: rustc {found} is older than the workspace's rust-version {msrv}")
    newest = max((version(p["rust_version"]), p["name"]) for p in meta["packages"]
                 if p["id"] not in ours and p.get("rust_version"))
    print(f"msrv: rust-version {msrv}; newest a dependency needs: "
          f"{'.'.join(map(str, newest[0][:2]))} ({newest[1]}); built with rustc {found}")


if __name__ == "__main__":
    main()
