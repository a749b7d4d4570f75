#!/usr/bin/env bash
# Benchmark: the figures the tests no longer time (issue 28, items 2 and
# 10). See docs/performance.md, "Depth and linear work".
#
#   bash benches/depth.sh
#
# - `check` of a URDF of 10⁴ and 10⁵ links (the tests count the work of
#   4× the links instead: tests/integration/robots_hostile.rs);
# - `budget` of 10⁵ copies sharing a group path of 64 names, and of 1,000
#   parts each on a path of 64 names of its own (64,000 groups);
# - `check` of a part file whose `group` has 30,000 names (refused at the
#   key; it once overflowed the stack).
#
# Builds the release binary, generates the files into a temporary
# directory (removed on exit), times each command with hyperfine and
# measures its peak memory with GNU time. Needs python3; hyperfine and GNU
# time are installed with apt-get when missing (as root).
#
# Environment: RUNS (default 5) and WARMUP (default 1) for hyperfine.
set -euo pipefail

RUNS="${RUNS:-5}"
WARMUP="${WARMUP:-1}"

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/massprop-depth.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

# shellcheck source=benches/lib.sh
source "$repo/benches/lib.sh"
need_bench_tools "the files"

echo "== build (cargo build --release --locked)" >&2
(cd "$repo" && cargo build --release --locked --quiet)
cp "$(cd "$repo" && target_dir .)/release/massprop" "$tmp/massprop"
commit="$(git -C "$repo" rev-parse --short=12 HEAD 2> /dev/null || echo unknown)"

echo "== generate" >&2
python3 - "$tmp" << 'PY'
import os, sys

out = sys.argv[1]
LINK = ('<link name="{}"><inertial><origin xyz="0 0 0"/><mass value="1"/>'
        '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>\n')


def many_links(n):
    """tests/integration/robots_hostile.rs's `many_links`: a chain of
    moving links, each with a fixed child, mirror pairs by name, every
    hundredth name used twice."""
    def name(i):
        if i % 100 == 99:
            return "dup"
        return f"{'left' if i % 2 == 0 else 'right'}_{i // 2}"
    s = ['<robot name="many">\n']
    s += [LINK.format(name(i)) for i in range(n)]
    for i in range(1, n):
        parent, kind = (i - 2, "revolute") if i % 2 == 0 else (i - 1, "fixed")
        s.append(f'<joint name="j{i}" type="{kind}"><parent link="{name(parent)}"/>'
                 f'<child link="{name(i)}"/></joint>\n')
    s.append("</robot>\n")
    return "".join(s)


for n in (10_000, 100_000):
    with open(os.path.join(out, f"links-{n}.urdf"), "w") as f:
        f.write(many_links(n))

point = '[[part]]\nname = "{}"\nshape = "point"\nmass = 1\ncenter = [{}, 0, 0]\ngroup = "{}"\n'
shared = "/".join(f"g{i}" for i in range(64))
with open(os.path.join(out, "shared.toml"), "w") as f:
    f.write(point.format("p", 0, shared) + "array = { count = 100000, step = [1, 0, 0] }\n")
with open(os.path.join(out, "distinct.toml"), "w") as f:
    for k in range(1000):
        f.write(point.format(f"p{k}", k, "/".join(f"p{k}n{i}" for i in range(64))))
with open(os.path.join(out, "deep.toml"), "w") as f:
    f.write(point.format("p", 0, "/".join(["a"] * 30_000)) + '[budget]\nlimit = "2 kg"\n')
PY

cd "$tmp"
commands=(
    "./massprop check --format json links-10000.urdf"
    "./massprop check --format json links-100000.urdf"
    "./massprop budget --format json shared.toml"
    "./massprop budget --format json distinct.toml"
    "./massprop check deep.toml"
)
echo "== time: hyperfine, $WARMUP warm-up runs, $RUNS runs" >&2
hyperfine -N -i --output=pipe --warmup "$WARMUP" --runs "$RUNS" \
    --export-json hf.json "${commands[@]}" >&2

echo "== peak memory and output size" >&2
: > rss.txt
for c in "${commands[@]}"; do
    # shellcheck disable=SC2086
    /usr/bin/time -f "%M" -o one.txt $c > out.txt 2> /dev/null || true
    # GNU time writes "Command exited with non-zero status N" first for
    # a refusal: the figure is the last line.
    echo "$(tail -1 one.txt) $(wc -c < out.txt)" >> rss.txt
done

python3 - hf.json rss.txt << 'PY'
import json, sys
r = json.load(open(sys.argv[1]))["results"]
rows = [l.split() for l in open(sys.argv[2])]
print()
print("| command | mean ± σ | peak RSS | stdout |")
print("|---|---|---|---|")
for res, (rss, size) in zip(r, rows):
    cmd = res["command"].replace("./massprop ", "")
    print(f"| `{cmd}` | {res['mean'] * 1e3:.0f} ± {res['stddev'] * 1e3:.0f} ms "
          f"| {int(rss) / 1024:.1f} MiB | {int(size) / 1e6:.2f} MB |")
PY
echo
echo "  machine      $(nproc) CPUs, $(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "  massprop     $commit ($(cd "$repo" && rustc --version 2> /dev/null || echo 'rustc unknown'))"
echo "  date         $(date -u +%Y-%m-%dT%H:%MZ)"
