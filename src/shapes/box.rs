//! A box: edges `a, b, c` along local x, y, z, centred on the origin;
//! dimensions [a, b, c]. Each ∫x² dm is a uniform segment's, m a²/12.

use super::{Dims, Drawn, MaterialRule, PER_VOLUME, Shape, ShapeInfo, ShapeKind, Spanned, product, segment};
use crate::numeric::Real;

/// The box, in the registry (`shapes::registry!`).
#[derive(Clone, Copy, Debug)]
pub struct Cuboid;

impl ShapeKind for Cuboid {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Box,
        name: "box",
        keys: &[
            "density", "size", "center", "rotation", "corner", "edges", "mass", "remove",
            "material",
        ],
        density: Some(PER_VOLUME),
        dims: Dims::Size(3),
        centred: &["size", "center", "rotation"],
        spanned: Some(Spanned::CornerEdges(3)),
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        drawn: Drawn::Corners,
        degenerate: "a zero or non-perpendicular edge",
        help: "a box takes `mass` or `density`, and `size` with `center` (and optional `rotation`), or `corner` with three `edges`",
    };

    /// Three products.
    const MEASURE_ROUNDINGS: f64 = 3.0;

    /// M a²/12: a², m·, /12, and one of slack.
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure<T: Real>(d: &[T]) -> T {
        product(d)
    }

    fn second_moments<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [a, b, c] = d else {
            unreachable!("the model passes a box three dimensions")
        };
        [segment(m, *a), segment(m, *b), segment(m, *c)]
    }

    fn axial_offset<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }
}
