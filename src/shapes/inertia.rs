//! A given inertia: a bought or previously computed component, its mass,
//! centre and inertia tensor about its centroid given. No closed form
//! here: the composer turns its tensor (`part::Place::Given`).

use super::{Dims, Drawn, MaterialRule, Shape, ShapeInfo, ShapeKind};
use crate::numeric::Real;

/// The inertia, in the registry (`shapes::registry!`).
#[derive(Clone, Copy, Debug)]
pub struct Inertia;

impl ShapeKind for Inertia {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Inertia,
        name: "inertia",
        keys: &[
            "mass", "center", "rotation", "inertia", "products", "remove",
        ],
        density: None,
        dims: Dims::Given,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::None,
        real_size: None,
        nonzero_moments: 0,
        drawn: Drawn::Given,
        degenerate: "a tensor that is not symmetric or not physically valid",
        help: "an inertia part takes `mass`, `center`, `inertia` = [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] about its centroid in its local axes (optional `rotation`), tensor convention unless `products = \"positive\"`",
    };

    /// None: its mass is given.
    const MEASURE_ROUNDINGS: f64 = 0.0;

    /// (its tensor is turned: `part::error::GIVEN`).
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure<T: Real>(d: &[T]) -> T {
        let [] = d else {
            unreachable!("the model passes a given inertia no dimensions")
        };
        T::of(1.0)
    }

    fn second_moments<T: Real>(_: T, d: &[T]) -> [T; 3] {
        let [] = d else {
            unreachable!("the model passes a given inertia no dimensions")
        };
        [T::of(0.0); 3]
    }

    fn axial_offset<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }
}
