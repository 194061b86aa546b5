#!/usr/bin/env bash
# VAMP's RRT-Connect on the Panda MotionBenchMaker problems with a count of the blocks of eight
# configurations it checks per solve. W = the work folder of ../shared/peers/vamp/build_vamp.sh.
#   W=… ./count_blocks.sh OUT
set -euo pipefail
OUT=${1:?usage: count_blocks.sh OUT}
: "${W:?set W to the VAMP work folder}"
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
mkdir -p "$OUT"
rm -rf "$OUT/impl" && cp -r "$W/src/src/impl" "$OUT/impl"
python3 - "$OUT/impl/vamp/planning/validate.hh" <<'PY'
import sys
p = sys.argv[1]; s = open(p).read()
s = s.replace("namespace vamp::planning\n{", "namespace vamp::planning\n{\n    inline std::size_t measured_blocks = 0;\n", 1)
s = s.replace("        bool valid = (environment.attachments)", "        ++measured_blocks;\n        bool valid = (environment.attachments)", 1)
s = s.replace("        for (auto i = 1U; i < n; ++i)\n        {", "        for (auto i = 1U; i < n; ++i)\n        {\n            ++measured_blocks;", 1)
open(p, "w").write(s)
PY
sed 's|auto result = RRTC::solve(Robot::Configuration(p.start), goals, env_v, settings, rng);|vamp::planning::measured_blocks = 0; auto result = RRTC::solve(Robot::Configuration(p.start), goals, env_v, settings, rng); auto blocks = vamp::planning::measured_blocks;|; s|std::cout << p.scene << "," << p.index << "," << result.nanoseconds|std::cout << p.scene << "," << p.index << "," << blocks << "," << result.nanoseconds|; s|std::cout << "scene,index,plan_us|std::cout << "scene,index,blocks,plan_us|' \
  "$W/cpp/vamp_mbm.cc" > "$OUT/vamp_count.cc"
vamp_compile "$OUT/impl" "$OUT/vamp_count" "$OUT/vamp_count.cc"
pinned "$OUT/vamp_count" "$W/cpp/panda_mbm.txt" 1 > "$OUT/blocks.csv"
python3 - "$OUT/blocks.csv" <<'PY'
import csv, statistics as st, sys, collections
rows = collections.defaultdict(list)
for r in csv.DictReader(open(sys.argv[1])):
    rows[r["scene"]].append(r)
print("| scene | problems | median plan µs | median blocks | configurations | ns per configuration (all time) |")
print("|---|---|---|---|---|---|")
for scene, rs in sorted(rows.items()):
    b = [int(r["blocks"]) for r in rs]; t = [float(r["plan_us"]) for r in rs]
    print(f"| {scene} | {len(rs)} | {st.median(t):.0f} | {st.median(b):.0f} | {8 * st.median(b):.0f} | {1000 * sum(t) / sum(b) / 8:.0f} |")
PY
