//! The reader of a part file: from its text to `RawFile`, straight from
//! the toml crate's own lexer and event parser (`toml_parser`), driven by
//! the key registry (`keys::part_keys!`, each shape's own keys).
//!
//! NOTE: `toml::from_str` parses the whole document into a generic tree
//! (`toml::de::DeTable`: every key, value and span as a node, ~22 bytes of
//! memory per input byte with the lexer's tokens and the parser's events)
//! and only then deserializes from it. Here the parser's events build a
//! small tree of `Node`s for one part at a time, converted to a `RawPart`
//! as the part ends (and handed out at once when streaming), and one for
//! the file's own tables (`units`, `[analysis]`, `[expect]`,
//! `[materials]`, `[params]`, `[growth]`, `[budget]`: small), converted at
//! the end (`tables`). Only the result, and the tokens of a chunk of whole
//! tables (`CHUNK`), are ever in memory. It reads everything a valid part
//! file holds: includes and their `params`, `array`, `mirror`, dotted keys,
//! sub-tables (`[part.rotation]`, `[materials.steel]`), booleans,
//! `part = [{ .. }]`. It gives `None` on any syntax error and anything
//! TOML or the file's form refuses (a duplicate or unknown key, a value of
//! the wrong type, a missing `shape`, a table defined twice, …): the
//! caller then words a syntax error by `errors`, and lets serde word the
//! classes not worded there yet. Where it returns `Some`,
//! `toml::from_str::<RawFile>` gives the same, values and spans alike
//! (tested in `tests`, by the property test tests/integration/hostile.rs
//! and by the fuzz target).

use super::raw::{Materials, RawFile, RawPart, RawUnits};
use values::{Entry, How, Node, own_value, set_from};

pub(in crate::model) mod errors;
mod tables;
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

/// The most parts a header or a dotted key has here: no table of a part
/// file is deeper (`[expect]`'s `center_of_mass.x` is 2), and a path of
/// a hundred thousand parts would make as many nested tables (dropped
/// recursively). A longer one is declined: the file is no part file.
const MAX_PATH: usize = 8;

/// `RawFile` from `text`, or `None` where it is not a valid part file
/// (serde then words the error).
pub fn parse(text: &str) -> Option<RawFile> {
    parse_in_chunks(text, CHUNK)
}

/// The file as the model reads it: `parse`.
pub fn read_file(text: &str) -> Option<RawFile> {
    parse(text)
}

/// Where each `[[part]]` goes as soon as it is read, with the file's
/// `units` and `[materials]` as read so far.
pub type PartSink<'a> =
    dyn FnMut(Option<&Spanned<RawUnits>>, Option<&Materials>, Spanned<RawPart>) + 'a;

/// `parse`, handing each part to `sink` as soon as it is read (after each
/// chunk) rather than keeping it: the `RawFile` returned has an empty
/// `part` list (its span kept). `None` where the file is not valid, also
/// after some parts were handed out.
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
    // builder (a value still open, `finish`, or the next header) fails.
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
    /// Its entries, and the key (dotted parts) being read.
    Table(usize, Vec<Entry<'i>>, Vec<Seg<'i>>),
}

/// A key, or one part of a dotted key or header, and where it is.
type Seg<'i> = (Cow<'i, str>, Range<usize>);

struct Builder<'i> {
    source: Source<'i>,
    failed: bool,
    /// Inside `[..]` or `[[..]]`: where it opened, whether an array table,
    /// and its keys.
    header: Option<(usize, bool, Vec<Seg<'i>>)>,
    /// The key (its dotted parts) of the key/value pair being read
    /// (document level).
    keys: Vec<Seg<'i>>,
    stack: Vec<Frame<'i>>,
    /// The file's own tables and keys (not its `[[part]]`s).
    root: Vec<Entry<'i>>,
    /// The table key/value pairs go to: its path from the root, or from
    /// the open part if `in_part`.
    at: Vec<Cow<'i, str>>,
    in_part: bool,
    parts: Option<(Range<usize>, Vec<Spanned<RawPart>>)>,
    /// The `[[part]]` being read: its header and its keys.
    part: Option<(Range<usize>, Vec<Entry<'i>>)>,
    /// Parts are handed out as read (`parse_streaming`), not kept.
    streaming: bool,
}

impl<'i> Builder<'i> {
    fn new(source: Source<'i>) -> Self {
        Builder {
            source,
            failed: false,
            header: None,
            keys: Vec::new(),
            stack: Vec::new(),
            root: Vec::new(),
            at: Vec::new(),
            in_part: false,
            parts: None,
            part: None,
            streaming: false,
        }
    }

    fn fail(&mut self) {
        self.failed = true;
    }

    fn raw(&self, span: Span, kind: Option<Encoding>) -> Raw<'i> {
        let text = &self.source.input()[span.start()..span.end()];
        Raw::new_unchecked(text, kind, span)
    }

    /// A root table converted as read so far (for the parts handed out).
    fn early<T>(&self, key: &str, convert: fn(Node<'i>) -> Option<T>) -> Option<T> {
        let (_, _, node) = self.root.iter().find(|(k, _, _)| k == key)?;
        convert(node.clone())
    }

    /// Hand the parts read so far to `sink`.
    fn hand_out(&mut self, sink: &mut PartSink<'_>) {
        let Some((_, parts)) = &mut self.parts else {
            return;
        };
        if parts.is_empty() {
            return;
        }
        let parts = std::mem::take(parts);
        let units = self.early("units", tables::units);
        let materials = self.early("materials", tables::materials);
        for p in parts {
            sink(units.as_ref(), materials.as_ref(), p);
        }
    }

    fn finish(mut self) -> Option<RawFile> {
        self.close_part();
        if self.failed || self.header.is_some() || !self.stack.is_empty() || !self.keys.is_empty() {
            return None;
        }
        let mut raw = RawFile {
            name: None,
            units: None,
            part: self.parts.map(|(span, v)| Spanned::new(span, v)),
            analysis: None,
            expect: None,
            materials: None,
            params: None,
            growth: None,
            budget: None,
        };
        for (k, _, v) in self.root {
            match &*k {
                "name" => values::set(&mut raw.name, tables::name(v)?),
                "units" => values::set(&mut raw.units, tables::units(v)?),
                "analysis" => values::set(&mut raw.analysis, tables::analysis(v)?),
                "expect" => values::set(&mut raw.expect, tables::expect(v)?),
                "materials" => values::set(&mut raw.materials, tables::materials(v)?),
                "params" => values::set(&mut raw.params, tables::params(v)?),
                "growth" => values::set(&mut raw.growth, tables::growth(v)?),
                "budget" => values::set(&mut raw.budget, tables::budget(v)?),
                // `part = [{ .. }, ..]`: the parts as an array of inline
                // tables (not beside `[[part]]`: the key is then taken).
                "part" if raw.part.is_none() && !self.streaming => {
                    let Node::Array(items, span) = v else {
                        return None;
                    };
                    let parts = items
                        .into_iter()
                        .map(|n| match n {
                            Node::Table(entries, span, _) => {
                                Some(Spanned::new(span, part(entries)?))
                            }
                            _ => None,
                        })
                        .collect::<Option<_>>()?;
                    raw.part = Some(Spanned::new(span, parts));
                    Some(())
                }
                _ => None,
            }?;
        }
        Some(raw)
    }

    /// The `[[part]]` being read is complete.
    fn close_part(&mut self) {
        self.in_part = false;
        let Some((span, entries)) = self.part.take() else {
            return;
        };
        match (part(entries), &mut self.parts) {
            (Some(p), Some((_, v))) => v.push(Spanned::new(span, p)),
            _ => self.fail(),
        }
    }

    /// A table header `[path]` or `[[path]]` from `span`.
    fn open_table(&mut self, span: Range<usize>, is_array: bool, path: Vec<Seg<'i>>) {
        let Some(((first, _), rest)) = path.split_first() else {
            return self.fail();
        };
        if first == "part" {
            if is_array {
                if !rest.is_empty() || self.root.iter().any(|(k, _, _)| k == "part") {
                    return self.fail();
                }
                self.close_part();
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
                self.part = Some((span, Vec::new()));
                self.in_part = true;
                self.at.clear();
                return;
            }
            // `[part.rotation]`: a table of the part still open.
            // NOTE: not of a part closed by another table's header since,
            // which TOML allows but no part file needs: refused.
            let Some((_, entries)) = &mut self.part else {
                return self.fail();
            };
            if rest.is_empty() || header_table(entries, rest, span).is_none() {
                return self.fail();
            }
            self.in_part = true;
            self.at = rest.iter().map(|(k, _)| k.clone()).collect();
            return;
        }
        if is_array {
            return self.fail();
        }
        self.close_part();
        if header_table(&mut self.root, &path, span).is_none() {
            return self.fail();
        }
        self.at = path.into_iter().map(|(k, _)| k).collect();
    }

    /// A complete value: into the open array or inline table, or to the
    /// current key.
    fn value(&mut self, node: Node<'i>) {
        match self.stack.last_mut() {
            Some(Frame::Array(_, items)) => items.push(node),
            Some(Frame::Table(_, entries, keys)) => {
                let keys = std::mem::take(keys);
                if put(entries, &keys, node).is_none() {
                    self.fail();
                }
            }
            None => {
                let keys = std::mem::take(&mut self.keys);
                if self.assign(keys, node).is_none() {
                    self.fail();
                }
            }
        }
    }

    /// `keys = node` (a dotted key through tables it makes) in the
    /// current table; `None` if TOML refuses it (a key given twice, a
    /// dotted key through a value or a table not its own).
    fn assign(&mut self, keys: Vec<Seg<'i>>, node: Node<'i>) -> Option<()> {
        let table = if self.in_part {
            &mut self.part.as_mut()?.1
        } else {
            &mut self.root
        };
        put(enter(table, &self.at)?, &keys, node)
    }
}

/// `keys = node` (a dotted key through tables it makes) in `table`;
/// `None` if TOML refuses it (no key, a key given twice, a dotted key
/// through a value or a table not its own).
fn put<'i>(table: &mut Vec<Entry<'i>>, keys: &[Seg<'i>], node: Node<'i>) -> Option<()> {
    let ((last, last_span), through) = keys.split_last()?;
    let mut table = table;
    for (k, span) in through {
        table = descend(table, k, span, How::Dotted)?;
    }
    if table.iter().any(|(k, _, _)| k == last) {
        return None;
    }
    table.push((last.clone(), last_span.clone(), node));
    Some(())
}

/// A part from its keys, by the key registry (`assign_part`); `None` for
/// an unknown key or a value of the wrong type. (A part with neither a
/// shape nor an include is read: the model says what it misses.)
fn part(entries: Vec<Entry<'_>>) -> Option<RawPart> {
    let mut p = RawPart::default();
    for (k, _, v) in entries {
        assign_part(&mut p, &k, v)?;
    }
    Some(p)
}

/// The table at `path` (made by headers) below `table`.
fn enter<'t, 'i>(
    mut table: &'t mut Vec<Entry<'i>>,
    path: &[Cow<'i, str>],
) -> Option<&'t mut Vec<Entry<'i>>> {
    for k in path {
        let i = table.iter().position(|(e, _, _)| e == k)?;
        match &mut table[i].2 {
            Node::Table(entries, _, _) => table = entries,
            _ => return None,
        }
    }
    Some(table)
}

/// The table under `key` in `table`, made `how` if there is none (its
/// span the key's, as toml gives it); `None` where TOML refuses to go
/// through what is there: a value, a closed inline table, a table a
/// header defined for a dotted key, a dotted key's for a header.
fn descend<'t, 'i>(
    table: &'t mut Vec<Entry<'i>>,
    key: &Cow<'i, str>,
    span: &Range<usize>,
    how: How,
) -> Option<&'t mut Vec<Entry<'i>>> {
    let i = match table.iter().position(|(e, _, _)| e == key) {
        Some(i) => i,
        None => {
            table.push((
                key.clone(),
                span.clone(),
                Node::Table(Vec::new(), span.clone(), how),
            ));
            table.len() - 1
        }
    };
    match &mut table[i].2 {
        Node::Table(entries, _, h) if enterable(*h, how) => Some(entries),
        _ => None,
    }
}

/// Whether a table made `made` may be gone through to add by `by`
/// (`How::Dotted`: a dotted key; `How::Implicit`: a header's path).
fn enterable(made: How, by: How) -> bool {
    match (made, by) {
        (How::Dotted, How::Dotted) => true,
        (How::Header | How::Implicit, How::Implicit) => true,
        (How::Inline | How::Header | How::Implicit, How::Dotted) => false,
        (How::Inline | How::Dotted, How::Implicit) => false,
        (How::Inline | How::Header | How::Implicit | How::Dotted, How::Inline | How::Header) => {
            false
        }
    }
}

/// Define the table of the header `[path]` (at `span`) below `table`;
/// `None` if TOML refuses: a table defined twice, a path through a value,
/// an inline table or a dotted key's table.
fn header_table<'i>(
    table: &mut Vec<Entry<'i>>,
    path: &[Seg<'i>],
    span: Range<usize>,
) -> Option<()> {
    let ((last, last_span), through) = path.split_last()?;
    let mut table = table;
    for (k, s) in through {
        table = descend(table, k, s, How::Implicit)?;
    }
    match table.iter_mut().find(|(e, _, _)| e == last) {
        Some((_, _, Node::Table(_, s, how))) if *how == How::Implicit => {
            *s = span;
            *how = How::Header;
            Some(())
        }
        Some(_) => None,
        None => {
            table.push((
                last.clone(),
                last_span.clone(),
                Node::Table(Vec::new(), span, How::Header),
            ));
            Some(())
        }
    }
}

/// The reader's assignment of each part key, from its declaration
/// (`keys::part_keys!`): `key = node` into its `RawPart` field, read as
/// the field's type reads it (`FromNode`); else a shape's own key, read
/// by its declared kind. `None` if the key is unknown, repeated, or the
/// value of the wrong type.
macro_rules! assigner {
    ($($name:ident: $kind:expr, $dim:expr, $fill:expr, $scope:ident, $doc:literal;)+) => {
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
        if self.header.is_some() || !self.keys.is_empty() || !self.stack.is_empty() {
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
        if self.header.is_some() || !self.keys.is_empty() || !self.stack.is_empty() {
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
        self.stack
            .push(Frame::Table(span.start(), Vec::new(), Vec::new()));
        true
    }

    fn inline_table_close(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        match self.stack.pop() {
            Some(Frame::Table(start, entries, keys)) if keys.is_empty() => {
                self.value(Node::Table(entries, start..span.end(), How::Inline))
            }
            _ => self.fail(),
        }
    }

    fn array_open(&mut self, span: Span, _error: &mut dyn ErrorSink) -> bool {
        self.stack.push(Frame::Array(span.start(), Vec::new()));
        true
    }

    fn array_close(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        match self.stack.pop() {
            Some(Frame::Array(start, items)) => self.value(Node::Array(items, start..span.end())),
            _ => self.fail(),
        }
    }

    fn simple_key(&mut self, span: Span, kind: Option<Encoding>, error: &mut dyn ErrorSink) {
        let mut key = Cow::Borrowed("");
        self.raw(span, kind).decode_key(&mut key, error);
        let seg = (key, span.start()..span.end());
        let path = match (&mut self.header, self.stack.last_mut()) {
            (Some((_, _, path)), _) => path,
            (None, Some(Frame::Table(_, _, keys))) => keys,
            (None, Some(Frame::Array(..))) => return self.fail(),
            (None, None) => &mut self.keys,
        };
        if path.len() >= MAX_PATH {
            return self.fail();
        }
        path.push(seg);
    }

    fn scalar(&mut self, span: Span, kind: Option<Encoding>, error: &mut dyn ErrorSink) {
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
pub(super) mod tests;
