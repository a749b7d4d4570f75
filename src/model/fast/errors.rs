//! The reader's own words for a file it cannot read, class by class:
//! syntax and decoding errors, in the parser's (`toml_parser`'s
//! `ParseError`: its description, what it expected, its span), given the
//! key on their line and, where one fits, a help; and every refusal the
//! reader met itself (`failure::Failure`): TOML's rules, unknown keys with
//! a "did you mean", values of the wrong type with what the key holds in
//! our words, missing keys.

use super::failure::{Failure, Found, Valid, What};
use crate::diag::{Diagnostic, Source, shorten};
use crate::shapes::Shape;
use crate::units;
use std::ops::Range;
use toml_parser::{Expected, ParseError};

/// A syntax or decoding error the parser reported, in massprop's words
/// (`fast::explain` words a `[[analysis]]` header before any).
pub(in crate::model) fn parse_error(source: &Source, error: &ParseError) -> Diagnostic {
    let text = &source.text;
    let span = error.unexpected().map_or(0..0, |s| s.start()..s.end());
    // Some spans fall inside a multi-byte character (after a BOM, a
    // combining mark): snap to boundaries.
    let floor = |i| crate::diag::floor_char_boundary(text, i);
    let span = floor(span.start)..floor(span.end).max(floor(span.start));
    let msg = describe(error).trim_end().replace(
        "cannot recurse further; max recursion depth met",
        "arrays and inline tables nested more than 80 deep, the most the TOML reader takes",
    );
    let at = span.start;
    let key = key_before(text, at);
    let d = match &key {
        Some(k) => source.error(span, format!("`{k}`: {msg}")),
        None => source.error(span, msg.clone()),
    };
    match key.as_deref() {
        Some("part") => d.help("write each part as a `[[part]]` table (two brackets)"),
        Some("rotation") => d.help(ROTATION_FORMS),
        Some(k) if msg.contains("string values must be quoted") => match quoted_value(text, at) {
            Some(v) => d.help(format!(
                "a number with a unit is written as a string: `{k} = {v}`"
            )),
            None => d,
        },
        _ => d,
    }
}

/// A refusal the reader met (`failure`), in massprop's words.
pub(in crate::model) fn word(source: &Source, f: Failure) -> Diagnostic {
    let text = &source.text;
    let floor = |i| crate::diag::floor_char_boundary(text, i);
    let span = floor(f.span.start)..floor(f.span.end).max(floor(f.span.start));
    match f.what {
        What::Toml(msg) => {
            // A number TOML refuses: said of its key.
            if let ("floating-point number overflowed", Some(k)) =
                (&*msg, key_before(text, span.start))
            {
                return source.error(span, format!("`{k}`: {msg}"));
            }
            // TOML names the key twice given: say which.
            if msg == "duplicate key" {
                let key = text.get(span.clone()).unwrap_or("").trim();
                return source.error(span, format!("duplicate key `{}`", shorten(key)));
            }
            source.error(span, msg.to_string())
        }
        What::PartTable => source
            .error(
                span,
                "`[part]` is one table, but parts are an array of tables",
            )
            .help("write each part as a `[[part]]` table (two brackets)"),
        What::Unknown { key, valid } => {
            let part_keys: Vec<&str>;
            let valid: &[&str] = match valid {
                Valid::Keys(keys) => keys,
                // In a part whose shape is known, the keys of that shape
                // (its description in `SHAPES`); else every part key.
                Valid::Part(Some(shape)) => {
                    part_keys = ["name", "shape"]
                        .into_iter()
                        .chain(shape.info().keys.iter().copied())
                        .collect();
                    &part_keys
                }
                Valid::Part(None) => {
                    part_keys = super::super::keys::names().collect();
                    &part_keys
                }
            };
            let d = source.error(span, format!("unknown key `{}`", shorten(&key)));
            match units::suggest(&key, valid.iter().copied()) {
                Some(s) => d.label(format!("did you mean `{s}`?")),
                None => d.help(format!(
                    "valid keys here: {}",
                    valid
                        .iter()
                        .map(|k| format!("`{k}`"))
                        .collect::<Vec<_>>()
                        .join(", ")
                )),
            }
        }
        What::Type {
            key,
            depth,
            found,
            expecting,
            shape,
        } => {
            let found_words = found_words(&found, text.get(span.clone()).unwrap_or(""));
            let Some(k) = key else {
                return source.error(
                    span,
                    format!("invalid type: {found_words}, expected {expecting}"),
                );
            };
            let ours = expected(&k, depth, shape);
            let d = source.error(
                span,
                format!(
                    "`{k}` {}: {found_words}, expected {}",
                    wrong_type(depth),
                    ours.as_deref().unwrap_or(expecting)
                ),
            );
            if k == "part" {
                return d.help("write each part as a `[[part]]` table (two brackets)");
            }
            if k == "rotation" && depth == 0 {
                return d.help(ROTATION_FORMS);
            }
            if matches!(found, Found::Wide) {
                return d.help("a TOML integer is 64-bit (up to 9223372036854775807): write a larger number as a float, e.g. `1e20`");
            }
            d
        }
        What::Missing(key) => {
            let d = source.error(span, format!("missing key `{key}`"));
            if key == "shape" {
                d.help(format!(
                    "every part needs `shape`, one of {}",
                    Shape::quoted_names()
                ))
            } else {
                d
            }
        }
        What::TooDeep => source
            .error(span, "this key nests tables too deeply")
            .help("a part file needs a few levels at most; is the key or header mistyped?"),
        What::Other(msg) => source.error(span, msg),
    }
}

/// What a value of the wrong type is, as written (`literal`).
fn found_words(found: &Found, literal: &str) -> String {
    match found {
        Found::Str(s) => format!("string {s:?}"),
        Found::Bool(b) => format!("boolean `{b}`"),
        Found::Number if super::values::is_integer(literal) => format!("integer `{literal}`"),
        Found::Number => format!("floating point `{literal}`"),
        Found::Wide => format!("integer `{literal}`"),
        Found::DateTime => "date-time".into(),
        Found::Array => "array".into(),
        Found::Table => "table".into(),
    }
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
/// it, where the reader's own would be only "an array" or "a number": the
/// keys whose values are arrays. `shape` the part's, for the length of
/// `size`.
fn expected(key: &str, depth: usize, shape: Option<Shape>) -> Option<String> {
    const QUANTITIES: &str = "numbers or strings with units";
    // A part's key: from its declaration (`keys`), a `size` as long as
    // its part's shape says.
    if let Some(k) = super::super::keys::declared(key) {
        let n = shape
            .map(|s| s.info().size_items)
            .filter(|n| *n > 0 && key == "size");
        return super::super::keys::expected(k, depth, n);
    }
    Some(match (key, depth) {
        ("part", 0) => "an array of tables, each a `[[part]]`".into(),
        ("materials", 0) => {
            "a table of materials such as { foam = { density = \"30 kg/m^3\" } }".into()
        }
        ("about" | "omega" | "alpha" | "velocity", 0) => format!("an array of 3 {QUANTITIES}"),
        ("axis", 0) => "an array of 3 numbers, such as [0, 0, 1]".into(),
        ("quaternion", 0) => "an array of 4 numbers [w, x, y, z]".into(),
        ("matrix", 0) => "3 rows, each an array of 3 numbers".into(),
        ("matrix", 1) => "a row, an array of 3 numbers".into(),
        _ => return None,
    })
}

/// A parse error as one line: its description, then what was expected.
fn describe(error: &ParseError) -> String {
    let mut message = error.description().to_string();
    if let Some(expected) = error.expected() {
        message.push_str(", expected ");
        if expected.is_empty() {
            message.push_str("nothing");
        }
        for (i, e) in expected.iter().enumerate() {
            if i != 0 {
                message.push_str(", ");
            }
            match e {
                Expected::Literal(s) => message.push_str(&literal(s)),
                Expected::Description(s) => message.push_str(s),
                _ => message.push_str("etc"),
            }
        }
    }
    message
}

/// A literal the parser expected, quoted.
fn literal(s: &str) -> String {
    match s {
        "\n" => "newline".to_owned(),
        "`" => "'`'".to_owned(),
        s if s.chars().all(|c| c.is_ascii_control()) => format!("`{}`", s.escape_debug()),
        s => format!("`{s}`"),
    }
}

/// `[[analysis]]` (or `[[units]]`, …) for a table the file has one of,
/// pointed at whole, with the fix.
pub(in crate::model) fn array_of_tables(source: &Source) -> Option<Diagnostic> {
    let (header, name) = array_of_tables_header(&source.text)?;
    Some(
        source
            .error(
                header,
                format!("`{name}` must be a table, found an array of tables"),
            )
            .help(format!("write `[{name}]`, with one pair of brackets")),
    )
}

/// The accepted forms of `rotation`, for every message about its type.
pub(in crate::model) const ROTATION_FORMS: &str = "write `{ quaternion = [w, x, y, z] }`, `{ axis = [x, y, z], degrees = θ }`, `{ matrix = [[..], [..], [..]] }`, or `{ intrinsic = \"zyx\", degrees = [a, b, c] }` (or `extrinsic`)";

/// The first `[[analysis]]`, `[[units]]`, `[[materials]]` or `[[expect]]`
/// header (tables the file has at most one of): where it is and its name.
pub(in crate::model) fn array_of_tables_header(text: &str) -> Option<(Range<usize>, &'static str)> {
    let mut at = 0;
    for line in text.split_inclusive('\n') {
        let code = line.trim_start();
        if let Some((inner, _)) = code.strip_prefix("[[").and_then(|h| h.split_once("]]")) {
            // The whole header, `[[ analysis ]]` with its spaces.
            let start = at + line.len() - code.len();
            let header = start..start + inner.len() + 4;
            let name = inner.trim();
            if let Some(table) = ["analysis", "units", "materials", "expect"]
                .into_iter()
                .find(|t| *t == name)
            {
                return Some((header, table));
            }
        }
        at += line.len();
    }
    None
}

/// The key on the line of `offset`: the name before the last `=` (`mass =
/// 1e400`), for syntax errors where no spanned parse is possible.
/// None inside a comment: a bad character there belongs to no key.
pub(in crate::model) fn key_before(text: &str, offset: usize) -> Option<String> {
    let line_start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let line = &text[line_start..offset];
    if comment_start(line).is_some() {
        return None;
    }
    let before = line.rsplit_once('=')?.0.trim_end();
    let start = before
        .char_indices()
        .rfind(|&(_, c)| !(c.is_alphanumeric() || c == '_' || c == '-'))
        .map_or(0, |(i, c)| i + c.len_utf8());
    let key = &before[start..];
    (!key.is_empty()).then(|| key.to_string())
}

/// Where a comment begins on a line of TOML: the first `#` outside a
/// string. (Multi-line strings are not followed; this only serves messages.)
pub(in crate::model) fn comment_start(line: &str) -> Option<usize> {
    let mut quote = None;
    let mut escaped = false;
    for (i, c) in line.char_indices() {
        match (quote, c) {
            (Some('"'), '\\') if !escaped => {
                escaped = true;
                continue;
            }
            (Some(q), c) if c == q && !escaped => quote = None,
            (None, '"' | '\'') => quote = Some(c),
            (None, '#') => return Some(i),
            _ => {}
        }
        escaped = false;
    }
    None
}

/// For "string values must be quoted" (`mass = 1 kg`): the line's value
/// from `offset`, without its comment, quoted as a quantity.
pub(in crate::model) fn quoted_value(text: &str, offset: usize) -> Option<String> {
    let line_end = text[offset..].find('\n').map_or(text.len(), |i| offset + i);
    let rest = &text[offset..line_end];
    let value = rest[..comment_start(rest).unwrap_or(rest.len())].trim();
    let plain = !value.is_empty()
        && value
            .chars()
            .next()
            .is_some_and(|c| c.is_ascii_digit() || c == '-' || c == '+' || c == '.')
        && !value.contains(['"', '\'', '[', ']', '{', '}', ',', '=']);
    plain.then(|| format!("\"{value}\""))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The reader's words for `text`, as the user sees them.
    fn ours(text: &str) -> String {
        super::super::explain(&Source::new("t.toml", text)).to_string()
    }

    /// Where the reference parser puts its first error.
    fn reference_span(text: &str) -> Range<usize> {
        let e = toml::from_str::<toml::Table>(text).expect_err("invalid TOML");
        e.span().expect("a syntax error has a place")
    }

    #[test]
    fn a_decoding_error_is_worded_before_an_earlier_wrong_type() {
        // The wrong type is a refusal of the form, found as the part ends;
        // the unquoted quantity TOML's own, reported first.
        let text = "[[part]]\nshape = 3\nmass = 1 kg\n";
        let d = ours(text);
        assert!(d.contains("t.toml:3:8"), "{d}");
        assert!(d.contains("string values must be quoted"), "{d}");
        assert!(d.contains("`mass = \"1 kg\"`"), "{d}");
    }

    #[test]
    fn a_key_given_twice_is_worded_before_an_earlier_unknown_key() {
        let text = "[[part]]\nshape = \"sphere\"\nmasss = 1\n[[part]]\nshape = \"sphere\"\nmass = 1\nmass = 2\n";
        let d = ours(text);
        assert!(d.contains("t.toml:7:1: error: duplicate key `mass`"), "{d}");
    }

    #[test]
    fn of_two_refusals_of_the_form_the_first_in_the_file_is_worded() {
        // `[analysis]` is converted after the parts, but comes first.
        let text = "[analysis]\nx = 1\n[[part]]\nshape = \"sphere\"\nmasss = 1\n";
        let d = ours(text);
        assert!(d.contains("t.toml:2:1: error: unknown key `x`"), "{d}");
        assert!(
            d.contains("`about`, `omega`, `alpha`, `velocity`, `axles`, `g`, `axes`"),
            "{d}"
        );
    }

    #[test]
    fn a_single_part_table_says_to_write_two_brackets() {
        for text in [
            "[part]\nshape = \"sphere\"\n",
            "[[part]]\nshape = \"sphere\"\n[part]\nshape = \"box\"\n",
        ] {
            let d = ours(text);
            assert!(d.contains("`[part]` is one table"), "{d}");
            assert!(d.contains("two brackets"), "{d}");
        }
    }

    #[test]
    fn a_value_of_the_wrong_type_names_its_key_depth_and_what_the_key_holds() {
        let d = ours("[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 2, true]\n");
        assert!(
            d.contains("`size` has an element of the wrong type: boolean `true`"),
            "{d}"
        );
        let d = ours("[[part]]\nshape = \"box\"\nmass = 1\nsize = 3\n");
        assert!(
            d.contains("`size` has the wrong type: integer `3`, expected an array of 3"),
            "{d}"
        );
        let d = ours("[[part]]\nshape = \"box\"\nmass = 1.50\nrotation = [1]\n");
        assert!(d.contains("`rotation` has the wrong type: array"), "{d}");
        assert!(d.contains("quaternion = [w, x, y, z]"), "{d}");
        let d = ours("[[part]]\nshape = \"box\"\nmass = 1979-05-27\n");
        assert!(d.contains("`mass` has the wrong type: date-time"), "{d}");
        let d = ours("[[part]]\nshape = \"box\"\nmass = 99999999999999999999\n");
        assert!(d.contains("integer `99999999999999999999`"), "{d}");
        assert!(d.contains("a TOML integer is 64-bit"), "{d}");
    }

    #[test]
    fn a_missing_key_of_a_table_is_named_at_the_table() {
        let d = ours("[materials]\nfoo = { }\n[[part]]\nshape = \"sphere\"\n");
        assert!(
            d.contains("t.toml:2:7: error: missing key `density`"),
            "{d}"
        );
        let d = ours("[budget]\n[[part]]\nshape = \"sphere\"\n");
        assert!(d.contains("missing key `limit`"), "{d}");
    }

    #[test]
    fn a_dotted_key_through_a_value_is_refused_in_tomls_words() {
        let d = ours("[[part]]\nshape = \"sphere\"\nmass = 1\nmass.x = 1\n");
        assert!(
            d.contains("t.toml:4:1: error: cannot extend value of type integer with a dotted key"),
            "{d}"
        );
        let d = ours("a = { b = 1 }\na.c = 2\n");
        assert!(d.contains("inline table"), "{d}");
    }

    /// Suggestions for a misspelt key come from the part's own shape: a
    /// box's `raduis` is not "did you mean `radius`" (a key boxes refuse).
    #[test]
    fn a_misspelt_key_is_matched_against_the_keys_of_the_parts_shape() {
        let d = ours(
            "[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\nraduis = 1\n",
        );
        assert!(d.contains("unknown key `raduis`"), "{d}");
        assert!(!d.contains("did you mean `radius`"), "{d}");
        assert!(
            d.contains("valid keys here: `name`, `shape`, `density`"),
            "{d}"
        );
        let d = ours("[[part]]\nshape = \"sphere\"\nmass = 1\ncenter = [0, 0, 0]\nraduis = 1\n");
        assert!(d.contains("did you mean `radius`?"), "{d}");
    }

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

    #[test]
    fn the_expect_keys_are_the_expected_quantities_and_their_aliases() {
        let mut want: Vec<&str> = crate::quantity::QUANTITIES
            .iter()
            .filter(|q| q.expected)
            .map(|q| q.key)
            .collect();
        want.extend(crate::quantity::ALIASES.iter().map(|a| a.0));
        assert_eq!(super::super::tables::EXPECT_KEYS, want.as_slice());
    }

    #[test]
    fn a_syntax_error_is_at_the_reference_parsers_span() {
        for text in [
            "a = [1, 2\n",
            "[part\n",
            "x = = 1\n",
            "a = 1\nb c\n",
            "a = [1,,2]\n",
        ] {
            let source = Source::new("t.toml", text);
            let d = super::super::explain(&source);
            let want = source.span(reference_span(text));
            assert_eq!(d.place().and_then(|p| p.span), Some(want), "{text:?}");
        }
    }

    #[test]
    fn a_syntax_error_names_the_key_on_its_line() {
        let text = "[[part]]\nshape = \"box\"\nmass = [1, 2\n";
        assert!(ours(text).contains("`mass`: "), "{}", ours(text));
    }

    #[test]
    fn a_syntax_error_in_a_comment_names_no_key() {
        let text = "# a = \u{7}\n";
        assert!(!ours(text).contains("`a`"), "{}", ours(text));
    }

    #[test]
    fn an_array_of_tables_header_outranks_a_syntax_error() {
        let text = "[[analysis]]\nx = [\n";
        assert!(
            ours(text).contains("`analysis` must be a table"),
            "{}",
            ours(text)
        );
    }

    #[test]
    fn arrays_nested_beyond_the_limit_are_said_in_our_words() {
        let text = format!("a = {}{}\n", "[".repeat(100), "]".repeat(100));
        assert!(
            ours(&text).contains("nested more than 80 deep"),
            "{}",
            ours(&text)
        );
    }
}
