//! Exact orientation predicates on f64 points: the sign of a 3×3 (orient3d)
//! or 2×2 (orient2d) determinant of coordinate differences, computed in
//! f64 with a forward error bound and, when the bound cannot decide, again
//! exactly in floating-point expansions (Shewchuk 1997: two-sum and
//! two-product, sums and products of non-overlapping expansions).
//!
//! NOTE: exact only where no product underflows or overflows: the callers
//! (`shells`) scale a mesh's coordinates by a power of two so that the
//! largest is below 1, and refuse a mesh with a nonzero coordinate below
//! `TINY` of that. Every coordinate is then a multiple of 2⁻²⁵², so every
//! term of a degree-3 determinant is a multiple of 2⁻⁷⁵⁶: each rounding
//! error the expansions keep is representable, and nothing overflows.

/// The least nonzero scaled coordinate the predicates are exact for.
pub const TINY: f64 = 6.223_015_277_861_142e-61; // 2⁻²⁰⁰

pub type P3 = [f64; 3];

/// The sign (−1, 0, 1) of ((b − a) × (c − a)) · (d − a): positive when d
/// is on the side the right-hand normal of the triangle (a, b, c) points.
pub fn orient3d(a: P3, b: P3, c: P3, d: P3) -> i8 {
    // NOTE: two equal points (a corner two triangles share, the common
    // case in a mesh) make the determinant exactly zero, which the filter
    // below cannot see through the roundings of the other differences.
    if a == d || b == d || c == d || a == b || a == c || b == c {
        return 0;
    }
    let ba = sub3(b, a);
    let ca = sub3(c, a);
    let da = sub3(d, a);
    let x = [
        ba[1] * ca[2] - ba[2] * ca[1],
        ba[2] * ca[0] - ba[0] * ca[2],
        ba[0] * ca[1] - ba[1] * ca[0],
    ];
    let det = x[0] * da[0] + x[1] * da[1] + x[2] * da[2];
    let m = |v: P3| v.map(f64::abs);
    let (bm, cm, dm) = (m(ba), m(ca), m(da));
    let permanent = (bm[1] * cm[2] + bm[2] * cm[1]) * dm[0]
        + (bm[2] * cm[0] + bm[0] * cm[2]) * dm[1]
        + (bm[0] * cm[1] + bm[1] * cm[0]) * dm[2];
    if permanent == 0.0 {
        // Every term has a factor that is an exact zero (a difference of
        // floats is zero only when they are equal).
        return 0;
    }
    // Shewchuk's first bound, (7 + 56ε)ε, with slack.
    let bound = 1e-15 * permanent;
    if det > bound {
        return 1;
    }
    if det < -bound {
        return -1;
    }
    orient3d_exact(a, b, c, d)
}

/// A triangle's plane, for the sides of many points: `orient3d(a, b, c,
/// d)` with the cross product (b − a) × (c − a) and its magnitudes
/// computed once.
pub struct Plane {
    a: P3,
    b: P3,
    c: P3,
    x: P3,
    xm: P3,
    /// The corners are pairwise distinct.
    distinct: bool,
}

impl Plane {
    pub fn of(t: &[P3; 3]) -> Plane {
        let [a, b, c] = *t;
        let (x, xm) = normal(t);
        Plane {
            a,
            b,
            c,
            x,
            xm,
            distinct: a != b && a != c && b != c,
        }
    }

    /// `orient3d(a, b, c, d)`, the same sign (both are exact; the filter
    /// is the same expression).
    pub fn side(&self, d: P3) -> i8 {
        let (a, b, c) = (self.a, self.b, self.c);
        if !self.distinct || a == d || b == d || c == d {
            return 0;
        }
        let da = sub3(d, a);
        let x = self.x;
        let det = x[0] * da[0] + x[1] * da[1] + x[2] * da[2];
        let dm = da.map(f64::abs);
        let permanent = self.xm[0] * dm[0] + self.xm[1] * dm[1] + self.xm[2] * dm[2];
        if permanent == 0.0 {
            return 0;
        }
        let bound = 1e-15 * permanent;
        if det > bound {
            return 1;
        }
        if det < -bound {
            return -1;
        }
        orient3d_exact(a, b, c, d)
    }
}

/// The sign of (b − a)ᵢ(c − a)ⱼ − (b − a)ⱼ(c − a)ᵢ for the coordinates
/// (i, j): the orientation of the triangle projected on that plane.
pub fn orient2d(a: P3, b: P3, c: P3, i: usize, j: usize) -> i8 {
    let same = |p: P3, q: P3| p[i] == q[i] && p[j] == q[j];
    if same(a, b) || same(a, c) || same(b, c) {
        return 0;
    }
    let (b0, b1) = (b[i] - a[i], b[j] - a[j]);
    let (c0, c1) = (c[i] - a[i], c[j] - a[j]);
    let det = b0 * c1 - b1 * c0;
    let permanent = (b0 * c1).abs() + (b1 * c0).abs();
    if permanent == 0.0 {
        return 0;
    }
    let bound = 1e-15 * permanent;
    if det > bound {
        return 1;
    }
    if det < -bound {
        return -1;
    }
    // NOTE: the common near-zero case (axis-aligned faces, corners on a
    // grid) has exact differences: then the determinant is exactly the
    // four-term sum of two two-products, summed here without allocating.
    let exact = |x: f64, y: f64, d: f64| two_sum(x, -y).1 == 0.0 && d == x - y;
    if exact(b[i], a[i], b0)
        && exact(b[j], a[j], b1)
        && exact(c[i], a[i], c0)
        && exact(c[j], a[j], c1)
    {
        let (p, pe) = two_product(b0, c1);
        let (q, qe) = two_product(b1, c0);
        let mut out = [0.0; 4];
        let mut len = 0;
        for x in [pe, p, -qe, -q] {
            // Grow the expansion `out[..len]` by x.
            let mut q = x;
            let mut k = 0;
            for idx in 0..len {
                let (s, h) = two_sum(q, out[idx]);
                if h != 0.0 {
                    out[k] = h;
                    k += 1;
                }
                q = s;
            }
            if q != 0.0 {
                out[k] = q;
                k += 1;
            }
            len = k;
        }
        return sign(&out[..len]);
    }
    let d = |x: f64, y: f64| diff(x, y);
    let l = mul(&d(b[i], a[i]), &d(c[j], a[j]));
    let r = mul(&d(b[j], a[j]), &d(c[i], a[i]));
    sign(&add(&l, &negate(&r)))
}

/// The filter's normal of the triangle (a, b, c): x = (b − a) × (c − a)
/// in f64, and each component's magnitude bound (the same products
/// without cancellation), for `Plane::side` and the crossing search's
/// planes (`shells::crossing::Flat`).
#[inline]
pub fn normal(t: &[P3; 3]) -> (P3, P3) {
    let [a, b, c] = *t;
    let ba = sub3(b, a);
    let ca = sub3(c, a);
    let (bm, cm) = (ba.map(f64::abs), ca.map(f64::abs));
    (
        [
            ba[1] * ca[2] - ba[2] * ca[1],
            ba[2] * ca[0] - ba[0] * ca[2],
            ba[0] * ca[1] - ba[1] * ca[0],
        ],
        [
            bm[1] * cm[2] + bm[2] * cm[1],
            bm[2] * cm[0] + bm[0] * cm[2],
            bm[0] * cm[1] + bm[1] * cm[0],
        ],
    )
}

fn sub3(a: P3, b: P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn orient3d_exact(a: P3, b: P3, c: P3, d: P3) -> i8 {
    let ba: [Vec<f64>; 3] = std::array::from_fn(|k| diff(b[k], a[k]));
    let ca: [Vec<f64>; 3] = std::array::from_fn(|k| diff(c[k], a[k]));
    let da: [Vec<f64>; 3] = std::array::from_fn(|k| diff(d[k], a[k]));
    let minor = |i: usize, j: usize| add(&mul(&ba[i], &ca[j]), &negate(&mul(&ba[j], &ca[i])));
    let det = add(
        &add(&mul(&minor(1, 2), &da[0]), &mul(&minor(2, 0), &da[1])),
        &mul(&minor(0, 1), &da[2]),
    );
    sign(&det)
}

fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// x − y exactly, as an expansion (least significant first, no zeros).
fn diff(x: f64, y: f64) -> Vec<f64> {
    let (s, e) = two_sum(x, -y);
    [e, s].into_iter().filter(|v| *v != 0.0).collect()
}

/// e + b exactly (Shewchuk's GROW-EXPANSION, zeros eliminated).
fn grow(e: &[f64], b: f64) -> Vec<f64> {
    let mut out = Vec::with_capacity(e.len() + 1);
    let mut q = b;
    for &x in e {
        let (s, h) = two_sum(q, x);
        if h != 0.0 {
            out.push(h);
        }
        q = s;
    }
    if q != 0.0 || out.is_empty() {
        out.push(q);
    }
    out.retain(|v| *v != 0.0);
    out
}

fn add(e: &[f64], f: &[f64]) -> Vec<f64> {
    let mut out: Vec<f64> = e.to_vec();
    for &x in f {
        out = grow(&out, x);
    }
    out
}

fn negate(e: &[f64]) -> Vec<f64> {
    e.iter().map(|x| -x).collect()
}

/// e · b exactly (Shewchuk's SCALE-EXPANSION, zeros eliminated).
fn scale(e: &[f64], b: f64) -> Vec<f64> {
    let mut out = Vec::with_capacity(2 * e.len());
    let Some((&first, rest)) = e.split_first() else {
        return out;
    };
    let (mut q, h) = two_product(first, b);
    out.push(h);
    for &x in rest {
        let (p1, p0) = two_product(x, b);
        let (sum, h) = two_sum(q, p0);
        out.push(h);
        // Fast-two-sum: |p1| ≥ |sum|.
        let s = p1 + sum;
        out.push(sum - (s - p1));
        q = s;
    }
    out.push(q);
    out.retain(|v| *v != 0.0);
    out
}

fn mul(e: &[f64], f: &[f64]) -> Vec<f64> {
    let mut out = Vec::new();
    for &x in f {
        out = add(&out, &scale(e, x));
    }
    out
}

/// The sign of a non-overlapping expansion: its most significant nonzero
/// component's.
fn sign(e: &[f64]) -> i8 {
    match e.iter().rev().find(|v| **v != 0.0) {
        Some(v) if *v > 0.0 => 1,
        Some(_) => -1,
        None => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_above_a_counter_clockwise_triangle_is_positive() {
        let (a, b, c) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        assert_eq!(orient3d(a, b, c, [0.2, 0.2, 1.0]), 1);
        assert_eq!(orient3d(a, b, c, [0.2, 0.2, -1.0]), -1);
        assert_eq!(orient3d(a, b, c, [5.0, -3.0, 0.0]), 0);
    }

    #[test]
    fn a_point_a_rounding_off_the_plane_is_told_exactly() {
        // The plane x + y + z = 1 through three points, and a point on it
        // whose naive determinant rounds; and one an ulp above.
        let (a, b, c) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
        let on = [0.1, 0.2, 0.7];
        // 0.1 + 0.2 + 0.7 is not exactly 1 in binary: the exact sign is
        // that of (0.1 + 0.2 + 0.7 − 1) computed in rationals.
        let exact = {
            use std::cmp::Ordering;
            // Sum exactly with expansions.
            let s = add(&add(&[0.1], &[0.2]), &add(&[0.7], &[-1.0]));
            match sign(&s).cmp(&0) {
                Ordering::Greater => 1,
                Ordering::Less => -1,
                Ordering::Equal => 0,
            }
        };
        assert_eq!(orient3d(a, b, c, on), exact);
        let up = [0.1, 0.2, f64::from_bits(0.7f64.to_bits() + 1)];
        assert_eq!(orient3d(a, b, c, up), 1);
    }

    #[test]
    fn the_exact_path_agrees_with_the_filter_on_clear_cases() {
        let mut x = 0x2545_f491_4f6c_dd1du64;
        let mut r = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for _ in 0..2000 {
            let p: [P3; 4] = std::array::from_fn(|_| [r(), r(), r()]);
            assert_eq!(
                orient3d(p[0], p[1], p[2], p[3]),
                orient3d_exact(p[0], p[1], p[2], p[3])
            );
        }
    }

    #[test]
    fn a_plane_gives_orient3d_s_sign() {
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        let mut r = |grid: bool| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let v = (x >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            if grid { (v * 8.0).round() / 4.0 } else { v }
        };
        for k in 0..4000 {
            // Points on a coarse grid half the time: coplanar and equal
            // corners are common there.
            let g = k % 2 == 0;
            let t: [P3; 3] = std::array::from_fn(|_| [r(g), r(g), r(g)]);
            let d = if k % 7 == 0 {
                t[k % 3]
            } else {
                [r(g), r(g), r(g)]
            };
            assert_eq!(Plane::of(&t).side(d), orient3d(t[0], t[1], t[2], d));
        }
    }

    #[test]
    fn orient2d_is_exact_for_nearly_collinear_points() {
        let a = [0.5, 0.5, 9.0];
        let b = [12.0, 12.0, 9.0];
        let c = [24.0, 24.0, 9.0];
        assert_eq!(orient2d(a, b, c, 0, 1), 0);
        let c2 = [24.0, f64::from_bits(24.0f64.to_bits() + 1), 9.0];
        assert_eq!(orient2d(a, b, c2, 0, 1), 1);
    }
}
