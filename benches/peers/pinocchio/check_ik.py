"""Independent confirmation of `ik_bench`'s solutions with Pinocchio's forward kinematics.

    cargo run --release -p mit-star-robot --example ik_bench -- --out ik.json [--held-out URDF LINK]
    /work/venv/bin/python benches/peers/pinocchio/check_ik.py ik.json [--urdf NAME=PATH ...]

For every robot of the JSON file (its URDF, the solver's link, the planned joints in
coordinate order and the held joints' values), loads the URDF with Pinocchio, places the
link by Pinocchio's forward kinematics at every returned solution, and prints per robot the
largest position error (metres) and orientation error (radians, the angle of the rotation
between target and reached frame) against the targets. It also places the link at every
sampled configuration the targets were made from (by our forward kinematics) and prints the
largest disagreement: the targets themselves are confirmed. `--urdf NAME=PATH` loads another
URDF for robot NAME (the original, unspherised file of a held-out arm: the kinematics must
be the same).
"""

import argparse
import json
import sys

import numpy as np
import pinocchio as pin


def quaternion_matrix(x, y, z, w):
    """The rotation matrix of a unit quaternion (x, y, z, w)."""
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def configuration(model, values):
    """Pinocchio's configuration vector from joint values by name (others at 0)."""
    q = pin.neutral(model)
    for joint_id in range(1, model.njoints):
        name = model.names[joint_id]
        if name not in values:
            continue
        joint = model.joints[joint_id]
        value = values[name]
        if joint.nq == 2:  # a continuous joint: (cos, sin)
            q[joint.idx_q] = np.cos(value)
            q[joint.idx_q + 1] = np.sin(value)
        else:
            q[joint.idx_q] = value
    return q


def check(robot, urdf):
    model = pin.buildModelFromUrdf(urdf)
    data = model.createData()
    frame = model.getFrameId(robot["link"])
    if frame >= len(model.frames):
        sys.exit(f"{urdf}: no frame {robot['link']}")
    held = {name: value for name, value in robot["held"]}
    missing = [n for n in list(held) + robot["joints"] if not model.existJointName(n)]
    if missing:
        sys.exit(f"{urdf}: Pinocchio's model lacks joints {missing}")
    def errors(case, joints):
        """Position and orientation error of the link at `joints` against the target."""
        values = dict(held)
        values.update(zip(robot["joints"], joints))
        pin.framesForwardKinematics(model, data, configuration(model, values))
        placement = data.oMf[frame]
        target = quaternion_matrix(*case["quaternion"])
        position = np.linalg.norm(placement.translation - np.array(case["position"]))
        orientation = np.linalg.norm(pin.log3(target.T @ placement.rotation))
        return position, orientation

    worst, targets, solved = [0.0, 0.0], [0.0, 0.0], 0
    for case in robot["cases"]:
        for k, e in enumerate(errors(case, case["sampled"])):
            targets[k] = max(targets[k], e)
        if case["solution"] is None:
            continue
        solved += 1
        for k, e in enumerate(errors(case, case["solution"])):
            worst[k] = max(worst[k], e)
    return len(robot["cases"]), solved, worst, targets


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json", help="the file ik_bench --out wrote")
    parser.add_argument("--urdf", action="append", default=[], metavar="NAME=PATH")
    args = parser.parse_args()
    overrides = dict(o.split("=", 1) for o in args.urdf)
    with open(args.json) as f:
        robots = json.load(f)["robots"]
    print(f"Pinocchio {pin.__version__}")
    print(
        "| robot | URDF | solutions | max position error (m) | max orientation error (rad) "
        "| targets vs Pinocchio: position (m) | orientation (rad) |"
    )
    print("|---|---|---|---|---|---|---|")
    for robot in robots:
        urdf = overrides.get(robot["name"], robot["urdf"])
        cases, solved, (position, orientation), (tp, to) = check(robot, urdf)
        print(
            f"| {robot['name']} | {urdf.rsplit('/', 1)[-1]} | {solved}/{cases} "
            f"| {position:.2e} | {orientation:.2e} | {tp:.2e} | {to:.2e} |"
        )


if __name__ == "__main__":
    main()
