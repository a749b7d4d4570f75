//! A capsule: a cylinder of radius `R` whose ends are hemispheres of
//! the same radius, `length` `L` between the hemispheres' centres along
//! local z (as MuJoCo and SDFormat define it), centred on the origin;
//! with an inner radius `r` hollow (an even wall): dimensions [R, r, L].
//!
//! NOTE: the derivation. The capsule is a tube r ≤ ρ ≤ R of length L and
//! a spherical shell r ≤ s ≤ R cut in two at its equator, each half moved
//! L/2 along its axis. Per unit density, with D = R − r:
//!
//! - V = π(R² − r²)L + ⁴⁄₃π(R³ − r³) = πD W, W = (R + r)L + ⁴⁄₃S₃,
//!   S₃ = R² + Rr + r²;
//! - ∫x² dV: the tube's π(R⁴ − r⁴)L/4 and the shell's ⁴⁄₁₅π(R⁵ − r⁵)
//!   (a sphere's ∫x² dV, ⁴⁄₁₅πR⁵), so ∫x² dV = πD X,
//!   X = (R + r)(R² + r²)L/4 + ⁴⁄₁₅S₅, S₅ = R⁴ + R³r + R²r² + Rr³ + r⁴;
//! - ∫z² dV: the tube's V_t L²/12; each half shell, its own z′ from its
//!   flat face, z = L/2 + z′: V_h L²/4 + L ∫z′ dV_h + ∫z′² dV_h, with
//!   ∫z′ dV_h = π(R⁴ − r⁴)/4 (`hemisphere`) and ∫z′² dV_h = ²⁄₁₅π(R⁵ −
//!   r⁵); both halves and the tube: ∫z² dV = πD Z,
//!   Z = (R + r)L³/12 + S₃L²/3 + (R + r)(R² + r²)L/2 + ⁴⁄₁₅S₅.
//!
//! So ∫x² dm = m X/W (∫y² dm alike) and ∫z² dm = m Z/W: D cancels, and
//! every term of W, X and Z is positive, so a thin wall is no difference
//! of large numbers (r = R: a thin capsule shell, its moments the limit)
//! and R = 0 never arises (the model needs `radius` > 0). A solid capsule
//! (r = 0): ∫x² dm = m R²(L/4 + 4R/15)/(L + 4R/3).

use super::common::{add, axes, rim, scaled};
use super::lift::Lift;
use super::outline::{Outline, Piece};
use super::read::Reader;
use super::{
    MaterialRule, Mover, Own, PER_VOLUME, Shape, ShapeInfo, ShapeKind, Slot, Units,
};
use crate::diag::Diagnostic;
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;

/// A capsule, solid or hollow, placed by its `center` and turned by its
/// `orientation`, in its file's units.
#[derive(Debug, Clone, PartialEq)]
pub struct Capsule {
    pub center: [f64; 3],
    /// `radius`.
    pub radius: f64,
    /// `inner_radius`.
    pub inner_radius: f64,
    /// `length`, between the hemispheres' centres.
    pub length: f64,
    pub orientation: Orientation,
}

/// W, X and Z of the module's comment (V = πDW, ∫x² dV = πDX,
/// ∫z² dV = πDZ) for the dimensions [R, r, L].
fn forms<T: Real>(d: &[T]) -> (T, T, T) {
    let [r_out, r_in, l] = d else {
        unreachable!("the model passes a capsule three dimensions")
    };
    let (big, small, l) = (*r_out, *r_in, *l);
    let sum = big + small;
    let (b2, s2) = (big * big, small * small);
    let s3 = b2 + big * small + s2;
    let s5 = b2 * b2 + b2 * big * small + b2 * s2 + big * small * s2 + s2 * s2;
    let four_fifteenths = T::of(4.0) / T::of(15.0);
    let w = sum * l + T::of(4.0) / T::of(3.0) * s3;
    let across = sum * (b2 + s2);
    let x = across * l / T::of(4.0) + four_fifteenths * s5;
    let z = sum * l * l * l / T::of(12.0)
        + s3 * l * l / T::of(3.0)
        + across * l / T::of(2.0)
        + four_fifteenths * s5;
    (w, x, z)
}

impl ShapeKind for Capsule {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Capsule,
        name: "capsule",
        keys: &[
            "density",
            "radius",
            "inner_radius",
            "diameter",
            "inner_diameter",
            "material",
            "length",
            "center",
            "rotation",
            "mass",
            "remove",
        ],
        density: Some(PER_VOLUME),
        sizes: &["radius", "inner_radius", "length"],
        size_items: 0,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        degenerate: "a density on a thin shell (`inner_radius` = `radius`)",
        help: "a capsule takes `mass` or `density`, `radius` (or `diameter`) and `length` (between its hemispherical ends' centres, along its local z) with `center` (and optional `rotation`); an `inner_radius` makes it hollow",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "capsule: cylinder of radius R (bore r), length L, with hemispherical ends",
        dims: &[
            super::symbol("R", "R", super::Slot::Radius),
            super::symbol("r", "r", super::Slot::InnerRadius),
            super::symbol("L", "L", super::Slot::Length),
        ],
        measure: "pi*((R^2 - r^2)*L + 4*(R^3 - r^3)/3)",
        moments: [
            "m*((R^2 - r^2)*L^3/12 + (R^3 - r^3)*L^2/3 + 3*(R^4 - r^4)*L/4 + 8*(R^5 - r^5)/15)/((R^2 - r^2)*L + 4*(R^3 - r^3)/3)",
            "m*((R^2 - r^2)*L^3/12 + (R^3 - r^3)*L^2/3 + 3*(R^4 - r^4)*L/4 + 8*(R^5 - r^5)/15)/((R^2 - r^2)*L + 4*(R^3 - r^3)/3)",
            "2*m*((R^4 - r^4)*L/4 + 4*(R^5 - r^5)/15)/((R^2 - r^2)*L + 4*(R^3 - r^3)/3)",
        ],
    };

    /// π and ⁴⁄₃ (2), R − r and R + r (2), S₃ (5), the products with L,
    /// ⁴⁄₃ and π D (4), the sum (1), and two of slack.
    const MEASURE_ROUNDINGS: f64 = 16.0;

    /// X and Z each a sum of positive terms: S₅ (9), R² + r² and its
    /// product (3), the powers of L (3), ⁴⁄₁₅ (2), the quotients (3) and
    /// the sums (4): at most 24 each, W's 11, the quotient and m (2):
    /// 37, counted as 48.
    const MOMENT_ROUNDINGS: f64 = 48.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    /// πDW.
    fn measure_of<T: Real>(d: &[T]) -> T {
        let (w, _, _) = forms(d);
        T::pi() * (d[0] - d[1]) * w
    }

    /// m X/W across, m Z/W along its axis.
    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let (w, x, z) = forms(d);
        let across = m * (x / w);
        [across, across, m * (z / w)]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        let [radius, inner_radius] = r.radii()?;
        let length = r.length("length")?;
        Ok(Capsule {
            center: r.point("center")?,
            radius,
            inner_radius,
            length,
            orientation: r.orientation(),
        })
    }

    fn real_size_direction(&self) -> Option<[DD; 3]> {
        None
    }

    /// Its end rims, the lines tangent to both, and each end's dome (a
    /// hollow one's inner surface is hidden).
    fn outline(&self) -> Outline {
        let c = self.center;
        let [x, y, z] = axes(&self.orientation.matrix());
        let (r, l) = (self.radius, self.length);
        let ends = [add(c, scaled(-l / 2.0, z)), add(c, scaled(l / 2.0, z))];
        Outline::Pieces(vec![
            rim(ends[0], r, &x, &y),
            rim(ends[1], r, &x, &y),
            Piece::Side {
                c: ends,
                r: [r, r],
                u: x,
                v: y,
            },
            Piece::Dome {
                c: ends[0],
                r,
                u: x,
                v: y,
                z: scaled(-1.0, z),
            },
            Piece::Dome {
                c: ends[1],
                r,
                u: x,
                v: y,
                z,
            },
        ])
    }

    placed_by_centre!(radius: Radius, inner_radius: InnerRadius, length: Length);

    centred_centroid!();
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::quadrature::gauss5 as gauss;
    use std::f64::consts::PI;

    /// Volume, ∫x² dV and ∫z² dV of the capsule by quadrature over its
    /// own description, independent of the closed forms: the region
    /// r ≤ dist(p, segment) ≤ R, the segment from z = −L/2 to +L/2. In
    /// cylindrical coordinates (ρ, θ, z): for each z the section is the
    /// annulus between the inner and outer profile, ρ from √(r² − e²) to
    /// √(R² − e²), e the distance of z past the segment's end. Each piece
    /// (the tube, and each cap in the variable e) is a polynomial of low
    /// degree once the ρ integral is done in closed form per slice, so a
    /// few panels of 5 points are exact to rounding.
    fn by_quadrature(big: f64, small: f64, l: f64) -> (f64, f64, f64) {
        // Per slice at height z, with outer and inner radii a ≥ b:
        // area π(a² − b²), ∫x² dA = π(a⁴ − b⁴)/4.
        let slice = |a2: f64, b2: f64| (PI * (a2 - b2), PI * (a2 * a2 - b2 * b2) / 4.0);
        let (mut v, mut xx, mut zz) = (0.0, 0.0, 0.0);
        for (z, w) in gauss(-l / 2.0, l / 2.0) {
            let (area, ix) = slice(big * big, small * small);
            v += w * area;
            xx += w * ix;
            zz += w * area * z * z;
        }
        // Each cap: e from 0 to R; the inner profile ends at e = r.
        for side in [-1.0, 1.0] {
            for (lo, hi) in [(0.0, small), (small, big)] {
                if hi <= lo {
                    continue;
                }
                for (e, w) in gauss(lo, hi) {
                    let a2 = big * big - e * e;
                    let b2 = if e < small { small * small - e * e } else { 0.0 };
                    let (area, ix) = slice(a2, b2);
                    let z = side * (l / 2.0 + e);
                    v += w * area;
                    xx += w * ix;
                    zz += w * area * z * z;
                }
            }
        }
        (v, xx, zz)
    }

    fn close(a: f64, b: f64, what: &str) {
        assert!(
            (a - b).abs() <= 64.0 * f64::EPSILON * b.abs(),
            "{what}: {a} against {b}"
        );
    }

    #[test]
    fn the_closed_forms_are_the_quadrature_of_the_capsule() {
        for (big, small, l) in [(0.5, 0.0, 2.0), (0.3, 0.2, 0.7), (1.0, 0.999, 0.01), (2.0, 0.5, 40.0)] {
            let (v, xx, zz) = by_quadrature(big, small, l);
            let d = [big, small, l];
            close(Capsule::measure_of(&d), v, "volume");
            let m = 7.0;
            let [mx, my, mz] = Capsule::moments_of(m, &d);
            close(mx, m * xx / v, "across");
            assert_eq!(mx, my);
            close(mz, m * zz / v, "along");
        }
    }

    #[test]
    fn a_capsule_of_no_length_is_a_sphere_and_one_of_no_caps_a_tube() {
        use crate::shapes::Shape;
        // L → 0: the sphere's own closed forms.
        let d = [0.4, 0.1, 0.0];
        close(
            Capsule::measure_of(&d),
            Shape::Sphere.measure_of(&[0.4, 0.1]),
            "sphere's volume",
        );
        let sphere = Shape::Sphere.second_moments(3.0, &[0.4, 0.1]);
        let capsule = Capsule::moments_of(3.0, &d);
        for k in 0..3 {
            close(capsule[k], sphere[k], "sphere's moments");
        }
        // A long capsule: its caps a vanishing share beside the tube's
        // (R/L = 10⁻⁶), so the tube's closed forms to 10⁻⁵.
        let (big, small, l) = (1e-3, 5e-4, 1e3);
        let tube = Shape::Cylinder.second_moments(1.0, &[big, small, l]);
        let capsule = Capsule::moments_of(1.0, &[big, small, l]);
        assert!((capsule[2] / tube[2] - 1.0).abs() < 1e-5);
        assert!((capsule[0] / tube[0] - 1.0).abs() < 1e-5);
    }

    #[test]
    fn a_thin_capsule_shell_is_the_limit_of_thin_walls() {
        // r = R: no volume, and the moments of an even wall as it thins.
        let (big, l) = (0.5, 1.2);
        assert_eq!(Capsule::measure_of(&[big, big, l]), 0.0);
        let shell = Capsule::moments_of(1.0, &[big, big, l]);
        let thin = Capsule::moments_of(1.0, &[big, big * (1.0 - 1e-9), l]);
        for k in 0..3 {
            assert!((shell[k] / thin[k] - 1.0).abs() < 1e-8, "{k}");
        }
        // Its surface: the tube's 2πRL of m R²/2 across… by area shares:
        // tube 2πRL (∫x² dA = πR³L), sphere 4πR² (∫x² dA = 4πR⁴/3).
        let area = 2.0 * PI * big * l + 4.0 * PI * big * big;
        let across = (PI * big.powi(3) * l + 4.0 * PI * big.powi(4) / 3.0) / area;
        close(shell[0], across, "thin shell across");
    }
}
