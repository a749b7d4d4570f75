//! A point mass at the origin: no dimensions, no second moment of its
//! own.

use super::common::axes;
use super::read::Reader;
use crate::diag::Diagnostic;
use super::outline::{Outline, Marker};
use super::{MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use super::lift::Lift;

/// A point mass, placed by its `center` and turned by its `orientation`,
/// in its file's units.
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    pub center: [f64; 3],

    pub orientation: Orientation,
}

impl ShapeKind for Point {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Point,
        name: "point",
        keys: &["center", "mass"],
        density: None,
        sizes: &[],
        size_items: 0,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::None,
        real_size: None,
        nonzero_moments: 0,
        degenerate: "none",
        help: "a point takes `mass` and `center`",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "point mass",
        dims: &[],
        measure: "",
        moments: [
            "0",
            "0",
            "0",
        ],
    };

    /// None: its mass is given.
    const MEASURE_ROUNDINGS: f64 = 0.0;

    /// None: it has no second moment (kept at the others’ count).
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        let [] = d else {
            unreachable!("the model passes a point no dimensions")
        };
        T::of(1.0)
    }

    fn moments_of<T: Real>(_: T, d: &[T]) -> [T; 3] {
        let [] = d else {
            unreachable!("the model passes a point no dimensions")
        };
        [T::of(0.0); 3]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        Ok(Point {
            center: r.point("center")?,
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
        Outline::Marker(Marker::Point, c)
    }










    placed_by_centre!();

    centred_centroid!();
}
