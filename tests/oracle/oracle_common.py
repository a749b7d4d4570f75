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


def massprop_whole_body(massprop: str, path: str, joints: dict, extra=()):
    """`massprop report PATH --format json --joints …` (and `extra`
    arguments) as (mass, centre of mass [3], inertia about it [3][3]), None
    and its stderr (warnings); or None, why massprop refused (its first line
    of stderr, the status) and its stderr."""
    import json

    spec = ", ".join(f"{k}={num(v)}" for k, v in joints.items())
    cmd = [massprop, "report", path, "--format", "json", *extra]
    if spec:
        cmd += ["--joints", spec]
    out = run(cmd)
    if out.returncode != 0:
        first = out.stderr.strip().splitlines()[0] if out.stderr.strip() else "no message"
        return None, f"{first} (exit {out.returncode})", out.stderr
    d = json.loads(out.stdout)
    return (d["mass"], list(d["center_of_mass"]), [list(r) for r in d["inertia_com"]]), None, out.stderr


def relative_disagreement(a, b) -> float:
    """How far two bodies (mass, centre [3], inertia about it [3][3]) are
    apart, relative: the mass against the mass; the centre against the
    larger of its largest coordinate and the radius of gyration
    sqrt(trace / mass); the inertia against its largest entry (the tensor's
    max norm) — pinocchio_oracle.py's measure."""
    ma, ca, ia = a
    mb, cb, ib = b
    trace = sum(ia[k][k] for k in range(3))
    scale_l = max(max(abs(x) for x in ca), math.sqrt(max(trace, 0.0) / ma) if ma > 0 else 0.0, 1e-300)
    scale_i = max(max(abs(x) for r in ia for x in r), 1e-300)
    return max(
        abs(ma - mb) / max(abs(ma), 1e-300),
        max(abs(x - y) for x, y in zip(ca, cb)) / scale_l,
        max(abs(x - y) for r, s in zip(ia, ib) for x, y in zip(r, s)) / scale_i,
    )
