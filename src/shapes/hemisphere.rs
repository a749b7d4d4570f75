//! A hemisphere: the half z ≥ 0 of a sphere of radius R about the origin,
//! hollow to an inner radius r (at r = R a thin hemispherical shell):
//! dimensions [R, r]. Its flat face lies in the local x–y plane, its dome
//! toward +z; its centroid on the z axis, off the origin.
//!
//! NOTE: the derivation, with ρ = r/R in [0, 1], P₃ = 1 + ρ + ρ² and
//! P₅ = 1 + ρ + ρ² + ρ³ + ρ⁴ (R³ − r³ = R³(1 − ρ)P₃, and so on):
//!
//! - V = ⅔π(R³ − r³), formed as ⅔π(R − r)(R² + Rr + r²);
//! - the first moment: in shells of radius s, z = s cos φ over the half
//!   solid angle, ∫cos φ dΩ = π, so ∫z dV = π ∫ s³ ds = π(R⁴ − r⁴)/4 and
//!   z̄ = ⅜ (R⁴ − r⁴)/(R³ − r³)
//!   = ⅜ R (1 + ρ)(1 + ρ²)/P₃ (⅜R solid, R/2 a thin shell);
//! - about the sphere's centre every ∫x² dm is the whole sphere's,
//!   k = R² P₅/(5P₃) per unit mass (the half has half the mass and half
//!   the integral); about the centroid x and y keep it, and
//!   ∫(z − z̄)² dm = m (k − z̄²). Written over 320P₃²,
//!   k − z̄² = R² (64P₅P₃ − 45(1 + ρ)²(1 + ρ²)²)/(320P₃²), and the
//!   numerator expands to 19 + 38ρ + 57ρ² + 12ρ³ + 57ρ⁴ + 38ρ⁵ + 19ρ⁶:
//!   every coefficient positive, so no cancellation (19/320 solid, 1/12 a
//!   thin shell).

use super::common::{axes, offset_centroid, offset_centroid_error, rim, var};
use super::read::Reader;
use crate::diag::Diagnostic;
use super::lift::Lift;
use super::outline::{Outline, Piece};
use super::{MaterialRule, Mover, Own, PER_VOLUME, Shape, ShapeInfo, ShapeKind, Slot, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;

fn powers<T: Real>(d: &[T]) -> (T, T, T) {
    let rho = d[1] / d[0];
    let one = T::of(1.0);
    (rho, rho * rho, one + rho + rho * rho)
}

/// The volume ⅔π(R − r)(R² + Rr + r²).
pub fn measure<T: Real>(d: &[T]) -> T {
    let (r_out, r_in) = (d[0], d[1]);
    T::of(2.0) / T::of(3.0)
        * T::pi()
        * (r_out - r_in)
        * (r_out * r_out + r_out * r_in + r_in * r_in)
}

/// The centroid's offset from the sphere's centre along local z.
pub fn offset<T: Real>(d: &[T]) -> T {
    let (rho, rho2, p3) = powers(d);
    let one = T::of(1.0);
    T::of(0.375) * d[0] * (one + rho) * (one + rho2) / p3
}

/// ∫x² dm, ∫y² dm, ∫z² dm about the centroid, local axes.
pub fn second_moments<T: Real>(m: T, d: &[T]) -> [T; 3] {
    let (rho, rho2, p3) = powers(d);
    let one = T::of(1.0);
    let rho3 = rho2 * rho;
    let p5 = one + rho + rho2 + rho3 + rho2 * rho2;
    let r2 = d[0] * d[0];
    let across = m * r2 / T::of(5.0) * (p5 / p3);
    // 19 + 38ρ + 57ρ² + 12ρ³ + 57ρ⁴ + 38ρ⁵ + 19ρ⁶ by Horner's rule: all
    // terms positive.
    let n = [19.0, 38.0, 57.0, 12.0, 57.0, 38.0, 19.0]
        .iter()
        .rev()
        .fold(T::of(0.0), |acc, &c| acc * rho + T::of(c));
    let axial = m * r2 * n / (T::of(320.0) * p3 * p3);
    [across, across, axial]
}

/// A hemisphere, solid or hollow, placed by its `center` and turned by its `orientation`,
/// in its file's units; its centroid lies off its centre along local z.
#[derive(Debug, Clone, PartialEq)]
pub struct Hemisphere {
    pub center: [f64; 3],
    /// `radius`.
    pub radius: f64,
    /// `inner_radius`.
    pub inner_radius: f64,
    pub orientation: Orientation,
}

impl Hemisphere {
    /// Its dimensions as its closed forms take them, read through `l`.
    fn dims<T: Real, L: Lift>(&self, l: L) -> [T; 2] {
        [var(self.radius, Slot::Radius, l), var(self.inner_radius, Slot::InnerRadius, l)]
    }
}

impl ShapeKind for Hemisphere {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Hemisphere,
        name: "hemisphere",
        keys: &[
            "density",
            "radius",
            "inner_radius",
            "diameter",
            "inner_diameter",
            "material",
            "center",
            "rotation",
            "mass",
            "remove",
        ],
        density: Some(PER_VOLUME),
        sizes: &["radius", "inner_radius"],
        size_items: 0,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        degenerate: "a density on a thin shell (`inner_radius` = `radius`)",
        help: "a hemisphere takes `mass` or `density`, and `radius` (or `diameter`) with `center`, the centre of its sphere (flat face in its local x–y plane, dome toward +z; optional `rotation`); an `inner_radius` makes it hollow (equal to `radius`: a thin shell)",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "hemisphere of radius R, hollow to r, dome along local z; its centroid 3(R⁴ − r⁴)/(8(R³ − r³)) above its centre",
        dims: &[
            super::symbol("R", "R", super::Slot::Radius),
            super::symbol("r", "r", super::Slot::InnerRadius),
        ],
        measure: "2*pi*(R^3 - r^3)/3",
        moments: [
            "2*m*(R^5 - r^5)/(5*(R^3 - r^3)) - m*(3*(R^4 - r^4)/(8*(R^3 - r^3)))^2",
            "2*m*(R^5 - r^5)/(5*(R^3 - r^3)) - m*(3*(R^4 - r^4)/(8*(R^3 - r^3)))^2",
            "2*m*(R^5 - r^5)/(5*(R^3 - r^3))",
        ],
    };

    /// 2/3 and π (3), R − r (1), R² + Rr + r² (3), three products, and one of slack.
    const MEASURE_ROUNDINGS: f64 = 11.0;

    /// The ratio of polynomials in ρ by Horner's rule (12, and ρ's own rounding six times over its degree) over 320P₃²: 40.
    const MOMENT_ROUNDINGS: f64 = 40.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        measure(d)
    }

    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        second_moments(m, d)
    }

    fn offset_of<T: Real>(d: &[T]) -> T {
        offset(d)
    }

    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        let [radius, inner_radius] = r.radii()?;
        Ok(Hemisphere {
            center: r.point("center")?,
            radius,
            inner_radius,
            orientation: r.orientation(),
        })
    }



    fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
        let z = Self::offset_of(&self.dims(l));
        offset_centroid([T::of(0.0), T::of(0.0), z], &self.center, &self.orientation, l)
    }

    /// The offset's error: 64 double-double units of the larger of the
    /// radius and the length it is formed from.
    fn centroid_error(&self, at: f64, centroid: &[f64; 3]) -> [f64; 3] {
        let big = self.radius.abs().max(0.0).max(0.0);
        offset_centroid_error(
            [0.0, 0.0, 64.0 * big],
            [0.0, 0.0, big],
            &self.orientation,
            at,
            centroid,
        )
    }












    fn real_size_direction(&self) -> Option<[DD; 3]> {
        None
    }

    fn outline(&self) -> Outline {
        let c = self.center;
        let [x, y, z] = axes(&self.orientation.matrix());
        let _ = z;
        Outline::Pieces(vec![
            rim(c, self.radius, &x, &y),
            Piece::Dome {
                c,
                r: self.radius,
                u: x,
                v: y,
                z,
            },
        ])
    }

    placed_by_centre!(radius: Radius, inner_radius: InnerRadius);
}
