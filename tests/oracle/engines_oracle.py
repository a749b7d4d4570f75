#!/usr/bin/env python3
"""Drake and Gazebo (gz-math) as independent oracles for
`massprop check --engine drake` and `massprop check --engine gazebo`.

Usage:

    python tests/oracle/engines_oracle.py --massprop PATH_TO_BINARY \
        [--seed N] [--cases N] [--engine drake|gazebo|both] \
        [--skip-kind KIND ...] [--keep DIR] [--no-parser]

Each engine is judged by its own library, imported here: Drake by pydrake
(`pip install drake`), Gazebo by gz-math's Python bindings (`gz.math8`,
`gz.math7`, or Debian's `python3-ignition-math`, gz-math 6). The two rarely
share an interpreter (pydrake is a pip wheel, the gz-math bindings a system
package built for the system python), so the script runs every engine whose
module imports and says which it skips and why; run it once with each
interpreter, e.g.:

    /tmp/oracle-venv/bin/python tests/oracle/engines_oracle.py --massprop BIN --engine drake
    /usr/bin/python3            tests/oracle/engines_oracle.py --massprop BIN --engine gazebo

The corpus depends on the seed only (standard-library `random`), so both
runs judge the same files.

A seeded corpus of URDF files is written to a temporary directory, one file
per case: a fixed root link `base` with a plain valid inertial and a link
`child` on a revolute joint, whose inertial is of one kind: valid tensors
turned by random rotations (non-zero products), a negative eigenvalue, the
triangle inequality broken or kept by a relative margin from 1e-1 down to
1e-17 (product-free tensors from 1e-13 down, decided to the ulp), c =
fl(a + b) moved by k ulps, exact equality, tiny tensors (moments 1e-9 ..
1e-20, where Drake's tolerance has an absolute floor), huge ones (1e5 ..
1e7), the zero tensor, negative and zero masses, turned thin rods (a double
principal moment, where gz-math's closed-form solver loses half its digits),
and tensors whose products are small beside the moments (where gz-math and
Drake skip the eigen solver). `massprop check --engine E --format json
FILES...` then runs on the files, ~200 a process, and each link's verdict is
compared with the library's verdict on the same numbers (the mass and the six
tensor entries as written):

- Drake: mass finite and ≥ 0 (`SpatialInertia::IsPhysicallyValid`'s mass
  test) and `RotationalInertia(ixx, iyy, izz, ixy, ixz, iyz)
  .CouldBePhysicallyValid()`, the test Drake's URDF/SDFormat parser applies
  first to every `<inertial>`. As a second, informational verdict the file
  itself is parsed (`Parser(MultibodyPlant(0.0))` with strict parsing: the
  parser's warning about an inertia becomes an error); where the parser and
  massprop differ it is counted in `parser≠mp` and shown, but does not fail
  the run (the parser also refuses mass 0 with a non-zero tensor, and
  re-checks the inertia after its shift to the link origin).
- Gazebo: `MassMatrix3d(mass, (ixx, iyy, izz), (ixy, ixz, iyz)).is_valid()`
  with its default tolerance 10: the test libsdformat applies to every link
  ("A link named X has invalid inertia").

A disagreement where massprop marks the deciding rule(s) `close` (a margin
within the engines' eigen-solver rounding) is counted as `close` and does not
fail the run; any other disagreement does. Each run prints a table per kind,
the library's own principal moments against massprop's (by the library's
path: the written diagonal, Eigen's solver, gz-math's closed form), the
disagreements by that path, and every disagreement in full.
tests/oracle/ENGINE-RULES.md has
the rules and the experiments behind them.

Exit status: 0 when every engine run agrees (close disagreements aside), 1 on
any other disagreement, 2 when the oracle itself cannot run (no engine
library, no binary, bad arguments). Standard library, plus pydrake and/or
the gz-math bindings.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import os
import random
import shutil
import sys
import tempfile
from typing import Callable, Optional

from oracle_common import num, nums, run, ulps  # beside this script

# Files per massprop process.
BATCH = 200

DBL_EPSILON = 2.0 ** -52
# Drake: CouldBePhysicallyValid's factor; gz-math: IsValid's default.
DRAKE_PRECISION = 16 * DBL_EPSILON
GZ_TOLERANCE = 10.0
# gz-math PrincipalMoments' default relative tolerance: products within it
# of the largest diagonal entry are taken as zero.
GZ_PRINCIPAL_TOL = 1e-6

ENGINES = ("drake", "gazebo")


# --------------------------------------------------------------------------
# The engines' libraries


@dataclasses.dataclass
class Library:
    engine: str
    module: object = None
    name: str = ""        # what was imported, with its version
    reason: str = ""      # why it could not be


def load_drake() -> Library:
    lib = Library("drake")
    try:
        import pydrake  # noqa: F401
        from pydrake.multibody import tree, parsing, plant
    except ImportError as err:
        lib.reason = (f"cannot import pydrake with {sys.executable} ({err}); "
                      "install it with `pip install drake`")
        return lib
    try:
        from importlib.metadata import version
        ver = version("drake")
    except Exception:  # pragma: no cover - version is informational
        ver = "?"
    lib.module = (tree, parsing, plant)
    lib.name = f"pydrake {ver}"
    return lib


def load_gazebo() -> Library:
    lib = Library("gazebo")
    errors = []
    for name, version in (("gz.math8", "gz-math 8"), ("gz.math7", "gz-math 7"),
                          ("ignition.math", "gz-math 6 (ignition)")):
        try:
            module = __import__(name, fromlist=["MassMatrix3d"])
            module.MassMatrix3d  # noqa: B018 - the binding must have it
        except (ImportError, AttributeError) as err:
            errors.append(f"{name}: {err}")
            continue
        lib.module = module
        lib.name = f"{name} ({version}, {os.path.dirname(module.__file__)})"
        return lib
    lib.reason = (f"cannot import gz-math's Python bindings with {sys.executable} ("
                  + "; ".join(errors) + "); on Debian/Ubuntu `apt-get install "
                  "python3-ignition-math` and run with /usr/bin/python3")
    return lib


LOADERS = {"drake": load_drake, "gazebo": load_gazebo}


# --------------------------------------------------------------------------
# Numbers and rotations (standard library only: both interpreters run this)





def random_rotation(rng: random.Random) -> list:
    """A uniformly distributed rotation matrix (from a unit quaternion)."""
    q = [rng.gauss(0.0, 1.0) for _ in range(4)]
    n = math.sqrt(sum(v * v for v in q))
    w, x, y, z = (v / n for v in q)
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]


def turned(moments, rot) -> list:
    """R diag(moments) Rᵀ as (xx, yy, zz, xy, xz, yz), exactly symmetric
    (each entry computed once)."""
    def entry(i, j):
        return math.fsum(rot[i][k] * moments[k] * rot[j][k] for k in range(3))
    return [entry(0, 0), entry(1, 1), entry(2, 2), entry(0, 1), entry(0, 2), entry(1, 2)]


def diagonal(moments) -> list:
    return [float(moments[0]), float(moments[1]), float(moments[2]), 0.0, 0.0, 0.0]


def log_uniform(rng: random.Random, lo: float, hi: float) -> float:
    return math.exp(rng.uniform(math.log(lo), math.log(hi)))


def pick(rng: random.Random, xs):
    return xs[rng.randrange(len(xs))]


def shuffled(rng: random.Random, xs) -> list:
    xs = list(xs)
    rng.shuffle(xs)
    return xs


def valid_moments(rng, scale: float) -> list:
    """Principal moments well inside the triangle inequality (a relative
    margin of at least 1e-3 from its edge)."""
    a = scale * rng.uniform(0.2, 1.0)
    b = scale * rng.uniform(0.2, 1.0)
    lo, hi = abs(a - b), a + b
    c = rng.uniform(lo + 1e-3 * hi, hi * (1 - 1e-3))
    return [a, b, c]


def moments_with_margin(rng, scale: float, rel: float, broken: bool) -> list:
    """(a, b, c), c the largest, with c − (a + b) = ±rel·(a + b)."""
    a = scale * rng.uniform(0.3, 1.0)
    b = scale * rng.uniform(0.3, 1.0)
    c = (a + b) * (1 + rel) if broken else (a + b) * (1 - rel)
    return [a, b, c]


def random_mass(rng) -> float:
    return log_uniform(rng, 1e-3, 1e2)


def random_xyz(rng) -> list:
    return [rng.uniform(-0.1, 0.1) for _ in range(3)]


# --------------------------------------------------------------------------
# The files


@dataclasses.dataclass
class Case:
    kind: str
    note: str             # what the case is, for a disagreement's report
    mass: float
    six: list             # xx yy zz xy xz yz, as written
    xyz: list = dataclasses.field(default_factory=lambda: [0.0, 0.0, 0.0])
    rpy: list = dataclasses.field(default_factory=lambda: [0.0, 0.0, 0.0])
    path: str = ""


BASE = ("base", 1.0, [0.0, 0.0, 0.05], [0.01, 0.02, 0.025, 0.0, 0.0, 0.0])


def inertial_xml(mass, six, xyz, rpy) -> str:
    xx, yy, zz, xy, xz, yz = six
    return (
        "<inertial>\n"
        f'      <origin xyz="{nums(xyz)}" rpy="{nums(rpy)}"/>\n'
        f'      <mass value="{num(mass)}"/>\n'
        f'      <inertia ixx="{num(xx)}" ixy="{num(xy)}" ixz="{num(xz)}" '
        f'iyy="{num(yy)}" iyz="{num(yz)}" izz="{num(zz)}"/>\n'
        "    </inertial>"
    )


def urdf_text(case: Case) -> str:
    name, mass, xyz, six = BASE
    return (
        '<robot name="oracle">\n'
        f'  <link name="{name}">\n    {inertial_xml(mass, six, xyz, [0.0] * 3)}\n  </link>\n'
        '  <link name="child">\n'
        f"    {inertial_xml(case.mass, case.six, case.xyz, case.rpy)}\n  </link>\n"
        '  <joint name="j0" type="revolute">\n'
        '    <parent link="base"/>\n    <child link="child"/>\n'
        '    <origin xyz="0 0 0.1" rpy="0 0 0"/>\n    <axis xyz="0 0 1"/>\n'
        '    <limit lower="-1" upper="1" effort="10" velocity="1"/>\n'
        "  </joint>\n</robot>\n"
    )


# --------------------------------------------------------------------------
# The corpus: one family per kind of case


Family = Callable[[random.Random], Case]
FAMILIES: list = []


def family(kind: str):
    """Register a generator of one kind of case."""
    def register(fn):
        FAMILIES.append((kind, fn))
        return fn
    return register


def maybe_turned_frame(rng, case: Case) -> Case:
    """A fifth of the cases also turn the inertial frame (`rpy`) and move the
    centre of mass: the rule is on the tensor as written, whatever the turn."""
    if rng.random() < 0.2:
        case.rpy = [rng.uniform(-math.pi, math.pi) for _ in range(3)]
        case.xyz = random_xyz(rng)
        case.note += ", with a random rpy and xyz"
    return case


@family("valid")
def valid(rng):
    p = valid_moments(rng, log_uniform(rng, 1e-7, 1e1))
    return maybe_turned_frame(rng, Case(
        "valid", f"turned valid tensor, moments {p}", random_mass(rng),
        turned(p, random_rotation(rng))))


@family("negative-eigenvalue")
def negative_eigenvalue(rng):
    s = log_uniform(rng, 1e-6, 1e1)
    p = [s, s * rng.uniform(0.5, 1.0), -s * log_uniform(rng, 1e-6, 1.0)]
    if rng.random() < 0.7:
        six, how = turned(p, random_rotation(rng)), "turned"
    else:
        six, how = diagonal(shuffled(rng, p)), "product-free"
    return maybe_turned_frame(rng, Case(
        "negative-eigenvalue", f"{how} tensor with eigenvalues {p}", random_mass(rng), six))


TURNED_MARGINS = (1e-1, 1e-2, 1e-4, 1e-6, 1e-9, 1e-12)


@family("triangle-margin")
def triangle_margin(rng):
    """A turned tensor whose moments break or keep the triangle inequality by
    a relative margin down to 1e-12 (round-off of the solvers: ~1e-15)."""
    rel = pick(rng, TURNED_MARGINS)
    broken = rng.random() < 0.6
    p = moments_with_margin(rng, log_uniform(rng, 1e-6, 1e1), rel, broken)
    return Case("triangle-margin",
                f"turned tensor, moments {p}: c − (a+b) = {'+' if broken else '−'}{rel:g}·(a+b)",
                random_mass(rng), turned(p, random_rotation(rng)))


FINE_MARGINS = (1e-13, 1e-14, 3e-15, 1e-15, 3e-16, 1e-16, 1e-17)


@family("triangle-fine")
def triangle_fine(rng):
    """Product-free tensors breaking or keeping the triangle inequality by a
    relative 1e-13 .. 1e-17: every engine uses the diagonal as written."""
    rel = pick(rng, FINE_MARGINS)
    broken = rng.random() < 0.7
    p = moments_with_margin(rng, log_uniform(rng, 1e-3, 1e3), rel, broken)
    return Case("triangle-fine",
                f"product-free {p}: c − (a+b) = {'+' if broken else '−'}{rel:g}·(a+b)",
                random_mass(rng), diagonal(shuffled(rng, p)))


ULP_STEPS = (-1, 0, 1, 2, 4, 8, 9, 10, 11, 12, 15, 16, 17, 18, 20, 24, 32, 33, 64, 1024)


@family("triangle-ulp")
def triangle_ulp(rng):
    """c = fl(a + b) moved k ulps, product-free: Drake's ε is 16 ulps of
    max(1, tr/2), gz-math's 10 ulps of tr/2 (about)."""
    k = pick(rng, ULP_STEPS)
    a = log_uniform(rng, 1e-3, 1e3)
    b = a * rng.uniform(0.3, 1.0)
    p = [a, b, ulps(a + b, k)]
    return Case("triangle-ulp", f"product-free {p}: c = fl(a+b) {k:+d} ulp",
                random_mass(rng), diagonal(shuffled(rng, p)))


EXACT_TRIANGLES = ([1.0, 1.0, 2.0], [0.25, 0.5, 0.75], [3.0, 5.0, 8.0],
                   [0.125, 0.125, 0.25], [1.5, 2.5, 4.0], [2.0 ** -20, 2.0 ** -21, 3 * 2.0 ** -21])


@family("triangle-equal")
def triangle_equal(rng):
    """A + B = C exactly (a flat plate): product-free it holds in every
    engine; turned, the equality is round-off (massprop: close)."""
    base = pick(rng, EXACT_TRIANGLES)
    scale = 2.0 ** rng.randrange(-30, 20)
    p = [v * scale for v in base]
    if rng.random() < 0.6:
        return Case("triangle-equal", f"product-free {p}: exact equality",
                    random_mass(rng), diagonal(shuffled(rng, p)))
    return Case("triangle-equal", f"turned {p}: exact equality, then turned",
                random_mass(rng), turned(p, random_rotation(rng)))


@family("tiny")
def tiny(rng):
    """Moments 1e-9 .. 1e-20: Drake's ε = 16 ε_mach · max(1, tr/2) has the
    absolute floor 2^-48 ≈ 3.55e-15 here, gz-math's stays relative."""
    what = pick(rng, ["valid", "triangle-floor", "negative-floor", "triangle-rel",
                      "negative-turned"])
    s = log_uniform(rng, 1e-20, 1e-9)
    floor = 2.0 ** -48   # Drake's ε for tr/2 ≤ 1
    f = pick(rng, (0.25, 0.99, 1.0, 1.01, 4.0))
    if what == "valid":
        p = valid_moments(rng, s)
        six, note = turned(p, random_rotation(rng)), f"turned valid tiny {p}"
    elif what == "triangle-floor":
        a, b = s, s * rng.uniform(0.3, 1.0)
        p = [a, b, (a + b) + f * floor]
        six, note = diagonal(shuffled(rng, p)), f"product-free {p}: c = a+b + {f}·2^-48"
    elif what == "negative-floor":
        p = [s, s, -f * floor]
        six, note = diagonal(shuffled(rng, p)), f"product-free {p}: a moment −{f}·2^-48"
    elif what == "triangle-rel":
        rel = pick(rng, (1e-3, 1e-9, 1e-14))
        p = moments_with_margin(rng, s, rel, True)
        six, note = diagonal(shuffled(rng, p)), f"product-free {p}: broken by {rel:g}"
    else:
        p = [s, s * rng.uniform(0.5, 1.0), -s * log_uniform(rng, 1e-6, 1.0)]
        six, note = turned(p, random_rotation(rng)), f"turned tiny, eigenvalues {p}"
    return Case("tiny", note, random_mass(rng), six)


@family("huge")
def huge(rng):
    """Moments 1e5 .. 1e7: gz-math's leading minors (I², I³ against an ε of
    size I) then decide near-zero moments, not the eigenvalues."""
    what = pick(rng, ["valid", "triangle", "triangle-fine", "near-zero", "negative"])
    s = log_uniform(rng, 1e5, 1e7)
    if what == "valid":
        p = valid_moments(rng, s)
        six, note = turned(p, random_rotation(rng)), f"turned valid huge {p}"
    elif what == "triangle":
        rel = pick(rng, (1e-2, 1e-6, 1e-10))
        broken = rng.random() < 0.6
        p = moments_with_margin(rng, s, rel, broken)
        six = turned(p, random_rotation(rng))
        note = f"turned huge {p}: broken={broken} by {rel:g}"
    elif what == "triangle-fine":
        k = pick(rng, (0, 4, 9, 10, 11, 16, 17, 40))
        a = s
        b = s * rng.uniform(0.3, 1.0)
        p = [a, b, ulps(a + b, k)]
        six, note = diagonal(shuffled(rng, p)), f"product-free huge {p}: c = fl(a+b) {k:+d} ulp"
    elif what == "near-zero":
        # A moment just below zero, within both engines' ε of it: the
        # eigenvalue test passes, gz-math's det I + ε ≥ 0 may not.
        f = pick(rng, (0.0, 0.1, 0.5, 0.9, 1.1))
        eps = GZ_TOLERANCE * DBL_EPSILON * s
        p = [s, s, -f * eps]
        six = diagonal(shuffled(rng, p)) if rng.random() < 0.5 else turned(p, random_rotation(rng))
        note = f"huge {p}: a moment −{f}·(gz ε)"
    else:
        p = [s, s * rng.uniform(0.5, 1.0), -s * log_uniform(rng, 1e-9, 1e-1)]
        six, note = turned(p, random_rotation(rng)), f"turned huge, eigenvalues {p}"
    return Case("huge", note, random_mass(rng), six)


@family("zero-tensor")
def zero_tensor(rng):
    z = pick(rng, [0.0, -0.0])
    mass = pick(rng, [random_mass(rng), 0.0, 1.0])
    return Case("zero-tensor", f"tensor all {num(z)}, mass {num(mass)}", mass, [z] * 6,
                xyz=random_xyz(rng) if rng.random() < 0.5 else [0.0] * 3)


@family("negative-mass")
def negative_mass(rng):
    m = pick(rng, [-1.0, -1e3, -1e-300, -5e-324, -1e-15, -0.0])
    p = valid_moments(rng, log_uniform(rng, 1e-6, 1.0))
    six = turned(p, random_rotation(rng)) if rng.random() < 0.5 else diagonal(p)
    return Case("negative-mass", f"mass {num(m)}, valid moments {p}", m, six)


@family("zero-mass")
def zero_mass(rng):
    m = pick(rng, [0.0, -0.0, 5e-324, 1e-300])
    p = valid_moments(rng, log_uniform(rng, 1e-6, 1.0))
    six = turned(p, random_rotation(rng)) if rng.random() < 0.5 else diagonal(p)
    return Case("zero-mass", f"mass {num(m)}, valid moments {p}", m, six)


ROD_RATIOS = (1e-1, 1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 0.0, -1e-11, -1e-9, -1e-7)


@family("thin-rod")
def thin_rod(rng):
    """A turned thin rod: moments (r·b, b, b(1 + g)), r from 1e-1 down to 0
    and below (a slightly negative moment). Its triangle margin is r, its
    double moment b is where a closed-form cubic (gz-math's) loses half its
    digits: acos near ±1 has an error of ~sqrt(ε_mach)."""
    r = pick(rng, ROD_RATIOS)
    g = pick(rng, (0.0, 1e-12, 1e-8, 1e-4))
    b = log_uniform(rng, 1e-6, 1e2)
    p = [r * b, b, b * (1 + g)]
    return maybe_turned_frame(rng, Case(
        "thin-rod", f"turned rod, moments {p} (ratio {r:g}, pair split {g:g})",
        random_mass(rng), turned(p, random_rotation(rng))))


SMALL_PRODUCTS = (1e-3, 1e-5, 2e-6, 1.01e-6, 1e-6, 0.99e-6, 1e-7, 1e-9, 1e-12, 1e-15, 1e-16)


@family("small-products")
def small_products(rng):
    """A boundary tensor plus one product of relative size 1e-3 .. 1e-16.
    gz-math's PrincipalMoments() returns the diagonal as written when every
    |product| ≤ 1e-6 · max(ixx, iyy, izz); Drake's when every |product| ≤
    4 ε_mach · tr/2. The product moves the eigenvalues by ~p²/gap (p for a
    double moment): a plate (A + B = C) then breaks the triangle
    inequality, a zero moment goes negative."""
    base = pick(rng, ["plate", "zero-moment"])
    scale = log_uniform(rng, 1e-6, 1e2)
    rel = pick(rng, SMALL_PRODUCTS)
    if base == "plate":
        # A + B = C exactly (the values and their sum are exact doubles).
        a, b = pick(rng, ([1.0, 1.0], [0.25, 0.5], [3.0, 5.0], [0.5, 1.5]))
        d = [a * scale, b * scale, (a + b) * scale]
    else:
        # A rod at the edge: (0, s, s). A product with the zero moment makes
        # it negative (by ~p²/s); one between the two others splits them
        # (±p) and breaks the triangle inequality by 2p.
        d = [0.0, scale, scale]
    order = shuffled(rng, [0, 1, 2])
    d = [d[i] for i in order]
    pairs = {(0, 1): 3, (0, 2): 4, (1, 2): 5}
    pair = pick(rng, list(pairs))
    p = rel * max(d[:3]) * pick(rng, [1.0, -1.0])
    six = d + [0.0, 0.0, 0.0]
    six[pairs[pair]] = p
    axes = "xyz"
    return Case("small-products",
                f"{base} diagonal {d} with i{axes[pair[0]]}{axes[pair[1]]} = {p!r} "
                f"({rel:g} × the largest moment)", random_mass(rng), six)


# --------------------------------------------------------------------------
# Generating and writing


def generate(seed: int, count: int, skip: set) -> list:
    """`count` cases, the families taken in turn so that a small corpus still
    has every kind; each family draws from its own stream of the seed."""
    families = [(k, f) for k, f in FAMILIES if k not in skip]
    if not families:
        raise SystemExit("engines_oracle: every kind is skipped")
    rngs = [random.Random(f"{seed}:{kind}") for kind, _ in families]
    cases = []
    for i in range(count):
        j = i % len(families)
        cases.append(families[j][1](rngs[j]))
    return cases


def write_cases(cases: list, directory: str) -> None:
    for i, case in enumerate(cases):
        case.path = os.path.join(directory, f"case-{i:05d}-{case.kind}.urdf")
        with open(case.path, "w", encoding="utf-8") as f:
            f.write(urdf_text(case))


# --------------------------------------------------------------------------
# The libraries' verdicts


@dataclasses.dataclass
class LibVerdict:
    valid: bool
    detail: str = ""
    moments: Optional[list] = None   # the library's principal moments, ascending
    path: str = ""                   # how the library found them


def drake_verdict(lib: Library, mass: float, six: list) -> LibVerdict:
    """Drake on the numbers: the mass as its parser takes it (finite, > 0,
    or 0 with an all-zero tensor) and RotationalInertia::CouldBePhysicallyValid()
    of the tensor as written (the central inertia, as URDF gives it)."""
    tree = lib.module[0]
    xx, yy, zz, xy, xz, yz = six
    inertia = tree.RotationalInertia(xx, yy, zz, xy, xz, yz)  # no check in release builds
    try:
        rot_ok = bool(inertia.CouldBePhysicallyValid())
        moments = [float(v) for v in inertia.CalcPrincipalMomentsOfInertia()]
    except Exception as err:  # the eigen solver failed
        return LibVerdict(False, f"CouldBePhysicallyValid() raised {err}")
    # The mass as Drake's parser takes it (massprop's rule): > 0, or 0 with
    # an all-zero tensor; IsPhysicallyValid alone allows any mass ≥ 0, and
    # the parser's `mass > 0` condition refuses 0 with a tensor (section 2
    # of ENGINE-RULES.md).
    mass_ok = math.isfinite(mass) and (mass > 0 or (mass == 0 and all(v == 0 for v in six)))
    trace = (xx + yy) + zz
    eps = DRAKE_PRECISION * max(1.0, 0.5 * abs(trace))
    a, b, c = moments
    detail = (f"mass > 0 (or 0 with a zero tensor): {mass_ok}; CouldBePhysicallyValid: {rot_ok}; Drake's principal "
              f"moments {moments!r}; ε = 16·DBL_EPSILON·max(1, |tr|/2) = {eps!r}; "
              f"A + B + ε − C = {(a + b + eps) - c!r}; A + ε = {a + eps!r}")
    diagonal_path = all(abs(p) <= 4 * DBL_EPSILON * 0.5 * abs(trace) for p in (xy, xz, yz))
    return LibVerdict(mass_ok and rot_ok, detail, sorted(moments),
                      "diagonal" if diagonal_path else "Eigen")


def gazebo_verdict(lib: Library, mass: float, six: list) -> LibVerdict:
    """gz-math on the numbers: MassMatrix3d(mass, diagonal, products)
    .is_valid() (default tolerance 10), as libsdformat's Link::Load."""
    gm = lib.module
    xx, yy, zz, xy, xz, yz = six
    mm = gm.MassMatrix3d()
    mm.set_mass(mass)
    mm.set_diagonal_moments(gm.Vector3d(xx, yy, zz))
    mm.set_off_diagonal_moments(gm.Vector3d(xy, xz, yz))
    valid = bool(mm.is_valid())
    pm = mm.principal_moments()
    moments = [float(pm.x()), float(pm.y()), float(pm.z())]
    near = bool(mm.is_near_positive())
    tol = GZ_PRINCIPAL_TOL * max(xx, yy, zz)
    shortcut = all(abs(p) <= tol for p in (xy, xz, yz))
    eps_moments = GZ_TOLERANCE * DBL_EPSILON * (0.5 * abs(sum_in_order(moments)))
    s = sorted(moments)
    detail = (f"IsNearPositive (mass, minors): {near}; gz principal moments {moments!r}"
              f"{' (the diagonal as written: every |product| ≤ 1e-6·max diagonal)' if shortcut else ''}; "
              f"ε (ValidMoments) = {eps_moments!r}; A + B + ε − C = {(s[0] + s[1] + eps_moments) - s[2]!r}")
    if shortcut:
        path = "diagonal"
    elif max(moments) == min(moments):
        path = "b/3"
    else:
        path = "cubic"
    return LibVerdict(valid, detail, sorted(moments), path)


def sum_in_order(xs) -> float:
    return (xs[0] + xs[1]) + xs[2]


def drake_parser_verdict(lib: Library, path: str) -> LibVerdict:
    """Drake's URDF parser on the file, strict: a warning about an inertial
    (which the lenient parser answers by substituting a plausible sphere) is
    raised as an error."""
    _, parsing, plant_mod = lib.module
    plant = plant_mod.MultibodyPlant(0.0)
    parser = parsing.Parser(plant)
    parser.SetStrictParsing()
    try:
        parser.AddModels(path)
        plant.Finalize()
        return LibVerdict(True)
    except Exception as err:  # RuntimeError: the parser's error
        lines = [ln for ln in str(err).splitlines() if ln.strip()]
        return LibVerdict(False, " | ".join(lines[:10]))


VERDICTS = {"drake": drake_verdict, "gazebo": gazebo_verdict}


# --------------------------------------------------------------------------
# massprop's verdicts



@dataclasses.dataclass
class MpLink:
    valid: bool
    close: bool           # the verdict rests on a rule massprop marks close
    marked: bool          # some rule is marked close
    inertia: Optional[list]
    mass: Optional[float]
    detail: str
    moments: Optional[list] = None   # massprop's (accurate) principal moments


@dataclasses.dataclass
class MpFile:
    links: dict           # name -> MpLink
    error: str = ""       # massprop gave no verdict for the file


def massprop_verdicts(massprop: str, engine: str, paths: list) -> dict:
    """{path: MpFile} from `massprop check --engine E --format json`, BATCH
    files a process."""
    out = {}
    for start in range(0, len(paths), BATCH):
        batch = paths[start:start + BATCH]
        proc = run([massprop, "check", "--engine", engine, "--format", "json", *batch])
        try:
            files = json.loads(proc.stdout)["files"]
        except (ValueError, KeyError, TypeError) as err:
            why = (f"massprop exited {proc.returncode} without the JSON contract ({err});\n"
                   f"stderr:\n{proc.stderr.strip()}\nstdout:\n{proc.stdout.strip()[:2000]}")
            for p in batch:
                out[p] = MpFile({}, why)
            continue
        by_path = {}
        for entry in files:
            by_path[os.path.realpath(entry.get("path", ""))] = entry
            by_path.setdefault(os.path.basename(entry.get("path", "")), entry)
        for p in batch:
            entry = by_path.get(os.path.realpath(p)) or by_path.get(os.path.basename(p))
            out[p] = file_verdict(entry, engine, proc.stderr)
    return out


def close_decides(valid: bool, rules: list) -> bool:
    """Whether massprop's verdict rests on a rule it marks close: valid with
    a close rule (it might fail), or invalid with every failing rule close."""
    if not any(r.get("close") for r in rules):
        return False
    if valid:
        return True
    failing = [r for r in rules if not r.get("holds")]
    return bool(failing) and all(r.get("close") for r in failing)


def file_verdict(entry: Optional[dict], engine: str, stderr: str) -> MpFile:
    if entry is None:
        return MpFile({}, f"massprop reported nothing for this file\nstderr:\n{stderr}")
    if entry.get("status") == "invalid":
        return MpFile({}, f"massprop could not read the file: {json.dumps(entry)}\n"
                      f"stderr:\n{stderr}")
    links = {}
    for link in entry.get("links", []):
        engines = [e for e in link.get("engines", []) if e.get("engine") == engine]
        inertial = link.get("inertial") or {}
        if not engines:
            links[link.get("name")] = MpLink(False, False, False, None, None,
                                             f"no {engine} verdict for this link: {json.dumps(link)}")
            continue
        eng = engines[0]
        rules = eng.get("rules", [])
        lines = [f"massprop: valid={eng.get('valid')} cause={json.dumps(eng.get('cause'))}"
                 + (f" note={eng.get('note')!r}" if eng.get("note") else "")]
        for r in rules:
            lines.append(f"    {'holds ' if r.get('holds') else 'FAILS '}{r.get('rule')}"
                         f"{' (close)' if r.get('close') else ''}: {r.get('statement')} "
                         f"(value {r.get('value')!r}, limit {r.get('limit')!r}, "
                         f"margin {r.get('margin')!r})")
        if inertial.get("principal_moments") is not None:
            lines.append(f"    massprop's principal moments {inertial.get('principal_moments')!r}")
        valid = bool(eng.get("valid"))
        links[link.get("name")] = MpLink(
            valid, close_decides(valid, rules), any(r.get("close") for r in rules),
            inertial.get("inertia"), inertial.get("mass"), "\n".join(lines),
            inertial.get("principal_moments"))
    return MpFile(links)


# --------------------------------------------------------------------------
# Comparing


@dataclasses.dataclass
class Outcome:
    case: Case
    link: str
    lib: LibVerdict
    mp: Optional[MpLink]
    status: str           # "agree", "close", "disagree"
    why: str = ""


def same_numbers(case_mass, case_six, mp: MpLink) -> bool:
    """massprop read the numbers as written (bit for bit; −0 = 0)."""
    if mp.inertia is None or mp.mass is None:
        return False
    return mp.mass == case_mass and all(float(a) == float(b) for a, b in zip(mp.inertia, case_six))


def compare(engine: str, lib: Library, cases: list, mp: dict) -> list:
    judge = VERDICTS[engine]
    outcomes = []
    base_name, base_mass, _, base_six = BASE
    for c in cases:
        f = mp[c.path]
        for name, mass, six, rpy in ((base_name, base_mass, base_six, [0.0] * 3),
                                     ("child", c.mass, c.six, c.rpy)):
            lv = judge(lib, mass, six)
            link = f.links.get(name)
            if f.error or link is None:
                outcomes.append(Outcome(c, name, lv, None, "disagree",
                                        f.error or f"massprop has no link {name!r}"))
                continue
            if not any(rpy) and not same_numbers(mass, six, link):
                outcomes.append(Outcome(c, name, lv, link, "disagree",
                                        f"massprop read mass {link.mass!r} inertia "
                                        f"{link.inertia!r}, the file has {mass!r} {six!r}"))
                continue
            if lv.valid == link.valid:
                status = "agree"
            elif link.close:
                status = "close"
            else:
                status = "disagree"
            outcomes.append(Outcome(c, name, lv, link, status))
    return outcomes


def print_table(engine: str, outcomes: list, parser_diff: Optional[dict]) -> None:
    rows = {}
    for o in outcomes:
        kind = o.case.kind if o.link == "child" else "root link (plain valid)"
        r = rows.setdefault(kind, dict(links=0, ok=0, err=0, agree=0, disagree=0,
                                       close=0, marked=0, parser=0))
        r["links"] += 1
        r["ok" if o.lib.valid else "err"] += 1
        r[o.status] += 1
        if o.mp is not None and o.mp.marked:
            r["marked"] += 1
    if parser_diff is not None:
        for kind, n in parser_diff.items():
            rows.setdefault(kind, dict(links=0, ok=0, err=0, agree=0, disagree=0,
                                       close=0, marked=0, parser=0))["parser"] = n
    kinds = sorted(rows)
    width = max(len(k) for k in kinds + ["kind"])
    cols = [("links", "links"), ("lib ok", "ok"), ("lib err", "err"), ("agree", "agree"),
            ("disagree", "disagree"), ("close", "close"), ("mp close", "marked")]
    if parser_diff is not None:
        cols.append(("parser≠mp", "parser"))
    print(f"{'kind':<{width}}  " + "  ".join(f"{h:>{max(len(h), 5)}}" for h, _ in cols))
    totals = {key: 0 for _, key in cols}
    for k in kinds:
        r = rows[k]
        for _, key in cols:
            totals[key] += r[key]
        print(f"{k:<{width}}  " + "  ".join(f"{r[key]:>{max(len(h), 5)}}" for h, key in cols))
    print(f"{'total':<{width}}  " + "  ".join(f"{totals[key]:>{max(len(h), 5)}}"
                                               for h, key in cols))
    print("\n(lib: the library's verdict on the numbers; close: a disagreement where "
          "massprop marks the deciding rule close, not a failure; mp close: links where "
          "massprop marks any rule close"
          + ("; parser≠mp: files where Drake's strict URDF parser and massprop differ, "
             "informational" if parser_diff is not None else "") + ")")


def describe(o: Outcome, engine: str, label: str) -> str:
    c = o.case
    mass, six = (c.mass, c.six) if o.link == "child" else (BASE[1], BASE[3])
    lines = ["=" * 78,
             f"{label} {os.path.basename(c.path)} [{c.kind}] link {o.link!r}: {c.note}",
             f"numbers as written: mass {mass!r}; ixx iyy izz ixy ixz iyz = "
             f"{' '.join(repr(v) for v in six)}"
             + (f"; rpy {c.rpy!r}" if o.link == "child" and any(c.rpy) else ""),
             f"{engine} library: {'valid' if o.lib.valid else 'INVALID'} — {o.lib.detail}"]
    if o.mp is None:
        lines.append(f"massprop: no verdict: {o.why}")
    else:
        if o.why:
            lines.append(o.why)
        lines.append(o.mp.detail)
    return "\n".join(lines)


CLOSE = 64 * DBL_EPSILON   # massprop's `close`: a margin within 64 ε_mach (relative)


def print_solver_error(engine: str, outcomes: list) -> None:
    """How far the library's own principal moments are from massprop's
    (accurate to about an ulp): max_i |λ_lib − λ_mp| / max |λ_mp|, by the
    way the library found them."""
    by_path = {}
    for o in outcomes:
        if o.mp is None or o.mp.moments is None or o.lib.moments is None:
            continue
        mp = sorted(float(v) for v in o.mp.moments)
        scale = max(abs(v) for v in mp)
        if not scale or not all(math.isfinite(v) for v in mp + o.lib.moments):
            continue
        err = max(abs(a - b) for a, b in zip(o.lib.moments, mp)) / scale
        by_path.setdefault(o.lib.path, []).append((err, o))
    print(f"\n{engine}'s own principal moments against massprop's "
          "(max |Δλ| / max |λ|), by the library's path:")
    for path, errs in sorted(by_path.items()):
        errs.sort(key=lambda e: e[0])
        worst, o = errs[-1]
        median = errs[len(errs) // 2][0]
        over = sum(1 for e, _ in errs if e > CLOSE)
        print(f"  {path:<9} {len(errs):>5} links: median {median:.2g}, max {worst:.2g} "
              f"({os.path.basename(o.case.path)} {o.link}), {over} above 64 ε = {CLOSE:.2g}")


def check_engine(engine: str, lib: Library, massprop: str, cases: list,
                 parser: bool) -> tuple:
    """Judge every case both ways; print the table and every disagreement.
    Returns (disagreements, close disagreements)."""
    mp = massprop_verdicts(massprop, engine, [c.path for c in cases])
    outcomes = compare(engine, lib, cases, mp)
    parser_diff, parser_cases = None, []
    if engine == "drake" and parser:
        parser_diff = {}
        for c in cases:
            pv = drake_parser_verdict(lib, c.path)
            f = mp[c.path]
            mp_valid = (not f.error and bool(f.links)
                        and all(link.valid for link in f.links.values()))
            if pv.valid != mp_valid:
                parser_diff[c.kind] = parser_diff.get(c.kind, 0) + 1
                parser_cases.append((c, pv, f))
    print(f"\ncheck --engine {engine} against {lib.name}, {len(cases)} files "
          f"({2 * len(cases)} links)\n")
    print_table(engine, outcomes, parser_diff)
    print_solver_error(engine, outcomes)
    bad = [o for o in outcomes if o.status == "disagree"]
    close = [o for o in outcomes if o.status == "close"]
    if bad or close:
        classes = {}
        for o in bad + close:
            key = (o.status, o.lib.path or "?", "lib valid" if o.lib.valid else "lib invalid")
            classes[key] = classes.get(key, 0) + 1
        print("\ndisagreements by the library's path to its principal moments:")
        for (status, path, verdict), n in sorted(classes.items()):
            print(f"  {status:<8} {path:<9} {verdict:<11} (massprop the other way): {n}")
    for o in bad:
        print("\n" + describe(o, engine, "DISAGREEMENT"))
    for o in close:
        print("\n" + describe(o, engine, "close (not a failure):"))
    if parser_cases:
        print(f"\n{len(parser_cases)} file(s) where Drake's strict URDF parser and "
              "massprop --engine drake differ (informational):")
        shown = {}
        for c, pv, f in parser_cases:
            key = (c.kind, pv.valid, pv.detail.split(":")[2] if pv.detail.count(":") > 2 else "")
            shown[key] = shown.get(key, 0) + 1
            if shown[key] > 3:
                continue
            child = f.links.get("child")
            print("-" * 78)
            print(f"{os.path.basename(c.path)} [{c.kind}] {c.note}")
            print(f"  child: mass {c.mass!r}; six {' '.join(repr(v) for v in c.six)}; "
                  f"xyz {c.xyz!r}; rpy {c.rpy!r}")
            print(f"  parser: {'accepts' if pv.valid else 'refuses: ' + pv.detail}")
            print(f"  massprop: {'valid' if child and child.valid else 'invalid'}"
                  + (f" ({child.detail.splitlines()[0]})" if child else f" ({f.error})"))
        hidden = sum(max(0, n - 3) for n in shown.values())
        if hidden:
            print(f"  ... and {hidden} more of the same kinds")
    return len(bad), len(close)


# --------------------------------------------------------------------------


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(
        description="Check `massprop check --engine drake|gazebo` against Drake's and "
                    "gz-math's own libraries.")
    parser.add_argument("--massprop", required=True, help="the massprop binary")
    parser.add_argument("--seed", type=int, default=20251125,
                        help="the corpus's seed (default %(default)s)")
    parser.add_argument("--cases", type=int, default=2000,
                        help="files in the corpus, every kind in turn (default %(default)s)")
    parser.add_argument("--engine", choices=["drake", "gazebo", "both"], default="both",
                        help="which engine(s) to check (default: both, each if its "
                             "library imports)")
    parser.add_argument("--skip-kind", action="append", default=[], metavar="KIND",
                        help="leave a kind of case out (repeatable); kinds: "
                             + ", ".join(k for k, _ in FAMILIES))
    parser.add_argument("--keep", metavar="DIR",
                        help="write the corpus to DIR and keep it (default: a temporary "
                             "directory, removed)")
    parser.add_argument("--no-parser", action="store_true",
                        help="skip the informational run of Drake's URDF parser")
    args = parser.parse_args(argv)

    massprop = shutil.which(args.massprop) or args.massprop
    if not os.path.isfile(massprop):
        print(f"engines_oracle: no massprop binary at {args.massprop}", file=sys.stderr)
        return 2
    unknown = set(args.skip_kind) - {k for k, _ in FAMILIES}
    if unknown:
        print(f"engines_oracle: unknown kind(s): {', '.join(sorted(unknown))}", file=sys.stderr)
        return 2

    wanted = ENGINES if args.engine == "both" else (args.engine,)
    libs = {}
    for engine in wanted:
        lib = LOADERS[engine]()
        if lib.module is None:
            print(f"engines_oracle: skipping {engine}: {lib.reason}", file=sys.stderr)
        else:
            libs[engine] = lib
    if not libs:
        print("engines_oracle: no engine library could be imported with "
              f"{sys.executable}; nothing checked", file=sys.stderr)
        return 2
    if args.engine != "both" and args.engine not in libs:
        return 2

    cases = generate(args.seed, args.cases, set(args.skip_kind))
    directory = args.keep or tempfile.mkdtemp(prefix="massprop-engines-oracle-")
    os.makedirs(directory, exist_ok=True)
    results = {}
    try:
        write_cases(cases, directory)
        for engine, lib in libs.items():
            results[engine] = check_engine(engine, lib, massprop, cases, not args.no_parser)
    finally:
        if not args.keep:
            shutil.rmtree(directory, ignore_errors=True)

    print()
    for engine in ENGINES:
        if engine in results:
            bad, close = results[engine]
            print(f"{engine}: {bad} disagreement(s), {close} close disagreement(s) "
                  f"({libs[engine].name})")
        elif engine in wanted:
            print(f"{engine}: skipped ({LOADERS[engine]().reason})")
        else:
            print(f"{engine}: not asked for")
    print(f"(seed {args.seed}, {len(cases)} files)")
    return 1 if any(bad for bad, _ in results.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
