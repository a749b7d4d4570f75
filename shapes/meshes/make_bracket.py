#!/usr/bin/env python3
"""Write bracket.stl: an L-bracket of 4 mm steel plate, 30 mm wide, legs
40 mm (along x) and 30 mm (along z), with a round 8 mm hole through each
leg, as an ASCII STL in millimetres (shapes/mesh-bracket.toml uses it).

Every face is triangulated so that faces meeting at an edge split it at
the same vertices (no T-junctions): the mesh is closed, and every triangle
is wound counter-clockwise seen from outside. Run from anywhere:
python3 shapes/meshes/make_bracket.py
"""
import math
import os

N = 24  # segments per hole
T, W, LX, LZ, R = 4.0, 30.0, 40.0, 30.0, 4.0
HOLE1 = (25.0, 15.0)  # (x, y) of the hole through the horizontal leg
HOLE2 = (15.0, 18.0)  # (y, z) of the hole through the vertical leg

tris = []


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def tri(a, b, c, outward):
    """Add (a, b, c), wound so its normal points along `outward`."""
    n = cross(sub(b, a), sub(c, a))
    tris.append((a, c, b) if dot(n, outward) < 0 else (a, b, c))


def rect(corners, outward):
    a, b, c, d = corners
    tri(a, b, c, outward)
    tri(a, c, d, outward)


def circle(cu, cv):
    """The hole's loop in a face's (u, v): N points, plus the angles of
    the face's corners added later by `holed`."""
    return [(cu + R * math.cos(2 * math.pi * k / N), cv + R * math.sin(2 * math.pi * k / N)) for k in range(N)]


def holed(u0, u1, v0, v1, centre, to3d, outward):
    """The rectangle [u0, u1] × [v0, v1] less a round hole about `centre`:
    each hole edge joined to the corner whose side faces it, and each side
    to the hole vertex at the side's middle angle."""
    cu, cv = centre
    corners = [(u0, v0), (u1, v0), (u1, v1), (u0, v1)]
    ang = [math.atan2(v - cv, u - cu) % (2 * math.pi) for (u, v) in corners]
    loop = circle(cu, cv)
    la = [2 * math.pi * k / N for k in range(N)]
    for k in range(4):
        a0, a1 = ang[k], ang[(k + 1) % 4]
        if a1 < a0:
            a1 += 2 * math.pi
        # Hole vertices inside this side's angular range, in order.
        inside = sorted(
            [i for i in range(N) if a0 <= la[i] < a1 or a0 <= la[i] + 2 * math.pi < a1],
            key=lambda i: la[i] if la[i] >= a0 else la[i] + 2 * math.pi,
        )
        mid = inside[len(inside) // 2]
        c0, c1 = to3d(*corners[k]), to3d(*corners[(k + 1) % 4])
        tri(c0, c1, to3d(*loop[mid]), outward)
        for j in range(len(inside)):
            i, nxt = inside[j], (inside[j] + 1) % N
            corner = c0 if j < len(inside) // 2 else c1
            tri(corner, to3d(*loop[i]), to3d(*loop[nxt]), outward)
    return loop


# Bottom (z = 0) and top of the horizontal leg (z = T), hole 1 through both.
hole1_bottom = holed(0, LX, 0, W, HOLE1, lambda u, v: [u, v, 0.0], [0, 0, -1])
hole1_top = holed(T, LX, 0, W, HOLE1, lambda u, v: [u, v, T], [0, 0, 1])
# Back (x = 0) and inner face of the vertical leg (x = T), hole 2 (u = y, v = z).
hole2_back = holed(0, W, 0, LZ, HOLE2, lambda u, v: [0.0, u, v], [-1, 0, 0])
hole2_inner = holed(0, W, T, LZ, HOLE2, lambda u, v: [T, u, v], [1, 0, 0])
# The holes' walls, facing their axes.
for k in range(N):
    k1 = (k + 1) % N
    (u, v), (u1, v1) = hole1_bottom[k], hole1_bottom[k1]
    a, b = [u, v, 0.0], [u1, v1, 0.0]
    c, d = [u1, v1, T], [u, v, T]
    mid = [(u + u1) / 2, (v + v1) / 2]
    rect((a, b, c, d), [HOLE1[0] - mid[0], HOLE1[1] - mid[1], 0])
    (u, v), (u1, v1) = hole2_back[k], hole2_back[k1]
    a, b = [0.0, u, v], [0.0, u1, v1]
    c, d = [T, u1, v1], [T, u, v]
    mid = [(u + u1) / 2, (v + v1) / 2]
    rect((a, b, c, d), [0, HOLE2[0] - mid[0], HOLE2[1] - mid[1]])
# The plain faces: the horizontal leg's end, the vertical leg's top.
rect(([LX, 0, 0], [LX, W, 0], [LX, W, T], [LX, 0, T]), [1, 0, 0])
rect(([0, 0, LZ], [T, 0, LZ], [T, W, LZ], [0, W, LZ]), [0, 0, 1])
# The L-shaped ends (y = 0 and y = W).
profile = [(0, 0), (LX, 0), (LX, T), (T, T), (T, LZ), (0, LZ)]
for y, out in [(0.0, [0, -1, 0]), (W, [0, 1, 0])]:
    p = [[x, y, z] for (x, z) in profile]
    for a, b, c in [(0, 1, 2), (0, 2, 3), (0, 3, 4), (0, 4, 5)]:
        tri(p[a], p[b], p[c], out)

here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, "bracket.stl"), "w") as f:
    f.write("solid bracket\n")
    for t in tris:
        f.write("  facet normal 0 0 0\n    outer loop\n")
        for p in t:
            f.write("      vertex %s %s %s\n" % tuple(repr(float(x)) for x in p))
        f.write("    endloop\n  endfacet\n")
    f.write("endsolid bracket\n")
print(len(tris), "triangles")
