"""Independent derivation of the [expect] values of shapes/smallsat.toml:
the basic and the predicted body (each part's basic mass, and its growth,
basic × its maturity's allowance, as a point mass at the part's centroid),
from the parts' textbook second moments about their centroids and the
parallel-axis sum, in mpmath at 30 digits. Nothing here is massprop's code
or output. Run: python3 tests/oracle/smallsat_expectations.py (needs mpmath)."""
import mpmath as mp
mp.mp.dps = 30
F = mp.mpf

GROWTH = {"estimated": F("0.15"), "calculated": F("0.08"), "measured": F("0.01")}

def box(m, a, b, c):  # ∫x² dm, ∫y² dm, ∫z² dm about the centroid
    return [m * a**2 / 12, m * b**2 / 12, m * c**2 / 12]

def cylinder_z(m, R, L, r=0):  # axis z; a tube with inner radius r
    return [m * (R**2 + r**2) / 4] * 2 + [m * L**2 / 12]

def hollow_sphere(m, R, r):
    j = m / 5 * (R**5 - r**5) / (R**3 - r**3)
    return [j, j, j]

def point(m):
    return [0, 0, 0]

# name, mass (kg), centre (mm), ∫x²,y²,z² dm (kg·mm²), maturity or None
F_ = lambda *xs: [F(str(x)) for x in xs]
PARTS = [
    ("primary structure", F("3.2"), F_(0, 0, 250), box(F("3.2"), 400, 400, 500), "calculated"),
    ("+X panel", F("0.9"), F_(202, 0, 250), box(F("0.9"), 4, 400, 500), "calculated"),
    ("-X panel", F("0.9"), F_(-202, 0, 250), box(F("0.9"), 4, 400, 500), "calculated"),
    ("adapter ring", F("0.6"), F_(0, 0, -10), cylinder_z(F("0.6"), 150, 20, 140), "measured"),
    ("solar array +Y", F("1.4"), F_(0, 210, 250), box(F("1.4"), 400, 6, 500), "estimated"),
    ("solar array -Y", F("1.4"), F_(0, -210, 250), box(F("1.4"), 400, 6, 500), "estimated"),
    ("battery pack", F("2.1"), F_(-80, 60, 60), box(F("2.1"), 150, 100, 80), "measured"),
    ("power control unit", F("0.8"), F_(80, 60, 40), box(F("0.8"), 120, 100, 40), "calculated"),
    ("propellant tank", F("1.2"), F_(0, 0, 300), hollow_sphere(F("1.2"), 120, 118), "calculated"),
    ("thruster", F("0.35"), F_(0, 0, 30), cylinder_z(F("0.35"), 30, 60), "estimated"),
    ("on-board computer", F("0.45"), F_(80, -80, 100), box(F("0.45"), 100, 100, 30), "measured"),
    ("transceiver", F("0.6"), F_(-80, -80, 100), box(F("0.6"), 100, 80, 40), "estimated"),
    ("camera", F("2.5"), F_(0, 0, 380), cylinder_z(F("2.5"), 60, 250), "estimated"),
    ("harness", F("0.7"), F_(0, 0, 200), point(F("0.7")), None),
]

def compose(items):
    """items: (mass, centre, [∫x², ∫y², ∫z²] about the centroid)."""
    m = sum(i[0] for i in items)
    c = [sum(i[0] * i[1][k] for i in items) / m for k in range(3)]
    J = mp.matrix(3, 3)  # ∫ρρᵀ dm about the centre of mass
    for mi, ci, ji in items:
        d = [ci[k] - c[k] for k in range(3)]
        for a in range(3):
            J[a, a] += ji[a]
            for b in range(3):
                J[a, b] += mi * d[a] * d[b]
    I = mp.eye(3) * (J[0, 0] + J[1, 1] + J[2, 2]) - J
    return m, c, I

basic = [(m, c, j) for _, m, c, j, _ in PARTS]
growth = [(m * GROWTH[k], c, [0, 0, 0]) for _, m, c, _, k in PARTS if k]
for label, items in [("basic", basic), ("predicted", basic + growth)]:
    m, c, I = compose(items)
    print(f"{label} mass (kg): {mp.nstr(m, 17)}")
    print(f"{label} centre of mass (mm): {[mp.nstr(x, 17) for x in c]}")
    print(f"{label} inertia about it (kg·mm²): Ixx {mp.nstr(I[0, 0], 17)}, Iyy {mp.nstr(I[1, 1], 17)}, Izz {mp.nstr(I[2, 2], 17)}, Ixy {mp.nstr(I[0, 1], 17)}, Ixz {mp.nstr(I[0, 2], 17)}, Iyz {mp.nstr(I[1, 2], 17)}")
g = sum(i[0] for i in growth)
print(f"growth (kg): {mp.nstr(g, 17)}; margin against 20 kg: {mp.nstr(20 - sum(i[0] for i in basic) - g, 17)} kg")
