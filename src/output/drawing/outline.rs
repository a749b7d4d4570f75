//! A part's outline for the drawing: its placed shape's
//! (`shapes::outline`, `Place::outline`).

pub use crate::shapes::outline::{Marker, Outline, Piece, V3};

/// A part's outline in the file's frame.
pub fn of(part: &crate::part::Part) -> Outline {
    part.spec.place.outline()
}
