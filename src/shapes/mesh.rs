//! A triangle mesh read from a file (`shape = "mesh"`): its own file's
//! coordinates, placed by `origin` and `rotation` as an include is. Its
//! integrals come from the file (the `mesh` module, `part::Place::Mesh`), no
//! closed form here.

use super::{Dims, Drawn, MaterialRule, PER_VOLUME, Shape, ShapeInfo, ShapeKind};
use crate::numeric::Real;

/// The mesh, in the registry (`shapes::registry!`).
#[derive(Clone, Copy, Debug)]
pub struct Mesh;

impl ShapeKind for Mesh {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Mesh,
        name: "mesh",
        keys: &[
            "file",
            "mesh_unit",
            "mode",
            "origin",
            "rotation",
            "mass",
            "density",
            "areal_density",
            "thickness",
            "material",
            "remove",
        ],
        density: Some(PER_VOLUME),
        dims: Dims::Mesh,
        centred: &["origin"],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 0,
        drawn: Drawn::Silhouette,
        degenerate: "an open, inconsistently oriented or inside-out surface, or a triangle of zero area",
        help: "a mesh takes `file` (STL or OBJ, relative to the part file), `mesh_unit` (the file's length unit), `mass`, `density` or `material`, optional `origin` and `rotation`; `mode = \"shell\"` weighs the surface as a sheet: `mass`, `areal_density`, or `thickness` with `density` or `material`",
    };

    /// (its measure is its file’s: `shapes::error`).
    const MEASURE_ROUNDINGS: f64 = 0.0;

    /// (its integrals carry their own bound: `part`).
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = None;

    fn measure<T: Real>(d: &[T]) -> T {
        let [] = d else {
            unreachable!("the model passes a mesh no dimensions")
        };
        T::of(1.0)
    }

    fn second_moments<T: Real>(_: T, d: &[T]) -> [T; 3] {
        let [] = d else {
            unreachable!("the model passes a mesh no dimensions")
        };
        [T::of(0.0); 3]
    }

    fn axial_offset<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }
}
