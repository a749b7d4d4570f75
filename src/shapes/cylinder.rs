//! A cylinder: radius `R`, length `L` along local z, centred on the
//! origin; with an inner radius `r` a tube: dimensions [R, r, L].
//!
//! About a diameter in its mid-plane m (R² + r²)/4 (half the axial
//! m (R² + r²)/2), and m L²/12 along the axis. R² − r² is formed as
//! (R − r)(R + r), so a thin wall is no difference of large numbers.

use super::common::{add, axes, rim, scaled};
use super::read::Reader;
use crate::diag::Diagnostic;
use super::outline::{Outline, Piece};
use super::{MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use super::lift::Lift;
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
        sizes: &["radius", "inner_radius", "length"],
        size_items: 0,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        degenerate: "a density on a thin shell (`inner_radius` = `radius`)",
        help: "a cylinder takes `mass` or `density`, `radius` (or `diameter`) and `length` (along its local z) with `center` (and optional `rotation`); an `inner_radius` makes it a tube",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "cylinder of radius R, bore r, length L along local z",
        dims: &[
            super::symbol("R", "R", super::Slot::Radius),
            super::symbol("r", "r", super::Slot::InnerRadius),
            super::symbol("L", "L", super::Slot::Length),
        ],
        measure: "pi*(R^2 - r^2)*L",
        moments: [
            "m*(3*(R^2 + r^2) + L^2)/12",
            "m*(3*(R^2 + r^2) + L^2)/12",
            "m*(R^2 + r^2)/2",
        ],
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

    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
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










    placed_by_centre!(radius: Radius, inner_radius: InnerRadius, length: Length);

    centred_centroid!();
}
