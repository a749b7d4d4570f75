#!/usr/bin/env bash
# Benchmark (issue 33, item 2): `check` and the plain `report` of a binary
# include tree of 21 files describing 2^20 instances, which compose each
# distinct sub-assembly once and place it per instance (`compose::placed`)
# and check each distinct file once (`model::walk::Reach`); beside them
# `report --format json`, which still lists every instance (streamed). See
# docs/performance.md, "Compose once, place many".
#
#   bash benches/instances.sh
#
# Builds the release binary, writes the tree (benches/cost.sh's: each file
# includes the next twice, the last a point mass) into a temporary
# directory (removed on exit), times each command with hyperfine and
# measures its peak memory with GNU time. Needs python3; hyperfine and GNU
# time are installed with apt-get when missing (as root).
#
# Environment: LEVELS (default 21 files: 2^20 instances), RUNS (default
# 10) and WARMUP (default 2) for hyperfine.
set -euo pipefail

LEVELS="${LEVELS:-21}"
RUNS="${RUNS:-10}"
WARMUP="${WARMUP:-2}"

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/massprop-instances.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

# shellcheck source=benches/lib.sh
source "$repo/benches/lib.sh"
need_bench_tools "the tree"

echo "== build (cargo build --release --locked)" >&2
(cd "$repo" && cargo build --release --locked --quiet)
cp "$repo/target/release/massprop" "$tmp/massprop"
commit="$(git -C "$repo" rev-parse --short=12 HEAD 2> /dev/null || echo unknown)"

echo "== generate" >&2
python3 - "$tmp" "$LEVELS" << 'PY'
import sys
out, levels = sys.argv[1], int(sys.argv[2])
for l in range(levels):
    if l == levels - 1:
        body = '[[part]]\nshape = "point"\nmass = 1\ncenter = [0, 0, 0]\n'
    else:
        body = ''.join(f'[[part]]\ninclude = "t{l+1}.toml"\norigin = [{k}, {l}, 0]\n'
                       for k in range(2))
    open(f"{out}/t{l}.toml", "w").write(body)
PY

cd "$tmp"
commands=(
    "./massprop check t0.toml"
    "./massprop check --format json t0.toml"
    "./massprop report t0.toml"
    "./massprop report --precision extended t0.toml"
)
echo "== time: hyperfine, $WARMUP warm-up runs, $RUNS runs" >&2
hyperfine -N -i --output=pipe --warmup "$WARMUP" --runs "$RUNS" \
    --export-json hf.json "${commands[@]}" >&2

echo "== peak memory and output size" >&2
: > rss.txt
for c in "${commands[@]}" "./massprop report --format json t0.toml"; do
    # shellcheck disable=SC2086
    /usr/bin/time -f "%e %M" -o one.txt $c > out.txt 2> /dev/null || true
    echo "$(tail -1 one.txt) $(wc -c < out.txt)" >> rss.txt
done

python3 - hf.json rss.txt "$LEVELS" << 'PY'
import json, sys
r = json.load(open(sys.argv[1]))["results"]
rows = [l.split() for l in open(sys.argv[2])]
n = 1 << (int(sys.argv[3]) - 1)
print()
print(f"tree of {sys.argv[3]} files, {n:,} instances")
print()
print("| command | mean ± σ | peak RSS | stdout |")
print("|---|---|---|---|")
for res, (_, rss, size) in zip(r, rows):
    cmd = res["command"].replace("./massprop ", "")
    print(f"| `{cmd}` | {res['mean'] * 1e3:.1f} ± {res['stddev'] * 1e3:.1f} ms "
          f"| {int(rss) / 1024:.1f} MiB | {int(size) / 1e6:.2f} MB |")
secs, rss, size = rows[-1]
print(f"| `report --format json t0.toml` (one run, GNU time) | {float(secs):.2f} s "
      f"| {int(rss) / 1024:.1f} MiB | {int(size) / 1e6:.1f} MB |")
PY
echo
echo "  machine      $(nproc) CPUs, $(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "  massprop     $commit ($(cd "$repo" && rustc --version 2> /dev/null || echo 'rustc unknown'))"
echo "  date         $(date -u +%Y-%m-%dT%H:%MZ)"
