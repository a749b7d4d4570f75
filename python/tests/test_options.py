"""Each keyword of `report()` and `check()` is its command's flag.

Each case runs the module with a keyword and the binary with the flag
spelled by hand, and compares the two JSON documents; a keyword mapped to
the wrong flag, or its value written wrongly, makes them differ (or makes
the binary refuse the flag: exit status 2).
"""

from __future__ import annotations

import re
import shutil
from fractions import Fraction
from pathlib import Path
from typing import Any, NamedTuple

import pytest

import massprop
from conftest import REPO, cli, cli_json


class Case(NamedTuple):
    command: str
    options: dict[str, Any]
    flags: list[str]
    paths: list[str]


CASES = {
    "omega as text": Case(
        "report", {"omega": "0,0,3000 rpm"}, ["--omega", "0,0,3000 rpm"], ["shapes/flywheel.toml"]
    ),
    "omega as numbers": Case(
        "report",
        {"omega": (0.5, -2, 314.159)},
        ["--omega", "0.5,-2,314.159"],
        ["shapes/bent-plate.toml"],
    ),
    "alpha": Case(
        "report",
        {"omega": "0,0,1", "alpha": "0,0,90 deg/s^2"},
        ["--omega", "0,0,1", "--alpha", "0,0,90 deg/s^2"],
        ["shapes/flywheel.toml"],
    ),
    "about as text": Case(
        "report", {"about": "0,0,10 mm"}, ["--about", "0,0,10 mm"], ["shapes/quickstart.toml"]
    ),
    "about as numbers": Case(
        "report", {"about": [0, 0, 1e-05]}, ["--about", "0,0,0.00001"], ["shapes/flywheel.toml"]
    ),
    "axes": Case(
        "report",
        {"axes": "axis=0,0,1;degrees=90"},
        ["--axes", "axis=0,0,1;degrees=90"],
        ["shapes/bent-plate.toml"],
    ),
    "precision": Case(
        "report", {"precision": "extended"}, ["--precision", "extended"], ["shapes/bent-plate.toml"]
    ),
    "rtol": Case("report", {"rtol": 1e-9}, ["--rtol", "1e-9"], ["shapes/bent-plate.toml"]),
    "products": Case(
        "report", {"products": "positive"}, ["--products", "positive"], ["shapes/bent-plate.toml"]
    ),
    "only": Case("report", {"only": "elbow"}, ["--only", "elbow"], ["shapes/robot-arm.toml"]),
    "set a quantity": Case(
        "report",
        {"set": {"head_mass": "1.5 kg"}},
        ["--set", "head_mass=1.5 kg"],
        ["shapes/quickstart.toml"],
    ),
    "set a number and an expression": Case(
        "report",
        {"set": {"spokes": 28, "tyre_section": "2 * 14 mm"}},
        ["--set", "spokes=28", "--set", "tyre_section=2 * 14 mm"],
        ["shapes/bicycle-wheel.toml"],
    ),
    "uncertainty": Case(
        "report", {"uncertainty": "linear"}, ["--uncertainty", "linear"], ["shapes/smallsat.toml"]
    ),
    "joints": Case(
        "report", {"joints": "elbow=30deg"}, ["--joints", "elbow=30deg"], ["shapes/robots/arm.urdf"]
    ),
    "package": Case(
        "report",
        {"package": ["arm=tests/robots/sdf_include/models/arm"]},
        ["--package", "arm=tests/robots/sdf_include/models/arm"],
        ["tests/robots/sdf_include/models/robot/model.sdf"],
    ),
    "sweep": Case(
        "report",
        {"sweep": ["elbow=0deg..90deg:3"]},
        ["--sweep", "elbow=0deg..90deg:3"],
        ["shapes/robots/arm.urdf"],
    ),
    "velocity": Case(
        "report",
        {"omega": "0,0,1", "velocity": "0,0,3 m/s"},
        ["--omega", "0,0,1", "--velocity", "0,0,3 m/s"],
        ["shapes/bent-plate.toml"],
    ),
    "case": Case("report", {"case": "driver"}, ["--case", "driver"], ["shapes/car.toml"]),
    "cases": Case("report", {"cases": True}, ["--cases"], ["shapes/car.toml"]),
    "samples and seed": Case(
        "report",
        {"uncertainty": "montecarlo", "samples": 300, "seed": 7},
        ["--uncertainty", "montecarlo", "--samples", "300", "--seed", "7"],
        ["shapes/cubesat-6u.toml"],
    ),
    "base_dir": Case(
        "report", {"base_dir": "shapes"}, ["--base-dir", "shapes"], ["shapes/robot-arm.toml"]
    ),
    "check precision": Case(
        "check", {"precision": "standard"}, ["--precision", "standard"], ["shapes"]
    ),
    "check rtol": Case("check", {"rtol": "1e-10"}, ["--rtol", "1e-10"], ["shapes"]),
    "check axes": Case(
        "check",
        {"axes": "x=0,1,0;y=-1,0,0"},
        ["--axes", "x=0,1,0;y=-1,0,0"],
        ["shapes/bent-plate.toml"],
    ),
    "check set": Case(
        "check",
        {"set": {"head_mass": "1.2 kg"}},
        ["--set", "head_mass=1.2 kg"],
        ["shapes/quickstart.toml"],
    ),
    "check engine": Case("check", {"engine": "mujoco"}, ["--engine", "mujoco"], ["shapes/robots"]),
    "check engines": Case(
        "check",
        {"engine": ["drake", "gazebo"]},
        ["--engine", "drake", "--engine", "gazebo"],
        ["shapes/robots"],
    ),
    "check exclude": Case(
        "check",
        {"exclude": ["robots/", "mesh*.toml"]},
        ["--exclude", "robots/", "--exclude", "mesh*.toml"],
        ["shapes"],
    ),
    "check several paths": Case(
        "check", {}, [], ["shapes/flywheel.toml", "shapes/robots/arm.urdf"]
    ),
}

# Covered by the tests below them, with files of their own.
OWN_TESTS = {"hidden", "bless", "include_root"}


@pytest.mark.parametrize("case", CASES.values(), ids=CASES.keys())
def test_the_keyword_gives_what_the_flag_gives(case: Case, monkeypatch: pytest.MonkeyPatch) -> None:
    # `check` exits 1 for a failed expectation (`--axes` turns them): a result.
    statuses = (0,) if case.command == "report" else (0, 1)
    expected = cli_json(
        case.command, "--format", "json", *case.flags, *case.paths, cwd=REPO, statuses=statuses
    )
    monkeypatch.chdir(REPO)
    if case.command == "report":
        got = massprop.report(case.paths[0], **case.options)
    else:
        got = massprop.check(case.paths, **case.options)
    assert got == expected


def test_the_option_changes_the_result_in_the_cases_that_show_it(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # A keyword silently dropped would still compare equal to a flag that
    # changes nothing: these cases' flags change the document.
    monkeypatch.chdir(REPO)
    for name in (
        "omega as numbers",
        "axes",
        "products",
        "only",
        "case",
        "cases",
        "set a quantity",
        "uncertainty",
        "check exclude",
    ):
        case = CASES[name]
        run = massprop.report if case.command == "report" else massprop.check
        target = case.paths[0] if case.command == "report" else case.paths
        assert run(target, **case.options) != run(target), name


def test_every_keyword_in_the_table_has_a_case() -> None:
    covered = {keyword for case in CASES.values() for keyword in case.options} | OWN_TESTS
    assert covered == set(massprop.OPTIONS)


# The flags the module sets itself, or that change only the table or where
# the output goes: no keyword on purpose (docs/python.md says why).
NOT_KEYWORDS = {
    "--color",
    "--format",
    "--output",
    "--width",
    "--full",
    "--quiet",
    "--verbose",
    "--help",
}


@pytest.mark.parametrize("command", ["report", "check"])
def test_every_flag_of_the_command_is_a_keyword_or_left_out_on_purpose(command: str) -> None:
    help_text = cli(command, "--help").stdout
    flags = set(re.findall(r"^\s+(?:-\w, )?(--[a-z][a-z-]*)", help_text, re.MULTILINE))
    assert "--omega" in flags or "--engine" in flags
    mapped = {flag for flag, _, commands in massprop.OPTIONS.values() if command in commands}
    assert flags - NOT_KEYWORDS == mapped


def test_hidden_searches_hidden_directories(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / ".hidden").mkdir()
    shutil.copy(REPO / "shapes" / "flywheel.toml", tmp_path / ".hidden" / "flywheel.toml")
    shutil.copy(REPO / "shapes" / "bent-plate.toml", tmp_path / "bent-plate.toml")
    monkeypatch.chdir(tmp_path)
    expected = cli_json("check", "--format", "json", "--hidden", ".", cwd=tmp_path)
    assert massprop.check(".", hidden=True) == expected
    assert expected["summary"]["files"] == 2
    assert massprop.check(".", hidden=False) == cli_json(
        "check", "--format", "json", ".", cwd=tmp_path
    )


def test_bless_writes_the_expectations_as_the_flag_does(
    tmp_path: Path, failing_part: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    for name in ("module", "cli"):
        (tmp_path / name).mkdir()
        shutil.copy(failing_part, tmp_path / name / "part.toml")
    monkeypatch.chdir(tmp_path / "module")
    got = massprop.check("part.toml", bless=True)
    expected = cli_json("check", "--format", "json", "--bless", "part.toml", cwd=tmp_path / "cli")
    assert got == expected
    assert got["summary"]["ok"] == 1
    blessed = (tmp_path / "module" / "part.toml").read_text()
    assert blessed == (tmp_path / "cli" / "part.toml").read_text()
    assert blessed != failing_part.read_text()


def test_include_root_allows_an_include_from_another_tree(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "lib").mkdir()
    (tmp_path / "top").mkdir()
    shutil.copy(REPO / "shapes" / "motor-bracket.toml", tmp_path / "lib" / "bracket.toml")
    (tmp_path / "top" / "main.toml").write_text(
        '[[part]]\nname = "bracket"\ninclude = "../lib/bracket.toml"\n'
    )
    monkeypatch.chdir(tmp_path / "top")
    with pytest.raises(massprop.MassPropError) as refused:
        massprop.report("main.toml")
    assert refused.value.status == 2
    expected = cli_json(
        "report", "--format", "json", "--include-root", "../lib", "main.toml", cwd=tmp_path / "top"
    )
    assert massprop.report("main.toml", include_root="../lib") == expected
    assert massprop.report("main.toml", include_root=[Path("../lib")]) == expected
    expected = cli_json(
        "check", "--format", "json", "--include-root", "../lib", "main.toml", cwd=tmp_path / "top"
    )
    assert massprop.check("main.toml", include_root=["../lib"]) == expected


def test_package_reaches_a_robot_a_part_file_includes(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # tests/robots/sdf_package/carrier.sdf's `model://gripper` is found
    # only through `--package`: `check` of a part file including it needs
    # the keyword as `report` does.
    robot_dir = REPO / "tests" / "robots" / "sdf_package"
    (tmp_path / "cart.toml").write_text(
        f'[[part]]\ninclude = "{(robot_dir / "carrier.sdf").as_posix()}"\norigin = [0, 0, 1]\n'
    )
    monkeypatch.chdir(tmp_path)
    package = f"gripper={(robot_dir / 'vendor' / 'gripper').as_posix()}"
    with pytest.raises(massprop.MassPropError) as refused:
        massprop.check("cart.toml", include_root=robot_dir)
    assert refused.value.status == 2
    assert "--package gripper=DIR" in str(refused.value)
    for command, run in (("report", massprop.report), ("check", massprop.check)):
        expected = cli_json(
            command,
            "--format",
            "json",
            "--include-root",
            str(robot_dir),
            "--package",
            package,
            "cart.toml",
            cwd=tmp_path,
        )
        assert run("cart.toml", include_root=robot_dir, package=package) == expected


def test_none_is_an_option_left_out(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(REPO)
    assert massprop.report("shapes/flywheel.toml", omega=None, set=None) == massprop.report(
        "shapes/flywheel.toml"
    )


def test_numbers_other_than_float_and_int_are_written_as_their_value(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # Any numbers.Real (numpy's scalars among them): a Fraction here.
    monkeypatch.chdir(REPO)
    expected = cli_json(
        "report", "--format", "json", "--omega", "0.5,0,3", "shapes/flywheel.toml", cwd=REPO
    )
    assert massprop.report("shapes/flywheel.toml", omega=(Fraction(1, 2), 0, 3)) == expected
