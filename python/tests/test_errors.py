"""Bad input raises `MassPropError` with massprop's diagnostic; a bad keyword, TypeError."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import massprop
from conftest import REPO, cli


def test_bad_input_raises_with_the_file_line_column_message_and_status_2(bad_part: Path) -> None:
    with pytest.raises(massprop.MassPropError) as raised:
        massprop.report(bad_part)
    # bad.toml's line 3 is `mass = "abc"`: the name starts at column 9.
    assert str(raised.value).startswith(f"{bad_part}:3:9: error: `mass`")
    assert raised.value.status == 2


def test_the_message_is_the_diagnostic_the_command_prints(bad_part: Path) -> None:
    done = cli("report", "--format", "json", str(bad_part))
    assert done.returncode == 2 and done.stdout == ""
    with pytest.raises(massprop.MassPropError) as raised:
        massprop.report(bad_part)
    assert str(raised.value) == done.stderr.rstrip("\n")
    assert raised.value.stderr == done.stderr
    assert raised.value.result is None


def test_an_unreadable_file_raises_with_status_2(tmp_path: Path) -> None:
    with pytest.raises(massprop.MassPropError) as raised:
        massprop.report(tmp_path / "missing.toml")
    assert raised.value.status == 2
    assert str(raised.value).startswith(f"{tmp_path / 'missing.toml'}: error: cannot read file")


def test_a_bad_option_value_raises_naming_the_flag() -> None:
    with pytest.raises(massprop.MassPropError) as raised:
        massprop.report(REPO / "shapes" / "flywheel.toml", omega=(1.0, 2.0))
    assert raised.value.status == 2
    assert "`--omega`" in str(raised.value)


def test_check_raises_for_an_invalid_file_and_keeps_the_other_files_results(bad_part: Path) -> None:
    flywheel = REPO / "shapes" / "flywheel.toml"
    with pytest.raises(massprop.MassPropError) as raised:
        massprop.check([bad_part, flywheel])
    error = raised.value
    assert error.status == 2
    assert str(error).startswith(f"{bad_part}:3:9: error:")
    statuses = {entry["path"]: entry["status"] for entry in error.result["files"]}
    assert statuses == {str(bad_part): "invalid", str(flywheel): "ok"}
    assert error.result["files"][0]["error"]["line"] == 3


def test_check_of_a_path_that_does_not_exist_raises(tmp_path: Path) -> None:
    with pytest.raises(massprop.MassPropError) as raised:
        massprop.check(tmp_path / "nowhere")
    assert raised.value.status == 2


def test_an_unknown_keyword_raises_type_error_naming_it() -> None:
    with pytest.raises(TypeError, match=r"^report\(\) got an unexpected keyword argument 'omgea'$"):
        massprop.report(REPO / "shapes" / "flywheel.toml", omgea="0,0,1")
    with pytest.raises(TypeError, match=r"^check\(\) got an unexpected keyword argument 'format'$"):
        massprop.check(REPO / "shapes", format="table")


def test_a_keyword_of_the_other_command_raises_type_error_saying_whose_it_is() -> None:
    with pytest.raises(
        TypeError, match=r"'omega' \(`--omega` is an option of `massprop report` only\)"
    ):
        massprop.check(REPO / "shapes", omega="0,0,1")
    with pytest.raises(
        TypeError, match=r"'hidden' \(`--hidden` is an option of `massprop check` only\)"
    ):
        massprop.report(REPO / "shapes" / "flywheel.toml", hidden=True)


@pytest.mark.parametrize(
    "options",
    [{"hidden": "yes"}, {"engine": 3}, {"set": ["leg=1"]}, {"set": {1: 2}}, {"rtol": True}],
    ids=["switch", "repeated", "set-not-a-mapping", "set-name", "bool-as-number"],
)
def test_a_value_of_the_wrong_type_raises_type_error_naming_the_keyword(options: dict) -> None:
    keyword = next(iter(options))
    with pytest.raises(TypeError, match=f"`{keyword}"):
        massprop.check(REPO / "shapes", **options)


@pytest.mark.parametrize("keyword", ["samples", "seed"])
def test_an_integer_option_refuses_a_float(keyword: str) -> None:
    with pytest.raises(TypeError, match=f"`{keyword}`: expected an integer"):
        massprop.report(
            REPO / "shapes" / "smallsat.toml", uncertainty="montecarlo", **{keyword: 10.0}
        )


def test_a_non_finite_number_raises_value_error() -> None:
    with pytest.raises(ValueError, match="`omega`: expected a finite number"):
        massprop.report(REPO / "shapes" / "flywheel.toml", omega=(0.0, 0.0, math.inf))
