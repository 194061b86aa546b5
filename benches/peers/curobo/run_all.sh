#!/bin/bash
# Held-out robots from cuRobo's sphere models: convert, generate 24 table/shelf problems each,
# plan with RRT-Connect, MIT* and AORRTC at 1 s, audit every path (`mit-star bench`).
#
#   benches/peers/curobo/run_all.sh [OUT=target/curobo]
#
# Needs the cuRobo mirror (convert.py says where), /work/venv with PyYAML and numpy, and
#   cargo build --release --bin mit-star && cargo build --release -p mit-star-robot --example held_out
# Runs are pinned to CPU 1 at top priority (CPU=… overrides). Nothing of cuRobo is committed:
# the converted models, meshes and problems stay under OUT.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-target/curobo}
target=${CARGO_TARGET_DIR:-target}
mit=$target/release/mit-star
gen=$target/release/examples/held_out
py=${PYTHON:-/work/venv/bin/python}
cpu=${CPU:-1}
mkdir -p "$out/runs"

convert() { "$py" "$here/convert.py" "$@"; }
convert --rev HEAD --yml curobo/content/configs/robot/ur10e.yml --out "$out/ur10e"
convert --rev HEAD --yml curobo/content/configs/robot/dual_ur10e.yml --out "$out/dual_ur10e"
convert --rev HEAD --yml curobo/content/configs/robot/unitree_g1.yml --out "$out/unitree_g1"
convert --rev 3690d28 --yml src/curobo/content/configs/robot/iiwa.yml --out "$out/iiwa"
convert --rev 3690d28 --yml src/curobo/content/configs/robot/kinova_gen3.yml \
    --out "$out/kinova_gen3" --meshes
# The mimic robot: refused by the loader (multiplier -1.5), converted to show the error.
convert --rev HEAD --yml curobo/content/configs/robot/simple_mimic_robot.yml \
    --out "$out/simple_mimic_robot" --no-lock --box-spheres
"$mit" robots "$out/simple_mimic_robot/simple_mimic_robot_spherized.urdf" || true

# The capped cover of the Kinova Gen3's meshes (the gripper's meshes are Git LFS pointers in
# the mirror: those three links keep cuRobo's spheres).
mkdir -p "$out/kinova_gen3/capped"
if [ ! -f "$out/kinova_gen3/capped/kinova_gen3_spherized.urdf" ]; then
    "$mit" spherise "$out/kinova_gen3/kinova_gen3_mesh/kinova_gen3.urdf" --tolerance 0.02 \
        --max-spheres 100 \
        --fallback "$out/kinova_gen3/kinova_gen3_spherized.urdf" \
        --output "$out/kinova_gen3/capped/kinova_gen3_spherized.urdf"
fi
cp "$out/kinova_gen3/kinova_gen3.srdf" "$out/kinova_gen3/capped/"

bench() { # URDF PROBLEMS LABEL
    uptime
    setsid bash -c 'echo -20 > /proc/self/autogroup; exec nice -n -20 taskset -c "$0" "$@"' \
        "$cpu" "$mit" bench --problem "mbm:$2" --robot "$1" \
        --planners rrt-connect,mit-star,aorrtc --runs 1 --time 1 --instances 24 --threads 1 \
        --output "$out/runs/$3" > "$out/runs/$3.log" 2>&1
    echo "== $3"
    grep -E '^\| .*layouts\) \| (RRT-Connect|MIT\*|AORRTC) \| [0-9]+ \|' "$out/runs/$3.log"
    grep 'Independent audit' "$out/runs/$3.log"
    uptime
}
for robot in iiwa kinova_gen3 ur10e dual_ur10e unitree_g1; do
    [ -d "$out/problems/$robot" ] ||
        "$gen" "$out/$robot/${robot}_spherized.urdf" "$out/problems/$robot" 24 1
    bench "$out/$robot/${robot}_spherized.urdf" "$out/problems/$robot" "$robot"
done
# The dual UR10e's ends drawn within the middle 30 % of each joint's range.
[ -d "$out/problems/dual_ur10e_s03" ] ||
    "$gen" "$out/dual_ur10e/dual_ur10e_spherized.urdf" "$out/problems/dual_ur10e_s03" 24 1 0.3
bench "$out/dual_ur10e/dual_ur10e_spherized.urdf" "$out/problems/dual_ur10e_s03" dual_s03
# Capped cover against cuRobo's spheres, on problems drawn for the (fatter) capped model.
[ -d "$out/problems/kinova_capped" ] ||
    "$gen" "$out/kinova_gen3/capped/kinova_gen3_spherized.urdf" "$out/problems/kinova_capped" 24 1
bench "$out/kinova_gen3/kinova_gen3_spherized.urdf" "$out/problems/kinova_capped" kc_hand
bench "$out/kinova_gen3/capped/kinova_gen3_spherized.urdf" "$out/problems/kinova_capped" kc_capped
