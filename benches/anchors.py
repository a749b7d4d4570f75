"""The anchors of issue 33's figures, in Python (benches/issue33.sh runs
them beside massprop, in the same run):

    anchors.py parts FILE      tomllib reads a generated part file
                               (benches/report-100k.sh's shapes: box, plate,
                               rod, point) and Pinocchio composes its parts
                               (pin.Inertia placed by pin.SE3, summed);
    anchors.py tree FILE       tomllib reads an include tree
                               (benches/cost.sh's) and Pinocchio composes
                               each distinct file once, placing it per
                               include;
    anchors.py mesh FILE       trimesh loads an STL and integrates it
                               (mass, centre of mass, inertia).

Prints the total mass (for the caller to compare with massprop's) and the
seconds taken, as `mass SECONDS`. Needs tomllib (Python 3.11), and pin
(Pinocchio) or trimesh in the environment (benches/issue33.sh makes a venv
under /tmp).
"""
import math
import os
import sys
import time
import tomllib

LENGTH = {"m": 1.0, "mm": 1e-3, "cm": 1e-2, "in": 0.0254}
MASS = {"kg": 1.0, "g": 1e-3}


def quat_matrix(q):
    w, x, y, z = q
    n = math.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = w / n, x / n, y / n, z / n
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]


def parts(path):
    import numpy as np
    import pinocchio as pin

    t0 = time.perf_counter()
    with open(path, "rb") as f:
        doc = tomllib.load(f)
    u = doc.get("units", {})
    ls, ms = LENGTH[u.get("length", "m")], MASS[u.get("mass", "kg")]
    total = pin.Inertia.Zero()
    for p in doc["part"]:
        shape = p["shape"]
        if shape == "point":
            m = p["mass"] * ms
            c = np.array(p["center"]) * ls
            total += pin.Inertia(m, c, np.zeros((3, 3)))
            continue
        if "edges" in p or "from" in p:
            if shape == "rod":
                a, b = np.array(p["from"]) * ls, np.array(p["to"]) * ls
                d = b - a
                dims = [float(np.linalg.norm(d))]
                z = d / dims[0]
                x = np.cross(z, [1.0, 0, 0] if abs(z[0]) < 0.9 else [0, 1.0, 0])
                x /= np.linalg.norm(x)
                rot = np.column_stack([x, np.cross(z, x), z])
                center = (a + b) / 2
            else:
                edges = [np.array(e) * ls for e in p["edges"]]
                dims = [float(np.linalg.norm(e)) for e in edges]
                cols = [e / n for e, n in zip(edges, dims)]
                if len(cols) == 2:
                    cols.append(np.cross(cols[0], cols[1]))
                rot = np.column_stack(cols)
                center = np.array(p["corner"]) * ls + sum(edges) / 2
        else:
            if shape == "rod":
                dims = [p["length"] * ls]
            else:
                dims = [x * ls for x in p["size"]]
            rot = np.array(quat_matrix(p["rotation"]["quaternion"]))
            center = np.array(p["center"]) * ls
        if "mass" in p:
            m = p["mass"] * ms
        else:
            key = {"box": "density", "plate": "areal_density", "rod": "linear_density"}[shape]
            scale = {"box": ls**3, "plate": ls**2, "rod": ls}[shape]
            m = p[key] * ms / scale * math.prod(dims)
        if shape == "box":
            a, b, c = dims
            diag = [m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12]
        elif shape == "plate":
            a, b = dims
            diag = [m * b * b / 12, m * a * a / 12, m * (a * a + b * b) / 12]
        else:  # rod along its z
            L = dims[0]
            diag = [m * L * L / 12, m * L * L / 12, 0.0]
        own = pin.Inertia(m, np.zeros(3), np.diag(diag))
        total += pin.SE3(rot, center).act(own)
    return total.mass, time.perf_counter() - t0


def tree(path):
    import numpy as np
    import pinocchio as pin

    t0 = time.perf_counter()
    done = {}

    def body(p):
        if p in done:
            return done[p]
        with open(p, "rb") as f:
            doc = tomllib.load(f)
        total = pin.Inertia.Zero()
        for part in doc["part"]:
            if "include" in part:
                sub = body(os.path.join(os.path.dirname(p), part["include"]))
                total += pin.SE3(np.eye(3), np.array(part.get("origin", [0, 0, 0]), float)).act(sub)
            else:
                total += pin.Inertia(part["mass"], np.array(part["center"], float), np.zeros((3, 3)))
        done[p] = total
        return total

    return body(path).mass, time.perf_counter() - t0


def mesh(path):
    import trimesh

    t0 = time.perf_counter()
    m = trimesh.load(path, force="mesh")
    m.density = 1000.0
    props = m.mass_properties
    return float(props["mass"]), time.perf_counter() - t0


if __name__ == "__main__":
    what, path = sys.argv[1], sys.argv[2]
    mass, secs = {"parts": parts, "tree": tree, "mesh": mesh}[what](path)
    print(f"{mass!r} {secs:.4f}")
