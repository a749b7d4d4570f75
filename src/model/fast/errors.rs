//! The reader's own words for a file it cannot read, class by class:
//! syntax errors, in the parser's (`toml_parser`'s `ParseError`: its
//! description, what it expected, its span), given the key on their line
//! and, where one fits, a help. (Classes not worded here yet are still
//! worded from serde's error by `model::toml_error`.) The small helpers
//! that find a key or a header in the text serve both.

use crate::diag::{Diagnostic, Source};
use std::ops::Range;
use toml_parser::parser::{RecursionGuard, ValidateWhitespace};
use toml_parser::{ErrorSink, Expected, ParseError};

/// The toml crate's own nesting limit, as the reader's (`RECURSION_LIMIT`).
const LIMIT: u32 = super::RECURSION_LIMIT;

/// The first syntax error of `source` (as the TOML parser reports it over
/// the whole file), in massprop's words; `None` where its syntax is valid.
/// Only on the error path: the file is lexed whole.
pub(in crate::model) fn syntax(source: &Source) -> Option<Diagnostic> {
    let text = &source.text;
    let toml = toml_parser::Source::new(text);
    let tokens = toml.lex().into_vec();
    let mut nothing = ();
    let mut ws = ValidateWhitespace::new(&mut nothing, toml);
    let mut guarded = RecursionGuard::new(&mut ws, LIMIT);
    let mut first = First(None);
    toml_parser::parser::parse_document(&tokens, &mut guarded, &mut first);
    let error = first.0?;
    // A `[[analysis]]` header is the error wherever the file fails.
    if let Some(d) = array_of_tables(source) {
        return Some(d);
    }
    let span = error.unexpected().map_or(0..0, |s| s.start()..s.end());
    // Some spans fall inside a multi-byte character (after a BOM, a
    // combining mark): snap to boundaries.
    let floor = |i| crate::diag::floor_char_boundary(text, i);
    let span = floor(span.start)..floor(span.end).max(floor(span.start));
    let msg = describe(&error).trim_end().replace(
        "cannot recurse further; max recursion depth met",
        "arrays and inline tables nested more than 80 deep, the most the TOML reader takes",
    );
    let key = key_before(text, span.start);
    let d = match &key {
        Some(k) => source.error(span, format!("`{k}`: {msg}")),
        None => source.error(span, msg),
    };
    Some(match key.as_deref() {
        Some("part") => d.help("write each part as a `[[part]]` table (two brackets)"),
        Some("rotation") => d.help(ROTATION_FORMS),
        _ => d,
    })
}

/// Keeps the first error the parser reports.
struct First(Option<ParseError>);

impl ErrorSink for First {
    fn report_error(&mut self, error: ParseError) {
        if self.0.is_none() {
            self.0 = Some(error);
        }
    }
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
        syntax(&Source::new("t.toml", text))
            .expect("a syntax error")
            .to_string()
    }

    /// Where the reference parser puts its first error.
    fn reference_span(text: &str) -> Range<usize> {
        let e = toml::from_str::<toml::Table>(text).expect_err("invalid TOML");
        e.span().expect("a syntax error has a place")
    }

    #[test]
    fn valid_toml_has_no_syntax_error_even_if_no_part_file() {
        let text = "[[analysis]]\nmass = 1 kg\n[[part]]\nshape = 3\n";
        assert!(syntax(&Source::new("t.toml", "[[part]]\nshape = 3\n")).is_none());
        assert!(toml::from_str::<toml::Table>(text).is_err());
        // (An unquoted quantity is a decoding error, not a syntax error.)
        assert!(syntax(&Source::new("t.toml", "mass = 1 kg\n")).is_none());
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
            let d = syntax(&source).expect("a syntax error");
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
