#!/usr/bin/env bash
# The Python wheel, as a user gets it: builds it with maturin (release),
# installs it into a FRESH virtual environment (not this checkout: the
# tests check they import the installed package), and runs python/tests
# there with pytest. Run by .ci/run; alone: `bash python/ci.sh`.
# Needs python3 with venv and pip, and PyPI (maturin, pytest); cargo builds
# into CARGO_TARGET_DIR when it is set, as everywhere else.
set -euo pipefail
cd "$(dirname "$0")/.."
repo="$PWD"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
pip_install() { "$1/bin/pip" install --quiet --disable-pip-version-check "${@:2}"; }

echo "-- maturin, in a virtual environment of its own"
python3 -m venv "$work/build-env"
pip_install "$work/build-env" 'maturin>=1.9,<2'
"$work/build-env/bin/maturin" --version

echo "-- the wheel (maturin build --release)"
"$work/build-env/bin/maturin" build --release --locked --out "$work/wheels"
wheel="$(ls "$work"/wheels/massprop-*.whl)"
echo "built $(basename "$wheel")"

echo "-- installed into a fresh virtual environment, with pytest"
python3 -m venv "$work/test-env"
pip_install "$work/test-env" pytest "$wheel"

echo "-- python/tests"
# From outside the checkout, so that `import massprop` can only find the
# installed package; PYTHONDONTWRITEBYTECODE keeps python/tests clean.
cd "$work"
PYTHONDONTWRITEBYTECODE=1 "$work/test-env/bin/python" -m pytest -p no:cacheprovider -q "$repo/python/tests"
