"""`massprop.check()` returns the CLI's check document; a failed expectation is a result."""

from __future__ import annotations

from pathlib import Path

import pytest

import massprop
from conftest import PART_FILES, REPO, cli, cli_json


def test_check_equals_the_cli_json_on_shapes(monkeypatch: pytest.MonkeyPatch) -> None:
    expected = cli_json("check", "--format", "json", "shapes", cwd=REPO)
    monkeypatch.chdir(REPO)
    got = massprop.check("shapes")
    assert got == expected
    # Every part file and robot description of shapes/, each passing.
    assert got["summary"]["files"] == len(PART_FILES) + len(
        list((REPO / "shapes" / "robots").iterdir())
    )
    assert all(entry["status"] == "ok" for entry in got["files"])


def test_check_takes_a_list_of_paths_in_order() -> None:
    paths = [REPO / "shapes" / "quickstart.toml", REPO / "shapes" / "bent-plate.toml"]
    got = massprop.check(paths)
    assert [entry["path"] for entry in got["files"]] == [str(p) for p in paths]


def test_a_failed_expectation_is_returned_not_raised(failing_part: Path) -> None:
    done = cli("check", "--format", "json", str(failing_part))
    assert done.returncode == 1
    got = massprop.check(failing_part)
    (entry,) = got["files"]
    assert entry["status"] == "failed"
    (mass,) = entry["checks"]
    # The box's mass is 2.0 kg as written; the expectation asked for 3.0.
    assert (mass["quantity"], mass["measured"], mass["value"], mass["pass"]) == (
        "mass",
        2.0,
        3.0,
        False,
    )
    assert got["summary"] == {"files": 1, "ok": 0, "failed": 1, "invalid": 0}
