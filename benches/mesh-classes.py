#!/usr/bin/env python3
"""What massprop, trimesh and MuJoCo do with each class of mesh (issue 30).

Generates one small STL a class (unit cubes, density 1, exact volume 1 or 2),
runs `massprop report --format json`, trimesh (volume, is_watertight) and
MuJoCo (default inertia and inertia="exact"), and prints a markdown table.
Usage: benches/mesh-classes.py target/debug/massprop   (needs trimesh, mujoco)
"""
import json, os, re, subprocess, sys, tempfile

def cube(lo=(0, 0, 0), s=1.0):
    x0, y0, z0 = lo
    x1, y1, z1 = x0 + s, y0 + s, z0 + s
    P = lambda i, j, k: ((x0, x1)[i], (y0, y1)[j], (z0, z1)[k])
    quads = [(P(0,0,0),P(0,1,0),P(1,1,0),P(1,0,0)), (P(0,0,1),P(1,0,1),P(1,1,1),P(0,1,1)),
             (P(0,0,0),P(1,0,0),P(1,0,1),P(0,0,1)), (P(0,1,0),P(0,1,1),P(1,1,1),P(1,1,0)),
             (P(0,0,0),P(0,0,1),P(0,1,1),P(0,1,0)), (P(1,0,0),P(1,1,0),P(1,1,1),P(1,0,1))]
    return [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]

def stl(t):
    s = "solid t\n"
    for tri in t:
        s += " facet normal 0 0 0\n  outer loop\n" + "".join("   vertex %r %r %r\n" % p for p in tri)
        s += "  endloop\n endfacet\n"
    return s + "endsolid t\n"

c = cube()
top = [((0,0,1),(1,0,1),(1,1,1)), ((0,0,1),(1,1,1),(0.5,1,1)), ((0,0,1),(0.5,1,1),(0,1,1))]
tj = c[:2] + top + c[4:]
# The corner (1, 1, 1) of the top face's first triangle 1e-12 off in x.
gap = [tuple(tuple(x + (1e-12 if p == (1, 1, 1) and k == 0 and i == 2 else 0) for k, x in enumerate(p))
             for p in tri) for i, tri in enumerate(c)]
CLASSES = [
    ("closed, manifold", c, 1.0, ""),
    ("two cubes along an edge (4 triangles an edge, 2 each way)", c + cube((1, 1, 0)), 2.0, ""),
    ("T-junction", tj, 1.0, ""),
    ("zero-area sliver closing a T-junction", tj + [((1,1,1),(0,1,1),(0.5,1,1))], 1.0, ""),
    ("a triangle repeated", c + [c[0]], 1.0, ""),
    ("open (a triangle missing)", c[1:], None, ""),
    ("inside out", [(a, cc, b) for a, b, cc in c], 1.0, ""),
    ("gap of 1e-12 at one corner", gap, None, ""),
    ("gap of 1e-12, `weld = \"1e-9 m\"`", gap, None, 'weld = "1e-9 m"\n'),
]

def obj(t):
    # MuJoCo reads binary STL only (f32): an OBJ keeps every digit.
    v = "".join("v %r %r %r\n" % p for tri in t for p in tri)
    return v + "".join("f %d %d %d\n" % (3 * i + 1, 3 * i + 2, 3 * i + 3) for i in range(len(t)))

def short(m):
    """A message's first words: no parentheses, up to its first colon."""
    m = m.split("`: ", 1)[-1].splitlines()[0]
    m = re.sub(r"\s*\((?:[^()]|\([^()]*\))*\)", "", m)
    for stop in (":", ";", ","):
        m = m.split(stop)[0]
    return m.strip()

def run_massprop(exe, d, name, extra):
    toml = os.path.join(d, name + ".toml")
    open(toml, "w").write('[[part]]\nshape = "mesh"\nfile = "%s.stl"\nmesh_unit = "m"\ndensity = 1\n%s' % (name, extra))
    r = subprocess.run([exe, "report", "--format", "json", toml], capture_output=True, text=True)
    if r.returncode != 0:
        return "refused: " + short(r.stderr)
    j = json.loads(r.stdout)
    warned = [short(w["message"]) for w in j["accuracy_warnings"] if w["quantity"] == "mesh"]
    return "%.15g" % j["mass"] + (" (warns: %s)" % "; ".join(warned) if warned else "")

def run_trimesh(path):
    import trimesh
    m = trimesh.load(path, process=True)
    return "%.15g%s" % (m.volume, "" if m.is_watertight else " (not watertight)")

def run_mujoco(path, inertia):
    import mujoco
    xml = ('<mujoco><compiler boundmass="0" boundinertia="0"/><asset><mesh name="m" file="%s"%s/></asset>'
           '<worldbody><body><freejoint/><geom type="mesh" mesh="m" density="1"/></body></worldbody></mujoco>'
           % (path, ' inertia="exact"' if inertia else ""))
    try:
        m = mujoco.MjModel.from_xml_string(xml)
        return "%.15g" % m.body_mass[1]
    except Exception as e:
        return "error: " + str(e).splitlines()[0][:60]

def main():
    exe = os.path.abspath(sys.argv[1])
    d = tempfile.mkdtemp()
    print("| class | exact | massprop | trimesh | MuJoCo default | MuJoCo `exact` |")
    print("|---|---|---|---|---|---|")
    for i, (label, tris, exact, extra) in enumerate(CLASSES):
        name = "m%d" % i
        path = os.path.join(d, name + ".stl")
        open(path, "w").write(stl(tris))
        open(path[:-3] + "obj", "w").write(obj(tris))
        cells = [label, "none (open; ≈ 1)" if exact is None else "%g" % exact,
                 run_massprop(exe, d, name, extra), run_trimesh(path),
                 run_mujoco(path[:-3] + "obj", False), run_mujoco(path[:-3] + "obj", True)]
        print("| " + " | ".join(cells) + " |")

if __name__ == "__main__":
    main()
