"""Our certified trajectories beside TOPP-RA's on the same waypoints and limits.

    cargo run --release -p mit-star-robot --example trajectory_peers -- plan target/mbm 25 target/peers
    /work/venv/bin/python benches/peers/toppra/compare.py target/peers          # run TOPP-RA
    cargo run --release -p mit-star-robot --example trajectory_peers -- check target/mbm target/peers
    /work/venv/bin/python benches/peers/toppra/compare.py target/peers --table  # the table

For each `SCENE/NNNN.path.json` the example wrote (a simplified Panda path, the Panda URDF's
velocity limits and MoveIt's Panda acceleration limits), this runs TOPP-RA 0.6: a cubic
`SplineInterpolator` through the waypoints (parameterised by cumulative joint-space distance,
not-a-knot), `JointVelocityConstraint` and `JointAccelerationConstraint` with the same limits,
`TOPPRA(..., parametrizer="ParametrizeConstAccel")`, from rest to rest. It times the TOPP-RA
call (spline, constraints, `compute_trajectory`), samples the result every millisecond into
`SCENE/NNNN.toppra.json` (our trajectory file format) for the example's collision check, and
with `--table` prints per scene, independently of both sides' code:

- durations (ours blended, TOPP-RA) and their ratio;
- computation times (ours: `Trajectory::blended` with its blend certifications, not the
  certifier's construction; TOPP-RA: the call above);
- the largest relative limit violation of each side's 1 ms samples, max over joints and samples
  of `|v|/V - 1` and `|a|/A - 1` from the samples' own velocities and accelerations, and of the
  finite differences `|dq/dt|/V - 1` and `|dv/dt|/A - 1` (a mean over an interval cannot exceed
  the bound either);
- collisions: ours by `check_trajectory` (the example), TOPP-RA's by certifying its samples as
  a polyline against the scene (`check` mode of the example).
"""

import json
import sys
import time
from pathlib import Path

import numpy as np
import toppra as ta
import toppra.algorithm as algo
import toppra.constraint as constraint

PERIOD = 1e-3


def run_toppra(record):
    """TOPP-RA on one path: (trajectory or None, seconds)."""
    waypoints = np.asarray(record["waypoints"], dtype=float)
    vlim = np.asarray(record["velocity_limits"], dtype=float)
    alim = np.asarray(record["acceleration_limits"], dtype=float)
    started = time.perf_counter()
    steps = np.linalg.norm(np.diff(waypoints, axis=0), axis=1)
    ss = np.concatenate([[0.0], np.cumsum(steps)])
    path = ta.SplineInterpolator(ss, waypoints)
    velocity = constraint.JointVelocityConstraint(np.stack([-vlim, vlim], axis=1))
    acceleration = constraint.JointAccelerationConstraint(np.stack([-alim, alim], axis=1))
    instance = algo.TOPPRA([velocity, acceleration], path, parametrizer="ParametrizeConstAccel")
    trajectory = instance.compute_trajectory(0, 0)
    return trajectory, time.perf_counter() - started


def violation(t, q, v, a, vlim, alim):
    """The largest relative limit violation of samples (rows of q, v, a at times t)."""
    worst = max(np.max(np.abs(v) / vlim), np.max(np.abs(a) / alim)) - 1.0
    dt = np.diff(t)[:, None]
    worst = max(worst, np.max(np.abs(np.diff(q, axis=0)) / dt / vlim) - 1.0)
    worst = max(worst, np.max(np.abs(np.diff(v, axis=0)) / dt / alim) - 1.0)
    return float(worst)


def sample_toppra(trajectory):
    duration = trajectory.duration
    t = np.append(np.arange(0.0, duration, PERIOD), duration)
    return t, trajectory(t), trajectory(t, 1), trajectory(t, 2)


def toppra_pass(folder):
    for path_file in sorted(folder.glob("*/*.path.json")):
        record = json.loads(path_file.read_text())
        trajectory, seconds = run_toppra(record)
        out = {"toppra_seconds": seconds, "toppra_ok": trajectory is not None}
        if trajectory is not None:
            vlim = np.asarray(record["velocity_limits"])
            alim = np.asarray(record["acceleration_limits"])
            t, q, v, a = sample_toppra(trajectory)
            out["toppra_duration"] = float(trajectory.duration)
            out["toppra_violation"] = violation(t, q, v, a, vlim, alim)
            samples = [
                {"time": float(t[i]), "position": q[i].tolist(), "velocity": v[i].tolist(),
                 "acceleration": a[i].tolist()}
                for i in range(len(t))
            ]
            name = path_file.name.replace(".path.json", ".toppra.json")
            (path_file.parent / name).write_text(json.dumps({"joints": record["joints"], "samples": samples}))
        (path_file.parent / path_file.name.replace(".path.json", ".toppra_run.json")).write_text(json.dumps(out))
        print(path_file, out.get("toppra_duration"), record["blended_duration"], flush=True)


def ours_violation(record, ours_file):
    data = json.loads(ours_file.read_text())
    s = data["samples"]
    t = np.array([x["time"] for x in s])
    q = np.array([x["position"] for x in s])
    v = np.array([x["velocity"] for x in s])
    a = np.array([x["acceleration"] for x in s])
    return violation(t, q, v, a, np.asarray(record["velocity_limits"]), np.asarray(record["acceleration_limits"]))


def table(folder):
    print("| scene | paths | median duration ours (s) | median TOPP-RA (s) | median ratio | max ratio | paths > 1.05x "
          "| median ratio, TOPP-RA collision-free | median compute ours (ms) | median TOPP-RA (ms) | median compute ratio | max violation ours | max violation TOPP-RA "
          "| collisions ours | TOPP-RA colliding | TOPP-RA outside position limits |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    totals = []
    for scene in sorted(p for p in folder.iterdir() if p.is_dir()):
        rows = []
        for path_file in sorted(scene.glob("*.path.json")):
            stem = path_file.name.replace(".path.json", "")
            record = json.loads(path_file.read_text())
            run = json.loads((scene / f"{stem}.toppra_run.json").read_text())
            check_file = scene / f"{stem}.toppra_check.json"
            check = json.loads(check_file.read_text()) if check_file.exists() else None
            if not run["toppra_ok"]:
                continue
            rows.append({
                "ours": record["blended_duration"],
                "toppra": run["toppra_duration"],
                "ours_ms": record["timing_seconds"] * 1e3,
                "toppra_ms": run["toppra_seconds"] * 1e3,
                "ours_violation": ours_violation(record, scene / f"{stem}.ours.json"),
                "toppra_violation": run["toppra_violation"],
                "ours_collides": not record["check_valid"],
                "toppra_collides": None if check is None else not check["collision_free"],
                "toppra_outside": None if check is None else check["outside_position_limits"] > 0,
            })
        if not rows:
            continue
        totals.extend(rows)
        print(line(scene.name.removesuffix("_panda"), rows))
    print(line("all", totals))


def line(name, rows):
    col = lambda k: np.array([r[k] for r in rows], dtype=float)
    ratio = col("ours") / col("toppra")
    compute = col("ours_ms") / col("toppra_ms")
    free = np.array([r["ours"] / r["toppra"] for r in rows if r["toppra_collides"] is False])
    free_text = f"{np.median(free):.3f} ({len(free)})" if len(free) else "n/a"
    count = lambda k: "n/a" if any(r[k] is None for r in rows) else str(sum(bool(r[k]) for r in rows))
    return (f"| {name} | {len(rows)} | {np.median(col('ours')):.3f} | {np.median(col('toppra')):.3f} | {np.median(ratio):.3f} "
            f"| {ratio.max():.3f} | {int((ratio > 1.05).sum())} | {free_text} | {np.median(col('ours_ms')):.3f} | {np.median(col('toppra_ms')):.2f} "
            f"| {np.median(compute):.3f} | {col('ours_violation').max():.1e} | {col('toppra_violation').max():.1e} "
            f"| {sum(r['ours_collides'] for r in rows)} | {count('toppra_collides')} | {count('toppra_outside')} |")


if __name__ == "__main__":
    folder = Path(sys.argv[1] if len(sys.argv) > 1 else "target/peers")
    if "--table" in sys.argv:
        table(folder)
    else:
        toppra_pass(folder)
