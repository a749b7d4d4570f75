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

use super::{Dims, Drawn, MaterialRule, PER_VOLUME, Shape, ShapeInfo, ShapeKind};
use crate::numeric::Real;

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

/// The torus, in the registry (`shapes::registry!`).
#[derive(Clone, Copy, Debug)]
pub struct Torus;

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
        dims: Dims::Torus,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        drawn: Drawn::Ring,
        degenerate: "a `tube_radius` above `radius` (self-intersecting), or a density on a thin shell (`inner_tube_radius` = `tube_radius`)",
        help: "a torus takes `mass` or `density`, `radius` (its axis to the tube's centre) and `tube_radius` (at most `radius`), with `center` (and optional `rotation`; its axis is local z); an `inner_tube_radius` makes the tube hollow",
    };

    /// 2π² (3), a − b and a + b (2), four products, and one of slack.
    const MEASURE_ROUNDINGS: f64 = 10.0;

    /// A² + b² and R² + ¾(…) with m/2: 8.
    const MOMENT_ROUNDINGS: f64 = 8.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure<T: Real>(d: &[T]) -> T {
        measure(d)
    }

    fn second_moments<T: Real>(m: T, d: &[T]) -> [T; 3] {
        second_moments(m, d)
    }

    fn axial_offset<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }
}
