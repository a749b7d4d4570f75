//! What the reference's `Scene` cannot write, exactly (issue 30 item 1):
//! parts placed by an include's frame (turned, moved, in other units),
//! copies of an `array` (copy i moved by i·step exactly, or turned by i·θ
//! about an axis), a `mirror`'s image (the reflection of the part), and a
//! triangle mesh's solid. Every body here is a list of
//! [`ExactPart`](super::reference::ExactPart)s in SI, composed by
//! [`compose_parts`](super::reference::compose_parts).
//!
//! Exact, except turns by angles whose sines are irrational: a turn by θ
//! about an axis a is the quaternion (|a| cos θ/2, sin θ/2 · a), whose
//! rotation q v q̄ / |q|² is exactly orthogonal and fixes a exactly
//! whatever q's rounding; cos and sin are their series in fixed point to
//! 2⁻³²⁰, θ in radians through the reference's 100-digit π, and |a| the
//! reference's square root (relative 2⁻²⁰⁰, exact for a square). Multiples
//! of 90° take exact values; the matrix is rounded to 2⁻³⁰⁰ ([`rounded`]).
//! So an irrational turn is within about 1e-60 of
//! the exact one: far below any error bound the tests compare (double-
//! double's unit is 5e-32), which makes the comparison exact in effect.

use super::reference::{self as r, ExactPart, M3, Q, V3};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// The part turned by `rot` about the origin, then moved by `t`:
/// centre t + R c, second moment R C Rᵀ.
pub fn placed(p: &ExactPart, rot: &M3, t: &V3) -> ExactPart {
    let c = r::mvec(rot, &p.center);
    ExactPart {
        mass: p.mass.clone(),
        center: std::array::from_fn(|i| &t[i] + &c[i]),
        second_moment: r::mmul(&r::mmul(rot, &p.second_moment), &r::transpose(rot)),
    }
}

/// The part moved by `t`.
pub fn moved(p: &ExactPart, t: &V3) -> ExactPart {
    placed(p, &identity(), t)
}

/// The part's mass and second moment times `k` (a density given apart
/// from its shape).
pub fn scaled(p: &ExactPart, k: &Q) -> ExactPart {
    ExactPart {
        mass: &p.mass * k,
        center: p.center.clone(),
        second_moment: p.second_moment.clone().map(|row| row.map(|x| x * k)),
    }
}

/// The part's numbers rounded to multiples of 2⁻³²⁰ (SI): exact for
/// every value an f64 holds above 2⁻²⁶⁷ (so an exact zero, or a value
/// massprop forms exactly, stays exact), and within 1e-96 of any other —
/// bodies of a few metres and kilograms have nothing near that. Without it
/// the sums of a few dozen parts, each with its own π and square roots,
/// carry denominators of tens of thousands of bits.
pub fn on_grid(p: &ExactPart) -> ExactPart {
    let den = Q::from_integer(BigInt::one() << 320usize);
    let g = |x: &Q| Q::from_integer(fixed(x, 320)) / &den;
    ExactPart {
        mass: g(&p.mass),
        center: std::array::from_fn(|i| g(&p.center[i])),
        second_moment: std::array::from_fn(|i| std::array::from_fn(|j| g(&p.second_moment[i][j]))),
    }
}

/// The affine map x ↦ o + M (x − o) applied to the part: a turn or a
/// reflection about the point `o`.
pub fn about_point(p: &ExactPart, m: &M3, o: &V3) -> ExactPart {
    let mo = r::mvec(m, o);
    let t: V3 = std::array::from_fn(|i| &o[i] - &mo[i]);
    placed(p, m, &t)
}

pub fn identity() -> M3 {
    std::array::from_fn(|i| std::array::from_fn(|j| if i == j { r::int(1) } else { r::int(0) }))
}

/// The reflection in the plane normal to `n` through the origin:
/// E − 2 n nᵀ / |n|², exactly.
pub fn reflection(n: &V3) -> M3 {
    let nn = r::dot(n, n);
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let e = if i == j { r::int(1) } else { r::int(0) };
            e - r::int(2) * &n[i] * &n[j] / &nn
        })
    })
}

/// `x` rounded to a multiple of 2⁻ᵇ (as the integer x·2ᵇ).
fn fixed(x: &Q, b: usize) -> BigInt {
    (x * Q::from_integer(BigInt::one() << b))
        .round()
        .to_integer()
}

const BITS: usize = 320;

/// cos x and sin x for |x| ≤ 4, by their series in fixed point (2⁻³²⁰).
fn cos_sin_radians(x: &Q) -> (Q, Q) {
    let one = BigInt::one() << BITS;
    let xf = fixed(x, BITS);
    let (mut c, mut s) = (one.clone(), BigInt::zero());
    let mut term = one.clone();
    for n in 1..200u32 {
        term = ((&term * &xf) >> BITS) / BigInt::from(n);
        if term.is_zero() {
            break;
        }
        match n % 4 {
            0 => c += &term,
            1 => s += &term,
            2 => c -= &term,
            _ => s -= &term,
        }
    }
    let den = Q::from_integer(one);
    (Q::from_integer(c) / &den, Q::from_integer(s) / den)
}

/// (cos, sin) of `deg` degrees, up to a common positive factor (exact at
/// multiples of 45°, where the factor is not 1).
fn half_turn_cs(deg: &Q) -> (Q, Q) {
    // Into [0, 720): a half angle in [0, 360).
    let full = r::int(720);
    let k = (deg / &full).floor();
    let d = deg - k * &full;
    let h = &d / r::int(2);
    let q45 = &h / r::int(45);
    if q45.is_integer() {
        let (c, s) = match q45.to_integer().to_string().as_str() {
            "0" => (1, 0),
            "1" => (1, 1),
            "2" => (0, 1),
            "3" => (-1, 1),
            "4" => (-1, 0),
            "5" => (-1, -1),
            "6" => (0, -1),
            _ => (1, -1),
        };
        return (r::int(c), r::int(s));
    }
    // Centred on 0: h − 180 in (−180, 180), then negate both (cos and sin
    // of h are minus those of h − 180°).
    let x = (h - r::int(180)) * r::pi() / r::int(180);
    let (c, s) = cos_sin_radians(&x);
    (-c, -s)
}

/// The rotation by `deg` degrees about `axis` (any non-zero length),
/// right-handed: exactly orthogonal, fixing the axis exactly (module
/// comment).
pub fn axis_turn(axis: &V3, deg: &Q) -> M3 {
    let (c, s) = half_turn_cs(deg);
    let len = r::sqrt(&r::dot(axis, axis));
    let m = r::rotation(&[&len * c, &s * &axis[0], &s * &axis[1], &s * &axis[2]]);
    rounded(&m)
}

/// Each entry rounded to a multiple of 2⁻³⁰⁰: an irrational turn's
/// rationals have denominators of a thousand bits, which nested placements
/// and the eigenvalues' exact polynomial multiply; 2⁻³⁰⁰ is far below any
/// bound compared, and an entry that is exactly 0, ±1 or a short dyadic
/// (a quarter turn's, the axis's own) stays exact.
pub fn rounded(m: &M3) -> M3 {
    let den = Q::from_integer(BigInt::one() << 300usize);
    m.clone()
        .map(|row| row.map(|x| Q::from_integer(fixed(&x, 300)) / &den))
}

/// A turn about file axis `k` (0, 1, 2).
pub fn about_axis(k: usize, deg: &Q) -> M3 {
    let e: V3 = std::array::from_fn(|i| if i == k { r::int(1) } else { r::int(0) });
    axis_turn(&e, deg)
}

/// Euler angles: intrinsic `seq` [a, b, c] is R_s0(a)·R_s1(b)·R_s2(c);
/// extrinsic is R_s2(c)·R_s1(b)·R_s0(a).
pub fn euler(seq: &str, deg: [f64; 3], intrinsic: bool) -> M3 {
    let axes: Vec<usize> = seq.bytes().map(|b| usize::from(b - b'x')).collect();
    let m: Vec<M3> = (0..3).map(|i| about_axis(axes[i], &r::q(deg[i]))).collect();
    rounded(&if intrinsic {
        r::mmul(&r::mmul(&m[0], &m[1]), &m[2])
    } else {
        r::mmul(&r::mmul(&m[2], &m[1]), &m[0])
    })
}

/// A closed triangle mesh's solid of density `rho` (SI), its corners the
/// file's numbers times `unit` (metres per mesh unit): the sum over the
/// triangles of the signed tetrahedra from the origin, each of volume
/// det[a, b, c]/6, first moment V (a + b + c)/4 and ∫x xᵀ = V/20 (a aᵀ +
/// b bᵀ + c cᵀ + s sᵀ), s = a + b + c (the divergence theorem; exact).
pub fn mesh(triangles: &[[[f64; 3]; 3]], unit: &Q, rho: &Q) -> ExactPart {
    let mut vol = Q::zero();
    let mut first: V3 = std::array::from_fn(|_| Q::zero());
    let mut second: M3 = std::array::from_fn(|_| std::array::from_fn(|_| Q::zero()));
    for t in triangles {
        let [a, b, c] = t.map(|p| p.map(|x| r::q(x) * unit));
        let v = r::dot(&a, &r::cross(&b, &c)) / r::int(6);
        let s: V3 = std::array::from_fn(|i| &a[i] + &b[i] + &c[i]);
        for i in 0..3 {
            first[i] += &v * &s[i] / r::int(4);
            for j in 0..3 {
                let sum = &a[i] * &a[j] + &b[i] * &b[j] + &c[i] * &c[j] + &s[i] * &s[j];
                second[i][j] += &v * sum / r::int(20);
            }
        }
        vol += v;
    }
    assert!(vol.is_positive(), "a mesh wound outward");
    let center: V3 = std::array::from_fn(|i| &first[i] / &vol);
    ExactPart {
        mass: rho * &vol,
        second_moment: std::array::from_fn(|i| {
            std::array::from_fn(|j| rho * (&second[i][j] - &vol * &center[i] * &center[j]))
        }),
        center,
    }
}

/// The exact value of a decimal numeral (`-12.5e-3`).
pub fn decimal(text: &str) -> Q {
    let (m, e) = match text.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<i32>().expect("an exponent")),
        None => (text, 0),
    };
    let (int, frac) = m.split_once('.').unwrap_or((m, ""));
    let digits: BigInt = format!("{int}{frac}").parse().expect("digits");
    let scale = e - frac.len() as i32;
    let ten = Q::from_integer(BigInt::from(10));
    let p = (0..scale.unsigned_abs()).fold(Q::one(), |acc, _| acc * &ten);
    let v = Q::from_integer(digits);
    if scale < 0 { v / p } else { v * p }
}

#[cfg(test)]
mod tests {
    // The benchmark compiles this module without its tests (no harness).
    #[allow(unused_imports)]
    use super::*;

    #[test]
    fn a_quarter_turn_about_z_is_exact() {
        let m = about_axis(2, &r::int(90));
        assert_eq!(
            r::fm(&m),
            [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
        );
        assert!(m.iter().flatten().all(|x| x.is_integer()));
    }

    #[test]
    fn thirty_degrees_has_a_sine_of_one_half_to_far_below_1e_40() {
        let m = about_axis(2, &r::int(30));
        let err = (&m[1][0] - r::frac(1, 2)).abs();
        assert!(
            err < Q::new(BigInt::one(), BigInt::one() << 190usize),
            "{err}"
        );
        // Orthogonal to its rounding (2⁻³⁰⁰ an entry).
        let mmt = r::mmul(&m, &r::transpose(&m));
        let tiny = Q::new(BigInt::one(), BigInt::one() << 290usize);
        let e = identity();
        for (row, want) in mmt.iter().zip(&e) {
            for (x, w) in row.iter().zip(want) {
                assert!((x - w).abs() < tiny);
            }
        }
    }

    #[test]
    fn a_turn_by_minus_ninety_about_a_long_axis_is_exact() {
        let m = axis_turn(&[r::int(0), r::int(3), r::int(0)], &r::int(-90));
        assert_eq!(
            r::fm(&m),
            [[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]
        );
    }

    #[test]
    fn a_reflection_is_its_own_inverse() {
        let s = reflection(&[r::int(1), r::int(2), r::int(-2)]);
        assert_eq!(r::mmul(&s, &s), identity());
    }

    #[test]
    fn a_unit_cube_mesh_weighs_its_density() {
        // Two triangles per face of [0, 1]³, outward.
        let v = |i: usize| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2 & 1) as f64];
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let tris: Vec<[[f64; 3]; 3]> = quads
            .iter()
            .flat_map(|q| [[v(q[0]), v(q[1]), v(q[2])], [v(q[0]), v(q[2]), v(q[3])]])
            .collect();
        let p = mesh(&tris, &r::int(1), &r::int(3));
        assert_eq!(p.mass, r::int(3));
        assert_eq!(p.center, [r::frac(1, 2), r::frac(1, 2), r::frac(1, 2)]);
        assert_eq!(p.second_moment[0][0], r::frac(1, 4));
        assert_eq!(p.second_moment[0][1], r::int(0));
    }

    #[test]
    fn a_decimal_is_read_exactly() {
        assert_eq!(decimal("-12.5e-3"), r::frac(-125, 10_000));
        assert_eq!(decimal("0.1"), r::frac(1, 10));
    }
}
