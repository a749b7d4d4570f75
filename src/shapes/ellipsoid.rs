//! A solid ellipsoid: semi-axes `a`, `b`, `c` along local x, y, z
//! (`radii`, SDFormat's `<ellipsoid><radii>`, MuJoCo's ellipsoid `size`),
//! centred on the origin; dimensions [a, b, c].
//!
//! NOTE: the derivation. The ellipsoid is the unit ball B stretched by
//! diag(a, b, c): p = (a u, b v, c w) for (u, v, w) in B, a map of
//! Jacobian abc. So V = abc |B| = ⁴⁄₃π abc, and ∫x² dV = a² abc ∫u² dB =
//! a² abc · ⁴⁄₁₅π (the ball's ∫u² dB, a third of ∫|p|² dB = ⁴⁄₅π): per
//! unit mass a²/5. So ∫x² dm = m a²/5, ∫y² dm = m b²/5, ∫z² dm = m c²/5,
//! each formed as (m a) a / 5: no difference anywhere, and a² alone never
//! formed (it could overflow or underflow where m a²/5 does not). Its
//! local axes are principal and its centroid is its centre; it is its own
//! mirror image in each local coordinate plane. No hollow form: an even
//! wall of an ellipsoid is no difference of two ellipsoids (their
//! semi-axes' differences are not one thickness), so the shape is solid.
//!
//! Its dimensions are its own key, `radii` (`OWN_KEYS`: three lengths,
//! each > 0, each taking "±"), read through `Reader::quantities` and
//! moved by a tolerance in the slots `Own(0, k)`.

use super::common::{axes, scaled};
use super::lift::Lift;
use super::outline::{Outline, Piece};
use super::read::Reader;
use super::{
    Key, Kind, MaterialRule, Mover, Own, PER_VOLUME, Shape, ShapeInfo, ShapeKind, Slot,
    Units,
};
use crate::diag::Diagnostic;
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use crate::units::Dim;

/// The semi-axes from the dimensions the closed forms are given.
fn semi_axes<T: Real>(d: &[T]) -> [T; 3] {
    let [a, b, c] = d else {
        unreachable!("an ellipsoid has three dimensions, its radii")
    };
    [*a, *b, *c]
}

/// A solid ellipsoid placed by its `center` and turned by its
/// `orientation`, in its file's units.
#[derive(Debug, Clone, PartialEq)]
pub struct Ellipsoid {
    pub center: [f64; 3],
    /// `radii`: the semi-axes along local x, y and z.
    pub radii: [f64; 3],
    pub orientation: Orientation,
}

impl ShapeKind for Ellipsoid {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Ellipsoid,
        name: "ellipsoid",
        keys: &[
            "density", "radii", "material", "center", "rotation", "mass", "remove",
        ],
        density: Some(PER_VOLUME),
        sizes: &["radii"],
        size_items: 0,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        degenerate: "a zero or negative radius",
        help: "an ellipsoid takes `mass` or `density`, and `radii` = [a, b, c], its semi-axes along its local x, y and z, with `center` (and optional `rotation`)",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "solid ellipsoid of semi-axes a, b, c",
        dims: &[
            super::symbol("a", "a", super::Slot::Own(0, 0)),
            super::symbol("b", "b", super::Slot::Own(0, 1)),
            super::symbol("c", "c", super::Slot::Own(0, 2)),
        ],
        measure: "4*pi*a*b*c/3",
        moments: [
            "m*(b^2 + c^2)/5",
            "m*(a^2 + c^2)/5",
            "m*(a^2 + b^2)/5",
        ],
    };

    const OWN_KEYS: &'static [Key] = &[Key::own(
        "radii",
        Kind::Quantities(Some(3)),
        Dim::LENGTH,
        "the semi-axes a, b, c along local x, y, z",
    )
    .tolerable()
    .positive()];

    /// ⁴⁄₃ and π (3: the quotient, π's own rounding, their product), the
    /// three products with a, b and c (3), and one of slack.
    const MEASURE_ROUNDINGS: f64 = 7.0;

    /// (m a) a / 5: two products and the quotient (3), and one of slack.
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    /// ⁴⁄₃π abc.
    fn measure_of<T: Real>(d: &[T]) -> T {
        let [a, b, c] = semi_axes(d);
        T::of(4.0) / T::of(3.0) * T::pi() * a * b * c
    }

    /// m a²/5, m b²/5, m c²/5.
    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        semi_axes(d).map(|r| m * r * r / T::of(5.0))
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        let radii = r.quantities::<3>("radii")?;
        Ok(Ellipsoid {
            center: r.point("center")?,
            radii,
            orientation: r.orientation(),
        })
    }

    fn real_size_direction(&self) -> Option<[DD; 3]> {
        None
    }

    /// The ellipsoid itself, {c + R diag(a, b, c) u : |u| ≤ 1}: each
    /// view draws its projection's outline, an ellipse.
    fn outline(&self) -> Outline {
        let [x, y, z] = axes(&self.orientation.matrix());
        let [a, b, c] = self.radii;
        Outline::Pieces(vec![Piece::Ellipsoid {
            c: self.center,
            m: [scaled(a, x), scaled(b, y), scaled(c, z)],
        }])
    }

    // Its mirror image: S R becomes S R F, F the flip of local x, the
    // ellipsoid its own image in its local y–z plane.
    placed_by_centre!(radii: [Own(0); 3]);

    centred_centroid!();
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::quadrature::gauss5 as gauss;
    use crate::shapes::Shape;
    use std::f64::consts::PI;

    /// Volume and ∫x² dV, ∫y² dV, ∫z² dV of the region x²/a² + y²/b² +
    /// z²/c² ≤ 1, by quadrature over its own description, independent of
    /// the closed forms: in stretched spherical coordinates
    /// (x, y, z) = (a ρ s cos θ, b ρ s sin θ, c ρ t), t = cos φ,
    /// s = √(1 − t²), dV = abc ρ² dρ dt dθ. The integrands are polynomials
    /// in ρ and t of degree at most 6 and trigonometric polynomials of
    /// degree 2 in θ, so 5 Gauss points in each and 8 equal steps round
    /// the turn are exact to rounding.
    fn by_quadrature(a: f64, b: f64, c: f64) -> (f64, [f64; 3]) {
        let (mut v, mut acc) = (0.0, [0.0; 3]);
        for (rho, wr) in gauss(0.0, 1.0) {
            for (t, wt) in gauss(-1.0, 1.0) {
                for k in 0..8 {
                    let theta = k as f64 * PI / 4.0;
                    let s = (1.0 - t * t).sqrt();
                    let p = [
                        a * rho * s * theta.cos(),
                        b * rho * s * theta.sin(),
                        c * rho * t,
                    ];
                    let w = a * b * c * rho * rho * wr * wt * PI / 4.0;
                    v += w;
                    for i in 0..3 {
                        acc[i] += w * p[i] * p[i];
                    }
                }
            }
        }
        (v, acc)
    }

    fn close(x: f64, y: f64, what: &str) {
        assert!(
            (x - y).abs() <= 64.0 * f64::EPSILON * y.abs(),
            "{what}: {x} against {y}"
        );
    }

    #[test]
    fn the_closed_forms_are_the_quadrature_of_the_ellipsoid() {
        for [a, b, c] in [[1.0, 1.0, 1.0], [0.3, 0.7, 1.9], [2.0, 0.01, 0.5], [1e3, 1.0, 1e-3]] {
            let (v, acc) = by_quadrature(a, b, c);
            close(Ellipsoid::measure_of(&[a, b, c]), v, "volume");
            let m = 7.0;
            let moments = Ellipsoid::moments_of(m, &[a, b, c]);
            for i in 0..3 {
                close(moments[i], m * acc[i] / v, "moment");
            }
        }
    }

    #[test]
    fn the_volume_is_the_textbook_four_thirds_pi_abc() {
        close(Ellipsoid::measure_of(&[1.0, 2.0, 3.0]), 8.0 * PI, "volume");
    }

    #[test]
    fn an_ellipsoid_of_equal_radii_is_the_solid_sphere() {
        let r = 0.4;
        close(
            Ellipsoid::measure_of(&[r, r, r]),
            Shape::Sphere.measure_of(&[r, 0.0]),
            "volume",
        );
        let sphere = Shape::Sphere.second_moments(3.0, &[r, 0.0]);
        let ellipsoid = Ellipsoid::moments_of(3.0, &[r, r, r]);
        for k in 0..3 {
            close(ellipsoid[k], sphere[k], "moments");
        }
    }

    #[test]
    fn each_moment_is_formed_without_the_square_of_its_radius() {
        // a² overflows f64 here, m a²/5 does not.
        let a = 1e200;
        let [x, _, _] = Ellipsoid::moments_of(1e-100, &[a, 1.0, 1.0]);
        close(x, 2e299, "huge radius");
    }

    #[test]
    fn its_numbers_are_its_centre_then_its_radii() {
        let mut e = Ellipsoid {
            center: [1.0, 2.0, 3.0],
            radii: [4.0, 5.0, 6.0],
            orientation: Orientation::Identity,
        };
        let mut seen = Vec::new();
        e.numbers(&mut |s, x| seen.push((s, *x)));
        assert_eq!(
            seen,
            [
                (Slot::At(0), 1.0),
                (Slot::At(1), 2.0),
                (Slot::At(2), 3.0),
                (Slot::Own(0, 0), 4.0),
                (Slot::Own(0, 1), 5.0),
                (Slot::Own(0, 2), 6.0),
            ]
        );
    }

    #[test]
    fn its_outline_is_the_ellipsoid_turned() {
        // A quarter turn about z: local x along file y.
        let e = Ellipsoid {
            center: [1.0, 0.0, 0.0],
            radii: [3.0, 2.0, 1.0],
            orientation: Orientation::Quaternion([
                std::f64::consts::FRAC_1_SQRT_2,
                0.0,
                0.0,
                std::f64::consts::FRAC_1_SQRT_2,
            ]),
        };
        let Outline::Pieces(pieces) = e.outline() else {
            panic!("an ellipsoid is drawn")
        };
        let [Piece::Ellipsoid { c, m }] = &pieces[..] else {
            panic!("one ellipsoid: {pieces:?}")
        };
        assert_eq!(*c, [1.0, 0.0, 0.0]);
        let near = |u: [f64; 3], v: [f64; 3]| (0..3).all(|k| (u[k] - v[k]).abs() < 1e-15);
        assert!(near(m[0], [0.0, 3.0, 0.0]), "{m:?}");
        assert!(near(m[1], [-2.0, 0.0, 0.0]), "{m:?}");
        assert!(near(m[2], [0.0, 0.0, 1.0]), "{m:?}");
        let [lo, hi] = e.outline().extent();
        assert!(near(lo, [-1.0, -3.0, -1.0]) && near(hi, [3.0, 3.0, 1.0]), "{lo:?} {hi:?}");
    }
}
