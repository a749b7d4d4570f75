#!/usr/bin/env python3
"""Pinocchio as an independent oracle for `massprop report ROBOT --joints`.

For every robot description given (by default every one in shapes/robots
and tests/robots) and for generated URDF trees (deep chains, branches,
mimic joints, prismatic and fixed joints, offsets of 10^3 m), at seeded
random configurations: the whole body's mass, centre of mass and inertia
about the centre of mass that massprop reports (JSON, SI) agree with
Pinocchio's to 1e-12 relative.

Pinocchio's model is built with a free-flyer root at the identity, so that
the root link counts (`computeTotalMass`, `centerOfMass`; the centroidal
composite inertia `data.Ig` from `ccrba`, at the centre of mass in world
axes). Mimic joints are set by hand from the file's `<mimic>` (q = offset +
multiplier * q_leader): Pinocchio reads them as independent joints.

    pip install pin numpy
    python3 tests/oracle/pinocchio_oracle.py --massprop target/release/massprop

Exit status 0 when every case agrees, 1 otherwise (each disagreement is
printed); files Pinocchio cannot read (SDFormat without its SDFormat
support, files massprop refuses) are named as skipped. For SDFormat,
drake_body_oracle.py has Pinocchio compose what Drake reads
(pin_of_drake.py).
"""

import argparse
import glob
import json
import math
import os
import random
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import numpy as np
import pinocchio as pin

RTOL = 1e-12


def massprop_body(massprop, path, joints):
    spec = ", ".join(f"{k}={float(v)!r}" for k, v in joints.items())
    cmd = [massprop, "report", path, "--format", "json"]
    if spec:
        cmd += ["--joints", spec]
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode != 0:
        return None, out.stderr.strip()
    if "< 0); composed as written" in out.stderr and path.endswith(".xml"):
        # An MJCF tensor with a negative moment: Pinocchio's MJCF reader
        # makes its own of a non-physical inertia (massprop composes it as
        # written; MuJoCo refuses it). Its URDF reader takes it as written,
        # and those files are compared.
        return None, "a link's inertia has a negative principal moment: " + out.stderr.strip().splitlines()[0]
    d = json.loads(out.stdout)
    return (d["mass"], np.array(d["center_of_mass"]), np.array(d["inertia_com"])), None


def mimics(path):
    """URDF `<mimic>`: joint -> (leader, multiplier, offset)."""
    out = {}
    if not path.endswith(".urdf"):
        return out
    root = ET.parse(path).getroot()
    for j in root.iter("joint"):
        m = j.find("mimic")
        if m is not None:
            out[j.get("name")] = (
                m.get("joint"),
                float(m.get("multiplier", "1")),
                float(m.get("offset", "0")),
            )
    return out


def pin_model(path):
    ff = pin.JointModelFreeFlyer()
    if path.endswith(".urdf"):
        return pin.buildModelFromUrdf(path, ff)
    if path.endswith(".xml"):
        made = pin.buildModelFromMJCF(path, ff, "root_joint")
        return made[0] if isinstance(made, tuple) else made
    if path.endswith(".sdf"):
        return pin.buildModelsFromSdf(path, ff)[0]
    raise ValueError(path)


def mjcf_joints(path):
    """MJCF: each joint's name as massprop names it (an unnamed one `joint
    N`, counting every joint in document order) and as Pinocchio does
    (`BODYJoint_K`, K counting the body's joints), and each free body's
    written pose (MuJoCo's qpos0 for a free joint), by Pinocchio's name."""
    names, free = {}, {}
    if not path.endswith(".xml"):
        return names, free
    root = ET.parse(path).getroot()
    count = 0
    for world in root.iter("worldbody"):
        for body in world.iter("body"):
            k = 0
            for j in body:
                if j.tag not in ("joint", "freejoint"):
                    continue
                count += 1
                ours = j.get("name") or f"joint {count}"
                theirs = j.get("name") or f"{body.get('name')}Joint_{k}"
                k += 1
                names[ours] = theirs
                if j.tag == "freejoint" or j.get("type") == "free":
                    pos = [float(x) for x in (body.get("pos") or "0 0 0").split()]
                    w, x, y, z = [float(v) for v in (body.get("quat") or "1 0 0 0").split()]
                    n = math.sqrt(w * w + x * x + y * y + z * z)
                    free[j.get("name") or f"{body.get('name')}_free"] = pos + [x / n, y / n, z / n, w / n]
    # Pinocchio's root joint takes the place of the world body's one child
    # body's own pose: set it there (massprop's frame is the world body's).
    tops = [b for w in root.iter("worldbody") for b in w.findall("body")]
    if len(tops) == 1 and not any(j.tag == "freejoint" or j.get("type") == "free" for j in tops[0]):
        b = tops[0]
        pos = [float(x) for x in (b.get("pos") or "0 0 0").split()]
        w, x, y, z = [float(v) for v in (b.get("quat") or "1 0 0 0").split()]
        n = math.sqrt(w * w + x * x + y * y + z * z)
        free["root_joint"] = pos + [x / n, y / n, z / n, w / n]
    return names, free


def pin_body(model, values, free=None):
    q = pin.neutral(model)
    for name, pose in (free or {}).items():
        if model.existJointName(name):
            j = model.joints[model.getJointId(name)]
            q[j.idx_q : j.idx_q + 7] = pose
    for name, x in values.items():
        jid = model.getJointId(name)
        j = model.joints[jid]
        if j.nq == 1:
            q[j.idx_q] = x
        elif j.nq == 2:  # a continuous joint: (cos, sin)
            q[j.idx_q] = math.cos(x)
            q[j.idx_q + 1] = math.sin(x)
    data = model.createData()
    mass = pin.computeTotalMass(model, data)
    com = pin.centerOfMass(model, data, q)
    pin.ccrba(model, data, q, np.zeros(model.nv))
    ig = data.Ig
    return mass, np.array(com), np.array(ig.inertia)


def movable(model):
    """Joint name -> (lower, upper) for every 1-dof joint but the root's."""
    out = {}
    for jid in range(2, model.njoints):
        j = model.joints[jid]
        if j.nv != 1:
            continue
        lo = model.lowerPositionLimit[j.idx_q] if j.nq == 1 else -math.pi
        hi = model.upperPositionLimit[j.idx_q] if j.nq == 1 else math.pi
        if not (math.isfinite(lo) and math.isfinite(hi)) or lo >= hi or hi - lo > 1e6:
            lo, hi = -math.pi, math.pi
        out[model.names[jid]] = (lo, hi)
    return out


def agree(a, b):
    """Relative disagreement of two bodies (mass, com, inertia)."""
    ma, ca, ia = a
    mb, cb, ib = b
    scale_l = max(np.abs(ca).max(), math.sqrt(max(np.trace(ia), 0.0) / ma) if ma > 0 else 0.0, 1e-300)
    scale_i = max(np.abs(ia).max(), 1e-300)
    return max(
        abs(ma - mb) / max(abs(ma), 1e-300),
        np.abs(ca - cb).max() / scale_l,
        np.abs(ia - ib).max() / scale_i,
    )


def check_file(massprop, path, rng, cases):
    try:
        model = pin_model(path)
    except Exception as e:  # noqa: BLE001 (any reader failure is a skip)
        return 0, [], f"skipped {path}: Pinocchio cannot read it ({str(e).splitlines()[0] if str(e) else type(e).__name__})"
    follow = mimics(path)
    named, floating = mjcf_joints(path)
    theirs_of = {t: o for o, t in named.items()}
    free = {theirs_of.get(k, k): v for k, v in movable(model).items() if k not in follow}
    bad = []
    for case in range(cases):
        values = {} if case == 0 else {k: rng.uniform(float(lo), float(hi)) for k, (lo, hi) in free.items()}
        ours, err = massprop_body(massprop, path, values)
        if ours is None:
            return 0, [], f"skipped {path}: massprop refuses it ({err.splitlines()[0]})"
        full = dict(values)
        for name, (leader, mult, off) in follow.items():
            full[name] = off + mult * full.get(leader, 0.0)
        theirs = pin_body(model, {named.get(k, k): v for k, v in full.items()}, floating)
        r = agree(ours, theirs)
        if not r <= RTOL:
            bad.append(f"{path} at {values}: relative disagreement {r:.3g}\n  massprop {ours}\n  pinocchio {theirs}")
    return cases, bad, None


def rpy(rng, on):
    return " ".join(f"{rng.uniform(-math.pi, math.pi)!r}" for _ in range(3)) if on else "0 0 0"


def inertial(rng, scale, turned):
    m = rng.uniform(0.1, 5.0)
    a, b, c = (rng.uniform(0.2, 1.0) * scale for _ in range(3))
    # A box's moments, turned by rpy: valid and with products in the link frame.
    ixx, iyy, izz = m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12
    xyz = " ".join(f"{rng.uniform(-scale, scale)!r}" for _ in range(3))
    return (
        f'<inertial><origin xyz="{xyz}" rpy="{rpy(rng, turned)}"/><mass value="{m!r}"/>'
        f'<inertia ixx="{ixx!r}" ixy="0" ixz="0" iyy="{iyy!r}" iyz="0" izz="{izz!r}"/></inertial>'
    )


def generated(rng, kind):
    """A URDF tree of one family, as text."""
    n = {"chain": 60, "branches": 40, "mimic": 12, "prismatic": 12, "fixed": 15, "far": 12}[kind]
    scale = 1e3 if kind == "far" else 0.2
    links, joints = [], []
    for i in range(n):
        turned = rng.random() < 0.5
        links.append(f'<link name="l{i}">{inertial(rng, scale * 0.3, turned)}</link>')
        if i == 0:
            continue
        parent = i - 1 if kind in ("chain", "far") else rng.randrange(i)
        types = {"prismatic": ["prismatic", "revolute"], "fixed": ["fixed", "revolute", "continuous"]}
        t = rng.choice(types.get(kind, ["revolute", "continuous"]))
        axis = [rng.uniform(-1, 1) for _ in range(3)]
        xyz = " ".join(f"{rng.uniform(-scale, scale)!r}" for _ in range(3))
        body = (
            f'<joint name="j{i}" type="{t}"><parent link="l{parent}"/><child link="l{i}"/>'
            f'<origin xyz="{xyz}" rpy="{rpy(rng, True)}"/>'
            f'<axis xyz="{axis[0]!r} {axis[1]!r} {axis[2]!r}"/>'
        )
        if t in ("revolute", "prismatic"):
            body += '<limit lower="-1.5" upper="1.5" effort="1" velocity="1"/>'
        if kind == "mimic" and i > 2 and t == "revolute" and rng.random() < 0.5:
            body += f'<mimic joint="j{i - 1}" multiplier="{rng.uniform(-2, 2)!r}" offset="{rng.uniform(-0.5, 0.5)!r}"/>'
        joints.append(body + "</joint>")
    return f'<?xml version="1.0"?>\n<robot name="{kind}">\n' + "\n".join(links + joints) + "\n</robot>\n"


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    repo = os.path.dirname(os.path.dirname(here))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--massprop", required=True)
    ap.add_argument("--cases", type=int, default=12, help="configurations per robot")
    ap.add_argument("--seed", type=int, default=34)
    ap.add_argument("files", nargs="*")
    a = ap.parse_args()
    rng = random.Random(a.seed)
    files = a.files or sorted(
        glob.glob(os.path.join(repo, "shapes/robots/*")) + glob.glob(os.path.join(repo, "tests/robots/*"))
    )
    files = [f for f in files if f.endswith((".urdf", ".sdf", ".xml"))]
    total, failures, skipped = 0, [], []
    with tempfile.TemporaryDirectory() as tmp:
        for kind in ["chain", "branches", "mimic", "prismatic", "fixed", "far"]:
            for k in range(2):
                p = os.path.join(tmp, f"{kind}{k}.urdf")
                with open(p, "w") as f:
                    f.write(generated(rng, kind))
                files.append(p)
        for path in files:
            n, bad, skip = check_file(a.massprop, path, rng, a.cases)
            total += n
            failures += bad
            if skip:
                skipped.append(skip)
    for s in skipped:
        print(s)
    for b in failures:
        print("DISAGREE:", b)
    print(f"pinocchio oracle: {total - len(failures)} of {total} configurations agree to {RTOL:g} ({len(skipped)} files skipped)")
    return 1 if failures or total == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
