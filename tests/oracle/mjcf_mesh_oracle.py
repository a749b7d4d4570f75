"""MJCF mesh geoms weighed for inertia (`inertiafromgeom`) against MuJoCo's
own compiler (issue 34 item 1, mesh geoms).

Random MJCF bodies without `<inertial>`, each with one to three mesh geoms
(and sometimes a primitive): closed meshes that are convex (boxes, prisms
of convex polygons) or not (extruded polyominoes: L, T, U, S shapes),
written as OBJ or binary STL under `<compiler meshdir>`, with a random
`scale` (mirroring ones too), `pos`, `quat`/`euler`, `mass`/`density`,
and `<mesh inertia>` absent (MuJoCo's `legacy` default), `exact`,
`convex` or `shell`. For each: MuJoCo's body_mass, body_ipos and
body_inertia against `massprop report --format json` of the file, and of a
part file that includes it. Coordinates and scales are dyadic (exact in
f32, as MuJoCo stores vertices), so both read the same numbers.

MuJoCo's default `legacy` weighing over-counts a mesh that is not
star-shaped about its centroid (an S or U polyomino): massprop copies it,
and the oracle compares. Where massprop refuses (`convex` on a mesh that is
not convex: the hull is not computed), the refusal must be right: MuJoCo's
answer for the mesh as written must then differ from its `inertia="exact"`
answer.

Usage: python mjcf_mesh_oracle.py --massprop BIN [--cases N]. Exit 1 on
any disagreement beyond 1e-9 relative.
"""

import argparse
import json
import math
import os
import random
import struct
import subprocess
import sys
import tempfile

import mujoco
import numpy as np

RTOL = 1e-9
GRID = 0.125


def box_mesh(rng):
    lo = [rng.randint(-8, 8) * GRID for _ in range(3)]
    hi = [a + rng.randint(1, 12) * GRID for a in lo]
    return prism([(lo[0], lo[1]), (hi[0], lo[1]), (hi[0], hi[1]), (lo[0], hi[1])], lo[2], hi[2])


def convex_prism(rng):
    n = rng.randint(3, 8)
    r = rng.randint(4, 16) * GRID
    c = [rng.randint(-8, 8) * GRID for _ in range(2)]
    start = rng.uniform(0, 2 * math.pi)
    # Corners rounded to the grid's 1/64: a polygon of at most eight
    # corners this large stays convex.
    poly = []
    for k in range(n):
        a = start + 2 * math.pi * k / n
        poly.append((c[0] + round(r * math.cos(a) * 64) / 64, c[1] + round(r * math.sin(a) * 64) / 64))
    z0 = rng.randint(-8, 8) * GRID
    return prism(poly, z0, z0 + rng.randint(2, 12) * GRID)


def prism(poly, z0, z1):
    """A convex polygon (counter-clockwise) extruded from z0 to z1."""
    tris = []
    n = len(poly)
    for k in range(1, n - 1):
        a, b, c = poly[0], poly[k], poly[k + 1]
        tris.append(((a[0], a[1], z1), (b[0], b[1], z1), (c[0], c[1], z1)))
        tris.append(((a[0], a[1], z0), (c[0], c[1], z0), (b[0], b[1], z0)))
    for k in range(n):
        a, b = poly[k], poly[(k + 1) % n]
        tris.append(((a[0], a[1], z0), (b[0], b[1], z0), (b[0], b[1], z1)))
        tris.append(((a[0], a[1], z0), (b[0], b[1], z1), (a[0], a[1], z1)))
    return tris


def polyomino(rng):
    """Unit squares grown by their edges, with no two touching only at a
    corner (the extruded solid is then a manifold), extruded."""
    while True:
        cells = {(0, 0)}
        for _ in range(rng.randint(2, 6)):
            x, y = rng.choice(sorted(cells))
            dx, dy = rng.choice([(1, 0), (-1, 0), (0, 1), (0, -1)])
            cells.add((x + dx, y + dy))
        bad = False
        for (x, y) in cells:
            for dx, dy in ((1, 1), (1, -1)):
                if (x + dx, y + dy) in cells and (x + dx, y) not in cells and (x, y + dy) not in cells:
                    bad = True
        if not bad and len(cells) > 2:
            break
    s = rng.randint(2, 6) * GRID
    h = rng.randint(1, 8) * GRID
    off = [rng.randint(-8, 8) * GRID for _ in range(3)]
    tris = []

    def quad(a, b, c, d):
        tris.append((a, b, c))
        tris.append((a, c, d))

    def P(x, y, z):
        return (off[0] + x * s, off[1] + y * s, off[2] + z * h)

    for (x, y) in cells:
        quad(P(x, y, 1), P(x + 1, y, 1), P(x + 1, y + 1, 1), P(x, y + 1, 1))
        quad(P(x, y, 0), P(x, y + 1, 0), P(x + 1, y + 1, 0), P(x + 1, y, 0))
        if (x + 1, y) not in cells:
            quad(P(x + 1, y, 0), P(x + 1, y + 1, 0), P(x + 1, y + 1, 1), P(x + 1, y, 1))
        if (x - 1, y) not in cells:
            quad(P(x, y, 0), P(x, y, 1), P(x, y + 1, 1), P(x, y + 1, 0))
        if (x, y + 1) not in cells:
            quad(P(x, y + 1, 0), P(x, y + 1, 1), P(x + 1, y + 1, 1), P(x + 1, y + 1, 0))
        if (x, y - 1) not in cells:
            quad(P(x, y, 0), P(x + 1, y, 0), P(x + 1, y, 1), P(x, y, 1))
    return tris


def write_obj(path, tris):
    index, verts, faces = {}, [], []
    for t in tris:
        f = []
        for v in t:
            if v not in index:
                index[v] = len(verts) + 1
                verts.append(v)
            f.append(index[v])
        faces.append(f)
    with open(path, "w") as out:
        for v in verts:
            out.write("v %r %r %r\n" % v)
        for f in faces:
            out.write("f %d %d %d\n" % tuple(f))


def write_stl(path, tris):
    with open(path, "wb") as out:
        out.write(b"\0" * 80 + struct.pack("<I", len(tris)))
        for t in tris:
            out.write(struct.pack("<3f", 0, 0, 0))
            for v in t:
                out.write(struct.pack("<3f", *v))
            out.write(b"\0\0")


def nums(rng, n, lo, hi):
    return " ".join(repr(rng.uniform(lo, hi)) for _ in range(n))


def case(rng, k, tmp):
    """A model's text and its mesh files written under tmp/meshes; and the
    same model with every solid mesh weighed `exact`."""
    assets, exact, geoms = [], [], []
    for i in range(rng.randint(1, 3)):
        kind = rng.random()
        tris = box_mesh(rng) if kind < 0.25 else convex_prism(rng) if kind < 0.5 else polyomino(rng)
        ext = rng.choice(["obj", "stl"])
        name = f"c{k}m{i}.{ext}"
        (write_obj if ext == "obj" else write_stl)(os.path.join(tmp, "meshes", name), tris)
        mode = rng.choice([None, None, "exact", "convex", "shell"])
        attrs = f'name="m{i}" file="{name}"'
        if mode:
            attrs += f' inertia="{mode}"'
        solid = f' inertia="{mode if mode == "shell" else "exact"}"'
        ex = f'name="m{i}" file="{name}"' + solid
        if rng.random() < 0.6:
            if mode == "shell":
                f = rng.choice([0.5, 2.0, 1.0])
                scale = [f * rng.choice([1, -1]) for _ in range(3)]
            else:
                scale = [rng.choice([0.5, 2.0, 1.0, 0.25, -1.0]) for _ in range(3)]
            attrs += ' scale="%r %r %r"' % tuple(scale)
            ex += ' scale="%r %r %r"' % tuple(scale)
        assets.append(f"<mesh {attrs}/>")
        exact.append(f"<mesh {ex}/>")
        g = f'type="mesh" mesh="m{i}" pos="{nums(rng, 3, -1, 1)}"'
        turn = rng.random()
        if turn < 0.4:
            g += f' quat="{nums(rng, 4, -1, 1)}"'
        elif turn < 0.7:
            g += f' euler="{nums(rng, 3, -180, 180)}"'
        amount = rng.random()
        if amount < 0.3:
            g += f' mass="{rng.uniform(0.1, 10)!r}"'
        elif amount < 0.6:
            g += f' density="{rng.uniform(100, 8000)!r}"'
        geoms.append(f"<geom {g}/>")
    if rng.random() < 0.3:
        geoms.append(f'<geom type="box" size="{nums(rng, 3, 0.05, 0.5)}" pos="{nums(rng, 3, -1, 1)}"/>')
    def model(meshes):
        return (
            '<mujoco model="meshes"><compiler meshdir="meshes"/><asset>'
            + "".join(meshes)
            + '</asset><worldbody><body name="b" pos="0.5 -0.25 1"><freejoint/>'
            + "".join(geoms)
            + "</body></worldbody></mujoco>\n"
        )

    return model(assets), model(exact)


def whole(model):
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    mujoco.mj_comPos(model, data)
    m = model.body_mass[1]
    r = data.ximat[1].reshape(3, 3)
    return m, data.xipos[1].copy(), r @ np.diag(model.body_inertia[1]) @ r.T


def massprop(binary, path):
    out = subprocess.run([binary, "report", path, "--format", "json"], capture_output=True, text=True)
    return out.returncode, out.stdout, out.stderr


def agree(name, got, want):
    scale = max(1e-300, float(np.max(np.abs(want))))
    if np.max(np.abs(np.asarray(got) - np.asarray(want))) > RTOL * scale:
        print(f"{name}: massprop {got} MuJoCo {want}", file=sys.stderr)
        return False
    return True


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--massprop", required=True)
    parser.add_argument("--cases", type=int, default=40)
    parser.add_argument("--seed", type=int, default=34)
    args = parser.parse_args()
    args.massprop = os.path.abspath(args.massprop)
    rng = random.Random(args.seed)
    bad = refused = 0
    with tempfile.TemporaryDirectory() as tmp:
        # MuJoCo writes its warnings to MUJOCO_LOG.TXT in the working
        # directory: keep it out of the repository.
        os.chdir(tmp)
        os.mkdir(os.path.join(tmp, "meshes"))
        for k in range(args.cases):
            text, exact = case(rng, k, tmp)
            path = os.path.join(tmp, f"c{k}.xml")
            with open(path, "w") as f:
                f.write(text)
            mass, com, inertia = whole(mujoco.MjModel.from_xml_path(path))
            part = os.path.join(tmp, f"c{k}.toml")
            with open(part, "w") as f:
                f.write(f'[[part]]\ninclude = "c{k}.xml"\n')
            for label, file in (("report", path), ("include", part)):
                code, out, err = massprop(args.massprop, file)
                if code != 0:
                    # A refusal is right only where MuJoCo's weighing of
                    # the mesh as written is not the exact solid's.
                    with open(path + ".exact.xml", "w") as f:
                        f.write(exact)
                    said = err.split("error:", 1)[-1].split("\n")[0]
                    ok_refusal = "inertia=\"convex\"" in said
                    m2, c2, i2 = whole(mujoco.MjModel.from_xml_path(path + ".exact.xml"))
                    differs = (
                        abs(m2 - mass) > 1e-9 * mass
                        or np.max(np.abs(c2 - com)) > 1e-9 * max(1, np.max(np.abs(com)))
                        or np.max(np.abs(i2 - inertia)) > 1e-9 * np.max(np.abs(inertia))
                    )
                    if not (ok_refusal and differs):
                        bad += 1
                        print(f"case {k} {label}: massprop refused where MuJoCo's answer is the exact one:\n{err}\n{text}", file=sys.stderr)
                    elif label == "report":
                        refused += 1
                    continue
                got = json.loads(out)
                ok = agree(f"case {k} {label} mass", [got["mass"]], [mass])
                ok &= agree(f"case {k} {label} centre", got["center_of_mass"], com)
                ok &= agree(f"case {k} {label} inertia", got["inertia_com"], inertia)
                if not ok:
                    bad += 1
                    print(text, file=sys.stderr)
    print(
        f"{args.cases} MJCF bodies of mesh geoms against MuJoCo: {bad} disagreements "
        f"({refused} refused: `convex` on a mesh that is not convex)"
    )
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
