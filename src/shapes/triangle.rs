//! A triangle: a thin triangular plate given by its three vertices in
//! the file's frame. Its one "dimension" is its area; its mass, centroid
//! and second moment come from its vertices (`part::Place::Vertices`),
//! not from closed forms here.

use super::{Dims, Drawn, MaterialRule, PER_AREA, Shape, ShapeInfo, ShapeKind, product};
use crate::numeric::Real;

/// The triangle, in the registry (`shapes::registry!`).
#[derive(Clone, Copy, Debug)]
pub struct Triangle;

impl ShapeKind for Triangle {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Triangle,
        name: "triangle",
        keys: &[
            "areal_density",
            "vertices",
            "mass",
            "remove",
            "material",
            "thickness",
        ],
        density: Some(PER_AREA),
        dims: Dims::Vertices,
        centred: &[],
        spanned: None,
        material: MaterialRule::Thickness,
        real_size: None,
        nonzero_moments: 0,
        drawn: Drawn::Edges,
        degenerate: "(nearly) collinear vertices",
        help: "a triangle takes `mass` or `areal_density`, and three `vertices` = [[x, y, z], [x, y, z], [x, y, z]] in the file's frame",
    };

    /// (its area is formed from its vertices: `shapes::error`).
    const MEASURE_ROUNDINGS: f64 = 1.0;

    /// (its second moment is formed from its vertices: `part::error::OUTER`).
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure<T: Real>(d: &[T]) -> T {
        product(d)
    }

    fn second_moments<T: Real>(_: T, d: &[T]) -> [T; 3] {
        let [_] = d else {
            unreachable!("the model passes a triangle its area")
        };
        [T::of(0.0); 3]
    }

    fn axial_offset<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }
}
