"""Where the `massprop` binary the wheel installed is.

The wheel (maturin's `bin` bindings) puts the binary in the environment's
scripts directory, beside `pip`; this package lives in its site-packages.
As ruff's `find_ruff_bin`, the search tries the places an installer may
have put the scripts for this package, in order, and takes the first that
holds the binary. Never `PATH`: that could be another version than the one
whose Python package is imported.
"""

from __future__ import annotations

import os
import sys
import sysconfig
from fnmatch import fnmatch


class MassPropNotFound(FileNotFoundError):
    """The `massprop` binary is not where the wheel installs it."""


def find_massprop_bin() -> str:
    """Return the path of the `massprop` binary installed with this package."""
    exe = "massprop" + (sysconfig.get_config_var("EXE") or "")
    here = os.path.dirname(os.path.abspath(__file__))
    if sys.platform == "win32":
        # <prefix>\Lib\site-packages\massprop -> <prefix>\Scripts
        beside_prefix = _join(_strip_suffix(here, "Lib/site-packages/massprop"), "Scripts")
    else:
        # <prefix>/lib/python3.X/site-packages/massprop -> <prefix>/bin
        beside_prefix = _join(_strip_suffix(here, "lib/python*/site-packages/massprop"), "bin")
    candidates = [
        # The running environment's scripts (a virtual environment's bin/).
        sysconfig.get_path("scripts"),
        # The base interpreter's, for a package installed there.
        sysconfig.get_path("scripts", vars={"base": sys.base_prefix}),
        # `pip install --prefix DIR`: the scripts beside this package's prefix.
        beside_prefix,
        # `pip install --target DIR`: DIR/bin beside DIR/massprop.
        _join(_strip_suffix(here, "massprop"), "bin"),
        # `pip install --user`: ~/.local/bin and its kin.
        sysconfig.get_path("scripts", scheme=_user_scheme()),
    ]
    tried: list[str] = []
    for directory in candidates:
        if not directory or directory in tried:
            continue
        tried.append(directory)
        path = os.path.join(directory, exe)
        if os.path.isfile(path):
            return path
    looked = "\n".join(f"  {directory}" for directory in tried)
    raise MassPropNotFound(
        f"the `massprop` binary is not installed beside this package; looked in:\n{looked}\n"
        "reinstall the wheel (`pip install --force-reinstall massprop`)"
    )


def _strip_suffix(path: str, pattern: str) -> str | None:
    """`path` without its last components when they match `pattern`.

    `pattern` uses `/` between components and may hold `*` wildcards; the
    components are compared case-insensitively (Windows' `Lib`).
    """
    parts = path.split(os.sep)
    wanted = pattern.split("/")
    if len(parts) <= len(wanted):
        return None
    tail = parts[-len(wanted) :]
    if not all(fnmatch(part.lower(), want.lower()) for part, want in zip(tail, wanted)):
        return None
    return os.sep.join(parts[: -len(wanted)])


def _join(directory: str | None, name: str) -> str | None:
    return os.path.join(directory, name) if directory else None


def _user_scheme() -> str:
    if sys.version_info >= (3, 10):
        return sysconfig.get_preferred_scheme("user")
    if os.name == "nt":
        return "nt_user"
    if sys.platform == "darwin" and getattr(sys, "_framework", None):
        return "osx_framework_user"
    return "posix_user"
