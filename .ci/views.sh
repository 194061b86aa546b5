#!/usr/bin/env bash
# Writes the 3-D view pages CI opens in headless Chromium (and the guide's screenshots are
# taken from): every shipped robot, box worlds in 2-D and 3-D with the search, a refused path
# marked red, a timed trajectory, a re-planning trial and an experiment report's views.
# Usage: .ci/views.sh OUT_DIR   (run from the repository root; builds the release binary)
set -euo pipefail
out=${1:?usage: .ci/views.sh OUT_DIR}
mkdir -p "$out" target
cargo build --release --locked -q -p mit-star-benches
tool=target/release/mit-star
for robot in panda ur5 fetch baxter; do
  case $robot in
    panda) archive=robot/data/panda/mbm_problems.tar.bz2; folder=target/bookshelf_small_panda ;;
    baxter) archive=robot/data/baxter/problems.tar.bz2
      folder=target/problems/bookshelf_tall_both_arms_easy_baxter ;;
    *) archive=robot/data/$robot/problems.tar.bz2; folder=target/problems/box_$robot ;;
  esac
  [ -d "$folder" ] || tar xjf "$archive" -C target/
done
quiet() { "$@" >/dev/null 2>&1 || { echo "failed: $*" >&2; "$@"; }; }
# Arms: the Panda on bookshelf_small (simplified, timed, with the search), each other robot.
# Instance 4: MIT* prunes its graph to the informed set, and on #3, whose path is within 0.5 %
# of the straight line, that set is so thin that the search overlay changed 0.014-0.022 % of
# the pixels (the toggle check wants 0.02 %); on #4 it changes 0.17-0.21 % at 0.1 s and 1 s.
quiet $tool plan --problem mbm:target/bookshelf_small_panda --instance 4 --planner mit-star \
  --time 1 --simplify --trajectory "$out/panda.json" \
  --joint-limits robot/data/panda/joint_limits.yaml --view "$out/panda-bookshelf_small.html" \
  --view-search --no-picture
quiet $tool plan --robot ur5 --problem mbm:target/problems/box_ur5 --instance 1 \
  --planner rrt-connect --time 1 --view "$out/ur5-box.html" --no-picture
quiet $tool plan --robot fetch --problem mbm:target/problems/box_fetch --instance 1 \
  --planner rrt-connect --time 1 --view "$out/fetch-box.html" --no-picture
quiet $tool plan --robot baxter --problem mbm:target/problems/bookshelf_tall_both_arms_easy_baxter \
  --instance 1 \
  --planner rrt-connect --time 1 --view "$out/baxter-bookshelf_tall.html" --no-picture
# Each shipped robot on its own, every joint through its range, spheres and meshes.
for robot in panda ur5 fetch baxter; do
  quiet $tool robots $robot --view "$out/robot-$robot.html"
done
# Box worlds with the search and the informed set.
quiet $tool plan --problem wall-gap --dim 2 --time 0.3 --view "$out/world-2d.html" \
  --view-search --no-picture
quiet $tool plan --problem random-rectangles --dim 3 --time 0.3 --view "$out/world-3d.html" \
  --view-search --no-picture
# A path through the wall, refused: its configurations in collision drawn red.
printf -- '-0.3 0\n0.3 0\n' > "$out/through-wall.txt"
$tool check-path --problem wall-gap --dim 2 --path "$out/through-wall.txt" \
  --view "$out/refused-2d.html" >/dev/null || true
# The timed trajectory checked, viewed over time.
quiet $tool check-path --problem mbm:target/bookshelf_small_panda --instance 4 \
  --trajectory "$out/panda.json" --joint-limits robot/data/panda/joint_limits.yaml \
  --view "$out/panda-trajectory.html"
# A re-planning trial among moving obstacles.
quiet $tool replan --scenes horizontal --planners rrt-connect --trials 1 --legs 1 \
  --iterations 2000 --output "$out/replan" --no-picture --view
# An experiment's report and its views.
quiet $tool bench --planners rrt-connect,mit-star --problem mbm:target/problems/box_ur5 \
  --robot ur5 --instances 2 --runs 2 --time 0.2 --output "$out/bench" -q
ls "$out"/*.html "$out"/bench/report.html "$out"/replan/*.html "$out"/bench/views/*.html
