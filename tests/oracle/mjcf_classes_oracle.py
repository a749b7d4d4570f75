"""The whole MJCF robot, with default classes, against MuJoCo itself
(issue 34, second round).

Random MJCF trees whose joints and geoms take their values from default
classes (the main class, nested classes, `childclass` on bodies and
frames, `class` on joints and geoms: joint type, axis, pos, ref, range,
limited; geom type, size, density, mass, group, and placement: pos,
fromto, quat/euler/axisangle/zaxis/xyaxes against a geom's own), geoms and
bodies inside (nested) `<frame>`s, some bodies weighed from their geoms
(`inertiafromgeom`), some with an `<inertial>`. For each, at random joint
values: MuJoCo's `mj_kinematics` and `mj_comPos` at that `qpos`, and the
world body's subtree mass, centre of mass and inertia about it formed from
every body's `body_mass`, `xipos`, `ximat` and `body_inertia`, against
`massprop report --format json --joints …` of the same file, and against a
part file that includes it with the same `joints`.

Each model is also written split over an MJCF `<include>` (its classes in
a file of their own), and split again at random inner places: runs of the
children of `<worldbody>`, of bodies, frames and default classes moved
into included files (nested, their roots `<mujoco>` or `<mujocoinclude>`),
each `<include>` where they stood. MuJoCo compiles each split to the same
masses and inertias as the one file, massprop's report of it agrees with
MuJoCo, and massprop reports it bit for bit as the one file.

Usage: python mjcf_classes_oracle.py --massprop BIN [--cases N]. Exit 1 on
any disagreement beyond 1e-9 relative.
"""

import argparse
import json
import math
import os
import random
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import mujoco
import numpy as np

RTOL = 1e-9


def nums(rng, n, lo, hi):
    return " ".join(repr(rng.uniform(lo, hi)) for _ in range(n))


def joint_defaults(rng):
    attrs = {}
    if rng.random() < 0.5:
        attrs["type"] = rng.choice(["hinge", "slide"])
    if rng.random() < 0.5:
        attrs["axis"] = nums(rng, 3, -1, 1)
    if rng.random() < 0.4:
        attrs["pos"] = nums(rng, 3, -0.2, 0.2)
    if rng.random() < 0.4:
        attrs["ref"] = repr(rng.uniform(-20, 20))
    if rng.random() < 0.3:
        attrs["range"] = "-30 40"
    return attrs


def geom_defaults(rng):
    attrs = {}
    if rng.random() < 0.5:
        attrs["type"] = rng.choice(["box", "sphere", "capsule", "cylinder", "ellipsoid"])
    if rng.random() < 0.6:
        attrs["size"] = nums(rng, 3, 0.02, 0.2)
    r = rng.random()
    if r < 0.3:
        attrs["density"] = repr(rng.uniform(200, 5000))
    elif r < 0.45:
        attrs["mass"] = repr(rng.uniform(0.1, 3))
    if rng.random() < 0.2:
        attrs["group"] = "6"
    # A geom's placement from its class: a position, one orientation form,
    # or a segment (where a geom of the class writes `pos` too, MuJoCo
    # refuses the model, and so must massprop).
    r = rng.random()
    if r < 0.06:
        attrs["fromto"] = nums(rng, 6, -0.2, 0.2)
    elif r < 0.45:
        attrs["pos"] = nums(rng, 3, -0.2, 0.2)
    attrs.update(orientation(rng, 0.5))
    return attrs


def orientation(rng, p):
    """One orientation form, with probability p."""
    if rng.random() >= p:
        return {}
    form = rng.choice(["quat", "euler", "axisangle", "zaxis", "xyaxes"])
    n = {"quat": 4, "euler": 3, "axisangle": 4, "zaxis": 3, "xyaxes": 6}[form]
    if form == "euler":
        return {form: nums(rng, 3, -90, 90)}
    return {form: nums(rng, n, -1, 1)}


def element(tag, attrs):
    return f"<{tag} " + " ".join(f'{k}="{v}"' for k, v in attrs.items()) + "/>"


def defaults(rng):
    """A main class and three more (b inside a), each setting some joint
    and geom values."""

    def block(name, inner=""):
        head = "<default>" if name is None else f'<default class="{name}">'
        j, g = joint_defaults(rng), geom_defaults(rng)
        body = (element("joint", j) if j else "") + (element("geom", g) if g else "")
        return head + body + inner + "</default>"

    return block(None, block("a", block("b")) + block("c"))


CLASSES = ["a", "b", "c"]


def body_xml(rng, depth, counter):
    counter[0] += 1
    k = counter[0]
    attrs = {"name": f"b{k}", "pos": nums(rng, 3, -0.5, 0.5)}
    if rng.random() < 0.5:
        attrs["euler"] = nums(rng, 3, -90, 90)
    if rng.random() < 0.3:
        attrs["childclass"] = rng.choice(CLASSES)
    inner = []
    for j in range(rng.randint(0, 2)):
        ja = {"name": f"j{k}_{j}"}
        if rng.random() < 0.4:
            ja["class"] = rng.choice(CLASSES)
        if rng.random() < 0.2:
            ja["type"] = rng.choice(["hinge", "slide"])
        inner.append(element("joint", ja))
    if rng.random() < 0.3:
        inner.append(
            '<inertial pos="%s" mass="%r" diaginertia="0.02 0.03 0.04"/>'
            % (nums(rng, 3, -0.1, 0.1), rng.uniform(0.5, 3))
        )
    for g in range(rng.randint(1, 2)):
        ga = {"size": nums(rng, 3, 0.02, 0.2)}
        if rng.random() < 0.6:
            ga["pos"] = nums(rng, 3, -0.1, 0.1)
        if g == 0:
            ga["group"] = "0"
        if rng.random() < 0.5:
            ga["class"] = rng.choice(CLASSES)
        if rng.random() < 0.3:
            del ga["size"]
            ga["type"] = "box"
            ga["size"] = nums(rng, 3, 0.02, 0.2)
        ga.update(orientation(rng, 0.3))
        inner.append(element("geom", ga))
    if depth > 0:
        for _ in range(rng.randint(1, 2)):
            inner.append(body_xml(rng, depth - 1, counter))
    # Some of its geoms and bodies inside a `<frame>` (nested, sometimes),
    # placed by the frame's pose, taking its `childclass`.
    if rng.random() < 0.4:
        movable = [i for i, x in enumerate(inner) if x.startswith(("<geom", "<body"))]
        if movable:
            lo = rng.choice(movable)
            hi = rng.choice([i for i in movable if i >= lo])
            for _ in range(rng.randint(1, 2)):
                fa = {"pos": nums(rng, 3, -0.3, 0.3)}
                fa.update(orientation(rng, 0.7))
                if rng.random() < 0.3:
                    fa["childclass"] = rng.choice(CLASSES)
                head = "<frame " + " ".join(f'{a}="{v}"' for a, v in fa.items()) + ">"
                inner[lo : hi + 1] = [head + "".join(inner[lo : hi + 1]) + "</frame>"]
                hi = lo
    return f"<body {' '.join(f'{a}={chr(34)}{v}{chr(34)}' for a, v in attrs.items())}>" + "".join(inner) + "</body>"


def robot(rng):
    counter = [0]
    return (
        '<mujoco model="classes">'
        + defaults(rng)
        + "<worldbody>"
        + body_xml(rng, 2, counter)
        + "</worldbody></mujoco>"
    )


SPLIT_AT = ("worldbody", "body", "frame", "default")


def split_inner(text, rng, directory, stem):
    """`text` with runs of children of worldbody, bodies, frames and
    default classes moved into included files (written in `directory`),
    innermost first, so that cuts nest; the number of files."""
    root = ET.fromstring(text)
    files = []

    def visit(elem):
        for child in list(elem):
            visit(child)
        kids = list(elem)
        if elem.tag not in SPLIT_AT or not kids or rng.random() >= 0.5:
            return
        i = rng.randrange(len(kids))
        j = rng.randrange(i, len(kids))
        inc = ET.Element(rng.choice(["mujoco", "mujocoinclude"]))
        for k in kids[i : j + 1]:
            elem.remove(k)
            inc.append(k)
        name = f"{stem}_inc{len(files) + 1}.xml"
        files.append(name)
        with open(os.path.join(directory, name), "w") as f:
            f.write(ET.tostring(inc, encoding="unicode"))
        elem.insert(i, ET.Element("include", {"file": name}))

    visit(root)
    return ET.tostring(root, encoding="unicode"), len(files)


def placeless(report):
    """A report less `source` and its warnings' places: a warning about an
    element of an included file points at the `<include>` that brings it
    in (docs/robots.md)."""
    out = {k: v for k, v in report.items() if k != "source"}
    out["warnings"] = [(w["kind"], w["message"]) for w in report.get("warnings", [])]
    return out


def mujoco_whole(model, data):
    """Mass, centre of mass and inertia about it of every body but the
    world, in the world frame."""
    mass, first, inertia = 0.0, np.zeros(3), np.zeros((3, 3))
    for b in range(1, model.nbody):
        m = model.body_mass[b]
        mass += m
        first += m * data.xipos[b]
    com = first / mass
    for b in range(1, model.nbody):
        m = model.body_mass[b]
        r = data.ximat[b].reshape(3, 3)
        d = data.xipos[b] - com
        inertia += r @ np.diag(model.body_inertia[b]) @ r.T + m * (d @ d * np.eye(3) - np.outer(d, d))
    return mass, com, inertia


def massprop_json(binary, args):
    out = subprocess.run([binary, "report", *args, "--format", "json"], capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"massprop report {args}: {out.stderr}")
    return json.loads(out.stdout)


def agree(name, got, want):
    scale = max(1e-300, float(np.max(np.abs(want))))
    if np.max(np.abs(np.asarray(got) - np.asarray(want))) > RTOL * scale:
        print(f"{name}: massprop {got} MuJoCo {want}", file=sys.stderr)
        return False
    return True


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--massprop", required=True)
    parser.add_argument("--cases", type=int, default=30)
    parser.add_argument("--seed", type=int, default=34)
    args = parser.parse_args()
    args.massprop = os.path.abspath(args.massprop)
    rng = random.Random(args.seed)
    bad = 0
    with tempfile.TemporaryDirectory() as tmp:
        # MuJoCo writes its warnings to MUJOCO_LOG.TXT in the working
        # directory: keep it out of the repository.
        os.chdir(tmp)
        refusals = 0
        inner_files = 0
        for case in range(args.cases):
            # A model MuJoCo refuses for a geom's placement (`pos` and
            # `fromto` both, `fromto` on a sphere) massprop must refuse
            # too; then another is drawn.
            while True:
                text = robot(rng)
                path = os.path.join(tmp, f"c{case}.xml")
                with open(path, "w") as f:
                    f.write(text)
                try:
                    model = mujoco.MjModel.from_xml_path(path)
                    break
                except ValueError as e:
                    if "fromto" not in str(e):
                        raise
                    # Every geom read (massprop reads only the geoms of
                    # the bodies it weighs from them).
                    with open(path, "w") as f:
                        f.write(text.replace("<worldbody>", '<compiler inertiafromgeom="true"/><worldbody>', 1))
                    out = subprocess.run([args.massprop, "report", path], capture_output=True, text=True)
                    if out.returncode != 2 or "fromto" not in out.stderr:
                        bad += 1
                        print(f"MuJoCo refuses ({e}) and massprop does not:\n{out.stderr}\n{text}", file=sys.stderr)
                    refusals += 1
            data = mujoco.MjData(model)
            data.qpos[:] = model.qpos0
            values = {}
            for j in range(model.njnt):
                if model.jnt_type[j] in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE):
                    x = rng.uniform(-1.0, 1.0)
                    data.qpos[model.jnt_qposadr[j]] = x
                    values[mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, j)] = x
            mujoco.mj_kinematics(model, data)
            mujoco.mj_comPos(model, data)
            mass, com, inertia = mujoco_whole(model, data)
            joints = ", ".join(f"{k}={v!r}" for k, v in values.items())
            alone = massprop_json(args.massprop, [path, "--joints", joints])
            part = os.path.join(tmp, f"c{case}.toml")
            with open(part, "w") as f:
                table = ", ".join(f"{k} = {v!r}" for k, v in values.items())
                f.write(f'[[part]]\ninclude = "c{case}.xml"\njoints = {{ {table} }}\n')
            included = massprop_json(args.massprop, [part])
            # The same model split over an `<include>`: its classes (and
            # any `<compiler>`) in a file of their own.
            with open(path) as f:
                written = f.read()
            head = '<mujoco model="classes">'
            cut = written.index("<worldbody>")
            with open(os.path.join(tmp, f"s{case}_classes.xml"), "w") as f:
                f.write("<mujoco>" + written[len(head) : cut] + "</mujoco>")
            split = os.path.join(tmp, f"s{case}.xml")
            with open(split, "w") as f:
                f.write(f'{head}<include file="s{case}_classes.xml"/>' + written[cut:])
            whole = mujoco.MjModel.from_xml_path(split)
            if not (
                np.array_equal(whole.body_mass, model.body_mass)
                and np.array_equal(whole.body_inertia, model.body_inertia)
            ):
                bad += 1
                print(f"case {case}: MuJoCo compiles the split model differently", file=sys.stderr)
            divided = massprop_json(args.massprop, [split, "--joints", joints])
            # Split at inner places: includes in the world body, bodies,
            # frames and default classes, nested.
            inner_text, count = split_inner(written, rng, tmp, f"i{case}")
            inner = os.path.join(tmp, f"i{case}.xml")
            with open(inner, "w") as f:
                f.write(inner_text)
            inner_files += count
            spliced = mujoco.MjModel.from_xml_path(inner)
            if not (
                np.array_equal(spliced.body_mass, model.body_mass)
                and np.array_equal(spliced.body_inertia, model.body_inertia)
            ):
                bad += 1
                print(f"case {case}: MuJoCo compiles the inner split model differently", file=sys.stderr)
            anywhere = massprop_json(args.massprop, [inner, "--joints", joints])
            if placeless(anywhere) != placeless(alone):
                bad += 1
                print(f"case {case}: massprop reports the inner split otherwise than the one file", file=sys.stderr)
            for label, got in (
                ("report", alone),
                ("include", included),
                ("split", divided),
                ("inner split", anywhere),
            ):
                ok = agree(f"case {case} {label} mass", [got["mass"]], [mass])
                ok &= agree(f"case {case} {label} centre", got["center_of_mass"], com)
                ok &= agree(f"case {case} {label} inertia", got["inertia_com"], inertia)
                if not ok:
                    bad += 1
                    print(text, file=sys.stderr)
    print(
        f"{args.cases} MJCF robots with default classes and frames: {bad} disagreements "
        f"({refusals} more refused by both for a geom's `fromto`; "
        f"{inner_files} included files in the inner splits)"
    )
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
