#!/usr/bin/env bash
# Benchmark (issue 33, item 3): output at disk speed. `report --format
# json` (its `parts` and `assemblies`, a row per instance) and `report
# --full` (its parts and sub-assemblies tables) of benches/instances.sh's
# binary include tree of 21 files describing 2^20 instances, in MB/s of
# wall time and of CPU time (user + system), with peak memory; with BASE
# set (another build's binary, e.g. main's), the same commands run by it
# beside, alternating, and each output compared byte for byte with its.
# See docs/performance.md, "Output at disk speed".
#
#   bash benches/output.sh
#   BASE=/path/to/main/massprop bash benches/output.sh
#
# Builds the release binary, writes the tree into a temporary directory
# (removed on exit), runs each command RUNS times writing to /dev/null
# under GNU time (the best run is printed, every run's figures go to
# stderr). Needs python3; GNU time is installed with apt-get when missing
# (as root).
#
# Environment: LEVELS (default 21 files: 2^20 instances), RUNS (default
# 1), BASE (default none).
set -euo pipefail

LEVELS="${LEVELS:-21}"
RUNS="${RUNS:-1}"
BASE="${BASE:-}"

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/massprop-output.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

# shellcheck source=benches/lib.sh
source "$repo/benches/lib.sh"
need_bench_tools "the tree"

echo "== build (cargo build --release --locked)" >&2
(cd "$repo" && cargo build --release --locked --quiet --bin massprop)
cp "$(target_dir "$repo")/release/massprop" "$tmp/massprop"
commit="$(git -C "$repo" rev-parse --short=12 HEAD 2> /dev/null || echo unknown)"
builds=(massprop)
if [ -n "$BASE" ]; then
    cp "$BASE" "$tmp/base"
    builds+=(base)
fi

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
: > runs.txt
for args in "--format json" "--full"; do
    # shellcheck disable=SC2086
    size="$(./massprop report $args t0.toml | wc -c)"
    for _ in $(seq "$RUNS"); do
        for b in "${builds[@]}"; do
            # shellcheck disable=SC2086
            /usr/bin/time -f "%e %U %S %M" -o one.txt "./$b" report $args t0.toml > /dev/null
            echo "$b|$args|$size|$(tail -1 one.txt)" | tee -a runs.txt >&2
        done
    done
done

python3 - runs.txt "$LEVELS" << 'PY'
import sys
best = {}
for line in open(sys.argv[1]):
    build, args, size, times = line.rstrip("\n").split("|")
    wall, user, system, rss = times.split()
    row = (float(wall), float(user), float(system), int(rss), int(size))
    key = (build, args)
    if key not in best or row[1] + row[2] < best[key][1] + best[key][2]:
        best[key] = row
n = 1 << (int(sys.argv[2]) - 1)
print()
print(f"tree of {sys.argv[2]} files, {n:,} instances; the run of least CPU, stdout to /dev/null")
print()
print("| build | command | stdout | wall | MB/s (wall) | user + sys | MB/s (CPU) | peak RSS |")
print("|---|---|---|---|---|---|---|---|")
for (build, args), (wall, user, system, rss, size) in best.items():
    cpu = user + system
    print(f"| {build} | `report {args} t0.toml` | {size / 1e6:,.0f} MB | {wall:.2f} s "
          f"| {size / 1e6 / wall:.0f} | {user:.2f} + {system:.2f} s | {size / 1e6 / cpu:.0f} "
          f"| {rss / 1024:.1f} MiB |")
PY

echo
# The same version on one core (`taskset -c 0`: the tables' second thread
# shares the core) writes the same bytes.
if command -v taskset > /dev/null; then
    for args in "--format json" "--full"; do
        # shellcheck disable=SC2086
        if cmp <(./massprop report $args t0.toml) <(taskset -c 0 ./massprop report $args t0.toml); then
            echo "  report $args: the same bytes on one core as on two"
        else
            echo "  report $args: DIFFERS on one core"
        fi
    done
    /usr/bin/time -f "%e %U %S %M" -o one.txt taskset -c 0 ./massprop report --full t0.toml > /dev/null
    echo "  report --full on one core: $(awk '{print $1 " s wall, " $2 " + " $3 " s CPU, " $4 / 1024 " MiB"}' one.txt)"
fi
if [ -n "$BASE" ]; then
    echo
    for args in "--format json" "--full"; do
        # shellcheck disable=SC2086
        if cmp <(./massprop report $args t0.toml) <(./base report $args t0.toml); then
            echo "  report $args: the same bytes as BASE's"
        else
            echo "  report $args: DIFFERS from BASE's"
        fi
    done
fi
echo
echo "  machine      $(nproc) CPUs, $(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "  massprop     $commit ($(cd "$repo" && rustc --version 2> /dev/null || echo 'rustc unknown'))"
echo "  date         $(date -u +%Y-%m-%dT%H:%MZ)"
