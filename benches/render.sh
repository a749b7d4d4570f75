#!/usr/bin/env bash
# Benchmark (issue 19, item 3): `massprop render` of a generated part file
# of 100,000 parts, end to end (read, compose, draw four views, write the
# SVG), beside `massprop report` of the same file for scale.
#
#   bash benches/render.sh              # 100,000 parts
#   PARTS=20000 bash benches/render.sh
#
# Target: at most one second (issue 33, item 4; issue 19 asked for about
# two), release build. Generates (python,
# deterministic, fixed seed) boxes, plates, rods, cylinders, tubes, disks,
# spheres, cones, tori and point masses, 1 to 60 mm, in a 2 m cube, units
# mm and kg (at the drawing's scale, ~0.17 px/mm, the parts under ~6 mm
# are smaller than a pixel: counted, not drawn); checks that render exits
# 0 and that its legend counts them; times both commands with hyperfine
# (median of RUNS) and the render's peak RSS with GNU time. Everything
# but the cargo build lives in a temporary directory, removed on exit.
#
# Issue 28, item 6: then 2,000,000 copies of a box in one place (a
# 150-byte file: an `array` of step 0), drawn once per view with their
# count: its time and peak RSS (GNU time, one run each of COPIES and
# COPIES/4, to see the cost linear) and the SVG's size (a few kB, as for
# one box); beside it, for scale, `report` (the table, which lists every
# copy) and `report --format json` of the same file, wall and user time.
# `CASE=copies` runs this case alone.
#
# Issue 33, item 4: with BASE=/path/to/another/massprop (main's build,
# say), then RUNS renders of the 100,000 parts by each binary in turn
# (interleaved, so both see the same load), each's median wall and user +
# system CPU time (GNU time), the SVGs compared byte for byte, and the
# load average before and after: on a shared machine the CPU times are
# the figures to read.
#
# Needs python3, hyperfine and GNU time (the latter two installed with
# apt-get when missing, as root). Environment: PARTS (default 100000),
# RUNS (default 5), WARMUP (default 1), COPIES (default 2000000), CASE
# (`all`, default, or `copies`), BASE (unset: no comparison).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/lib.sh"
need_bench_tools "the part file"
PARTS="${PARTS:-100000}"
RUNS="${RUNS:-5}"
WARMUP="${WARMUP:-1}"
COPIES="${COPIES:-2000000}"
CASE="${CASE:-all}"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/massprop-render.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
cargo build --release --locked --quiet --manifest-path "$here/../Cargo.toml" --bin massprop
cp "$(target_dir "$here/..")/release/massprop" "$tmp/massprop"

# copies N: render N coincident copies of a box; time, peak RSS, SVG size.
copies() {
    printf '[[part]]\nshape = "box"\nmass = 1\nsize = [0.1, 0.2, 0.3]\ncenter = [0, 0, 0]\narray = { count = %d, step = [0, 0, 0] }\n' "$1" > "$tmp/copies.toml"
    /usr/bin/time -f '%e %U %M' -o "$tmp/time" "$tmp/massprop" render "$tmp/copies.toml" -o "$tmp/copies.svg"
    read -r wall user rss < "$tmp/time"
    printf '%d copies in one place (%d-byte file): render %s s (%s s user), peak RSS %.0f MB, SVG %d bytes; %s\n' \
        "$1" "$(wc -c < "$tmp/copies.toml")" "$wall" "$user" "$((rss / 1024))" "$(wc -c < "$tmp/copies.svg")" \
        "$(grep -o '[0-9]* coincident cop[a-z]* not drawn again' "$tmp/copies.svg" | head -1)"
    for format in table json; do
        /usr/bin/time -f '%e %U' -o "$tmp/time" "$tmp/massprop" report --format "$format" "$tmp/copies.toml" > /dev/null
        read -r wall user < "$tmp/time"
        printf '    report --format %s of the same file: %s s (%s s user)\n' "$format" "$wall" "$user"
    done
}
copies "$((COPIES / 4))"
copies "$COPIES"
[ "$CASE" = copies ] && exit 0

python3 - "$tmp/parts.toml" "$PARTS" << 'PY'
import random, sys
out, n = sys.argv[1], int(sys.argv[2])
rng = random.Random(20261127)
def v(xs): return "[" + ", ".join("%.6g" % x for x in xs) + "]"
def at(): return v([rng.uniform(-1000, 1000) for _ in range(3)])
def turn(): return "{ axis = %s, degrees = %.6g }" % (v([rng.gauss(0, 1) for _ in range(3)]), rng.uniform(0, 360))
def size(): return rng.uniform(1, 60)
lines = ['name = "generated"', 'units = { length = "mm", mass = "kg" }']
for j in range(n):
    s = rng.choice(["box", "plate", "rod", "cylinder", "tube", "disk", "sphere", "cone", "torus", "point"])
    p = ["", "[[part]]", 'mass = %.6g' % rng.uniform(0.001, 2), 'group = "g%d"' % (j % 7)]
    if s == "box": p += ['shape = "box"', "size = " + v([size() for _ in range(3)]), "center = " + at(), "rotation = " + turn()]
    elif s == "plate": p += ['shape = "plate"', "size = " + v([size(), size()]), "center = " + at(), "rotation = " + turn()]
    elif s == "rod": p += ['shape = "rod"', "length = %.6g" % size(), "center = " + at(), "rotation = " + turn()]
    elif s in ("cylinder", "tube"):
        r = size()
        p += ['shape = "cylinder"', "radius = %.6g" % r, "length = %.6g" % size(), "center = " + at(), "rotation = " + turn()]
        if s == "tube": p += ["inner_radius = %.6g" % (0.8 * r)]
    elif s == "disk": p += ['shape = "disk"', "radius = %.6g" % size(), "center = " + at(), "rotation = " + turn()]
    elif s == "sphere": p += ['shape = "sphere"', "radius = %.6g" % size(), "center = " + at()]
    elif s == "cone": p += ['shape = "cone"', "radius = %.6g" % size(), "top_radius = 0", "length = %.6g" % size(), "center = " + at(), "rotation = " + turn()]
    elif s == "torus":
        r = size()
        p += ['shape = "torus"', "radius = %.6g" % r, "tube_radius = %.6g" % (0.3 * r), "center = " + at(), "rotation = " + turn()]
    else: p += ['shape = "point"', "center = " + at()]
    lines += p
open(out, "w").write("\n".join(lines) + "\n")
PY
"$tmp/massprop" render "$tmp/parts.toml" -o "$tmp/parts.svg"
grep -o '[0-9]* parts smaller than a pixel not drawn' "$tmp/parts.svg" >&2 || true
echo "SVG: $(du -h "$tmp/parts.svg" | cut -f1)" >&2
hyperfine --runs "$RUNS" --warmup "$WARMUP" --export-json "$tmp/times.json" \
    "$tmp/massprop render $tmp/parts.toml -o $tmp/out.svg" \
    "$tmp/massprop report $tmp/parts.toml -o $tmp/out.txt"
python3 - "$tmp/times.json" << 'PY'
import json, sys
r = json.load(open(sys.argv[1]))["results"]
print("render median %.2f s, report median %.2f s" % (r[0]["median"], r[1]["median"]))
PY
rss=()
for _ in 1 2 3; do
    rss+=("$(/usr/bin/time -f '%M' "$tmp/massprop" render "$tmp/parts.toml" -o "$tmp/out.svg" 2>&1 > /dev/null | tail -1)")
done
printf '%s\n' "${rss[@]}" | sort -n | sed -n 2p | awk '{ printf "render peak RSS (median of 3): %.0f MB\n", $1 / 1024 }'

[ -n "${BASE:-}" ] || exit 0
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for _ in $(seq "$RUNS"); do
    for who in base this; do
        bin="$tmp/massprop"
        [ "$who" = base ] && bin="$BASE"
        /usr/bin/time -f "$who %e %U %S" -a -o "$tmp/pairs" "$bin" render "$tmp/parts.toml" -o "$tmp/$who.svg"
    done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
cmp "$tmp/base.svg" "$tmp/this.svg" && echo "the two SVGs are byte-identical"
python3 - "$tmp/pairs" << 'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    who, wall, user, system = line.split()
    runs.setdefault(who, []).append((float(wall), float(user) + float(system)))
for who in ("base", "this"):
    r = runs[who]
    print("%s: render median wall %.2f s, median user+sys %.2f s (runs: %s)" % (
        who, statistics.median(w for w, _ in r), statistics.median(c for _, c in r),
        ", ".join("%.2f/%.2f" % x for x in r)))
PY
