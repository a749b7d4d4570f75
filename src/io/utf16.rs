//! A part file in UTF-16, told apart from UTF-8 before it is read
//! (`io::source_of`): what it is and how to convert it.

use crate::diag::Diagnostic;

/// A file in UTF-16 (as Windows editors and PowerShell's `>` write text),
/// found before it is read as UTF-8: with its byte-order mark it is
/// invalid UTF-8 at the first byte, and without one it is valid UTF-8
/// with a NUL in every other byte; either way it says what it is and how
/// to convert it, not a line of ␀. NOTE: no TOML text has a NUL, so a
/// file that looks UTF-16 is never a part file misjudged.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Utf16 {
    /// Little- (`true`) or big-endian, with a byte-order mark or not.
    Marked(bool),
    Unmarked(bool),
}

impl Utf16 {
    /// The encoding of `bytes` if it is UTF-16: a byte-order mark
    /// (`FF FE`, `FE FF`), or in three of four of its first 256 byte pairs
    /// one byte NUL and the other not (ASCII text in UTF-16).
    pub(super) fn of(bytes: &[u8]) -> Option<Utf16> {
        match bytes {
            [0xff, 0xfe, ..] => return Some(Utf16::Marked(true)),
            [0xfe, 0xff, ..] => return Some(Utf16::Marked(false)),
            _ => {}
        }
        let pairs: Vec<&[u8]> = bytes.chunks_exact(2).take(256).collect();
        // Little-endian ASCII: the second byte of each pair NUL.
        let count = |le: bool| {
            let (zero, other) = if le { (1, 0) } else { (0, 1) };
            pairs
                .iter()
                .filter(|p| p[zero] == 0 && p[other] != 0)
                .count()
        };
        let most = |n: usize| !pairs.is_empty() && 4 * n >= 3 * pairs.len();
        if most(count(true)) {
            Some(Utf16::Unmarked(true))
        } else if most(count(false)) {
            Some(Utf16::Unmarked(false))
        } else {
            None
        }
    }

    /// Whether it is little-endian.
    fn le(self) -> bool {
        match self {
            Utf16::Marked(le) | Utf16::Unmarked(le) => le,
        }
    }

    /// The characters of `bytes` in this encoding, without a byte-order
    /// mark, a bad unit as U+FFFD.
    fn chars(self, bytes: &[u8]) -> impl Iterator<Item = char> + '_ {
        let le = self.le();
        let units = bytes.chunks_exact(2).map(move |p| {
            let pair = [p[0], p[1]];
            if le {
                u16::from_le_bytes(pair)
            } else {
                u16::from_be_bytes(pair)
            }
        });
        char::decode_utf16(units)
            .map(|c| c.unwrap_or(char::REPLACEMENT_CHARACTER))
            .skip_while(|c| *c == '\u{feff}')
    }

    /// `bytes` decoded (`chars`).
    pub(super) fn decoded(self, bytes: &[u8]) -> String {
        self.chars(bytes).collect()
    }

    /// The error for file `name` of `bytes`: what it is, and how to
    /// convert it, at its first character, the first line shown decoded.
    pub(super) fn error(self, name: &str, bytes: &[u8]) -> Diagnostic {
        let (le, mark, from) = match self {
            Utf16::Marked(le) => (le, "with a byte-order mark", "UTF-16"),
            Utf16::Unmarked(true) => (true, "without a byte-order mark", "UTF-16LE"),
            Utf16::Unmarked(false) => (false, "without a byte-order mark", "UTF-16BE"),
        };
        let endian = if le { "little-endian" } else { "big-endian" };
        // NOTE: only the first line is shown; it is decoded (a bad unit
        // as U+FFFD), so the snippet reads as the file does in an editor.
        let first_line: String = self
            .chars(bytes)
            .take_while(|c| *c != '\n')
            .take(200)
            .collect();
        let source = crate::diag::Source::new(name, first_line);
        let first = source.text.chars().next().map_or(0, char::len_utf8);
        source
            .error(
                0..first.max(1),
                format!("the file is UTF-16 ({endian}, {mark}), not UTF-8"),
            )
            .help(format!(
                "massprop reads UTF-8 text: convert it with `iconv -f {from} -t UTF-8 OLD > NEW`, or save it as UTF-8 in the editor"
            ))
    }
}

#[cfg(test)]
mod tests {
    use crate::io::source_of;

    /// `text` in UTF-16, little- or big-endian, with a byte-order mark or
    /// not.
    fn utf16(text: &str, le: bool, bom: bool) -> Vec<u8> {
        let units = bom.then_some(0xfeff).into_iter().chain(text.encode_utf16());
        units
            .flat_map(|u| if le { u.to_le_bytes() } else { u.to_be_bytes() })
            .collect()
    }

    #[test]
    fn a_utf16_file_with_a_byte_order_mark_says_so() {
        for (le, endian) in [(true, "little"), (false, "big")] {
            let d = source_of("a.toml", utf16("[[part]]\n", le, true)).unwrap_err();
            assert_eq!(
                d.message(),
                format!("the file is UTF-16 ({endian}-endian, with a byte-order mark), not UTF-8")
            );
            assert!(d.help_text().unwrap().contains("iconv -f UTF-16 -t UTF-8"));
        }
    }

    #[test]
    fn a_utf16_file_without_a_byte_order_mark_says_so_and_in_which_order() {
        let d = source_of("a.toml", utf16("[[part]]\nshape = \"box\"\n", true, false)).unwrap_err();
        assert_eq!(
            d.message(),
            "the file is UTF-16 (little-endian, without a byte-order mark), not UTF-8"
        );
        assert!(
            d.help_text()
                .unwrap()
                .contains("iconv -f UTF-16LE -t UTF-8")
        );
        let d = source_of("a.toml", utf16("x = 1\n", false, false)).unwrap_err();
        assert!(
            d.message().contains("(big-endian, without"),
            "{}",
            d.message()
        );
    }

    #[test]
    fn a_utf16_file_is_decoded_for_a_search_to_judge() {
        for (le, bom) in [(true, true), (false, true), (true, false)] {
            let text = "[registry]\ntoken = \"x\"\n";
            let bytes = utf16(text, le, bom);
            let u = super::Utf16::of(&bytes).expect("utf-16");
            assert_eq!(u.decoded(&bytes), text);
        }
    }

    #[test]
    fn utf8_text_is_not_taken_for_utf16() {
        for text in ["[[part]]\n", "a", "", "\u{e9} = \"\u{fc}\"\n"] {
            assert!(
                source_of("a.toml", text.as_bytes().to_vec()).is_ok(),
                "{text}"
            );
        }
    }
}
