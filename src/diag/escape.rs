//! How text from input is shown in every output for people: control
//! characters as their pictures, the characters a reader would act on
//! (C1 controls, bidirectional formatting, line and paragraph separators,
//! U+FFFE and U+FFFF) as �; the one list of them (`is_hidden`), which
//! JSON escapes instead (`output::json_line`).

/// The text with control characters (but tab) shown as their Unicode
/// pictures (U+0000..U+001F as ␀..␟, DEL as ␡; C1, the bidirectional
/// formatting characters, the line and paragraph separators and U+FFFE,
/// U+FFFF as �), one character each, so a stray one neither vanishes nor
/// moves the carets nor acts on the terminal nor reorders or breaks the
/// line. A newline is shown as ␊ too: text from input never starts a line
/// of its own (a CI runner reads `::error::…` at the start of any line of
/// standard output or error as a command).
pub fn visible(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    push_visible(&mut out, text);
    out
}

/// Append `visible(text)` to `out`: text from input written to stdout (a
/// part's name, a file name) can neither act on the terminal nor add a line
/// to line-per-record output.
pub fn push_visible(out: &mut String, text: &str) {
    if !may_hide(text) {
        out.push_str(text);
        return;
    }
    let from = out.len();
    out.extend(text.chars().map(|c| match c {
        '\t' => c,
        '\0'..='\u{1f}' => char::from_u32(0x2400 + c as u32).unwrap_or('\u{fffd}'),
        '\u{7f}' => '\u{2421}',
        c if is_hidden(c) => '\u{fffd}',
        c => c,
    }));
    if out[from..].contains(LEGACY_COMMAND) {
        let shown = out[from..].replace(LEGACY_COMMAND, LEGACY_COMMAND_SHOWN);
        out.truncate(from);
        out.push_str(&shown);
    }
}

/// The GitHub runner's older workflow-command syntax, `##[name]value`,
/// which it reads ANYWHERE in a line of standard output or error (its
/// `ActionCommand.TryParse` looks for the prefix with `IndexOf`), not only
/// at the line's start as it does `::name::`: so no text from input may
/// show it. Text shows it as `#＃[` (U+FF03), JSON as `#\u0023[`, the
/// same string to a JSON reader (`output::json_line`).
pub const LEGACY_COMMAND: &str = "##[";

/// `LEGACY_COMMAND` as text from input shows it.
const LEGACY_COMMAND_SHOWN: &str = "#\u{ff03}[";

/// Whether text from input may hold a character `is_hidden` names: one
/// scan of the bytes, so that most text is copied as it is. (C1 controls
/// are U+0080..U+009F, encoded with a 0xC2 lead byte; the bidirectional
/// marks and the separators have lead bytes 0xD8 and 0xE2; U+FFFE and
/// U+FFFF, 0xEF; and the runner's older command prefix, `LEGACY_COMMAND`.)
pub fn may_hide(text: &str) -> bool {
    text.bytes()
        .any(|b| b < 0x20 || b == 0x7f || b == 0xc2 || b == 0xd8 || b == 0xe2 || b == 0xef)
        || text.contains(LEGACY_COMMAND)
}

/// The characters that text from input may not show raw, in any output:
/// controls (C0, DEL, C1), the bidirectional formatting characters, the
/// line and paragraph separators, U+FFFE and U+FFFF. Tables, messages and
/// XML show them as pictures or �, JSON escapes them (`output::json_line`).
pub fn is_hidden(c: char) -> bool {
    c.is_control() || is_bidi(c) || is_line_separator(c) || is_xml_noncharacter(c)
}

/// U+FFFE and U+FFFF: noncharacters that XML 1.0 forbids (a JUnit report
/// or an SVG holding one is not well-formed), and U+FFFE reads as a
/// byte-swapped byte-order mark.
pub fn is_xml_noncharacter(c: char) -> bool {
    matches!(c, '\u{fffe}' | '\u{ffff}')
}

/// The Unicode line and paragraph separators (U+2028, U+2029): not
/// controls, but a log viewer or editor may start a new line at them, so a
/// name could add a line to line-per-record output.
pub fn is_line_separator(c: char) -> bool {
    matches!(c, '\u{2028}' | '\u{2029}')
}

/// The bidirectional formatting characters (embeddings, overrides,
/// isolates and marks): not controls to Unicode, but on a terminal they
/// reorder how the rest of the line reads ("Trojan Source": a name can make
/// `PATH: failed` read as something else).
pub fn is_bidi(c: char) -> bool {
    matches!(
        c,
        '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}' | '\u{200e}' | '\u{200f}' | '\u{61c}'
    )
}

#[cfg(test)]
mod tests {
    #[test]
    fn text_from_input_never_shows_the_runners_older_command_prefix() {
        for text in [
            "##[add-mask]secret",
            "a ##[error]x",
            "###[",
            "##\n##[",
            "##[##[",
        ] {
            let shown = super::visible(text);
            assert!(!shown.contains(super::LEGACY_COMMAND), "{shown}");
            assert_eq!(shown.chars().count(), text.chars().count(), "{shown}");
        }
        assert_eq!(super::visible("a#[b]##c"), "a#[b]##c");
    }

    use super::*;

    #[test]
    fn bidirectional_formatting_characters_are_shown_as_replacement_characters() {
        // "ok ", U+202E, "deliaf" would read as "ok failed" on a terminal.
        assert_eq!(visible("ok \u{202e}deliaf"), "ok \u{fffd}deliaf");
        assert_eq!(visible("a\u{2028}b\u{2029}c"), "a\u{fffd}b\u{fffd}c");
        for c in [
            '\u{202a}', '\u{202e}', '\u{2066}', '\u{2069}', '\u{200e}', '\u{200f}', '\u{61c}',
        ] {
            assert_eq!(
                visible(&format!("a{c}b")),
                "a\u{fffd}b",
                "{:04x}",
                u32::from(c)
            );
        }
        // Neighbours of the ranges and other text behind the same lead bytes
        // stay as they are.
        let t = "\u{2027}\u{202f}\u{2065}\u{206a}—…│\u{200d}\u{61b}\u{61d}";
        assert_eq!(visible(t), t);
    }

    #[test]
    fn noncharacters_that_xml_forbids_are_shown_as_replacement_characters() {
        assert_eq!(visible("a\u{fffe}b\u{ffff}c"), "a\u{fffd}b\u{fffd}c");
        // Others behind the same lead byte stay.
        let t = "\u{feff}\u{fffd}\u{ff01}\u{f900}";
        assert_eq!(visible(t), t);
    }
}
