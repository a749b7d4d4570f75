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
/// matrix whose columns are the matching unit eigenvectors, or `None` if
/// the iteration does not converge or an eigenvalue is not finite (which
/// finite input does not cause).
pub fn jacobi<T: Real>(mut a: M3<T>) -> Option<([T; 3], M3<T>)> {
    let zero = T::of(0.0);
    let one = T::of(1.0);
    let mut v = [[zero; 3]; 3];
    for (k, row) in v.iter_mut().enumerate() {
        row[k] = one;
    }
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
            return lam.iter().all(|x| x.is_finite()).then_some((lam, v));
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

    #[test]
    fn diagonal_and_zero_matrices_need_no_rotation() {
        let (lam, v) = jacobi([[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 0.0]]).unwrap();
        assert_eq!(lam, [2.0, 3.0, 0.0]);
        assert_eq!(v, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
    }
}
