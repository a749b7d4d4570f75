"""The wheel's `massprop` command, `python -m massprop`, and the version they carry."""

from __future__ import annotations

import os
import subprocess
import sys
import sysconfig
from importlib.metadata import version
from pathlib import Path

import pytest

import massprop
from conftest import REPO, cli


def test_the_module_is_the_installed_package_not_the_source_tree() -> None:
    installed = Path(massprop.__file__).resolve()
    assert REPO / "python" not in installed.parents, installed


def test_the_massprop_command_is_in_the_environments_scripts() -> None:
    command = Path(sysconfig.get_path("scripts")) / (
        "massprop" + (sysconfig.get_config_var("EXE") or "")
    )
    assert command.is_file() and os.access(command, os.X_OK)
    assert Path(massprop.find_massprop_bin()) == command


def test_the_command_prints_the_version_of_the_installed_wheel() -> None:
    done = subprocess.run(
        [massprop.find_massprop_bin(), "--version"], capture_output=True, text=True
    )
    assert done.returncode == 0
    assert done.stdout.strip() == f"massprop {version('massprop')}"
    assert massprop.__version__ == version("massprop")


def test_the_wheels_version_is_cargo_tomls() -> None:
    tomllib = pytest.importorskip(
        "tomllib", reason="tomllib is Python 3.11's; older ones cannot read Cargo.toml here"
    )
    with open(REPO / "Cargo.toml", "rb") as file:
        cargo = tomllib.load(file)
    assert version("massprop") == cargo["package"]["version"]


def test_the_command_reports_a_part_file(tmp_path: Path) -> None:
    done = subprocess.run(
        [massprop.find_massprop_bin(), "report", str(REPO / "shapes" / "quickstart.toml")],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    assert "mass" in done.stdout


def test_python_dash_m_massprop_is_the_command(bad_part: Path) -> None:
    for args in (
        ["report", "--format", "json", str(REPO / "shapes" / "flywheel.toml")],
        ["report", str(bad_part)],
    ):
        module = subprocess.run(
            [sys.executable, "-m", "massprop", "--color", "never", *args],
            capture_output=True,
            text=True,
        )
        binary = cli(*args)
        assert (module.returncode, module.stdout, module.stderr) == (
            binary.returncode,
            binary.stdout,
            binary.stderr,
        )
    assert binary.returncode == 2
