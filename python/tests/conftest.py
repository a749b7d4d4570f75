"""Shared helpers: the repository's files and the massprop binary run directly.

The tests compare the module with the command it wraps: `cli()` runs the
binary the wheel installed, as a user at a shell would, with its flags
spelled out by hand (never through the module's option table).
"""

from __future__ import annotations

import json
import subprocess
from pathlib import Path
from typing import Any

import pytest

import massprop

REPO = Path(__file__).resolve().parents[2]
SHAPES = REPO / "shapes"
PART_FILES = sorted(SHAPES.glob("*.toml"))


def cli(*args: str, cwd: Path | str | None = None) -> subprocess.CompletedProcess[str]:
    """The installed `massprop` binary with these arguments, its output as text."""
    return subprocess.run(
        [massprop.find_massprop_bin(), "--color", "never", *args],
        capture_output=True,
        text=True,
        cwd=cwd,
        stdin=subprocess.DEVNULL,
    )


def cli_json(*args: str, cwd: Path | str | None = None, statuses: tuple[int, ...] = (0,)) -> Any:
    """The binary's JSON document, parsed by the stdlib; its status one of `statuses`."""
    done = cli(*args, cwd=cwd)
    assert done.returncode in statuses, done.stderr
    return json.loads(done.stdout)


@pytest.fixture
def bad_part(tmp_path: Path) -> Path:
    """A part file whose `mass` on line 3 names nothing: the value's text starts at column 9."""
    path = tmp_path / "bad.toml"
    path.write_text('[[part]]\nshape = "box"\nmass = "abc"\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n')
    return path


@pytest.fixture
def failing_part(tmp_path: Path) -> Path:
    """A valid 2 kg box whose `[expect]` asks for 3 kg ± 1 %: the expectation fails."""
    path = tmp_path / "failing.toml"
    path.write_text(
        '[[part]]\nshape = "box"\nmass = 2.0\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n'
        '\n[expect]\nmass = { value = 3.0, tol = "1%" }\n'
    )
    return path
