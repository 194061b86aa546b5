#!/usr/bin/env python3
"""Convert a cuRobo robot configuration (its yml + URDF) into a sphere URDF and an SRDF that
`mit-star --robot path/to/NAME_spherized.urdf` loads.

Reads everything from the bare git snapshot of cuRobo's repository (nothing of cuRobo is
committed here): `--rev` a commit, `--yml` the configuration's path in that commit, e.g.

    convert.py --rev HEAD --yml curobo/content/configs/robot/ur10e.yml --out target/curobo/ur10e
    convert.py --rev 3690d28 --yml src/curobo/content/configs/robot/iiwa.yml \
        --out target/curobo/iiwa --meshes

What is written, in `--out`:
- `NAME_spherized.urdf`: the URDF with every `<collision>` and `<visual>` removed, and each
  link of `collision_link_names` given the yml's `collision_spheres` (centre, radius +
  `collision_sphere_buffer`; cuRobo's placeholder spheres of radius <= 0 are skipped) as
  `<collision><geometry><sphere/>` elements.
- `NAME.srdf`: `<disable_collisions>` for the yml's `self_collision_ignore` pairs and for
  adjacent links (two links joined by one joint, or rigidly through fixed joints), and a
  `<group name="arm">` of the configuration space joints.
- with `--meshes`: `NAME_mesh/NAME.urdf` (the original collision meshes of the same links,
  for `mit-star spherise`), its meshes beside it, and `NAME_mesh/NAME.srdf` (the same SRDF).

Joints: the configuration space is `cspace.joint_names`. Every other revolute or prismatic
joint (a gripper's, a locked one) becomes a fixed joint at its `lock_joints` value (else 0,
clamped to its limits), its motion folded into the joint origin; a mimic joint follows its
leader's value (`multiplier * leader + offset`) and stays a mimic joint when its leader moves.
`--no-lock` ignores `lock_joints` (for the mimic robot, whose only mimic leader is locked).

`--box-spheres` gives links without yml spheres spheres covering their `<visual>` boxes (a row
along each box's longest side, radius half the box's second side): cuRobo's
`simple_mimic_robot` has no spheres at all.

cuRobo's `self_collision_buffer` (a per-link inflation for self-collision only) has no
counterpart here and is ignored; the script says so, and names every link the yml mentions
that the URDF lacks.
"""

import argparse
import math
import os
import posixpath
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import yaml

MIRROR = "/work/.mirror/NVlabs+curobo/repo"


def git_show(rev, path):
    """The bytes of `path` at `rev` in the mirror."""
    return subprocess.run(
        ["git", "-C", MIRROR, "show", f"{rev}:{path}"], check=True, capture_output=True
    ).stdout


def note(message):
    print(f"note: {message}", file=sys.stderr)


def rpy_matrix(r, p, y):
    cr, sr, cp, sp, cy, sy = (math.cos(r), math.sin(r), math.cos(p), math.sin(p),
                              math.cos(y), math.sin(y))
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    return rz @ ry @ rx


def matrix_rpy(m):
    p = math.asin(max(-1.0, min(1.0, -m[2, 0])))
    if abs(math.cos(p)) < 1e-9:
        return math.atan2(-m[1, 2], m[1, 1]), p, 0.0
    return math.atan2(m[2, 1], m[2, 2]), p, math.atan2(m[1, 0], m[0, 0])


def axis_rotation(axis, angle):
    a = np.asarray(axis, float)
    a = a / np.linalg.norm(a)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * (k @ k)


def floats(text, default):
    return [float(v) for v in text.split()] if text else list(default)


def kinematics_of(config):
    return config["robot_cfg"]["kinematics"] if "robot_cfg" in config else config["kinematics"]


def load_spheres(rev, config_dir, kin):
    spheres = kin.get("collision_spheres")
    if isinstance(spheres, str):
        spheres = yaml.safe_load(git_show(rev, posixpath.join(config_dir, spheres)))[
            "collision_spheres"
        ]
    return spheres or {}


def fix_joint(joint, value):
    """Turns a moving `joint` into a fixed one at `value`, its motion folded into the origin."""
    origin = joint.find("origin")
    if origin is None:
        origin = ET.SubElement(joint, "origin")
    xyz = np.array(floats(origin.get("xyz"), [0, 0, 0]))
    rot = rpy_matrix(*floats(origin.get("rpy"), [0, 0, 0]))
    axis_el = joint.find("axis")
    axis = floats(axis_el.get("xyz") if axis_el is not None else None, [1, 0, 0])
    if joint.get("type") == "prismatic":
        xyz = xyz + rot @ (np.asarray(axis) / np.linalg.norm(axis) * value)
    else:
        rot = rot @ axis_rotation(axis, value)
    origin.set("xyz", " ".join(f"{v:.12g}" for v in xyz))
    origin.set("rpy", " ".join(f"{v:.12g}" for v in matrix_rpy(rot)))
    joint.set("type", "fixed")
    for tag in ("axis", "limit", "mimic", "dynamics", "safety_controller", "calibration"):
        for el in joint.findall(tag):
            joint.remove(el)


def clamp_to_limits(joint, value):
    limit = joint.find("limit")
    if joint.get("type") == "continuous" or limit is None:
        return value
    lo, hi = float(limit.get("lower", "0")), float(limit.get("upper", "0"))
    return min(max(value, lo), hi)


def lock_joints(root, cspace, locks):
    """Fixes every moving joint outside `cspace`; returns the joints left moving."""
    joints = {j.get("name"): j for j in root.findall("joint")}
    moving = lambda j: j.get("type") in ("revolute", "continuous", "prismatic")  # noqa: E731
    values = {}
    for name, joint in joints.items():
        if moving(joint) and joint.find("mimic") is None and name not in cspace:
            values[name] = clamp_to_limits(joint, float(locks.get(name, 0.0)))
    # Mimic joints: follow a fixed leader's value, stay mimic joints of a moving one.
    for name, joint in joints.items():
        mimic = joint.find("mimic")
        if moving(joint) and mimic is not None:
            leader = mimic.get("joint")
            if leader in values:
                value = float(mimic.get("multiplier", "1")) * values[leader] + float(
                    mimic.get("offset", "0")
                )
                values[name] = value
    for name, value in values.items():
        fix_joint(joints[name], value)
    if values:
        note(f"fixed {len(values)} joints outside the configuration space: "
             + ", ".join(f"{n}={v:.3g}" for n, v in sorted(values.items())))
    return [n for n, j in joints.items() if moving(j)]


def rigid_groups(root):
    """Link -> representative of its rigid body (links joined by fixed joints)."""
    parent = {}

    def find(link):
        while parent.get(link, link) != link:
            link = parent[link]
        return link

    for joint in root.findall("joint"):
        if joint.get("type") == "fixed":
            a, b = find(joint.find("parent").get("link")), find(joint.find("child").get("link"))
            if a != b:
                parent[b] = a
    return find


def adjacent_pairs(root, links):
    """Pairs of `links` on one rigid body or on two bodies joined by one joint."""
    find = rigid_groups(root)
    body_edges = set()
    for joint in root.findall("joint"):
        a, b = find(joint.find("parent").get("link")), find(joint.find("child").get("link"))
        body_edges.add(frozenset((a, b)))
    pairs = set()
    for i, a in enumerate(links):
        for b in links[i + 1:]:
            if find(a) == find(b) or frozenset((find(a), find(b))) in body_edges:
                pairs.add(tuple(sorted((a, b))))
    return pairs


def box_spheres(link):
    """Spheres covering the `<visual>` boxes of `link`."""
    out = []
    for visual in link.findall("visual"):
        box = visual.find("geometry/box")
        if box is None:
            continue
        size = floats(box.get("size"), [0, 0, 0])
        origin = visual.find("origin")
        xyz = np.array(floats(origin.get("xyz") if origin is not None else None, [0, 0, 0]))
        rot = rpy_matrix(*floats(origin.get("rpy") if origin is not None else None, [0, 0, 0]))
        order = np.argsort(size)[::-1]
        long_axis, radius = order[0], size[order[1]] / 2
        count = max(1, math.ceil(size[long_axis] / radius))
        for k in range(count):
            offset = np.zeros(3)
            offset[long_axis] = -size[long_axis] / 2 + radius + k * (
                (size[long_axis] - 2 * radius) / max(1, count - 1)
            )
            # The corner of the box's cross-section is within radius * sqrt(2) of the axis.
            out.append({"center": list(xyz + rot @ offset), "radius": radius * math.sqrt(2)})
    return out


def write_srdf(path, name, cspace, disabled):
    lines = [f'<?xml version="1.0"?>\n<robot name="{name}">', '  <group name="arm">']
    lines += [f'    <joint name="{j}"/>' for j in cspace]
    lines.append("  </group>")
    for a, b, reason in sorted(disabled):
        lines.append(f'  <disable_collisions link1="{a}" link2="{b}" reason="{reason}"/>')
    lines.append("</robot>")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rev", required=True)
    ap.add_argument("--yml", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--name", help="file stem (default: the yml's)")
    ap.add_argument("--no-lock", action="store_true")
    ap.add_argument("--box-spheres", action="store_true")
    ap.add_argument("--meshes", action="store_true")
    args = ap.parse_args()

    name = args.name or posixpath.splitext(posixpath.basename(args.yml))[0]
    config_dir = posixpath.dirname(args.yml)
    content = posixpath.dirname(posixpath.dirname(config_dir))  # .../content
    kin = kinematics_of(yaml.safe_load(git_show(args.rev, args.yml)))
    urdf_path = posixpath.join(content, "assets", kin["urdf_path"])
    root = ET.fromstring(git_show(args.rev, urdf_path))
    original = ET.fromstring(git_show(args.rev, urdf_path))
    links = {l.get("name"): l for l in root.findall("link")}

    cspace = list(kin["cspace"]["joint_names"])
    locks = {} if args.no_lock else dict(kin.get("lock_joints") or {})
    cspace = [j for j in cspace if j not in locks]
    missing = [j for j in cspace if j not in {x.get("name") for x in root.findall("joint")}]
    if missing:
        note(f"configuration-space joints the URDF lacks (dropped): {missing}")
        cspace = [j for j in cspace if j not in missing]
    moving = lock_joints(root, set(cspace), locks)
    lock_joints(original, set(cspace), locks)
    group = [j for j in moving if j in cspace]

    spheres = load_spheres(args.rev, config_dir, kin)
    listed = kin.get("collision_link_names") or list(spheres)
    buffer = float(kin.get("collision_sphere_buffer") or 0.0)
    if kin.get("self_collision_buffer"):
        note("self_collision_buffer ignored (no per-link self-collision inflation here)")
    unknown = sorted({l for l in list(listed) + list(spheres) if l not in links})
    if unknown:
        note(f"links named in the yml that the URDF lacks (skipped): {unknown}")

    for link in links.values():
        for tag in ("collision", "visual"):
            for el in link.findall(tag):
                link.remove(el)
    sphere_links, count = [], 0
    for link_name in listed:
        if link_name not in links:
            continue
        entries = spheres.get(link_name) or []
        if not entries and args.box_spheres:
            src = next(l for l in original.findall("link") if l.get("name") == link_name)
            entries = box_spheres(src)
        kept = [s for s in entries if float(s["radius"]) > 0]
        for s in kept:
            c = ET.SubElement(links[link_name], "collision")
            ET.SubElement(c, "origin", xyz=" ".join(f"{float(v):.9g}" for v in s["center"]))
            g = ET.SubElement(c, "geometry")
            ET.SubElement(g, "sphere", radius=f"{float(s['radius']) + buffer:.9g}")
        if kept:
            sphere_links.append(link_name)
            count += len(kept)
    if args.box_spheres:
        for link_name, link in links.items():
            if link_name in sphere_links:
                continue
            src = next(l for l in original.findall("link") if l.get("name") == link_name)
            for s in box_spheres(src):
                c = ET.SubElement(link, "collision")
                ET.SubElement(c, "origin", xyz=" ".join(f"{v:.9g}" for v in s["center"]))
                g = ET.SubElement(c, "geometry")
                ET.SubElement(g, "sphere", radius=f"{s['radius']:.9g}")
                count += 1
            if link.find("collision") is not None:
                sphere_links.append(link_name)

    disabled = {(a, b, "Adjacent") for a, b in adjacent_pairs(root, sphere_links)}
    adjacent = {(a, b) for a, b, _ in disabled}
    for a, others in (kin.get("self_collision_ignore") or {}).items():
        for b in others or []:
            if a in links and b in links and a != b:
                pair = tuple(sorted((a, b)))
                if pair not in adjacent:
                    disabled.add((pair[0], pair[1], "Never"))
            elif a != b:
                note(f"self_collision_ignore pair ({a}, {b}) names a link the URDF lacks")
    disabled = {(a, b, r) for a, b, r in disabled if a in sphere_links and b in sphere_links}

    os.makedirs(args.out, exist_ok=True)
    robot_name = root.get("name")
    ET.ElementTree(root).write(os.path.join(args.out, f"{name}_spherized.urdf"),
                               xml_declaration=True, encoding="utf-8")
    write_srdf(os.path.join(args.out, f"{name}.srdf"), robot_name, group, disabled)
    print(f"{name}: {len(group)} joints in the group, {len(moving)} moving, "
          f"{count} spheres on {len(sphere_links)} links, {len(disabled)} disabled pairs")

    if args.meshes:
        mesh_dir = os.path.join(args.out, f"{name}_mesh")
        os.makedirs(mesh_dir, exist_ok=True)
        urdf_dir = posixpath.dirname(urdf_path)
        asset_root = posixpath.join(content, "assets", kin.get("asset_root_path", ""))
        for link in original.findall("link"):
            for el in link.findall("visual"):
                link.remove(el)
            if link.get("name") not in listed:
                for el in link.findall("collision"):
                    link.remove(el)
            for mesh in link.findall("collision/geometry/mesh"):
                rel = mesh.get("filename").removeprefix("package://")
                for base in (urdf_dir, asset_root):
                    try:
                        data = git_show(args.rev, posixpath.normpath(posixpath.join(base, rel)))
                        break
                    except subprocess.CalledProcessError:
                        data = None
                if data is None:
                    sys.exit(f"mesh {rel} of link {link.get('name')} not found in the mirror")
                target = os.path.join(mesh_dir, rel)
                os.makedirs(os.path.dirname(target), exist_ok=True)
                with open(target, "wb") as f:
                    f.write(data)
                mesh.set("filename", rel)
        ET.ElementTree(original).write(os.path.join(mesh_dir, f"{name}.urdf"),
                                       xml_declaration=True, encoding="utf-8")
        write_srdf(os.path.join(mesh_dir, f"{name}.srdf"), robot_name, group, disabled)
        print(f"{name}: meshes in {mesh_dir}")


if __name__ == "__main__":
    main()
