//! A cylinder: radius `R`, length `L` along local z, centred on the
//! origin; with an inner radius `r` a tube: dimensions [R, r, L].
//!
//! About a diameter in its mid-plane m (R² + r²)/4 (half the axial
//! m (R² + r²)/2), and m L²/12 along the axis. R² − r² is formed as
//! (R − r)(R + r), so a thin wall is no difference of large numbers.

use super::read::Reader;
use crate::diag::Diagnostic;
use super::common::{reset_turn, points, 
    at, axes, density_power, diagonal, exact_centroid_error, flip, mirror_axis, norm1, var,
};
use super::outline::{Outline, Piece};
use super::{Dims, MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use super::lift::Lift;
use super::common::{add, rim, scaled};
use super::{PER_VOLUME, across_ring, ring, segment};

/// A cylinder or tube, placed by its `center` and turned by its `orientation`,
/// in its file's units.
#[derive(Debug, Clone, PartialEq)]
pub struct Cylinder {
    pub center: [f64; 3],
    /// `radius`.
    pub radius: f64,
    /// `inner_radius`.
    pub inner_radius: f64,
    /// `length`.
    pub length: f64,
    pub orientation: Orientation,
}

impl Cylinder {
    /// Its dimensions as its closed forms take them, read through `l`.
    fn dims<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
        [var(self.radius, Slot::Radius, l), var(self.inner_radius, Slot::InnerRadius, l), var(self.length, Slot::Length, l)]
    }
}

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
        degenerate: "a density on a thin shell (`inner_radius` = `radius`)",
        help: "a cylinder takes `mass` or `density`, `radius` (or `diameter`) and `length` (along its local z) with `center` (and optional `rotation`); an `inner_radius` makes it a tube",
    };

    /// π (1), R − r and R + r (2), two products, the length (1).
    const MEASURE_ROUNDINGS: f64 = 6.0;

    /// m (R² + r²)/4: 4, and one of slack.
    const MOMENT_ROUNDINGS: f64 = 5.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        let [_, _, l] = d else {
            unreachable!("the model passes a cylinder three dimensions")
        };
        ring(d) * *l
    }

    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [r_out, r_in, l] = d else {
            unreachable!("the model passes a cylinder three dimensions")
        };
        let q = across_ring(m, *r_out, *r_in);
        [q, q, segment(m, *l)]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &impl Reader) -> Result<Self, Diagnostic> {
        let [radius, inner_radius] = r.radii()?;
        let length = r.length("length")?;
        Ok(Cylinder {
            center: r.point("center")?,
            radius,
            inner_radius,
            length,
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
            Self::moments_of(m, &[self.radius, self.inner_radius, self.length]),
            3,
            Self::INFO.nonzero_moments,
        )
    }

    fn moved(&mut self, m: &impl Mover) {
        self.center = m.point(self.center);
        self.radius *= m.length();
        self.inner_radius *= m.length();
        self.length *= m.length();
        m.turn(&mut self.orientation);
    }

    fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
        let [x, y, z] = &mut self.center;
        f(Slot::At(0), x);
        f(Slot::At(1), y);
        f(Slot::At(2), z);
        f(Slot::Radius, &mut self.radius);
        f(Slot::InnerRadius, &mut self.inner_radius);
        f(Slot::Length, &mut self.length);
    }

    fn real_size_direction(&self) -> Option<[DD; 3]> {
        None
    }

    fn outline(&self) -> Outline {
        let c = self.center;
        let [x, y, z] = axes(&self.orientation.matrix());
        let _ = (&x, &y, &z);
        let (r, inner, l) = (self.radius, self.inner_radius, self.length);
        let ends = [add(c, scaled(-l / 2.0, z)), add(c, scaled(l / 2.0, z))];
        let mut p = vec![rim(ends[0], r, &x, &y), rim(ends[1], r, &x, &y)];
        p.push(Piece::Side {
            c: ends,
            r: [r, r],
            u: x,
            v: y,
        });
        if inner > 0.0 {
            p.extend(ends.map(|at| rim(at, inner, &x, &y)));
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
        self.length = src.length;
        reset_turn(&mut self.orientation, &src.orientation);
    }

    fn mirror(&mut self) {
        flip(mirror_axis::<Self>(), &mut self.orientation);
    }
}
