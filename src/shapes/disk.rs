//! A disk: a thin circular plate of radius `R` in the local x–y plane;
//! with an inner radius `r` an annulus: dimensions [R, r]. A cylinder of
//! no length: m (R² + r²)/4 about each diameter.

use super::common::{axes, rim};
use super::read::Reader;
use crate::diag::Diagnostic;
use super::outline::Outline;
use super::{MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use super::lift::Lift;
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
        sizes: &["radius", "inner_radius"],
        size_items: 0,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Thickness,
        real_size: None,
        nonzero_moments: 2,
        degenerate: "a density on a thin ring (`inner_radius` = `radius`)",
        help: "a disk takes `mass` or `areal_density`, and `radius` or `diameter` (in its local x–y plane) with `center` (and optional `rotation`); an `inner_radius` makes it an annulus",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "thin disk of radius R, hole r, in the local x–y plane",
        dims: &[
            super::symbol("R", "R", super::Slot::Radius),
            super::symbol("r", "r", super::Slot::InnerRadius),
        ],
        measure: "pi*(R^2 - r^2)",
        moments: [
            "m*(R^2 + r^2)/4",
            "m*(R^2 + r^2)/4",
            "m*(R^2 + r^2)/2",
        ],
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

    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        let [radius, inner_radius] = r.radii()?;
        Ok(Disk {
            center: r.point("center")?,
            radius,
            inner_radius,
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
        let mut p = vec![rim(c, self.radius, &x, &y)];
        if self.inner_radius > 0.0 {
            p.push(rim(c, self.inner_radius, &x, &y));
        }
        Outline::Pieces(p)
    }










    placed_by_centre!(radius: Radius, inner_radius: InnerRadius);

    centred_centroid!();
}
