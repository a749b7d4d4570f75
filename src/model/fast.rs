//! A fast path from a part file's text to `RawFile`, straight from the toml
//! crate's own lexer and event parser (`toml_parser`), with no value tree
//! in between.
//!
//! NOTE: `toml::from_str` parses the whole document into a generic tree
//! (`toml::de::DeTable`: every key, value and span as a node, ~22 bytes of
//! memory per input byte with the lexer's tokens and the parser's events)
//! and only then deserializes `RawFile` from it. Here the parser's events
//! fill `RawFile` as they come: only the result, and the tokens of a chunk
//! of whole tables (`CHUNK`), are ever in memory. It covers what part files are made of (top-level `name` and
//! `units`, `[[part]]` tables, `[analysis]`, inline tables and arrays of
//! strings and numbers; `[expect]` and `[materials]` it passes over for
//! serde to read alone, `Section`) and gives up — `None` — on anything else
//! (dotted keys, other tables, booleans, dates), on any syntax error, any
//! duplicate or unknown key and any value of the wrong type. The caller then
//! takes the serde path, which accepts or rejects the file and words every
//! error as before. When `read_file` returns `Some`, the result equals
//! what `toml::from_str::<RawFile>` gives, values and spans alike (tested
//! in `tests`).
//!
//! NOTE: the builder fills `RawPart` itself, the serde mirror's own struct,
//! so the two readers share one definition of a part's keys and types. A
//! key that `Builder::assign` does not take only sends the files that use
//! it down the serde path; the
//! property test (tests/integration/hostile.rs) and the fuzz target assert
//! that wherever this returns `Some`, serde gives the same `RawFile`.

pub use super::raw::Section;
use super::raw::{RawAnalysis, RawFile, RawPart, RawUnits};
use values::{Node, own_value, set, set_from, string, units_key, vector};

mod values;
use std::borrow::Cow;
use std::ops::Range;
use toml::Spanned;
use toml_parser::decoder::{Encoding, ScalarKind};
use toml_parser::lexer::{Token, TokenKind};
use toml_parser::parser::{EventReceiver, RecursionGuard, ValidateWhitespace};
use toml_parser::{ErrorSink, ParseError, Raw, Source, Span};

/// The toml crate's own nesting limit (`toml::de::parser::LIMIT`).
const RECURSION_LIMIT: u32 = 80;

/// `RawFile` from `text`, or `None` where the serde path must decide;
/// its `[expect]` and `[materials]` still to be read from its `sections`
/// (`read_file` does).
pub fn parse(text: &str) -> Option<RawFile> {
    parse_in_chunks(text, CHUNK)
}

/// The file as the model reads it on the fast path: `parse`, with its
/// `[expect]` and `[materials]` read by serde (`Section::read`). Where this
/// returns `Some`, `toml::from_str::<RawFile>` gives the same, values and
/// spans alike (tested here, by the property test and by the fuzz target).
pub fn read_file(text: &str) -> Option<RawFile> {
    let mut raw = parse(text)?;
    let sections = Section::read(text, &raw.sections)?;
    raw.expect = sections.expect;
    raw.materials = sections.materials;
    raw.sections.clear();
    Some(raw)
}

/// Where each `[[part]]` goes as soon as it is read, with the file's
/// `units` and the `Section`s read so far.
pub type PartSink<'a> = dyn FnMut(Option<&Spanned<RawUnits>>, &[Section], Spanned<RawPart>) + 'a;

/// `parse`, handing each part to `sink` as soon as it is read (after each
/// chunk) rather than keeping it: the `RawFile` returned has an empty
/// `part` list (its span kept). `None` where the serde path must decide,
/// also after some parts were handed out.
///
/// NOTE: a raw part takes ~370 bytes and its vectors ~160 more, 4–5 times
/// the text it is read from: kept for a whole file of a million parts, the
/// raw parts alone were over the memory budget (3 × the input + 64 MiB).
pub fn parse_streaming(
    text: &str,
    chunk_tokens: usize,
    sink: &mut PartSink<'_>,
) -> Option<RawFile> {
    read(text, chunk_tokens, Some(sink))
}

/// `parse`, lexing and parsing `chunk_tokens` tokens at a time (at least:
/// a chunk ends before a line that starts with `[`). Public for the
/// property test and the fuzz target, which read their files in small
/// chunks too.
pub fn parse_in_chunks(text: &str, chunk_tokens: usize) -> Option<RawFile> {
    read(text, chunk_tokens, None)
}

/// `parse_in_chunks`, the parts read handed to `sink` after each chunk if
/// there is one.
fn read(text: &str, chunk_tokens: usize, mut sink: Option<&mut PartSink<'_>>) -> Option<RawFile> {
    let source = Source::new(text);
    let mut builder = Builder::new(source);
    builder.streaming = sink.is_some();
    let mut error = Failed(false);
    // NOTE: lexed and parsed a chunk of whole tables at a time, not the
    // whole file: the lexer's tokens take 14 bytes of memory per byte of
    // input, more than the rest of reading a file together. A chunk ends
    // before a `[` that opens a line outside any array or inline table
    // (strings and comments are single tokens, so counting brackets is
    // exact), once it holds `CHUNK` tokens, and is closed with an
    // end-of-file token: that `[` opens a table header, so each chunk is a
    // document of whole tables and the parser's events are those of the
    // whole file. Should a chunk ever end inside a value, the parser or the
    // builder (a value still open, `finish`, or the next header) fails,
    // and the serde path decides, as for any file this declines.
    let mut lexer = source.lex();
    let eof = Source::new("")
        .lex()
        .next()
        .expect("invariant: the lexer ends every input with an end-of-file token");
    let mut chunk: Vec<Token> = Vec::with_capacity(chunk_tokens.min(CHUNK) + 1);
    let mut line_start = true;
    // Arrays and inline tables open at this point.
    let mut depth = 0usize;
    loop {
        let token = lexer.next();
        let end = match &token {
            None => true,
            Some(t) => {
                chunk.len() >= chunk_tokens
                    && line_start
                    && depth == 0
                    && t.kind() == TokenKind::LeftSquareBracket
            }
        };
        if end && !chunk.is_empty() {
            if chunk.last().is_some_and(|t| t.kind() != TokenKind::Eof) {
                chunk.push(eof);
            }
            let mut ws = ValidateWhitespace::new(&mut builder, source);
            let mut guarded = RecursionGuard::new(&mut ws, RECURSION_LIMIT);
            toml_parser::parser::parse_document(&chunk, &mut guarded, &mut error);
            chunk.clear();
            if error.0 || builder.failed {
                return None;
            }
            if token.is_none() {
                // The last part is complete.
                builder.close_part();
            }
            if let Some(sink) = sink.as_mut() {
                builder.hand_out(&mut **sink);
            }
        }
        let Some(t) = token else { break };
        match t.kind() {
            TokenKind::LeftSquareBracket | TokenKind::LeftCurlyBracket => depth += 1,
            TokenKind::RightSquareBracket | TokenKind::RightCurlyBracket => {
                depth = depth.saturating_sub(1);
            }
            _ => {}
        }
        line_start = t.kind() == TokenKind::Newline;
        chunk.push(t);
    }
    builder.finish()
}

/// Tokens lexed and parsed at a time (24 bytes each): a few thousand
/// parts.
pub const CHUNK: usize = 1 << 16;

/// Records that the parser reported an error.
struct Failed(bool);

impl ErrorSink for Failed {
    fn report_error(&mut self, _error: ParseError) {
        self.0 = true;
    }
}

/// An array or inline table still open.
enum Frame<'i> {
    Array(usize, Vec<Node<'i>>),
    Table(usize, Vec<(Cow<'i, str>, Node<'i>)>, Option<Cow<'i, str>>),
}

/// Which table key/value pairs go to.
#[derive(Clone, Copy, PartialEq)]
enum Current {
    Root,
    Units,
    Part,
    Analysis,
    /// `[expect]` or `[materials]` (or a table under them): read by serde
    /// alone (`Section`), its keys and values passed over here.
    Skipped,
}

struct Builder<'i> {
    source: Source<'i>,
    failed: bool,
    current: Current,
    /// Inside `[..]` or `[[..]]`: where it opened, whether an array table,
    /// and its keys.
    header: Option<(usize, bool, Vec<Cow<'i, str>>)>,
    /// The key of the key/value pair being read (document level).
    key: Option<Cow<'i, str>>,
    stack: Vec<Frame<'i>>,
    name: Option<Spanned<String>>,
    units: Option<Spanned<RawUnits>>,
    parts: Option<(Range<usize>, Vec<Spanned<RawPart>>)>,
    part: Option<(Range<usize>, RawPart)>,
    analysis: Option<Spanned<RawAnalysis>>,
    /// Parts are handed out as read (`parse_streaming`), not kept.
    streaming: bool,
    /// The `[expect]` and `[materials]` tables met, the last one's end
    /// `usize::MAX` while it is read.
    sections: Vec<Section>,
}

impl<'i> Builder<'i> {
    fn new(source: Source<'i>) -> Self {
        Builder {
            source,
            failed: false,
            current: Current::Root,
            header: None,
            key: None,
            stack: Vec::new(),
            name: None,
            units: None,
            parts: None,
            part: None,
            analysis: None,
            streaming: false,
            sections: Vec::new(),
        }
    }

    fn fail(&mut self) {
        self.failed = true;
    }

    fn raw(&self, span: Span, kind: Option<Encoding>) -> Raw<'i> {
        let text = &self.source.input()[span.start()..span.end()];
        Raw::new_unchecked(text, kind, span)
    }

    /// Hand the parts read so far to `sink`.
    fn hand_out(&mut self, sink: &mut PartSink<'_>) {
        let closed = match self.sections.last() {
            Some(s) if s.span.end == usize::MAX => self.sections.len() - 1,
            _ => self.sections.len(),
        };
        if let Some((_, parts)) = &mut self.parts {
            for p in parts.drain(..) {
                sink(self.units.as_ref(), &self.sections[..closed], p);
            }
        }
    }

    /// Inside `[expect]` or `[materials]`, past its header.
    fn skipping(&self) -> bool {
        self.current == Current::Skipped && self.header.is_none()
    }

    fn finish(mut self) -> Option<RawFile> {
        self.close_part();
        if let Some(last) = self.sections.last_mut()
            && last.span.end == usize::MAX
        {
            last.span.end = self.source.input().len();
        }
        if self.failed || self.header.is_some() || !self.stack.is_empty() || self.key.is_some() {
            return None;
        }
        Some(RawFile {
            name: self.name,
            units: self.units,
            part: self.parts.map(|(span, v)| Spanned::new(span, v)),
            analysis: self.analysis,
            expect: None,
            // Serde's, from the sections.
            materials: None,
            // A file with `[params]` or a part's `params` is declined
            // (`open_table`, `assign`): serde reads it.
            params: None,
            // A file with `[growth]` or `[budget]` is declined
            // (`open_table`): serde reads it.
            growth: None,
            budget: None,
            sections: self.sections,
        })
    }

    /// The `[[part]]` being read is complete.
    fn close_part(&mut self) {
        let Some((span, p)) = self.part.take() else {
            return;
        };
        // A part with neither a shape nor an include is an error: serde's.
        if p.shape.is_none() && p.include.is_none() {
            return self.fail();
        }
        match &mut self.parts {
            Some((_, v)) => v.push(Spanned::new(span, p)),
            None => self.fail(),
        }
    }

    /// A table header `[path]` or `[[path]]` from `span`.
    fn open_table(&mut self, span: Range<usize>, is_array: bool, path: Vec<Cow<'i, str>>) {
        self.close_part();
        if let Some(last) = self.sections.last_mut()
            && last.span.end == usize::MAX
        {
            last.span.end = span.start;
        }
        match (is_array, path.as_slice()) {
            (false, [k, ..]) if k == "expect" || k == "materials" => {
                self.sections.push(Section {
                    span: span.start..usize::MAX,
                    materials: k == "materials",
                });
                self.current = Current::Skipped;
            }
            (true, [k]) if k == "part" => {
                if self.parts.is_none() {
                    // Made at the size the file's `[[part]]` lines say (a
                    // list doubled up to 100,000 parts of 368 bytes held 48
                    // MB for 37), unless they are handed out as read.
                    let tables = if self.streaming {
                        0
                    } else {
                        super::part_tables(self.source.input()) as usize
                    };
                    self.parts = Some((span.clone(), Vec::with_capacity(tables)));
                }
                self.part = Some((span, RawPart::default()));
                self.current = Current::Part;
            }
            (false, [k]) if k == "analysis" && self.analysis.is_none() => {
                self.analysis = Some(Spanned::new(span, RawAnalysis::default()));
                self.current = Current::Analysis;
            }
            (false, [k]) if k == "units" && self.units.is_none() => {
                self.units = Some(Spanned::new(span, RawUnits::default()));
                self.current = Current::Units;
            }
            _ => self.fail(),
        }
    }

    /// A complete value: into the open array or inline table, or to the
    /// current key.
    fn value(&mut self, node: Node<'i>) {
        match self.stack.last_mut() {
            Some(Frame::Array(_, items)) => items.push(node),
            Some(Frame::Table(_, entries, key)) => match key.take() {
                Some(k) if !entries.iter().any(|(e, _)| *e == k) => entries.push((k, node)),
                _ => self.fail(),
            },
            None => match self.key.take() {
                Some(k) => {
                    if self.assign(&k, node).is_none() {
                        self.fail();
                    }
                }
                None => self.fail(),
            },
        }
    }

    /// `key = node` in the current table; `None` if the key is unknown,
    /// repeated, or the value of the wrong type.
    fn assign(&mut self, key: &str, node: Node<'i>) -> Option<()> {
        match self.current {
            // Not reached: nothing is assigned while skipping.
            Current::Skipped => Some(()),
            Current::Root => match key {
                "name" => set(&mut self.name, string(node)?),
                "units" => {
                    let span = node.span();
                    let Node::Table(entries, _) = node else {
                        return None;
                    };
                    let mut u = RawUnits::default();
                    for (k, v) in entries {
                        units_key(&mut u, &k, v)?;
                    }
                    set(&mut self.units, Spanned::new(span, u))
                }
                _ => None,
            },
            Current::Units => {
                let u = self.units.as_mut()?.get_mut();
                units_key(u, key, node)
            }
            Current::Analysis => {
                let a = self.analysis.as_mut()?.get_mut();
                match key {
                    "about" => set(&mut a.about, vector(node)?),
                    "omega" => set(&mut a.omega, vector(node)?),
                    "alpha" => set(&mut a.alpha, vector(node)?),
                    _ => None,
                }
            }
            Current::Part => assign_part(&mut self.part.as_mut()?.1, key, node),
        }
    }
}

/// The reader's assignment of each part key, from its declaration
/// (`keys::part_keys!`): `key = node` into its `RawPart` field, read as
/// the field's type reads it (`FromNode`); else a shape's own key, read
/// by its declared kind. `None` if the key is unknown, repeated, or the
/// value of the wrong type.
macro_rules! assigner {
    ($($name:ident: $kind:expr, $dim:expr, $tol:literal, $scope:ident, $doc:literal;)+) => {
        fn assign_part(p: &mut RawPart, key: &str, node: Node<'_>) -> Option<()> {
            match key {
                $(stringify!($name) => set_from(&mut p.$name, node),)+
                _ => {
                    let declared = crate::shapes::own_key(key)?;
                    let value = own_value(declared.kind, node)?;
                    let own = p.own.get_or_insert_with(Default::default);
                    if own.iter().any(|(k, _)| *k == declared.name) {
                        return None;
                    }
                    own.push((declared.name, value));
                    Some(())
                }
            }
        }
    };
}
super::keys::part_keys!(assigner);

impl<'i> EventReceiver for Builder<'i> {
    fn std_table_open(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        if self.header.is_some() || self.key.is_some() || !self.stack.is_empty() {
            return self.fail();
        }
        self.header = Some((span.start(), false, Vec::new()));
    }

    fn std_table_close(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        match self.header.take() {
            Some((start, false, path)) => self.open_table(start..span.end(), false, path),
            _ => self.fail(),
        }
    }

    fn array_table_open(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        if self.header.is_some() || self.key.is_some() || !self.stack.is_empty() {
            return self.fail();
        }
        self.header = Some((span.start(), true, Vec::new()));
    }

    fn array_table_close(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        match self.header.take() {
            Some((start, true, path)) => self.open_table(start..span.end(), true, path),
            _ => self.fail(),
        }
    }

    fn inline_table_open(&mut self, span: Span, _error: &mut dyn ErrorSink) -> bool {
        if self.skipping() {
            return true;
        }
        self.stack
            .push(Frame::Table(span.start(), Vec::new(), None));
        true
    }

    fn inline_table_close(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        if self.skipping() {
            return;
        }
        match self.stack.pop() {
            Some(Frame::Table(start, entries, None)) => {
                self.value(Node::Table(entries, start..span.end()))
            }
            _ => self.fail(),
        }
    }

    fn array_open(&mut self, span: Span, _error: &mut dyn ErrorSink) -> bool {
        if self.skipping() {
            return true;
        }
        self.stack.push(Frame::Array(span.start(), Vec::new()));
        true
    }

    fn array_close(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        if self.skipping() {
            return;
        }
        match self.stack.pop() {
            Some(Frame::Array(start, items)) => self.value(Node::Array(items, start..span.end())),
            _ => self.fail(),
        }
    }

    fn simple_key(&mut self, span: Span, kind: Option<Encoding>, error: &mut dyn ErrorSink) {
        if self.skipping() {
            return;
        }
        let mut key = Cow::Borrowed("");
        self.raw(span, kind).decode_key(&mut key, error);
        if let Some((_, _, path)) = &mut self.header {
            path.push(key);
            return;
        }
        let slot = match self.stack.last_mut() {
            Some(Frame::Table(_, _, k)) => k,
            Some(Frame::Array(..)) => return self.fail(),
            None => &mut self.key,
        };
        // A second key before a value: a dotted key.
        match slot {
            Some(_) => self.fail(),
            None => *slot = Some(key),
        }
    }

    fn key_sep(&mut self, _span: Span, _error: &mut dyn ErrorSink) {
        // Dotted keys outside headers: left to the serde path.
        if self.header.is_none() && !self.skipping() {
            self.fail();
        }
    }

    fn scalar(&mut self, span: Span, kind: Option<Encoding>, error: &mut dyn ErrorSink) {
        if self.skipping() {
            return;
        }
        let mut text = Cow::Borrowed("");
        let range = span.start()..span.end();
        let node = match self.raw(span, kind).decode_scalar(&mut text, error) {
            ScalarKind::String => Node::Str(text, range),
            // As `toml::de::DeFloat::to_f64`: an overflow to infinity is an
            // error, an explicit `inf` is not.
            ScalarKind::Float => match text.parse::<f64>() {
                Ok(x) if !x.is_infinite() || text.contains("inf") => Node::Num(x, range),
                _ => return self.fail(),
            },
            // As the toml deserializer: i64 if it fits, else u64; either
            // becomes f64 in every field that takes a number.
            ScalarKind::Integer(radix) => {
                let r = radix.value();
                if let Ok(i) = i64::from_str_radix(&text, r) {
                    Node::Num(i as f64, range)
                } else if let Ok(u) = u64::from_str_radix(&text, r) {
                    Node::Num(u as f64, range)
                } else {
                    return self.fail();
                }
            }
            ScalarKind::Boolean(b) => Node::Bool(b, range),
            ScalarKind::DateTime => return self.fail(),
        };
        self.value(node);
    }

    fn error(&mut self, _span: Span, _error: &mut dyn ErrorSink) {
        self.fail();
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// The fast path gives what serde gives, spans included; and so does it
    /// read in chunks of any size, or it declines.
    pub(in crate::model) fn same(text: &str) {
        let fast = read_file(text).unwrap_or_else(|| panic!("fast path declined:\n{text}"));
        let serde: RawFile = toml::from_str(text).unwrap();
        assert_eq!(format!("{fast:?}"), format!("{serde:?}"), "{text}");
        assert_eq!(in_chunks_the_same_or_declined(text), 0, "{text}");
    }

    /// Read in chunks of 1 to 40 tokens: the same `RawFile` as read whole,
    /// or declined (should a chunk end inside a value); never another.
    /// Returns how many chunk sizes declined (the callers require none).
    fn in_chunks_the_same_or_declined(text: &str) -> usize {
        let whole = format!(
            "{:?}",
            parse_in_chunks(text, usize::MAX).expect("read whole")
        );
        let mut declined = 0;
        for n in 1..=40 {
            match parse_in_chunks(text, n) {
                Some(raw) => assert_eq!(format!("{raw:?}"), whole, "chunks of {n}:\n{text}"),
                None => declined += 1,
            }
        }
        declined
    }

    #[test]
    fn a_file_read_in_chunks_of_whole_tables_reads_as_whole() {
        let part = |i: usize| {
            format!(
                "[[part]]\nname = \"p{i}\"\nshape = \"box\"\nmass = {i}\nsize = [1, 2, 3]\ncenter = [{i}, 0, 0]\n"
            )
        };
        let many: String = (1..=30).map(part).collect();
        same(&format!(
            "name = \"n\"\nunits = {{ length = \"mm\" }}\n{many}[analysis]\nomega = [0, 0, 1]\n{}",
            part(31)
        ));
        // Whole tables in every chunk: never declined.
        assert_eq!(in_chunks_the_same_or_declined(&many), 0);
    }

    #[test]
    fn a_line_of_an_array_that_starts_with_a_bracket_does_not_end_a_chunk() {
        // Lines of arrays that start with `[`, as a table header does.
        let text = "[[part]]\nshape = \"plate\"\nmass = 1\ncorner = [0, 0, 0]\nedges = [\n[0, 125, 0],\n[0, 0, 100]]\n\
                    [[part]]\nshape = \"box\"\nmass = 1\ncenter = [\n0, 0, 0]\nsize = [\n1,\n2, 3]\n\
                    rotation = { matrix = [\n[1, 0, 0],\n[0, 1, 0],\n[0, 0, 1]] }\n";
        same(text);
        // `[1][0]` is no TOML value: declined however it is read.
        let bad =
            "[[part]]\nshape = \"rod\"\nmass = 1\nfrom = [\n0, 0, 0]\nto = [\n[1][0], 0, 0]\n";
        assert!(toml::from_str::<RawFile>(bad).is_err());
        for n in [1, 2, 3, 5, usize::MAX] {
            assert!(parse_in_chunks(bad, n).is_none(), "chunks of {n}");
        }
    }

    /// The fast path leaves the file to serde.
    pub(in crate::model) fn declines(text: &str) {
        assert!(read_file(text).is_none(), "fast path accepted:\n{text}");
    }

    #[test]
    fn part_files_read_as_serde_reads_them() {
        same(
            "# comment\nname = \"bent plate\"  # trailing\nunits = { length = \"mm\", mass = \"kg\" }\n\n\
             [[part]]\nname = \"A\"\nshape = \"plate\"\nareal_density = \"70 kg/m^2\"\n\
             corner = [0, 0, 0]\nedges = [[0, 125, 0], [0, 0, 100]]\n\n\
             [[ part ]]\n'name' = \"B \\u00e9\\n\"\nshape = 'box'\nmass = 1_000.5\nsize = [0x10, 0o7, 0b1]\n\
             center = [ -0.0, +1e-3, \"5 mm\" , ]\nrotation = { quaternion = [1, 0, 0, 0] }\n\n\
             [analysis]\nabout = [0, 0, 0]\nomega = [0, 0, \"30 rpm\"]\nalpha = [0, 0, 2]\n",
        );
        same(
            "[units]\nlength = \"in\"\n[[part]]\nshape = \"rod\"\nlinear_density = 2\nlength = 3\n\
             center = [1, 2, 3]\nrotation = { axis = [0, 1, 0], degrees = 90.0 }\n\
             [[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\n\
             rotation = { intrinsic = \"zyx\", degrees = [10, 20, 30] }\n\
             [[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\n\
             rotation = { matrix = [[1, 0, 0], [0, 1, 0], [0, 0, 1]] }\n\
             [[part]]\nshape = \"rod\"\nmass = 1\nfrom = [0, 0, 0]\nto = [1, 1, 1]\ndiameter = 0.1\n\
             [[part]]\nshape = \"plate\"\nmass = 1\nsize = [1, 2]\ncenter = [0, 0, 0]\nthickness = \"2 mm\"\n",
        );
        same(
            "[[part]]\nshape = \"cylinder\"\ndensity = \"7850 kg/m^3\"\nradius = 0.25\n\
             inner_radius = \"210 mm\"\nlength = 0.06\ncenter = [0, 0, 0]\n\
             [[part]]\nshape = \"sphere\"\nmass = 1\nradius = 2\ncenter = [1, 0, 0]\n",
        );
        // Values the model rejects are still read: the same errors follow.
        same("[[part]]\nshape = \"sphere\"\nmass = nan\ncenter = [inf, -inf, 1e300]\nsize = []\n");
        same("[[part]]\r\nshape = \"point\"\r\nmass = -1\r\ncenter = [1, 2]\r\n");
        same("name = \"no parts\"\n");
        same("");
    }

    /// Cut-outs, materials, triangles, given tensors and includes: on the
    /// fast path.
    #[test]
    fn every_key_of_a_shape_reads_as_serde_reads_it() {
        same(
            "[[part]]\nshape = \"box\"\nmaterial = \"steel\"\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\nremove = true\n\
             [[part]]\nshape = \"triangle\"\nareal_density = 2\nvertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\nremove = false\n\
             [[part]]\nshape = \"inertia\"\nmass = 2\ncenter = [1, 2, 3]\ninertia = [[1, 0, 0], [0, 2, 0], [0, 0, 3]]\nproducts = \"positive\"\n\
             [[part]]\nshape = \"plate\"\nmass = 1\narea = 2\ncenter = [0, 0, 0]\n\
             [[part]]\nshape = \"cone\"\ndensity = 2\ndiameter = 2\ninner_diameter = \"1 mm\"\ntop_radius = 0.5\ntop_inner_radius = 0.25\nlength = 3\ncenter = [0, 0, 0]\n\
             [[part]]\nshape = \"torus\"\nmass = 2\nradius = 2\ntube_radius = 1\ninner_tube_radius = 0.5\ncenter = [0, 0, 0]\n\
             [[part]]\nshape = \"prism\"\nmass = 2\npolygon = [[0, 0], [1, 0], [\"1 mm\", 1]]\nlength = 3\norigin = [1, 2, 3]\n\
             [[part]]\nname = \"arm\"\ninclude = \"arm.toml\"\norigin = [1, 2, \"3 mm\"]\nrotation = { axis = [0, 0, 1], degrees = 90 }\n\
             [[part]]\nshape = \"mesh\"\nfile = \"b.stl\"\nmesh_unit = \"mm\"\nmode = \"shell\"\nthickness = 2\ndensity = 3\norigin = [1, 2, 3]\n",
        );
        declines("[[part]]\nshape = \"box\"\nremove = 1\n");
        declines("[[part]]\nshape = \"box\"\nname = true\n");
    }

    /// `streamed` makes parts with an empty `[growth]` table: a file that
    /// has one, or a `[budget]`, must never reach it.
    #[test]
    fn a_file_with_a_weight_statement_is_left_to_serde() {
        let part =
            "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\nmaturity = \"estimated\"\n";
        // The tag keys alone are the fast path's.
        same(&format!("{part}group = \"a/b\"\n"));
        for table in ["[growth]\nestimated = \"15 %\"\n", "[budget]\nlimit = 10\n"] {
            declines(&format!("{table}{part}"));
            declines(&format!("{part}{table}"));
        }
    }

    #[test]
    fn anything_else_is_left_to_serde() {
        // Not covered: dotted keys, inline `part`, other tables.
        declines("units.length = \"mm\"\n");
        declines("part = [{ shape = \"point\", mass = 1, center = [0, 0, 0] }]\n");
        declines("[[part]]\nshape = \"box\"\n[part.rotation]\naxis = [0, 0, 1]\ndegrees = 90\n");
        // Errors: syntax, duplicates, unknown keys, wrong types, missing shape.
        declines("[[part]\nshape = \"point\"\n");
        declines("[[part]]\nshape = \"point\"\nshape = \"box\"\n");
        declines("[[part]]\nshape = \"point\"\nmasss = 1\n");
        declines("[[part]]\nshape = \"point\"\nmass = [1]\n");
        declines("[[part]]\nshape = \"point\"\nmass = true\n");
        declines("[[part]]\nmass = 1\n");
        declines("[[part]]\nshape = \"box\"\nrotation = { axis = [0, 0, 1], axis = [1, 0, 0] }\n");
        declines("[analysis]\n[analysis]\n");
        declines("units = { length = \"mm\" }\n[units]\nmass = \"kg\"\n");
        declines("[[part]]\nshape = \"point\"\nmass = 99999999999999999999999\n");
        declines("[[part]]\nshape = \"point\"\nmass = 1e999\n");
    }
}
