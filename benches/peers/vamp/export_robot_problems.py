#!/usr/bin/env python3
"""Another robot's MotionBenchMaker problems (VAMP's `resources/<robot>/problems.tar.bz2`,
MoveIt YAML) in the text format of the shared export_problems.py, for the C++ harnesses of
this folder built for that robot (mbm_problems.hh, `-DMBM_ROBOT=…`).

Run with the Python of VAMP's work folder ($W/venv/bin/python): the scenes and requests are
read by VAMP's own functions (`load_moveit_yaml_scene`, `load_moveit_yaml_request` of its
`resources/problem_tar_to_pkl_json.py`), so that the obstacles are VAMP's reading of the
files. That script itself cannot make the robot's `problems.pkl` when VAMP's Python module was
built for the Panda only (as `build_vamp.sh` builds it): it checks each start and goal with the
robot's module. So every problem is written as valid here, and the comparison keeps the
problems whose start and goal our side finds valid (anytime_table.py takes the problems both
sides ran).

    $W/venv/bin/python export_robot_problems.py $W/src/resources ur5 OUT.txt
"""
import re
import sys
import tarfile
from pathlib import Path

# The joint order of VAMP's robot (vamp/robots/<robot>.hh, `joint_names`).
JOINTS = {
    "ur5": ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint",
            "wrist_2_joint", "wrist_3_joint"],
    "fetch": ["torso_lift_joint", "shoulder_pan_joint", "shoulder_lift_joint",
              "upperarm_roll_joint", "elbow_flex_joint", "forearm_roll_joint",
              "wrist_flex_joint", "wrist_roll_joint"],
}


def main():
    resources, robot, out = Path(sys.argv[1]), sys.argv[2], sys.argv[3]
    sys.path.insert(0, str(resources))
    from problem_tar_to_pkl_json import load_moveit_yaml_request, load_moveit_yaml_scene
    from yaml import CLoader, load

    joints = JOINTS[robot]
    scenes, requests = {}, {}
    with tarfile.open(resources / robot / "problems.tar.bz2", "r:bz2") as tar:
        for member in tar.getmembers():
            if not member.isfile():
                continue
            _, folder, filename = member.name.split("/")
            scene = folder.replace(f"_{robot}", "")
            index = int(re.findall(r"\d+", filename)[0])
            data = load(tar.extractfile(member).read(), Loader=CLoader)
            if filename.startswith("scene"):
                scenes[(scene, index)] = load_moveit_yaml_scene(data)
            else:
                requests[(scene, index)] = load_moveit_yaml_request(data, joints)
    fl = lambda xs: " ".join(repr(float(x)) for x in xs)
    with open(out, "w") as f:
        for scene, index in sorted(scenes):
            objects, request = scenes[(scene, index)], requests[(scene, index)]
            f.write(f"P {scene} {index} 1 {len(request['goals'])}\n")
            f.write(f"S {fl(request['start'])}\n")
            for goal in request["goals"]:
                f.write(f"G {fl(goal)}\n")
            for o in objects["sphere"]:
                f.write(f"sphere {fl(o['position'])} {float(o['radius'])!r}\n")
            for o in objects["cylinder"]:
                # As vamp.problem_dict_to_vamp: the box scene's cylinders become cuboids.
                if scene == "box":
                    f.write(f"cuboid {fl(o['position'])} {fl(o['orientation_euler_xyz'])} "
                            f"{fl([o['radius'], o['radius'], o['length'] / 2])}\n")
                else:
                    f.write(f"capsule {fl(o['position'])} {fl(o['orientation_euler_xyz'])} "
                            f"{float(o['radius'])!r} {float(o['length'])!r}\n")
            for o in objects["box"]:
                f.write(f"cuboid {fl(o['position'])} {fl(o['orientation_euler_xyz'])} "
                        f"{fl(o['half_extents'])}\n")
            f.write("E\n")
    print(f"wrote {out}: {len(scenes)} problems")


if __name__ == "__main__":
    main()
