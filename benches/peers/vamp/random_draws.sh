#!/usr/bin/env bash
# VAMP's planners with independent random draws instead of its Halton sequence: how much of
# its lead on the Panda's MotionBenchMaker problems the sequence accounts for.
#
# VAMP's harness restarts one fixed Halton sequence before every problem, so each problem has
# one outcome. This builds the shared harness (RRT-Connect) and our vamp_anytime.cc (AORRTC
# over time) again with VAMP's own XORShift generator in place of the Halton one, keyed by
# each of KEYS, and prints per scene RRT-Connect's median iterations, tree states and planning
# time under both (Halton: the shared harness as it is), then AORRTC's pooled medians over the
# keys in SCENES (the time to a first solution and the cost at 10 ms, 100 ms and 1 s, as
# anytime_table.py reads them). W = the work folder of ../shared/peers/vamp/build_vamp.sh.
# OUT/w is then a work folder for the shared side_by_side.sh in which VAMP draws at random
# (XORShift with the first key): W=OUT/w BIN=… MBM=… side_by_side.sh SBS.
#   W=… [KEYS="2 5 7 11 13"] [SCENES=cage] [PER_SCENE=20] ./random_draws.sh OUT
set -euo pipefail
OUT=${1:?usage: random_draws.sh OUT}
: "${W:?set W to the VAMP work folder}"
KEYS=${KEYS:-2 5 7 11 13}
SCENES=${SCENES:-cage}
PER_SCENE=${PER_SCENE:-20}
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
mkdir -p "$OUT"
gcc -O3 -march=native -mavx2 -I"$W/deps/SIMDxorshift/include" \
  -c "$W/deps/SIMDxorshift/src/simdxorshift128plus.c" -o "$OUT/simdxorshift.o"
# The one change: the Halton generator becomes XORShift(VAMP_KEY, 3), restarted before every
# problem as the Halton one is; with VAMP_PER_PROBLEM=1 at run time, each problem's generator
# is keyed VAMP_KEY + 100000 · (index − 1) instead, so that no two problems of a scene share
# their draws (as our harness seeds its instances).
KEY='std::strtoul(std::getenv("VAMP_KEY"), nullptr, 10)'
RANDOM_RNG="std::shared_ptr<vamp::rng::RNG<Robot>> rng = std::make_shared<vamp::rng::XORShift<Robot>>($KEY, 3UL);"
RESEED="if (const char *per = std::getenv(\"VAMP_PER_PROBLEM\"); per \\&\\& *per == '1') rng = std::make_shared<vamp::rng::XORShift<Robot>>($KEY + 100000UL * (p.index - 1), 3UL); else rng->reset();"
for source in "$W/cpp/vamp_mbm.cc" "$HERE/vamp_anytime.cc"; do
  name=$(basename "$source" .cc)_random
  sed -e "s|auto rng = std::make_shared<vamp::rng::Halton<Robot>>();|$RANDOM_RNG|" \
    -e "s|rng->reset();|$RESEED|" \
    -e 's|#include <vamp/random/halton.hh>|#include <vamp/random/halton.hh>\n#include <vamp/random/xorshift.hh>\n#include <cstdlib>|' \
    "$source" > "$OUT/$name.cc"
  grep -q XORShift "$OUT/$name.cc" || { echo "no Halton generator to replace in $source" >&2; exit 1; }
  vamp_compile "$W/src/src/impl" "$OUT/$name" "$OUT/$name.cc" "$OUT/simdxorshift.o"
done
# A work folder for the shared side_by_side.sh whose VAMP draws at random (the first key).
mkdir -p "$OUT/w/cpp"
ln -sf "$W/cpp/panda_mbm.txt" "$OUT/w/cpp/panda_mbm.txt"
printf '#!/usr/bin/env bash\nVAMP_KEY=%s exec %q "$@"\n' "${KEYS%% *}" "$(cd "$OUT" && pwd)/vamp_mbm_random" \
  > "$OUT/w/cpp/vamp_mbm"
chmod +x "$OUT/w/cpp/vamp_mbm"
pinned "$W/cpp/vamp_mbm" "$W/cpp/panda_mbm.txt" 1 > "$OUT/rrtc.halton.csv"
for key in $KEYS; do
  VAMP_KEY=$key pinned "$OUT/vamp_mbm_random" "$W/cpp/panda_mbm.txt" 1 > "$OUT/rrtc.random.$key.csv"
done
python3 - "$OUT" <<'PY'
import csv, glob, statistics as st, sys, collections
out = sys.argv[1]
def table(paths):
    rows = collections.defaultdict(list)
    for path in paths:
        for r in csv.DictReader(open(path)):
            if r["solved"] == "1":
                rows[r["scene"]].append(r)
    return rows
halton, random = table([f"{out}/rrtc.halton.csv"]), table(sorted(glob.glob(f"{out}/rrtc.random.*.csv")))
m = lambda rs, k: st.median(float(r[k]) for r in rs)
print("RRT-Connect (range 1), medians per scene: Halton (one run) | random draws (all keys)")
print("| scene | iterations | iterations, random | states | states, random | plan µs | plan µs, random |")
print("|---|---|---|---|---|---|---|")
for scene in sorted(halton):
    h, r = halton[scene], random[scene]
    print(f"| {scene} | {m(h, 'iterations'):.0f} | {m(r, 'iterations'):.0f} | {m(h, 'graph_size'):.0f} "
          f"| {m(r, 'graph_size'):.0f} | {m(h, 'plan_us'):.0f} | {m(r, 'plan_us'):.0f} |")
PY
awk -v keep=",$SCENES," '/^P /{k = index(keep, "," $2 ",") > 0} k' "$W/cpp/panda_mbm.txt" > "$OUT/scenes.txt"
for key in $KEYS; do
  VAMP_KEY=$key pinned "$OUT/vamp_anytime_random" "$OUT/scenes.txt" "$PER_SCENE" 1 > "$OUT/aorrtc.random.$key.csv"
done
python3 - "$OUT" "$HERE" <<'PY'
import glob, sys, collections
sys.path.insert(0, sys.argv[2])
import anytime_table as A
runs = collections.defaultdict(list)
for path in sorted(glob.glob(f"{sys.argv[1]}/aorrtc.random.*.csv")):
    for (scene, _), row in A.vamp_rows(path).items():
        runs[scene].append(row)
print("\nVAMP's AORRTC with random draws, pooled over the keys")
print("| scene | runs | median t_first (ms) | cost at 10 ms | at 100 ms | at 1 s |")
print("|---|---|---|---|---|---|")
for scene, rows in sorted(runs.items()):
    cols = [A.median([r[i] for r in rows]) for i in range(4)]
    print(f"| {scene} | {len(rows)} | {cols[0]:.2f} | " + " | ".join(f"{c:.2f}" for c in cols[1:]) + " |")
PY
