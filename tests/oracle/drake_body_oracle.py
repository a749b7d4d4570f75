#!/usr/bin/env python3
"""Drake as an independent oracle for `massprop report ROBOT --joints`, for
SDFormat above all (Pinocchio's pip wheel is built without SDFormat, so
pinocchio_oracle.py cannot read it; Drake's wheel carries libsdformat).

For every robot description given (by default every one in shapes/robots
and tests/robots: SDFormat, and URDF and MJCF as a second oracle beside
Pinocchio) and for generated SDFormat models — chains of 60 links,
branches, mimic joints (SDFormat 1.11 `<axis><mimic>`), prismatic, fixed
and ball joints, poses `relative_to` links, joints, `<frame>`s (attached
to each other in chains) and `__model__`, axes `<xyz expressed_in>` any of
them, poses in degrees and quaternions, models with their own `<pose>`,
offsets of 10^3 m, a small robot 10^3 m away — at seeded
random configurations (inside the joints' limits, and a fifth of the
values beyond them): the whole body's mass, centre of mass and inertia
about the centre of mass in the model frame that massprop reports (JSON,
SI) agree with Drake's MultibodyPlant:

- mass: `CalcTotalMass`;
- centre: `CalcCenterOfMassPositionInWorld`;
- inertia: each body's spatial inertia (`CalcSpatialInertiaInBodyFrame`,
  re-expressed in the world at `EvalBodyPoseInWorld`) shifted by Drake
  straight to the centre (`SpatialInertia.Shift`) and summed. Not
  `CalcSpatialInertia(context, frame, bodies)`: it sums about the world
  origin and shifts the sum, which rounds off eps·m·|p|² (10⁻⁸ relative
  for a 0.3 m robot 2.7 km from the origin).

Compared in the model frame, massprop's: Drake places the model at its own
`<pose>` in its world; its `__model__` frame at the zero configuration
(Drake attaches that frame to the canonical link) takes the results back.
A link that no joint holds floats at its written pose in Drake, as massprop
keeps it. Drake turns a `<mimic>` into a constraint of its solver, not of
positions: each follower is set here by hand (SDFormat: multiplier·(leader
− reference) + offset; URDF: offset + multiplier·leader). Drake's parser
replaces an inertial that is not physically valid; massprop composes it as
written (and warns): such a link is given its inertial as written (read
here from the file) before comparing.

Generated too (`--no-root-joints` leaves them out): roots held by a
revolute or prismatic joint from `world`, which turn or slide the root in
the model frame (massprop dropped such joints until this oracle found it).

Agreement: relative_disagreement() in oracle_common.py (the mass against
the mass, the centre against max(|c|∞, radius of gyration), the inertia
against its largest entry) within 1e-12 — or, where links lie far from
the centre compared with the body's size, within the round-off both sides
cannot avoid: placing a link P metres from the origin rounds its position
by eps·P, which moves its share of the inertia by about m·eps·P·R (R the
radius of gyration), eps·P/R of the whole: the tolerance is
max(1e-12, 32·eps·P/R), P the farthest link origin from the origin.

Files with `<include>`s are given to Drake as drake_view() copies them
(include URIs made the absolute paths massprop resolves them to: Drake's
resolver finds neither relative URIs nor `model://` siblings), with
`--package` for massprop where a `model://NAME` is a package.

Generated models with nested `<model>`s, a `<world>` or an `<include>`
(`--nested K` of each) are checked like the rest: a refusal of any
generated model is a failure. Joints are named by the model that declares
them (Drake files a joint under its child's model instance).

Where Python has `pin`, Pinocchio composes the same plant too
(pin_of_drake.py: Drake's reading, Pinocchio's kinematics and composite
inertia), held to the same tolerance: Pinocchio's own SDFormat reader is
not in its pip wheel.

    pip install drake numpy pin
    python3 tests/oracle/drake_body_oracle.py --massprop target/release/massprop

Exit status 0 when every case agrees, 1 otherwise (each disagreement is
printed, with the file, the joint values and both bodies).
"""

import argparse
import atexit
import glob
import logging
import math
import os
import random
import re
import shutil
import sys
import tempfile
import xml.etree.ElementTree as ET

import numpy as np
from pydrake.common.eigen_geometry import Quaternion
from pydrake.math import RollPitchYaw, RotationMatrix
from pydrake.multibody.parsing import Parser
from pydrake.multibody.plant import MultibodyPlant
from pydrake.multibody.tree import BodyIndex, JointIndex, RotationalInertia, SpatialInertia, UnitInertia

from oracle_common import massprop_whole_body, num, nums, relative_disagreement

try:
    # Pinocchio composes what Drake reads, where Python has `pin` (its wheel
    # cannot read SDFormat itself): pin_of_drake.py.
    from pin_of_drake import PinOfDrake as PIN
except ImportError:
    PIN = None

# Drake's parser warns on stderr of what it replaces or ignores (an invalid
# inertia, a mimic outside a discrete plant): handled here, so quiet.
logging.getLogger("drake").setLevel(logging.ERROR)
WORST = [0.0, ""]
# `--root-joints`: a root held by a revolute or prismatic joint from `world`.
ROOT_JOINTS = True

RTOL = 1e-12
EPS = np.finfo(float).eps

# Families of generated models: (links, scale of the offsets, joint types).
FAMILIES = {
    "chain": (60, 0.2, ["revolute", "continuous"]),
    "branches": (40, 0.2, ["revolute", "continuous"]),
    "mimic": (14, 0.2, ["revolute", "prismatic"]),
    "prismatic": (12, 0.2, ["prismatic", "revolute"]),
    "fixed": (15, 0.2, ["fixed", "revolute", "continuous", "ball"]),
    "frames": (20, 0.3, ["revolute", "prismatic", "continuous"]),
    "far": (12, 1e3, ["revolute", "prismatic"]),
    # A small robot 10³ m from the model frame's origin.
    "remote": (12, 0.2, ["revolute", "prismatic", "fixed"]),
}
NESTED = ["nested", "world", "include"]


# ---------------------------------------------------------------- Drake


class DrakeRobot:
    def __init__(self, path):
        self.plant = MultibodyPlant(0.0)
        Parser(self.plant).AddModels(path)
        self.plant.Finalize()
        p = self.plant
        self.top = None
        if path.endswith(".sdf"):
            root = ET.parse(path).getroot()
            tops = root.findall("model") + [m for w in root.findall("world") for m in w.findall("model")]
            tops += [i for w in [root] + root.findall("world") for i in w.findall("include")]
            if len(tops) == 1:
                self.top = tops[0].get("name") or (tops[0].findtext("name") or "").strip() or None
        self.declared = declared_joints(path)
        self.joints = {}
        for k in range(p.num_joints()):
            j = p.get_joint(JointIndex(k))
            if j.num_positions() == 1 and j.type_name() in ("revolute", "prismatic"):
                self.joints[self.scoped(j)] = j
        if path.endswith(".xml"):
            # MJCF: an unnamed joint is `joint N` to massprop (N counting
            # every joint in document order) and `PARENT-CHILD` to Drake;
            # the hinges and slides paired in order.
            ours, count = [], 0
            for j in ET.parse(path).getroot().iter():
                if j.tag in ("joint", "freejoint"):
                    count += 1
                    if j.tag == "joint" and j.get("type", "hinge") in ("hinge", "slide"):
                        ours.append(j.get("name") or f"joint {count}")
            if len(ours) == len(self.joints):
                self.joints = dict(zip(ours, self.joints.values()))
        self.bodies = [BodyIndex(k) for k in range(1, p.num_bodies())]
        self.written = {}
        self.pin = None
        # massprop's frame is the model frame; Drake places the model at its
        # `<pose>` in the world: its `__model__` frame, where it is with every
        # joint at zero (Drake attaches that frame to the canonical link, and
        # it moves with a root that a joint from `world` moves).
        self.model_pose = None
        if self.top is not None and p.HasModelInstanceNamed(self.top):
            frame = p.GetFrameByName("__model__", p.GetModelInstanceByName(self.top))
            self.model_pose = frame.CalcPoseInWorld(p.CreateDefaultContext())

    def as_written(self, path, link):
        """Give `link` its inertial as `path` writes it, valid or not.

        Drake's parser replaces a non-physical inertial (warning "has
        invalid inertia"); massprop composes it as written. Read from the
        file here (the inertial frame's pose in the link's, mass, the six
        entries, each with its format's default), turned and shifted to the
        link's origin by Drake, and set as the body's parameter, so that
        the kinematics stay Drake's."""
        m, xyz, r, t = written_inertial(path, link)
        i_c = RotationalInertia(t[0][0], t[1][1], t[2][2], t[0][1], t[0][2], t[1][2]).ReExpress(r)
        i_o = i_c.ShiftFromCenterOfMass(m, -np.array(xyz))
        g = i_o.CopyToFullMatrix3() / m
        unit = UnitInertia(g[0][0], g[1][1], g[2][2], g[0][1], g[0][2], g[1][2])
        self.written[link] = SpatialInertia(m, np.array(xyz), unit, skip_validity_check=True)

    def scoped(self, j):
        """A joint's name as massprop names it: scoped by the model that
        declares it, from the outermost one, whose own name is left out
        when it is alone. Drake puts a joint in its child's model instance,
        which may be nested below the declaring model (a joint of the outer
        model to `sub::link`): the longest scope of Drake's instance under
        which the file declares a joint of that name is the one."""
        if self.top is None and not self.declared:
            return j.name()
        instance = self.plant.GetModelInstanceName(j.model_instance())
        parts = instance.split("::")
        if self.top is not None and parts[0] == self.top:
            parts = parts[1:]
        for k in range(len(parts), -1, -1):
            name = "::".join(parts[:k] + [j.name()])
            if name in self.declared:
                return name
        return "::".join(parts + [j.name()])

    def body(self, values):
        p = self.plant
        ctx = p.CreateDefaultContext()
        q = p.GetPositions(ctx)
        for name, x in values.items():
            q[self.joints[name].position_start()] = x
        p.SetPositions(ctx, q)
        for link, m in self.written.items():
            p.GetBodyByName(link).SetSpatialInertiaInBodyFrame(ctx, m)
        mass = p.CalcTotalMass(ctx)
        com = p.CalcCenterOfMassPositionInWorld(ctx)
        poses = [p.EvalBodyPoseInWorld(ctx, p.get_body(b)) for b in self.bodies]
        # NOTE: not `CalcSpatialInertia(ctx, frame, bodies)`: it sums the
        # bodies about the world origin and shifts the sum, which loses
        # eps·m·|p|² (10⁻⁸ of a 0.2 m robot 10³ m away). Each body's own
        # spatial inertia (Drake's, about its origin, in world axes) is
        # shifted by Drake straight to the centre of mass instead.
        total = SpatialInertia.Zero()
        for b, x in zip(self.bodies, poses):
            m_b = p.get_body(b).CalcSpatialInertiaInBodyFrame(ctx).ReExpress(x.rotation())
            total += m_b.Shift(com - x.translation())
        i_w = total.CalcRotationalInertia()
        self.pinocchio = None
        if PIN is not None:
            # Pinocchio's composition of Drake's reading (pin_of_drake.py),
            # built once, after any inertial as written is set.
            if self.pin is None:
                self.pin = PIN(p, ctx)
            self.pinocchio = self.pin.body(q)
        if self.model_pose is not None:
            x_wm = self.model_pose
            com = x_wm.inverse().multiply(com)
            i_w = i_w.ReExpress(x_wm.rotation().inverse())
            if self.pinocchio is not None:
                m_p, c_p, i_p = self.pinocchio
                r = x_wm.rotation().inverse().matrix()
                self.pinocchio = (m_p, x_wm.inverse().multiply(c_p), r @ i_p @ r.T)
        if self.pinocchio is not None:
            m_p, c_p, i_p = self.pinocchio
            self.pinocchio = (m_p, list(c_p), np.array(i_p).tolist())
        far = max(np.linalg.norm(x.translation()) for x in poses)
        return (mass, list(com), i_w.CopyToFullMatrix3().tolist()), far


# ---------------------------------------------------------------- the file itself


def written_inertial(path, link):
    """A URDF or SDFormat link's inertial as written: mass, the inertial
    frame's origin in the link's and its rotation (Drake's RotationMatrix),
    and the tensor's entries [3][3] in the inertial frame."""
    root = ET.parse(path).getroot()
    el = next(x for x in root.iter("link") if x.get("name") == link)
    i = el.find("inertial")
    if path.endswith(".urdf"):
        o = i.find("origin")
        xyz = [float(v) for v in (o.get("xyz", "0 0 0") if o is not None else "0 0 0").split()]
        rot = RollPitchYaw(*[float(v) for v in (o.get("rpy", "0 0 0") if o is not None else "0 0 0").split()]).ToRotationMatrix()
        m = float(i.find("mass").get("value"))
        e = {k: float(i.find("inertia").get(k, "0")) for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")}
    else:
        pe = i.find("pose")
        v = [float(x) for x in ((pe.text or "").split() if pe is not None else [])] or [0.0] * 6
        xyz = v[:3]
        if pe is not None and pe.get("rotation_format") == "quat_xyzw":
            x, y, z, w = v[3:]
            n = math.sqrt(w * w + x * x + y * y + z * z)
            rot = RotationMatrix(Quaternion(w / n, x / n, y / n, z / n))
        else:
            a = v[3:] if len(v) == 6 else [0.0, 0.0, 0.0]
            if pe is not None and pe.get("degrees") == "true":
                a = [math.radians(x) for x in a]
            rot = RollPitchYaw(*a).ToRotationMatrix()
        m = float((i.findtext("mass") or "1").strip())
        ie = i.find("inertia")
        e = {k: float(((ie.findtext(k) if ie is not None else None) or ("1" if k in ("ixx", "iyy", "izz") else "0")).strip())
             for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")}
    t = [[e["ixx"], e["ixy"], e["ixz"]], [e["ixy"], e["iyy"], e["iyz"]], [e["ixz"], e["iyz"], e["izz"]]]
    return m, xyz, rot, t


# ---------------------------------------------------------------- mimics


def followers(path):
    """Joint -> (leader, multiplier, offset, reference), so that the
    follower is multiplier·(leader − reference) + offset; SDFormat joints
    of nested and included models by their scoped names (`sub::j`)."""
    out = {}
    if path.endswith(".urdf"):
        for j in ET.parse(path).getroot().iter("joint"):
            m = j.find("mimic")
            if m is not None:
                out[j.get("name")] = (m.get("joint"), float(m.get("multiplier", "1")), float(m.get("offset", "0")), 0.0)
        return out
    if not path.endswith(".sdf"):
        return out

    def walk(model, prefix):
        for j in model.findall("joint"):
            m = j.find("axis/mimic")
            if m is not None:
                f = {k: float((m.findtext(k) or d).strip()) for k, d in (("multiplier", "1"), ("offset", "0"), ("reference", "0"))}
                out[prefix + j.get("name")] = (prefix + m.get("joint"), f["multiplier"], f["offset"], f["reference"])
        for sub in model.findall("model"):
            walk(sub, f"{prefix}{sub.get('name')}::")
        for inc in model.findall("include"):
            included = ET.parse(included_file(inc.findtext("uri") or "", os.path.dirname(path))).getroot().find("model")
            walk(included, f"{prefix}{(inc.findtext('name') or included.get('name')).strip()}::")

    root = ET.parse(path).getroot()
    tops = root.findall("model") + [m for w in root.findall("world") for m in w.findall("model")]
    incs = [i for w in root.findall("world") for i in w.findall("include")]
    for top in tops:
        walk(top, "" if len(tops) + len(incs) == 1 else f"{top.get('name')}::")
    for inc in incs:
        included = ET.parse(included_file(inc.findtext("uri") or "", os.path.dirname(path))).getroot().find("model")
        name = (inc.findtext("name") or included.get("name")).strip()
        walk(included, "" if len(tops) + len(incs) == 1 else f"{name}::")
    return out


def included_file(uri, here):
    """The file an `<include>`'s `file://` URI (absolute, as drake_view
    writes them) or relative path names: a directory's model.config's
    first `<sdf>`."""
    p = os.path.join(here, uri.strip().removeprefix("file://"))
    if os.path.isdir(p):
        config = os.path.join(p, "model.config")
        return os.path.join(p, ET.parse(config).getroot().findtext("sdf").strip())
    return p


def drake_view(path, tmp):
    """(a file Drake reads as massprop reads `path`, massprop's extra
    arguments). Drake's resolver finds neither relative include URIs nor
    `model://NAME` beside the including model's directory: the file's
    directory is copied, each include URI written as the absolute
    `file://` path of what massprop resolves it to. A
    `model://NAME` found in no sibling directory is a package: the
    directory named NAME under the file's directory, given to massprop as
    `--package NAME=DIR`."""
    text = open(path).read()
    if not path.endswith(".sdf") or "<include" not in text:
        return path, []
    top = os.path.dirname(os.path.abspath(path))
    copy = tempfile.mkdtemp(prefix="drake-view-", dir=tmp)
    shutil.rmtree(copy)
    shutil.copytree(top, copy)
    packages = {}

    def resolved(uri, here):
        if uri.startswith("model://"):
            name = uri[len("model://") :].strip("/")
            sibling = os.path.join(os.path.dirname(here), name)
            if os.path.isdir(sibling):
                return sibling
            for d, dirs, _ in os.walk(copy):
                if name in dirs:
                    packages[name] = os.path.relpath(os.path.join(d, name), copy)
                    return os.path.join(d, name)
            return uri
        if "://" in uri:
            return uri.removeprefix("file://")
        return os.path.normpath(os.path.join(here, uri))

    for d, _, files in os.walk(copy):
        for name in files:
            if not name.endswith(".sdf"):
                continue
            p = os.path.join(d, name)
            t = open(p).read()
            t = re.sub(
                r"(<include>(?:(?!</include>).)*?<uri>)\s*([^<]*?)\s*(</uri>)",
                lambda m: m.group(1) + "file://" + resolved(m.group(2), d) + m.group(3),
                t,
                flags=re.S,
            )
            with open(p, "w") as f:
                f.write(t)
    extra = []
    for name, rel in sorted(packages.items()):
        extra += ["--package", f"{name}={os.path.join(top, rel)}"]
    return os.path.join(copy, os.path.relpath(os.path.abspath(path), top)), extra


def declared_joints(path):
    """The joints an SDFormat file declares, by their scoped names (as
    `followers` scopes them); empty for other formats."""
    out = set()
    if not path.endswith(".sdf"):
        return out

    def walk(model, prefix, here):
        for j in model.findall("joint"):
            out.add(prefix + j.get("name"))
        for sub in model.findall("model"):
            walk(sub, f"{prefix}{sub.get('name')}::", here)
        for inc in model.findall("include"):
            try:
                included = ET.parse(included_file(inc.findtext("uri") or "", here)).getroot().find("model")
            except (OSError, ET.ParseError):
                continue
            walk(included, f"{prefix}{(inc.findtext('name') or included.get('name')).strip()}::", here)

    root = ET.parse(path).getroot()
    here = os.path.dirname(path)
    tops = root.findall("model") + [m for w in root.findall("world") for m in w.findall("model")]
    incs = [i for w in root.findall("world") for i in w.findall("include")]
    for top in tops:
        walk(top, "" if len(tops) + len(incs) == 1 else f"{top.get('name')}::", here)
    for inc in incs:
        try:
            included = ET.parse(included_file(inc.findtext("uri") or "", here)).getroot().find("model")
        except (OSError, ET.ParseError):
            continue
        name = (inc.findtext("name") or included.get("name")).strip()
        walk(included, "" if len(tops) + len(incs) == 1 else f"{name}::", here)
    return out


def with_followers(values, follow):
    full = dict(values)
    pending = dict(follow)
    while pending:  # followers of followers, leaders first
        moved = False
        for name, (leader, mult, off, ref) in list(pending.items()):
            if leader in pending:
                continue
            full[name] = mult * (full.get(leader, 0.0) - ref) + off
            del pending[name]
            moved = True
        if not moved:
            raise ValueError(f"followers in a cycle: {sorted(pending)}")
    return full


# ---------------------------------------------------------------- checking


def sample(rng, joint, outside):
    lo, hi = float(joint.position_lower_limits()[0]), float(joint.position_upper_limits()[0])
    if not (math.isfinite(lo) and math.isfinite(hi)) or lo >= hi:
        return rng.uniform(-2 * math.pi, 2 * math.pi)
    if outside:
        w = 0.5 * (hi - lo)
        return rng.uniform(lo - w, lo) if rng.random() < 0.5 else rng.uniform(hi, hi + w)
    return rng.uniform(lo, hi)


def tolerance(body, far):
    m, _, inertia = body
    r = math.sqrt(max(np.trace(np.array(inertia)), 0.0) / m) if m > 0 else 0.0
    return max(RTOL, 32 * EPS * far / r) if r > 0 else RTOL


KEPT = []
# Where drake_view copies a file's directory for Drake's resolver.
VIEWS = tempfile.mkdtemp(prefix="drake-views-")
atexit.register(shutil.rmtree, VIEWS, True)
# Configurations Pinocchio (pin_of_drake.py) composed too.
PINNED = [0]


def kept(path):
    """A generated model that disagrees, copied where it outlives the run
    (with the files it includes)."""
    if not KEPT:
        KEPT.append(tempfile.mkdtemp(prefix="drake-body-oracle-"))
    for f in glob.glob(os.path.join(os.path.dirname(path), "included*.sdf")) + [path]:
        shutil.copy(f, KEPT[0])
    return os.path.join(KEPT[0], os.path.basename(path))


def check_file(massprop, path, rng, cases, generated, nested=False):
    """(configurations checked, disagreements, why skipped or None)."""
    view, extra = drake_view(path, VIEWS)
    try:
        robot = DrakeRobot(view)
    except Exception as e:  # noqa: BLE001 (any reader failure)
        why = str(e).strip().splitlines()[0] if str(e).strip() else type(e).__name__
        if generated:
            return 0, [f"{path}: Drake cannot read a generated model: {why}"], None
        return 0, [], f"skipped {path}: Drake cannot read it ({why})"
    follow = followers(view)
    free = {k: j for k, j in robot.joints.items() if k not in follow}
    bad = []
    for case in range(cases):
        values = {} if case == 0 else {k: sample(rng, j, rng.random() < 0.2) for k, j in free.items()}
        ours, err, warnings = massprop_whole_body(massprop, path, values, extra)
        if ours is None:
            if generated:
                return 0, [f"{path}: massprop refuses a generated model: {err}"], None
            return 0, [], f"skipped {path}: massprop refuses it ({err})"
        for w in warnings.splitlines():
            if "is not physically valid" in w and case == 0:
                robot.as_written(view, w.split('link "', 1)[1].split('"', 1)[0])
        try:
            theirs, far = robot.body(with_followers(values, follow))
        except ValueError as e:  # a joint Pinocchio is not given here
            return 0, [f"{path}: {e}"] if generated else [], None if generated else f"skipped {path}: {e}"
        tol = tolerance(theirs, far)
        if robot.pinocchio is not None:
            PINNED[0] += 1
            r = relative_disagreement(ours, robot.pinocchio)
            if not r <= tol:
                keep = kept(path) if generated else path
                bad.append(
                    f"{keep} at --joints \"{', '.join(f'{k}={num(v)}' for k, v in values.items())}\": "
                    f"Pinocchio (composing Drake's reading) disagrees by {r:.3g} (tolerance {tol:.3g})\n"
                    f"  massprop  {ours}\n  pinocchio {robot.pinocchio}"
                )
        r = relative_disagreement(ours, theirs)
        if r / tol > WORST[0]:
            WORST[:] = [r / tol, f"{os.path.basename(path)}: {r:.3g} of tolerance {tol:.3g}"]
        if not r <= tol:
            keep = kept(path) if generated else path
            bad.append(
                f"{keep} at --joints \"{', '.join(f'{k}={num(v)}' for k, v in values.items())}\": "
                f"relative disagreement {r:.3g} (tolerance {tol:.3g})\n  massprop {ours}\n  drake    {theirs}"
            )
    return cases, bad, None


# ---------------------------------------------------------------- generated SDFormat


def rand3(rng, scale):
    return [rng.uniform(-scale, scale) for _ in range(3)]


def pose(rng, xyz, relative_to=None):
    """A `<pose>` at xyz, turned at random, its rotation written as
    radians, degrees or a quaternion (x y z w)."""
    attr = f' relative_to="{relative_to}"' if relative_to else ""
    how = rng.choice(["rpy", "degrees", "quat", "identity"] if not any(xyz) else ["rpy", "degrees", "quat"])
    if how == "identity":
        return f"<pose{attr}/>"
    if how == "rpy":
        return f"<pose{attr}>{nums(xyz)} {nums(rand3(rng, math.pi))}</pose>"
    if how == "degrees":
        return f'<pose{attr} degrees="true">{nums(xyz)} {nums(rand3(rng, 180.0))}</pose>'
    q = np.array([rng.gauss(0, 1) for _ in range(4)])
    return f'<pose{attr} rotation_format="quat_xyzw">{nums(xyz)} {nums(q / np.linalg.norm(q))}</pose>'


def rotation(rng):
    q = np.array([rng.gauss(0, 1) for _ in range(4)])
    w, x, y, z = q / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


def inertial(rng, scale):
    """A box's inertial: its moments in a turned inertial frame, or its
    full tensor (with products) in the link's axes."""
    m = rng.uniform(0.1, 5.0)
    a, b, c = (rng.uniform(0.2, 1.0) * scale for _ in range(3))
    d = np.diag([m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12])
    xyz = rand3(rng, scale)
    if rng.random() < 0.5:
        at, t = pose(rng, xyz), d
    else:
        r = rotation(rng)
        at, t = f"<pose>{nums(xyz)} 0 0 0</pose>", r @ d @ r.T
    entries = "".join(f"<{k}>{num(t[i][j])}</{k}>" for k, (i, j) in
                      [("ixx", (0, 0)), ("ixy", (0, 1)), ("ixz", (0, 2)), ("iyy", (1, 1)), ("iyz", (1, 2)), ("izz", (2, 2))])
    return f"<inertial>{at}<mass>{num(m)}</mass><inertia>{entries}</inertia></inertial>"


def model_body(rng, kind, anchored=True, base=None):
    """The links, joints and `<frame>`s of one model of a family, as XML
    elements; every `relative_to` and `attached_to` names a frame placed
    before it (or the joint's own child), so that the graph has no cycle."""
    n, scale, types = FAMILIES[kind]
    if base is None:
        base = [1e3, -2e3, 1.5e3] if kind == "remote" else [0.0, 0.0, 0.0]
    size = scale * 0.3
    out, placed, moving = [], [], []

    def at(target, default_is_model):
        v = rand3(rng, scale)
        if target == "__model__" or (target is None and default_is_model):
            v = [x + o for x, o in zip(v, base)]
        return v

    out.append(f'<link name="l0">{pose(rng, at(None, True))}{inertial(rng, size)}</link>')
    placed.append("l0")
    if anchored:
        r = rng.random()
        if r < 0.4:
            out.append(f'<joint name="anchor" type="fixed">{pose(rng, rand3(rng, scale))}<parent>world</parent><child>l0</child></joint>')
        elif r < 0.6 and ROOT_JOINTS:
            t = rng.choice(["revolute", "prismatic"])
            out.append(
                f'<joint name="anchor" type="{t}">{pose(rng, rand3(rng, scale))}<parent>world</parent><child>l0</child>'
                f"<axis><xyz>{nums(rand3(rng, 1.0))}</xyz></axis></joint>"
            )
    for i in range(1, n):
        parent = i - 1 if kind in ("chain", "far", "remote") else rng.randrange(i)
        if kind == "frames" or rng.random() < 0.25:
            to = rng.choice(placed + [None])
            rel = rng.choice([None, None, "__model__"] + placed)
            attached = f' attached_to="{to}"' if to else ""
            p = pose(rng, at(rel, to is None), rel)
            out.append(f'<frame name="f{i}"{attached}>{p}</frame>')
            placed.append(f"f{i}")
        t = rng.choice(types)
        if rng.random() < 0.6:
            lt = rng.choice([None, "__model__"] + placed)
            jt = rng.choice([None, None, f"l{i}"] + placed)
        else:
            jt = rng.choice(["__model__"] + placed)
            lt = f"j{i}"
        out.append(f'<link name="l{i}">{pose(rng, at(lt, True), lt)}{inertial(rng, size)}</link>')
        axis = ""
        if t != "fixed" and t != "ball":
            ex = rng.choice([None, None, None, "__model__", f"l{parent}", f"l{i}", f"j{i}"] + placed)
            ex = f' expressed_in="{ex}"' if ex else ""
            axis = f"<axis><xyz{ex}>{nums(rand3(rng, 1.0))}</xyz>"
            if t in ("revolute", "prismatic"):
                axis += f"<limit><lower>{num(-rng.uniform(0.2, 2))}</lower><upper>{num(rng.uniform(0.2, 2))}</upper></limit>"
            if kind == "mimic" and moving and rng.random() < 0.5:
                leader = rng.choice(moving)
                axis += (
                    f'<mimic joint="{leader}"><multiplier>{num(rng.uniform(-2, 2))}</multiplier>'
                    f"<offset>{num(rng.uniform(-0.5, 0.5))}</offset><reference>{num(rng.uniform(-0.3, 0.3))}</reference></mimic>"
                )
            axis += "</axis>"
            moving.append(f"j{i}")
        out.append(
            f'<joint name="j{i}" type="{t}">{pose(rng, at(jt, False), jt)}'
            f"<parent>l{parent}</parent><child>l{i}</child>{axis}</joint>"
        )
        placed += [f"l{i}", f"j{i}"]
    return out


def sdf(body, name="m", placed=""):
    """A file of one model; `placed`: the model's own `<pose>` (where Drake
    puts it in its world; massprop reports in the model frame)."""
    return f'<?xml version="1.0"?>\n<sdf version="1.11">\n<model name="{name}">{placed}\n' + "\n".join(body) + "\n</model>\n</sdf>\n"


def nested_files(rng, kind, tmp, k):
    """A model of one of the constructs another change teaches massprop:
    a nested `<model>`, a `<world>`, an `<include>` (of a file beside it)."""
    if kind == "world":
        body = model_body(rng, "fixed")
        text = sdf(body).replace("<model", '<world name="w">\n<model', 1).replace("</model>\n</sdf>", "</model>\n</world>\n</sdf>")
        return text
    outer = model_body(rng, "prismatic")
    inner = model_body(rng, "mimic", anchored=False)
    joint = (
        f'<joint name="jn" type="revolute">{pose(rng, rand3(rng, 0.2))}<parent>l0</parent><child>sub::l0</child>'
        f"<axis><xyz>{nums(rand3(rng, 1.0))}</xyz><limit><lower>-1</lower><upper>1</upper></limit></axis></joint>"
    )
    if kind == "nested":
        sub = f'<model name="sub">{pose(rng, rand3(rng, 0.5))}\n' + "\n".join(inner) + "\n</model>"
    else:
        path = os.path.join(tmp, f"included{k}.sdf")
        with open(path, "w") as f:
            f.write(sdf(inner, "part"))
        sub = f"<include><uri>file://{path}</uri><name>sub</name>{pose(rng, rand3(rng, 0.5))}</include>"
    return sdf(outer + [sub, joint])


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    repo = os.path.dirname(os.path.dirname(here))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--massprop", required=True)
    ap.add_argument("--cases", type=int, default=12, help="configurations per robot")
    ap.add_argument("--models", type=int, default=2, help="generated models of each family")
    ap.add_argument("--nested", type=int, default=2, help="generated models of each of nested, world, include")
    ap.add_argument("--seed", type=int, default=34)
    ap.add_argument(
        "--root-joints",
        action=argparse.BooleanOptionalAction,
        default=True,
        help="also hold generated roots by revolute and prismatic joints from `world` (default: on)",
    )
    ap.add_argument("files", nargs="*")
    a = ap.parse_args()
    global ROOT_JOINTS
    ROOT_JOINTS = a.root_joints
    rng = random.Random(a.seed)
    files = a.files or sorted(
        glob.glob(os.path.join(repo, "shapes/robots/*")) + glob.glob(os.path.join(repo, "tests/robots/*")) + glob.glob(os.path.join(repo, "tests/robots/*/*.sdf"))
    )
    files = [f for f in files if f.endswith((".urdf", ".sdf", ".xml"))]
    total, failures, skipped = 0, [], []
    with tempfile.TemporaryDirectory() as tmp:
        made = []
        for kind in FAMILIES:
            for k in range(a.models):
                placed = pose(rng, rand3(rng, FAMILIES[kind][1] * 5)) if k % 2 else ""
                made.append((os.path.join(tmp, f"{kind}{k}.sdf"), sdf(model_body(rng, kind), placed=placed), False))
        for kind in NESTED:
            for k in range(a.nested):
                made.append((os.path.join(tmp, f"{kind}{k}.sdf"), nested_files(rng, kind, tmp, f"{kind}{k}"), True))
        for path, text, _ in made:
            with open(path, "w") as f:
                f.write(text)
        work = [(f, False, False) for f in files] + [(p, True, nested) for p, _, nested in made]
        for path, generated, nested in work:
            n, bad, skip = check_file(a.massprop, path, rng, a.cases, generated, nested)
            total += n
            failures += bad
            if skip:
                skipped.append(skip)
    for s in skipped:
        print(s)
    for b in failures:
        print("DISAGREE:", b)
    print(
        f"drake body oracle: {total - len(failures)} of {total} configurations agree "
        f"to {RTOL:g} or the round-off bound ({len(skipped)} files skipped); "
        f"the closest to its tolerance: {WORST[1] or 'none'}"
    )
    if PIN is None:
        print("pinocchio: not composed (Python has no `pin`)")
    else:
        print(f"pinocchio, composing Drake's reading: {PINNED[0]} configurations compared (each a failure above if not within the same tolerance)")
    return 1 if failures or total == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
