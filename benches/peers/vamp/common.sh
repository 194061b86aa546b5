# Sourced by the helpers in this folder (not run by itself).
#
# vamp_compile IMPL BINARY SOURCE… — compiles a C++ harness against VAMP's headers in IMPL (the
#   work folder's `$W/src/src/impl`, or a patched copy) with the flags of VAMP's CMake Release
#   build, as ../shared/peers/vamp/build_vamp.sh compiles `vamp_mbm`; needs W.
# pinned COMMAND… — runs COMMAND in its own session at the highest priority, pinned to CPU
#   ${CPU:-0} (plain `nice` does nothing across sessions when the kernel groups by session).
# ours_scene BINARY OUT SCENE [ARGUMENT…] — our side of the shared side_by_side.sh for one
#   scene, pinned: `BINARY bench` with RRT-Connect on problems 1–100 of `$MBM/SCENE_panda`,
#   range 1, to the first solution, one thread, the extra ARGUMENTs added; results in OUT/SCENE,
#   its output in OUT/SCENE.log; needs MBM.

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

ours_scene() {
  local binary=$1 out=$2 scene=$3
  shift 3
  pinned "$binary" bench --planners rrt-connect --problem "mbm:$MBM/${scene}_panda" --instances 1-100 \
    --time 1 --runs 1 --threads 1 --first-solution --set range=1.0 --no-plots -q "$@" \
    --output "$out/$scene" > "$out/$scene.log" 2>&1
}
