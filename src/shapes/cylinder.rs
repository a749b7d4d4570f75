//! A cylinder: radius `R`, length `L` along local z, centred on the
//! origin; with an inner radius `r` a tube: dimensions [R, r, L].
//!
//! About a diameter in its mid-plane m (R² + r²)/4 (half the axial
//! m (R² + r²)/2), and m L²/12 along the axis. R² − r² is formed as
//! (R − r)(R + r), so a thin wall is no difference of large numbers.

use super::{Dims, Drawn, MaterialRule, PER_VOLUME, Shape, ShapeInfo, ShapeKind, across_ring, ring, segment};
use crate::numeric::Real;

/// The cylinder, in the registry (`shapes::registry!`).
#[derive(Clone, Copy, Debug)]
pub struct Cylinder;

impl ShapeKind for Cylinder {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Cylinder,
        name: "cylinder",
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
        dims: Dims::Radii { length: true },
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        drawn: Drawn::Frustum,
        degenerate: "a density on a thin shell (`inner_radius` = `radius`)",
        help: "a cylinder takes `mass` or `density`, `radius` (or `diameter`) and `length` (along its local z) with `center` (and optional `rotation`); an `inner_radius` makes it a tube",
    };

    /// Π (1), R − r and R + r (2), two products, the length (1).
    const MEASURE_ROUNDINGS: f64 = 6.0;

    /// M (R² + r²)/4: 4, and one of slack.
    const MOMENT_ROUNDINGS: f64 = 5.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure<T: Real>(d: &[T]) -> T {
        let [_, _, l] = d else {
            unreachable!("the model passes a cylinder three dimensions")
        };
        ring(d) * *l
    }

    fn second_moments<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [r_out, r_in, l] = d else {
            unreachable!("the model passes a cylinder three dimensions")
        };
        let q = across_ring(m, *r_out, *r_in);
        [q, q, segment(m, *l)]
    }

    fn axial_offset<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }
}
