#!/usr/bin/env bash
# Benchmark (issue 33, item 5): every figure of issue 33 beside its anchor,
# measured side by side in one run on the same machine, and the plot of
# time and memory against parts and instances.
#
#   bash benches/issue33.sh                      # the table on stdout
#   SVG=docs/issue33.svg bash benches/issue33.sh # and the plot
#
# The inputs are the per-figure scripts' own, made by their own generators
# (read out of benches/report-100k.sh, benches/cost.sh, benches/mesh.sh and
# benches/render.sh, so that the files are the same bytes): the 100,000-part
# file (seed 20260104), the binary include tree of 21 files describing 2²⁰
# instances, the 998,000-triangle UV sphere (binary STL) and the
# 100,000-part drawing file. Anchors: the toml crate deserializing the part
# file into `toml::Table` (examples/toml_only.rs); tomllib + Pinocchio
# composing the part file and the tree (each distinct file composed once);
# trimesh integrating the sphere (benches/anchors.py, in a venv under /tmp
# made on the first run: `pip install pin trimesh`).
#
# Each command runs RUNS times (default 3), the median of wall time and of
# peak RSS (GNU time) reported. The machine may be shared: the ratios,
# measured in the same run, are the figures to read.
#
# Environment: RUNS (default 3); SVG (a path: also write the plot there);
# VENV (default /tmp/massprop-anchors-venv); SWEEP (default
# "10000 30000 100000 300000": flat files of the plot) and TREE (default
# "10 12 14 16 18 20": trees of the plot).
set -euo pipefail

RUNS="${RUNS:-3}"
VENV="${VENV:-/tmp/massprop-anchors-venv}"
SWEEP="${SWEEP:-10000 30000 100000 300000}"
TREE="${TREE:-10 12 14 16 18 20}"
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/massprop-issue33.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

# shellcheck source=benches/lib.sh
source "$repo/benches/lib.sh"
need_bench_tools "the inputs"

echo "== build (cargo build --release --locked: massprop, example toml_only)" >&2
(cd "$repo" && cargo build --release --locked --quiet --bin massprop --example toml_only)
cp "$repo/target/release/massprop" "$tmp/massprop"
cp "$repo/target/release/examples/toml_only" "$tmp/toml_only"
commit="$(git -C "$repo" rev-parse --short=12 HEAD 2> /dev/null || echo unknown)"

if [ ! -x "$VENV/bin/python" ]; then
    echo "== venv for the anchors: $VENV (pip install pin trimesh)" >&2
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install -q pin trimesh >&2
fi

# heredoc SCRIPT N: the Nth python heredoc (from 1) of a bench script.
heredoc() {
    awk -v want="$2" '/<< *.PY.$|<<.PY.$/ { n++; if (n == want) { on = 1; next } }
        on && /^PY$/ { exit } on { print }' "$1"
}

echo "== generate" >&2
heredoc "$repo/benches/report-100k.sh" 1 > "$tmp/gen-parts.py"
python3 "$tmp/gen-parts.py" "$tmp/parts.toml" 100000 20260104 > /dev/null
for n in $SWEEP; do
    python3 "$tmp/gen-parts.py" "$tmp/parts-$n.toml" "$n" 20260104 > /dev/null
done
python3 - "$tmp" $TREE << 'PY'
import os, sys
# benches/cost.sh's trees: each file includes the next twice.
def tree_files(d, levels):
    os.makedirs(d, exist_ok=True)
    for l in range(levels):
        body = ('[[part]]\nshape = "point"\nmass = 1\ncenter = [0, 0, 0]\n' if l == levels - 1 else
                ''.join(f'[[part]]\ninclude = "t{l+1}.toml"\norigin = [{k}, {l}, 0]\n' for k in range(2)))
        open(f"{d}/t{l}.toml", "w").write(body)
for k in map(int, sys.argv[2:]):
    tree_files(f"{sys.argv[1]}/tree-{k}", k + 1)
PY
heredoc "$repo/benches/mesh.sh" 1 > "$tmp/gen-mesh.py"
python3 "$tmp/gen-mesh.py" "$tmp" 500 > /dev/null
rm -f "$tmp/sphere-ascii.stl"
printf '[[part]]\nshape = "mesh"\nfile = "sphere.stl"\nmesh_unit = "m"\ndensity = 1000\n' > "$tmp/sphere.toml"
awk '/^python3 - "\$tmp\/parts.toml" "\$PARTS" << .PY.$/ { on = 1; next } on && /^PY$/ { exit } on { print }' \
    "$repo/benches/render.sh" > "$tmp/gen-render.py"
python3 "$tmp/gen-render.py" "$tmp/render.toml" 100000

# measure LABEL -- COMMAND...: RUNS runs; appends "LABEL wall_median
# rss_median_kib stdout_bytes" to rows.
measure() {
    local label="$1"
    shift 2
    : > "$tmp/one"
    for _ in $(seq "$RUNS"); do
        /usr/bin/time -o "$tmp/time" -f "%e %M" "$@" > "$tmp/out" 2> /dev/null || true
        tail -1 "$tmp/time" >> "$tmp/one"
    done
    python3 - "$tmp/one" "$label" "$(wc -c < "$tmp/out")" >> "$tmp/rows" << 'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
print(sys.argv[2], statistics.median(float(r[0]) for r in rows),
      statistics.median(int(r[1]) for r in rows), sys.argv[3])
PY
}
# anchor LABEL KIND FILE: the Python anchor, its own timing (median of
# RUNS, after the interpreter's start) and mass.
anchor() {
    : > "$tmp/one"
    for _ in $(seq "$RUNS"); do "$VENV/bin/python" "$repo/benches/anchors.py" "$2" "$3" >> "$tmp/one"; done
    python3 - "$tmp/one" "$1" >> "$tmp/rows" << 'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
print(sys.argv[2], statistics.median(float(r[1]) for r in rows), 0, 0, rows[0][0])
PY
}

cd "$tmp"
echo "== measure ($RUNS runs each; load average $(cut -d' ' -f1-3 /proc/loadavg))" >&2
: > rows
measure toml -- ./toml_only parts.toml
measure report-table -- ./massprop report parts.toml
measure report-json -- ./massprop report --format json parts.toml
measure report-one-core -- taskset -c 0 ./massprop report parts.toml
anchor pin-parts parts parts.toml
measure tree-check -- ./massprop check tree-20/t0.toml
measure tree-report -- ./massprop report tree-20/t0.toml
measure tree-json -- ./massprop report --format json tree-20/t0.toml
measure tree-full -- ./massprop report --full tree-20/t0.toml
anchor pin-tree tree tree-20/t0.toml
measure mesh -- ./massprop report --format json sphere.toml
measure mesh-one-core -- taskset -c 0 ./massprop report --format json sphere.toml
anchor trimesh mesh sphere.stl
measure render -- ./massprop render render.toml -o render.svg
for n in $SWEEP; do measure "sweep-json-$n" -- ./massprop report --format json "parts-$n.toml"; done
for k in $TREE; do measure "sweep-tree-$k" -- ./massprop report --format json "tree-$k/t0.toml"; done

PLOT="$repo/benches/plot.py" python3 - rows "$(wc -c < parts.toml)" "$commit" "${SVG:-}" "$SWEEP" "$TREE" << 'PY'
import sys
rows = {r[0]: r[1:] for r in (l.split() for l in open(sys.argv[1]))}
size, commit, svg = int(sys.argv[2]), sys.argv[3], sys.argv[4]
t = lambda k: float(rows[k][0])
mib = lambda k: int(rows[k][1]) / 1024
out = lambda k: int(rows[k][2])
print(f"| figure | issue 33's target | measured | anchor, same run | ratio |")
print(f"|---|---|---|---|---|")
budget = 3 * size / 2**20 + 64
for k, what in [("report-table", "`report`, 100,000 parts (table)"), ("report-json", "`report --format json`, 100,000 parts")]:
    print(f"| {what} | ≤ 0.5 × toml crate, ≤ {budget:.0f} MiB | {t(k):.3f} s, {mib(k):.0f} MiB "
          f"| toml crate into `toml::Table`: {t('toml'):.3f} s, {mib('toml'):.0f} MiB "
          f"| **{t(k) / t('toml'):.2f} ×** |")
print(f"| `report`, 100,000 parts, one core (`taskset -c 0`) | — | {t('report-one-core'):.3f} s "
      f"| tomllib + Pinocchio: {t('pin-parts'):.2f} s | {t('report-one-core') / t('toml'):.2f} × toml |")
print(f"| `check` of the 2²⁰-instance tree | < 50 ms (item 2: see compose) | {t('tree-check') * 1e3:.0f} ms "
      f"| tomllib + Pinocchio, each file once: {t('pin-tree') * 1e3:.0f} ms | — |")
print(f"| `report` (short) of the tree | < 50 ms (item 2: see compose) | {t('tree-report') * 1e3:.0f} ms | — | — |")
for k, what in [("tree-json", "`report --format json` of the tree"), ("tree-full", "`report --full` of the tree")]:
    rate = out(k) / t(k) / 1e6
    print(f"| {what} | ≥ 300 MB/s | {t(k):.2f} s, {out(k) / 1e6:.0f} MB: **{rate:.0f} MB/s**, {mib(k):.0f} MiB | — | — |")
print(f"| 998,000-triangle mesh (binary STL), `report --format json` | ≤ 0.5 s | **{t('mesh'):.2f} s** "
      f"({t('mesh-one-core'):.2f} s on one core), {mib('mesh'):.0f} MiB "
      f"| trimesh (load, mass properties): {t('trimesh'):.2f} s | {t('mesh') / t('trimesh'):.2f} × |")
print(f"| `render` of 100,000 parts | ≤ 1 s | **{t('render'):.2f} s**, {mib('render'):.0f} MiB | — | — |")
print()
print(f"masses: Pinocchio {rows['pin-parts'][3]} kg (parts), {rows['pin-tree'][3]} (tree); trimesh {rows['trimesh'][3]} kg")
print(f"massprop {commit}; medians of the runs; anchors timed inside Python (interpreter start-up excluded)")
if not svg:
    sys.exit()
# The plot: time and peak memory against parts (flat files, JSON) and
# instances (include trees, JSON).
import json, os, subprocess
series = {"parts (JSON)": [(int(n), t(f"sweep-json-{n}"), mib(f"sweep-json-{n}")) for n in sys.argv[5].split()],
          "instances (JSON)": [(1 << int(k), t(f"sweep-tree-{k}"), mib(f"sweep-tree-{k}")) for k in sys.argv[6].split()]}
subprocess.run([sys.executable, os.environ["PLOT"], svg], input=json.dumps(series), text=True, check=True)
PY
