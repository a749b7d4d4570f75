# Shared by the bench scripts (sourced, not run): the tools they need.
#
# need COMMAND PACKAGE: install PACKAGE with apt-get (as root) when COMMAND
# is missing.
need() {
    if ! command -v "$1" > /dev/null 2>&1; then
        echo "== installing $2 (for $1)" >&2
        apt-get update -q > /dev/null
        apt-get install -y -q "$2" > /dev/null
    fi
}

# need_bench_tools WHAT: hyperfine and GNU time, installed when missing;
# python3, which generates WHAT, required.
need_bench_tools() {
    need hyperfine hyperfine
    [ -x /usr/bin/time ] || need /usr/bin/time time
    command -v python3 > /dev/null || {
        echo "error: python3 is needed to generate $1" >&2
        exit 2
    }
}

# target_dir DIR: the directory cargo builds the package in DIR into, as
# cargo itself reports it (`cargo metadata`'s target_directory), asked from
# the directory the script runs cargo in, as cargo resolves it:
# CARGO_TARGET_DIR when set (as CI caches often set it), else a
# .cargo/config's build.target-dir, else DIR/target. The release binary is
# "$(target_dir DIR)/release/massprop".
target_dir() {
    cargo metadata --format-version 1 --no-deps --locked --manifest-path "$1/Cargo.toml" |
        python3 -c 'import json, sys; print(json.load(sys.stdin)["target_directory"])'
}
