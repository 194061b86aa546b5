#!/usr/bin/env bash
# Packages every crate of the workspace as crates.io would receive it (`cargo package` builds
# each from its own tarball), then builds and runs examples/dependent — a project of its own
# that depends on the crates by version — against those packaged sources, so that what a user
# downloads is what is tested. Usage: bash .ci/package.sh [TARGET_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:-target}
version=$(sed -n 's/^version = "\(.*\)"$/\1/p' Cargo.toml | head -1)
# Cargo unpacks a crate of a registry into CARGO_HOME once per name and version and reuses the
# unpacked sources after: a workspace crate's sources from an earlier run (the crates are
# always 0.1.0 here) would be compiled instead of this run's, and a change that one crate's API
# makes for another fails the verification. Drop them, so that this run's are unpacked.
cargo_home=${CARGO_HOME:-$HOME/.cargo}
rm -rf "$cargo_home"/registry/src/*/mit-star*-"$version" "$cargo_home"/registry/cache/*/mit-star*-"$version".crate
cargo package --workspace --locked --target-dir "$target"
patches=()
for dir in "$target"/package/mit-star*-"$version"; do
  [ -d "$dir" ] || continue
  name=$(basename "$dir" "-$version")
  patches+=(--config "patch.crates-io.$name.path=\"$PWD/$dir\"")
done
[ ${#patches[@]} -ge 8 ] || { echo "package: expected the unpacked crates in $target/package, found ${#patches[@]}" >&2; exit 1; }
cargo run --locked --release --manifest-path examples/dependent/Cargo.toml \
  --target-dir "$target/dependent" "${patches[@]}"
