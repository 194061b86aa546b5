# Sourced by the helpers in this folder (not run by itself).
#
# vamp_compile IMPL BINARY SOURCE… — compiles a C++ harness against VAMP's headers in IMPL (the
#   work folder's `$W/src/src/impl`, or a patched copy) with the flags of VAMP's CMake Release
#   build, as ../shared/peers/vamp/build_vamp.sh compiles `vamp_mbm`; needs W.
# pinned COMMAND… — runs COMMAND in its own session at the highest priority, pinned to CPU
#   ${CPU:-0} (plain `nice` does nothing across sessions when the kernel groups by session).

vamp_compile() {
  local impl=$1 binary=$2
  shift 2
  g++ -std=c++17 -O3 -DNDEBUG -march=native -mavx2 -fno-math-errno -fno-signed-zeros \
    -fno-trapping-math -fno-rounding-math -ffp-contract=fast -fassociative-math \
    -Wno-ignored-attributes -I"$impl" -isystem /usr/include/eigen3 -isystem "$W/deps/nigh/src" \
    -isystem "$W/deps/pdqsort" -I"$W/deps/SIMDxorshift/include" "$@" -o "$binary"
}

pinned() {
  setsid bash -c 'echo -20 > /proc/self/autogroup 2>/dev/null || true; exec nice -n -20 taskset -c "$0" "$@"' \
    "${CPU:-0}" "$@"
}
