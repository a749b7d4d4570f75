//! docs/part-file.md's table of part keys says what the key registry
//! declares (`massprop::model::schema::part_keys`: `keys::part_keys!` and
//! each shape's `OWN_KEYS`): every key with its value's kind, its
//! dimension, whether it takes "±", and its line; no key the registry
//! lacks. (The keys-by-shape table is checked in `docs`.) And the number
//! of a part a "±" on a key moves comes from its declaration
//! (`Key::fill`, `ShapeInfo::slot`).

use massprop::model::schema::part_keys;
use massprop::shapes::{Fill, Key, Kind, SHAPES, Shape, Slot};
use massprop::units::Dim;
use std::collections::BTreeMap;

/// The rows between the table's markers: key → its other columns.
fn documented() -> BTreeMap<String, Vec<String>> {
    let doc = std::fs::read_to_string("docs/part-file.md").unwrap();
    let begin = doc
        .find("<!-- part-keys: begin -->\n")
        .expect("docs/part-file.md marks its table of part keys");
    let end = doc.find("<!-- part-keys: end -->").unwrap();
    let mut rows = BTreeMap::new();
    for line in doc[begin..end].lines().skip(3) {
        let cells: Vec<String> = line
            .trim_matches('|')
            .split(" | ")
            .map(|c| c.trim().to_string())
            .collect();
        assert_eq!(cells.len(), 5, "a row of 5 cells: {line}");
        let key = cells[0]
            .strip_prefix('`')
            .and_then(|k| k.strip_suffix('`'))
            .unwrap_or_else(|| panic!("a key in backticks: {line}"))
            .to_string();
        assert!(rows.insert(key, cells[1..].to_vec()).is_none(), "{line}");
    }
    rows
}

/// What the docs call a key's value, by its declared kind.
fn kind_word(kind: Kind) -> String {
    match kind {
        Kind::Quantity => "quantity".into(),
        Kind::Point => "point `[x, y, z]`".into(),
        Kind::Quantities(None) => "array of quantities".into(),
        Kind::Quantities(Some(n)) => format!("array of {n} quantities"),
        Kind::Rows { width, .. } => format!("rows of {width} quantities"),
        Kind::Str => "string".into(),
        Kind::Bool => "boolean".into(),
        Kind::Rotation => "rotation table".into(),
        Kind::ArrayTable | Kind::MirrorTable | Kind::ParamsTable => "table".into(),
    }
}

/// What the docs call a dimension.
fn dimension_word(dim: Dim) -> &'static str {
    [
        (Dim::DIMENSIONLESS, "—"),
        (Dim::LENGTH, "length"),
        (Dim::AREA, "area"),
        (Dim::MASS, "mass"),
        (Dim::DENSITY, "mass/volume"),
        (Dim::AREAL_DENSITY, "mass/area"),
        (Dim::LINEAR_DENSITY, "mass/length"),
        (Dim::INERTIA, "mass·length²"),
    ]
    .iter()
    .find(|(d, _)| *d == dim)
    .map(|(_, w)| *w)
    .unwrap_or_else(|| panic!("the test has no word for {dim:?}"))
}

/// The row the registry gives a key.
fn row_of(key: &Key) -> Vec<String> {
    let tol = if key.takes_tolerance() { "yes" } else { "no" };
    vec![
        kind_word(key.kind),
        dimension_word(key.dim).to_string(),
        tol.to_string(),
        key.doc.to_string(),
    ]
}

#[test]
fn every_declared_part_key_is_documented_with_its_kind_dimension_tolerance_and_line() {
    let doc = documented();
    let mut wrong = Vec::new();
    for key in part_keys() {
        let want = row_of(key);
        match doc.get(key.name) {
            Some(row) if *row == want => {}
            Some(row) => wrong.push(format!("`{}`: {row:?}, declared {want:?}", key.name)),
            None => wrong.push(format!(
                "`{}` missing: | `{}` | {} |",
                key.name,
                key.name,
                want.join(" | ")
            )),
        }
    }
    assert!(
        wrong.is_empty(),
        "docs/part-file.md's part keys:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn every_key_the_table_of_part_keys_lists_is_declared() {
    let declared: Vec<&str> = part_keys().map(|k| k.name).collect();
    for key in documented().keys() {
        assert!(
            declared.contains(&key.as_str()),
            "docs/part-file.md lists `{key}`, which no declaration has"
        );
    }
}

#[test]
fn the_table_of_part_keys_lists_them_in_the_registrys_order() {
    let doc = std::fs::read_to_string("docs/part-file.md").unwrap();
    let mut at = 0;
    for key in part_keys() {
        let row = format!("\n| `{}` | ", key.name);
        let found = doc[at..]
            .find(&row)
            .unwrap_or_else(|| panic!("`{}` after the key before it", key.name));
        at += found + row.len();
    }
}

/// The slot a "±" on `key` moves on a part of `shape`, and its factor, as
/// the model looks it up: the shape's own declaration, else a common one.
fn slot(shape: Shape, key: &str, row: usize, component: usize) -> Option<(Slot, f64)> {
    let all: Vec<Key> = part_keys().copied().collect();
    let declared = shape
        .own_keys()
        .iter()
        .chain(&all)
        .find(|k| k.name == key)?;
    shape.info().slot(declared, row, component, &all)
}

#[test]
fn a_diameter_moves_half_a_cylinders_radius_and_nothing_on_a_rod() {
    assert_eq!(
        slot(Shape::Cylinder, "diameter", 0, 0),
        Some((Slot::Radius, 0.5))
    );
    assert_eq!(
        slot(Shape::Cylinder, "inner_diameter", 0, 0),
        Some((Slot::InnerRadius, 0.5))
    );
    // A rod's diameter is its real size, never composed.
    assert_eq!(slot(Shape::Rod, "diameter", 0, 0), None);
}

#[test]
fn a_size_moves_a_box_but_no_number_of_a_prism_that_does_not_size_by_it() {
    assert_eq!(slot(Shape::Box, "size", 0, 1), Some((Slot::Size(1), 1.0)));
    assert_eq!(slot(Shape::Prism, "size", 0, 1), None);
    assert_eq!(slot(Shape::Prism, "polygon", 0, 1), None);
}

#[test]
fn an_ellipsoids_radii_move_its_own_slots_component_by_component() {
    assert_eq!(
        slot(Shape::Ellipsoid, "radii", 0, 2),
        Some((Slot::Own(0, 2), 1.0))
    );
}

#[test]
fn every_key_declared_to_take_a_tolerance_moves_a_number_of_some_shape_that_takes_it() {
    for key in part_keys() {
        let moves = SHAPES
            .iter()
            .filter(|s| s.keys.contains(&key.name))
            .any(|s| slot(s.shape, key.name, 0, 0).is_some());
        assert_eq!(
            moves,
            key.fill != Fill::No,
            "`{}`: declared {:?}",
            key.name,
            key.fill
        );
    }
}
