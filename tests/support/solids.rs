//! The exact forms of the shapes of issue 17 (cone, torus, hemisphere,
//! prism) and of issue 29 (capsule, ellipsoid) for the reference composer (`reference`), derived here from the
//! definitions by exact polynomial integration, independently of
//! massprop's closed forms (which take another road: Bernstein
//! coefficients, ratios in ρ = r/R, Green's theorem in double-double).
//! Each returns ∫xxᵀ dm / m about the centroid in local axes (diagonal, or
//! with the prism's x–y product), the centroid's offset in local axes, and
//! the measure a density multiplies (`None`: a thin shell, mass only).

use super::reference::{Q, frac, int, pi};
use num_traits::Zero;

/// A polynomial in t, coefficients from t⁰ up.
type Poly = Vec<Q>;

fn mul(a: &Poly, b: &Poly) -> Poly {
    let mut out = vec![Q::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

fn sub(a: &Poly, b: &Poly) -> Poly {
    let n = a.len().max(b.len());
    (0..n)
        .map(|k| {
            a.get(k).cloned().unwrap_or_else(Q::zero) - b.get(k).cloned().unwrap_or_else(Q::zero)
        })
        .collect()
}

/// ∫₀¹ tᵏ p(t) dt.
fn moment(p: &Poly, k: usize) -> Q {
    p.iter()
        .enumerate()
        .map(|(i, c)| c / int((i + k + 1) as i64))
        .fold(Q::zero(), |a, b| a + b)
}

fn pow(p: &Poly, n: usize) -> Poly {
    (0..n).fold(vec![int(1)], |acc, _| mul(&acc, p))
}

/// A cone [R₀, R₁, L] or hollow [R₀, R₁, L, a₀, a₁]: the outer radius
/// ρ(t) = R₀ + (R₁ − R₀)t and the inner α(t) likewise at z = L(t − ½).
/// The section's area is π(ρ² − α²) and its ∫x² dA = π(ρ⁴ − α⁴)/4, so with
/// A(t) = ρ² − α²: V = πL ∫A dt; z̄ = L(∫tA/∫A − ½); ∫x² dm/m =
/// ∫(ρ⁴ − α⁴)/(4∫A); ∫(z − z̄)² dm/m = L²(∫t²A/∫A − (∫tA/∫A)²).
pub fn cone(size: &[Q]) -> ([Q; 3], Q, Option<Q>) {
    let (r0, r1, l) = (&size[0], &size[1], &size[2]);
    let zero = Q::zero();
    let (a0, a1) = (size.get(3).unwrap_or(&zero), size.get(4).unwrap_or(&zero));
    let outer: Poly = vec![r0.clone(), r1 - r0];
    let inner: Poly = vec![a0.clone(), a1 - a0];
    let area = sub(&pow(&outer, 2), &pow(&inner, 2));
    let fourth = sub(&pow(&outer, 4), &pow(&inner, 4));
    let m0 = moment(&area, 0);
    assert!(!m0.is_zero(), "the reference takes no thin conical shell");
    let tbar = moment(&area, 1) / &m0;
    let across = moment(&fourth, 0) / (int(4) * &m0);
    let axial = l * l * (moment(&area, 2) / &m0 - &tbar * &tbar);
    let offset = l * (tbar - frac(1, 2));
    ([across.clone(), across, axial], offset, Some(pi() * l * m0))
}

/// A torus [R, a] or hollow [R, a, b] (see massprop's docs/part-file.md):
/// by Pappus, a point (R + u, z) of the tube's annular section sweeps
/// 2π(R + u), so ∫f dV = ∫∫ f 2π(R + u) du dz; the annulus's ∫∫u² = ∫∫z² =
/// π(a⁴ − b⁴)/4 and its odd moments vanish. ∫z² dm/m = (a² + b²)/4, and
/// ∫(x² + y²) dm/m = R² + 3(a² + b²)/4 (∫∫(R + u)³ = R³A + 3R∫∫u²).
pub fn torus(size: &[Q]) -> ([Q; 3], Q, Option<Q>) {
    let (big, a) = (&size[0], &size[1]);
    let zero = Q::zero();
    let b = size.get(2).unwrap_or(&zero);
    let tube = a * a + b * b;
    let across = (big * big + int(3) * &tube / int(4)) / int(2);
    let volume = int(2) * pi() * pi() * big * (a * a - b * b);
    (
        [across.clone(), across, tube / int(4)],
        Q::zero(),
        (!volume.is_zero()).then_some(volume),
    )
}

/// A hemisphere [R] or hollow [R, r], the half z ≥ 0: in shells of radius
/// s, V = 2π(R³ − r³)/3, ∫z dV = π(R⁴ − r⁴)/4 (∫ s³ ds ∫cos φ dΩ over a
/// half, π), and ∫x² dV = ∫z² dV = 2π(R⁵ − r⁵)/15 (half a sphere's); at
/// r = R the thin shell's limits (the differences divided by R − r).
pub fn hemisphere(size: &[Q]) -> ([Q; 3], Q, Option<Q>) {
    let big = &size[0];
    let zero = Q::zero();
    let r = size.get(1).unwrap_or(&zero);
    // (Rⁿ − rⁿ)/(R − r) = Σ R^k r^(n−1−k): exact at r = R too.
    let div = |n: u32| -> Q {
        (0..n)
            .map(|k| pow_q(big, k) * pow_q(r, n - 1 - k))
            .fold(Q::zero(), |a, b| a + b)
    };
    let (v3, v4, v5) = (div(3), div(4), div(5));
    // Per unit mass: V ∝ 2π/3 v3, ∫z ∝ π/4 v4, ∫x² ∝ 2π/15 v5.
    let zbar = frac(3, 8) * &v4 / &v3;
    let second = frac(1, 5) * &v5 / &v3;
    let axial = &second - &zbar * &zbar;
    let volume = int(2) * pi() * (pow_q(big, 3) - pow_q(r, 3)) / int(3);
    (
        [second.clone(), second, axial],
        zbar,
        (!volume.is_zero()).then_some(volume),
    )
}

/// A capsule [R, L] or hollow [R, L, r]: a tube r ≤ ρ ≤ R of length L
/// (V_t = π(R² − r²)L, ∫x² dV_t = π(R⁴ − r⁴)L/4, ∫z² dV_t = V_t L²/12)
/// and a spherical shell r ≤ s ≤ R split at its equator, each half moved
/// L/2 along z (V_h = 2π(R³ − r³)/3, ∫z′ dV_h = π(R⁴ − r⁴)/4,
/// ∫x² dV_h = ∫z′² dV_h = 2π(R⁵ − r⁵)/15, z = L/2 + z′): the sums of the
/// three pieces' own integrals, each difference Rⁿ − rⁿ carried as
/// (R − r) Σ R^k r^(n−1−k) so that at r = R the thin shell's limits
/// remain; centred, so no offset.
pub fn capsule(size: &[Q]) -> ([Q; 3], Q, Option<Q>) {
    let (big, l) = (&size[0], &size[1]);
    let zero = Q::zero();
    let r = size.get(2).unwrap_or(&zero);
    let div = |n: u32| -> Q {
        (0..n)
            .map(|k| pow_q(big, k) * pow_q(r, n - 1 - k))
            .fold(Q::zero(), |a, b| a + b)
    };
    // Each integral over π(R − r): the tube's, then both half shells'.
    let volume = div(2) * l + int(2) * (int(2) * div(3) / int(3));
    let xx = div(4) * l / int(4) + int(2) * (int(2) * div(5) / int(15));
    let half = |moved: &Q| -> Q {
        // V_h L²/4 + L ∫z′ dV_h + ∫z′² dV_h, over π(R − r).
        int(2) * div(3) / int(3) * moved * moved
            + int(2) * moved * div(4) / int(4)
            + int(2) * div(5) / int(15)
    };
    let zz = div(2) * l * l * l / int(12) + int(2) * half(&(l / int(2)));
    let measure = pi() * (big - r) * &volume;
    (
        [&xx / &volume, &xx / &volume, &zz / &volume],
        Q::zero(),
        (!measure.is_zero()).then_some(measure),
    )
}

/// A solid ellipsoid [a, b, c], by slices across local z. With
/// z = c(2t − 1), t from 0 to 1, the slice is the ellipse of semi-axes
/// a s and b s, s² = 1 − (2t − 1)² = 4t(1 − t): its area π a b s² and its
/// ∫x² dA = π a³ b s⁴/4 (∫y² dA = π a b³ s⁴/4), so over the length 2c:
/// V = 2πabc ∫s² dt, ∫x² dV = 2π a³ b c ∫s⁴ dt / 4 and
/// ∫z² dV = 2πabc ∫z² s² dt, each integral of a polynomial in t carried
/// exactly; centred, so no offset.
pub fn ellipsoid(size: &[Q]) -> ([Q; 3], Q, Option<Q>) {
    let (a, b, c) = (&size[0], &size[1], &size[2]);
    let s2: Poly = vec![Q::zero(), int(4), int(-4)];
    let z: Poly = vec![-c.clone(), int(2) * c];
    let area = moment(&s2, 0);
    let fourth = moment(&pow(&s2, 2), 0);
    let across = &fourth / (int(4) * &area);
    let along = moment(&mul(&pow(&z, 2), &s2), 0) / &area;
    (
        [a * a * &across, b * b * &across, along],
        Q::zero(),
        Some(int(2) * pi() * a * b * c * area),
    )
}

fn pow_q(x: &Q, n: u32) -> Q {
    (0..n).fold(int(1), |a, _| a * x)
}

/// A simple polygon (either orientation): its area, centroid and
/// ∫(p − g)(p − g)ᵀ dA/A as [xx, yy, xy], summed over the triangles
/// (o, pᵢ, pᵢ₊₁) of a fan from the origin, each signed by its orientation:
/// a triangle's centroid is its vertices' mean and, about the origin,
/// ∫ppᵀ dA = (A/12)(Σ vᵢvᵢᵀ + s sᵀ), s = Σ vᵢ (the Dirichlet moments of
/// the reference's `triangle_form`).
pub fn polygon(p: &[[Q; 2]]) -> (Q, [Q; 2], [Q; 3]) {
    let n = p.len();
    let zero = Q::zero();
    let (mut area, mut fx, mut fy) = (zero.clone(), zero.clone(), zero.clone());
    let mut s = [zero.clone(), zero.clone(), zero.clone()];
    for i in 0..n {
        let (a, b) = (&p[i], &p[(i + 1) % n]);
        let t = (&a[0] * &b[1] - &b[0] * &a[1]) / int(2);
        fx += &t * (&a[0] + &b[0]) / int(3);
        fy += &t * (&a[1] + &b[1]) / int(3);
        // The vertices o = 0, a, b: Σ vvᵀ + s sᵀ with s = a + b.
        let (sx, sy) = (&a[0] + &b[0], &a[1] + &b[1]);
        let xx = &a[0] * &a[0] + &b[0] * &b[0] + &sx * &sx;
        let yy = &a[1] * &a[1] + &b[1] * &b[1] + &sy * &sy;
        let xy = &a[0] * &a[1] + &b[0] * &b[1] + &sx * &sy;
        s[0] += &t * xx / int(12);
        s[1] += &t * yy / int(12);
        s[2] += &t * xy / int(12);
        area += t;
    }
    let g = [&fx / &area, &fy / &area];
    let second = [
        &s[0] / &area - &g[0] * &g[0],
        &s[1] / &area - &g[1] * &g[1],
        &s[2] / &area - &g[0] * &g[1],
    ];
    let abs = if area < zero { -area } else { area };
    (abs, g, second)
}
