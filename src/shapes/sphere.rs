//! A sphere: radius `R` about the origin; with an inner radius `r` a
//! hollow sphere, and with r = R a thin shell: dimensions [R, r].
//!
//! m/5 · (R⁵ − r⁵)/(R³ − r³) along every axis, written as
//! m R²/5 · (1 + ρ + ρ² + ρ³ + ρ⁴)/(1 + ρ + ρ²) with ρ = r/R: no
//! cancellation for thin walls, no overflow in R⁵, and m R²/3 for a thin
//! shell. The volume's R³ − r³ is formed as (R − r)(R² + Rr + r²).

use super::{Dims, Drawn, MaterialRule, PER_VOLUME, Shape, ShapeInfo, ShapeKind};
use crate::numeric::Real;

/// The sphere, in the registry (`shapes::registry!`).
#[derive(Clone, Copy, Debug)]
pub struct Sphere;

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
        dims: Dims::Radii { length: false },
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        drawn: Drawn::Ball,
        degenerate: "a density on a thin shell (`inner_radius` = `radius`)",
        help: "a sphere takes `mass` or `density`, and `radius` (or `diameter`) with `center`; an `inner_radius` makes it hollow (equal to `radius`: a thin shell)",
    };

    /// 4/3 and π (3), R − r (1), R² + Rr + r² (3), three products, and one of slack.
    const MEASURE_ROUNDINGS: f64 = 11.0;

    /// ρ = r/R moves the ratio by at most its own rounding, its powers and sums 7 and 3, the division 3, m R²/5 four; at most 18.
    const MOMENT_ROUNDINGS: f64 = 18.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure<T: Real>(d: &[T]) -> T {
        let [r_out, r_in] = d else {
            unreachable!("the model passes a sphere two dimensions")
        };
        let (r_out, r_in) = (*r_out, *r_in);
        T::of(4.0) / T::of(3.0)
            * T::pi()
            * (r_out - r_in)
            * (r_out * r_out + r_out * r_in + r_in * r_in)
    }

    fn second_moments<T: Real>(m: T, d: &[T]) -> [T; 3] {
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

    fn axial_offset<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }
}
