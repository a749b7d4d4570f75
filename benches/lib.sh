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
