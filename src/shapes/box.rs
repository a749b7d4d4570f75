//! A box: edges `a, b, c` along local x, y, z, centred on the origin;
//! dimensions [a, b, c]. Each ∫x² dm is a uniform segment's, m a²/12.

use super::read::Reader;
use crate::diag::Diagnostic;
use super::lift::Lift;
use super::outline::{Outline, Piece};
use super::{MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Spanned, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use super::{PER_VOLUME, product, segment};

/// A box, in its file's units: by its `center`, `size` and turn, or by a
/// `corner` and the 3 perpendicular `edges` that span it.
#[derive(Debug, Clone, PartialEq)]
pub enum Cuboid {
    Centred {
        center: [f64; 3],
        size: [f64; 3],
        orientation: Orientation,
    },
    Spanned {
        corner: [f64; 3],
        edges: [[f64; 3]; 3],
    },
}

impl ShapeKind for Cuboid {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Box,
        name: "box",
        keys: &[
            "density", "size", "center", "rotation", "corner", "edges", "mass", "remove",
            "material",
        ],
        density: Some(PER_VOLUME),
        sizes: &["size"],
        size_items: 3,
        centred: &["size", "center", "rotation"],
        spanned: Some(Spanned::CornerEdges(3)),
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        degenerate: "a zero or non-perpendicular edge",
        help: "a box takes `mass` or `density`, and `size` with `center` (and optional `rotation`), or `corner` with three `edges`",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "solid rectangular box a × b × c",
        dims: &[
            super::symbol("a", "a", super::Slot::Size(0)),
            super::symbol("b", "b", super::Slot::Size(1)),
            super::symbol("c", "c", super::Slot::Size(2)),
        ],
        measure: "a*b*c",
        moments: [
            "m*(b^2 + c^2)/12",
            "m*(a^2 + c^2)/12",
            "m*(a^2 + b^2)/12",
        ],
    };

    /// Three products.
    const MEASURE_ROUNDINGS: f64 = 3.0;

    /// m a²/12: a², m·, /12, and one of slack.
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        product(d)
    }

    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [a, b, c] = d else {
            unreachable!("the model passes a box three dimensions")
        };
        [segment(m, *a), segment(m, *b), segment(m, *c)]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    by_corner_or_centre!(Cuboid, 3);

    fn real_size_direction(&self) -> Option<[DD; 3]> {
        match self {
            Cuboid::Centred { .. } => None,
            Cuboid::Spanned { .. } => None,
        }
    }
}
