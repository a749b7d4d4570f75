"""Independent derivation of the [expect] values of shapes/bicycle-wheel.toml
and shapes/rocket-stage.toml: every part's mass, centroid and second moment
by numerical quadrature (mpmath, 30 digits) over the solid, not by the
closed forms massprop uses; rods and points by their definitions; then the
parallel-axis sum. Run: python3 tests/oracle/example_expectations.py (needs mpmath)."""
import mpmath as mp
mp.mp.dps = 30
pi = mp.pi

def zeros():
    return mp.matrix(3, 3)

class Body:
    def __init__(self):
        self.m = mp.mpf(0); self.s = mp.matrix(3, 1); self.J = mp.matrix(3, 3)  # ∫ρρᵀ about origin
    def add(self, m, c, Jc):
        c = mp.matrix(c)
        self.m += m; self.s += m * c
        self.J += Jc + m * (c * c.T)
    def props(self):
        c = self.s / self.m
        Jg = self.J - self.m * (c * c.T)
        I = mp.eye(3) * (Jg[0, 0] + Jg[1, 1] + Jg[2, 2]) - Jg
        return self.m, c, I

def rot_axis(axis, deg):
    a = mp.matrix(axis); a = a / mp.norm(a); t = mp.radians(deg)
    K = mp.matrix([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return mp.eye(3) + mp.sin(t) * K + (1 - mp.cos(t)) * (K * K)

def revolve(rho, z0, z1, outer, inner):
    """Solid of revolution about local z, z in [z0, z1], radius from inner(z)
    to outer(z): mass, centroid z, and local J (diag) about its centroid."""
    f = lambda g: mp.quad(g, [z0, z1])
    m = rho * pi * f(lambda z: outer(z)**2 - inner(z)**2)
    zc = rho * pi * f(lambda z: z * (outer(z)**2 - inner(z)**2)) / m
    jxx = rho * pi * f(lambda z: (outer(z)**4 - inner(z)**4) / 4)   # ∫x² dm
    jzz = rho * pi * f(lambda z: (z - zc)**2 * (outer(z)**2 - inner(z)**2))
    return m, zc, mp.diag([jxx, jxx, jzz])

def cone(rho, R, Rt, L, a=0, at=0):
    o = lambda z: R + (Rt - R) * (z + L / 2) / L
    i = lambda z: a + (at - a) * (z + L / 2) / L
    return revolve(rho, -L / 2, L / 2, o, i)

def tube(rho, R, r, L):
    return revolve(rho, -L / 2, L / 2, lambda z: R, lambda z: r)

def torus(rho, Rc, t, ti=0):
    """Quadrature over the tube's cross-section (s, z): dm = ρ 2π s ds dz."""
    def integ(g):
        def over_z(z):
            h = mp.sqrt(t**2 - z**2)
            hi = mp.sqrt(ti**2 - z**2) if abs(z) < ti else None
            if hi is None:
                return mp.quad(lambda s: g(s, z) * s, [Rc - h, Rc + h])
            return mp.quad(lambda s: g(s, z) * s, [Rc - h, Rc - hi]) + mp.quad(lambda s: g(s, z) * s, [Rc + hi, Rc + h])
        pts = [-t, -ti, 0, ti, t] if ti > 0 else [-t, 0, t]
        return 2 * pi * rho * mp.quad(over_z, pts)
    m = integ(lambda s, z: 1)
    jxx = integ(lambda s, z: s**2 / 2)
    jzz = integ(lambda s, z: z**2)
    return m, mp.diag([jxx, jxx, jzz])

def thin_torus(M, Rc, t):
    """A thin toroidal shell of mass M: surface quadrature (area element
    t (Rc + t cos φ) dφ dθ)."""
    w = lambda ph: t * (Rc + t * mp.cos(ph))
    A = 2 * pi * mp.quad(w, [0, 2 * pi])
    jxx = 2 * pi * mp.quad(lambda ph: w(ph) * (Rc + t * mp.cos(ph))**2 / 2, [0, 2 * pi]) / A * M
    jzz = 2 * pi * mp.quad(lambda ph: w(ph) * (t * mp.sin(ph))**2, [0, 2 * pi]) / A * M
    return mp.diag([jxx, jxx, jzz])

def scale(J, k):
    return J * k

def place(body, m, zc_local, Jlocal, center, R=None):
    R = mp.eye(3) if R is None else R
    c = mp.matrix(center) + R * mp.matrix([0, 0, zc_local])
    body.add(m, c, R * Jlocal * R.T)

def rod(body, m, a, b):
    a = mp.matrix(a); b = mp.matrix(b); d = b - a
    body.add(m, (a + b) / 2, m / 12 * (d * d.T))

def point(body, m, c):
    body.add(m, c, zeros())

def prism_local(rho, poly, L):
    """Prism over polygon (local x-y), z in [-L/2, L/2]: area integrals by
    quadrature over x of the polygon's vertical extent (convex in y)."""
    xs = sorted(set(p[0] for p in poly))
    def ys(x):
        hits = []
        n = len(poly)
        for k in range(n):
            (x0, y0), (x1, y1) = poly[k], poly[(k + 1) % n]
            if x0 != x1 and min(x0, x1) <= x <= max(x0, x1):
                hits.append(y0 + (y1 - y0) * (x - x0) / (x1 - x0))
        return min(hits), max(hits)
    f = lambda g: mp.quad(lambda x: g(x, *ys(x)), xs)
    A = f(lambda x, lo, hi: hi - lo)
    Sx = f(lambda x, lo, hi: x * (hi - lo)); Sy = f(lambda x, lo, hi: (hi**2 - lo**2) / 2)
    cx, cy = Sx / A, Sy / A
    Ixx = f(lambda x, lo, hi: (x - cx)**2 * (hi - lo))
    Iyy = f(lambda x, lo, hi: ((hi - cy)**3 - (lo - cy)**3) / 3)
    Ixy = f(lambda x, lo, hi: (x - cx) * ((hi - cy)**2 - (lo - cy)**2) / 2)
    m = rho * A * L
    J = rho * L * mp.matrix([[Ixx, Ixy, 0], [Ixy, Iyy, 0], [0, 0, 0]])
    J[2, 2] = m * L**2 / 12
    return m, (cx, cy), J

def show(name, body):
    m, c, I = body.props()
    print(name)
    print("  mass", mp.nstr(m, 15))
    print("  center", [mp.nstr(x, 15) for x in c])
    for i in range(3):
        print("  I", [mp.nstr(I[i, j], 15) for j in range(3)])

def thin_cone(M, R, L):
    """A thin conical shell (lateral surface, apex at +L/2, base radius R
    at −L/2) of mass M: surface quadrature, dA ∝ r(z) dz."""
    r = lambda z: R * (L / 2 - z) / L
    A = mp.quad(r, [-L / 2, L / 2])
    zc = mp.quad(lambda z: z * r(z), [-L / 2, L / 2]) / A
    jxx = M * mp.quad(lambda z: r(z)**3 / 2, [-L / 2, L / 2]) / A
    jzz = M * mp.quad(lambda z: (z - zc)**2 * r(z), [-L / 2, L / 2]) / A
    return zc, mp.diag([jxx, jxx, jzz])

def thin_annulus(rho_a, R, r):
    """A thin annulus (zero thickness) of areal density rho_a."""
    m = rho_a * 2 * pi * mp.quad(lambda s: s, [r, R])
    jxx = rho_a * 2 * pi * mp.quad(lambda s: s**3 / 2, [r, R])
    return m, mp.diag([jxx, jxx, 0])

def bicycle_wheel():
    mm = mp.mpf(1)
    b = Body()
    kg = lambda g: mp.mpf(g) / 1000
    bsd, erd, section = mp.mpf(622), mp.mpf(602), mp.mpf(25)
    Rc = bsd / 2 + section / 2
    # tyre: hollow torus of given mass
    m1, J1 = torus(1, Rc, section / 2, section / 2 - 1)
    b.add(kg(230), [0, 0, 0], J1 * (kg(230) / m1))
    # inner tube: thin toroidal shell
    b.add(kg(100), [0, 0, 0], thin_torus(kg(100), Rc, section / 2 - 1))
    # rim: tube of given mass
    m3, z3, J3 = tube(1, bsd / 2, erd / 2, 19)
    b.add(kg(450), [0, 0, 0], J3 * (kg(450) / m3))
    alu, steel = mp.mpf(2700) * 1e-9, mp.mpf(7850) * 1e-9  # kg/mm³
    m4, z4, J4 = tube(alu, 17, 12, 70)
    b.add(m4, [0, 0, 0], J4)
    m5, J5 = thin_annulus(alu * 3, (45 + 10) / mp.mpf(2), 17)
    b.add(m5, [0, 0, 35], J5); b.add(m5, [0, 0, -35], J5)
    m6, z6, J6 = tube(steel, 7.5, 5, 100)
    b.add(m6, [0, 0, 0], J6)
    for side in (1, -1):
        for k in range(16):
            R = rot_axis([0, 0, 1], 22.5 * k)
            a = R * mp.matrix([22.5, 0, 35 * side]); e = R * mp.matrix([301, 0, 0])
            rod(b, kg('6.2'), a, e)
    t = mp.radians(11.25)
    point(b, kg(6), [301 * mp.cos(t), 301 * mp.sin(t), 0])
    return b

def rocket_stage():
    b = Body()
    kgmm3 = lambda rho: mp.mpf(rho) * 1e-9
    m, zc, J = cone(kgmm3(1800), 45, 20, 90, 41, 16); place(b, m, zc, J, [0, 0, 45])
    m, zc, J = cone(kgmm3(1600), 60, 77.5, 120, 57, 74.5); place(b, m, zc, J, [0, 0, 60])
    poly = [(mp.mpf('77.5'), 130), (mp.mpf('197.5'), 150), (mp.mpf('197.5'), 270), (mp.mpf('77.5'), 430)]
    m, (cx, cy), J = prism_local(kgmm3(1600), poly, 5)
    Rf = rot_axis([1, 0, 0], 90)
    for k in range(4):
        R = rot_axis([0, 0, 1], 90 * k) * Rf
        b.add(m, R * mp.matrix([cx, cy, 0]), R * J * R.T)
    m, zc, J = tube(kgmm3(1600), 77.5, 74.5, 1400); place(b, m, zc, J, [0, 0, 820])
    m, zc, J = tube(kgmm3(2700), 54, 51, 1000); place(b, m, zc, J, [0, 0, 590])
    m, zc, J = tube(kgmm3(1750), 51, 20, 950); place(b, m, zc, J, [0, 0, 585])
    m, zc, J = tube(kgmm3(2700), 51, 0, 25); place(b, m, zc, J, [0, 0, mp.mpf('1077.5')])
    m, zc, J = tube(1, 70, 0, 150); place(b, 2.5, zc, J * (mp.mpf('2.5') / m), [0, 0, 1200])
    m, zc, J = tube(1, 70, 0, 200); place(b, 1.8, zc, J * (mp.mpf('1.8') / m), [0, 0, 1420])
    zc, J = thin_cone(mp.mpf('0.77'), 77.5, 550); place(b, mp.mpf('0.77'), zc, J, [0, 0, 1520 + 275])
    return b

if __name__ == "__main__":
    show("bicycle wheel", bicycle_wheel())
    show("rocket stage", rocket_stage())
