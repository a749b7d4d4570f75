//! A plate: a thin rectangle `a × b` in the local x–y plane, zero
//! thickness; dimensions [a, b]. Its real `thickness` never enters its
//! moments (`analysis::ideal` compares it with the box it describes).

use super::{Dims, Drawn, MaterialRule, PER_AREA, Shape, ShapeInfo, ShapeKind, Solid, Spanned, product, segment};
use crate::numeric::Real;

/// The plate, in the registry (`shapes::registry!`).
#[derive(Clone, Copy, Debug)]
pub struct Plate;

impl ShapeKind for Plate {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Plate,
        name: "plate",
        keys: &[
            "areal_density",
            "size",
            "center",
            "rotation",
            "corner",
            "edges",
            "mass",
            "remove",
            "thickness",
            "material",
        ],
        density: Some(PER_AREA),
        dims: Dims::Size(2),
        centred: &["size", "center", "rotation"],
        spanned: Some(Spanned::CornerEdges(2)),
        material: MaterialRule::Thickness,
        real_size: Some(("thickness", Solid::Box)),
        nonzero_moments: 2,
        drawn: Drawn::Corners,
        degenerate: "a zero or non-perpendicular edge",
        help: "a plate takes `mass` or `areal_density`, and `size` = [x, y] with `center` (and optional `rotation`), or `corner` with two `edges`; optionally its real `thickness`",
    };

    /// Two products.
    const MEASURE_ROUNDINGS: f64 = 2.0;

    /// M a²/12: a², m·, /12, and one of slack.
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure<T: Real>(d: &[T]) -> T {
        product(d)
    }

    fn second_moments<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [a, b] = d else {
            unreachable!("the model passes a plate two dimensions")
        };
        [segment(m, *a), segment(m, *b), T::of(0.0)]
    }

    fn axial_offset<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }
}
