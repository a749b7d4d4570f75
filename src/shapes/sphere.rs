//! A sphere: radius `R` about the origin; with an inner radius `r` a
//! hollow sphere, and with r = R a thin shell: dimensions [R, r].
//!
//! m/5 · (R⁵ − r⁵)/(R³ − r³) along every axis, written as
//! m R²/5 · (1 + ρ + ρ² + ρ³ + ρ⁴)/(1 + ρ + ρ²) with ρ = r/R: no
//! cancellation for thin walls, no overflow in R⁵, and m R²/3 for a thin
//! shell. The volume's R³ − r³ is formed as (R − r)(R² + Rr + r²).

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
use super::PER_VOLUME;

/// A sphere, hollow or a thin shell, placed by its `center` and turned by its `orientation`,
/// in its file's units.
#[derive(Debug, Clone, PartialEq)]
pub struct Sphere {
    pub center: [f64; 3],
    /// `radius`.
    pub radius: f64,
    /// `inner_radius`.
    pub inner_radius: f64,
    pub orientation: Orientation,
}

impl Sphere {
    /// Its dimensions as its closed forms take them, read through `l`.
    fn dims<T: Real, L: Lift>(&self, l: L) -> [T; 2] {
        [var(self.radius, Slot::Radius, l), var(self.inner_radius, Slot::InnerRadius, l)]
    }
}

impl ShapeKind for Sphere {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Sphere,
        name: "sphere",
        keys: &[
            "density",
            "radius",
            "inner_radius",
            "diameter",
            "inner_diameter",
            "material",
            "center",
            "rotation",
            "mass",
            "remove",
        ],
        density: Some(PER_VOLUME),
        dims: Dims::Radii { length: false },
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        degenerate: "a density on a thin shell (`inner_radius` = `radius`)",
        help: "a sphere takes `mass` or `density`, and `radius` (or `diameter`) with `center`; an `inner_radius` makes it hollow (equal to `radius`: a thin shell)",
    };

    /// 4/3 and π (3), R − r (1), R² + Rr + r² (3), three products, and one of slack.
    const MEASURE_ROUNDINGS: f64 = 11.0;

    /// ρ = r/R moves the ratio by at most its own rounding, its powers and sums 7 and 3, the division 3, m R²/5 four; at most 18.
    const MOMENT_ROUNDINGS: f64 = 18.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        let [r_out, r_in] = d else {
            unreachable!("the model passes a sphere two dimensions")
        };
        let (r_out, r_in) = (*r_out, *r_in);
        T::of(4.0) / T::of(3.0)
            * T::pi()
            * (r_out - r_in)
            * (r_out * r_out + r_out * r_in + r_in * r_in)
    }

    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [r_out, r_in] = d else {
            unreachable!("the model passes a sphere two dimensions")
        };
        let one = T::of(1.0);
        let rho = *r_in / *r_out;
        let rho2 = rho * rho;
        let ratio = (one + rho + rho2 + rho2 * rho + rho2 * rho2) / (one + rho + rho2);
        let q = m * *r_out * *r_out / T::of(5.0) * ratio;
        [q, q, q]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &impl Reader) -> Result<Self, Diagnostic> {
        let [radius, inner_radius] = r.radii()?;
        Ok(Sphere {
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
        let r = self.radius;
        Outline::Pieces(vec![Piece::Ellipsoid {
            c,
            m: [[r, 0.0, 0.0], [0.0, r, 0.0], [0.0, 0.0, r]],
        }])
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
