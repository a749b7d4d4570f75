//! Eigenvalues and eigenvectors of a symmetric 3×3 matrix by the cyclic
//! Jacobi method, in f64 or double-double.
//!
//! NOTE: Jacobi, not nalgebra's `SymmetricEigen` (tridiagonal QR). For a
//! positive semi-definite matrix, Jacobi with the stopping test
//! |a_pq| ≤ ε √(a_pp a_qq) computes every eigenvalue, the small ones too, to
//! a relative accuracy set by the matrix's scaled condition number rather
//! than by its largest eigenvalue (Demmel and Veselić, "Jacobi's method is
//! more accurate than QR", 1992). A second moment of a body is positive
//! semi-definite, and the small eigenvalues are the ones that matter: the
//! smallest principal moment of a slender body is the sum of the two
//! smallest.

use crate::numeric::{M3, Real};

/// Sweeps before giving up. A 3×3 matrix converges quadratically in 3 to 6
/// sweeps in f64 and a few more in double-double.
const MAX_SWEEPS: usize = 60;

/// Eigen-decomposition of a symmetric `a`: eigenvalues (unordered) and the
/// matrix whose columns are the matching unit eigenvectors. `None` only if
/// an entry is not finite (NaN or infinity in, as from a second moment that
/// overflowed) or an eigenvalue is beyond the range of f64: on finite input
/// the cyclic Jacobi method converges, quadratically, in a few sweeps.
pub fn jacobi<T: Real>(a: M3<T>) -> Option<([T; 3], M3<T>)> {
    jacobi_counted(a).map(|(lam, v, _)| (lam, v))
}

/// `jacobi`, with the number of plane rotations it applied: each adds a
/// backward error of a few roundings, which the error bounds count
/// (`bounds::eigen`).
pub fn jacobi_counted<T: Real>(a: M3<T>) -> Option<([T; 3], M3<T>, usize)> {
    if !a.iter().flatten().all(|x| x.is_finite()) {
        return None;
    }
    // NOTE: scaled by a power of two (exact) so that the largest entry is
    // near 1, and the eigenvalues scaled back: near the ends of the range a
    // step could overflow (a_qq − a_pp of entries of opposite signs near
    // 1e308, or g + h) or lose digits to subnormals. The eigenvectors do
    // not change.
    let big = a.iter().flatten().fold(0.0f64, |m, x| m.max(x.f64().abs()));
    if big == 0.0 {
        return Some((
            [T::of(0.0); 3],
            std::array::from_fn(|i| std::array::from_fn(|j| T::of(if i == j { 1.0 } else { 0.0 }))),
            0,
        ));
    }
    let e = big.log2().floor() as i32;
    let (lam, v, rotations) = jacobi_scaled(a.map(|r| r.map(|x| times_pow2(x, -e))))?;
    let lam = lam.map(|x| times_pow2(x, e));
    lam.iter()
        .all(|x| x.is_finite())
        .then_some((lam, v, rotations))
}

/// `x` times 2^`k`, exact (barring underflow), for any `k` between the
/// exponents of the smallest subnormal and the largest f64.
fn times_pow2<T: Real>(x: T, k: i32) -> T {
    // 2^n for |n| ≤ 1022, a normal f64: its exponent field alone.
    let pow2 = |n: i32| f64::from_bits(((n + 1023) as u64) << 52);
    let half = k / 2;
    x * T::of(pow2(half)) * T::of(pow2(k - half))
}

/// `jacobi` of a matrix whose entries are at most about 1 in magnitude.
fn jacobi_scaled<T: Real>(mut a: M3<T>) -> Option<([T; 3], M3<T>, usize)> {
    let zero = T::of(0.0);
    let one = T::of(1.0);
    let mut v = [[zero; 3]; 3];
    for (k, row) in v.iter_mut().enumerate() {
        row[k] = one;
    }
    let mut rotations = 0;
    for _ in 0..MAX_SWEEPS {
        let mut rotated = false;
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            let apq = a[p][q];
            if apq == zero {
                continue;
            }
            let (app, aqq) = (a[p][p], a[q][q]);
            // Off-diagonal negligible relative to its own diagonal entries
            // (√a·√b, not √(ab): the product can overflow or underflow).
            if apq.abs() <= T::of(T::EPS) * app.abs().sqrt() * aqq.abs().sqrt() {
                a[p][q] = zero;
                a[q][p] = zero;
                continue;
            }
            rotated = true;
            rotations += 1;
            // The rotation angle: tan 2φ = 2 a_pq / (a_qq − a_pp); t = tan φ
            // is the smaller root of t² + 2θt − 1 = 0, |φ| ≤ π/4.
            let diff = aqq - app;
            // |θ| beyond 1e150: t = 1/(2θ) = a_pq/(a_qq − a_pp), formed
            // without θ itself, which could overflow.
            let t = if apq.abs().f64() * 1e150 < diff.abs().f64() {
                apq / diff
            } else {
                let theta = diff / (T::of(2.0) * apq);
                // √(θ² + 1) as |θ| √(1 + 1/θ²) beyond 1: θ² may overflow.
                let r = if theta.abs() > one {
                    theta.abs() * (one + one / (theta * theta)).sqrt()
                } else {
                    (theta * theta + one).sqrt()
                };
                let t = one / (theta.abs() + r);
                if theta < zero { -t } else { t }
            };
            let c = one / (t * t + one).sqrt();
            let s = t * c;
            let tau = s / (one + c);
            a[p][p] = app - t * apq;
            a[q][q] = aqq + t * apq;
            a[p][q] = zero;
            a[q][p] = zero;
            let r = 3 - p - q;
            let (g, h) = (a[r][p], a[r][q]);
            a[r][p] = g - s * (h + g * tau);
            a[p][r] = a[r][p];
            a[r][q] = h + s * (g - h * tau);
            a[q][r] = a[r][q];
            for row in v.iter_mut() {
                let (g, h) = (row[p], row[q]);
                row[p] = g - s * (h + g * tau);
                row[q] = h + s * (g - h * tau);
            }
        }
        if !rotated {
            let lam = [a[0][0], a[1][1], a[2][2]];
            return lam
                .iter()
                .all(|x| x.is_finite())
                .then_some((lam, v, rotations));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::DD;

    fn rotation(axis: [f64; 3], deg: f64) -> M3<f64> {
        let n = axis.iter().map(|x| x * x).sum::<f64>().sqrt();
        let k = axis.map(|x| x / n);
        let (s, c) = f64::sin_cos_deg(deg);
        let mut r = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                let cross = match (i, j) {
                    (0, 1) => -k[2],
                    (0, 2) => k[1],
                    (1, 0) => k[2],
                    (1, 2) => -k[0],
                    (2, 0) => -k[1],
                    (2, 1) => k[0],
                    _ => 0.0,
                };
                r[i][j] = if i == j { c } else { 0.0 } + s * cross + (1.0 - c) * k[i] * k[j];
            }
        }
        r
    }

    fn rdrt(r: &M3<f64>, d: [f64; 3]) -> M3<f64> {
        let mut a = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                a[i][j] = (0..3).map(|k| r[i][k] * d[k] * r[j][k]).sum();
            }
        }
        a
    }

    #[test]
    fn eigenpairs_satisfy_a_v_equals_lambda_v() {
        let a = rdrt(&rotation([1.0, -2.0, 0.5], 33.0), [1.0, 2.5, 4.0]);
        let (lam, v) = jacobi(a).unwrap();
        for k in 0..3 {
            for i in 0..3 {
                let av: f64 = (0..3).map(|j| a[i][j] * v[j][k]).sum();
                assert!((av - lam[k] * v[i][k]).abs() < 1e-14, "{k} {i}");
            }
        }
        let mut sorted = lam;
        sorted.sort_by(f64::total_cmp);
        for (x, e) in sorted.iter().zip([1.0, 2.5, 4.0]) {
            assert!((x - e).abs() < 4e-15);
        }
    }

    #[test]
    fn graded_matrix_keeps_its_tiny_eigenvalue_to_full_relative_accuracy() {
        // diag(1, 1e-10, 1e-20) with off-diagonals that couple them at the
        // geometric mean: a QR-based solver gets the 1e-20 eigenvalue only
        // to ±1e-16 absolute. The exact eigenvalues of this matrix are those
        // of the scaled form D^½ B D^½, B = [[1, .1, 0], [.1, 1, .1], [0, .1, 1]].
        let d = [1.0, 1e-10, 1e-20];
        let b = [[1.0, 0.1, 0.0], [0.1, 1.0, 0.1], [0.0, 0.1, 1.0]];
        let a: M3<f64> =
            std::array::from_fn(|i| std::array::from_fn(|j| d[i].sqrt() * b[i][j] * d[j].sqrt()));
        let (lam, _) = jacobi(a).unwrap();
        let (lam_dd, _) = jacobi(a.map(|r| r.map(DD::of))).unwrap();
        let mut f: Vec<f64> = lam.to_vec();
        let mut e: Vec<f64> = lam_dd.iter().map(|x| x.f64()).collect();
        f.sort_by(f64::total_cmp);
        e.sort_by(f64::total_cmp);
        // Smallest ≈ 1e-20 · (1 − 0.01 − …): f64 Jacobi within a few ulps.
        assert!(e[0] > 0.9e-20 && e[0] < 1.0e-20, "{e:?}");
        for k in 0..3 {
            assert!(
                (f[k] - e[k]).abs() <= 8.0 * f64::EPSILON * e[k],
                "{k}: {f:?} {e:?}"
            );
        }
    }

    #[test]
    fn double_double_resolves_what_f64_cannot() {
        // A rod-like second moment along a general unit axis u: eigenvalues
        // 1 (along u), ε and ε. Built in DD, the ε = 1e-24 pair survives.
        let (s, c) = DD::sin_cos_deg(31.0);
        let (s2, c2) = DD::sin_cos_deg(67.0);
        let u = [c * c2, c * s2, s];
        let eps = DD::of(1e-24);
        let a: M3<DD> = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                (DD::of(1.0) - eps) * u[i] * u[j] + if i == j { eps } else { DD::of(0.0) }
            })
        });
        let (lam, _) = jacobi(a).unwrap();
        let mut l: Vec<f64> = lam.iter().map(|x| x.f64()).collect();
        l.sort_by(f64::total_cmp);
        for x in &l[..2] {
            assert!((x / 1e-24 - 1.0).abs() < 1e-6, "{l:?}");
        }
        assert!((l[2] - 1.0).abs() < 1e-15);
    }

    #[test]
    fn extreme_scales_converge_in_both_precisions() {
        // Off-diagonals 1e-200 of a diagonal difference near the top of the
        // range: θ would overflow.
        let a = [[1e300, 1e100, 0.0], [1e100, 2e300, 0.0], [0.0, 0.0, 1.0]];
        let (l, _) = jacobi(a).unwrap();
        let (d, _) = jacobi(a.map(|r| r.map(DD::of))).unwrap();
        for (x, y) in l.iter().zip(d) {
            assert!((x - y.f64()).abs() <= 4.0 * f64::EPSILON * x.abs());
        }
        // Eigenvalues beyond the range (2.7e308): None, never NaN or inf.
        let huge = [
            [1.7e308, 1e308, 0.0],
            [1e308, 1.7e308, 0.0],
            [0.0, 0.0, 1.0],
        ];
        assert!(jacobi(huge).is_none());
        assert!(jacobi(huge.map(|r| r.map(DD::of))).is_none());
    }

    /// `A v = λ v` for each pair, to `tol` of the largest entry, and the
    /// eigenvalues' sum is the trace.
    fn assert_eigenpairs(a: &M3<f64>, lam: &[f64; 3], v: &M3<f64>, tol: f64) {
        // Scaled by the largest entry, so that nothing overflows here; an
        // eigenvalue among subnormals is as exact as their spacing allows.
        let big = a
            .iter()
            .flatten()
            .fold(f64::MIN_POSITIVE, |m, x| m.max(x.abs()));
        let tol = tol + 4.0 * f64::from_bits(1) / big;
        for k in 0..3 {
            for i in 0..3 {
                let av: f64 = (0..3).map(|j| a[i][j] / big * v[j][k]).sum();
                let r = av - lam[k] / big * v[i][k];
                assert!(r.abs() <= tol, "{a:?}: {lam:?} residual {r:e}");
            }
        }
        let trace = (a[0][0] / big + a[1][1] / big) + a[2][2] / big;
        let sum = (lam[0] / big + lam[1] / big) + lam[2] / big;
        assert!((trace - sum).abs() <= tol, "{a:?}: {lam:?}");
    }

    /// The solver converges on every finite symmetric matrix whose
    /// eigenvalues are finite, whatever the scale and signs of its entries:
    /// entries from subnormal to near the largest f64, zeros, indefinite
    /// matrices (a body with cut-outs).
    #[test]
    fn finite_symmetric_matrices_always_converge() {
        let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        for case in 0..20_000 {
            // One scale for the matrix, each entry up to 40 decades below.
            let top = (next() % 617) as i32 - 308;
            let mut a = [[0.0f64; 3]; 3];
            for (i, j) in [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)] {
                let r = next();
                let x = match r % 8 {
                    0 => 0.0,
                    1 => f64::from_bits(r >> 44), // subnormal
                    _ => {
                        let m = (r >> 11) as f64 / (1u64 << 53) as f64;
                        let sign = if r & 16 == 0 { 1.0 } else { -1.0 };
                        let decades = ((r >> 5) % 40) as i32;
                        sign * m * 10f64.powi(top - decades)
                    }
                };
                a[i][j] = x;
                a[j][i] = x;
            }
            // Near the top, entries whose eigenvalues fit (|λ| ≤ 3 max|a|).
            if case % 10 == 0 {
                a = a.map(|r| {
                    r.map(|x| x.signum() * f64::MAX / 3.0 * (x.abs() / 10f64.powi(top)).min(1.0))
                });
            }
            let (lam, v) = jacobi(a).unwrap_or_else(|| panic!("case {case}: {a:?}"));
            assert_eigenpairs(&a, &lam, &v, 1e-13);
            if case % 20 == 0 {
                let (lam, v) = jacobi(a.map(|r| r.map(DD::of)))
                    .unwrap_or_else(|| panic!("DD case {case}: {a:?}"));
                let f = |m: M3<DD>| m.map(|r| r.map(|x| x.f64()));
                assert_eigenpairs(&a, &lam.map(|x| x.f64()), &f(v), 1e-13);
            }
        }
    }

    #[test]
    fn opposite_diagonals_near_the_top_of_the_range_do_not_overflow() {
        // a_qq − a_pp is 3.4e308 here: it overflowed before the scaling.
        let a = [
            [-1.7e308, 1e307, 0.0],
            [1e307, 1.7e308, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let (lam, v) = jacobi(a).unwrap();
        assert_eigenpairs(&a, &lam, &v, 1e-15);
    }

    #[test]
    fn a_matrix_of_subnormals_keeps_its_digits() {
        // 3 and 1 times the smallest subnormal: eigenvalues 4 and 2 of them.
        let t = f64::from_bits(1);
        let (lam, _) = jacobi([[3.0 * t, t, 0.0], [t, 3.0 * t, 0.0], [0.0, 0.0, 0.0]]).unwrap();
        let mut l = lam;
        l.sort_by(f64::total_cmp);
        assert_eq!(l, [0.0, 2.0 * t, 4.0 * t]);
    }

    #[test]
    fn infinity_or_nan_in_is_none_at_once() {
        for bad in [f64::INFINITY, f64::NAN] {
            let a = [[1.0, bad, 0.0], [bad, 1.0, 0.0], [0.0, 0.0, 1.0]];
            assert!(jacobi(a).is_none());
            assert!(jacobi(a.map(|r| r.map(DD::of))).is_none());
        }
    }

    #[test]
    fn diagonal_and_zero_matrices_need_no_rotation() {
        let (lam, v) = jacobi([[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 0.0]]).unwrap();
        assert_eq!(lam, [2.0, 3.0, 0.0]);
        assert_eq!(v, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        let (lam, v) = jacobi([[0.0; 3]; 3]).unwrap();
        assert_eq!(lam, [0.0; 3]);
        assert_eq!(v, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
    }
}
