#!/usr/bin/env bash
# Benchmark (issue 13): what the error bounds and `--precision auto` cost,
# end to end: `massprop report --format json` of a BASE commit from before
# the bounds (default bb5eaa8: `--precision standard|extended`, standard the
# default) against HEAD's (bounds always computed; `--precision
# auto|standard|extended`, auto the default: standard, recomputed in
# extended where a bound exceeds --rtol 1e-12).
#
#   bash benches/precision.sh            # BASE = bb5eaa8
#   bash benches/precision.sh OTHER_REV  # or BASE=OTHER_REV
#
# Builds both release binaries from committed trees (HEAD's and BASE's,
# each a `git worktree` in a temporary directory with a CARGO_TARGET_DIR of
# its own: the repository's working tree and target/ are left alone;
# uncommitted changes are not measured), generates the inputs
# deterministically (fixed seeds) into the temporary directory:
#
# - every file in shapes/ (HEAD's; the includes resolve beside them);
# - one file of 100,000 parts, the generator of benches/report-100k.sh
#   (same seed, so the same file);
# - one random assembly of 1,000 rotated boxes (python, fixed seed);
#
# checks that every command reports every input (exit status 0) and that
# their masses agree, then times with hyperfine (medians; output to
# /dev/null, hyperfine's default) four commands per input:
#
#   base standard   BASE  report --format json --precision standard (its default)
#   head standard   HEAD  report --format json --precision standard
#   head auto       HEAD  report --format json   (the default, auto)
#   head extended   HEAD  report --format json --precision extended
#
# and prints a Markdown table of the medians with the ratios auto/base
# standard and auto/head standard, which arithmetic auto chose for each
# input (the JSON's "precision") and how many lines it wrote to standard
# error, and the peak RSS (GNU time, %M, median of 3 runs) of all four on
# the 100,000-part file. The machine has 2 cores: run it on a quiet one, or
# read the min … max spread printed beside the table. Safe to run repeatedly
# and from any directory; everything it creates lives in the temporary
# directory (the worktrees are removed and pruned on exit).
#
# Needs git, cargo, python3, hyperfine and GNU time; the latter two are
# installed with apt-get when missing (as root).
#
# Environment: BASE (default bb5eaa8; the first argument wins); HEAD_REV
# (default HEAD: the commit measured as "head"); RUNS
# (default 10) and WARMUP (default 1) for the small inputs (shapes/ and the
# 1,000 boxes); RUNS_BIG (default 5) for the 100,000 parts; PARTS (default
# 100000); BOXES (default 1000); RSS_RUNS (default 3); KEEP_TARGET=DIR to
# keep both cargo target directories in DIR between runs (DIR/head,
# DIR/base), so that a second run does not rebuild from scratch.
set -euo pipefail

BASE="${1:-${BASE:-bb5eaa8}}"
RUNS="${RUNS:-10}"
RUNS_BIG="${RUNS_BIG:-5}"
WARMUP="${WARMUP:-1}"
PARTS="${PARTS:-100000}"
BOXES="${BOXES:-1000}"
RSS_RUNS="${RSS_RUNS:-3}"
SEED=20260104     # benches/report-100k.sh's
BOX_SEED=20261124

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
HEAD_REV="${HEAD_REV:-HEAD}"
head_rev="$(git -C "$repo" rev-parse --verify "$HEAD_REV^{commit}")"
base_rev="$(git -C "$repo" rev-parse --verify "$BASE^{commit}")"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/massprop-precision.XXXXXX")"
cleanup() {
    for wt in "$tmp/wt-head" "$tmp/wt-base"; do
        if [ -d "$wt" ]; then
            git -C "$repo" worktree remove --force "$wt" > /dev/null 2>&1 || true
        fi
    done
    rm -rf "$tmp"
    git -C "$repo" worktree prune > /dev/null 2>&1 || true
}
trap cleanup EXIT

# shellcheck source=benches/lib.sh
source "$repo/benches/lib.sh"
need_bench_tools "the inputs"

# build NAME REV: a worktree of REV at $tmp/wt-NAME, its release binary
# copied to $tmp/NAME (a copy: no rebuild can swap it between runs).
build() {
    local name="$1" rev="$2" target
    target="${KEEP_TARGET:+$KEEP_TARGET/$name}"
    target="${target:-$tmp/target-$name}"
    echo "== build $name: ${rev:0:12} (cargo build --release --locked, target $target)" >&2
    git -C "$repo" worktree add --detach --quiet "$tmp/wt-$name" "$rev"
    (cd "$tmp/wt-$name" && CARGO_TARGET_DIR="$target" cargo build --release --locked --quiet --bin massprop)
    cp "$target/release/massprop" "$tmp/$name"
}
build head "$head_rev"
build base "$base_rev"

dirty=""
if [ "$head_rev" = "$(git -C "$repo" rev-parse HEAD)" ] \
    && [ -n "$(git -C "$repo" status --porcelain -- src Cargo.toml Cargo.lock 2> /dev/null)" ]; then
    dirty=" (the working tree has uncommitted changes in src/ or Cargo.*: not measured)"
fi

# Inputs: name<TAB>path, one a line.
mkdir "$tmp/in"
cp -R "$tmp/wt-head/shapes" "$tmp/in/shapes"
: > "$tmp/inputs.tsv"
for f in "$tmp"/in/shapes/*.toml; do
    printf '%s\t%s\n' "shapes/$(basename "$f")" "$f" >> "$tmp/inputs.tsv"
done

echo "== generate $BOXES rotated boxes (seed $BOX_SEED)" >&2
python3 - "$tmp/in/boxes.toml" "$BOXES" "$BOX_SEED" << 'PY'
"""A random assembly of N boxes, each turned by a random unit quaternion:
edges 1 to 200 mm, centres within 1 m of the origin, a mass (0.001 to 5 kg)
or a density (1e-6 to 9e-6 kg/mm³), half each; 17 significant digits."""
import math
import random
import sys

out, n, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
rng = random.Random(seed)


def num(x):
    return f"{float(x):.17g}"


def vec(xs):
    return "[" + ", ".join(num(x) for x in xs) + "]"


lines = [f"# Generated by benches/precision.sh (seed {seed}): {n} rotated boxes.",
         'name = "random boxes"',
         'units = { length = "mm", mass = "kg" }']
for j in range(n):
    q = [rng.gauss(0, 1) for _ in range(4)]
    norm = math.sqrt(sum(x * x for x in q))
    q = [x / norm for x in q]
    lines += ["", "[[part]]", f'name = "box {j + 1:04d}"', 'shape = "box"',
              f"size = {vec(rng.uniform(1.0, 200.0) for _ in range(3))}",
              f"center = {vec(rng.uniform(-1000.0, 1000.0) for _ in range(3))}",
              f"rotation = {{ quaternion = {vec(q)} }}"]
    if rng.random() < 0.5:
        lines.append(f"mass = {num(rng.uniform(0.001, 5.0))}")
    else:
        lines.append(f"density = {num(rng.uniform(1e-6, 9e-6))}")
with open(out, "w", encoding="utf-8") as fh:
    fh.write("\n".join(lines) + "\n")
PY
printf '%s\t%s\n' "$BOXES rotated boxes" "$tmp/in/boxes.toml" >> "$tmp/inputs.tsv"

echo "== generate $PARTS parts (benches/report-100k.sh's generator, seed $SEED)" >&2
# The generator is taken from HEAD's benches/report-100k.sh (its first
# python heredoc), so that the two benchmarks read the same file.
git -C "$repo" show "$head_rev:benches/report-100k.sh" \
    | awk '/^python3 .*<< .PY.$/ {on = 1; next} on && /^PY$/ {exit} on' > "$tmp/gen100k.py"
grep -q 'rng = random.Random(seed)' "$tmp/gen100k.py" \
    || { echo "error: could not extract the generator from benches/report-100k.sh" >&2; exit 2; }
python3 "$tmp/gen100k.py" "$tmp/in/parts.toml" "$PARTS" "$SEED" > "$tmp/expected-mass"
big_name="$PARTS parts"
printf '%s\t%s\n' "$big_name" "$tmp/in/parts.toml" >> "$tmp/inputs.tsv"

base_mode=()
base_help="$("$tmp/base" report --help)"
if [[ "$base_help" == *--precision* ]]; then
    base_mode=(--precision standard)
fi
labels=("base standard" "head standard" "head auto" "head extended")
cmd_of() { # cmd_of INDEX FILE: the command line, words split on spaces
    case "$1" in
        0) echo "$tmp/base report --format json ${base_mode[*]} $2" ;;
        1) echo "$tmp/head report --format json --precision standard $2" ;;
        2) echo "$tmp/head report --format json $2" ;;
        3) echo "$tmp/head report --format json --precision extended $2" ;;
    esac
}

echo "== correctness: every command reports every input; masses agree" >&2
mkdir "$tmp/out"
i=0
while IFS=$'\t' read -r name file; do
    i=$((i + 1))
    for c in 0 1 2 3; do
        status=0
        # shellcheck disable=SC2046 # the command is split into words on purpose
        $(cmd_of "$c" "$file") < /dev/null > "$tmp/out/$i.$c.json" 2> "$tmp/out/$i.$c.err" || status=$?
        if [ "$status" -ne 0 ]; then
            echo "error: ${labels[$c]} on $name exited with status $status" >&2
            sed -n 1,20p "$tmp/out/$i.$c.err" >&2
            exit 1
        fi
    done
done < "$tmp/inputs.tsv"
python3 - "$tmp/inputs.tsv" "$tmp/out" "$tmp/expected-mass" "$big_name" > "$tmp/choices.md" << 'PY'
import json, sys
inputs = [l.rstrip("\n").split("\t") for l in open(sys.argv[1])]
out, want_big, big = sys.argv[2], float(open(sys.argv[3]).read()), sys.argv[4]
print("| input | auto chose | auto's stderr lines | head standard's stderr lines |")
print("|---|---|---:|---:|")
for i, (name, _) in enumerate(inputs, 1):
    docs = [json.load(open(f"{out}/{i}.{c}.json")) for c in range(4)]
    masses = [d["mass"] for d in docs]
    ref = want_big if name == big else masses[0]
    for c, m in enumerate(masses):
        if not abs(m - ref) <= 1e-9 * abs(ref):
            sys.exit(f"error: {name}: command {c} reports mass {m!r}, expected {ref!r}")
    err = [sum(1 for _ in open(f"{out}/{i}.{c}.err")) for c in range(4)]
    print(f"| {name} | {docs[2].get('precision', '?')} | {err[2]} | {err[1]} |")
PY

echo "== time: hyperfine, $WARMUP warm-up; $RUNS runs each ($RUNS_BIG for $big_name)" >&2
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
i=0
while IFS=$'\t' read -r name file; do
    i=$((i + 1))
    runs="$RUNS"
    [ "$name" = "$big_name" ] && runs="$RUNS_BIG"
    cmds=()
    for c in 0 1 2 3; do cmds+=("$(cmd_of "$c" "$file")"); done
    echo "-- $name" >&2
    hyperfine -N --style basic --warmup "$WARMUP" --runs "$runs" \
        --export-json "$tmp/hf.$i.json" "${cmds[@]}" < /dev/null > "$tmp/hf.$i.log" 2>&1 \
        || { cat "$tmp/hf.$i.log" >&2; exit 1; }
done < "$tmp/inputs.tsv"
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"

echo "== peak RSS on $big_name: /usr/bin/time -f %M, median of $RSS_RUNS runs" >&2
big_file="$(awk -F'\t' -v n="$big_name" '$1 == n {print $2}' "$tmp/inputs.tsv")"
: > "$tmp/rss.txt"
for c in 0 1 2 3; do
    for _ in $(seq "$RSS_RUNS"); do
        # shellcheck disable=SC2046 # the command is split into words on purpose
        /usr/bin/time -f %M -o "$tmp/time.txt" $(cmd_of "$c" "$big_file") > /dev/null 2>&1
        tail -n 1 "$tmp/time.txt"
    done | sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}' >> "$tmp/rss.txt"
done

python3 - "$tmp/inputs.tsv" "$tmp" "$tmp/rss.txt" "$big_name" << 'PY'
import json, statistics, sys
inputs = [l.rstrip("\n").split("\t") for l in open(sys.argv[1])]
tmp, rss, big = sys.argv[2], [int(x) for x in open(sys.argv[3]).read().split()], sys.argv[4]


def t(s):
    return f"{s * 1e3:.1f} ms" if s < 1 else f"{s:.3f} s"


rows, spread = [], []
for i, (name, _) in enumerate(inputs, 1):
    res = json.load(open(f"{tmp}/hf.{i}.json"))["results"]
    med = [statistics.median(r["times"]) for r in res]
    n = len(res[0]["times"])
    rows.append(f"| {name} | " + " | ".join(t(m) for m in med)
                + f" | {med[2] / med[0]:.2f}x | {med[2] / med[1]:.2f}x |")
    spread.append(f"| {name} | {n} | " + " | ".join(f"{t(r['min'])} … {t(r['max'])}" for r in res) + " |")
print()
print("Medians, `report --format json` (output to /dev/null):")
print()
print("| input | base standard | head standard | head auto | head extended | auto/base-standard | auto/head-standard |")
print("|---|---:|---:|---:|---:|---:|---:|")
print("\n".join(rows))
print()
print("Spread (min … max of the timed runs):")
print()
print("| input | runs | base standard | head standard | head auto | head extended |")
print("|---|---:|---|---|---|---|")
print("\n".join(spread))
print()
labels = ["base standard", "head standard", "head auto", "head extended"]
print(f"Peak RSS on {big} (median of the runs, MiB):")
print()
print("| " + " | ".join(labels) + " | auto/base-standard |")
print("|" + "---:|" * (len(labels) + 1))
print("| " + " | ".join(f"{k / 1024:.1f}" for k in rss) + f" | {rss[2] / rss[0]:.2f}x |")
PY
echo
echo "Which arithmetic auto chose (the JSON's \"precision\"):"
echo
cat "$tmp/choices.md"
echo
echo "- base         ${base_rev:0:12} ($BASE)"
echo "- head         ${head_rev:0:12} ($HEAD_REV)$dirty"
echo "- machine      $(nproc) CPUs, $(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo), $(uname -sr)"
echo "- load avg     $load_before before timing, $load_after after (1, 5, 15 min)"
echo "- rustc        $(rustc --version 2> /dev/null || echo unknown)"
echo "- date         $(date -u +%Y-%m-%dT%H:%MZ)"
