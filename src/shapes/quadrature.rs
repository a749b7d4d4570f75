//! The closed forms of the cone, torus, hemisphere and prism against
//! numerical integration over the solid, written here independently of
//! them: Gauss–Legendre in the radial and axial coordinates (exact for the
//! polynomials these integrands are), the trapezoid rule around a full
//! turn (exact for trigonometric polynomials of low degree), and for the
//! prism an exact triangulation.

use super::Shape;
use super::prism::polygon;
use crate::numeric::Real;

/// Gauss–Legendre on [lo, hi], 5 nodes in closed form (exact to degree
/// 9): the ellipsoid's and the capsule's tests integrate with it (their
/// tolerances are derived for its roundings).
pub(super) fn gauss5(lo: f64, hi: f64) -> Vec<(f64, f64)> {
    let p = (5.0 - 2.0 * (10.0f64 / 7.0).sqrt()).sqrt() / 3.0;
    let q = (5.0 + 2.0 * (10.0f64 / 7.0).sqrt()).sqrt() / 3.0;
    let wp = (322.0 + 13.0 * 70.0f64.sqrt()) / 900.0;
    let wq = (322.0 - 13.0 * 70.0f64.sqrt()) / 900.0;
    [(0.0, 128.0 / 225.0), (p, wp), (-p, wp), (q, wq), (-q, wq)]
        .iter()
        .map(|(x, w)| (lo + (hi - lo) * (x + 1.0) / 2.0, w * (hi - lo) / 2.0))
        .collect()
}

/// Gauss–Legendre nodes and weights on [lo, hi], 8 points (exact to
/// degree 15).
fn gauss(lo: f64, hi: f64) -> Vec<(f64, f64)> {
    const X: [f64; 4] = [
        0.183_434_642_495_649_8,
        0.525_532_409_916_329,
        0.796_666_477_413_626_7,
        0.960_289_856_497_536_2,
    ];
    const W: [f64; 4] = [
        0.362_683_783_378_362,
        0.313_706_645_877_887_3,
        0.222_381_034_453_374_5,
        0.101_228_536_290_376_3,
    ];
    let (mid, half) = ((lo + hi) / 2.0, (hi - lo) / 2.0);
    X.iter()
        .zip(W)
        .flat_map(|(&x, w)| [(mid - half * x, w * half), (mid + half * x, w * half)])
        .collect()
}

/// The trapezoid rule on a full turn, exact for trigonometric polynomials
/// of degree below `n`.
fn turn(n: usize) -> Vec<(f64, f64)> {
    let h = 2.0 * std::f64::consts::PI / n as f64;
    (0..n).map(|k| (k as f64 * h, h)).collect()
}

/// Volume, centroid and ∫(p − c)(p − c)ᵀ dV / V of weighted sample points.
struct Moments {
    volume: f64,
    centroid: [f64; 3],
    second: [[f64; 3]; 3],
}

fn moments(points: &[([f64; 3], f64)]) -> Moments {
    let volume: f64 = points.iter().map(|p| p.1).sum();
    let centroid: [f64; 3] =
        std::array::from_fn(|i| points.iter().map(|(p, w)| p[i] * w).sum::<f64>() / volume);
    let second = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            points
                .iter()
                .map(|(p, w)| (p[i] - centroid[i]) * (p[j] - centroid[j]) * w)
                .sum::<f64>()
                / volume
        })
    });
    Moments {
        volume,
        centroid,
        second,
    }
}

fn close(a: f64, b: f64, tol: f64, what: &str) {
    assert!(
        (a - b).abs() <= tol * b.abs().max(f64::MIN_POSITIVE),
        "{what}: {a:e} vs {b:e} (relative {:e})",
        (a - b).abs() / b.abs()
    );
}

/// A closed form (per unit mass, about the centroid, diagonal) against the
/// quadrature's, and its offset along z.
#[allow(clippy::needless_range_loop)]
fn check(shape: Shape, d: &[f64], q: &Moments, tol: f64, what: &str) {
    let c = shape.second_moments(1.0, d);
    let scale = c.iter().fold(0.0f64, |m, x| m.max(*x));
    for k in 0..3 {
        close(
            c[k],
            q.second[k][k],
            tol,
            &format!("{what}: second moment {k}"),
        );
        for l in 0..3 {
            if l != k {
                assert!(q.second[k][l].abs() <= 1e-12 * scale, "{what}: product");
            }
        }
    }
    let size = d.iter().fold(0.0f64, |m, x| m.max(*x));
    assert!(
        (shape.axial_offset(d) - q.centroid[2]).abs() <= tol * size,
        "{what}: centroid {} vs {}",
        shape.axial_offset(d),
        q.centroid[2]
    );
    assert!(q.centroid[0].abs() <= 1e-14 * size && q.centroid[1].abs() <= 1e-14 * size);
}

/// A cone or frustum [R₀, a₀, R₁, a₁, L] by quadrature in z, r and θ (a
/// thin shell: over its surface, weight ∝ radius).
fn cone_quadrature(d: [f64; 5]) -> Moments {
    let [r0, a0, r1, a1, l] = d;
    let mut pts = Vec::new();
    for (z, wz) in gauss(-l / 2.0, l / 2.0) {
        let t = z / l + 0.5;
        // The wall from the ends' own (exact) differences: the outer and
        // inner radii formed apart would lose its digits when thin.
        let inner = a0 + (a1 - a0) * t;
        let wall = (r0 - a0) + ((r1 - a1) - (r0 - a0)) * t;
        let outer = inner + wall;
        for (th, wt) in turn(8) {
            if wall == 0.0 {
                pts.push(([outer * th.cos(), outer * th.sin(), z], outer * wz * wt));
                continue;
            }
            for (x, wx) in gauss(0.0, 1.0) {
                let (r, wr) = (inner + wall * x, wall * wx);
                pts.push(([r * th.cos(), r * th.sin(), z], r * wr * wz * wt));
            }
        }
    }
    moments(&pts)
}

#[test]
fn cone_closed_forms_match_quadrature() {
    let cases: [([f64; 5], &str); 9] = [
        ([0.4, 0.0, 0.0, 0.0, 1.3], "full cone"),
        ([0.0, 0.0, 0.4, 0.0, 1.3], "inverted cone"),
        ([0.4, 0.0, 0.25, 0.0, 0.7], "frustum"),
        ([0.3, 0.0, 0.3, 0.0, 2.0], "cylinder"),
        ([0.4, 0.3, 0.2, 0.05, 0.9], "hollow frustum"),
        ([0.4, 0.4 - 4e-10, 0.1, 0.1 - 4e-10, 0.9], "wall 1e-9"),
        ([0.4, 0.4, 0.1, 0.1, 0.9], "thin shell"),
        ([1e-4, 0.0, 0.0, 0.0, 10.0], "slender"),
        ([10.0, 2.0, 9.0, 1.0, 1e-3], "flat"),
    ];
    for (d, what) in cases {
        let q = cone_quadrature(d);
        check(Shape::Cone, &d, &q, 1e-12, what);
        if d[1] != d[0] || d[3] != d[2] {
            close(Shape::Cone.measure(&d), q.volume, 1e-12, what);
        } else {
            assert_eq!(Shape::Cone.measure(&d), 0.0);
        }
    }
    // Textbook values: a full cone's centroid a quarter of the way up,
    // I about its axis 3/10 m R².
    let s = Shape::Cone.second_moments(1.0, &[2.0, 0.0, 0.0, 0.0, 4.0]);
    close(s[0] + s[1], 0.3 * 4.0, 1e-15, "3/10 m R²");
    close(
        Shape::Cone.axial_offset(&[2.0, 0.0, 0.0, 0.0, 4.0]),
        -1.0,
        1e-15,
        "L/4",
    );
}

/// A torus [R, a, b] by quadrature over its tube's section (s, φ) and θ.
fn torus_quadrature(d: [f64; 3]) -> Moments {
    let [big, a, b] = d;
    let mut pts = Vec::new();
    let radial = if a == b { vec![(a, 1.0)] } else { gauss(b, a) };
    for (s, ws) in radial {
        for (phi, wp) in turn(8) {
            let rho = big + s * phi.cos();
            for (th, wt) in turn(8) {
                pts.push((
                    [rho * th.cos(), rho * th.sin(), s * phi.sin()],
                    s * rho * ws * wp * wt,
                ));
            }
        }
    }
    moments(&pts)
}

#[test]
fn torus_closed_forms_match_quadrature() {
    for (d, what) in [
        ([1.0, 0.25, 0.0], "solid"),
        ([1.0, 0.25, 0.2], "hollow"),
        ([1.0, 1.0, 0.0], "horn"),
        ([1.0, 1e-6, 0.0], "tiny tube"),
        ([1.0, 0.3, 0.3 - 3e-10], "wall 1e-9"),
        ([1.0, 0.3, 0.3], "thin shell"),
    ] {
        let q = torus_quadrature(d);
        check(Shape::Torus, &d, &q, 1e-12, what);
        if d[1] != d[2] {
            close(Shape::Torus.measure(&d), q.volume, 1e-12, what);
        }
    }
}

/// A hemisphere [R, r] by quadrature in r, u = cos φ ∈ [0, 1] and θ.
fn hemisphere_quadrature(d: [f64; 2]) -> Moments {
    let [big, small] = d;
    let mut pts = Vec::new();
    let radial = if big == small {
        vec![(big, 1.0)]
    } else {
        gauss(small, big)
    };
    for (r, wr) in radial {
        for (u, wu) in gauss(0.0, 1.0) {
            let s = (1.0 - u * u).sqrt();
            for (th, wt) in turn(8) {
                pts.push((
                    [r * s * th.cos(), r * s * th.sin(), r * u],
                    r * r * wr * wu * wt,
                ));
            }
        }
    }
    moments(&pts)
}

#[test]
fn hemisphere_closed_forms_match_quadrature() {
    for (d, what) in [
        ([0.5, 0.0], "solid"),
        ([0.5, 0.3], "hollow"),
        ([0.5, 0.5 - 5e-10], "wall 1e-9"),
        ([0.5, 0.5], "thin shell"),
    ] {
        let q = hemisphere_quadrature(d);
        check(Shape::Hemisphere, &d, &q, 1e-12, what);
        if d[0] != d[1] {
            close(Shape::Hemisphere.measure(&d), q.volume, 1e-12, what);
        }
    }
    close(
        Shape::Hemisphere.axial_offset(&[8.0, 0.0]),
        3.0,
        1e-15,
        "3R/8",
    );
}

/// A polygon's area, centroid and per-area second moments by a fan of
/// triangles from an interior point `o` (the polygon star-shaped about
/// it), each by the triangle's own formula: centroid the vertices' mean,
/// ∫(p − g)(p − g)ᵀ dA = (A/12) Σ dᵢdᵢᵀ, dᵢ the vertices less it.
fn fan(p: &[[f64; 2]], o: [f64; 2]) -> (f64, [f64; 2], [f64; 3]) {
    let n = p.len();
    let tris: Vec<(f64, [f64; 2], [f64; 3])> = (0..n)
        .map(|i| {
            let v = [o, p[i], p[(i + 1) % n]];
            let area = ((v[1][0] - o[0]) * (v[2][1] - o[1]) - (v[2][0] - o[0]) * (v[1][1] - o[1]))
                .abs()
                / 2.0;
            let g = [
                (v[0][0] + v[1][0] + v[2][0]) / 3.0,
                (v[0][1] + v[1][1] + v[2][1]) / 3.0,
            ];
            let mut c = [0.0; 3];
            for q in v {
                let (dx, dy) = (q[0] - g[0], q[1] - g[1]);
                c[0] += dx * dx * area / 12.0;
                c[1] += dy * dy * area / 12.0;
                c[2] += dx * dy * area / 12.0;
            }
            (area, g, c)
        })
        .collect();
    let area: f64 = tris.iter().map(|t| t.0).sum();
    let g = [0, 1].map(|k| tris.iter().map(|t| t.0 * t.1[k]).sum::<f64>() / area);
    // Parallel axes: each triangle's own plus A (gᵢ − g)(gᵢ − g)ᵀ.
    let mut c = [0.0; 3];
    for (a, gi, ci) in &tris {
        let (dx, dy) = (gi[0] - g[0], gi[1] - g[1]);
        c[0] += ci[0] + a * dx * dx;
        c[1] += ci[1] + a * dy * dy;
        c[2] += ci[2] + a * dx * dy;
    }
    (area, g, c.map(|x| x / area))
}

#[test]
#[allow(clippy::needless_range_loop)]
fn prism_polygons_match_their_triangulation() {
    // A star-shaped polygon of 40 vertices about (0.3, −0.2), either
    // orientation, and far from its origin.
    let mut seed = 12345u64;
    let mut rand = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for offset in [[0.0, 0.0], [1e6, -3e5]] {
        let o = [0.3 + offset[0], -0.2 + offset[1]];
        let star: Vec<[f64; 2]> = (0..40)
            .map(|k| {
                let th = 2.0 * std::f64::consts::PI * k as f64 / 40.0;
                let r = 0.5 + rand();
                [o[0] + r * th.cos(), o[1] + r * th.sin()]
            })
            .collect();
        let reversed: Vec<[f64; 2]> = star.iter().rev().copied().collect();
        let (area, g, c) = fan(&star, o);
        let tol = if offset[0] == 0.0 { 1e-13 } else { 1e-9 };
        for poly in [&star, &reversed] {
            let p = polygon(poly);
            close(p.area.f64(), area, tol, "area");
            for k in 0..2 {
                assert!((p.centroid[k].f64() - g[k]).abs() <= 1e-15 * g[k].abs().max(1.0) + tol);
            }
            for k in 0..3 {
                assert!(
                    (p.second[k].f64() - c[k]).abs() <= tol * c[0].max(c[1]),
                    "{k}: {:e} vs {:e}",
                    p.second[k].f64(),
                    c[k]
                );
            }
        }
    }
}

#[test]
#[allow(clippy::needless_range_loop)]
fn a_rectangular_prism_is_the_box_and_an_l_two_boxes() {
    let (a, b, l) = (0.6, 0.25, 1.5);
    let p = polygon(&[[0.0, 0.0], [a, 0.0], [a, b], [0.0, b]]);
    let boxed = Shape::Box.second_moments(1.0, &[a, b, l]);
    close(p.second[0].f64(), boxed[0], 1e-15, "x");
    close(p.second[1].f64(), boxed[1], 1e-15, "y");
    assert!(p.second[2].f64().abs() <= 1e-16);
    // An L: the boxes [0, 2] × [0, 1] and [0, 1] × [1, 3], by parallel
    // axes about their common centroid.
    let l_shape = polygon(&[
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 3.0],
        [0.0, 3.0],
    ]);
    let boxes = [([1.0, 0.5], [2.0, 1.0]), ([0.5, 2.0], [1.0, 2.0])];
    let area: f64 = boxes.iter().map(|(_, s)| s[0] * s[1]).sum();
    let g = [0, 1].map(|k| boxes.iter().map(|(c, s)| s[0] * s[1] * c[k]).sum::<f64>() / area);
    let mut c = [0.0; 3];
    for (ci, s) in boxes {
        let m = s[0] * s[1];
        let (dx, dy) = (ci[0] - g[0], ci[1] - g[1]);
        c[0] += m * (s[0] * s[0] / 12.0 + dx * dx);
        c[1] += m * (s[1] * s[1] / 12.0 + dy * dy);
        c[2] += m * dx * dy;
    }
    close(l_shape.area.f64(), area, 1e-15, "L area");
    for k in 0..3 {
        close(l_shape.second[k].f64(), c[k] / area, 1e-14, "L");
    }
    close(l_shape.centroid[0].f64(), g[0], 1e-15, "L centroid x");
}
