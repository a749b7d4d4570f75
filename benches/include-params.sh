#!/usr/bin/env bash
# Benchmark (issue 28, item 6): an include with `params` is parsed once;
# each other set of `params` re-evaluates only the parameters passed and
# those that use them.
#
#   bash benches/include-params.sh          # 100,000 parameters
#   bash benches/include-params.sh 10000    # 10,000
#
# Generates (python) a library part file of N parameters (a chain of
# lengths, each the one before plus 1 mm, and `leg`, which the part's size
# uses), a file including it once, and a file including it 40 times, each
# with another `leg`; then the worst case, 40 includes each passing the
# chain's first parameter, which every other uses. Builds the release
# binary of the working tree and times `report` with hyperfine (median
# of 5). Target: 40 includes well under a second more than one.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/lib.sh"
need_bench_tools "the part files"
n="${1:-100000}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cargo build --release --quiet --manifest-path "$here/../Cargo.toml"
bin="$(target_dir "$here/..")/release/massprop"
python3 - "$tmp" "$n" <<'PY'
import sys
out, n = sys.argv[1], int(sys.argv[2])
lines = ['[params]', 'leg = "10 mm"', 'p0 = "1 mm"']
lines += [f'p{i} = "p{i - 1} + 1 mm"' for i in range(1, n)]
lines += ['[[part]]', 'shape = "box"', 'mass = 1', f'size = ["leg", "p{n - 1}", "1 mm"]', 'center = [0, 0, 0]']
open(out + "/lib.toml", "w").write("\n".join(lines) + "\n")
def includes(count, key):
    return "".join(
        f'[[part]]\ninclude = "lib.toml"\nparams = {{ {key} = "{k + 1} mm" }}\norigin = [{k}, 0, 0]\n'
        for k in range(count))
open(out + "/one.toml", "w").write(includes(1, "leg"))
open(out + "/forty.toml", "w").write(includes(40, "leg"))
open(out + "/forty-chain.toml", "w").write(includes(40, "p0"))
PY
run() {
    hyperfine --runs 5 --warmup 1 --style basic "$bin report --format json $*" 2>&1 | grep -E "Time|Range"
}
echo "== 1 include of $n parameters"; run "$tmp/one.toml"
echo "== 40 includes, each another \`leg\`"; run "$tmp/forty.toml"
echo "== 40 includes, each another \`p0\` (all $n parameters use it)"; run "$tmp/forty-chain.toml"
