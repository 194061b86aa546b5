#!/usr/bin/env bash
# Packages every crate of the workspace as crates.io would receive it (`cargo package` builds
# each from its own tarball), then builds and runs examples/dependent — a project of its own
# that depends on the crates by version — against those packaged sources, so that what a user
# downloads is what is tested. Usage: bash .ci/package.sh [TARGET_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:-target}
version=$(sed -n 's/^version = "\(.*\)"$/\1/p' Cargo.toml | head -1)
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
