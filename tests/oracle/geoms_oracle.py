"""MJCF inertials from geoms, and URDF inertials exported from geometry,
against MuJoCo's own compiler (issue 34 items 1, 3 and 4).

1. Random MJCF bodies without `<inertial>` (box, sphere, capsule, cylinder,
   ellipsoid geoms at random pos/quat/euler/fromto, with `density`, `mass`
   or neither, some in a group outside `inertiagrouprange`): MuJoCo's
   body_mass, body_ipos and body_inertia (principal moments) against
   massprop's `report --format json` of the same file.
2. Random URDF links with box, cylinder and sphere `<collision>`s: their
   inertials written by `massprop export --from-geometry collision
   --density D --update`, then the file loaded in MuJoCo: each body's mass
   and principal moments against the exported inertial's (numpy's
   eigenvalues of the written tensor).

Usage: python geoms_oracle.py --massprop BIN [--cases N]. Exit 1 on any
disagreement beyond 1e-9 relative.
"""

import argparse
import json
import os
import random
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import mujoco
import numpy as np

RTOL = 1e-9


def close(a, b, scale):
    return abs(a - b) <= RTOL * max(scale, 1e-300)


def geom(rng, i):
    kind = rng.choice(["box", "sphere", "capsule", "cylinder", "ellipsoid"])
    attrs = {"type": kind, "name": f"g{i}"}
    if kind in ("box", "ellipsoid"):
        attrs["size"] = " ".join(repr(rng.uniform(0.01, 1.0)) for _ in range(3))
    elif kind == "sphere":
        attrs["size"] = repr(rng.uniform(0.01, 1.0))
    else:
        r = rng.uniform(0.01, 0.5)
        if rng.random() < 0.4:
            a = [rng.uniform(-1, 1) for _ in range(3)]
            b = [x + rng.uniform(-1, 1) for x in a]
            attrs["fromto"] = " ".join(repr(x) for x in a + b)
            attrs["size"] = repr(r)
        else:
            attrs["size"] = f"{r!r} {rng.uniform(0.01, 1.0)!r}"
    if "fromto" not in attrs:
        attrs["pos"] = " ".join(repr(rng.uniform(-2, 2)) for _ in range(3))
        turn = rng.random()
        if turn < 0.4:
            q = [rng.gauss(0, 1) for _ in range(4)]
            attrs["quat"] = " ".join(repr(x) for x in q)
        elif turn < 0.7:
            attrs["euler"] = " ".join(repr(rng.uniform(-180, 180)) for _ in range(3))
    amount = rng.random()
    if amount < 0.3:
        attrs["mass"] = repr(rng.uniform(0.1, 10))
    elif amount < 0.6:
        attrs["density"] = repr(rng.uniform(100, 8000))
    if i > 0 and rng.random() < 0.15:
        attrs["group"] = "6"
    return "<geom " + " ".join(f'{k}="{v}"' for k, v in attrs.items()) + "/>"


def massprop_json(binary, path):
    out = subprocess.run(
        [binary, "report", path, "--format", "json"], capture_output=True, text=True
    )
    if out.returncode != 0:
        raise RuntimeError(f"massprop report {path}: {out.stderr}")
    return json.loads(out.stdout)


def mjcf_case(rng, binary, tmp, k):
    geoms = [geom(rng, i) for i in range(rng.randint(1, 4))]
    text = (
        '<mujoco><worldbody><body name="b"><freejoint/>'
        + "".join(geoms)
        + "</body></worldbody></mujoco>"
    )
    path = os.path.join(tmp, f"m{k}.xml")
    with open(path, "w") as f:
        f.write(text)
    m = mujoco.MjModel.from_xml_path(path)
    mine = massprop_json(binary, path)
    mass, com = m.body_mass[1], m.body_ipos[1]
    moments = sorted(m.body_inertia[1])
    bad = []
    if not close(mine["mass"], mass, mass):
        bad.append(f"mass {mine['mass']} vs MuJoCo {mass}")
    reach = max(1.0, max(abs(x) for x in com))
    if any(not close(a, b, reach) for a, b in zip(mine["center_of_mass"], com)):
        bad.append(f"centre {mine['center_of_mass']} vs MuJoCo {list(com)}")
    if any(not close(a, b, moments[-1]) for a, b in zip(mine["principal_moments"], moments)):
        bad.append(f"principal moments {mine['principal_moments']} vs MuJoCo {moments}")
    return [f"{path}: {b}\n{text}" for b in bad]


def urdf_case(rng, binary, tmp, k):
    links, joints = [], []
    for i in range(rng.randint(1, 3)):
        cols = []
        for _ in range(rng.randint(1, 3)):
            kind = rng.choice(["box", "cylinder", "sphere"])
            if kind == "box":
                g = '<box size="%r %r %r"/>' % tuple(rng.uniform(0.01, 1) for _ in range(3))
            elif kind == "cylinder":
                g = '<cylinder radius="%r" length="%r"/>' % (
                    rng.uniform(0.01, 0.5),
                    rng.uniform(0.01, 1),
                )
            else:
                g = '<sphere radius="%r"/>' % rng.uniform(0.01, 0.5)
            xyz = " ".join(repr(rng.uniform(-1, 1)) for _ in range(3))
            rpy = " ".join(repr(rng.uniform(-3, 3)) for _ in range(3))
            cols.append(
                f'<collision><origin xyz="{xyz}" rpy="{rpy}"/><geometry>{g}</geometry></collision>'
            )
        links.append(
            f'<link name="l{i}"><inertial><mass value="1"/>'
            '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'
            + "".join(cols)
            + "</link>"
        )
        # Every link hinged, under a massless base that MuJoCo fuses into
        # the world (a root link would be fused with it, its mass lost).
        parent = "base" if i == 0 else f"l{i - 1}"
        joints.append(
            f'<joint name="j{i}" type="revolute"><parent link="{parent}"/><child link="l{i}"/>'
                '<origin xyz="0 0 1"/><axis xyz="0 1 0"/>'
                '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
            )
    path = os.path.join(tmp, f"u{k}.urdf")
    with open(path, "w") as f:
        f.write('<robot name="r"><link name="base"/>' + "".join(links) + "".join(joints) + "</robot>\n")
    density = repr(rng.uniform(100, 8000))
    out = subprocess.run(
        [binary, "export", path, "--from-geometry", "collision", "--density", density,
         "--update", path],
        capture_output=True,
        text=True,
    )
    if out.returncode != 0:
        return [f"{path}: export --from-geometry: {out.stderr}"]
    root = ET.parse(path).getroot()
    m = mujoco.MjModel.from_xml_path(path)
    bad = []
    for link in root.findall("link"):
        name = link.get("name")
        inertial = link.find("inertial")
        if inertial is None:
            continue
        mass = float(inertial.find("mass").get("value"))
        t = inertial.find("inertia")
        g = {a: float(t.get(a)) for a in ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"]}
        tensor = np.array([
            [g["ixx"], g["ixy"], g["ixz"]],
            [g["ixy"], g["iyy"], g["iyz"]],
            [g["ixz"], g["iyz"], g["izz"]],
        ])
        mine = sorted(np.linalg.eigvalsh(tensor))
        if name == "base":
            continue
        b = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, name)
        if b < 0:
            bad.append(f"{path}: link {name}: not a body in MuJoCo's model")
            continue
        theirs = sorted(m.body_inertia[b])
        if not close(m.body_mass[b], mass, mass):
            bad.append(f"{path}: link {name}: mass {mass} vs MuJoCo {m.body_mass[b]}")
        if any(not close(a, c, mine[-1]) for a, c in zip(mine, theirs)):
            bad.append(f"{path}: link {name}: principal moments {mine} vs MuJoCo {theirs}")
    return bad


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--massprop", required=True)
    p.add_argument("--cases", type=int, default=100)
    p.add_argument("--seed", type=int, default=34)
    a = p.parse_args()
    rng = random.Random(a.seed)
    bad = []
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(a.cases):
            bad += mjcf_case(rng, a.massprop, tmp, k)
            bad += urdf_case(rng, a.massprop, tmp, k)
        for b in bad[:20]:
            print(b)
    print(
        f"{a.cases} MJCF bodies and {a.cases} exported URDFs against MuJoCo: "
        f"{len(bad)} disagreements"
    )
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
