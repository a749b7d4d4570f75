//! A point mass at the origin: no dimensions, no second moment of its
//! own.

use super::{Dims, Drawn, MaterialRule, Shape, ShapeInfo, ShapeKind};
use crate::numeric::Real;

/// The point, in the registry (`shapes::registry!`).
#[derive(Clone, Copy, Debug)]
pub struct Point;

impl ShapeKind for Point {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Point,
        name: "point",
        keys: &["center", "mass"],
        density: None,
        dims: Dims::None,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::None,
        real_size: None,
        nonzero_moments: 0,
        drawn: Drawn::Point,
        degenerate: "none",
        help: "a point takes `mass` and `center`",
    };

    /// None: its mass is given.
    const MEASURE_ROUNDINGS: f64 = 0.0;

    /// None: it has no second moment (kept at the others’ count).
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure<T: Real>(d: &[T]) -> T {
        let [] = d else {
            unreachable!("the model passes a point no dimensions")
        };
        T::of(1.0)
    }

    fn second_moments<T: Real>(_: T, d: &[T]) -> [T; 3] {
        let [] = d else {
            unreachable!("the model passes a point no dimensions")
        };
        [T::of(0.0); 3]
    }

    fn axial_offset<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }
}
