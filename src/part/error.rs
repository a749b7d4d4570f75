//! The error model of one part, as `part` composes it: its mass's
//! (`mass_error`) and its centroid's (`centroid_error`); the rest, each
//! placed shape's, is `shapes::error`.

use super::{MassSpec, Spec};
pub use crate::shapes::error::{
    GIVEN, OUTER, Own, TURN, U_DD, U64, placed_units, turn_error, unit_of,
};

/// The error of a part's mass, relative, in units of the arithmetic `T`:
/// 0 when given; for a density, one product and its measure's roundings
/// (`shapes::error::measure_error`), and the f64 roundings that formed the
/// density from the file's numbers (`Placed::mass`: a material's density
/// times a thickness, an area or a diameter's π/4 d², in f64 whatever the
/// arithmetic, so in `extended` worth 2⁵³/7 of its units each).
pub fn mass_error<T: crate::numeric::Real>(spec: &Spec) -> f64 {
    if let MassSpec::Given(_) = spec.mass {
        return 0.0;
    }
    1.0 + spec.place.measure_error() + f64::from(spec.placed.mass) * U64 / unit_of::<T>()
}

/// How far each component of a part's centroid, as `part::centroid` forms
/// it in double-double, may lie from the exact centroid
/// (`shapes::error::centroid_error`), with the rounding of its position by
/// the frames that placed it (`Placed::at`).
pub fn centroid_error(spec: &Spec, centroid: &[f64; 3]) -> [f64; 3] {
    spec.place
        .centroid_error(f64::from(spec.placed.at), centroid)
}
