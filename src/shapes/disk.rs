//! A disk: a thin circular plate of radius `R` in the local x–y plane;
//! with an inner radius `r` an annulus: dimensions [R, r]. A cylinder of
//! no length: m (R² + r²)/4 about each diameter.

use super::{Dims, Drawn, MaterialRule, PER_AREA, Shape, ShapeInfo, ShapeKind, across_ring, ring};
use crate::numeric::Real;

/// The disk, in the registry (`shapes::registry!`).
#[derive(Clone, Copy, Debug)]
pub struct Disk;

impl ShapeKind for Disk {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Disk,
        name: "disk",
        keys: &[
            "areal_density",
            "radius",
            "inner_radius",
            "diameter",
            "inner_diameter",
            "material",
            "thickness",
            "center",
            "rotation",
            "mass",
            "remove",
        ],
        density: Some(PER_AREA),
        dims: Dims::Radii { length: false },
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Thickness,
        real_size: None,
        nonzero_moments: 2,
        drawn: Drawn::Rims,
        degenerate: "a density on a thin ring (`inner_radius` = `radius`)",
        help: "a disk takes `mass` or `areal_density`, and `radius` or `diameter` (in its local x–y plane) with `center` (and optional `rotation`); an `inner_radius` makes it an annulus",
    };

    /// Π (1), R − r and R + r (2), two products, and one of slack.
    const MEASURE_ROUNDINGS: f64 = 6.0;

    /// M (R² + r²)/4: 4, and one of slack.
    const MOMENT_ROUNDINGS: f64 = 5.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure<T: Real>(d: &[T]) -> T {
        ring(d)
    }

    fn second_moments<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [r_out, r_in] = d else {
            unreachable!("the model passes a disk two dimensions")
        };
        let q = across_ring(m, *r_out, *r_in);
        [q, q, T::of(0.0)]
    }

    fn axial_offset<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }
}
