//! A disk: a thin circular plate of radius `R` in the local x–y plane;
//! with an inner radius `r` an annulus: dimensions [R, r]. A cylinder of
//! no length: m (R² + r²)/4 about each diameter.

use super::read::Reader;
use crate::diag::Diagnostic;
use super::common::{reset_turn, points, 
    at, axes, density_power, diagonal, exact_centroid_error, flip, mirror_axis, norm1, var,
};
use super::outline::Outline;
use super::{Dims, MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use super::lift::Lift;
use super::common::rim;
use super::{PER_AREA, across_ring, ring};

/// A disk or annulus, placed by its `center` and turned by its `orientation`,
/// in its file's units.
#[derive(Debug, Clone, PartialEq)]
pub struct Disk {
    pub center: [f64; 3],
    /// `radius`.
    pub radius: f64,
    /// `inner_radius`.
    pub inner_radius: f64,
    pub orientation: Orientation,
}

impl Disk {
    /// Its dimensions as its closed forms take them, read through `l`.
    fn dims<T: Real, L: Lift>(&self, l: L) -> [T; 2] {
        [var(self.radius, Slot::Radius, l), var(self.inner_radius, Slot::InnerRadius, l)]
    }
}

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
        degenerate: "a density on a thin ring (`inner_radius` = `radius`)",
        help: "a disk takes `mass` or `areal_density`, and `radius` or `diameter` (in its local x–y plane) with `center` (and optional `rotation`); an `inner_radius` makes it an annulus",
    };

    /// π (1), R − r and R + r (2), two products, and one of slack.
    const MEASURE_ROUNDINGS: f64 = 6.0;

    /// m (R² + r²)/4: 4, and one of slack.
    const MOMENT_ROUNDINGS: f64 = 5.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        ring(d)
    }

    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [r_out, r_in] = d else {
            unreachable!("the model passes a disk two dimensions")
        };
        let q = across_ring(m, *r_out, *r_in);
        [q, q, T::of(0.0)]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &impl Reader) -> Result<Self, Diagnostic> {
        let [radius, inner_radius] = r.radii()?;
        Ok(Disk {
            center: r.point("center")?,
            radius,
            inner_radius,
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
            Self::moments_of(m, &[self.radius, self.inner_radius]),
            3,
            Self::INFO.nonzero_moments,
        )
    }

    fn moved(&mut self, m: &impl Mover) {
        self.center = m.point(self.center);
        self.radius *= m.length();
        self.inner_radius *= m.length();
        m.turn(&mut self.orientation);
    }

    fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
        let [x, y, z] = &mut self.center;
        f(Slot::At(0), x);
        f(Slot::At(1), y);
        f(Slot::At(2), z);
        f(Slot::Radius, &mut self.radius);
        f(Slot::InnerRadius, &mut self.inner_radius);
    }

    fn real_size_direction(&self) -> Option<[DD; 3]> {
        None
    }

    fn outline(&self) -> Outline {
        let c = self.center;
        let [x, y, z] = axes(&self.orientation.matrix());
        let _ = (&x, &y, &z);
        let mut p = vec![rim(c, self.radius, &x, &y)];
        if self.inner_radius > 0.0 {
            p.push(rim(c, self.inner_radius, &x, &y));
        }
        Outline::Pieces(p)
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
        self.radius = src.radius;
        self.inner_radius = src.inner_radius;
        reset_turn(&mut self.orientation, &src.orientation);
    }

    fn mirror(&mut self) {
        flip(mirror_axis::<Self>(), &mut self.orientation);
    }
}
