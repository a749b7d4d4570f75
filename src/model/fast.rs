//! The reader of a part file: from its text to `RawFile`, straight from
//! the toml crate's own lexer and event parser (`toml_parser`), driven by
//! the key registry (`keys::part_keys!`, each shape's own keys).
//!
//! NOTE: `toml::from_str` parses the whole document into a generic tree (`toml::de::DeTable`:
//! every key, value and span as a node, ~22 bytes of memory per input byte with the lexer's
//! tokens and the parser's events) and only then deserializes from it. Here the parser's events
//! build a small tree of `Node`s for one part at a time, converted to a `RawPart` as the part
//! ends (and handed out at once when streaming), and one for the file's own tables (`units`,
//! `[analysis]`, `[expect]`, `[materials]`, `[params]`, `[growth]`, `[budget]`, `[envelope]`,
//! `[[case]]`: small), converted at the end (`tables`). Only the result, and the tokens of a chunk of whole
//! tables (`CHUNK`), are ever in memory. It reads everything a valid part
//! file holds: includes and their `params`, `array`, `mirror`, dotted keys,
//! sub-tables (`[part.rotation]`, `[materials.steel]`), booleans,
//! `part = [{ .. }]`. It gives `None` on any syntax error and anything
//! TOML or the file's form refuses (a duplicate or unknown key, a value of
//! the wrong type, a table defined twice, …); `explain` then reads the
//! file again, whole and to its end, to word the first error in its own
//! words (`failure`, `errors`). Where it returns `Some`, the reference
//! parser (`toml::from_str::<toml::Table>`) accepts the file, and where
//! it refuses one the reader refuses it with a located error (tested in
//! `tests`, by the property test tests/integration/hostile.rs and by the
//! fuzz target).

use super::raw::{Materials, RawFile, RawPart, RawUnits};
use values::{Entry, How, Node, Seg, own_value, set_from};

mod cases;
pub(in crate::model) mod errors;
pub(in crate::model) mod failure;
pub mod pieces;
pub mod reference;
pub(in crate::model) mod tables;
mod tree;
mod values;
use failure::{Failure, Found, Read, Valid, What};
use pieces::Shift;
use std::borrow::Cow;
use std::ops::Range;
use toml::Spanned;
use toml_parser::decoder::{Encoding, ScalarKind};
use toml_parser::lexer::{Token, TokenKind};
use toml_parser::parser::{EventReceiver, RecursionGuard, ValidateWhitespace};
use toml_parser::{ErrorSink, ParseError, Raw, Source, Span};
use tree::{Refused, enter, header_table, put};

/// The toml crate's own nesting limit (`toml::de::parser::LIMIT`).
const RECURSION_LIMIT: u32 = 80;

/// The most parts a header or a dotted key has here: no table of a part
/// file is deeper (`[expect]`'s `center_of_mass.x` is 2), and a path of
/// a hundred thousand parts would make as many nested tables (dropped
/// recursively). A longer one is declined: the file is no part file.
const MAX_PATH: usize = 8;

/// `RawFile` from `text`, or `None` where it is not a valid part file
/// (`explain` then words the error).
pub fn parse(text: &str) -> Option<RawFile> {
    parse_in_chunks(text, CHUNK)
}

/// Why `source` is no valid part file, in massprop's words: the first
/// syntax or decoding error the parser reports; else the first refusal of
/// TOML's rules (a key or table defined twice, a dotted key through a
/// value); else the first refusal of the form of a part file in the file
/// (an unknown key, a value of the wrong type, a missing key). Only on the
/// error path: the file is read again whole, to its end.
pub(in crate::model) fn explain(source: &crate::diag::Source) -> crate::diag::Diagnostic {
    // A `[[analysis]]` header is the error wherever the file fails.
    if let Some(d) = errors::array_of_tables(source) {
        return d;
    }
    let text = &source.text;
    let mut builder = Builder::new(Source::new(text));
    builder.explain = true;
    let mut first = First(None);
    let tokens = Source::new(text).lex().into_vec();
    {
        let mut ws = ValidateWhitespace::new(&mut builder, Source::new(text));
        let mut guarded = RecursionGuard::new(&mut ws, RECURSION_LIMIT);
        toml_parser::parser::parse_document(&tokens, &mut guarded, &mut first);
    }
    if let Some(e) = first.0 {
        return errors::parse_error(source, &e);
    }
    let failure = match builder.finish() {
        Ok(_) => None,
        Err(f) => f,
    };
    match failure {
        Some(f) => errors::word(source, f),
        // NOTE: the reader refused a file its whole reading takes: a
        // chunk ended inside a value. Never seen (the property test and
        // the fuzz target read every file in chunks of 1 to 40 tokens);
        // said rather than hidden.
        None => source.error(
            0..0,
            "this file could not be read in pieces; please report it",
        ),
    }
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
    let mut builder = Builder::new(Source::new(text));
    builder.streaming = sink.is_some();
    feed(&mut builder, 0..text.len(), chunk_tokens, &mut sink)?;
    builder.finish().ok()
}

/// Reads the stretch `range` of the builder's file into `builder`, a chunk
/// at a time, the parts read handed to `sink` after each chunk; the part
/// still open is closed at its end (the end of the file, or of a stretch
/// the next of which begins with a `[[part]]` header, which closes it).
/// `None` on a syntax error or a refusal; else whether the stretch ended
/// clean: after a newline, outside any array or inline table (a stretch
/// that ends so ends where the whole file's lexer has a token boundary, the
/// start of a line: `pieces`).
fn feed(
    builder: &mut Builder<'_>,
    range: Range<usize>,
    chunk_tokens: usize,
    sink: &mut Option<&mut PartSink<'_>>,
) -> Option<bool> {
    let whole = builder.source;
    let text = &whole.input()[range.clone()];
    // Lexed from the stretch's own text (its spans from its start), the
    // events shifted to the file's (`Shift`).
    let source = Source::new(text);
    let mut error = First(None);
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
            let mut shifted = Shift(builder, range.start);
            let mut ws = ValidateWhitespace::new(&mut shifted, source);
            let mut guarded = RecursionGuard::new(&mut ws, RECURSION_LIMIT);
            toml_parser::parser::parse_document(&chunk, &mut guarded, &mut error);
            chunk.clear();
            if error.0.is_some() || builder.failed {
                return None;
            }
            if token.is_none() {
                // The last part is complete (and may be refused).
                builder.close_part();
                if builder.failed {
                    return None;
                }
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
        if t.kind() != TokenKind::Eof {
            line_start = t.kind() == TokenKind::Newline;
        }
        chunk.push(t);
    }
    Some(line_start && depth == 0)
}

/// Tokens lexed and parsed at a time (24 bytes each): a few thousand
/// parts.
pub const CHUNK: usize = 1 << 16;

/// Keeps the first error the parser reports (a syntax error, or one of
/// decoding a key or a value, in the file's order).
struct First(Option<ParseError>);

impl ErrorSink for First {
    fn report_error(&mut self, error: ParseError) {
        if self.0.is_none() {
            self.0 = Some(error);
        }
    }
}

/// An array or inline table still open.
enum Frame<'i> {
    Array(usize, Vec<Node<'i>>),
    /// Its entries, and the key (dotted parts) being read.
    Table(usize, Vec<Entry<'i>>, Vec<Seg<'i>>),
}

struct Builder<'i> {
    source: Source<'i>,
    failed: bool,
    /// Reading to explain a refusal (`explain`): each failure kept, the
    /// first of TOML's rules and the first in the file of the form's.
    explain: bool,
    toml_failure: Option<Failure>,
    form_failure: Option<Failure>,
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
    /// `[[part]]` headers read, and headers of the file's own tables
    /// (`pieces` checks both).
    opened: usize,
    tables: usize,
}

impl<'i> Builder<'i> {
    fn new(source: Source<'i>) -> Self {
        Builder {
            source,
            failed: false,
            explain: false,
            toml_failure: None,
            form_failure: None,
            header: None,
            keys: Vec::new(),
            stack: Vec::new(),
            root: Vec::new(),
            at: Vec::new(),
            in_part: false,
            parts: None,
            part: None,
            streaming: false,
            opened: 0,
            tables: 0,
        }
    }

    fn fail(&mut self, f: Failure) {
        self.failed = true;
        if !self.explain {
            return;
        }
        if f.is_toml() {
            self.toml_failure.get_or_insert(f);
        } else if self
            .form_failure
            .as_ref()
            .is_none_or(|g| f.span.start < g.span.start)
        {
            self.form_failure = Some(f);
        }
    }

    /// A state only a syntax error leads to (which the parser reports).
    fn confused(&mut self, span: Span) {
        self.fail(Failure::toml(span.start()..span.end(), "invalid TOML here"));
    }

    fn raw(&self, span: Span, kind: Option<Encoding>) -> Raw<'i> {
        let text = &self.source.input()[span.start()..span.end()];
        Raw::new_unchecked(text, kind, span)
    }

    /// A root table converted as read so far (for the parts handed out).
    fn early<T>(&self, key: &str, convert: fn(Node<'i>) -> Read<T>) -> Option<T> {
        let (_, _, node) = self.root.iter().find(|(k, _, _)| k == key)?;
        convert(node.clone()).ok()
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

    /// The file read, or (when explaining) the failure to word: the first
    /// of TOML's rules, else the first of the form's in the file.
    fn finish(mut self) -> Result<RawFile, Option<Failure>> {
        self.close_part();
        if self.header.is_some() || !self.stack.is_empty() || !self.keys.is_empty() {
            // Only after a syntax error, which the parser reports.
            self.fail(Failure::toml(0..0, "invalid TOML"));
        }
        let mut raw = RawFile {
            name: None,
            units: None,
            part: self.parts.take().map(|(span, v)| Spanned::new(span, v)),
            analysis: None,
            expect: None,
            materials: None,
            params: None,
            growth: None,
            budget: None,
            envelope: None,
            case: None,
        };
        for (k, ks, v) in std::mem::take(&mut self.root) {
            if let Err(f) = self.root_key(&mut raw, &k, &ks, v) {
                self.fail(f);
            }
        }
        if !self.failed {
            return Ok(raw);
        }
        Err(self.toml_failure.or(self.form_failure))
    }

    /// One of the file's own keys into `raw`.
    fn root_key(&self, raw: &mut RawFile, k: &str, ks: &Range<usize>, v: Node<'i>) -> Read<()> {
        root_value(raw, k, ks, v).map_err(|f| f.at_key(k))
    }

    /// The `[[part]]` being read is complete.
    fn close_part(&mut self) {
        self.in_part = false;
        let Some((span, entries)) = self.part.take() else {
            return;
        };
        match part(entries) {
            Ok(p) => match &mut self.parts {
                Some((_, v)) => v.push(Spanned::new(span, p)),
                None => self.fail(Failure::toml(span, "invalid TOML")),
            },
            Err(f) => self.fail(f),
        }
    }

    /// A table header `[path]` or `[[path]]` from `span`.
    fn open_table(&mut self, span: Range<usize>, is_array: bool, path: Vec<Seg<'i>>) {
        let Some(((first, first_span), rest)) = path.split_first() else {
            return self.fail(Failure::toml(span, "invalid TOML"));
        };
        if first == "part" {
            if is_array {
                if !rest.is_empty() {
                    // No key of a part is an array of tables.
                    let (k, ks) = &rest[0];
                    let shape = self.part.as_ref().and_then(|(_, e)| shape_of(e));
                    return self.fail(Failure::new(
                        ks.clone(),
                        What::Unknown {
                            key: k.to_string(),
                            valid: Valid::Part(shape),
                        },
                    ));
                }
                if let Some((_, _, node)) = self.root.iter().find(|(k, _, _)| k == "part") {
                    let f = match node {
                        Node::Table(..) => Failure::new(span.clone(), What::PartTable),
                        _ => Failure::toml(first_span.clone(), "duplicate key"),
                    };
                    return self.fail(f);
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
                self.opened += 1;
                self.in_part = true;
                self.at.clear();
                return;
            }
            if rest.is_empty() {
                // `[part]`: one table, where parts are an array of them.
                self.close_part();
                self.fail(Failure::new(span, What::PartTable));
                let text = self.source.input();
                // Read on into a table of its own, for later errors.
                let _ = header_table(&mut self.root, &path, 0..0, text);
                self.at = path.into_iter().map(|(k, _)| k).collect();
                return;
            }
            // `[part.rotation]`: a table of the part still open.
            // NOTE: not of a part closed by another table's header since,
            // which TOML allows but no part file needs: refused.
            let Some((_, entries)) = &mut self.part else {
                return self.fail(Failure::new(
                    span,
                    What::Other(
                        "a table of a part (`[part.…]`) must follow its `[[part]]`, before any other table"
                            .into(),
                    ),
                ));
            };
            let text = self.source.input();
            if let Err(f) = header_table(entries, rest, span, text).map_err(Refused::word) {
                return self.fail(f);
            }
            self.in_part = true;
            self.at = rest.iter().map(|(k, _)| k.clone()).collect();
            return;
        }
        if first == "case" {
            return self.open_case(span, path, is_array);
        }
        if is_array {
            // `[[analysis]]` and the like are worded before (`explain`);
            // any other name is an unknown key here, or an array of tables
            // where a table belongs.
            self.close_part();
            let f = if ROOT_KEYS.contains(&&**first) {
                Failure::new(
                    span,
                    What::Other(format!(
                        "`{first}`: an array of tables where a table belongs; write `[{first}]`, with one pair of brackets"
                    )),
                )
            } else {
                Failure::new(
                    first_span.clone(),
                    What::Unknown {
                        key: first.to_string(),
                        valid: Valid::Keys(ROOT_KEYS),
                    },
                )
            };
            return self.fail(f);
        }
        self.close_part();
        self.tables += 1;
        let text = self.source.input();
        if let Err(f) = header_table(&mut self.root, &path, span, text).map_err(Refused::word) {
            return self.fail(f);
        }
        self.at = path.into_iter().map(|(k, _)| k).collect();
    }

    /// A complete value: into the open array or inline table, or to the
    /// current key.
    fn value(&mut self, node: Node<'i>) {
        let text = self.source.input();
        match self.stack.last_mut() {
            Some(Frame::Array(_, items)) => items.push(node),
            Some(Frame::Table(_, entries, keys)) => {
                let keys = std::mem::take(keys);
                if let Err(e) = put(entries, &keys, node, text) {
                    self.fail(e.word());
                }
            }
            None => {
                let keys = std::mem::take(&mut self.keys);
                if let Err(e) = self.assign(keys, node, text) {
                    self.fail(e.word());
                }
            }
        }
    }

    /// `keys = node` (a dotted key through tables it makes) in the
    /// current table; refused where TOML refuses it (a key given twice, a
    /// dotted key through a value or a table not its own).
    fn assign(&mut self, keys: Vec<Seg<'i>>, node: Node<'i>, text: &str) -> Result<(), Refused> {
        let span = keys.first().map_or(0..0, |(_, s)| s.clone());
        let table = if self.in_part {
            match self.part.as_mut() {
                Some((_, entries)) => entries,
                None => return Err(Refused::Confused(span)),
            }
        } else {
            &mut self.root
        };
        let Some(table) = enter(table, &self.at) else {
            return Err(Refused::Confused(span));
        };
        put(table, &keys, node, text)
    }
}

/// One of the file's own keys into `raw`, its failure not yet given the
/// key.
fn root_value(raw: &mut RawFile, k: &str, ks: &Range<usize>, v: Node<'_>) -> Read<()> {
    use values::set;
    match k {
        "name" => set(&mut raw.name, tables::name(v)?, ks),
        "units" => set(&mut raw.units, tables::units(v)?, ks),
        "analysis" => set(&mut raw.analysis, tables::analysis(v)?, ks),
        "expect" => set(&mut raw.expect, tables::expect(v)?, ks),
        "materials" => set(&mut raw.materials, tables::materials(v)?, ks),
        "params" => set(&mut raw.params, tables::params(v)?, ks),
        "growth" => set(&mut raw.growth, tables::growth(v)?, ks),
        "budget" => set(&mut raw.budget, tables::budget(v)?, ks),
        "envelope" => set(&mut raw.envelope, tables::envelope(v)?, ks),
        "case" => set(&mut raw.case, cases::cases(v)?, ks),
        // `part = [{ .. }, ..]`: the parts as an array of inline tables
        // (not beside `[[part]]`: TOML refuses the key then). Kept, not
        // handed out, when streaming (`Streamed::saw_all_of` then has the
        // file read whole).
        "part" => {
            let Node::Array(items, span) = v else {
                return values::wrong(&v, PARTS);
            };
            let parts = items
                .into_iter()
                .map(|n| match n {
                    Node::Table(entries, span, _) => Ok(Spanned::new(span, part(entries)?)),
                    other => values::wrong(&other, "a part table with `shape`")
                        .map_err(Failure::in_array),
                })
                .collect::<Read<_>>()?;
            set(&mut raw.part, Spanned::new(span, parts), ks)
        }
        _ => values::unknown(k, ks, ROOT_KEYS),
    }
}

/// What `[[part]]` holds, in a message.
const PARTS: &str = "an array of tables, each a `[[part]]`";

/// The file's own keys, in a message.
pub(in crate::model) const ROOT_KEYS: &[&str] = &[
    "name",
    "units",
    "part",
    "analysis",
    "expect",
    "materials",
    "params",
    "growth",
    "budget",
    "envelope",
    "case",
];

/// A part from its keys, by the key registry (`assign_part`); refused for
/// an unknown key or a value of the wrong type. (A part with neither a
/// shape nor an include is read: the model says what it misses.)
fn part(entries: Vec<Entry<'_>>) -> Read<RawPart> {
    // The shape first: an unknown key is matched against its keys.
    let shape = shape_of(&entries);
    let mut p = RawPart::default();
    for (k, ks, v) in entries {
        assign_part(&mut p, &k, &ks, v, shape).map_err(|f| f.at_key(&k).in_part(shape))?;
    }
    Ok(p)
}

/// The shape a part's keys name, if a known one.
fn shape_of(entries: &[Entry<'_>]) -> Option<crate::shapes::Shape> {
    entries.iter().find_map(|(k, _, v)| match (&**k, v) {
        ("shape", Node::Str(s, _)) => crate::shapes::Shape::from_name(s),
        _ => None,
    })
}

/// The reader's assignment of each part key, from its declaration
/// (`keys::part_keys!`): `key = node` into its `RawPart` field, read as
/// the field's type reads it (`FromNode`); else a shape's own key, read
/// by its declared kind. Refused if the key is unknown, repeated, or the
/// value of the wrong type.
macro_rules! assigner {
    ($($name:ident: $kind:expr, $dim:expr, $fill:expr, $scope:ident, $doc:literal;)+) => {
        fn assign_part(
            p: &mut RawPart,
            key: &str,
            ks: &Range<usize>,
            node: Node<'_>,
            shape: Option<crate::shapes::Shape>,
        ) -> Read<()> {
            match key {
                $(stringify!($name) => set_from(&mut p.$name, node, ks),)+
                _ => {
                    let Some(declared) = crate::shapes::own_key(key) else {
                        return Err(Failure::new(
                            ks.clone(),
                            What::Unknown { key: key.to_string(), valid: Valid::Part(shape) },
                        ));
                    };
                    let value = own_value(declared.kind, node)?;
                    let own = p.own.get_or_insert_with(Default::default);
                    if own.iter().any(|(k, _)| *k == declared.name) {
                        return Err(Failure::toml(ks.clone(), "duplicate key"));
                    }
                    own.push((declared.name, value));
                    Ok(())
                }
            }
        }
    };
}
super::keys::part_keys!(assigner);

impl<'i> EventReceiver for Builder<'i> {
    fn std_table_open(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        if self.header.is_some() || !self.keys.is_empty() || !self.stack.is_empty() {
            return self.confused(span);
        }
        self.header = Some((span.start(), false, Vec::new()));
    }

    fn std_table_close(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        match self.header.take() {
            Some((start, false, path)) => self.open_table(start..span.end(), false, path),
            _ => self.confused(span),
        }
    }

    fn array_table_open(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        if self.header.is_some() || !self.keys.is_empty() || !self.stack.is_empty() {
            return self.confused(span);
        }
        self.header = Some((span.start(), true, Vec::new()));
    }

    fn array_table_close(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        match self.header.take() {
            Some((start, true, path)) => self.open_table(start..span.end(), true, path),
            _ => self.confused(span),
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
            _ => self.confused(span),
        }
    }

    fn array_open(&mut self, span: Span, _error: &mut dyn ErrorSink) -> bool {
        self.stack.push(Frame::Array(span.start(), Vec::new()));
        true
    }

    fn array_close(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        match self.stack.pop() {
            Some(Frame::Array(start, items)) => self.value(Node::Array(items, start..span.end())),
            _ => self.confused(span),
        }
    }

    fn simple_key(&mut self, span: Span, kind: Option<Encoding>, error: &mut dyn ErrorSink) {
        let mut key = Cow::Borrowed("");
        self.raw(span, kind).decode_key(&mut key, error);
        let seg = (key, span.start()..span.end());
        let input = self.source.input();
        let path = match (&mut self.header, self.stack.last_mut()) {
            (Some((_, _, path)), _) => path,
            (None, Some(Frame::Table(_, _, keys))) => keys,
            (None, Some(Frame::Array(..))) => return self.confused(span),
            (None, None) => &mut self.keys,
        };
        if path.len() < MAX_PATH {
            return path.push(seg);
        }
        // Kept to its first parts, so that reading goes on; the error
        // points at the whole key (to its `=` or `]`), once.
        if path.len() == MAX_PATH {
            let start = path[0].1.start;
            path.push(seg);
            let line = &input[start..];
            let end = start
                + line[..line.find(['=', ']', '\n']).unwrap_or(line.len())]
                    .trim_end()
                    .len();
            self.fail(Failure::new(start..end.max(span.end()), What::TooDeep));
        }
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
                _ => {
                    self.fail(Failure::toml(
                        range.clone(),
                        "floating-point number overflowed",
                    ));
                    Node::Num(0.0, range)
                }
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
                    Node::Other(Found::Wide, range)
                }
            }
            ScalarKind::Boolean(b) => Node::Bool(b, range),
            ScalarKind::DateTime => Node::Other(Found::DateTime, range),
        };
        self.value(node);
    }

    fn error(&mut self, span: Span, _error: &mut dyn ErrorSink) {
        self.confused(span);
    }
}

#[cfg(test)]
pub(super) mod tests;
