#!/usr/bin/env bash
# Benchmark: `massprop check DIR` over 1,000 generated part files of 20 parts
# each, in one invocation. See docs/performance.md.
#
#   bash benches/check-many.sh
#
# Builds the release binary, generates the files deterministically (fixed
# seed) into a temporary directory, times the check with hyperfine (warm-up,
# then repeated runs), measures peak memory with GNU time, checks that every
# expectation holds (exit status 0), and prints a summary. Safe to run
# repeatedly and from any directory; everything it creates apart from the
# cargo build lives in the temporary directory, removed on exit.
#
# Needs python3 (the generator), hyperfine and GNU time; the latter two are
# installed with apt-get when missing (as root).
#
# Environment: RUNS (default 20) and WARMUP (default 3) for hyperfine.
set -euo pipefail

FILES=1000
PARTS=20
SEED=20251122
RUNS="${RUNS:-20}"
WARMUP="${WARMUP:-3}"

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/massprop-check-many.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

# shellcheck source=benches/lib.sh
source "$repo/benches/lib.sh"
need_bench_tools "the part files"

echo "== build (cargo build --release --locked)" >&2
(cd "$repo" && cargo build --release --locked --quiet)
# Benchmark a copy, so that a concurrent rebuild cannot swap the binary
# between runs.
cp "$(cd "$repo" && target_dir .)/release/massprop" "$tmp/massprop"

commit="$(git -C "$repo" rev-parse --short=12 HEAD 2> /dev/null || echo unknown)"
if [ -n "$(git -C "$repo" status --porcelain -- src Cargo.toml Cargo.lock 2> /dev/null)" ]; then
    commit="$commit + uncommitted changes in src/ or Cargo.*"
fi

echo "== generate $FILES part files of $PARTS parts (seed $SEED)" >&2
python3 - "$tmp/parts" "$FILES" "$PARTS" "$SEED" << 'PY'
"""Deterministic part files: every shape, both placement styles, every
rotation form, file units and unit strings, and an [expect] block that holds
(mass computed here to 0.01 %, centre of mass inside the box spanned by the
part centroids)."""
import math
import os
import random
import sys

out, n_files, n_parts, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
rng = random.Random(seed)

LEN = {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254, "ft": 0.3048}
MASS = {"kg": 1.0, "g": 0.001, "lb": 0.45359237}
# Density units with their SI factors, by the shape whose density they give.
DENSITY_UNITS = {
    "box": [("kg/m^3", 1.0), ("g/cm^3", 1e3), ("g/cm³", 1e3), ("lb/in^3", 0.45359237 / 0.0254**3),
            ("lb/ft^3", 0.45359237 / 0.3048**3), ("kg/mm^3", 1e9)],
    "plate": [("kg/m^2", 1.0), ("g/cm^2", 10.0), ("g/mm²", 1e3), ("lb/ft^2", 0.45359237 / 0.3048**2),
              ("lb/in^2", 0.45359237 / 0.0254**2)],
    "rod": [("kg/m", 1.0), ("g/m", 1e-3), ("g/mm", 1.0), ("lb/ft", 0.45359237 / 0.3048),
            ("lb/in", 0.45359237 / 0.0254)],
}
DENSITY_KEY = {"box": "density", "plate": "areal_density", "rod": "linear_density"}
DENSITY_DIM = {"box": 3, "plate": 2, "rod": 1}
MATERIALS = [7850.0, 2700.0, 4430.0, 1600.0, 1040.0, 8500.0]  # kg/m³
EULER = ["xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz", "zyz"]


def sig(x, n=5):
    return float(f"{x:.{n}g}")


def num(x):
    """A TOML number that reads back as exactly x."""
    if x == 0:
        return "0"
    r = repr(float(x))
    return r[:-2] if r.endswith(".0") else r


def vec(items):
    return "[" + ", ".join(items) + "]"


class File:
    def __init__(self, lu, mu):
        self.lu, self.mu = lu, mu
        self.lf, self.mf = LEN[lu], MASS[mu]

    def length(self, si, plain=0.85):
        """(text, SI value as written) for a length."""
        if rng.random() < plain:
            n = sig(si / self.lf, 6)
            return num(n), n * self.lf
        u = rng.choice(list(LEN))
        n = sig(si / LEN[u], 6)
        return f'"{num(n)} {u}"', n * LEN[u]

    def point(self, p, plain=0.9):
        texts, values = zip(*(self.length(c, plain) for c in p))
        return vec(texts), list(values)

    def mass(self, si):
        if rng.random() < 0.6:
            n = sig(si / self.mf, 5)
            return num(n), n * self.mf
        u = rng.choice(list(MASS))
        n = sig(si / MASS[u], 5)
        return f'"{num(n)} {u}"', n * MASS[u]

    def density(self, shape, si):
        if rng.random() < 0.4:
            f = self.mf / self.lf ** DENSITY_DIM[shape]
            n = sig(si / f, 5)
            return num(n), n * f
        u, f = rng.choice(DENSITY_UNITS[shape])
        n = sig(si / f, 4)
        return f'"{num(n)} {u}"', n * f


def rand_quaternion():
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(x * x for x in q))
    return [x / n for x in q]


def matrix(q):
    w, x, y, z = q
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]


def rotation(form):
    """A rotation table in the given form (1..5); the centroid and mass
    do not depend on it, so nothing else is needed here."""
    if form == 1:
        return "{ quaternion = %s }" % vec(num(x) for x in rand_quaternion())
    if form == 2:
        axis = [0, 0, 0]
        while axis == [0, 0, 0]:
            axis = [rng.randint(-2, 2) for _ in range(3)]
        deg = rng.choice([90, -90, 180, 45, round(rng.uniform(-180, 360), 1)])
        return "{ axis = %s, degrees = %s }" % (vec(str(a) for a in axis), num(deg))
    if form == 3:
        rows = matrix(rand_quaternion())
        return "{ matrix = %s }" % vec(vec(num(x) for x in r) for r in rows)
    kind = "intrinsic" if form == 4 else "extrinsic"
    angles = [round(rng.uniform(-180, 180), 1) for _ in range(3)]
    return '{ %s = "%s", degrees = %s }' % (kind, rng.choice(EULER), vec(num(a) for a in angles))


def frame():
    """Three perpendicular unit vectors: axis-aligned (as most drawings are)
    or turned arbitrarily."""
    if rng.random() < 0.4:
        axes = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
        rng.shuffle(axes)
        return [[rng.choice([1.0, -1.0]) * c for c in a] for a in axes]
    r = matrix(rand_quaternion())
    return [[r[0][j], r[1][j], r[2][j]] for j in range(3)]


def part(f, shape, j, scale, origin):
    """Lines of one [[part]] table, its mass (kg) and centroid (m)."""
    lines = ["", "[[part]]"]
    if rng.random() < 0.7:
        lines.append(f'name = "{shape} {j + 1}"')
    lines.append(f'shape = "{shape}"')
    c_si = [o + scale * rng.uniform(-3, 3) for o in origin]

    if shape == "point":
        m_text, m = f.mass(7850.0 * scale**3 * rng.uniform(0.001, 0.05))
        lines.append(f"mass = {m_text}")
        text, c = f.point(c_si)
        lines.append(f"center = {text}")
        return lines, m, c

    by_edges = rng.random() < 0.5
    use_mass = rng.random() < 0.4
    rho = rng.choice(MATERIALS)
    k = DENSITY_DIM[shape]
    if shape == "box":
        dims_si = [scale * rng.uniform(0.05, 1.0) for _ in range(3)]
    elif shape == "plate":
        dims_si = [scale * rng.uniform(0.1, 1.0) for _ in range(2)]
        rho *= rng.uniform(0.001, 0.01)  # areal: times a thickness
    else:
        dims_si = [scale * rng.uniform(0.2, 2.0)]
        rho *= rng.uniform(1e-5, 1e-3)  # linear: times a section area
    mass_lines = []
    if use_mass:
        m_text, m_given = f.mass(rho * math.prod(dims_si))
        mass_lines.append(f"mass = {m_text}")
    else:
        d_text, d = f.density(shape, rho)
        mass_lines.append(f"{DENSITY_KEY[shape]} = {d_text}")

    if by_edges and shape == "rod":
        axis = frame()[0]
        half = [dims_si[0] / 2 * a for a in axis]
        a_text, a = f.point([c - h for c, h in zip(c_si, half)])
        b_text, b = f.point([c + h for c, h in zip(c_si, half)])
        lines += [f"from = {a_text}", f"to = {b_text}"]
        c = [(x + y) / 2 for x, y in zip(a, b)]
        extent = [math.dist(a, b)]
    elif by_edges:
        axes = frame()[:k]
        # Edges as plain numbers in file units, full precision; SI as written.
        edges_file = [[num(d / f.lf * x) for x in ax] for d, ax in zip(dims_si, axes)]
        edges = [[float(x) * f.lf for x in e] for e in edges_file]
        corner_si = [c - sum(e[i] for e in edges) / 2 for i, c in enumerate(c_si)]
        corner_text, corner = f.point(corner_si)
        lines += [f"corner = {corner_text}", "edges = %s" % vec(vec(e) for e in edges_file)]
        c = [corner[i] + sum(e[i] for e in edges) / 2 for i in range(3)]
        extent = [math.sqrt(sum(x * x for x in e)) for e in edges]
    else:
        if shape == "rod":
            l_text, l = f.length(dims_si[0], plain=0.7)
            lines.append(f"length = {l_text}")
            extent = [l]
        else:
            texts, extent = zip(*(f.length(d, plain=0.8) for d in dims_si))
            lines.append(f"size = {vec(texts)}")
        text, c = f.point(c_si)
        lines.append(f"center = {text}")
        form = rng.randrange(6)
        if form:
            lines.append(f"rotation = {rotation(form)}")

    lines += mass_lines
    m = m_given if use_mass else d * math.prod(extent)
    return lines, m, c


def part_file(i):
    lu = rng.choice(list(LEN))
    mu = rng.choice(list(MASS))
    if rng.random() < 0.15:
        lu, mu = "m", "kg"  # and the units table left out: the defaults
        header = []
    else:
        header = [f'units = {{ length = "{lu}", mass = "{mu}" }}']
    f = File(lu, mu)
    scale = rng.choice([0.02, 0.2, 1.0, 3.0])  # typical part size, m
    far = rng.random() < 0.2
    origin = [scale * (rng.uniform(100, 1000) if far else rng.uniform(-2, 2)) for _ in range(3)]
    lines = [f"# Generated by benches/check-many.sh (seed {seed}), file {i}.",
             f'name = "generated {i:04d}"'] + header

    shapes = ["box", "plate", "rod", "point"] * (n_parts // 4) + ["box"] * (n_parts % 4)
    rng.shuffle(shapes)
    total, moment = 0.0, [0.0, 0.0, 0.0]
    lo, hi = [math.inf] * 3, [-math.inf] * 3
    for j, shape in enumerate(shapes):
        pl, m, c = part(f, shape, j, scale, origin)
        lines += pl
        total += m
        for k in range(3):
            moment[k] += m * c[k]
            lo[k], hi[k] = min(lo[k], c[k]), max(hi[k], c[k])

    omega = rng.random() < 0.3
    if omega or rng.random() < 0.3:
        lines += ["", "[analysis]"]
        if rng.random() < 0.5:
            text, _ = f.point([o + scale * rng.uniform(-1, 1) for o in origin])
            lines.append(f"about = {text}")
        if omega:
            w = [round(rng.uniform(-50, 50), 2) for _ in range(3)]
            w_text = [num(x) for x in w]
            if rng.random() < 0.5:
                w_text[2] = f'"{rng.choice([600, 1500, 3000])} rpm"'
            lines.append(f"omega = {vec(w_text)}")
            if rng.random() < 0.5:
                lines.append(f'alpha = [0, 0, "{rng.randint(1, 90)} deg/s^2"]')

    lines += ["", "[expect]"]
    r = rng.random()
    if r < 0.6:
        lines.append(f'mass = {{ value = {num(sig(total / f.mf, 9))}, tol = "0.01%" }}')
    elif r < 0.8:
        u = rng.choice(list(MASS))
        lines.append(f'mass = {{ value = "{num(sig(total / MASS[u], 9))} {u}", tol = "0.01%" }}')
    else:
        lines.append(f"mass = {{ value = {num(total / f.mf)}, tol = {num(sig(1e-4 * total / f.mf, 2))} }}")
    # The centre of mass is a weighted mean of the centroids: inside their box.
    com = [x / total for x in moment]
    assert all(l <= x <= h for l, x, h in zip(lo, com, hi))
    pad = [1e-6 * (h - l) + 1e-9 * (abs(l) + abs(h)) for l, h in zip(lo, hi)]
    lo_f = [num((l - p) / f.lf) for l, p in zip(lo, pad)]
    hi_f = [num((h + p) / f.lf) for h, p in zip(hi, pad)]
    if rng.random() < 0.6:
        lines.append(f"center_of_mass = {{ min = {vec(lo_f)}, max = {vec(hi_f)} }}")
    else:
        for axis, l, h in zip("xyz", lo_f, hi_f):
            lines.append(f"center_of_mass.{axis} = {{ min = {l}, max = {h} }}")
    if rng.random() < 0.5:
        lines.append("principal_moments = { min = [0, 0, 0] }")
    if omega:
        lines.append('kinetic_energy = { min = "0 J" }')
    return "\n".join(lines) + "\n"


for i in range(n_files):
    d = os.path.join(out, f"g{i // 100:02d}")
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, f"part-{i:04d}.toml"), "w", encoding="utf-8") as fh:
        fh.write(part_file(i))
PY

cd "$tmp"
count="$(find parts -name '*.toml' | wc -l)"
bytes="$(cat parts/*/*.toml | wc -c)"
digest="$(cat parts/*/*.toml | sha256sum | cut -c1-16)"

echo "== correctness: every expectation holds" >&2
status=0
./massprop check parts > check.out 2> check.err || status=$?
if [ "$status" -ne 0 ]; then
    echo "error: massprop check exited with status $status on the generated files" >&2
    # sed, not head: under pipefail, head closing the pipe early is a failure.
    grep -v ': ok$' check.out | sed -n 1,20p >&2 || true
    sed -n 1,40p check.err >&2
    exit 1
fi
tail -1 check.out >&2
grep -qx "checked $FILES files: $FILES ok, 0 failed, 0 invalid" check.out \
    || { echo "error: unexpected summary line" >&2; exit 1; }

echo "== time: hyperfine, $WARMUP warm-up runs, $RUNS runs" >&2
one=parts/g00/part-0000.toml
hyperfine -N --output=pipe --warmup "$WARMUP" --runs "$RUNS" \
    --export-json hf.json \
    "./massprop check parts" "./massprop check $one" >&2

echo "== peak memory: /usr/bin/time -v" >&2
/usr/bin/time -v -o time.txt ./massprop check parts > /dev/null
rss_kb="$(awk -F': ' '/Maximum resident set size/ {print $2}' time.txt)"

python3 - hf.json "$FILES" "$rss_kb" << PY
import json, sys
r = json.load(open(sys.argv[1]))["results"]
files, rss = int(sys.argv[2]), int(sys.argv[3])
many, one = r[0], r[1]
ms = lambda s: f"{s * 1e3:.1f} ms"
print()
print("massprop check: $count files x $PARTS parts ($((bytes / 1024)) KiB, sha256 $digest...), one invocation")
print(f"  mean ± σ     {ms(many['mean'])} ± {ms(many['stddev'])}   ({len(many['times'])} runs, $WARMUP warm-up)")
print(f"  min … max    {ms(many['min'])} … {ms(many['max'])}")
print(f"  per file     {many['mean'] / files * 1e6:.0f} µs")
print(f"  one file     {ms(one['mean'])} ± {ms(one['stddev'])} (process start-up and one file)")
print(f"  peak RSS     {rss / 1024:.1f} MiB")
PY
echo "  machine      $(nproc) CPUs, $(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo), $(uname -sr)"
echo "  massprop     $commit ($(cd "$repo" && rustc --version 2> /dev/null || echo 'rustc unknown'))"
echo "  date         $(date -u +%Y-%m-%dT%H:%MZ)"
