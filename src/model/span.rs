//! Where a piece of a string value lies in the file: the one map from a
//! byte range of the value, as read, to its bytes in the source (an
//! expression's or a tolerance's error pointed at its token).

use std::ops::Range;

/// Where bytes `at` of a string's value lie in the file, given the
/// string's span there: a literal string (`'…'`) maps by its opening
/// quote, a basic one (`"…"`) through its escapes; anything else (a
/// multi-line string, a span that is not the string's) is the whole span.
pub(super) fn sub_span(
    file: &str,
    span: Range<usize>,
    value: &str,
    at: Range<usize>,
) -> Range<usize> {
    let Some(raw) = file.get(span.clone()) else {
        return span;
    };
    // Raw offsets of each byte of the value, and of its end.
    let mut map: Vec<usize> = Vec::with_capacity(value.len() + 1);
    if raw.len() == value.len() {
        // The source itself: `--set`'s value.
        map.extend(span.start..=span.end);
    } else if raw.starts_with('\'') && !raw.starts_with("'''") {
        map.extend(span.start + 1..=span.start + 1 + value.len());
    } else if raw.starts_with('"') && !raw.starts_with("\"\"\"") {
        let body = &raw[1..raw.len().saturating_sub(1).max(1)];
        let mut decoded = String::with_capacity(value.len());
        let mut chars = body.char_indices().peekable();
        while let Some((i, c)) = chars.next() {
            let r = span.start + 1 + i;
            let d = if c == '\\' {
                let Some((_, e)) = chars.next() else { break };
                let hex = |n: usize, chars: &mut std::iter::Peekable<std::str::CharIndices>| {
                    let s: String = (0..n).filter_map(|_| chars.next().map(|x| x.1)).collect();
                    u32::from_str_radix(&s, 16).ok().and_then(char::from_u32)
                };
                match e {
                    'b' => '\u{8}',
                    't' => '\t',
                    'n' => '\n',
                    'f' => '\u{c}',
                    'r' => '\r',
                    'e' => '\u{1b}',
                    '"' => '"',
                    '\\' => '\\',
                    'x' => hex(2, &mut chars).unwrap_or('\u{fffd}'),
                    'u' => hex(4, &mut chars).unwrap_or('\u{fffd}'),
                    'U' => hex(8, &mut chars).unwrap_or('\u{fffd}'),
                    _ => '\u{fffd}',
                }
            } else {
                c
            };
            decoded.push(d);
            map.extend(std::iter::repeat_n(r, d.len_utf8()));
        }
        map.push(span.end - 1);
        if decoded != value {
            return span;
        }
    } else {
        return span;
    }
    match (map.get(at.start), map.get(at.end)) {
        (Some(&s), Some(&e)) => s..e.max(s + 1),
        _ => span,
    }
}
