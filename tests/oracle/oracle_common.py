"""What both oracle scripts share (standard library only: the Drake and the
gz-math oracle run under different interpreters): numbers as the files
write them, a number moved by ulps, and running massprop."""

import math
import subprocess


def num(x: float) -> str:
    """A number as the file writes it: Python's shortest round-trip repr."""
    return repr(float(x))


def nums(xs) -> str:
    return " ".join(num(x) for x in xs)


def ulps(x: float, k: int) -> float:
    """`x` moved by `k` units in the last place (k < 0: downwards)."""
    direction = math.inf if k > 0 else -math.inf
    for _ in range(abs(k)):
        x = math.nextafter(x, direction)
    return x


def run(cmd: list, timeout: float = 600) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
