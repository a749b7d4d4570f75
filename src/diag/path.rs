//! How a path is shown, in every output: the one rule (`display_path`),
//! which can be read back (`path_bytes`), and never lets a file's name
//! choose how a line begins.

use std::borrow::Cow;
use std::path::Path;

/// A path as text, for every output (messages, tables, JSON): the one
/// rule for showing a path.
///
/// - A path that is UTF-8 is its own text (so the name still opens the
///   file), unless it holds the text `\xNN` with NN from 80 to ff (below).
/// - A path that is not UTF-8 shows each byte that is not UTF-8 as `\xNN`
///   (two lowercase hex digits), and each backslash of its own doubled; so
///   does a UTF-8 path holding the text `\x80`..`\xff`. The rule can be
///   read back (`path_bytes`): every name of any bytes is told apart from
///   every other, and SARIF's URIs give the name's bytes.
/// - A path that does not begin with an ASCII letter or digit, `.`, `/`,
///   `_` or `~` is shown with `./` before it: a path is shown at the start
///   of a line (`PATH:LINE:COL: error: …`, `PATH: ok`), and a file name in a
///   pull request (found by `check DIR`, or by a shell's glob) must not
///   choose how a line begins (`::error::…` is a command to a CI runner);
///   `./NAME` is still a relative path to the same file.
///
/// Control characters are then shown as text from input always is: as
/// their pictures by `visible` on a terminal, as JSON escapes in JSON.
pub fn display_path(path: &Path) -> String {
    #[cfg(unix)]
    let text = {
        use std::os::unix::ffi::OsStrExt;
        shown_bytes(path.as_os_str().as_bytes())
    };
    #[cfg(not(unix))]
    let text = path.to_string_lossy().into_owned();
    match begins_safely(&text) {
        true => text,
        false => format!("./{text}"),
    }
}

/// Whether a path shown at the start of a line begins with text of its
/// own choosing there: empty, or its first character is an ASCII letter
/// or digit, `.`, `/`, `_` or `~` (none of which a CI runner, a terminal
/// or a reader takes for anything but the start of a path).
fn begins_safely(text: &str) -> bool {
    text.chars()
        .next()
        .is_none_or(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '/' | '_' | '~'))
}

/// A path's bytes as `display_path` shows them, before the `./` rule.
#[cfg(unix)]
fn shown_bytes(bytes: &[u8]) -> String {
    use std::fmt::Write;
    if let Ok(text) = std::str::from_utf8(bytes)
        && !has_byte_escape(text)
    {
        return text.to_string();
    }
    let mut out = String::new();
    for chunk in bytes.utf8_chunks() {
        for c in chunk.valid().chars() {
            if c == '\\' {
                out.push('\\');
            }
            out.push(c);
        }
        for b in chunk.invalid() {
            let _ = write!(out, "\\x{b:02x}");
        }
    }
    out
}

/// Whether `text` holds `\xNN` with NN a byte from 80 to ff in lowercase
/// hex: what `display_path` writes for a byte that is not UTF-8 (every
/// such byte is 80 or above).
fn has_byte_escape(text: &str) -> bool {
    text.match_indices("\\x")
        .any(|(i, _)| byte_escape(&text[i..]).is_some())
}

/// The byte of a `\xNN` (NN from 80 to ff, lowercase) at the start of `s`.
fn byte_escape(s: &str) -> Option<u8> {
    let hex = s.strip_prefix("\\x")?.get(..2)?;
    let lower = |c: char| c.is_ascii_digit() || ('a'..='f').contains(&c);
    if !hex.chars().all(lower) {
        return None;
    }
    u8::from_str_radix(hex, 16).ok().filter(|b| *b >= 0x80)
}

/// The bytes of the path that `display_path` showed as `shown` (its `./`,
/// if it added one, kept: the same file): for a SARIF URI of a name that
/// is not UTF-8.
///
/// NOTE: exact, because `display_path` shows a name holding `\xNN` text
/// (NN ≥ 80) with its backslashes doubled: a shown text without such a
/// sequence is a UTF-8 name as it is, one with it is read as escaped.
pub fn path_bytes(shown: &str) -> Vec<u8> {
    if !has_byte_escape(shown) {
        return shown.as_bytes().to_vec();
    }
    let mut out = Vec::with_capacity(shown.len());
    let mut rest = shown;
    while let Some(c) = rest.chars().next() {
        if let Some(b) = byte_escape(rest) {
            out.push(b);
            rest = &rest[4..];
        } else if let Some(after) = rest.strip_prefix("\\\\") {
            out.push(b'\\');
            rest = after;
        } else {
            let mut buf = [0; 4];
            out.extend_from_slice(c.encode_utf8(&mut buf).as_bytes());
            rest = &rest[c.len_utf8()..];
        }
    }
    out
}

/// A place's path as a line begins with it: `display_path`'s `./` rule
/// again, for a place named otherwise (every file's name comes from
/// `display_path` already, so this changes none of them), but for
/// massprop's own names (`<stdin>`, and flags: `--set NAME`, `--axes`).
pub(super) fn line_start(path: &str) -> Cow<'_, str> {
    if begins_safely(path) || path == "<stdin>" || path.starts_with("--") {
        path.into()
    } else {
        format!("./{path}").into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::visible;

    #[cfg(unix)]
    fn unix(bytes: &[u8]) -> &Path {
        use std::os::unix::ffi::OsStrExt;
        Path::new(std::ffi::OsStr::from_bytes(bytes))
    }

    #[cfg(unix)]
    #[test]
    fn a_path_shows_bytes_that_are_not_utf8_as_hex() {
        let path = unix(b"d\xe9/\xff\xfeb\x1b\xc3\xa9.toml");
        // The escape character is text, shown by `visible` where printed.
        assert_eq!(display_path(path), "d\\xe9/\\xff\\xfeb\u{1b}\u{e9}.toml");
        assert_eq!(
            visible(&display_path(path)),
            "d\\xe9/\\xff\\xfeb\u{241b}\u{e9}.toml"
        );
        assert_eq!(display_path(Path::new("plain/a b.toml")), "plain/a b.toml");
    }

    #[test]
    fn a_path_that_would_begin_a_line_with_its_own_text_gets_dot_slash() {
        for (path, shown) in [
            ("::error::x.toml", "./::error::x.toml"),
            (" ::warning::x", "./ ::warning::x"),
            ("\n::add-mask::x", "./\n::add-mask::x"),
            ("-x.toml", "./-x.toml"),
            ("é.toml", "./é.toml"),
            ("a.toml", "a.toml"),
            ("./::x.toml", "./::x.toml"),
            ("/abs/::x", "/abs/::x"),
            ("_a", "_a"),
            ("~/a", "~/a"),
            ("", ""),
        ] {
            assert_eq!(display_path(Path::new(path)), shown, "{path:?}");
        }
    }

    #[test]
    fn a_place_begins_a_line_as_a_path_would_but_for_massprops_own_names() {
        assert_eq!(line_start("::x"), "./::x");
        assert_eq!(line_start("a.toml"), "a.toml");
        assert_eq!(line_start("<stdin>"), "<stdin>");
        assert_eq!(line_start("--set m"), "--set m");
        assert_eq!(line_start("<x"), "./<x");
    }

    #[cfg(unix)]
    #[test]
    fn every_shown_path_reads_back_to_its_bytes() {
        for bytes in [
            &b"d\xe9/\xff\xfeb\x1b\xc3\xa9.toml"[..],
            b"plain/a b.toml",
            b"literal\\xff.toml",
            b"both\\xff\xff.toml",
            b"back\\\\slash\xe9",
            b"\\\xab",
            b"\\xab",
            b"\\x41\x80",
            b"::\xff",
            "é\\x9f".as_bytes(),
        ] {
            let shown = display_path(unix(bytes));
            let back = path_bytes(&shown);
            let back = back
                .strip_prefix(b"./")
                .filter(|_| !bytes.starts_with(b"./"));
            let back = back.map_or(path_bytes(&shown), <[u8]>::to_vec);
            assert_eq!(back, bytes, "{shown:?}");
        }
    }

    #[cfg(unix)]
    #[test]
    fn names_that_differ_are_shown_differently() {
        // The pairs the plain `\xNN` rule alone would confuse.
        let pairs: [(&[u8], &[u8]); 3] = [
            (b"\\xff", b"\xff"),
            (b"\\\xab", b"\\xab"),
            (b"a\\\\xff", b"a\\\xff"),
        ];
        for (a, b) in pairs {
            assert_ne!(display_path(unix(a)), display_path(unix(b)), "{a:?} {b:?}");
        }
    }
}
