//! The keys of a part as the model reads them off its table: each with
//! where it is when present (`key_spans`), a quantity by its key
//! (`quantity_key`), the earliest of a set (`first`).

use super::raw::{Quantity, RawPart};
use std::ops::Range;
use toml::Spanned;

/// Keys of a part with the span of each that is present.
pub(super) type Present<'k> = Vec<(&'k str, Option<Range<usize>>)>;

/// Every key a part may have, with where it is when present.
pub(super) fn key_spans(p: &RawPart) -> [(&'static str, Option<Range<usize>>); 35] {
    [
        ("density", p.density.as_deref().map(Spanned::span)),
        (
            "areal_density",
            p.areal_density.as_deref().map(Spanned::span),
        ),
        (
            "linear_density",
            p.linear_density.as_deref().map(Spanned::span),
        ),
        ("size", p.size.as_ref().map(Spanned::span)),
        ("length", p.length.as_deref().map(Spanned::span)),
        ("center", p.center.as_ref().map(Spanned::span)),
        ("rotation", p.rotation.as_deref().map(Spanned::span)),
        ("corner", p.corner.as_deref().map(Spanned::span)),
        ("edges", p.edges.as_deref().map(Spanned::span)),
        ("from", p.from.as_deref().map(Spanned::span)),
        ("to", p.to.as_deref().map(Spanned::span)),
        ("mass", p.mass.as_ref().map(Spanned::span)),
        ("thickness", p.thickness.as_deref().map(Spanned::span)),
        ("diameter", p.diameter.as_deref().map(Spanned::span)),
        ("radius", p.radius.as_deref().map(Spanned::span)),
        ("inner_radius", p.inner_radius.as_deref().map(Spanned::span)),
        ("remove", p.remove.as_deref().map(Spanned::span)),
        ("inertia", p.inertia.as_deref().map(Spanned::span)),
        ("products", p.products.as_deref().map(Spanned::span)),
        ("vertices", p.vertices.as_deref().map(Spanned::span)),
        ("material", p.material.as_deref().map(Spanned::span)),
        ("area", p.area.as_deref().map(Spanned::span)),
        ("include", p.include.as_deref().map(Spanned::span)),
        ("origin", p.origin.as_deref().map(Spanned::span)),
        ("params", p.params.as_deref().map(Spanned::span)),
        (
            "inner_diameter",
            p.inner_diameter.as_deref().map(Spanned::span),
        ),
        ("top_radius", p.top_radius.as_deref().map(Spanned::span)),
        (
            "top_inner_radius",
            p.top_inner_radius.as_deref().map(Spanned::span),
        ),
        ("tube_radius", p.tube_radius.as_deref().map(Spanned::span)),
        (
            "inner_tube_radius",
            p.inner_tube_radius.as_deref().map(Spanned::span),
        ),
        ("polygon", p.polygon.as_deref().map(Spanned::span)),
        ("file", p.file.as_deref().map(Spanned::span)),
        ("mesh_unit", p.mesh_unit.as_deref().map(Spanned::span)),
        ("mode", p.mode.as_deref().map(Spanned::span)),
        ("tol", p.tol.as_deref().map(Spanned::span)),
    ]
}

/// The span of `key` among `keys` (from `key_spans`), if present.
pub(super) fn span_of(keys: &[(&str, Option<Range<usize>>)], key: &str) -> Option<Range<usize>> {
    keys.iter()
        .find(|(k, _)| *k == key)
        .and_then(|(_, s)| s.clone())
}

/// A part's quantity by its key: the density kinds' keys and the sizes
/// `ShapeInfo` names (`thickness`, `diameter`, `area`).
pub(super) fn quantity_key<'p>(p: &'p RawPart, key: &str) -> Option<&'p Spanned<Quantity>> {
    match key {
        "density" => p.density.as_deref(),
        "areal_density" => p.areal_density.as_deref(),
        "linear_density" => p.linear_density.as_deref(),
        "thickness" => p.thickness.as_deref(),
        "diameter" => p.diameter.as_deref(),
        "area" => p.area.as_deref(),
        _ => unreachable!("`{key}` is not a quantity key of `ShapeInfo`"),
    }
}

/// The keys of `key_spans`, and `shape`.
pub(super) fn present_keys(p: &RawPart) -> Present<'static> {
    let mut keys: Present<'static> = key_spans(p).to_vec();
    keys.push(("shape", p.shape.as_ref().map(Spanned::span)));
    keys
}

/// The earliest present key of a set, with its span.
pub(super) fn first<'k>(
    set: &[(&'k str, Option<Range<usize>>)],
) -> Option<(&'k str, Range<usize>)> {
    set.iter()
        .filter_map(|(k, s)| s.clone().map(|s| (*k, s)))
        .min_by_key(|(_, s)| s.start)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::SHAPES;
    use std::collections::BTreeSet;

    /// The keys the model reads off a part (`key_spans`) are exactly the
    /// keys the shapes accept and those of an include: a key added to one
    /// and not the other fails here.
    #[test]
    fn the_part_keys_read_are_the_keys_the_shapes_and_includes_accept() {
        let read: BTreeSet<&str> = key_spans(&RawPart::default()).iter().map(|k| k.0).collect();
        let mut accepted: BTreeSet<&str> =
            SHAPES.iter().flat_map(|s| s.keys.iter().copied()).collect();
        accepted.extend(["include", "origin", "params"]);
        // `tol` goes wherever `mass` does (`tolerance::accepts`).
        accepted.insert(crate::model::tolerance::TOL_KEY);
        assert_eq!(read, accepted);
    }

    /// Every quantity key the shape table names (density, real size,
    /// material section) is one `quantity_key` reads.
    #[test]
    fn every_quantity_key_of_the_shape_table_is_read() {
        let p = RawPart::default();
        for s in &SHAPES {
            let keys = s
                .density
                .map(|d| d.key)
                .into_iter()
                .chain(s.real_size.map(|r| r.0))
                .chain(
                    super::super::material::material_keys(s.material)
                        .iter()
                        .copied(),
                );
            for k in keys {
                // Unknown keys are unreachable!: reaching the end is the test.
                assert!(quantity_key(&p, k).is_none(), "{}: `{k}`", s.name);
            }
        }
    }
}
