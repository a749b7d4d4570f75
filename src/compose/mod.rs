//! Composition of parts into one body, and its principal moments and axes,
//! in the precision asked for (`--precision`).
//!
//! Both modes work from the numbers the file gave, in the file's units
//! (`model::Spec`); only results are converted to SI (in `report`).
//!
//! - `standard`: each part in f64; every sum compensated (Neumaier), so
//!   the totals are as if summed in twice the precision and rounded once;
//!   the second moment accumulated about the composite centre of mass with
//!   a correction for the rounding of the centre itself; the principal axes
//!   by Jacobi in f64.
//! - `extended`: the same steps in double-double (~32 digits): rotation of
//!   each part, its closed form, the sums and the Jacobi eigen solution.

mod placed;

pub use placed::bodies_composed;

use crate::bounds::{BodyError, Tally};
use crate::eigen::jacobi_counted;
use crate::la::Vector3;
use crate::mass::Body;
use crate::numeric::{DD, M3, Real, Sum, two_sum};
use crate::part::EachPart;

pub use crate::thresholds::EQUAL_MOMENT_RTOL;
use crate::thresholds::SIGN_TIE;

pub use crate::numeric::Precision;

/// Compose parts into mass, centre of mass and second moment about it, in
/// the file's units.
///
/// NOTE: two passes. The first finds the centre of mass; the second sums each
/// part's second moment with its offset *from that centre*. Summing about a
/// distant origin and shifting back subtracts two huge, nearly equal numbers
/// and loses every digit for parts 10⁹ sizes from the origin. The residual
/// first moment s = Σ mᵢdᵢ (zero in exact arithmetic) then corrects the
/// rounding of the centre ĉ itself: C = Σ(Cᵢ + mᵢdᵢdᵢᵀ) − s sᵀ/m and
/// c = ĉ + s/m.
pub fn compose<P: EachPart + ?Sized>(parts: &P, precision: Precision) -> Body {
    compose_bounded(parts, precision).0
}

/// `compose`, with the error bounds of the body it returns (`bounds`): the
/// composer's own sums and, beside them, the few sums the bounds need.
pub fn compose_bounded<P: EachPart + ?Sized>(parts: &P, precision: Precision) -> (Body, BodyError) {
    match precision {
        Precision::Standard => compose_standard(parts),
        Precision::Extended => compose_extended(parts),
    }
}

/// `compose_bounded` of a model: a file of parts alone as a list of its
/// parts (`compose_standard`, `compose_extended`); one with
/// sub-assemblies or copies with each distinct sub-assembly composed once
/// and placed per instance, each copy placed from its part's physics
/// (`placed`).
pub fn compose_model(model: &crate::model::Model, precision: Precision) -> (Body, BodyError) {
    let plain = model
        .items
        .iter()
        .all(|item| matches!(item, crate::model::Item::Part { copies: None, .. }));
    if plain {
        return compose_bounded(model, precision);
    }
    match precision {
        Precision::Standard => placed::compose_root::<f64>(model),
        Precision::Extended => placed::compose_root::<DD>(model),
    }
}

fn compose_standard<P: EachPart + ?Sized>(parts: &P) -> (Body, BodyError) {
    // The pivot ĉ = Σ (mᵢ/m) cᵢ: weights first, so that huge masses far out
    // cannot overflow a first moment Σ mᵢcᵢ the centre itself fits in.
    let mut mass = Sum::default();
    parts.each(&mut |p| mass.add(p.mass::<f64>()));
    let total = mass.value();
    let mut first = [Sum::default(); 3];
    parts.each(&mut |p| {
        let w = p.mass::<f64>() / total;
        let c = p.centroid();
        for (f, ci) in first.iter_mut().zip(&c) {
            f.add(w * ci.hi);
        }
    });
    let c0 = first.map(Sum::value);
    let mut sum = [[Sum::default(); 3]; 3];
    let mut s = [Sum::default(); 3];
    let mut tally = Tally::default();
    parts.each(&mut |p| {
        let m: f64 = p.mass();
        let c = p.centroid();
        // c.hi − ĉ is exact when they are close (Sterbenz); c.lo carries the
        // rest of a centroid formed from a corner and edges.
        let d: [f64; 3] = std::array::from_fn(|i| (c[i].hi - c0[i]) + c[i].lo);
        let (own, error): (M3<f64>, _) = p.own_second_moment_bounded(m);
        let off = crate::part::error::centroid_error(&p.spec, &c.map(|x| x.hi));
        tally.add(m, d, off, &error);
        for i in 0..3 {
            // (m d) dᵀ, not (d dᵀ) m: d dᵀ alone can underflow or overflow.
            let md = m * d[i];
            s[i].add(md);
            for j in i..3 {
                sum[i][j].add(own[i][j]);
                sum[i][j].add(md * d[j]);
            }
        }
    });
    let s = s.map(Sum::value);
    let mut c = [[DD::of(0.0); 3]; 3];
    for i in 0..3 {
        for j in i..3 {
            // s (s/m)ᵀ, not s sᵀ/m: the square of s may overflow when m is huge.
            sum[i][j].add(-(s[i] * (s[j] / total)));
            c[i][j] = DD::of(sum[i][j].value());
            c[j][i] = c[i][j];
        }
    }
    let body = Body {
        mass: DD::of(total),
        center_of_mass: std::array::from_fn(|i| {
            let (hi, lo) = two_sum(c0[i], s[i] / total);
            DD::new(hi, lo)
        }),
        second_moment: c,
    };
    let error = finish(&tally, Precision::Standard, &body, s);
    (body, error)
}

fn finish(tally: &Tally, precision: Precision, body: &Body, s: [f64; 3]) -> BodyError {
    tally.finish(
        precision,
        body.mass.f64(),
        s,
        body.center_of_mass.map(DD::f64),
        &body.second_moment.map(|r| r.map(DD::f64)),
    )
}

fn compose_extended<P: EachPart + ?Sized>(parts: &P) -> (Body, BodyError) {
    let zero = DD::of(0.0);
    let mut total = zero;
    parts.each(&mut |p| total += p.mass::<DD>());
    // Σ (mᵢ/m) cᵢ, as in `compose_standard`.
    let mut c0 = [zero; 3];
    parts.each(&mut |p| {
        let w = p.mass::<DD>() / total;
        for (f, ci) in c0.iter_mut().zip(p.centroid()) {
            *f += w * ci;
        }
    });
    let mut c = [[zero; 3]; 3];
    let mut s = [zero; 3];
    let mut tally = Tally::default();
    parts.each(&mut |p| {
        let m: DD = p.mass();
        let cen = p.centroid();
        let d: [DD; 3] = std::array::from_fn(|i| cen[i] - c0[i]);
        let (own, error): (M3<DD>, _) = p.own_second_moment_bounded(m);
        let off = crate::part::error::centroid_error(&p.spec, &cen.map(|x| x.hi));
        tally.add(m.f64(), d.map(DD::f64), off, &error);
        for i in 0..3 {
            let md = m * d[i];
            s[i] += md;
            for j in i..3 {
                c[i][j] += own[i][j] + md * d[j];
            }
        }
    });
    for i in 0..3 {
        for j in i..3 {
            c[i][j] = c[i][j] - s[i] * (s[j] / total);
            c[j][i] = c[i][j];
        }
    }
    let body = Body {
        mass: total,
        center_of_mass: std::array::from_fn(|i| c0[i] + s[i] / total),
        second_moment: c,
    };
    let error = finish(&tally, Precision::Extended, &body, s.map(DD::f64));
    (body, error)
}

impl Principal {
    /// What the error bounds are formed from (`bounds::eigen`).
    pub fn solved(&self) -> crate::bounds::Solved<'_> {
        crate::bounds::Solved {
            lambda: self.lambda,
            eigenvectors: &self.eigenvectors,
            rotations: self.rotations,
            equal: &self.equal,
            backward: self.backward,
        }
    }
}

/// Principal moments (ascending) and axes of a body, with the moments that
/// are equal within `EQUAL_MOMENT_RTOL`.
#[derive(Debug, Clone, PartialEq)]
pub struct Principal {
    /// Ascending, never negative; in the units of the second moment given.
    pub moments: [DD; 3],
    /// `axes[i]` is the unit axis of `moments[i]`; `axes[0] × axes[1] = axes[2]`.
    pub axes: [Vector3<f64>; 3],
    /// Indices of moments equal to each other ([] when all differ, else two
    /// or three indices). Their axes are not unique.
    pub equal: Vec<usize>,
    /// The eigenvalue of C belonging to each axis (`moments[i]` is the sum
    /// of the other two) and its eigenvector as the solver found it (before
    /// the sign rule and the choice among equal moments): what the error
    /// bounds are formed from (`bounds::eigen`).
    pub lambda: [f64; 3],
    pub eigenvectors: [Vector3<f64>; 3],
    /// Plane rotations the Jacobi solver applied.
    pub rotations: usize,
    /// A bound on the solver's backward error (`bounds::backward_error`);
    /// infinite (unknown) unless measured (`principal_bounded`).
    pub backward: f64,
}

/// Principal moments and axes of the second moment `c` (∫ρρᵀ dm), solved in
/// f64 (`standard`, from `c` rounded to f64) or in double-double.
///
/// NOTE: we diagonalise C, not I; they share eigenvectors, and each principal
/// moment is then a sum of two non-negative principal second moments,
/// I₁ = λ₂ + λ₃ and so on, so moments are never negative and always satisfy
/// the triangle inequality, with no cancellation in forming them: the
/// smallest moment of a slender body is the sum of the two small λ, not a
/// difference of large numbers.
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
pub fn principal(c: &M3<DD>, precision: Precision) -> Option<Principal> {
    principal_with(c, precision, false)
}

/// `principal`, with the solver's backward error measured
/// (`Principal::backward`, `bounds::backward_error`) for the error bounds;
/// `principal` leaves it infinite (unknown) and spares the work.
pub fn principal_bounded(c: &M3<DD>, precision: Precision) -> Option<Principal> {
    principal_with(c, precision, true)
}

fn principal_with(c: &M3<DD>, precision: Precision, bound: bool) -> Option<Principal> {
    match precision {
        Precision::Standard => principal_in::<f64>(&c.map(|r| r.map(|x| x.f64())), bound),
        Precision::Extended => principal_in::<DD>(c, bound),
    }
}

fn principal_in<T: Real + Into<DD>>(c: &M3<T>, bound: bool) -> Option<Principal> {
    let (lam, v, rotations) = jacobi_counted(*c)?;
    if !lam.iter().all(|x| x.is_finite()) {
        return None;
    }
    let backward = if bound {
        crate::bounds::backward_error(c, &lam, &v)
    } else {
        f64::INFINITY
    };
    let lam: [DD; 3] = lam.map(|x| {
        if x > T::of(0.0) {
            x.into()
        } else {
            DD::of(0.0)
        }
    });
    // Moment k belongs to the axis of λ_k and is the sum of the other two.
    let moment = |k: usize| lam[(k + 1) % 3] + lam[(k + 2) % 3];
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| {
        moment(a)
            .partial_cmp(&moment(b))
            .unwrap_or(std::cmp::Ordering::Equal)
            .then(a.cmp(&b))
    });
    let moments = order.map(moment);
    let vecs = order.map(|k| Vector3::new(v[0][k].f64(), v[1][k].f64(), v[2][k].f64()).normalize());

    let top = moments[2].f64();
    let close = |a: DD, b: DD| (b - a).f64().abs() <= EQUAL_MOMENT_RTOL * top;
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
        lambda: order.map(|k| lam[k].f64()),
        eigenvectors: vecs,
        rotations,
        backward,
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
    use crate::la::Matrix3;
    use crate::mass::inertia_of;
    use crate::model::rotation::Orientation;
    use crate::part::{MassSpec, Part, Place, Spec};

    #[derive(Debug, PartialEq)]
    struct P {
        moments: [f64; 3],
        axes: [Vector3<f64>; 3],
        equal: Vec<usize>,
    }

    /// `principal` of an f64 matrix in standard precision, moments as f64.
    fn principal_f(c: &Matrix3<f64>) -> Option<P> {
        let rows: M3<DD> = std::array::from_fn(|i| std::array::from_fn(|j| DD::of(c[(i, j)])));
        let p = principal(&rows, Precision::Standard)?;
        Some(P {
            moments: p.moments.map(|x| x.f64()),
            axes: p.axes,
            equal: p.equal,
        })
    }

    fn rot(axis: Vector3<f64>, deg: f64) -> Matrix3<f64> {
        crate::model::rotation::to_matrix3(&crate::model::rotation::axis_angle(
            [axis.x, axis.y, axis.z],
            deg,
        ))
    }

    fn assert_right_handed_unit(p: &P) {
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
        let p = principal_f(&c).unwrap();
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
        let p1 = principal_f(&c).unwrap();
        let p2 = principal_f(
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
        let p = principal_f(&(Matrix3::identity() * 2.0)).unwrap();
        assert_eq!(p.equal, vec![0, 1, 2]);
        assert_eq!(p.axes, [Vector3::x(), Vector3::y(), Vector3::z()]);
        assert_eq!(p.moments, [4.0, 4.0, 4.0]);
    }

    #[test]
    fn a_rod_has_two_equal_moments_and_a_unique_axis() {
        // Rod along (1, 1, 1)/√3: C = s u uᵀ.
        let u = Vector3::new(1.0, 1.0, 1.0).normalize();
        let p = principal_f(&(u * u.transpose() * 3.0)).unwrap();
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
        let p0 = principal_f(&c0).unwrap();
        let p1 = principal_f(&(r * c0 * r.transpose())).unwrap();
        assert_eq!(p0.equal, vec![0, 1]);
        assert_eq!(p1.equal, vec![0, 1]);
        for k in 0..3 {
            assert!((p0.axes[k] - p1.axes[k]).amax() < 1e-15, "{k}");
        }
        assert_right_handed_unit(&p0);
    }

    #[test]
    fn zero_second_moment_is_three_equal_zero_moments() {
        let p = principal_f(&Matrix3::zeros()).unwrap();
        assert_eq!(p.moments, [0.0; 3]);
        assert_eq!(p.equal, vec![0, 1, 2]);
    }

    /// A 100 × 100 × 100 lattice of cubes of mass 0.1, 10⁹ from the origin,
    /// each turned by its own pseudo-random quaternion. Exact result by
    /// hand: a cube's own second moment is m a²/12 E whatever its turn; the
    /// lattice adds N m h² (n² − 1)/12 per axis and no products, so
    /// C = N m (h²(n² − 1) + a²)/12 E for the f64 value m of 0.1 (h = ¼ and
    /// a = ⅛ place every centre exactly). The masses are not dyadic, so every
    /// m d² rounds and a plain sum of a million of them drifts.
    fn million_cubes() -> Vec<Part> {
        let (n, h, a, m) = (100usize, 0.25, 0.125, 0.1);
        let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut rand = move || {
            // splitmix64
            seed = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = seed;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let mut parts = Vec::with_capacity(n * n * n);
        for i in 0..n {
            for j in 0..n {
                for k in 0..n {
                    let center = [1e9 + h * i as f64, -2e9 + h * j as f64, 3e9 + h * k as f64];
                    let q = [rand(), rand(), rand(), rand()];
                    let norm = q.iter().map(|x| x * x).sum::<f64>().sqrt();
                    parts.push(Part {
                        name: String::new(),
                        named: true,
                        spec: Spec {
                            mass: MassSpec::Given(m),
                            place: Place::Box(crate::shapes::r#box::Cuboid::Centred {
                                center,
                                size: [a; 3],
                                orientation: Orientation::Quaternion(q.map(|x| x / norm)),
                            }),
                            removed: false,
                            placed: Default::default(),
                        },
                        span: 0..0,
                        assembly: Vec::new(),
                        tol: None,
                        material: None,
                    });
                }
            }
        }
        parts
    }

    #[test]
    fn a_million_turned_cubes_far_from_the_origin_compose_to_the_exact_result() {
        let parts = million_cubes();
        // In double-double, from the closed form: ~1e-32 relative.
        let x = DD::of(1e6) * DD::of(0.1) * DD::of(0.0625 * 9999.0 + 0.015625) / DD::of(12.0);
        let exact = x.f64();
        let com = [1e9 + 12.375, -2e9 + 12.375, 3e9 + 12.375];
        for precision in [Precision::Standard, Precision::Extended] {
            let body = compose(&parts, precision);
            // Frobenius error relative to ‖C‖ = √3 X. Each cube's turned
            // second moment is off by a few ulps of m a²/12 (1e-3 of X/N),
            // and the lattice sums are compensated: far below 1e-15.
            let mut err2 = 0.0;
            for i in 0..3 {
                for j in 0..3 {
                    let want = if i == j { x } else { DD::of(0.0) };
                    err2 += (body.second_moment[i][j] - want).f64().powi(2);
                }
            }
            let rel = err2.sqrt() / (3f64.sqrt() * exact);
            eprintln!("{precision:?}: relative Frobenius error {rel:e}");
            assert!(rel <= 1e-15, "{precision:?}: {rel:e}");
            assert!((body.mass - DD::of(1e6) * DD::of(0.1)).f64().abs() <= f64::EPSILON * 1e5);
            for (c, w) in body.center_of_mass.iter().zip(com) {
                assert!(
                    (c.f64() - w).abs() <= f64::EPSILON * w.abs(),
                    "{c:?} vs {w}"
                );
            }
            let p = principal(&body.second_moment, precision).unwrap();
            assert_eq!(p.equal, vec![0, 1, 2]);
            for m in p.moments {
                assert!((m.f64() / (2.0 * exact) - 1.0).abs() <= 1e-15);
            }
            // What the compensation buys: the same sums done plainly.
            if precision == Precision::Standard {
                let mut plain = 0.0;
                for p in &parts {
                    let m: f64 = p.mass();
                    let d = p.centroid()[0].f64() - body.center_of_mass[0].f64();
                    plain += m * d * d + p.own_second_moment::<f64>(m)[0][0];
                }
                let plain_err = (plain / exact - 1.0).abs();
                eprintln!("plain summation: relative error {plain_err:e}");
                // The scene is hard enough for the bound above to mean something.
                assert!(plain_err > 1e-13, "{plain_err:e}");
            }
        }
    }
}
