//! A rod: a slender segment of length `L` along local z, zero radius;
//! dimensions [L]. Its real `diameter` never enters its moments
//! (`analysis::ideal` compares it with the cylinder it describes).

use super::{Dims, Drawn, MaterialRule, PER_LENGTH, Shape, ShapeInfo, ShapeKind, Solid, Spanned, product, segment};
use crate::numeric::Real;

/// The rod, in the registry (`shapes::registry!`).
#[derive(Clone, Copy, Debug)]
pub struct Rod;

impl ShapeKind for Rod {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Rod,
        name: "rod",
        keys: &[
            "linear_density",
            "length",
            "center",
            "rotation",
            "from",
            "to",
            "mass",
            "remove",
            "diameter",
            "material",
            "area",
        ],
        density: Some(PER_LENGTH),
        dims: Dims::Length,
        centred: &["length", "center", "rotation"],
        spanned: Some(Spanned::FromTo),
        material: MaterialRule::Section,
        real_size: Some(("diameter", Solid::Cylinder)),
        nonzero_moments: 1,
        drawn: Drawn::Segment,
        degenerate: "`to` equal to `from`",
        help: "a rod takes `mass` or `linear_density`, and `length` with `center` (and optional `rotation`), or `from` and `to`; optionally its real `diameter`",
    };

    /// One product.
    const MEASURE_ROUNDINGS: f64 = 1.0;

    /// M L²/12: L², m·, /12, and one of slack.
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure<T: Real>(d: &[T]) -> T {
        product(d)
    }

    fn second_moments<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [l] = d else {
            unreachable!("the model passes a rod one dimension")
        };
        let zero = T::of(0.0);
        [zero, zero, segment(m, *l)]
    }

    fn axial_offset<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }
}
