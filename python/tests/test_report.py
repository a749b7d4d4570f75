"""`massprop.report()` returns the CLI's JSON document, exactly."""

from __future__ import annotations

import json
import math
from decimal import Decimal
from pathlib import Path

import pytest

import massprop
from conftest import PART_FILES, REPO, cli, cli_json


def test_shapes_holds_part_files_to_compare() -> None:
    assert len(PART_FILES) >= 10


@pytest.mark.parametrize("path", PART_FILES, ids=lambda p: p.name)
def test_report_equals_the_cli_json_for_every_file_in_shapes(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    relative = str(path.relative_to(REPO))
    expected = cli_json("report", "--format", "json", relative, cwd=REPO)
    monkeypatch.chdir(REPO)
    assert massprop.report(relative) == expected


def _pairs(value: object, tokens: object):
    """Each float of `value` with the decimal text the CLI printed for it."""
    if isinstance(value, dict):
        assert isinstance(tokens, dict) and value.keys() == tokens.keys()
        for key in value:
            yield from _pairs(value[key], tokens[key])
    elif isinstance(value, list):
        assert isinstance(tokens, list) and len(value) == len(tokens)
        for v, t in zip(value, tokens):
            yield from _pairs(v, t)
    elif isinstance(value, float):
        yield value, tokens


@pytest.mark.parametrize("path", PART_FILES, ids=lambda p: p.name)
def test_every_float_is_the_double_nearest_the_decimal_the_cli_printed(path: Path) -> None:
    # The CLI's text with each real kept as its decimal string: the float
    # report() returns must be the double nearest that decimal (within half
    # an ulp, measured in exact decimal arithmetic, not by float()).
    tokens = json.loads(cli("report", "--format", "json", str(path)).stdout, parse_float=str)
    pairs = list(_pairs(massprop.report(path), tokens))
    assert pairs
    for value, token in pairs:
        assert isinstance(token, str)
        assert abs(Decimal(value) - Decimal(token)) <= Decimal(math.ulp(value)) / 2, token


def test_reals_are_floats_and_the_inertia_tensor_nested_lists() -> None:
    result = massprop.report(REPO / "shapes" / "bent-plate.toml")
    assert type(result["mass"]) is float
    tensor = result["inertia_com"]
    assert type(tensor) is list and len(tensor) == 3
    for row in tensor:
        assert type(row) is list and len(row) == 3
        assert all(type(x) is float for x in row)
    # The keys documented as integers stay integers.
    assert type(result["format_version"]) is int


def test_report_takes_a_path_object_as_a_string() -> None:
    path = REPO / "shapes" / "flywheel.toml"
    assert massprop.report(path) == massprop.report(str(path))


def test_a_path_that_starts_with_a_dash_is_a_path(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    source = (REPO / "shapes" / "flywheel.toml").read_text()
    (tmp_path / "-flywheel.toml").write_text(source)
    monkeypatch.chdir(tmp_path)
    result = massprop.report("-flywheel.toml")
    assert result == cli_json("report", "--format", "json", "--", "-flywheel.toml", cwd=tmp_path)
    assert result["mass"] == massprop.report(REPO / "shapes" / "flywheel.toml")["mass"]
