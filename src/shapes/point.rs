//! A point mass at the origin: no dimensions, no second moment of its
//! own.

use super::read::Reader;
use crate::diag::Diagnostic;
use super::common::{reset_turn, points, 
    at, axes, density_power, diagonal, exact_centroid_error, flip, mirror_axis, norm1,
};
use super::outline::{Outline, Marker};
use super::{Dims, MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Units};
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

impl Point {
    /// Its dimensions as its closed forms take them, read through `l`.
    fn dims<T: Real, L: Lift>(&self, _: L) -> [T; 0] {
        []
    }
}

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
        degenerate: "none",
        help: "a point takes `mass` and `center`",
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

    fn read(r: &impl Reader) -> Result<Self, Diagnostic> {
        Ok(Point {
            center: r.point("center")?,
            orientation: r.orientation(),
        })
    }

    fn measure<T: Real, L: Lift>(&self, l: L) -> T {
        Self::measure_of(&self.dims(l))
    }

    fn measure_error(&self) -> f64 {
        Self::MEASURE_ROUNDINGS
    }

    fn own_second_moment<T: Real, L: Lift>(
        &self,
        m: T,
        units: Option<Units>,
        l: L,
    ) -> (M3<T>, Option<Own>) {
        let d = Self::moments_of(m, &self.dims(l));
        diagonal(d, &self.orientation, units, Self::MOMENT_ROUNDINGS)
    }

    fn independent_moments(&self, m: f64, _: &M3<f64>) -> ([f64; 3], usize, usize) {
        (
            Self::moments_of(m, &[]),
            3,
            Self::INFO.nonzero_moments,
        )
    }

    fn moved(&mut self, m: &impl Mover) {
        self.center = m.point(self.center);

        m.turn(&mut self.orientation);
    }

    fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
        let [x, y, z] = &mut self.center;
        f(Slot::At(0), x);
        f(Slot::At(1), y);
        f(Slot::At(2), z);

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

    fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
        at(&self.center, l)
    }

    fn centroid_error(&self, at: f64, _: &[f64; 3]) -> [f64; 3] {
        exact_centroid_error(at)
    }

    fn shortest_span(&self) -> f64 {
        f64::INFINITY
    }

    fn density_power(&self) -> i32 {
        density_power::<Self>()
    }

    fn scaled_rounding(&self) -> Option<f64> {
        None
    }

    fn reach(&self) -> f64 {
        norm1(&self.center)
    }

    fn positions(&self) -> ([[f64; 3]; 4], usize) {
        points(&[self.center])
    }

    fn reset_from(&mut self, src: &Self) {
        self.center = src.center;
        reset_turn(&mut self.orientation, &src.orientation);
    }

    fn mirror(&mut self) {
        flip(mirror_axis::<Self>(), &mut self.orientation);
    }
}
