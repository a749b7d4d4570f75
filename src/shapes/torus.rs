//! A torus about local z: its tube's centre line a circle of radius R in
//! the local x–y plane, the tube of radius a, hollow to an inner tube
//! radius b: dimensions [R, a, b]. Its centroid is the origin.
//!
//! NOTE: the derivation (Pappus): a point of the tube's section at
//! (R + u, z), u² + z² in [b², a²], sweeps a circle of radius R + u, so
//! ∫f dV = ∫∫ f 2π(R + u) dA over the annulus, whose odd moments in u
//! vanish. With A = π(a² − b²), ∫∫u² dA = ∫∫z² dA = π(a⁴ − b⁴)/4:
//!
//! - V = 2πR A = 2π²R (a − b)(a + b);
//! - ∫z² dV = 2πR π(a⁴ − b⁴)/4, so ∫z² dm = m (a² + b²)/4;
//! - ∫(x² + y²) dV = 2π ∫∫(R + u)³ dA = 2πR (R² A + 3π(a⁴ − b⁴)/4), so
//!   ∫(x² + y²) dm = m (R² + ¾(a² + b²)) and ∫x² dm = ∫y² dm half of it.
//!
//! Sums of positive terms only: no cancellation for a thin tube wall or a
//! thin tube; at b = a, a thin toroidal shell.

use super::common::axes;
use super::read::Reader;
use crate::diag::Diagnostic;
use super::outline::{Outline, Piece};
use super::{ MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use super::lift::Lift;
use super::PER_VOLUME;

/// The volume 2π²R (a − b)(a + b).
pub fn measure<T: Real>(d: &[T]) -> T {
    let (r, a, b) = (d[0], d[1], d[2]);
    T::of(2.0) * T::pi() * T::pi() * r * (a - b) * (a + b)
}

/// ∫x² dm, ∫y² dm, ∫z² dm about the centre, local axes.
pub fn second_moments<T: Real>(m: T, d: &[T]) -> [T; 3] {
    let (r, a, b) = (d[0], d[1], d[2]);
    let tube = a * a + b * b;
    let across = m * (r * r + T::of(0.75) * tube) / T::of(2.0);
    [across, across, m * tube / T::of(4.0)]
}


/// A torus, its tube solid or hollow, placed by its `center` and turned by its `orientation`,
/// in its file's units.
#[derive(Debug, Clone, PartialEq)]
pub struct Torus {
    pub center: [f64; 3],
    /// `radius`.
    pub radius: f64,
    /// `tube_radius`.
    pub tube_radius: f64,
    /// `inner_tube_radius`.
    pub inner_tube_radius: f64,
    pub orientation: Orientation,
}

impl ShapeKind for Torus {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Torus,
        name: "torus",
        keys: &[
            "density",
            "radius",
            "tube_radius",
            "inner_tube_radius",
            "material",
            "center",
            "rotation",
            "mass",
            "remove",
        ],
        density: Some(PER_VOLUME),
        sizes: &["radius", "tube_radius", "inner_tube_radius"],
        size_items: 0,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        degenerate: "a `tube_radius` above `radius` (self-intersecting), or a density on a thin shell (`inner_tube_radius` = `tube_radius`)",
        help: "a torus takes `mass` or `density`, `radius` (its axis to the tube's centre) and `tube_radius` (at most `radius`), with `center` (and optional `rotation`; its axis is local z); an `inner_tube_radius` makes the tube hollow",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "torus: centre-line radius R, tube radius a, bore a_i, about local z",
        dims: &[
            super::symbol("R", "R", super::Slot::Radius),
            super::symbol("a", "a", super::Slot::TubeRadius),
            super::symbol("a_i", "a_i", super::Slot::InnerTubeRadius),
        ],
        measure: "2*pi^2*R*(a^2 - a_i^2)",
        moments: [
            "m*(R^2/2 + 5*(a^2 + a_i^2)/8)",
            "m*(R^2/2 + 5*(a^2 + a_i^2)/8)",
            "m*(R^2 + 3*(a^2 + a_i^2)/4)",
        ],
    };

    /// 2π² (3), a − b and a + b (2), four products, and one of slack.
    const MEASURE_ROUNDINGS: f64 = 10.0;

    /// A² + b² and R² + ¾(…) with m/2: 8.
    const MOMENT_ROUNDINGS: f64 = 8.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        measure(d)
    }

    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        second_moments(m, d)
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        let [radius, tube_radius, inner_tube_radius] = r.torus()?;
        Ok(Torus {
            center: r.point("center")?,
            radius,
            tube_radius,
            inner_tube_radius,
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
        Outline::Pieces(vec![Piece::Torus {
            c,
            r: self.radius,
            a: self.tube_radius,
            u: x,
            v: y,
        }])
    }










    placed_by_centre!(radius: Radius, tube_radius: TubeRadius, inner_tube_radius: InnerTubeRadius);

    centred_centroid!();
}
