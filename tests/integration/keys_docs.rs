//! docs/part-file.md's table of part keys says what the key registry
//! declares (`massprop::model::schema::part_keys`: `keys::part_keys!` and
//! each shape's `OWN_KEYS`): every key with its value's kind, its
//! dimension, whether it takes "±", and its line; no key the registry
//! lacks. (The keys-by-shape table is checked in `docs`.)

use massprop::model::schema::part_keys;
use massprop::shapes::{Key, Kind};
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
