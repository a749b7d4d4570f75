#!/usr/bin/env bash
# Benchmark (issue 12, item 6): time and peak memory against the size of the
# input and the size of the work, for the inputs that are cheap to write and
# expensive to expand or show.
#
#   bash benches/cost.sh            # figures as a markdown table on stdout
#   SVG=docs/cost.svg bash benches/cost.sh   # and the plot
#
# Measures, one run each (GNU time: wall seconds and peak RSS), the release
# binary on files it generates deterministically in a temporary directory:
#
# - flat files of N point masses (17-digit numbers), `report --format json`
#   and the table: time and memory against parts and input bytes, beside
#   the memory budget of the issue, 3 × input + 64 MiB;
# - binary include trees of k + 1 small files describing 2^k instances
#   (`report --format json`): time and memory against instances;
# - a tree of 32 files describing 2^31 instances (refused by the part
#   limit: how long the refusal takes);
# - a part name of 1 to 20 MB (the table);
# - an unknown key of 200 KB ("did you mean");
# - the 100,000 point masses with `[materials]` and `[expect]` (`check`).
#
# Environment: FLAT (default "10000 30000 100000 300000 1000000"), TREE
# (default "10 12 14 16 18 20"), SVG (a path: also write the plot there).
# Needs python3 (generator and plot) and GNU time (installed with apt-get
# when missing, as root). Removes its temporary directory on exit.
set -euo pipefail

FLAT="${FLAT:-10000 30000 100000 300000 1000000}"
TREE="${TREE:-10 12 14 16 18 20}"
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/massprop-cost.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

if [ ! -x /usr/bin/time ]; then
    apt-get update -qq && apt-get install -y -qq time >/dev/null
fi
cargo build --release --quiet --manifest-path "$repo/Cargo.toml"
# shellcheck source=benches/lib.sh
source "$repo/benches/lib.sh"
bin="$(target_dir "$repo")/release/massprop"

# One measurement: `measure LABEL COUNT BYTES -- command...` appends a row
# of seconds and peak KiB (and the exit status) to $tmp/rows.
measure() {
    local label="$1" count="$2" bytes="$3"
    shift 4
    local status=0
    /usr/bin/time -o "$tmp/time" -f "%e %M" "$@" >"$tmp/out" 2>"$tmp/err" || status=$?
    read -r secs kib <"$tmp/time" || true
    # GNU time writes "Command exited with non-zero status N" first.
    if grep -q "^Command" "$tmp/time"; then
        read -r secs kib < <(tail -1 "$tmp/time")
    fi
    echo "$label $count $bytes $secs $kib $status $(wc -c <"$tmp/out")" >>"$tmp/rows"
}

python3 - "$tmp" "$FLAT" "$TREE" <<'EOF'
import random, sys, os
tmp, flat, tree = sys.argv[1], sys.argv[2].split(), sys.argv[3].split()
random.seed(20261124)
for n in map(int, flat):
    with open(f"{tmp}/flat-{n}.toml", "w") as f:
        for _ in range(n):
            f.write('[[part]]\nshape = "point"\nmass = %.17g\ncenter = [%.17g, %.17g, %.17g]\n'
                    % (random.uniform(0.1, 2), *(random.uniform(-1, 1) for _ in range(3))))
def tree_files(d, levels):
    os.makedirs(d, exist_ok=True)
    for l in range(levels):
        body = ('[[part]]\nshape = "point"\nmass = 1\ncenter = [0, 0, 0]\n' if l == levels - 1 else
                ''.join(f'[[part]]\ninclude = "t{l+1}.toml"\norigin = [{k}, {l}, 0]\n' for k in range(2)))
        open(f"{d}/t{l}.toml", "w").write(body)
for k in map(int, tree):
    tree_files(f"{tmp}/tree-{k}", k + 1)
tree_files(f"{tmp}/tree-31", 32)
for mb in (1, 5, 20):
    name = "n" * (mb << 20)
    open(f"{tmp}/name-{mb}.toml", "w").write(
        f'[[part]]\nname = "{name}"\nshape = "point"\nmass = 1\ncenter = [0, 0, 0]\n'
        '[[part]]\nshape = "point"\nmass = 1\ncenter = [1, 0, 0]\n')
# The same 100,000 point masses with materials and expectations, read
# by `check` (those tables are serde's, read alone).
pts = open(f"{tmp}/flat-100000.toml").read() if os.path.exists(f"{tmp}/flat-100000.toml") else ""
if pts:
    open(f"{tmp}/expect-100000.toml", "w").write(
        '[materials]\nfoam = { density = "30 kg/m^3" }\n' + pts
        + '[expect]\nmass = { min = 0 }\ncenter_of_mass.x = { min = -1, max = 1 }\n')
key = "k" * 200_000
open(f"{tmp}/key.toml", "w").write(f'[[part]]\nshape = "point"\nmass = 1\ncenter = [0, 0, 0]\n{key} = 1\n')
EOF

for n in $FLAT; do
    f="$tmp/flat-$n.toml"
    bytes=$(wc -c <"$f")
    measure flat-json "$n" "$bytes" -- "$bin" report --format json "$f"
    measure flat-table "$n" "$bytes" -- "$bin" report "$f"
done
if [ -f "$tmp/expect-100000.toml" ]; then
    measure check-expect 100000 "$(wc -c <"$tmp/expect-100000.toml")" -- "$bin" check "$tmp/expect-100000.toml"
fi
for k in $TREE; do
    measure tree-json "$((1 << k))" "$(cat "$tmp/tree-$k"/*.toml | wc -c)" -- \
        "$bin" report --format json "$tmp/tree-$k/t0.toml"
done
measure tree-refused "$((1 << 31))" "$(cat "$tmp/tree-31"/*.toml | wc -c)" -- \
    "$bin" report --format json "$tmp/tree-31/t0.toml"
for mb in 1 5 20; do
    measure long-name "$((mb << 20))" "$(wc -c <"$tmp/name-$mb.toml")" -- "$bin" report "$tmp/name-$mb.toml"
done
measure unknown-key 200000 "$(wc -c <"$tmp/key.toml")" -- "$bin" report "$tmp/key.toml"

python3 - "$tmp/rows" "${SVG:-}" <<'EOF'
import sys, math
rows = [l.split() for l in open(sys.argv[1])]
print("| input | parts, instances or characters | input | time | peak memory | budget (3 × input + 64 MiB; trees 256 MiB) | exit | output |")
print("|---|---:|---:|---:|---:|---:|---:|---:|")
for label, count, b, secs, kib, status, out in rows:
    mib, inp = int(kib) / 1024, int(b) / 2**20
    # A tree's budget is the issue's 256 MiB for 2^20 instances; a file's
    # 3 x its size + 64 MiB.
    budget = 256 if label.startswith("tree") else 3 * inp + 64
    mark = "" if mib <= budget else " (over)"
    print(f"| {label} | {int(count):,} | {inp:.2f} MiB | {float(secs):.2f} s | {mib:.0f} MiB{mark} | {budget:.0f} MiB | {status} | {int(out)/2**20:.1f} MiB |")
svg = sys.argv[2]
if not svg:
    sys.exit()
# A log-log plot by hand (no plotting library on the machines): time and
# memory against parts (flat files) and instances (include trees).
series = {}
for label, count, b, secs, kib, status, out in rows:
    if label in ("flat-json", "flat-table", "tree-json"):
        series.setdefault(label, []).append((int(count), float(secs), int(kib) / 1024))
    if label == "flat-json":
        # The memory budget of a flat file, 3 × input + 64 MiB (its time
        # is not a budget: drawn below the panel's floor).
        series.setdefault("budget", []).append((int(count), 0, 3 * int(b) / 2**20 + 64))
W, H, M = 900, 380, 60
def panel(x0, title, idx, unit, lo, hi):
    xs = [c for s in series.values() for c, *_ in s]
    xl, xh = math.log10(min(xs)), math.log10(max(xs))
    yl, yh = math.log10(lo), math.log10(hi)
    pw, ph = W / 2 - M - 20, H - 2 * M
    X = lambda c: x0 + M + (math.log10(c) - xl) / (xh - xl) * pw
    Y = lambda v: H - M - (math.log10(max(v, lo)) - yl) / (yh - yl) * ph
    out = [f'<text x="{x0 + M + pw / 2}" y="24" text-anchor="middle" font-weight="bold">{title}</text>',
           f'<rect x="{x0 + M}" y="{M}" width="{pw}" height="{ph}" fill="none" stroke="#888"/>']
    for e in range(math.ceil(xl), math.floor(xh) + 1):
        out.append(f'<text x="{X(10**e)}" y="{H - M + 18}" text-anchor="middle">1e{e}</text>')
    for e in range(math.ceil(yl), math.floor(yh) + 1):
        out.append(f'<text x="{x0 + M - 6}" y="{Y(10**e) + 4}" text-anchor="end">1e{e}</text>')
        out.append(f'<line x1="{x0 + M}" x2="{x0 + M + pw}" y1="{Y(10**e)}" y2="{Y(10**e)}" stroke="#ddd"/>')
    out.append(f'<text x="{x0 + M + pw / 2}" y="{H - 12}" text-anchor="middle">parts or instances</text>')
    out.append(f'<text x="{x0 + 14}" y="{H / 2}" transform="rotate(-90 {x0 + 14} {H / 2})" text-anchor="middle">{unit}</text>')
    colours = {"flat-json": "#1f77b4", "flat-table": "#2ca02c", "tree-json": "#d62728", "budget": "#555"}
    shown = [(l, s) for l, s in sorted(series.items()) if not (l == "budget" and idx == 0)]
    for i, (label, s) in enumerate(shown):
        dash = ' stroke-dasharray="6 4"' if label == "budget" else ""
        pts = " ".join(f"{X(c):.1f},{Y(v[idx]):.1f}" for c, *v in s)
        out.append(f'<polyline points="{pts}" fill="none" stroke="{colours[label]}" stroke-width="2"{dash}/>')
        name = "budget, 3 × input + 64 MiB" if label == "budget" else label
        out.append(f'<text x="{x0 + M + 8}" y="{M + 16 + 16 * i}" fill="{colours[label]}">{name}</text>')
    return out
body = panel(0, "time", 0, "seconds", 0.001, 1000) + panel(W / 2, "peak memory", 1, "MiB", 1, 100000)
open(svg, "w").write(f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">'
                      f'<rect width="{W}" height="{H}" fill="white"/>' + "".join(body) + "</svg>\n")
EOF
