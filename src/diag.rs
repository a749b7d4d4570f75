//! One diagnostic type for every user-facing error: `path:line:col: error:
//! message`, the offending source line with carets under the span, and an
//! optional help line, the way compilers print them so editors and CI can
//! jump to the place.

use serde::Serialize;
use std::fmt;
use std::ops::Range;
use std::path::{Path, PathBuf};
use unicode_width::{UnicodeWidthChar, UnicodeWidthStr};

mod escape;
mod path;
pub use escape::{
    LEGACY_COMMAND, is_bidi, is_hidden, is_line_separator, is_xml_noncharacter, may_hide,
    push_visible, visible,
};
use path::line_start;
pub use path::{display_path, path_bytes};

/// A part file's text and the name it is reported under (`<stdin>` for `-`).
#[derive(Debug, Clone)]
pub struct Source {
    /// The name messages show: the path as `display_path` writes it.
    pub name: String,
    /// The file the text was read from, when the name alone cannot be
    /// opened (a path that is not UTF-8 is shown escaped); see `path`.
    pub file: Option<PathBuf>,
    /// The text without a leading byte-order mark, so that columns count
    /// what an editor shows.
    pub text: String,
    /// Whether the file began with a byte-order mark (`--bless` keeps it).
    pub bom: bool,
    /// Read from standard input or a pipe (`<(git show …)`), not a regular
    /// file: its includes have no directory of their own to be relative to
    /// (`--base-dir` gives one).
    pub piped: bool,
}

impl Source {
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> Source {
        let mut text = text.into();
        let bom = text.starts_with('\u{feff}');
        if bom {
            text.drain(..'\u{feff}'.len_utf8());
        }
        Source {
            name: name.into(),
            file: None,
            text,
            bom,
            piped: false,
        }
    }

    /// The same source, read from `file` (opened, and includes resolved
    /// against, by this path; shown by `name`).
    pub fn read_from(mut self, file: PathBuf) -> Source {
        self.file = Some(file);
        self
    }

    /// The path of the file the text came from, for the file system:
    /// `file` if it was read from one, else the name itself.
    pub fn path(&self) -> &Path {
        self.file.as_deref().unwrap_or(Path::new(&self.name))
    }

    /// 1-based line and column (in characters) of a byte offset.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let offset = floor_char_boundary(&self.text, offset.min(self.text.len()));
        let before = &self.text[..offset];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let col = self.text[line_start..offset].chars().count() + 1;
        (line, col)
    }

    /// The lines and columns of a byte range: its first character and its
    /// last (inclusive, as GitHub's annotations and SARIF take it; an empty
    /// range ends where it starts).
    pub fn span(&self, range: Range<usize>) -> Span {
        span_by(&self.text, range, |offset| self.line_col(offset))
    }

    /// An error at `span` of this source.
    pub fn error(&self, span: Range<usize>, message: impl Into<String>) -> Diagnostic {
        let (line, col) = self.line_col(span.start);
        let start = floor_char_boundary(&self.text, span.start.min(self.text.len()));
        let line_start = self.text[..start].rfind('\n').map_or(0, |i| i + 1);
        let line_end = self.text[start..]
            .find('\n')
            .map_or(self.text.len(), |i| start + i);
        let line_text = self.text[line_start..line_end].trim_end_matches('\r');
        // Underline the span's part on its first line, at least one caret.
        let end = span.end.clamp(start, line_end.max(start));
        let end = floor_char_boundary(&self.text, end);
        // A long line (a generated file, a million-element array) is shown
        // as a window around the span, not echoed whole.
        let chars: Vec<char> = visible(line_text).chars().collect();
        let span_chars = self.text[start..end].chars().count();
        let (text, snippet_col, span_chars) = if chars.len() > LONG_LINE {
            let from = (col - 1).saturating_sub(LONG_LINE / 3);
            let to = (from + LONG_LINE).min(chars.len());
            let mut text: String = if from > 0 {
                "…".into()
            } else {
                String::new()
            };
            text.extend(&chars[from..to]);
            if to < chars.len() {
                text.push('…');
            }
            let shown = span_chars.min(to.saturating_sub(col - 1)).max(1);
            (text, col - from + usize::from(from > 0), shown)
        } else {
            (chars.iter().collect(), col, span_chars)
        };
        // Carets count display columns, so wide characters line up.
        let shown: String = self.text[start..].chars().take(span_chars).collect();
        let width = UnicodeWidthStr::width(visible(&shown).as_str()).max(1);
        Diagnostic(Box::new(Inner {
            place: Some(Place {
                path: self.name.clone(),
                span: Some(self.span(span)),
            }),
            message: message.into(),
            snippet: Some(Snippet {
                line,
                text,
                col: snippet_col,
                width,
                label: None,
            }),
            help: None,
            notes: Vec::new(),
            chain_in_message: false,
        }))
    }
}

/// Lines longer than this (in characters) are shown as a window.
const LONG_LINE: usize = 160;

/// A name or key from input as a message quotes it: at most `QUOTED`
/// characters, the rest cut with its length said (a long source line is
/// shown as a window the same way).
pub fn shorten(text: &str) -> String {
    const QUOTED: usize = 64;
    let n = text.chars().count();
    if n <= QUOTED {
        return text.to_string();
    }
    let head: String = text.chars().take(QUOTED - 4).collect();
    format!("{head}… ({n} characters)")
}

/// The span of `range` in `text`, its first character and its last
/// (inclusive, as GitHub's annotations and SARIF take it; an empty range
/// ends where it starts), each placed by `line_col`: the one rule for a
/// span, for `Source::span` and for a caller that indexes the lines itself
/// (`robot::check`, over files of 10⁵ links).
pub fn span_by(
    text: &str,
    range: Range<usize>,
    mut line_col: impl FnMut(usize) -> (usize, usize),
) -> Span {
    let (line, column) = line_col(range.start);
    let start = floor_char_boundary(text, range.start.min(text.len()));
    let end = floor_char_boundary(text, range.end.min(text.len()));
    let last = text[..end]
        .char_indices()
        .next_back()
        .map_or(start, |(i, _)| i.max(start));
    let (end_line, end_column) = line_col(last);
    Span {
        line,
        column,
        end_line,
        end_column,
    }
}

/// The largest char boundary at or before `i` (clamped to the text): toml
/// reports some error spans inside a multi-byte character.
pub(crate) fn floor_char_boundary(s: &str, i: usize) -> usize {
    let mut i = i.min(s.len());
    while i > 0 && !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

#[derive(Debug, Clone, PartialEq)]
struct Snippet {
    line: usize,
    text: String,
    col: usize,
    width: usize,
    label: Option<String>,
}

/// A user-facing error. `Display` renders it completely, ending in a newline.
/// Boxed so that `Result<T, Diagnostic>` stays small on the happy path.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostic(Box<Inner>);

/// Where an error is: the file as named, and the span in it when the error
/// has one (an unreadable file has none).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Place {
    pub path: String,
    #[serde(flatten)]
    pub span: Option<Span>,
}

/// A span's first and last characters, 1-based lines and columns counted in
/// characters; the end is inclusive.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Span {
    pub line: usize,
    pub column: usize,
    pub end_line: usize,
    pub end_column: usize,
}

impl fmt::Display for Place {
    /// `path:line:col`, or `path`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.span {
            Some(s) => write!(f, "{}:{}:{}", self.path, s.line, s.column),
            None => f.write_str(&self.path),
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
struct Inner {
    /// The file and span, or none for errors about flags.
    place: Option<Place>,
    message: String,
    snippet: Option<Snippet>,
    help: Option<String>,
    /// `= note:` lines after the help: the include chain, innermost first.
    notes: Vec<String>,
    /// The message already names the whole include chain (a cycle, too
    /// deep): no "included from" notes.
    chain_in_message: bool,
}

impl Diagnostic {
    /// An error about a whole file (unreadable, say): `path: error: …`.
    pub fn file(path: &str, message: impl Into<String>) -> Diagnostic {
        Diagnostic(Box::new(Inner {
            place: Some(Place {
                path: path.to_string(),
                span: None,
            }),
            message: message.into(),
            snippet: None,
            help: None,
            notes: Vec::new(),
            chain_in_message: false,
        }))
    }

    /// An error with no place in a file (a command-line flag, say).
    pub fn plain(message: impl Into<String>) -> Diagnostic {
        Diagnostic(Box::new(Inner {
            place: None,
            message: message.into(),
            snippet: None,
            help: None,
            notes: Vec::new(),
            chain_in_message: false,
        }))
    }

    /// Text printed after the carets on the source line.
    pub fn label(mut self, label: impl Into<String>) -> Diagnostic {
        if let Some(s) = &mut self.0.snippet {
            s.label = Some(label.into());
        }
        self
    }

    pub fn help(mut self, help: impl Into<String>) -> Diagnostic {
        self.0.help = Some(help.into());
        self
    }

    /// A `= note:` line, after any earlier ones.
    pub fn note(mut self, note: impl Into<String>) -> Diagnostic {
        self.0.notes.push(note.into());
        self
    }

    /// Mark the message as naming the whole include chain itself.
    pub fn with_chain_in_message(mut self) -> Diagnostic {
        self.0.chain_in_message = true;
        self
    }

    /// An "included from" note, unless the message names the chain.
    pub fn included_from(self, place: impl Into<String>) -> Diagnostic {
        if self.0.chain_in_message {
            self
        } else {
            self.note(format!("included from {}", place.into()))
        }
    }

    /// A "did you mean" help line when there is a suggestion.
    pub fn suggest(self, suggestion: Option<&str>) -> Diagnostic {
        match suggestion {
            Some(s) => self.help(format!("did you mean `{s}`?")),
            None => self,
        }
    }

    pub fn message(&self) -> &str {
        &self.0.message
    }

    /// The file and span, when the error has a place.
    pub fn place(&self) -> Option<&Place> {
        self.0.place.as_ref()
    }

    /// The text after the carets, when there is one.
    pub fn label_text(&self) -> Option<&str> {
        self.0.snippet.as_ref().and_then(|s| s.label.as_deref())
    }

    /// The `help:` line, when there is one.
    pub fn help_text(&self) -> Option<&str> {
        self.0.help.as_deref()
    }

    /// The `note:` lines (the include chain, innermost first).
    pub fn notes(&self) -> &[String] {
        &self.0.notes
    }
}

/// The styles of a message's parts, as rustc and cargo colour them: the
/// level (`error` bold red, `warning` bold yellow, with the carets and
/// their label in its colour), the message bold, the gutter and its
/// numbers bold blue, `help` and `note` bold. `PLAIN` is every style empty,
/// which renders as nothing: the text is the same with or without colour,
/// less the escape sequences.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Palette {
    pub error: anstyle::Style,
    pub warning: anstyle::Style,
    pub emphasis: anstyle::Style,
    pub gutter: anstyle::Style,
}

impl Palette {
    pub const PLAIN: Palette = Palette {
        error: anstyle::Style::new(),
        warning: anstyle::Style::new(),
        emphasis: anstyle::Style::new(),
        gutter: anstyle::Style::new(),
    };

    pub const COLOUR: Palette = {
        use anstyle::{AnsiColor, Color, Style};
        let bold = Style::new().bold();
        Palette {
            error: bold.fg_color(Some(Color::Ansi(AnsiColor::Red))),
            warning: bold.fg_color(Some(Color::Ansi(AnsiColor::Yellow))),
            emphasis: bold,
            gutter: bold.fg_color(Some(Color::Ansi(AnsiColor::Blue))),
        }
    };

    /// `COLOUR` when `colour`, else `PLAIN`.
    pub fn of(colour: bool) -> Palette {
        if colour {
            Palette::COLOUR
        } else {
            Palette::PLAIN
        }
    }

    /// `warning: TEXT` and a newline, as standard error shows a warning
    /// that has no place in a file's text: the one place warnings are
    /// written, `TEXT` shown by `visible` (one line, whatever it quotes).
    pub fn warning_line(&self, text: &str) -> String {
        let w = self.warning;
        format!("{w}warning{w:#}: {}\n", visible(text))
    }
}

impl Diagnostic {
    /// The diagnostic as `Display` writes it, coloured as rustc colours
    /// its own when `colour` is true (for standard error on a terminal);
    /// with the escape sequences taken out, the same text.
    pub fn render(&self, colour: bool) -> String {
        let mut out = String::new();
        self.write_styled(&mut out, Palette::of(colour))
            .expect("invariant: writing to a String does not fail");
        out
    }

    fn write_styled(&self, f: &mut dyn fmt::Write, p: Palette) -> fmt::Result {
        let d = &self.0;
        // Every piece from input shown by `visible`: no raw newline (nor
        // CR, nor separator) in a message, a label, a help or a note, so
        // each line begins with massprop's own text.
        let message = visible(&d.message);
        let (e, m, g) = (p.error, p.emphasis, p.gutter);
        if let Some(place) = &d.place {
            let place = Place {
                path: line_start(&place.path).into_owned(),
                span: place.span,
            };
            write!(f, "{}: ", visible(&place.to_string()))?;
        }
        writeln!(f, "{e}error{e:#}: {m}{message}{m:#}")?;
        // `= help:` under the gutter's bar, as rustc aligns it.
        let gutter = d.snippet.as_ref().map_or(1, |s| s.line.to_string().len());
        let indent = " ".repeat(gutter + 1);
        if let Some(s) = &d.snippet {
            let num = s.line.to_string();
            let pad = " ".repeat(num.len());
            writeln!(f, "{g}{pad} |{g:#}")?;
            writeln!(f, "{g}{num} |{g:#} {}", s.text)?;
            // Pad to the caret in display columns; tabs stay tabs so the
            // caret lines up whatever the terminal's tab width.
            let lead: String = s
                .text
                .chars()
                .take(s.col - 1)
                .map(|c| match c {
                    '\t' => "\t".to_string(),
                    c => " ".repeat(c.width().unwrap_or(0)),
                })
                .collect();
            let carets = "^".repeat(s.width);
            match &s.label {
                Some(label) => writeln!(
                    f,
                    "{g}{pad} |{g:#} {lead}{e}{carets} {}{e:#}",
                    visible(label)
                )?,
                None => writeln!(f, "{g}{pad} |{g:#} {lead}{e}{carets}{e:#}")?,
            }
        }
        if let Some(help) = &d.help {
            writeln!(f, "{indent}{g}={g:#} {m}help{m:#}: {}", visible(help))?;
        }
        for note in &d.notes {
            writeln!(f, "{indent}{g}={g:#} {m}note{m:#}: {}", visible(note))?;
        }
        Ok(())
    }
}

impl fmt::Display for Diagnostic {
    /// Without colour: `render(true)` is this text with escape sequences.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.write_styled(f, Palette::PLAIN)
    }
}

impl std::error::Error for Diagnostic {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_and_column_are_one_based_and_count_characters() {
        let s = Source::new("f.toml", "a = 1\nbé = 2\n");
        assert_eq!(s.line_col(0), (1, 1));
        assert_eq!(s.line_col(6), (2, 1));
        // 'é' is two bytes but one column.
        assert_eq!(s.line_col(9), (2, 3));
    }

    #[test]
    fn rendering_shows_location_source_line_and_carets() {
        let s = Source::new("f.toml", "x = 1\nsizee = [1]\n");
        let d = s
            .error(6..11, "unknown key `sizee`")
            .label("here")
            .suggest(Some("size"));
        assert_eq!(
            d.to_string(),
            "f.toml:2:1: error: unknown key `sizee`\n  |\n2 | sizee = [1]\n  | ^^^^^ here\n  = help: did you mean `size`?\n"
        );
    }

    #[test]
    fn carets_line_up_under_wide_characters() {
        // 部 and 品 are two columns wide each: `;` is the 12th character but
        // stands in display column 14, after 13 columns of text.
        let text = "name = \"部品\"; x\n";
        let s = Source::new("f.toml", text);
        let semicolon = text.find(';').unwrap();
        let d = s.error(semicolon..semicolon + 1, "bad").to_string();
        assert!(d.starts_with("f.toml:1:12:"), "{d}");
        assert!(d.contains(&format!("  | {}^\n", " ".repeat(13))), "{d}");
    }

    #[test]
    fn control_characters_show_as_pictures_and_keep_the_carets_in_line() {
        // DEL and ESC would vanish (or drive the terminal); each shows as
        // one visible character, so `x` is still under its caret.
        let text = "a = 1 # \u{7f}\u{1b}[2J x\n";
        let s = Source::new("f.toml", text);
        let x = text.find('x').unwrap();
        let d = s.error(x..x + 1, "bad").to_string();
        assert!(d.contains("1 | a = 1 # \u{2421}\u{241b}[2J x\n"), "{d}");
        assert!(d.contains(&format!("  | {}^\n", " ".repeat(14))), "{d}");
        assert!(!d.contains('\u{1b}') && !d.contains('\u{7f}'), "{d}");
    }

    #[test]
    fn a_long_line_is_shown_as_a_window_around_the_span() {
        let text = format!("x = [{}9]\n", "0, ".repeat(100_000));
        let s = Source::new("f.toml", text.as_str());
        let nine = text.find('9').unwrap();
        let d = s.error(nine..nine + 1, "bad").to_string();
        assert!(
            d.starts_with(&format!("f.toml:1:{}:", nine + 1)),
            "{}",
            &d[..40]
        );
        assert!(d.len() < 1000, "the whole line was echoed");
        // The caret is still under the 9.
        let lines: Vec<&str> = d.lines().collect();
        let caret = lines[3].find('^').unwrap();
        assert_eq!(lines[2][..caret + 3].chars().last(), Some('9'), "{d}");
    }

    #[test]
    fn help_lines_align_with_the_gutter_and_messages_show_control_characters() {
        let text = "\n".repeat(11) + "a = 1\n";
        let s = Source::new("f.toml", text.as_str());
        let d = s.error(11..12, "key `\u{1b}[2J`").help("h").to_string();
        assert!(d.contains("key `\u{241b}[2J`"), "{d}");
        assert!(d.contains("\n12 | a = 1\n   |"), "{d}");
        assert!(d.ends_with("\n   = help: h\n"), "{d}");
    }

    #[test]
    fn a_byte_order_mark_is_not_a_column() {
        let s = Source::new("f.toml", "\u{feff}mass = x\n");
        assert!(s.bom);
        assert_eq!(s.text, "mass = x\n");
        assert_eq!(s.line_col(7), (1, 8));
        assert!(!Source::new("f.toml", "mass = x").bom);
    }

    #[test]
    fn spans_inside_a_character_snap_to_its_start() {
        // toml has reported spans one byte into a BOM or an em dash.
        let text = "a = 1 # \u{2014}\n";
        let s = Source::new("f.toml", text);
        let inside = text.find('\u{2014}').unwrap() + 1;
        assert_eq!(s.line_col(inside), (1, 9));
        let d = s.error(inside..inside + 1, "bad").to_string();
        assert!(d.starts_with("f.toml:1:9:"), "{d}");
        assert_eq!(floor_char_boundary(text, inside), inside - 1);
        assert_eq!(floor_char_boundary(text, 1000), text.len());
    }

    /// The characters a reader may take for the end of a line: LF, CR,
    /// VT, FF, NEL (U+0085), and the line and paragraph separators.
    const LINE_BREAKS: [char; 7] = [
        '\n', '\r', '\u{b}', '\u{c}', '\u{85}', '\u{2028}', '\u{2029}',
    ];

    #[test]
    fn no_piece_of_a_diagnostic_can_start_a_line_of_its_own() {
        for b in LINE_BREAKS {
            let forged = format!("x{b}::error file=x::forged");
            let s = Source::new("f.toml", format!("a = 1 # {b}\n"));
            let d = s
                .error(0..1, format!("unknown key `{forged}`"))
                .label(forged.as_str())
                .help(forged.as_str())
                .note(forged.as_str())
                .to_string();
            // Lines: the message, the gutter, the source line, the carets,
            // the help, the note.
            assert_eq!(d.matches('\n').count(), 6, "{b:?}: {d}");
            assert!(
                d.lines().all(|l| !l.trim_start().starts_with("::")),
                "{b:?}: {d}"
            );
            assert!(b == '\n' || !d.contains(b), "{b:?}: {d}");
        }
    }

    #[test]
    fn a_place_named_otherwise_than_by_display_path_still_begins_safely() {
        let d = Diagnostic::file("::error::x", "bad").to_string();
        assert_eq!(d, "./::error::x: error: bad\n");
        let d = Source::new("--set m", "1").error(0..1, "bad").to_string();
        assert!(d.starts_with("--set m:1:1: error: bad\n"), "{d}");
    }

    #[test]
    fn a_warning_is_one_line_whatever_it_quotes() {
        for b in LINE_BREAKS {
            let line = Palette::PLAIN.warning_line(&format!("f: `a{b}::error::x`"));
            assert_eq!(line.lines().count(), 1, "{b:?}: {line}");
            assert!(line.starts_with("warning: f: `a"), "{line}");
        }
    }

    #[test]
    fn a_location_shows_control_characters_as_pictures() {
        let d = Diagnostic::file("a\u{1b}[2J.toml", "bad").to_string();
        assert_eq!(d, "a\u{241b}[2J.toml: error: bad\n");
    }

    #[test]
    fn a_source_read_from_a_file_opens_that_file_and_shows_its_name() {
        let s = Source::new("shown.toml", "").read_from(PathBuf::from("real.toml"));
        assert_eq!(
            (s.name.as_str(), s.path()),
            ("shown.toml", Path::new("real.toml"))
        );
        assert_eq!(Source::new("a.toml", "").path(), Path::new("a.toml"));
    }

    /// A diagnostic with every part: place, snippet with a label, help,
    /// notes.
    fn every_part() -> Diagnostic {
        let text = "\n".repeat(9) + "mass = \"2 kgg\"\n";
        let s = Source::new("f.toml", text.as_str());
        let at = text.find("2 kgg").unwrap();
        s.error(at..at + 5, "unknown unit `kgg`")
            .label("here")
            .help("did you mean `kg`?")
            .note("included from a.toml:3:1")
    }

    #[test]
    fn uncoloured_rendering_is_display() {
        let d = every_part();
        assert_eq!(d.render(false), d.to_string());
        assert!(!d.render(false).contains('\u{1b}'));
    }

    #[test]
    fn coloured_rendering_is_the_same_text_with_escape_sequences() {
        let d = every_part();
        let coloured = d.render(true);
        assert_ne!(coloured, d.to_string());
        assert_eq!(
            anstream::adapter::strip_str(&coloured).to_string(),
            d.to_string()
        );
    }

    #[test]
    fn coloured_rendering_colours_as_rustc() {
        let coloured = every_part().render(true);
        let red = "\u{1b}[1m\u{1b}[31m";
        let blue = "\u{1b}[1m\u{1b}[34m";
        let bold = "\u{1b}[1m";
        let reset = "\u{1b}[0m";
        assert!(
            coloured.starts_with(&format!(
                "f.toml:10:9: {red}error{reset}: {bold}unknown unit `kgg`{reset}\n"
            )),
            "{coloured:?}"
        );
        assert!(
            coloured.contains(&format!("{blue}10 |{reset} mass")),
            "{coloured:?}"
        );
        assert!(
            coloured.contains(&format!("{red}^^^^^ here{reset}\n")),
            "{coloured:?}"
        );
        assert!(
            coloured.contains(&format!("{blue}={reset} {bold}help{reset}: did you mean")),
            "{coloured:?}"
        );
        assert!(
            coloured.contains(&format!("{blue}={reset} {bold}note{reset}: included")),
            "{coloured:?}"
        );
    }

    #[test]
    fn a_warning_line_colours_only_its_level() {
        assert_eq!(Palette::PLAIN.warning_line("f: x"), "warning: f: x\n");
        assert_eq!(
            Palette::COLOUR.warning_line("f: x"),
            "\u{1b}[1m\u{1b}[33mwarning\u{1b}[0m: f: x\n"
        );
    }

    #[test]
    fn an_empty_span_at_end_of_file_still_gets_one_caret() {
        let s = Source::new("f.toml", "x = [");
        let d = s.error(5..5, "unclosed array");
        assert!(d.to_string().contains("1 | x = [\n  |      ^\n"));
    }
}
