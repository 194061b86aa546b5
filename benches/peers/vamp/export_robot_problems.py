#!/usr/bin/env python3
"""Another robot's MotionBenchMaker problems (VAMP's `resources/<robot>/problems.tar.bz2`,
MoveIt YAML) as the `problems.pkl` VAMP's `resources/problem_tar_to_pkl_json.py` makes, for
the shared `export_problems.py` to turn into the text the C++ harnesses of this folder read
when built for that robot (mbm_problems.hh, `-DMBM_ROBOT=…`).

Run with the Python of VAMP's work folder ($W/venv/bin/python): the scenes and requests are
read by VAMP's own functions (`load_moveit_yaml_scene`, `load_moveit_yaml_request`), so the
obstacles are VAMP's reading of the files. VAMP's script itself cannot make the robot's pkl
when VAMP's Python module was built for the Panda only (as `build_vamp.sh` builds it): it
checks each start and goal with the robot's module. So every problem is marked valid here,
and the comparison keeps the problems whose start and goal our side finds valid
(anytime_table.py takes the problems both sides ran).

    $W/venv/bin/python export_robot_problems.py $W/src/resources ur5 ur5.pkl
    python3 $W/cpp/export_problems.py ur5.pkl ur5_mbm.txt
"""
import pickle
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
            key = (folder.replace(f"_{robot}", ""), int(re.findall(r"\d+", filename)[0]))
            data = load(tar.extractfile(member).read(), Loader=CLoader)
            if filename.startswith("scene"):
                scenes[key] = load_moveit_yaml_scene(data)
            else:
                requests[key] = load_moveit_yaml_request(data, joints)
    problems = {}
    for scene, index in sorted(scenes):
        problems.setdefault(scene, []).append(
            {**scenes[(scene, index)], **requests[(scene, index)],
             "index": index, "problem": scene, "valid": True})
    with open(out, "wb") as f:
        pickle.dump({"robot": robot, "joints": joints, "problems": problems}, f)
    print(f"wrote {out}: {len(scenes)} problems")


if __name__ == "__main__":
    main()
