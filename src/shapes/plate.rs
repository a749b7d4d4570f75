//! A plate: a thin rectangle `a × b` in the local x–y plane, zero
//! thickness; dimensions [a, b]. Its real `thickness` never enters its
//! moments (`analysis::ideal` compares it with the box it describes).

use super::common::local_z;
use super::read::Reader;
use crate::diag::Diagnostic;
use super::lift::Lift;
use super::outline::{Outline, Piece};
use super::{MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Spanned, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use crate::numeric::pow2_scaled;
use super::{PER_AREA, Solid, product, segment};

/// A plate, in its file's units: by its `center`, `size` and turn, or by a
/// `corner` and the 2 perpendicular `edges` that span it.
#[derive(Debug, Clone, PartialEq)]
pub enum Plate {
    Centred {
        center: [f64; 3],
        size: [f64; 2],
        orientation: Orientation,
    },
    Spanned {
        corner: [f64; 3],
        edges: [[f64; 3]; 2],
    },
}

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
        sizes: &["size"],
        size_items: 2,
        centred: &["size", "center", "rotation"],
        spanned: Some(Spanned::CornerEdges(2)),
        material: MaterialRule::Thickness,
        real_size: Some(("thickness", Solid::Box)),
        nonzero_moments: 2,
        degenerate: "a zero or non-perpendicular edge",
        help: "a plate takes `mass` or `areal_density`, and `size` = [x, y] with `center` (and optional `rotation`), or `corner` with two `edges`; optionally its real `thickness`",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "thin rectangular plate a × b",
        dims: &[
            super::symbol("a", "a", super::Slot::Size(0)),
            super::symbol("b", "b", super::Slot::Size(1)),
        ],
        measure: "a*b",
        moments: [
            "m*b^2/12",
            "m*a^2/12",
            "m*(a^2 + b^2)/12",
        ],
    };

    /// Two products.
    const MEASURE_ROUNDINGS: f64 = 2.0;

    /// m a²/12: a², m·, /12, and one of slack.
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        product(d)
    }

    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [a, b] = d else {
            unreachable!("the model passes a plate two dimensions")
        };
        [segment(m, *a), segment(m, *b), T::of(0.0)]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    by_corner_or_centre!(Plate, 2);

    fn real_size_direction(&self) -> Option<[DD; 3]> {
        match self {
            Plate::Centred { orientation, .. } => Some(local_z(orientation)),
            Plate::Spanned { edges, .. } => {
                let [a, b] = [edges[0], edges[1]].map(|e| pow2_scaled(e.map(DD::of)));
                Some(std::array::from_fn(|i| {
                    let (j, k) = ((i + 1) % 3, (i + 2) % 3);
                    a[j] * b[k] - a[k] * b[j]
                }))
            },
        }
    }
}
