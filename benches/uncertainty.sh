#!/usr/bin/env bash
# Benchmark (issue 18, item 6): the cost of propagating tolerances.
#
#   bash benches/uncertainty.sh          # 1,000 parts; 100,000 for linear
#   bash benches/uncertainty.sh 2000     # 2,000 parts
#
# Generates (python, deterministic) a part file of N parts, each with one
# to three tolerances (sizes, masses, densities, positions) and a shared
# parameter ± (a sheet thickness half the parts use), and a second file
# of 100 N parts; builds the release binary of the working tree, and
# times with hyperfine (median of 5): a plain report, `--uncertainty
# linear` (target: within 3× the plain report) and `--uncertainty
# montecarlo` of 10,000 samples (target: about a second for 1,000 parts
# on two cores), and linear on the large file.
#
# Issue 28, item 6: then 2,000,000 toleranced copies of a box (a 150-byte
# file: an `array` of step 0, its mass and a size ± each), and a quarter
# of them, with `--uncertainty linear` and `--uncertainty montecarlo
# --samples SAMPLES` (default 20: the cost is samples × copies): time and
# peak RSS (GNU time, one run each; the target: within 64 MiB, and time
# linear in the copies).
# `CASE=copies` runs these alone. Environment: COPIES (default 2000000),
# SAMPLES (default 20), CASE (`all`, default, or `copies`).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/lib.sh"
need_bench_tools "the part files"
n="${1:-1000}"
COPIES="${COPIES:-2000000}"
SAMPLES="${SAMPLES:-20}"
CASE="${CASE:-all}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cargo build --release --quiet --manifest-path "$here/../Cargo.toml"
bin="$(target_dir "$here/..")/release/massprop"

# copies N ARGS…: report N toleranced copies with ARGS; time and peak RSS.
copies() {
    local count="$1"
    shift
    printf '[[part]]\nshape = "box"\nmass = "1 kg ± 0.1 kg"\nsize = ["0.1 m ± 1 mm", 0.2, 0.3]\ncenter = [0, 0, 0]\narray = { count = %d, step = [0, 0, 0] }\n' \
        "$count" > "$tmp/copies.toml"
    /usr/bin/time -f '%e %U %M' -o "$tmp/time" "$bin" report --format json "$tmp/copies.toml" "$@" > "$tmp/out.json"
    read -r wall user rss < "$tmp/time"
    printf '%d copies (%d-byte file), %s: %s s (%s s user), peak RSS %.1f MiB\n' \
        "$count" "$(wc -c < "$tmp/copies.toml")" "$*" "$wall" "$user" "$(awk -v k="$rss" 'BEGIN { print k / 1024 }')"
}
for count in "$((COPIES / 4))" "$COPIES"; do
    copies "$count"
    copies "$count" --uncertainty linear
    copies "$count" --uncertainty montecarlo --samples "$SAMPLES"
done
[ "$CASE" = copies ] && exit 0
python3 - "$tmp" "$n" <<'PY'
import random, sys
out, n = sys.argv[1], int(sys.argv[2])
def write(path, count):
    random.seed(1)
    lines = ['units = { length = "mm", mass = "kg" }', '[params]', 'sheet = "2 mm ± 0.05 mm"']
    for i in range(count):
        x, y, z = (random.uniform(-500, 500) for _ in range(3))
        k = i % 4
        lines.append("[[part]]")
        if k == 0:
            lines += ['shape = "box"', 'density = "2700 kg/m^3 ± 1 %"',
                      f'size = ["{random.uniform(10, 50):.2f} mm ± 0.1 mm", {random.uniform(10, 50):.2f}, "sheet"]',
                      f'center = [{x:.3f}, {y:.3f}, "{z:.3f} mm ± 0.5 mm"]']
        elif k == 1:
            lines += ['shape = "cylinder"', 'density = 7.85e-6',
                      f'radius = "{random.uniform(5, 20):.2f} mm ± 0.05 mm"', 'inner_radius = 3',
                      f'length = {random.uniform(20, 200):.1f}', f'center = [{x:.3f}, {y:.3f}, {z:.3f}]']
        elif k == 2:
            lines += ['shape = "point"', f'mass = "{random.uniform(0.1, 2):.3f} kg ± 0.02 kg"',
                      f'center = ["{x:.3f} mm ± 2 mm", {y:.3f}, {z:.3f}]']
        else:
            lines += ['shape = "box"', 'density = 2.7e-6',
                      f'size = [{random.uniform(50, 100):.1f}, {random.uniform(50, 100):.1f}, "sheet"]',
                      f'center = [{x:.3f}, {y:.3f}, {z:.3f}]']
    open(path, "w").write("\n".join(lines) + "\n")
write(out + "/small.toml", n)
write(out + "/large.toml", 100 * n)
PY
run() {
    hyperfine --runs 5 --warmup 1 --style basic "$bin report --format json $*" 2>&1 | grep -E "Time|Range"
}
echo "== $n parts: plain report"; run "$tmp/small.toml"
echo "== $n parts: --uncertainty linear"; run "$tmp/small.toml --uncertainty linear"
echo "== $n parts: --uncertainty montecarlo (10,000 samples)"; run "$tmp/small.toml --uncertainty montecarlo"
echo "== $((100 * n)) parts: plain report"; run "$tmp/large.toml"
echo "== $((100 * n)) parts: --uncertainty linear"; run "$tmp/large.toml --uncertainty linear"
