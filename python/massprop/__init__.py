"""massprop from Python: mass properties of composite rigid bodies.

    >>> import massprop
    >>> r = massprop.report("arm.toml", omega="0,0,3000 rpm")
    >>> r["mass"], r["inertia_com"][2][2]

`report(path, **options)` and `check(paths, **options)` run the `massprop`
binary this wheel installed, with `--format json`, and return its JSON
document as Python objects (dicts, lists, floats, ints, strings; the keys
are docs/json.md's and docs/check.md's). Options are keyword arguments
named as the command's flags (`include_root=` for `--include-root`):
`OPTIONS` maps each keyword to its flag. Bad input raises `MassPropError`,
whose message is massprop's diagnostic (`FILE:LINE:COL: error: …`).

Why a subprocess and no native module: docs/python.md.
"""

from __future__ import annotations

import functools
import json
import math
import numbers
import os
import subprocess
from collections.abc import Iterable, Mapping
from typing import Any, Callable, Union, cast

from massprop._find import MassPropNotFound, find_massprop_bin

try:
    from importlib.metadata import PackageNotFoundError, version

    #: The installed wheel's version: Cargo.toml's, the binary's `--version`.
    __version__ = version("massprop")
except PackageNotFoundError:  # imported from a source tree, not installed
    __version__ = "unknown"

__all__ = [
    "OPTIONS",
    "__version__",
    "MassPropError",
    "MassPropNotFound",
    "check",
    "find_massprop_bin",
    "report",
]

StrPath = Union[str, "os.PathLike[str]"]


class MassPropError(Exception):
    """massprop refused the input or the options (exit status 2), or failed.

    `str(error)` is massprop's diagnostic, as standard error shows it:
    `FILE:LINE:COL: error: MESSAGE`, the source line and its carets, and
    any `help:` line. Attributes:

    - `status`: massprop's exit status (2 for bad input or a bad option;
      negative, -N, when signal N ended it);
    - `stderr`: the whole of its standard error;
    - `argv`: the command line that was run;
    - `result`: `check`'s JSON document, when it wrote one (a file that is
      invalid still leaves the other files' results there), else None.
    """

    def __init__(
        self, message: str, status: int, stderr: str, argv: list[str], result: Any = None
    ) -> None:
        super().__init__(message)
        self.status = status
        self.stderr = stderr
        self.argv = argv
        self.result = result


# --- The options: one table, keyword -> (flag, how its value is written, commands) ---
#
# A converter takes the keyword and the value and returns the value's text
# for `--flag=TEXT`, a list of texts (the flag repeated), or True/False for
# a switch (given or not). A new flag of `report` or `check` is one line
# here (and one case in python/tests/test_options.py, which checks that
# every entry has one).

Converter = Callable[[str, Any], Union[str, list[str], bool]]


def _number_text(keyword: str, value: Any) -> str:
    # numbers.Real, not float: numpy's scalars are numbers too (without
    # importing numpy); bool is an int, but never a number here.
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"`{keyword}`: expected a number, got {type(value).__name__}")
    if isinstance(value, numbers.Integral):
        return str(int(value))
    number = float(value)
    if not math.isfinite(number):
        raise ValueError(f"`{keyword}`: expected a finite number, got {number!r}")
    # NOTE: repr is the shortest text that reads back as the same float, so
    # massprop gets exactly the float the script holds.
    return repr(number)


def _text(keyword: str, value: Any) -> str:
    if not isinstance(value, str):
        raise TypeError(f"`{keyword}`: expected a string, got {type(value).__name__}")
    return value


def _number(keyword: str, value: Any) -> str:
    """A number, or its text with a unit (`rtol=1e-9`, `rtol="1e-9"`)."""
    return value if isinstance(value, str) else _number_text(keyword, value)


def _integer(keyword: str, value: Any) -> str:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"`{keyword}`: expected an integer, got {type(value).__name__}")
    return str(int(value))


def _vector(keyword: str, value: Any) -> str:
    """`"0,0,3000 rpm"` as the flag takes it, or three numbers (SI or the file's length unit)."""
    if isinstance(value, str):
        return value
    if isinstance(value, Iterable) and not isinstance(value, (bytes, Mapping)):
        return ",".join(_number_text(keyword, x) for x in value)
    raise TypeError(
        f'`{keyword}`: expected three numbers or a string such as "0,0,3000 rpm", '
        f"got {type(value).__name__}"
    )


def _path(keyword: str, value: Any) -> str:
    if not isinstance(value, (str, os.PathLike)):
        raise TypeError(f"`{keyword}`: expected a path, got {type(value).__name__}")
    return os.fsdecode(value)


def _repeated(one: Converter) -> Converter:
    """The flag once per item: one value, or a list of them."""

    def convert(keyword: str, value: Any) -> list[str]:
        if isinstance(value, (str, os.PathLike)):
            value = [value]
        if not isinstance(value, Iterable) or isinstance(value, (bytes, Mapping)):
            raise TypeError(
                f"`{keyword}`: expected one value or a list of them, got {type(value).__name__}"
            )
        return [one(keyword, item) for item in value]  # type: ignore[misc]

    return convert


def _params(keyword: str, value: Any) -> list[str]:
    """`set={"leg": "750 mm", "n": 24}`: `--set leg=750 mm --set n=24`."""
    if not isinstance(value, Mapping):
        raise TypeError(
            f"`{keyword}`: expected a mapping of parameter names to values, "
            f"got {type(value).__name__}"
        )
    items = []
    for name, item in value.items():
        if not isinstance(name, str):
            raise TypeError(f"`{keyword}`: parameter names are strings, got {name!r}")
        items.append(f"{name}={_number(f'{keyword}[{name!r}]', item)}")
    return items


def _switch(keyword: str, value: Any) -> bool:
    if not isinstance(value, bool):
        raise TypeError(f"`{keyword}`: expected True or False, got {type(value).__name__}")
    return value


REPORT, CHECK = "report", "check"
BOTH = (REPORT, CHECK)

#: keyword -> (flag, converter, the commands that take it)
OPTIONS: dict[str, tuple[str, Converter, tuple[str, ...]]] = {
    "about": ("--about", _vector, (REPORT,)),
    "alpha": ("--alpha", _vector, (REPORT,)),
    "axes": ("--axes", _text, BOTH),
    "base_dir": ("--base-dir", _path, BOTH),
    "bless": ("--bless", _switch, (CHECK,)),
    "case": ("--case", _text, (REPORT,)),
    "cases": ("--cases", _switch, (REPORT,)),
    "engine": ("--engine", _repeated(_text), (CHECK,)),
    "exclude": ("--exclude", _repeated(_text), (CHECK,)),
    "hidden": ("--hidden", _switch, (CHECK,)),
    "include_root": ("--include-root", _repeated(_path), BOTH),
    "joints": ("--joints", _text, (REPORT,)),
    "omega": ("--omega", _vector, (REPORT,)),
    "only": ("--only", _text, (REPORT,)),
    "package": ("--package", _repeated(_text), BOTH),
    "precision": ("--precision", _text, BOTH),
    "products": ("--products", _text, (REPORT,)),
    "rtol": ("--rtol", _number, BOTH),
    "samples": ("--samples", _integer, (REPORT,)),
    "seed": ("--seed", _integer, (REPORT,)),
    "set": ("--set", _params, BOTH),
    "sweep": ("--sweep", _repeated(_text), (REPORT,)),
    "uncertainty": ("--uncertainty", _text, (REPORT,)),
    "velocity": ("--velocity", _vector, (REPORT,)),
}


def _flags(command: str, options: Mapping[str, Any]) -> list[str]:
    argv: list[str] = []
    for keyword, value in options.items():
        entry = OPTIONS.get(keyword)
        if entry is None or command not in entry[2]:
            hint = ""
            if entry is not None:
                hint = f" (`{entry[0]}` is an option of `massprop {entry[2][0]}` only)"
            raise TypeError(f"{command}() got an unexpected keyword argument {keyword!r}{hint}")
        if value is None:
            # None is "not given", as the keyword left out.
            continue
        flag, convert, _ = entry
        text = convert(keyword, value)
        if text is True:
            argv.append(flag)
        elif text is False:
            pass
        elif isinstance(text, list):
            # NOTE: `--flag=VALUE` in one word, so a value that starts with
            # `-` (`omega="-1,0,0"`) is never taken for a flag.
            argv.extend(f"{flag}={item}" for item in text)
        else:
            argv.append(f"{flag}={text}")
    return argv


# NOTE: the search asks sysconfig for five directories, about a millisecond:
# done once per process (a failed search is not cached, and raises each time).
_binary = functools.lru_cache(maxsize=None)(find_massprop_bin)


def _run(
    command: str, paths: list[str], options: Mapping[str, Any], ok: tuple[int, ...]
) -> dict[str, Any]:
    argv = [_binary(), "--color=never", command, "--format=json"]
    # `--` ends the options: a path that starts with `-` is a path.
    argv += [*_flags(command, options), "--", *paths]
    done = subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True)
    stderr = done.stderr.decode("utf-8", errors="replace")
    result = None
    if done.stdout.strip():
        # NOTE: Python's json reads each number as the float nearest its
        # decimal text, and massprop writes the shortest text that reads
        # back as its f64: the floats here are exactly massprop's.
        try:
            result = json.loads(done.stdout.decode("utf-8"))
        except ValueError:
            result = None
    if done.returncode in ok and isinstance(result, dict):
        return cast("dict[str, Any]", result)
    message = stderr.rstrip("\n")
    if not message:
        if done.returncode in ok:
            message = f"massprop {command} printed no JSON document (exit status {done.returncode})"
        else:
            message = f"massprop {command} ended with exit status {done.returncode} and no message"
    raise MassPropError(message, done.returncode, stderr, argv, result)


def report(path: StrPath, **options: Any) -> dict[str, Any]:
    """`massprop report PATH --format json`, as a dict (keys: docs/json.md).

    Options are the flags' (`omega="0,0,3000 rpm"`, `about=(0, 0, 0.01)`,
    `axes="axis=0,0,1;degrees=90"`, `precision="extended"`,
    `set={"leg": "750 mm"}`, `uncertainty="linear"`, …): `OPTIONS` lists
    them. Raises `MassPropError` (status 2) when massprop refuses the file
    or an option, TypeError for an unknown keyword or a value of the wrong
    type.
    """
    return _run(REPORT, [_path("path", path)], options, ok=(0,))


def check(paths: StrPath | Iterable[StrPath], **options: Any) -> dict[str, Any]:
    """`massprop check PATHS… --format json`, as a dict (keys: docs/check.md).

    `paths` is one path or a list of them (part files, robot descriptions,
    directories). A failed expectation or validity check is a result, not
    an error: the file's `status` is `"failed"` and `summary["failed"]`
    counts it (the command's exit status 1). A file that cannot be read or
    is invalid, or a bad option, raises `MassPropError` (status 2), whose
    `result` still holds the JSON document when massprop wrote one.
    """
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    return _run(CHECK, [_path("paths", p) for p in paths], options, ok=(0, 1))
