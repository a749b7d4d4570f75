//! The rewording of the toml crate's and serde's errors into massprop's
//! diagnostics, for the classes of error the reader does not word itself
//! yet (syntax errors it does: `fast::errors`): serde's words for TOML's
//! ("map" → table, "sequence" → array), unknown keys with "did you
//! mean", the key a type error is about (its value, or an element inside
//! it) and what that key holds in our words (`expected`: "an array of 3
//! numbers or strings with units"), the accepted forms of a `rotation`,
//! too-deep keys given a place. (An array
//! where a table belongs never reaches serde's struct code: see
//! `raw::table_only`.) It depends on the wording of those crates'
//! messages: every wording it relies on is pinned by a test below, so an
//! upgrade that changes one fails here, not in a user's terminal.
//!
//! NOTE: cohesive: one rewording of one crate's errors; more than half the
//! file is the tests that pin each upstream wording beside the code that
//! relies on it.

use super::fast::errors::{ROTATION_FORMS, comment_start, key_before, quoted_value};
use crate::diag::{Diagnostic, Source, shorten};
use crate::shapes::Shape;
use crate::units;
use std::ops::Range;

/// Turn a toml error into a diagnostic that names the key: unknown keys get
/// a "did you mean" drawn from the key list in serde's own message, and
/// type errors name the key that holds the offending value.
pub(super) fn toml_error(source: &Source, e: &toml::de::Error) -> Diagnostic {
    if e.span().is_none() && e.message().contains("recursion limit") {
        // toml gives no place for too deep a dotted key or table header:
        // point at the line whose key has the most dots.
        let (start, len) = deepest_key(&source.text);
        return source
            .error(start..start + len, "this key nests tables too deeply")
            .help("a part file needs a few levels at most; is the key or header mistyped?");
    }
    let span = e.span().unwrap_or(0..0);
    // toml reports some spans inside a multi-byte character (after a BOM,
    // a combining mark or an em dash in a comment): snap to boundaries.
    let floor = |i| crate::diag::floor_char_boundary(&source.text, i);
    let span = floor(span.start)..floor(span.end).max(floor(span.start));
    // serde's words for TOML's: a "map" is a table, a "sequence" an array,
    // both as the value found ("invalid type: map") and as the one
    // expected ("expected a map", from `[materials]`'s map).
    let msg = e
        .message()
        .trim_end()
        .replace("expected f64", "expected a number")
        .replace("invalid type: map", "invalid type: table")
        .replace("expected a map", "expected a table")
        .replace("invalid type: sequence", "invalid type: array")
        .replace("a sequence", "an array")
        // The toml crate's limit of nesting (80 levels), in its words.
        .replace(
            "cannot recurse further; max recursion depth met",
            "arrays and inline tables nested more than 80 deep, the most the TOML reader takes",
        );
    // `[[analysis]]` for `[analysis]`: serde's words ("wrong type", "invalid
    // length", or an unknown key inside it) would name neither the table
    // nor the fix. Such a header is an error wherever serde stumbled.
    if let Some(d) = super::fast::errors::array_of_tables(source) {
        return d;
    }
    // A date-time reaches a table type as a table with toml's private key.
    if msg.starts_with("unknown field `$__toml_private") {
        let key = key_at(&source.text, span.start);
        let d = source.error(
            span,
            match &key {
                Some((k, depth)) => {
                    format!("`{k}` {}: date-time, expected a table", wrong_type(*depth))
                }
                None => "a date-time where a table belongs".to_string(),
            },
        );
        return match key {
            Some((k, 0)) if k == "rotation" => d.help(ROTATION_FORMS),
            _ => d,
        };
    }
    if let Some(rest) = msg.strip_prefix("unknown field ") {
        // serde: "unknown field `k`, expected one of `a`, `b`" or "expected `a`".
        let quoted: Vec<&str> = rest.split('`').skip(1).step_by(2).collect();
        if let Some((key, valid)) = quoted.split_first() {
            // In a part whose shape is known, the keys of that shape (its
            // description in `SHAPES`), not every key any part may have.
            // Elsewhere in a part, every part key (a shape's own keys are
            // no fields of serde's).
            let shape_keys: Vec<&str>;
            let valid: &[&str] = match shape_of_part_at(&source.text, span.start) {
                Some(shape) if valid.contains(&"shape") => {
                    shape_keys = ["name", "shape"]
                        .into_iter()
                        .chain(shape.info().keys.iter().copied())
                        .collect();
                    &shape_keys
                }
                _ if valid.contains(&"shape") => {
                    let more = super::keys::names().filter(|k| !valid.contains(k));
                    shape_keys = valid
                        .iter()
                        .copied()
                        .chain(more.map(|k| k as &str))
                        .collect();
                    &shape_keys
                }
                _ => valid,
            };
            let suggestion = units::suggest(key, valid.iter().copied());
            let d = source.error(span, format!("unknown key `{}`", shorten(key)));
            return match suggestion {
                Some(s) => d.label(format!("did you mean `{s}`?")),
                None => d.help(format!(
                    "valid keys here: {}",
                    valid
                        .iter()
                        .map(|k| format!("`{k}`"))
                        .collect::<Vec<_>>()
                        .join(", ")
                )),
            };
        }
    }
    if let Some(rest) = msg.strip_prefix("missing field ") {
        let key = rest.trim_matches('`');
        let d = source.error(span, format!("missing key `{key}`"));
        return if key == "shape" {
            d.help(format!(
                "every part needs `shape`, one of {}",
                Shape::quoted_names()
            ))
        } else {
            d
        };
    }
    if msg.starts_with("duplicate key") {
        let key = source.text.get(span.clone()).unwrap_or("").trim();
        return source.error(span, format!("duplicate key `{}`", shorten(key)));
    }
    let at = span.start;
    // TOML integers are 64-bit: toml says "integer `1e20-ish` as i128".
    let wide_integer = msg.contains(" as i128");
    let msg = msg.replacen(" as i128", "", 1);
    // A date or time reaches serde as a table.
    let date = source.text[at..].starts_with(|c: char| c.is_ascii_digit());
    let msg = if msg.starts_with("invalid type: table") && date {
        msg.replacen("table", "date-time", 1)
    } else {
        msg
    };
    // ... and to a spanned table of tables (`materials`) as a string, with
    // toml's own word for what it wanted.
    let msg = match msg.strip_suffix(", expected a spanned value") {
        Some(_) if date => "invalid type: date-time, expected a table".to_string(),
        Some(found) => format!("{found}, expected a table"),
        None => msg,
    };
    // The key, and how many arrays deep inside its value the error is.
    let (key, depth) = match key_at(&source.text, at) {
        Some((k, depth)) => (Some(k), depth),
        None => (key_before(&source.text, at), 0),
    };
    let d = match (key.as_deref(), msg.strip_prefix("invalid type: ")) {
        (Some(k), Some(rest)) => {
            // The type found as toml says it; what was expected in our
            // words where serde's are only "an array".
            let rest = match (
                rest.split_once(", expected "),
                expected(k, depth, &source.text, at),
            ) {
                (Some((found, _)), Some(ours)) => format!("{found}, expected {ours}"),
                _ => rest.to_string(),
            };
            source.error(span, format!("`{k}` {}: {rest}", wrong_type(depth)))
        }
        (Some(k), None) => source.error(span, format!("`{k}`: {msg}")),
        (None, _) => source.error(span, msg.clone()),
    };
    if key.as_deref() == Some("part") {
        return d.help("write each part as a `[[part]]` table (two brackets)");
    }
    if key.as_deref() == Some("rotation") && depth == 0 {
        return d.help(ROTATION_FORMS);
    }
    if wide_integer {
        return d.help("a TOML integer is 64-bit (up to 9223372036854775807): write a larger number as a float, e.g. `1e20`");
    }
    if msg.contains("string values must be quoted")
        && let (Some(k), Some(v)) = (key.as_deref(), quoted_value(&source.text, at))
    {
        return d.help(format!(
            "a number with a unit is written as a string: `{k} = {v}`"
        ));
    }
    d
}

/// "has the wrong type", said of a key's value (`depth` 0) or of an element
/// inside it.
fn wrong_type(depth: usize) -> &'static str {
    if depth == 0 {
        "has the wrong type"
    } else {
        "has an element of the wrong type"
    }
}

/// What the value of `key` is, in massprop's words, `depth` arrays inside
/// it, where serde's would be only "an array" or "a number": the keys
/// whose values are arrays. `text` and `at` find the part's shape (the
/// length of `size`).
fn expected(key: &str, depth: usize, text: &str, at: usize) -> Option<String> {
    const QUANTITIES: &str = "numbers or strings with units";
    // A part's key: from its declaration (`keys`), a `size` as long as
    // its part's shape says.
    if let Some(k) = super::keys::declared(key) {
        let n = shape_of_part_at(text, at)
            .map(|s| s.info().size_items)
            .filter(|n| *n > 0 && key == "size");
        return super::keys::expected(k, depth, n);
    }
    Some(match (key, depth) {
        ("part", 0) => "an array of tables, each a `[[part]]`".into(),
        ("materials", 0) => {
            "a table of materials such as { foam = { density = \"30 kg/m^3\" } }".into()
        }
        ("about" | "omega" | "alpha", 0) => format!("an array of 3 {QUANTITIES}"),
        ("axis", 0) => "an array of 3 numbers, such as [0, 0, 1]".into(),
        ("quaternion", 0) => "an array of 4 numbers [w, x, y, z]".into(),
        ("matrix", 0) => "3 rows, each an array of 3 numbers".into(),
        ("matrix", 1) => "a row, an array of 3 numbers".into(),
        _ => return None,
    })
}

/// The innermost key whose value contains byte `offset`, and how many
/// arrays deep inside that value `offset` is (0: the value itself, 1: an
/// element of it), from a spanned parse of the whole file. Only used on
/// the error path.
fn key_at(text: &str, offset: usize) -> Option<(String, usize)> {
    use toml::de::{DeTable, DeValue};
    type Best = Option<(String, usize, usize)>;
    fn consider(best: &mut Best, k: &str, depth: usize, span: Range<usize>, offset: usize) {
        if span.contains(&offset) && best.as_ref().is_none_or(|b| span.len() <= b.2) {
            *best = Some((k.to_string(), depth, span.len()));
        }
    }
    fn visit(v: &DeValue<'_>, key: Option<(&str, usize)>, offset: usize, best: &mut Best) {
        match v {
            DeValue::Table(t) => {
                for (k, v) in t.iter() {
                    consider(best, k.get_ref(), 0, k.span(), offset);
                    consider(best, k.get_ref(), 0, v.span(), offset);
                    visit(v.get_ref(), Some((k.get_ref(), 0)), offset, best);
                }
            }
            DeValue::Array(a) => {
                let inner = key.map(|(k, depth)| (k, depth + 1));
                for v in a.iter() {
                    if let Some((k, depth)) = inner {
                        consider(best, k, depth, v.span(), offset);
                    }
                    visit(v.get_ref(), inner, offset, best);
                }
            }
            _ => {}
        }
    }
    let root = DeTable::parse(text).ok()?;
    let mut best = None;
    visit(&DeValue::Table(root.into_inner()), None, offset, &mut best);
    best.map(|(k, depth, _)| (k, depth))
}

/// The shape of the `[[part]]` that has a key at `offset`, when it names a
/// known one. Only used on the error path.
fn shape_of_part_at(text: &str, offset: usize) -> Option<Shape> {
    use toml::de::{DeTable, DeValue};
    let root = DeTable::parse(text).ok()?;
    let root = root.into_inner();
    let parts = root.iter().find(|(k, _)| k.get_ref() == "part")?.1;
    let DeValue::Array(parts) = parts.get_ref() else {
        return None;
    };
    parts.iter().find_map(|p| {
        let DeValue::Table(t) = p.get_ref() else {
            return None;
        };
        let here = t
            .iter()
            .any(|(k, v)| k.span().contains(&offset) || v.span().contains(&offset));
        let shape = t.iter().find(|(k, _)| k.get_ref() == "shape")?.1;
        match (here, shape.get_ref()) {
            (true, DeValue::String(s)) => Shape::from_name(s),
            _ => None,
        }
    })
}

/// The line whose key (before `=`, or a `[header]`) has the most dots:
/// its offset and the length of the key.
fn deepest_key(text: &str) -> (usize, usize) {
    let mut best = (0, 0, 0);
    let mut at = 0;
    for line in text.split_inclusive('\n') {
        let code = &line[..comment_start(line).unwrap_or(line.len())];
        let key = code.split('=').next().unwrap_or("").trim_end();
        let dots = key.matches('.').count();
        if dots > best.0 {
            best = (dots, at, key.len());
        }
        at += line.len();
    }
    (best.1, best.2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::fast::errors::array_of_tables_header;

    #[test]
    fn the_key_before_an_error_is_found_on_its_line_but_not_in_a_comment() {
        let text = "x = 1\nlength = 3 mm\n";
        assert_eq!(
            key_before(text, text.find("3 mm").unwrap()).as_deref(),
            Some("length")
        );
        // A multi-byte character before the key (a BOM left in, say).
        let text = "\u{2014}mass = 1 kg";
        assert_eq!(
            key_before(text, text.find('1').unwrap()).as_deref(),
            Some("mass")
        );
        let text = "shape = \"box\" # a = b \u{7f}";
        assert_eq!(key_before(text, text.find('\u{7f}').unwrap()), None);
        // `#` inside a string is not a comment.
        let text = "name = \"#1\"\nmass = 1 kg";
        assert_eq!(
            key_before(text, text.find("1 kg").unwrap()).as_deref(),
            Some("mass")
        );
    }

    /// Suggestions for a misspelt key come from the part's own shape: a
    /// box's `raduis` is not "did you mean `radius`" (a key boxes refuse).
    #[test]
    fn a_misspelt_key_is_matched_against_the_keys_of_the_parts_shape() {
        let text = "[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\nraduis = 1\n";
        let d = crate::model::Model::parse(&Source::new("t.toml", text))
            .unwrap_err()
            .to_string();
        assert!(d.contains("unknown key `raduis`"), "{d}");
        assert!(!d.contains("did you mean `radius`"), "{d}");
        assert!(
            d.contains("valid keys here: `name`, `shape`, `density`"),
            "{d}"
        );
        let text = "[[part]]\nshape = \"sphere\"\nmass = 1\ncenter = [0, 0, 0]\nraduis = 1\n";
        let d = crate::model::Model::parse(&Source::new("t.toml", text))
            .unwrap_err()
            .to_string();
        assert!(d.contains("did you mean `radius`?"), "{d}");
    }

    #[test]
    fn comments_start_at_the_first_hash_outside_strings() {
        assert_eq!(comment_start("a = 1 # x"), Some(6));
        assert_eq!(comment_start("a = \"#\" # x"), Some(8));
        assert_eq!(comment_start("a = '#\\' # x"), Some(9));
        assert_eq!(comment_start("a = \"\\\"#\" # x"), Some(10));
        assert_eq!(comment_start("a = 1"), None);
    }

    #[test]
    fn a_bare_quantity_is_suggested_quoted() {
        assert_eq!(
            quoted_value("mass = 1 kg # m", 7).as_deref(),
            Some("\"1 kg\"")
        );
        assert_eq!(quoted_value("mass = [1 kg]", 7), None);
        assert_eq!(quoted_value("mass = kg", 7), None);
    }

    // The upstream wordings this module matches on, each with the wording
    // we turn it into: an upgrade of toml or serde that changes one fails
    // here.

    /// toml's and serde's message for `text` read as a part file, and our
    /// diagnostic for it as printed.
    fn reworded(text: &str) -> (String, String) {
        let e = toml::from_str::<crate::model::raw::RawFile>(text)
            .expect_err("the text is not a valid part file");
        let ours = toml_error(&Source::new("t.toml", text), &e).to_string();
        (e.message().to_string(), ours)
    }

    #[test]
    fn the_readers_syntax_errors_read_as_serdes_reworded_did() {
        // NOTE: while both paths exist: the reader's own words for a
        // syntax error are those this module made of serde's.
        for text in [
            "[[part]]\nshape = \"box\"\nsize = [1, 2\n",
            "[part\n",
            "[[part]]\nshape = = 1\n",
            "mass = 1\nb c\n",
            "[[part]]\nrotation = [1,,2]\n",
            "part = {shape = \"box\"\n",
            "[[analysis]]\nx = [\n",
            "# \u{7}\n",
        ] {
            let source = Source::new("t.toml", text);
            let ours = crate::model::fast::errors::syntax(&source).expect("a syntax error");
            assert_eq!(ours.to_string(), reworded(text).1, "{text:?}");
        }
    }

    #[test]
    fn an_array_of_tables_header_is_pointed_at_whole() {
        let text = "[[part]]\nshape = \"point\"\n  [[ analysis ]]\nabout = [0, 0, 0]\n";
        let (header, name) = array_of_tables_header(text).unwrap();
        assert_eq!((&text[header], name), ("[[ analysis ]]", "analysis"));
    }

    #[test]
    fn an_array_where_a_table_belongs_is_called_an_array() {
        // serde's derived struct would read an array as its fields in
        // order ("invalid length 0"); `raw::table_only` refuses it.
        let (upstream, ours) = reworded("units = []\n");
        assert!(
            upstream.starts_with("invalid type: sequence, expected a table"),
            "{upstream}"
        );
        assert!(
            ours.contains("error: `units` has the wrong type: array, expected a table such as"),
            "{ours}"
        );
        let (_, ours) = reworded(&part_with("rotation = []"));
        assert!(
            ours.contains("`rotation` has the wrong type: array"),
            "{ours}"
        );
        assert!(!ours.contains("invalid length"), "{ours}");
    }

    /// `rotation = [1]` was read as a quaternion of one number ("integer
    /// `1`, expected an array"), and `foam = [1]` as a density, accepted.
    #[test]
    fn an_array_is_never_read_as_the_fields_of_a_table() {
        let (_, ours) = reworded(&part_with("rotation = [1]"));
        assert!(
            ours.contains("3:12: error: `rotation` has the wrong type: array, expected a rotation table such as { axis = [0, 0, 1], degrees = 90 }\n"),
            "{ours}"
        );
        assert!(
            ours.contains("help: write `{ quaternion = [w, x, y, z] }`, `{ axis"),
            "{ours}"
        );
        let (_, ours) = reworded("[materials]\nfoam = [1]\n");
        assert!(
            ours.contains("2:8: error: `foam` has the wrong type: array, expected a table such as { density = \"30 kg/m^3\" }\n"),
            "{ours}"
        );
        for text in [
            "units = [\"mm\", \"kg\"]\n",
            "analysis = [[0, 0, 0]]\n",
            "expect = [{ value = 1 }]\n",
            "[expect]\nmass = [1, 0.1]\n",
            "[expect]\ncenter_of_mass = { x = [1] }\n",
            "part = [[\"box\"]]\n",
        ] {
            let (_, ours) = reworded(text);
            assert!(
                ours.contains("wrong type: array, expected a"),
                "{text}: {ours}"
            );
        }
    }

    #[test]
    fn a_date_time_where_a_table_belongs_is_called_a_date_time() {
        // A date reaches a table type as a table with toml's private key.
        let (upstream, ours) = reworded(&part_with("rotation = 1979-05-27"));
        assert!(
            upstream.starts_with("unknown field `$__toml_private_datetime`"),
            "{upstream}"
        );
        assert!(
            ours.contains("error: `rotation` has the wrong type: date-time, expected a table\n"),
            "{ours}"
        );
        // ... and a spanned table of tables as a string.
        let (upstream, ours) = reworded("materials = 1979-05-27\n");
        assert_eq!(
            upstream,
            "invalid type: string \"1979-05-27\", expected a spanned value"
        );
        assert!(
            ours.contains(
                "error: `materials` has the wrong type: date-time, expected a table of materials"
            ),
            "{ours}"
        );
    }

    #[test]
    fn an_element_of_the_wrong_type_is_called_an_element() {
        let (_, ours) = reworded(&part_with("center = [0, true, 0]"));
        assert!(
            ours.contains("3:14: error: `center` has an element of the wrong type: boolean `true`, expected a number, or a string with a unit"),
            "{ours}"
        );
        let (_, ours) = reworded(&part_with("edges = [1, 2, 3]"));
        assert!(
            ours.contains("`edges` has an element of the wrong type: integer `1`, expected an edge vector, an array of 3 numbers or strings with units\n"),
            "{ours}"
        );
        let (_, ours) = reworded(&part_with("rotation = { matrix = [[1, 0, 0], 0, 1] }"));
        assert!(
            ours.contains("`matrix` has an element of the wrong type: integer `0`, expected a row, an array of 3 numbers\n"),
            "{ours}"
        );
    }

    #[test]
    fn the_length_of_size_is_the_shapes() {
        let (_, ours) = reworded("[[part]]\nshape = \"plate\"\nsize = 1\n");
        assert!(
            ours.contains("`size` has the wrong type: integer `1`, expected an array of 2 lengths"),
            "{ours}"
        );
        let (_, ours) = reworded(&part_with("size = 1"));
        assert!(ours.contains("expected an array of 3 lengths"), "{ours}");
    }

    /// A part with `key = value` after its shape.
    fn part_with(line: &str) -> String {
        format!("[[part]]\nshape = \"box\"\n{line}\n")
    }

    #[test]
    fn an_unknown_field_becomes_an_unknown_key_with_a_suggestion() {
        let (upstream, ours) = reworded(&part_with("mas = 1"));
        assert!(
            upstream.starts_with("unknown field `mas`, expected one of `name`, `shape`, `mass`"),
            "{upstream}"
        );
        assert!(
            ours.starts_with("t.toml:3:1: error: unknown key `mas`\n"),
            "{ours}"
        );
        assert!(ours.contains("did you mean `mass`?"), "{ours}");
    }

    #[test]
    fn an_unknown_field_far_from_every_key_lists_the_valid_keys() {
        let (upstream, ours) = reworded(&part_with("xyzzy = 1"));
        assert!(
            upstream.starts_with("unknown field `xyzzy`, expected one of `name`"),
            "{upstream}"
        );
        assert!(ours.contains("error: unknown key `xyzzy`"), "{ours}");
        // The keys of the part's shape, a box (`SHAPES`), not serde's list.
        assert!(
            ours.contains("help: valid keys here: `name`, `shape`, `density`, `size`"),
            "{ours}"
        );
    }

    #[test]
    fn an_unknown_field_where_one_key_is_valid_suggests_that_key() {
        // serde words a single valid key as "expected `k`", not "one of".
        let (upstream, ours) = reworded("[materials]\nfoam = { densty = 1 }\n");
        assert_eq!(upstream, "unknown field `densty`, expected `density`");
        assert!(ours.contains("error: unknown key `densty`"), "{ours}");
        assert!(ours.contains("did you mean `density`?"), "{ours}");
    }

    #[test]
    fn a_missing_field_becomes_a_missing_key() {
        let (upstream, ours) = reworded("[materials]\nfoam = {}\n");
        assert_eq!(upstream, "missing field `density`");
        assert!(
            ours.starts_with("t.toml:2:8: error: missing key `density`\n"),
            "{ours}"
        );
    }

    #[test]
    fn a_duplicate_key_is_named() {
        let (upstream, ours) = reworded(&part_with("mass = 1\nmass = 2"));
        assert!(upstream.starts_with("duplicate key"), "{upstream}");
        assert!(
            ours.starts_with("t.toml:4:1: error: duplicate key `mass`\n"),
            "{ours}"
        );
    }

    #[test]
    fn a_map_of_the_wrong_type_is_called_a_table_and_its_key_named() {
        let (upstream, ours) = reworded(&part_with("mass = { a = 1 }"));
        assert!(
            upstream.starts_with("invalid type: map, expected"),
            "{upstream}"
        );
        assert!(
            ours.contains("error: `mass` has the wrong type: table, expected a number"),
            "{ours}"
        );
    }

    #[test]
    fn an_expected_sequence_is_called_an_array() {
        let (upstream, ours) = reworded(&part_with("center = 1"));
        assert!(upstream.ends_with("expected a sequence"), "{upstream}");
        assert!(
            ours.contains("error: `center` has the wrong type: integer `1`, expected an array of 3 numbers or strings with units, such as [0, 0, \"5 mm\"]\n"),
            "{ours}"
        );
    }

    #[test]
    fn a_sequence_of_the_wrong_type_is_called_an_array() {
        let (upstream, ours) = reworded("name = [1]\n");
        assert!(
            upstream.starts_with("invalid type: sequence, expected"),
            "{upstream}"
        );
        assert!(
            ours.contains("error: `name` has the wrong type: array, expected a string\n"),
            "{ours}"
        );
    }

    #[test]
    fn an_expected_map_is_called_a_table() {
        let (upstream, ours) = reworded("materials = 1\n");
        assert!(upstream.ends_with("expected a map"), "{upstream}");
        assert!(
            ours.contains("error: `materials` has the wrong type: integer `1`, expected a table of materials such as"),
            "{ours}"
        );
        assert!(!ours.contains("map"), "{ours}");
    }

    #[test]
    fn an_expected_f64_is_called_a_number() {
        let (upstream, ours) = reworded(&part_with("rotation = { quaternion = [\"a\", 0, 0, 0] }"));
        assert!(upstream.ends_with("expected f64"), "{upstream}");
        assert!(
            ours.contains(
                "error: `quaternion` has an element of the wrong type: string \"a\", expected a number\n"
            ),
            "{ours}"
        );
    }

    #[test]
    fn an_integer_beyond_64_bits_loses_as_i128_and_gets_a_help() {
        let (upstream, ours) = reworded(&part_with("mass = 99999999999999999999"));
        assert!(
            upstream.starts_with("invalid type: integer `99999999999999999999` as i128,"),
            "{upstream}"
        );
        assert!(
            ours.contains("error: `mass` has the wrong type: integer `99999999999999999999`, expected a number"),
            "{ours}"
        );
        assert!(!ours.contains("i128"), "{ours}");
        assert!(ours.contains("help: a TOML integer is 64-bit"), "{ours}");
    }

    #[test]
    fn a_date_of_the_wrong_type_is_called_a_date_time() {
        // A date reaches serde as a map.
        let (upstream, ours) = reworded(&part_with("mass = 1979-05-27"));
        assert!(
            upstream.starts_with("invalid type: map, expected"),
            "{upstream}"
        );
        assert!(
            ours.contains("error: `mass` has the wrong type: date-time, expected a number"),
            "{ours}"
        );
    }

    #[test]
    fn a_too_deep_key_without_a_place_is_given_the_line_of_the_deepest_key() {
        let text = format!("name = \"x\"\n{} = 1\n", vec!["a"; 100].join("."));
        let e = toml::from_str::<crate::model::raw::RawFile>(&text).unwrap_err();
        // toml gives no span for this one: the reason we find the line.
        assert_eq!(e.span(), None);
        let (upstream, ours) = reworded(&text);
        assert!(upstream.contains("recursion limit"), "{upstream}");
        assert!(
            ours.starts_with("t.toml:2:1: error: this key nests tables too deeply\n"),
            "{ours}"
        );
    }

    #[test]
    fn an_unquoted_quantity_gets_the_quoted_form_as_help() {
        let (upstream, ours) = reworded(&part_with("mass = 1 kg # heavy"));
        assert!(
            upstream.starts_with("string values must be quoted"),
            "{upstream}"
        );
        assert!(
            ours.contains("help: a number with a unit is written as a string: `mass = \"1 kg\"`"),
            "{ours}"
        );
    }

    #[test]
    fn a_part_that_is_not_an_array_of_tables_gets_the_double_brackets_as_help() {
        let (upstream, ours) = reworded("part = 1\n");
        assert!(upstream.ends_with("expected a sequence"), "{upstream}");
        assert!(
            ours.contains("help: write each part as a `[[part]]` table (two brackets)"),
            "{ours}"
        );
    }

    /// Every key given every kind of wrong value: the message is ours,
    /// with none of serde's or toml's internal words.
    #[test]
    fn no_wrong_value_anywhere_gets_serdes_words() {
        const WRONG: &[&str] = &[
            "1",
            "1.5",
            "\"x\"",
            "true",
            "1979-05-27",
            "[]",
            "[1]",
            "[[1]]",
            "[true]",
            "[{}]",
            "[[[1]]]",
            "{}",
            "{ a = 1 }",
            "{ value = 1 }",
            "[1979-05-27]",
        ];
        // Every field of `RawPart`.
        const PART_KEYS: &[&str] = &[
            "name",
            "shape",
            "mass",
            "density",
            "areal_density",
            "linear_density",
            "size",
            "length",
            "center",
            "rotation",
            "corner",
            "edges",
            "from",
            "to",
            "thickness",
            "diameter",
            "radius",
            "inner_radius",
            "include",
            "origin",
            "material",
            "area",
            "vertices",
            "inertia",
            "products",
            "remove",
        ];
        let part = "[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n";
        let mut files = Vec::new();
        for v in WRONG {
            for key in PART_KEYS {
                let lines: Vec<String> = part
                    .lines()
                    .filter(|l| !l.starts_with(&format!("{key} ")))
                    .map(str::to_string)
                    .collect();
                files.push(format!("{}\n{key} = {v}\n", lines.join("\n")));
            }
            for key in ["quaternion", "axis", "degrees", "matrix", "intrinsic"] {
                files.push(format!("{part}rotation = {{ {key} = {v} }}\n"));
            }
            for top in ["name", "units", "analysis", "expect", "materials"] {
                files.push(format!("{top} = {v}\n{part}"));
            }
            files.push(format!("part = {v}\n"));
            files.push(format!("[units]\nlength = {v}\n{part}"));
            files.push(format!("[analysis]\nabout = {v}\n{part}"));
            files.push(format!("[materials]\nfoam = {v}\n{part}"));
            files.push(format!("[materials.foam]\ndensity = {v}\n{part}"));
            for entry in ["mass", "center_of_mass", "inertia_com"] {
                files.push(format!("{part}[expect]\n{entry} = {v}\n"));
                for sub in ["value", "tol", "max", "x", "xy"] {
                    files.push(format!("{part}[expect]\n{entry} = {{ {sub} = {v} }}\n"));
                }
            }
        }
        let serde_words = [
            "sequence",
            " map",
            "invalid length",
            "struct",
            "enum",
            "variant",
            "tuple",
            "f64",
            "i64",
            "u64",
            "i128",
            "unit value",
            "newtype",
            "identifier",
            "spanned",
            "$__",
        ];
        for text in &files {
            let Err(d) = crate::model::Model::parse(&Source::new("t.toml", text.as_str())) else {
                continue;
            };
            let d = d.to_string();
            let first = d.lines().next().unwrap_or_default();
            for w in serde_words {
                assert!(!first.contains(w), "{text}\n{d}");
            }
        }
    }

    #[test]
    fn model_parse_words_toml_errors_through_this_module() {
        let text = part_with("mas = 1");
        let Err(d) = crate::model::Model::parse(&Source::new("t.toml", text.as_str())) else {
            panic!("an unknown key is an error");
        };
        assert_eq!(d.message(), "unknown key `mas`");
        assert_eq!(d.place().unwrap().to_string(), "t.toml:3:1");
    }
}
