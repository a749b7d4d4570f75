//! Composition of parts into one body, and its principal moments and axes.

use crate::mass::MassProps;
use crate::model::Part;
use nalgebra::{Matrix3, SymmetricEigen, Vector3};

/// Principal moments within this fraction of the largest are reported as
/// equal, and their axes as not unique. 1e-9 is far above the rounding of a
/// composed tensor (~1e-15 relative) and far below any gap an engineer would
/// call distinct; below it the computed axes are noise.
pub const EQUAL_MOMENT_RTOL: f64 = 1e-9;

/// Components of a unit axis whose magnitudes differ by less than this count
/// as tied for the sign rule, so rounding cannot flip an axis.
const SIGN_TIE: f64 = 1e-9;

/// Compose parts into mass, centre of mass and second moment about it.
///
/// NOTE: two passes. The first finds the centre of mass; the second sums each
/// part's second moment with its offset *from that centre*. Summing about a
/// distant origin and shifting back subtracts two huge, nearly equal numbers
/// and loses every digit for parts 10⁹ sizes from the origin. The residual
/// first moment Σ mᵢdᵢ (zero in exact arithmetic) then corrects the rounding
/// of the centre itself: C = Σ(Cᵢ + mᵢdᵢdᵢᵀ) − s sᵀ/m and c = ĉ + s/m.
pub fn compose(parts: &[Part]) -> MassProps {
    let mass: f64 = parts.iter().map(|p| p.mass).sum();
    let first: Vector3<f64> = parts.iter().map(|p| p.center * p.mass).sum();
    let com = first / mass;
    let mut c = Matrix3::zeros();
    let mut s = Vector3::zeros();
    for p in parts {
        let d = p.center - com;
        // (m d) dᵀ, not (d dᵀ) m: d dᵀ alone can underflow or overflow.
        c += p.second_moment() + (d * p.mass) * d.transpose();
        s += d * p.mass;
    }
    MassProps {
        mass,
        center_of_mass: com + s / mass,
        // s (s/m)ᵀ, not s sᵀ/m: the square of s may overflow when m is huge.
        second_moment: c - s * (s / mass).transpose(),
    }
}

/// Principal moments (ascending) and axes of a body, with the moments that
/// are equal within `EQUAL_MOMENT_RTOL`.
#[derive(Debug, Clone, PartialEq)]
pub struct Principal {
    /// kg·m², ascending, never negative.
    pub moments: [f64; 3],
    /// `axes[i]` is the unit axis of `moments[i]`; axes[0] × axes[1] = axes[2].
    pub axes: [Vector3<f64>; 3],
    /// Indices of moments equal to each other ([] when all differ, else two
    /// or three indices). Their axes are not unique.
    pub equal: Vec<usize>,
}

/// Principal moments and axes of the second moment `c` (∫ρρᵀ dm).
///
/// NOTE: we diagonalise C, not I; they share eigenvectors, and each principal
/// moment is then a sum of two non-negative principal second moments,
/// I₁ = λ₂ + λ₃ and so on, so moments are never negative and always satisfy
/// the triangle inequality, with no cancellation in forming them.
///
/// Sign rule, deterministic. When all three moments differ: for the first
/// two axes, the component of largest magnitude is positive (among
/// components tied to within 1e-9, the first); the third axis is the cross
/// product of the first two. Where moments are equal, the axes are not
/// unique and are chosen from the file's axes instead: when all three are
/// equal, x, y, z; when two are, the axis of the distinct moment follows the
/// sign rule, the first axis of the equal pair is the file axis most nearly
/// perpendicular to it projected into their plane, and the other completes
/// a right-handed set (whatever the sign of its largest component).
///
/// Returns `None` only if the eigen solver fails to converge, which finite
/// input does not cause.
pub fn principal(c: &Matrix3<f64>) -> Option<Principal> {
    // Solve on a scaled copy so the convergence test is independent of units.
    let scale = c.amax();
    if scale == 0.0 {
        return Some(Principal {
            moments: [0.0; 3],
            axes: [Vector3::x(), Vector3::y(), Vector3::z()],
            equal: vec![0, 1, 2],
        });
    }
    let eig = SymmetricEigen::try_new(c / scale, f64::EPSILON, 10_000)?;
    let lam = eig.eigenvalues.map(|x| x.max(0.0) * scale);
    // Moment k belongs to the axis of λ_k and is the sum of the other two.
    let moment = |k: usize| lam[(k + 1) % 3] + lam[(k + 2) % 3];
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| moment(a).total_cmp(&moment(b)).then(a.cmp(&b)));
    let moments = order.map(moment);
    let vecs = order.map(|k| eig.eigenvectors.column(k).normalize());

    let close = |a: f64, b: f64| (b - a).abs() <= EQUAL_MOMENT_RTOL * moments[2];
    let equal: Vec<usize> = match (close(moments[0], moments[1]), close(moments[1], moments[2])) {
        (true, true) => vec![0, 1, 2],
        (true, false) => vec![0, 1],
        (false, true) => vec![1, 2],
        (false, false) => vec![],
    };
    let axes = match equal[..] {
        [_, _, _] => [Vector3::x(), Vector3::y(), Vector3::z()],
        [0, 1] => {
            let u = sign_rule(vecs[2]);
            let v = in_plane(&u);
            [v, u.cross(&v), u]
        }
        [1, 2] => {
            let u = sign_rule(vecs[0]);
            let v = in_plane(&u);
            [u, v, u.cross(&v)]
        }
        _ => {
            let a = sign_rule(vecs[0]);
            let b = sign_rule(vecs[1]);
            [a, b, a.cross(&b).normalize()]
        }
    };
    Some(Principal {
        moments,
        axes,
        equal,
    })
}

/// Flip `v` so its largest component (first among near-ties) is positive.
fn sign_rule(v: Vector3<f64>) -> Vector3<f64> {
    let max = v.amax();
    let lead = v
        .iter()
        .find(|x| x.abs() >= max - SIGN_TIE)
        .expect("a unit vector has a component of largest magnitude");
    if *lead < 0.0 { -v } else { v }
}

/// A unit vector perpendicular to unit `u`: the file axis most nearly
/// perpendicular to `u` (first among near-ties), projected off `u`.
fn in_plane(u: &Vector3<f64>) -> Vector3<f64> {
    let min = u.amin();
    let k = u
        .iter()
        .position(|x| x.abs() <= min + SIGN_TIE)
        .expect("a vector has a component of smallest magnitude");
    let e = Vector3::ith(k, 1.0);
    (e - u * u.dot(&e)).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mass::inertia_of;

    fn rot(axis: Vector3<f64>, deg: f64) -> Matrix3<f64> {
        crate::model::rotation::axis_angle(axis.normalize(), deg)
    }

    fn assert_right_handed_unit(p: &Principal) {
        for a in &p.axes {
            assert!((a.norm() - 1.0).abs() < 1e-15);
        }
        let triple = p.axes[0].cross(&p.axes[1]).dot(&p.axes[2]);
        assert!((triple - 1.0).abs() < 1e-14, "triple product {triple}");
    }

    #[test]
    fn principal_axes_diagonalise_the_inertia_tensor() {
        let r = rot(Vector3::new(1.0, 2.0, -0.5), 33.0);
        let c = r * Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 4.0)) * r.transpose();
        let p = principal(&c).unwrap();
        let i = inertia_of(&c);
        assert_eq!(p.equal, Vec::<usize>::new());
        // Moments of I are sums of pairs of λ: 2+4, 1+4, 1+2 → 3, 5, 6.
        for (m, e) in p.moments.iter().zip([3.0, 5.0, 6.0]) {
            assert!((m - e).abs() < 1e-14);
        }
        for k in 0..3 {
            let residual = i * p.axes[k] - p.axes[k] * p.moments[k];
            assert!(residual.amax() < 1e-14);
        }
        assert_right_handed_unit(&p);
    }

    #[test]
    fn sign_rule_makes_the_largest_component_positive() {
        let r = rot(Vector3::new(0.3, -1.0, 0.2), 71.0);
        let c = r * Matrix3::from_diagonal(&Vector3::new(5.0, 2.0, 1.0)) * r.transpose();
        let p1 = principal(&c).unwrap();
        let p2 = principal(
            &(-r * Matrix3::from_diagonal(&Vector3::new(5.0, 2.0, 1.0)) * -r.transpose()),
        )
        .unwrap();
        for a in &p1.axes[..2] {
            let lead = a
                .iter()
                .copied()
                .fold(0.0f64, |m, x| if x.abs() > m.abs() { x } else { m });
            assert!(lead > 0.0);
        }
        assert_eq!(p1, p2);
    }

    #[test]
    fn three_equal_moments_give_the_file_axes() {
        let p = principal(&(Matrix3::identity() * 2.0)).unwrap();
        assert_eq!(p.equal, vec![0, 1, 2]);
        assert_eq!(p.axes, [Vector3::x(), Vector3::y(), Vector3::z()]);
        assert_eq!(p.moments, [4.0, 4.0, 4.0]);
    }

    #[test]
    fn a_rod_has_two_equal_moments_and_a_unique_axis() {
        // Rod along (1, 1, 1)/√3: C = s u uᵀ.
        let u = Vector3::new(1.0, 1.0, 1.0).normalize();
        let p = principal(&(u * u.transpose() * 3.0)).unwrap();
        assert_eq!(p.equal, vec![1, 2]);
        assert!(p.moments[0].abs() < 1e-15);
        assert!((p.axes[0] - u).amax() < 1e-15);
        assert_right_handed_unit(&p);
    }

    #[test]
    fn degenerate_axes_do_not_depend_on_the_solver() {
        // A flat disc-like body, C = diag(1, 1, 0) turned about its own normal
        // z: the tensor is unchanged up to rounding, so the axes must be too.
        let c0 = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.0));
        let r = rot(Vector3::z(), 17.0);
        let p0 = principal(&c0).unwrap();
        let p1 = principal(&(r * c0 * r.transpose())).unwrap();
        assert_eq!(p0.equal, vec![0, 1]);
        assert_eq!(p1.equal, vec![0, 1]);
        for k in 0..3 {
            assert!((p0.axes[k] - p1.axes[k]).amax() < 1e-15, "{k}");
        }
        assert_right_handed_unit(&p0);
    }

    #[test]
    fn zero_second_moment_is_three_equal_zero_moments() {
        let p = principal(&Matrix3::zeros()).unwrap();
        assert_eq!(p.moments, [0.0; 3]);
        assert_eq!(p.equal, vec![0, 1, 2]);
    }
}
