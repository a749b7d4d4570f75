#!/usr/bin/env python3
"""MuJoCo as an independent oracle for `massprop check --engine mujoco` and
`massprop export --to mjcf`.

Usage:

    python tests/oracle/mujoco_oracle.py --massprop PATH_TO_BINARY \
        [--seed N] [--cases N] [--skip-kind KIND ...] [--keep DIR] [--no-export]

Part one (agreement). A seeded corpus of small robot descriptions is
written, one file per case, to a temporary directory: single-body MJCF
models (`fullinertia` and `diaginertia` + `quat`, with and without a joint,
some with `<compiler balanceinertia/boundmass/boundinertia>`), two-body MJCF
models whose moving body leans on a jointless child, and two-link URDF
models (a base and a child on a moving or a fixed joint). The tensors are
valid ones turned by random rotations, and invalid ones of every kind: a
negative eigenvalue, the triangle inequality broken by a relative margin
from 1e-1 down to one ulp, exact equality, eigenvalues either side of
mjEPS = 1e-14 and mjMINVAL = 1e-15, tiny, zero and negative masses. MuJoCo
compiles each file (`mujoco.MjModel.from_xml_path`): that is its verdict.
Then `massprop check --engine mujoco --format json FILES...` runs on the same
files, ~200 a process; a file is valid for massprop iff every link's mujoco
verdict is. The two must agree on every file.

Where a verdict rests on MuJoCo's own eigenvalue solver (a tensor with
non-zero products), the corpus keeps a relative margin of at least 1e-12
from the limit: that solver is accurate to ~15 ulps of the largest moment,
not to the last bit, so nearer than that its verdict is round-off. The
one-ulp and exact-equality cases use `diaginertia` and product-free
`fullinertia`/URDF tensors, whose values MuJoCo uses as written.
tests/oracle/MUJOCO-RULES.md has the rules and the experiments behind them.

Part two (export). For every `shapes/*.toml` that `massprop report` accepts,
`massprop export FILE --to mjcf --about 0,0,0` (a `fullinertia` element;
the link origin at the file's origin, whatever the file's own `about`) and
`... --principal` (`diaginertia` + `quat`) are each put in a body on a
freejoint, compiled, and MuJoCo's mass, centre (`body_ipos`) and sorted
principal moments (`body_inertia`) compared with `massprop report FILE
--format json --about 0,0,0` (`mass`, `center_of_mass_ref`,
`principal_moments`) to a relative 1e-12.

Exit status: 0 when everything agrees, 1 on any disagreement or mismatch,
2 when the oracle itself cannot run (no mujoco, no binary, bad arguments).
Standard library, numpy and mujoco only.
"""

from __future__ import annotations

import argparse
import dataclasses
import glob
import json
import math
import os
import re
import shutil
import sys
import tempfile
from fractions import Fraction
from typing import Callable, Optional

import numpy as np

from oracle_common import num, nums, run, ulps  # beside this script

try:
    import mujoco
except ImportError as err:  # pragma: no cover - reported, not tested
    print(f"mujoco_oracle: cannot import mujoco ({err}); "
          "install it with `pip install mujoco`", file=sys.stderr)
    sys.exit(2)

# MuJoCo's constants (include/mujoco/mjtnum.h): mjEPS is the floor of a
# fullinertia's smallest eigenvalue, mjMINVAL that of a moving body's mass
# and principal moments.
MJ_EPS = 1e-14
MJ_MINVAL = 1e-15

# Files per massprop process.
BATCH = 200

# Substrings of MuJoCo's messages about an inertial; any other failure means
# the corpus wrote something MuJoCo cannot read (a bug here, not a verdict).
INERTIAL_MESSAGES = (
    "inertia must have positive eigenvalues",
    "inertia must satisfy A + B >= C",
    "mass and inertia of moving bodies must be larger than mjMINVAL",
    "mass and inertia cannot be negative",
)

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


# --------------------------------------------------------------------------
# Numbers and rotations





def random_quat(rng: np.random.Generator) -> np.ndarray:
    """A uniformly distributed unit quaternion (w, x, y, z)."""
    q = rng.normal(size=4)
    return q / np.linalg.norm(q)


def quat_matrix(q) -> np.ndarray:
    """The rotation matrix of the unit quaternion (w, x, y, z)."""
    w, x, y, z = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])


def rpy_matrix(rpy) -> np.ndarray:
    """URDF's fixed-axis roll, pitch, yaw: Rz(yaw) Ry(pitch) Rx(roll)."""
    r, p, y = rpy
    cr, sr, cp, sp, cy, sy = (math.cos(r), math.sin(r), math.cos(p),
                              math.sin(p), math.cos(y), math.sin(y))
    return np.array([
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ])


def turned(moments, rot: np.ndarray) -> np.ndarray:
    """R diag(moments) Rᵀ, made exactly symmetric."""
    m = rot @ np.diag(moments) @ rot.T
    return (m + m.T) / 2


def six(m: np.ndarray) -> list:
    """A tensor's entries in MJCF fullinertia order: xx yy zz xy xz yz."""
    return [m[0, 0], m[1, 1], m[2, 2], m[0, 1], m[0, 2], m[1, 2]]


def log_uniform(rng: np.random.Generator, lo: float, hi: float) -> float:
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


def moments_with_margin(rng, scale: float, rel: float, broken: bool) -> list:
    """Principal moments (a, b, c), c the largest, with c − (a + b) =
    ±rel·c: broken (c > a + b) or kept (c < a + b) by that margin."""
    a = scale * rng.uniform(0.3, 1.0)
    b = scale * rng.uniform(0.3, 1.0)
    c = (a + b) * (1 + rel) if broken else (a + b) * (1 - rel)
    return [a, b, c]


def valid_moments(rng, scale: float) -> list:
    """Principal moments well inside the triangle inequality (a relative
    margin of at least 1e-3 from its edge)."""
    a = scale * rng.uniform(0.2, 1.0)
    b = scale * rng.uniform(0.2, 1.0)
    lo, hi = abs(a - b), a + b
    c = rng.uniform(lo + 1e-3 * hi, hi * (1 - 1e-3))
    return [a, b, c]


def shuffled(rng, xs) -> list:
    xs = list(xs)
    rng.shuffle(xs)
    return xs


# --------------------------------------------------------------------------
# The files


@dataclasses.dataclass
class Inertial:
    """One inertial as written. `full` (six numbers, MJCF order) or `diag`
    (three) with `quat`; for URDF, `full` and an optional `rpy`."""

    mass: float
    pos: tuple = (0.0, 0.0, 0.0)
    full: Optional[list] = None
    diag: Optional[list] = None
    quat: Optional[list] = None
    rpy: Optional[list] = None

    def mjcf(self) -> str:
        attrs = f'pos="{nums(self.pos)}" mass="{num(self.mass)}"'
        if self.full is not None:
            attrs += f' fullinertia="{nums(self.full)}"'
        else:
            if self.quat is not None:
                attrs += f' quat="{nums(self.quat)}"'
            attrs += f' diaginertia="{nums(self.diag)}"'
        return f"<inertial {attrs}/>"

    def urdf(self) -> str:
        xx, yy, zz, xy, xz, yz = self.full
        rpy = self.rpy if self.rpy is not None else (0.0, 0.0, 0.0)
        return (
            "<inertial>\n"
            f'      <origin xyz="{nums(self.pos)}" rpy="{nums(rpy)}"/>\n'
            f'      <mass value="{num(self.mass)}"/>\n'
            f'      <inertia ixx="{num(xx)}" ixy="{num(xy)}" ixz="{num(xz)}" '
            f'iyy="{num(yy)}" iyz="{num(yz)}" izz="{num(zz)}"/>\n'
            "    </inertial>"
        )


def compiler_attrs(compiler: dict) -> str:
    parts = []
    for key, value in compiler.items():
        if isinstance(value, bool):
            parts.append(f'{key}="{"true" if value else "false"}"')
        else:
            parts.append(f'{key}="{num(value)}"')
    return " ".join(parts)


MJCF_JOINTS = {
    "hinge": '<joint type="hinge" axis="0 0 1"/>',
    "slide": '<joint type="slide" axis="1 0 0"/>',
    "ball": '<joint type="ball"/>',
    "free": "<freejoint/>",
}


def mjcf_body(name: str, inertial: Optional[Inertial], joint: Optional[str],
              inner: str = "", indent: str = "    ") -> str:
    lines = [f'{indent}<body name="{name}" pos="0 0 0.1">']
    if joint is not None:
        lines.append(f"{indent}  {MJCF_JOINTS[joint]}")
    if inertial is not None:
        lines.append(f"{indent}  {inertial.mjcf()}")
    if inner:
        lines.append(inner)
    lines.append(f"{indent}</body>")
    return "\n".join(lines)


def mjcf_model(body: str, compiler: dict) -> str:
    comp = f"  <compiler {compiler_attrs(compiler)}/>\n" if compiler else ""
    return (f'<mujoco model="oracle">\n{comp}  <worldbody>\n{body}\n'
            "  </worldbody>\n</mujoco>\n")


def mjcf_single(inertial: Inertial, joint: Optional[str],
                compiler: Optional[dict] = None) -> str:
    return mjcf_model(mjcf_body("link", inertial, joint), compiler or {})


URDF_JOINTS = ("revolute", "continuous", "prismatic", "floating", "planar")

BASE_INERTIAL = Inertial(mass=1.0, pos=(0.0, 0.0, 0.05),
                         full=[0.01, 0.02, 0.025, 0.0, 0.0, 0.0])


def urdf_model(links: list, joints: list, compiler: Optional[dict] = None) -> str:
    """`links`: (name, Inertial or None); `joints`: (type, parent, child)."""
    out = ['<robot name="oracle">']
    if compiler:
        out.append(f"  <mujoco>\n    <compiler {compiler_attrs(compiler)}/>\n  </mujoco>")
    for name, inertial in links:
        if inertial is None:
            out.append(f'  <link name="{name}"/>')
        else:
            out.append(f'  <link name="{name}">\n    {inertial.urdf()}\n  </link>')
    for i, (kind, parent, child) in enumerate(joints):
        body = [f'  <joint name="j{i}" type="{kind}">',
                f'    <parent link="{parent}"/>', f'    <child link="{child}"/>',
                '    <origin xyz="0 0 0.1" rpy="0 0 0"/>']
        if kind in ("revolute", "continuous", "prismatic", "planar"):
            body.append('    <axis xyz="0 0 1"/>')
        if kind in ("revolute", "prismatic"):
            body.append('    <limit lower="-1" upper="1" effort="10" velocity="1"/>')
        body.append("  </joint>")
        out.append("\n".join(body))
    out.append("</robot>")
    return "\n".join(out) + "\n"


def urdf_pair(child: Optional[Inertial], joint: str,
              compiler: Optional[dict] = None,
              base: Optional[Inertial] = BASE_INERTIAL) -> str:
    """A base link and a child link on one joint."""
    return urdf_model([("base", base), ("child", child)],
                      [(joint, "base", "child")], compiler)


# --------------------------------------------------------------------------
# The corpus: one family per kind of case


@dataclasses.dataclass
class Case:
    kind: str
    ext: str          # "xml" (MJCF) or "urdf"
    text: str
    note: str         # what the case is, for a disagreement's report
    intent: bool      # the verdict MUJOCO-RULES.md predicts (informational)
    path: str = ""


Family = Callable[[np.random.Generator], Case]
FAMILIES: list[tuple[str, Family]] = []


def family(kind: str):
    """Register a generator of one kind of case."""
    def register(fn):
        FAMILIES.append((kind, fn))
        return fn
    return register


def pick(rng, xs):
    return xs[int(rng.integers(len(xs)))]


def maybe_joint(rng) -> Optional[str]:
    """A moving body half the time, on a random joint type."""
    return pick(rng, list(MJCF_JOINTS)) if rng.uniform() < 0.5 else None


def random_mass(rng) -> float:
    return log_uniform(rng, 1e-3, 1e2)


def random_pos(rng) -> tuple:
    return tuple(float(v) for v in rng.uniform(-0.1, 0.1, 3))


def full_inertial(rng, moments, *, rotate=True, mass=None) -> Inertial:
    rot = quat_matrix(random_quat(rng)) if rotate else np.eye(3)
    m = turned(moments, rot) if rotate else np.diag(moments)
    return Inertial(mass=random_mass(rng) if mass is None else mass,
                    pos=random_pos(rng), full=six(m))


def diag_inertial(rng, diag, *, mass=None) -> Inertial:
    return Inertial(mass=random_mass(rng) if mass is None else mass,
                    pos=random_pos(rng), diag=list(diag),
                    quat=list(random_quat(rng)))


def moving_word(joint) -> str:
    return f"moving ({joint})" if joint else "fixed"


# Valid tensors --------------------------------------------------------------

@family("valid-full")
def valid_full(rng):
    joint = maybe_joint(rng)
    p = valid_moments(rng, log_uniform(rng, 1e-7, 1e1))
    return Case("valid-full", "xml", mjcf_single(full_inertial(rng, p), joint),
                f"turned valid tensor, moments {p}, {moving_word(joint)}", True)


@family("valid-diag")
def valid_diag(rng):
    joint = maybe_joint(rng)
    p = shuffled(rng, valid_moments(rng, log_uniform(rng, 1e-7, 1e1)))
    return Case("valid-diag", "xml", mjcf_single(diag_inertial(rng, p), joint),
                f"diaginertia {p} with a random quat, {moving_word(joint)}", True)


# Negative eigenvalues ---------------------------------------------------------

@family("negative-eigenvalue")
def negative_eigenvalue(rng):
    joint = maybe_joint(rng)
    scale = log_uniform(rng, 1e-6, 1e1)
    p = [scale, scale * rng.uniform(0.5, 1.0), -scale * log_uniform(rng, 1e-6, 1.0)]
    rotate = rng.uniform() < 0.7
    return Case("negative-eigenvalue", "xml",
                mjcf_single(full_inertial(rng, p, rotate=rotate), joint),
                f"fullinertia with eigenvalues {p} ({'turned' if rotate else 'axis-aligned'}),"
                f" {moving_word(joint)}", False)


@family("negative-diag")
def negative_diag(rng):
    """A negative diaginertia value: clamped to 0 (boundinertia's default),
    then the triangle inequality on the clamped values; a moving body then
    needs every moment >= mjMINVAL."""
    joint = maybe_joint(rng)
    a = log_uniform(rng, 1e-4, 1.0)
    shape = pick(rng, ["equal", "unequal"])
    b = a if shape == "equal" else a * rng.uniform(1.5, 3.0)
    d = shuffled(rng, [a, b, -a * rng.uniform(0.1, 2.0)])
    intent = joint is None and shape == "equal"
    return Case("negative-diag", "xml", mjcf_single(diag_inertial(rng, d), joint),
                f"diaginertia {d}, {moving_word(joint)}", intent)


# The triangle inequality -------------------------------------------------------

TRIANGLE_MARGINS = (1e-1, 1e-2, 1e-4, 1e-6, 1e-9, 1e-12)


@family("triangle-margin-full")
def triangle_margin_full(rng):
    """A turned tensor whose moments break (or keep) the triangle inequality
    by a relative margin down to 1e-12, well above MuJoCo's solver's
    round-off."""
    joint = maybe_joint(rng)
    rel = pick(rng, TRIANGLE_MARGINS)
    broken = rng.uniform() < 0.6
    p = moments_with_margin(rng, log_uniform(rng, 1e-6, 1e1), rel, broken)
    return Case("triangle-margin-full", "xml",
                mjcf_single(full_inertial(rng, p), joint),
                f"turned tensor, moments {p}: c − (a+b) = {'+' if broken else '−'}{rel}·c,"
                f" {moving_word(joint)}", not broken)


@family("triangle-margin-diag")
def triangle_margin_diag(rng):
    joint = maybe_joint(rng)
    rel = pick(rng, TRIANGLE_MARGINS)
    broken = rng.uniform() < 0.6
    p = shuffled(rng, moments_with_margin(rng, log_uniform(rng, 1e-6, 1e1), rel, broken))
    return Case("triangle-margin-diag", "xml", mjcf_single(diag_inertial(rng, p), joint),
                f"diaginertia {p}: broken={broken} by {rel}, {moving_word(joint)}",
                not broken)


def ulp_triangle(rng, k: int) -> list:
    """Moments (a, b, c) with c = fl(a + b) moved k ulps (k = 0: MuJoCo's
    A + B >= C holds with equality in floating point)."""
    a = log_uniform(rng, 1e-6, 1e1)
    b = a * rng.uniform(0.3, 1.0)
    return [a, b, ulps(a + b, k)]


ULP_STEPS = (-2, -1, 0, 0, 1, 1, 2, 3, 8, 64, 1024)


@family("triangle-ulp-diag")
def triangle_ulp_diag(rng):
    joint = maybe_joint(rng)
    k = pick(rng, ULP_STEPS)
    p = shuffled(rng, ulp_triangle(rng, k))
    return Case("triangle-ulp-diag", "xml", mjcf_single(diag_inertial(rng, p), joint),
                f"diaginertia {p}: c = fl(a+b) {k:+d} ulp, {moving_word(joint)}", k <= 0)


@family("triangle-ulp-full")
def triangle_ulp_full(rng):
    joint = maybe_joint(rng)
    k = pick(rng, ULP_STEPS)
    p = shuffled(rng, ulp_triangle(rng, k))
    return Case("triangle-ulp-full", "xml",
                mjcf_single(full_inertial(rng, p, rotate=False), joint),
                f"product-free fullinertia {p}: c = fl(a+b) {k:+d} ulp, {moving_word(joint)}",
                k <= 0)


EXACT_TRIANGLES = ([1.0, 1.0, 2.0], [0.25, 0.5, 0.75], [3.0, 5.0, 8.0],
                   [0.125, 0.125, 0.25], [1.5, 2.5, 4.0], [2.0 ** -20, 2.0 ** -21, 3 * 2.0 ** -21])


@family("triangle-equal")
def triangle_equal(rng):
    """Exact equality with exactly representable moments: A + B = C holds."""
    joint = maybe_joint(rng)
    base = pick(rng, EXACT_TRIANGLES)
    scale = 2.0 ** int(rng.integers(-20, 4))
    p = shuffled(rng, [v * scale for v in base])
    form = pick(rng, ["diag", "full"])
    inertial = diag_inertial(rng, p) if form == "diag" else full_inertial(rng, p, rotate=False)
    return Case("triangle-equal", "xml", mjcf_single(inertial, joint),
                f"{form} {p}: exact equality, {moving_word(joint)}", True)


@family("triangle-rounding")
def triangle_rounding(rng):
    """MuJoCo adds in floating point: c = fl(a + b) where fl rounded up, so
    the exact a + b is below c and yet A + B >= C holds."""
    joint = maybe_joint(rng)
    while True:
        a = log_uniform(rng, 1e-6, 1e1)
        b = a * rng.uniform(0.3, 1.0)
        if Fraction(a + b) > Fraction(a) + Fraction(b):
            break
    p = shuffled(rng, [a, b, a + b])
    form = pick(rng, ["diag", "full"])
    inertial = diag_inertial(rng, p) if form == "diag" else full_inertial(rng, p, rotate=False)
    return Case("triangle-rounding", "xml", mjcf_single(inertial, joint),
                f"{form} {p}: c = fl(a+b) > exact a+b, {moving_word(joint)}", True)


# Eigenvalue floor (mjEPS) and moving-body floor (mjMINVAL) -----------------------

EIG_FLOOR_VALUES = (
    ("1e-14", 1e-14, True), ("1e-14 + 1 ulp", ulps(1e-14, 1), True),
    ("1e-14 − 1 ulp", ulps(1e-14, -1), False), ("1e-14·(1+1e-9)", 1e-14 * (1 + 1e-9), True),
    ("1e-14·(1−1e-9)", 1e-14 * (1 - 1e-9), False), ("2e-14", 2e-14, True),
    ("1e-15", 1e-15, False), ("1e-15 + 1 ulp", ulps(1e-15, 1), False),
    ("1e-15 − 1 ulp", ulps(1e-15, -1), False), ("0", 0.0, False), ("−0", -0.0, False),
    ("−1e-300", -1e-300, False),
)


@family("eigen-floor-full")
def eigen_floor_full(rng):
    """A product-free fullinertia whose smallest moment sits at mjEPS or
    mjMINVAL, to the ulp; the others equal, so the triangle holds."""
    joint = maybe_joint(rng)
    label, v, intent = pick(rng, EIG_FLOOR_VALUES)
    s = log_uniform(rng, 1e-6, 1e1)
    p = shuffled(rng, [v, s, s])
    return Case("eigen-floor-full", "xml",
                mjcf_single(full_inertial(rng, p, rotate=False), joint),
                f"product-free fullinertia {p}: smallest {label}, {moving_word(joint)}", intent)


@family("eigen-floor-turned")
def eigen_floor_turned(rng):
    """A turned tensor whose every moment is ~1e-14, the smallest a relative
    1e-1..1e-9 either side of mjEPS (round-off ~1e-29: decided)."""
    joint = maybe_joint(rng)
    rel = pick(rng, (1e-1, 1e-3, 1e-6, 1e-9))
    above = rng.uniform() < 0.5
    low = MJ_EPS * (1 + rel if above else 1 - rel)
    p = [low, 2e-14, 2.5e-14]
    return Case("eigen-floor-turned", "xml", mjcf_single(full_inertial(rng, p), joint),
                f"turned tensor, moments {p}: smallest {'above' if above else 'below'} 1e-14"
                f" by {rel}, {moving_word(joint)}", above)


@family("zero-fullinertia")
def zero_fullinertia(rng):
    joint = maybe_joint(rng)
    z = pick(rng, [0.0, -0.0])
    return Case("zero-fullinertia", "xml",
                mjcf_single(Inertial(mass=random_mass(rng), full=[z] * 6), joint),
                f"fullinertia all {num(z)}, {moving_word(joint)}", False)


DIAG_FLOOR_VALUES = (
    ("1e-15", 1e-15), ("1e-15 + 1 ulp", ulps(1e-15, 1)), ("1e-15 − 1 ulp", ulps(1e-15, -1)),
    ("5e-16", 5e-16), ("2e-15", 2e-15), ("0", 0.0),
)


@family("diag-minval")
def diag_minval(rng):
    """diaginertia values either side of mjMINVAL: only a moving body minds."""
    joint = maybe_joint(rng)
    label, v = pick(rng, DIAG_FLOOR_VALUES)
    if rng.uniform() < 0.5:
        s = log_uniform(rng, 1e-6, 1e1)
        d, what = shuffled(rng, [v, s, s]), f"one moment {label}"
    else:
        d, what = [v, v, v], f"all three {label}"
    intent = joint is None or v >= MJ_MINVAL
    return Case("diag-minval", "xml", mjcf_single(diag_inertial(rng, d), joint),
                f"diaginertia {d}: {what}, {moving_word(joint)}", intent)


# Masses -------------------------------------------------------------------------

MASS_VALUES = (
    ("1e-15", 1e-15), ("1e-15 + 1 ulp", ulps(1e-15, 1)), ("1e-15 − 1 ulp", ulps(1e-15, -1)),
    ("1e-16", 1e-16), ("2e-15", 2e-15), ("0", 0.0), ("−0", -0.0),
    ("−1e-15", -1e-15), ("−1", -1.0), ("−1e3", -1e3),
)


@family("mass")
def mass_floor(rng):
    """Tiny, zero and negative masses: a moving body needs mass >= mjMINVAL,
    a fixed one nothing (a negative mass is clamped to 0)."""
    joint = maybe_joint(rng)
    label, m = pick(rng, MASS_VALUES)
    p = valid_moments(rng, log_uniform(rng, 1e-6, 1.0))
    form = pick(rng, ["diag", "full"])
    inertial = (diag_inertial(rng, p, mass=m) if form == "diag"
                else full_inertial(rng, p, mass=m))
    intent = joint is None or m >= MJ_MINVAL
    return Case("mass", "xml", mjcf_single(inertial, joint),
                f"{form}, mass {label}, {moving_word(joint)}", intent)


# Compiler settings ----------------------------------------------------------------

@family("balanceinertia")
def balanceinertia(rng):
    """balanceinertia replaces moments that break the triangle inequality by
    their mean; a negative fullinertia eigenvalue is refused before that."""
    joint = maybe_joint(rng)
    what = pick(rng, ["broken-diag", "broken-full", "broken-turned", "negative-eig",
                      "mean-minval", "valid"])
    scale = log_uniform(rng, 1e-6, 1.0)
    if what == "broken-diag":
        p = shuffled(rng, moments_with_margin(rng, scale, pick(rng, (1e-1, 1e-9)), True))
        inertial, intent = diag_inertial(rng, p), True
    elif what == "broken-full":
        p = shuffled(rng, ulp_triangle(rng, pick(rng, (1, 5, 1000))))
        inertial, intent = full_inertial(rng, p, rotate=False), True
    elif what == "broken-turned":
        p = moments_with_margin(rng, scale, 1e-2, True)
        inertial, intent = full_inertial(rng, p), True
    elif what == "negative-eig":
        p = [scale, scale, -scale * 0.1]
        inertial, intent = full_inertial(rng, p), False
    elif what == "mean-minval":
        # (0 + 0 + c)/3: 3e-15/3 = 9.999999999999999e-16 < mjMINVAL, the next
        # double up gives exactly 1e-15.
        c = pick(rng, [3e-15, ulps(3e-15, 1), 6e-15])
        p = shuffled(rng, [0.0, 0.0, c])
        inertial, intent = diag_inertial(rng, p), joint is None or (c / 3.0) >= MJ_MINVAL
    else:
        p = valid_moments(rng, scale)
        inertial, intent = full_inertial(rng, p), True
    return Case("balanceinertia", "xml",
                mjcf_single(inertial, joint, {"balanceinertia": True}),
                f"balanceinertia, {what}, moments {p}, {moving_word(joint)}", intent)


@family("boundmass")
def boundmass(rng):
    joint = pick(rng, list(MJCF_JOINTS) + [None])
    mass = pick(rng, [0.0, -1.0, 1e-16, 1e-3])
    bound = pick(rng, [1e-3, 1e-15, 1e-16])
    p = valid_moments(rng, log_uniform(rng, 1e-6, 1.0))
    intent = joint is None or max(mass, bound) >= MJ_MINVAL
    return Case("boundmass", "xml",
                mjcf_single(diag_inertial(rng, p, mass=mass), joint, {"boundmass": bound}),
                f"boundmass {bound}, mass {mass}, {moving_word(joint)}", intent)


@family("boundinertia")
def boundinertia(rng):
    """boundinertia raises each principal moment to it before the triangle
    check; with it set, a fullinertia may even have an eigenvalue down to
    −mjEPS·max(1, largest)."""
    joint = maybe_joint(rng)
    what = pick(rng, ["zero-diag", "negative-diag", "small-full", "negative-full",
                      "negative-full-edge", "triangle"])
    bound = pick(rng, [1e-3, 1e-15, 1e-16])
    if what == "zero-diag":
        d = [0.0, 0.0, 0.0]
        inertial = diag_inertial(rng, d)
        intent = joint is None or bound >= MJ_MINVAL
    elif what == "negative-diag":
        d = shuffled(rng, [-0.5, 1e-3, 1e-3])
        inertial = diag_inertial(rng, d)
        intent = joint is None or bound >= MJ_MINVAL
    elif what == "small-full":
        small = pick(rng, [1e-15, 0.0])
        d = shuffled(rng, [small, 1.0, 1.0])
        inertial = full_inertial(rng, d, rotate=False)
        intent = joint is None or max(small, bound) >= MJ_MINVAL
    elif what == "negative-full":
        d = shuffled(rng, [-0.1, 1.0, 1.0])
        inertial = full_inertial(rng, d, rotate=False)
        intent = False
    elif what == "negative-full-edge":
        big = pick(rng, [0.5, 1.0, 3.5, 123.456])
        edge = -(MJ_EPS * max(1.0, big))
        k = pick(rng, [-1, 0, 1])
        d = shuffled(rng, [ulps(edge, k), big, big])
        inertial = full_inertial(rng, d, rotate=False)
        intent = k >= 0 and (joint is None or bound >= MJ_MINVAL)
    else:
        bound = pick(rng, [2.0, 1.5, 1.4])
        d = shuffled(rng, [1.0, 1.0, 3.0])
        inertial = diag_inertial(rng, d)
        intent = bound >= 1.5
    return Case("boundinertia", "xml",
                mjcf_single(inertial, joint, {"boundinertia": bound}),
                f"boundinertia {bound}, {what} {d}, {moving_word(joint)}", intent)


@family("negative-bound")
def negative_bound(rng):
    """A negative boundmass/boundinertia lets a negative value through the
    clamp: "mass and inertia cannot be negative"."""
    key = pick(rng, ["boundmass", "boundinertia"])
    bad = rng.uniform() < 0.6
    if key == "boundmass":
        inertial = diag_inertial(rng, [1.0, 1.0, 1.0], mass=-5.0 if bad else 1.0)
    else:
        inertial = diag_inertial(rng, shuffled(rng, [-5.0 if bad else 1.0, 1.0, 1.0]))
    return Case("negative-bound", "xml", mjcf_single(inertial, None, {key: -1.0}),
                f"{key} −1, {'a negative value' if bad else 'all positive'}, fixed", not bad)


# A moving body leaning on a jointless child ------------------------------------------

@family("static-child")
def static_child(rng):
    """A moving body below mjMINVAL passes when a jointless descendant
    (reached through jointless bodies) has mass and all moments >= mjMINVAL."""
    what = pick(rng, ["child", "grandchild", "tiny-child", "moving-child", "flat-child"])
    heavy = Inertial(mass=1.0, diag=[1e-3, 1e-3, 1e-3])
    massless = Inertial(mass=0.0, diag=[0.0, 0.0, 0.0])
    if what == "child":
        inner, intent = mjcf_body("child", heavy, None, indent="      "), True
    elif what == "grandchild":
        inner = mjcf_body("child", massless, None,
                          mjcf_body("grandchild", heavy, None, indent="        "),
                          indent="      ")
        intent = True
    elif what == "tiny-child":
        inner = mjcf_body("child", Inertial(mass=1e-16, diag=[1e-3] * 3), None,
                          indent="      ")
        intent = False
    elif what == "moving-child":
        inner, intent = mjcf_body("child", heavy, "hinge", indent="      "), False
    else:
        inner = mjcf_body("child", Inertial(mass=1.0, diag=[1e-3, 1e-3, 0.0]), None,
                          indent="      ")
        intent = False
    body = mjcf_body("link", massless, pick(rng, list(MJCF_JOINTS)), inner)
    return Case("static-child", "xml", mjcf_model(body, {}),
                f"massless moving body with a {what}", intent)


# URDF --------------------------------------------------------------------------------

def urdf_joint(rng, moving: bool) -> str:
    return pick(rng, URDF_JOINTS) if moving else "fixed"


def urdf_inertial(rng, moments, *, rotate: str = "none", mass=None) -> Inertial:
    """A URDF inertial with principal moments `moments`: products written
    out ("products"), turned by the origin's rpy ("rpy"), or neither."""
    ine = Inertial(mass=random_mass(rng) if mass is None else mass, pos=random_pos(rng))
    if rotate == "products":
        ine.full = six(turned(moments, quat_matrix(random_quat(rng))))
    elif rotate == "rpy":
        ine.full = six(np.diag(moments))
        ine.rpy = [float(v) for v in rng.uniform(-math.pi, math.pi, 3)]
    else:
        ine.full = six(np.diag(moments))
    return ine


@family("urdf-valid")
def urdf_valid(rng):
    moving = rng.uniform() < 0.6
    rotate = pick(rng, ["products", "rpy", "none"])
    p = valid_moments(rng, log_uniform(rng, 1e-7, 1e1))
    joint = urdf_joint(rng, moving)
    return Case("urdf-valid", "urdf", urdf_pair(urdf_inertial(rng, p, rotate=rotate), joint),
                f"valid child ({rotate}), moments {p}, joint {joint}", True)


@family("urdf-negative-eigenvalue")
def urdf_negative_eigenvalue(rng):
    moving = rng.uniform() < 0.5
    scale = log_uniform(rng, 1e-6, 1e1)
    p = [scale, scale * rng.uniform(0.5, 1.0), -scale * log_uniform(rng, 1e-6, 1.0)]
    rotate = pick(rng, ["products", "rpy", "none"])
    joint = urdf_joint(rng, moving)
    return Case("urdf-negative-eigenvalue", "urdf",
                urdf_pair(urdf_inertial(rng, p, rotate=rotate), joint),
                f"child moments {p} ({rotate}), joint {joint}", False)


@family("urdf-triangle")
def urdf_triangle(rng):
    """Every URDF inertial is imported as a fullinertia: product-free ones to
    the ulp, turned ones by a relative margin."""
    moving = rng.uniform() < 0.5
    joint = urdf_joint(rng, moving)
    if rng.uniform() < 0.5:
        k = pick(rng, ULP_STEPS)
        p = shuffled(rng, ulp_triangle(rng, k))
        return Case("urdf-triangle", "urdf", urdf_pair(urdf_inertial(rng, p), joint),
                    f"product-free child {p}: c = fl(a+b) {k:+d} ulp, joint {joint}", k <= 0)
    rel = pick(rng, TRIANGLE_MARGINS)
    broken = rng.uniform() < 0.6
    rotate = pick(rng, ["products", "rpy"])
    p = moments_with_margin(rng, log_uniform(rng, 1e-6, 1e1), rel, broken)
    return Case("urdf-triangle", "urdf", urdf_pair(urdf_inertial(rng, p, rotate=rotate), joint),
                f"child ({rotate}) moments {p}: broken={broken} by {rel}, joint {joint}",
                not broken)


@family("urdf-eigen-floor")
def urdf_eigen_floor(rng):
    """mjEPS applies to every URDF link, fixed or moving."""
    moving = rng.uniform() < 0.5
    joint = urdf_joint(rng, moving)
    label, v, intent = pick(rng, EIG_FLOOR_VALUES)
    s = log_uniform(rng, 1e-6, 1e1)
    p = shuffled(rng, [v, s, s])
    return Case("urdf-eigen-floor", "urdf", urdf_pair(urdf_inertial(rng, p), joint),
                f"product-free child {p}: smallest {label}, joint {joint}", intent)


@family("urdf-zero-tensor")
def urdf_zero_tensor(rng):
    """An all-zero URDF tensor is not imported as a fullinertia: a fixed
    link may have it, a moving one then has no inertia."""
    moving = rng.uniform() < 0.5
    joint = urdf_joint(rng, moving)
    z = pick(rng, [0.0, -0.0])
    ine = Inertial(mass=random_mass(rng), pos=random_pos(rng), full=[z] * 6)
    return Case("urdf-zero-tensor", "urdf", urdf_pair(ine, joint),
                f"child tensor all {num(z)}, joint {joint}", not moving)


@family("urdf-no-inertial")
def urdf_no_inertial(rng):
    moving = rng.uniform() < 0.5
    joint = urdf_joint(rng, moving)
    return Case("urdf-no-inertial", "urdf", urdf_pair(None, joint),
                f"child without <inertial>, joint {joint}", not moving)


@family("urdf-mass")
def urdf_mass(rng):
    moving = rng.uniform() < 0.5
    joint = urdf_joint(rng, moving)
    label, m = pick(rng, MASS_VALUES)
    p = valid_moments(rng, log_uniform(rng, 1e-6, 1.0))
    ine = urdf_inertial(rng, p, rotate=pick(rng, ["products", "none"]), mass=m)
    return Case("urdf-mass", "urdf", urdf_pair(ine, joint),
                f"child mass {label}, joint {joint}", not moving or m >= MJ_MINVAL)


@family("urdf-root")
def urdf_root(rng):
    """The tensor on the root link (fixed: fused into the world, but its
    fullinertia is checked)."""
    what = pick(rng, ["valid", "negative", "triangle", "floor", "zero", "mass"])
    child = urdf_inertial(rng, valid_moments(rng, 1e-2), rotate="products")
    if what == "valid":
        base, intent = urdf_inertial(rng, valid_moments(rng, 1e-2), rotate="products"), True
    elif what == "negative":
        base, intent = urdf_inertial(rng, [1e-2, 1e-2, -1e-4], rotate="products"), False
    elif what == "triangle":
        k = pick(rng, (0, 1, 4))
        base, intent = urdf_inertial(rng, shuffled(rng, ulp_triangle(rng, k))), k <= 0
    elif what == "floor":
        label, v, intent = pick(rng, EIG_FLOOR_VALUES)
        base = urdf_inertial(rng, shuffled(rng, [v, 1e-2, 1e-2]))
    elif what == "zero":
        base, intent = Inertial(mass=1.0, full=[0.0] * 6), True
    else:
        base = urdf_inertial(rng, valid_moments(rng, 1e-2), mass=pick(rng, [0.0, -1.0]))
        intent = True
    joint = urdf_joint(rng, True)
    return Case("urdf-root", "urdf", urdf_pair(child, joint, base=base),
                f"root link {what}, child on {joint}", intent)


@family("urdf-compiler")
def urdf_compiler(rng):
    """<mujoco><compiler .../></mujoco> in a URDF."""
    what = pick(rng, ["balance", "boundmass", "boundinertia-zero", "boundinertia-negative"])
    joint = urdf_joint(rng, True)
    if what == "balance":
        p = moments_with_margin(rng, 1e-3, 1e-2, True)
        ine, comp, intent = urdf_inertial(rng, p, rotate="products"), {"balanceinertia": True}, True
    elif what == "boundmass":
        ine = urdf_inertial(rng, valid_moments(rng, 1e-3), mass=0.0)
        comp, intent = {"boundmass": 1e-3}, True
    elif what == "boundinertia-zero":
        ine = Inertial(mass=1.0, full=[0.0] * 6)
        comp, intent = {"boundinertia": 1e-6}, True
    else:
        ine = urdf_inertial(rng, shuffled(rng, [-1e-15, 1.0, 1.0]))
        comp, intent = {"boundinertia": 1e-6}, True
    return Case("urdf-compiler", "urdf", urdf_pair(ine, joint, compiler=comp),
                f"{what} {comp}, child on {joint}", intent)


@family("urdf-static-child")
def urdf_static_child(rng):
    """A massless moving link with a fixed-joint child: fused (fusestatic
    is on for URDF), the pair passes when the child has mass and inertia."""
    what = pick(rng, ["massive", "massless"])
    grand = (urdf_inertial(rng, valid_moments(rng, 1e-3), rotate="products")
             if what == "massive" else None)
    joint = urdf_joint(rng, True)
    text = urdf_model([("base", BASE_INERTIAL), ("child", None), ("tip", grand)],
                      [(joint, "base", "child"), ("fixed", "child", "tip")])
    return Case("urdf-static-child", "urdf", text,
                f"massless child on {joint} with a {what} fixed tip", what == "massive")


# --------------------------------------------------------------------------
# Generating, judging, comparing


def generate(seed: int, count: int, skip: set) -> list:
    """`count` cases, the families taken in turn so that a small corpus still
    has every kind; each family draws from its own stream of the seed."""
    families = [(k, f) for k, f in FAMILIES if k not in skip]
    if not families:
        raise SystemExit("mujoco_oracle: every kind is skipped")
    rngs = [np.random.default_rng([seed, i]) for i in range(len(families))]
    cases = []
    for i in range(count):
        j = i % len(families)
        cases.append(families[j][1](rngs[j]))
    return cases


def write_cases(cases: list, directory: str) -> None:
    for i, case in enumerate(cases):
        case.path = os.path.join(directory, f"case-{i:05d}-{case.kind}.{case.ext}")
        with open(case.path, "w", encoding="utf-8") as f:
            f.write(case.text)


@dataclasses.dataclass
class Verdict:
    valid: bool
    message: str = ""
    inertial: bool = True   # failed for an inertial reason (or passed)
    detail: str = ""


def quiet_warnings() -> None:
    """MuJoCo prints a warning ("Inertia matrix is too close to singular")
    for the corpus's legitimately tiny moments; a verdict is an error or
    none, so warnings are dropped."""
    mujoco.set_mju_user_warning(lambda message: None)


def mujoco_verdict(path: str) -> Verdict:
    """MuJoCo's own verdict: the model compiles, or its error message."""
    try:
        mujoco.MjModel.from_xml_path(path)
        return Verdict(True)
    except ValueError as err:
        message = str(err).strip()
        return Verdict(False, message, any(s in message for s in INERTIAL_MESSAGES))



def massprop_verdicts(massprop: str, paths: list) -> dict:
    """{path: Verdict} from `massprop check --engine mujoco --format json`,
    BATCH files a process. A file massprop could not read, or a run whose
    output is not the JSON contract, is a Verdict with `inertial=False`."""
    out = {}
    for start in range(0, len(paths), BATCH):
        batch = paths[start:start + BATCH]
        proc = run([massprop, "check", "--engine", "mujoco", "--format", "json", *batch])
        try:
            files = json.loads(proc.stdout)["files"]
        except (ValueError, KeyError, TypeError) as err:
            why = (f"massprop exited {proc.returncode} without the JSON contract ({err});\n"
                   f"stderr:\n{proc.stderr.strip()}\nstdout:\n{proc.stdout.strip()[:2000]}")
            for p in batch:
                out[p] = Verdict(False, why, inertial=False)
            continue
        by_path = {}
        for entry in files:
            by_path[os.path.realpath(entry.get("path", ""))] = entry
            by_path.setdefault(os.path.basename(entry.get("path", "")), entry)
        for p in batch:
            entry = by_path.get(os.path.realpath(p)) or by_path.get(os.path.basename(p))
            out[p] = file_verdict(entry, proc.stderr)
    return out


def file_verdict(entry: Optional[dict], stderr: str) -> Verdict:
    """A file's verdict: valid iff every link's mujoco engine says valid."""
    if entry is None:
        return Verdict(False, f"massprop reported nothing for this file\nstderr:\n{stderr}",
                       inertial=False)
    if entry.get("status") == "invalid":
        return Verdict(False, f"massprop could not read the file: {json.dumps(entry)}\n"
                       f"stderr:\n{stderr}", inertial=False)
    valid, lines = True, []
    for link in entry.get("links", []):
        engines = [e for e in link.get("engines", []) if e.get("engine") == "mujoco"]
        if not engines:
            valid = False
            lines.append(f"  link {link.get('name')!r}: no mujoco verdict")
            continue
        eng = engines[0]
        valid = valid and bool(eng.get("valid"))
        lines.append(f"  link {link.get('name')!r} (line {link.get('line')}): "
                     f"valid={eng.get('valid')} cause={json.dumps(eng.get('cause'))}")
        for rule in eng.get("rules", []):
            lines.append(f"    {'holds ' if rule.get('holds') else 'FAILS '}"
                         f"{rule.get('rule')}: {rule.get('statement')} "
                         f"(value {rule.get('value')!r}, limit {rule.get('limit')!r}, "
                         f"margin {rule.get('margin')!r})")
    return Verdict(valid, "", True, "\n".join(lines))


def agree(mj: Verdict, mp: Verdict) -> bool:
    if not mj.inertial:
        # MuJoCo could not read the file for a reason that is no inertial's:
        # only "massprop could not read it either" agrees.
        return not mp.inertial
    if not mp.inertial:
        return False
    return mj.valid == mp.valid


def print_table(rows: dict) -> None:
    kinds = sorted(rows)
    width = max(len(k) for k in kinds + ["kind"])
    print(f"{'kind':<{width}}  {'cases':>5}  {'mj ok':>5}  {'mj err':>6}  "
          f"{'agree':>5}  {'disagree':>8}  {'intent≠mj':>9}")
    totals = [0] * 6
    for k in kinds:
        r = rows[k]
        vals = [r["cases"], r["mj_ok"], r["mj_err"], r["agree"], r["disagree"], r["intent"]]
        totals = [a + b for a, b in zip(totals, vals)]
        print(f"{k:<{width}}  {vals[0]:>5}  {vals[1]:>5}  {vals[2]:>6}  {vals[3]:>5}  "
              f"{vals[4]:>8}  {vals[5]:>9}")
    print(f"{'total':<{width}}  {totals[0]:>5}  {totals[1]:>5}  {totals[2]:>6}  "
          f"{totals[3]:>5}  {totals[4]:>8}  {totals[5]:>9}")


def check_agreement(massprop: str, cases: list) -> int:
    """Judge every case both ways; print the table and each disagreement.
    Returns the number of disagreements."""
    mj = {c.path: mujoco_verdict(c.path) for c in cases}
    mp = massprop_verdicts(massprop, [c.path for c in cases])
    rows, bad, drift = {}, [], []
    for c in cases:
        r = rows.setdefault(c.kind, dict(cases=0, mj_ok=0, mj_err=0, agree=0,
                                         disagree=0, intent=0))
        r["cases"] += 1
        r["mj_ok" if mj[c.path].valid else "mj_err"] += 1
        if mj[c.path].inertial and mj[c.path].valid != c.intent:
            r["intent"] += 1
            drift.append(c)
        if agree(mj[c.path], mp[c.path]):
            r["agree"] += 1
        else:
            r["disagree"] += 1
            bad.append(c)
    print("check --engine mujoco against MuJoCo's compiler "
          f"(mujoco {mujoco.__version__}), {len(cases)} files\n")
    print_table(rows)
    for c in drift[:20]:
        print(f"\nnote: MuJoCo's verdict is not the one MUJOCO-RULES.md predicts "
              f"(rules changed?): {os.path.basename(c.path)}: {c.note}\n"
              f"  MuJoCo: {'valid' if mj[c.path].valid else mj[c.path].message}")
    seen = set()
    for c in bad:
        m, p = mj[c.path], mp[c.path]
        print("\n" + "=" * 78)
        print(f"DISAGREEMENT {os.path.basename(c.path)} [{c.kind}] {c.note}")
        print(f"MuJoCo:   {'valid' if m.valid else 'invalid: ' + m.message}")
        if p.inertial:
            print(f"massprop: {'valid' if p.valid else 'invalid'}")
        elif p.message in seen:
            print("massprop: no verdict (the same failure as above)")
        else:
            seen.add(p.message)
            print(f"massprop: no verdict: {p.message}")
        if p.detail:
            print(p.detail)
        print("--- file ---")
        print(c.text.rstrip())
    return len(bad)


# --------------------------------------------------------------------------
# Export: massprop's MJCF inertial, loaded by MuJoCo


INERTIAL_RE = re.compile(r"<inertial\b[^>]*/>", re.S)


def exported_body(element: str) -> str:
    """An exported `<inertial>` in a body on a freejoint. No geom: with
    inertiafromgeom at its default ("auto") an explicit inertial is the
    body's whole mass distribution (a geom would be ignored, whatever its
    mass); "false" says so outright."""
    return ('<mujoco model="export">\n  <compiler inertiafromgeom="false"/>\n'
            "  <worldbody>\n    <body name=\"part\">\n      <freejoint/>\n"
            f"      {element}\n    </body>\n  </worldbody>\n</mujoco>\n")


def close(a: float, b: float, scale: float, rel: float = 1e-12) -> bool:
    return abs(a - b) <= rel * scale


def check_export(massprop: str) -> int:
    """Export every shapes/*.toml both ways and compare with its report.
    Returns the number of mismatches."""
    shapes = sorted(glob.glob(os.path.join(REPO, "shapes", "*.toml")))
    print(f"\nexport --to mjcf loaded by MuJoCo, {len(shapes)} part files in shapes/\n")
    failures = 0
    for shape in shapes:
        name = os.path.relpath(shape, REPO)
        # The link frame is the report frame (`about`, `axes`): pinned to the
        # file's origin for both commands, the centre is `center_of_mass_ref`.
        frame = ["--about", "0,0,0"]
        rep = run([massprop, "report", shape, "--format", "json", *frame])
        if rep.returncode != 0:
            print(f"  skip  {name}: `massprop report` rejects it")
            continue
        report = json.loads(rep.stdout)
        mass, com = report["mass"], report["center_of_mass_ref"]
        moments = sorted(report["principal_moments"])
        gyration = math.sqrt(max(moments) / mass) if mass > 0 else 0.0
        for flags in ([], ["--principal"]):
            label = f"{name} {' '.join(flags) or '(fullinertia)'}"
            exp = run([massprop, "export", shape, "--to", "mjcf", *frame, *flags])
            found = INERTIAL_RE.findall(exp.stdout)
            if exp.returncode != 0 or len(found) != 1:
                failures += 1
                print(f"  FAIL  {label}: export exited {exp.returncode} with "
                      f"{len(found)} <inertial> elements\n{exp.stdout}{exp.stderr}")
                continue
            xml = exported_body(found[0])
            try:
                model = mujoco.MjModel.from_xml_string(xml)
            except ValueError as err:
                failures += 1
                print(f"  FAIL  {label}: MuJoCo refuses it: {err}\n{xml}")
                continue
            got_mass = float(model.body_mass[1])
            got_com = [float(v) for v in model.body_ipos[1]]
            got_moments = sorted(float(v) for v in model.body_inertia[1])
            problems = []
            if not close(got_mass, mass, abs(mass)):
                problems.append(f"mass {got_mass!r} vs {mass!r}")
            scale = max(max(abs(v) for v in com), gyration)
            if not all(close(g, w, scale) for g, w in zip(got_com, com)):
                problems.append(f"centre {got_com} vs {com}")
            if not all(close(g, w, max(moments)) for g, w in zip(got_moments, moments)):
                problems.append(f"principal moments {got_moments} vs {moments}")
            if problems:
                failures += 1
                print(f"  FAIL  {label}: " + "; ".join(problems) + f"\n{xml}")
            else:
                print(f"  ok    {label}")
    return failures


# --------------------------------------------------------------------------


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(
        description="Check `massprop check --engine mujoco` and `massprop export --to mjcf` "
                    "against MuJoCo's own compiler.")
    parser.add_argument("--massprop", required=True, help="the massprop binary")
    parser.add_argument("--seed", type=int, default=20251125,
                        help="the corpus's seed (default %(default)s)")
    parser.add_argument("--cases", type=int, default=2000,
                        help="files in the corpus, every kind in turn (default %(default)s)")
    parser.add_argument("--skip-kind", action="append", default=[], metavar="KIND",
                        help="leave a kind of case out (repeatable); kinds: "
                             + ", ".join(k for k, _ in FAMILIES))
    parser.add_argument("--keep", metavar="DIR",
                        help="write the corpus to DIR and keep it (default: a temporary "
                             "directory, removed)")
    parser.add_argument("--no-export", action="store_true", help="skip the export check")
    args = parser.parse_args(argv)

    massprop = shutil.which(args.massprop) or args.massprop
    if not os.path.isfile(massprop):
        print(f"mujoco_oracle: no massprop binary at {args.massprop}", file=sys.stderr)
        return 2
    unknown = set(args.skip_kind) - {k for k, _ in FAMILIES}
    if unknown:
        print(f"mujoco_oracle: unknown kind(s): {', '.join(sorted(unknown))}", file=sys.stderr)
        return 2

    quiet_warnings()
    cases = generate(args.seed, args.cases, set(args.skip_kind))
    directory = args.keep or tempfile.mkdtemp(prefix="massprop-oracle-")
    os.makedirs(directory, exist_ok=True)
    try:
        write_cases(cases, directory)
        disagreements = check_agreement(massprop, cases)
        mismatches = 0 if args.no_export else check_export(massprop)
    finally:
        if not args.keep:
            shutil.rmtree(directory, ignore_errors=True)

    print(f"\n{disagreements} disagreement(s) with MuJoCo's compiler, "
          f"{mismatches} export mismatch(es) (seed {args.seed}, {len(cases)} cases)")
    return 1 if disagreements or mismatches else 0


if __name__ == "__main__":
    sys.exit(main())
