//! A sphere: radius `R` about the origin; with an inner radius `r` a
//! hollow sphere, and with r = R a thin shell: dimensions [R, r].
//!
//! m/5 · (R⁵ − r⁵)/(R³ − r³) along every axis, written as
//! m R²/5 · (1 + ρ + ρ² + ρ³ + ρ⁴)/(1 + ρ + ρ²) with ρ = r/R: no
//! cancellation for thin walls, no overflow in R⁵, and m R²/3 for a thin
//! shell. The volume's R³ − r³ is formed as (R − r)(R² + Rr + r²).

use super::common::axes;
use super::read::Reader;
use crate::diag::Diagnostic;
use super::outline::{Outline, Piece};
use super::{MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use super::lift::Lift;
use super::PER_VOLUME;

/// A sphere, hollow or a thin shell, placed by its `center` and turned by its `orientation`,
/// in its file's units.
#[derive(Debug, Clone, PartialEq)]
pub struct Sphere {
    pub center: [f64; 3],
    /// `radius`.
    pub radius: f64,
    /// `inner_radius`.
    pub inner_radius: f64,
    pub orientation: Orientation,
}

impl ShapeKind for Sphere {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Sphere,
        name: "sphere",
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
        help: "a sphere takes `mass` or `density`, and `radius` (or `diameter`) with `center`; an `inner_radius` makes it hollow (equal to `radius`: a thin shell)",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "sphere of radius R, hollow to r",
        dims: &[
            super::symbol("R", "R", super::Slot::Radius),
            super::symbol("r", "r", super::Slot::InnerRadius),
        ],
        measure: "4*pi*(R^3 - r^3)/3",
        moments: [
            "2*m*(R^5 - r^5)/(5*(R^3 - r^3))",
            "2*m*(R^5 - r^5)/(5*(R^3 - r^3))",
            "2*m*(R^5 - r^5)/(5*(R^3 - r^3))",
        ],
    };

    /// 4/3 and π (3), R − r (1), R² + Rr + r² (3), three products, and one of slack.
    const MEASURE_ROUNDINGS: f64 = 11.0;

    /// ρ = r/R moves the ratio by at most its own rounding, its powers and sums 7 and 3, the division 3, m R²/5 four; at most 18.
    const MOMENT_ROUNDINGS: f64 = 18.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        let [r_out, r_in] = d else {
            unreachable!("the model passes a sphere two dimensions")
        };
        let (r_out, r_in) = (*r_out, *r_in);
        T::of(4.0) / T::of(3.0)
            * T::pi()
            * (r_out - r_in)
            * (r_out * r_out + r_out * r_in + r_in * r_in)
    }

    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [r_out, r_in] = d else {
            unreachable!("the model passes a sphere two dimensions")
        };
        let one = T::of(1.0);
        let rho = *r_in / *r_out;
        let rho2 = rho * rho;
        let ratio = (one + rho + rho2 + rho2 * rho + rho2 * rho2) / (one + rho + rho2);
        let q = m * *r_out * *r_out / T::of(5.0) * ratio;
        [q, q, q]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        let [radius, inner_radius] = r.radii()?;
        Ok(Sphere {
            center: r.point("center")?,
            radius,
            inner_radius,
            orientation: r.orientation(),
        })
    }







    fn real_size_direction(&self) -> Option<[DD; 3]> {
        None
    }

    fn outline(&self) -> Outline {
        let c = self.center;
        let [x, y, z] = axes(&self.orientation.matrix());
        let _ = (&x, &y, &z);
        let r = self.radius;
        Outline::Pieces(vec![Piece::Ellipsoid {
            c,
            m: [[r, 0.0, 0.0], [0.0, r, 0.0], [0.0, 0.0, r]],
        }])
    }










    placed_by_centre!(radius: Radius, inner_radius: InnerRadius);

    centred_centroid!();
}
