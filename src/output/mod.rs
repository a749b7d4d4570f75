//! The output layer: how every command's result is written, for people
//! (tables in the file's units) and for scripts (JSON in SI).
//!
//! - `format`: numbers, percentages, display units and labels — the one
//!   place a value's look is decided;
//! - `grid`: the one table writer;
//! - one module per command (`report`, `check`, `diff`, `materials`), each
//!   with a `table` and a `json` renderer that return strings;
//! - `drawing`: the `render` command's SVG of the body (its own output: no `Format`).
//!
//! `Format` is matched in one place, `render`: a command hands over its
//! result as an `Output` and never looks at the format. How the text is
//! dressed for where it goes (colour, a terminal's width) is a `Style`,
//! handed in with it.

pub mod budget;
pub mod check;
pub mod ci;
pub mod diff;
pub mod drawing;
pub mod format;
pub mod grid;
pub mod inertial;
pub mod junit;
pub mod materials;
pub mod report;
pub mod robot;

use crate::analysis::check::FileResult;
use crate::analysis::diff::Diff;
use crate::analysis::summary::Summary;
use std::io::Write as _;

/// Output format (`--format`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Format {
    /// Tables for people, in the file's units.
    #[default]
    Table,
    /// One JSON object in SI units (docs/json.md, docs/check.md,
    /// docs/diff.md).
    Json,
    /// `check` only: GitHub Actions workflow commands (docs/ci.md).
    Github,
    /// `check` only: JUnit XML, as cargo-nextest writes it.
    Junit,
    /// `check` only: SARIF 2.1.0, for code scanning.
    Sarif,
}

/// How output is dressed for where it goes. The default, plain, is a
/// pipe's and a file's: what every pinned output shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Style {
    /// ANSI colour, as cargo colours (`check`'s `error`).
    pub colour: bool,
    /// The most columns a table may take (a terminal's width, or
    /// `--width`): a wider one is split (`grid::Fit`). None: no limit.
    pub width: Option<usize>,
}

/// A command's result, ready to be written in either format.
pub enum Output<'a> {
    /// `report`: the summary, the name of the file it came from, and how
    /// much of it a table shows (JSON has everything).
    Report(&'a Summary, &'a str, report::Detail),
    /// `check`: every file's result, how many files a directory's search
    /// passed over, and whether the table leaves out what passed
    /// (`--quiet`).
    Check(&'a [FileResult], usize, bool),
    Diff(&'a Diff),
    /// `diff` of a part file and a robot description's link.
    LinkDiff(&'a crate::analysis::diff::LinkDiff),
    Materials(&'a [materials::Listed]),
    /// `budget`: the weight statement.
    Budget(&'a crate::analysis::budget::Statement),
}

/// `output` in `format` and `style`, in memory.
pub fn render(output: &Output, format: Format, style: Style) -> String {
    let mut out = Vec::new();
    write(output, format, style, &mut out).expect("invariant: writing to memory does not fail");
    String::from_utf8(out).expect("invariant: every output is UTF-8")
}

/// `output` in `format`, written to `w`: the one place formats are told
/// apart. A report is written as it is made (its rows are never all in
/// memory); the other outputs are small and made first. `style` dresses
/// the tables for people; JSON and the CI formats are for programs, and
/// always plain.
pub fn write(
    output: &Output,
    format: Format,
    style: Style,
    w: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    let text = match (format, output) {
        (Format::Table, Output::Report(s, source, detail)) => {
            return report::write_detail_to(s, source, *detail, style.width, w);
        }
        (Format::Json, Output::Report(s, _, _)) => return report::write_json_to(s, w),
        (Format::Table, Output::Check(r, skipped, quiet)) => {
            check::table_of(r, *skipped, style, *quiet)
        }
        (Format::Json, Output::Check(r, _, _)) => check::json(r),
        (Format::Github, Output::Check(r, skipped, _)) => ci::github(r, *skipped),
        (Format::Junit, Output::Check(r, _, _)) => ci::junit(r),
        (Format::Sarif, Output::Check(r, _, _)) => ci::sarif(r),
        // The command line offers them for `check` alone (`cli`).
        (Format::Github | Format::Junit | Format::Sarif, _) => {
            return Err(std::io::Error::new(
                std::io::ErrorKind::Unsupported,
                "the CI formats are for `check`'s results",
            ));
        }
        (Format::Table, Output::Diff(d)) => diff::table(d, style.width),
        (Format::Json, Output::Diff(d)) => diff::json(d),
        (Format::Table, Output::LinkDiff(d)) => diff::link_table(d, style.width),
        (Format::Json, Output::LinkDiff(d)) => diff::link_json(d),
        (Format::Table, Output::Materials(l)) => materials::table(l),
        (Format::Json, Output::Materials(l)) => materials::json(l),
        (Format::Table, Output::Budget(b)) => budget::table(b, style.width),
        (Format::Json, Output::Budget(b)) => budget::json(b),
    };
    w.write_all(text.as_bytes())
}

/// `value` as one line of JSON, ending in a newline: every JSON output is
/// written by this.
///
/// NOTE: serde_json escapes only U+0000..U+001F in strings; DEL, the C1
/// controls (U+0080..U+009F: U+009B is a CSI to terminals that take 8-bit
/// controls), the bidirectional formatting characters (`diag::is_bidi`) and
/// the line and paragraph separators (`diag::is_line_separator`)
/// from a name would reach a terminal raw from
/// `massprop report --format json | less`. They are escaped as `\u007f`,
/// `\u009b`, `\u202e`, …, which every JSON reader decodes back to the same
/// text.
pub fn json_line<T: serde::Serialize + ?Sized>(value: &T) -> String {
    let mut out = Vec::new();
    json_line_to(value, &mut out).expect("invariant: writing to memory does not fail");
    String::from_utf8(out).expect("invariant: serde_json writes UTF-8")
}

/// `json_line`, written to `w` as it is made.
pub fn json_line_to<T: serde::Serialize + ?Sized>(
    value: &T,
    w: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    // Written in pieces, not a call to `w` per token.
    let mut w = std::io::BufWriter::with_capacity(1 << 16, w);
    let mut ser = serde_json::Serializer::with_formatter(&mut w, ControlsEscaped);
    // Outputs hold finite numbers and strings, which always serialize: an
    // error is one of writing.
    value.serialize(&mut ser).map_err(std::io::Error::from)?;
    w.write_all(b"\n")?;
    w.flush()
}

/// A serializer of `json_line`'s JSON into `w`, unbuffered (the report's
/// rows are written between its tokens: `report::write_json_to`).
pub(crate) fn json_serializer<W: std::io::Write>(
    w: W,
) -> serde_json::Serializer<W, impl serde_json::ser::Formatter> {
    serde_json::Serializer::with_formatter(w, ControlsEscaped)
}

/// serde_json's compact formatter, with DEL and C1 controls escaped and
/// every real written as a float without a sign on zero.
struct ControlsEscaped;

impl serde_json::ser::Formatter for ControlsEscaped {
    // NOTE: every real of every command passes here, so this is the one
    // place their form is fixed (docs/json.md): serde_json writes an `f64`
    // with a `.0` or an exponent, so never as an integer, but it keeps the
    // sign of zero, and a script that tests `x < 0` or prints `-0.0` would
    // see a sign no computation meant (a σ of zero, a rotated zero).
    fn write_f64<W: ?Sized + std::io::Write>(&mut self, w: &mut W, x: f64) -> std::io::Result<()> {
        let x = if x == 0.0 { 0.0 } else { x };
        serde_json::ser::CompactFormatter.write_f64(w, x)
    }

    fn write_f32<W: ?Sized + std::io::Write>(&mut self, w: &mut W, x: f32) -> std::io::Result<()> {
        let x = if x == 0.0 { 0.0 } else { x };
        serde_json::ser::CompactFormatter.write_f32(w, x)
    }

    fn write_string_fragment<W: ?Sized + std::io::Write>(
        &mut self,
        w: &mut W,
        fragment: &str,
    ) -> std::io::Result<()> {
        // NOTE: every name of every row passes here (a million rows of
        // long names in a large report): printable ASCII without `#`, what
        // almost every name is, is written in one pass over its bytes
        // rather than `may_hide`'s two (its test and `##[`'s search). Such
        // text is never one `may_hide` finds (the same bytes either way:
        // `plain_ascii_is_never_hidden`).
        if fragment
            .bytes()
            .all(|b| (0x20..0x7f).contains(&b) && b != b'#')
            || !crate::diag::may_hide(fragment)
        {
            return w.write_all(fragment.as_bytes());
        }
        let mut start = 0;
        for (i, c) in fragment.char_indices() {
            // serde_json has escaped C0 already; the rest of
            // `diag::is_hidden` is left to this, and the runner's older
            // command prefix (`diag::LEGACY_COMMAND`, read anywhere in a
            // line) has its second `#` escaped: the same string.
            let legacy = c == '#'
                && i > 0
                && fragment[i..].starts_with("#[")
                && fragment[..i].ends_with('#');
            if crate::diag::is_hidden(c) || legacy {
                w.write_all(&fragment.as_bytes()[start..i])?;
                write!(w, "\\u{:04x}", u32::from(c))?;
                start = i + c.len_utf8();
            }
        }
        w.write_all(&fragment.as_bytes()[start..])
    }
}

#[cfg(test)]
mod tests {
    use super::json_line;

    #[test]
    fn plain_ascii_is_never_hidden() {
        // Every printable ASCII character but `#`, alone and in a run: the
        // fast path's text, which `may_hide` passes too.
        let plain: String = (0x20u8..0x7f)
            .filter(|&b| b != b'#')
            .map(char::from)
            .collect();
        assert!(!crate::diag::may_hide(&plain));
        for c in plain.chars() {
            assert!(!crate::diag::may_hide(&c.to_string()), "{c:?}");
        }
    }

    #[test]
    fn json_never_shows_the_runners_older_command_prefix_and_reads_back_the_same_text() {
        for text in [
            "##[add-mask]secret",
            "a ##[error]x ###[y",
            "##[",
            "#",
            "#[##[",
            "é##[é",
        ] {
            let line = json_line(&serde_json::json!({ "name": text }));
            assert!(!line.contains(crate::diag::LEGACY_COMMAND), "{line}");
            let back: serde_json::Value = serde_json::from_str(&line).unwrap();
            assert_eq!(back["name"], text);
        }
    }

    #[test]
    fn json_writes_a_negative_zero_as_zero_and_every_real_as_a_float() {
        let line =
            json_line(&serde_json::json!({ "a": -0.0, "b": [0.0, -0.0_f64, 2.0, -1.5e-300] }));
        assert_eq!(line, "{\"a\":0.0,\"b\":[0.0,0.0,2.0,-1.5e-300]}\n");
    }

    #[test]
    fn json_escapes_every_control_character_and_reads_back_the_same_text() {
        let text = "a\u{1b}[31m\u{7f}b\u{9b}2Jc\u{80}\u{9f}\u{a0}é\u{202e}d\u{2069}—\u{2028}\n";
        let line = json_line(&serde_json::json!({ "name": text }));
        assert_eq!(
            line,
            "{\"name\":\"a\\u001b[31m\\u007fb\\u009b2Jc\\u0080\\u009f\u{a0}é\\u202ed\\u2069—\\u2028\\n\"}\n"
        );
        assert!(!line.chars().any(|c| (c.is_control() && c != '\n')
            || crate::diag::is_bidi(c)
            || crate::diag::is_line_separator(c)));
        let back: serde_json::Value = serde_json::from_str(&line).unwrap();
        assert_eq!(back["name"], text);
    }
}
