//! A large part file read on every core: cut at `[[part]]` headers into
//! pieces, each read by its own builder on its own thread, and put back
//! together in the file's order.
//!
//! NOTE: why this replaces the simpler one-core reading (`read`) for large
//! files: reading (lexing, parsing, checking each part) is almost all of
//! `report`'s time for a file of many parts, and it is independent from
//! one `[[part]]` to the next. The result must be the one-core reading's
//! to the bit, and so it is by construction, not by care:
//!
//! - the pieces begin at lines that start with `[[part]]`; whether such a
//!   line is a header (not inside a multi-line string or an array) is
//!   known only once the text before it is lexed, so each piece checks
//!   that it ended clean (`feed`: after a newline, outside any array), which
//!   means the whole file's lexer starts a token there too (the lexer is
//!   deterministic and a newline token never reaches past itself), and the
//!   tokens of each piece are those of the whole file;
//! - each piece is then read as one more chunk of the one-core reading
//!   (which already reads in chunks of whole tables), by a builder that
//!   starts from the file's own tables as they stand before the first
//!   `[[part]]` (the preamble, read first); a piece that opens another
//!   table of the file, or a preamble with a part, declines the pieces;
//! - a part's number (`part 12` for a part without a name) is its index
//!   in the file: each piece counts the header lines before it
//!   (`super::super::is_part_table`), and must then read exactly as many
//!   parts as it counted in its own lines, or the pieces are declined;
//! - anything refused in any piece (a syntax error, a key, a value)
//!   declines the pieces too: the file is then read again on one core,
//!   which finds the first error in the file's order and words it as
//!   always (an invalid file is read twice anyway, `explain`).
//!
//! Pinned against the one-core reading by `tests::same` (every reader test
//! reads its file in 2 to 5 pieces too), the property test
//! (tests/integration/hostile.rs) and the model's tests of one against two
//! threads (`model::streamed`).

use super::{Builder, PartSink, RawFile, RawPart, Spanned, feed};
use crate::model::raw::{Materials, RawUnits};
use std::cell::Cell;
use toml_parser::parser::EventReceiver;
use toml_parser::{ErrorSink, Source, Span, decoder::Encoding};

/// Bytes of a file per piece, at least: below twice this a file is read
/// on one core (starting a thread and reading the preamble twice cost
/// little, but a small file is read in a millisecond anyway).
pub const MIN_PIECE: usize = 1 << 20;

/// Pieces at most, whatever the cores.
const MAX_PIECES: usize = 16;

thread_local! {
    /// Pieces forced for this thread's readings (`with_pieces`).
    static FORCED: Cell<Option<usize>> = const { Cell::new(None) };
}

/// Runs `f` with every file this thread reads cut into `pieces` pieces
/// where it has that many `[[part]]` lines, whatever its size: for the
/// tests, which compare one piece (the one-core reading) with several on
/// small files. `1` reads on one core.
#[doc(hidden)]
pub fn with_pieces<T>(pieces: usize, f: impl FnOnce() -> T) -> T {
    let before = FORCED.with(|c| c.replace(Some(pieces.max(1))));
    let out = f();
    FORCED.with(|c| c.set(before));
    out
}

/// How many pieces `text` is read in: one per core, each at least
/// `MIN_PIECE` bytes (or as `with_pieces` forces).
pub fn pieces_for(text: &str) -> usize {
    if let Some(n) = FORCED.with(Cell::get) {
        return n;
    }
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    cores.min(text.len() / MIN_PIECE).clamp(1, MAX_PIECES)
}

/// What reading in pieces gave.
pub enum Pieces<S> {
    /// The file, with the parts handed to each piece's state (in the
    /// file's order); its `part` list empty, as when streaming.
    Read(Box<RawFile>, Vec<S>),
    /// Not read in pieces (too few `[[part]]` lines, a piece not ending
    /// clean, a part or table the pieces cannot take, or anything
    /// refused): read it on one core.
    Declined,
}

/// Where each piece's parts go: its state, the file's `units` and
/// `[materials]` as read, and the part.
pub type Take<'a, S> =
    dyn Fn(&mut S, Option<&Spanned<RawUnits>>, Option<&Materials>, Spanned<RawPart>) + Sync + 'a;

/// Reads `text` in `pieces` pieces, on as many threads: each piece's state
/// made by `new(first, parts)` (the index in the file of its first part,
/// and how many `[[part]]` lines it has), its parts handed to `take`.
pub fn read<S: Send>(
    text: &str,
    pieces: usize,
    new: &(dyn Fn(usize, usize) -> S + Sync),
    take: &Take<'_, S>,
) -> Pieces<S> {
    let Some(cut) = Cut::of(text, pieces) else {
        return Pieces::Declined;
    };
    let mut first = Builder::new(Source::new(text));
    first.streaming = true;
    // The preamble: the file's own keys and tables, before any part.
    if cut.starts[0] > 0 {
        let mut none: Option<&mut PartSink<'_>> = None;
        match feed(&mut first, 0..cut.starts[0], super::CHUNK, &mut none) {
            Some(true) if first.opened == 0 => {}
            _ => return Pieces::Declined,
        }
    }
    let root = first.root.clone();
    let tables = first.tables;
    let last = cut.starts.len() - 1;
    let range = |k: usize| cut.starts[k]..cut.starts.get(k + 1).copied().unwrap_or(text.len());
    let one = |builder: &mut Builder<'_>, k: usize| -> Option<S> {
        let mut state = new(cut.before[k], cut.lines[k]);
        let mut sink = |u: Option<&Spanned<RawUnits>>, m: Option<&Materials>, p| {
            take(&mut state, u, m, p);
        };
        let mut sink: Option<&mut PartSink<'_>> = Some(&mut sink);
        let clean = feed(builder, range(k), super::CHUNK, &mut sink)?;
        // The next piece begins where the whole file's lexer begins a
        // token, and this one read the parts its lines promised.
        (clean || k == last).then_some(())?;
        (builder.opened == cut.lines[k]).then_some(())?;
        Some(state)
    };
    let (head, rest) = std::thread::scope(|scope| {
        let handles: Vec<_> = (1..=last)
            .map(|k| {
                let (one, root) = (&one, root.clone());
                // A thread the system cannot start declines the pieces
                // (`None` below), rather than panicking.
                std::thread::Builder::new().spawn_scoped(scope, move || {
                    let mut b = Builder::new(Source::new(text));
                    b.streaming = true;
                    b.root = root;
                    let state = one(&mut b, k)?;
                    // No table of the file's own after the preamble: each
                    // piece's parts were made with the preamble's.
                    (b.tables == 0).then_some(state)
                })
            })
            .collect();
        let head = one(&mut first, 0).filter(|_| first.tables == tables);
        let rest: Vec<Option<S>> = handles
            .into_iter()
            .map(|h| {
                h.ok()
                    .and_then(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
            })
            .collect();
        (head, rest)
    });
    let Some(head) = head else {
        return Pieces::Declined;
    };
    let Some(rest) = rest.into_iter().collect::<Option<Vec<S>>>() else {
        return Pieces::Declined;
    };
    match first.finish() {
        Ok(raw) => Pieces::Read(Box::new(raw), std::iter::once(head).chain(rest).collect()),
        Err(_) => Pieces::Declined,
    }
}

/// `parse`, in `pieces` pieces where the file can be read so: for the
/// tests and the property test, which compare it with the one-core
/// reading. `None` where declined (or refused).
#[doc(hidden)]
pub fn parse_in_pieces(text: &str, pieces: usize) -> Option<RawFile> {
    let new = |_, n| Vec::with_capacity(n);
    let take = |v: &mut Vec<Spanned<RawPart>>, _: Option<&_>, _: Option<&_>, p| v.push(p);
    match read(text, pieces, &new, &take) {
        Pieces::Read(mut raw, parts) => {
            if let Some(list) = raw.part.as_mut() {
                list.get_mut().extend(parts.into_iter().flatten());
            }
            Some(*raw)
        }
        Pieces::Declined => None,
    }
}

/// Where the pieces begin: `starts[0]` the first line that starts with
/// `[[part]]`, the others the first such line after each share of the
/// file; and the `[[part]]` header lines before each piece and in it.
struct Cut {
    starts: Vec<usize>,
    before: Vec<usize>,
    lines: Vec<usize>,
}

impl Cut {
    /// `None` where there are not two pieces to read.
    fn of(text: &str, pieces: usize) -> Option<Cut> {
        if pieces < 2 {
            return None;
        }
        let share = text.len() / pieces;
        let mut starts = Vec::with_capacity(pieces);
        let mut before = Vec::with_capacity(pieces);
        let mut count = 0usize;
        let mut at = 0usize;
        for line in text.split_inclusive('\n') {
            let here = at;
            at += line.len();
            if !line.trim_start().starts_with("[[") {
                continue;
            }
            if crate::model::is_part_table(line.trim_start()) {
                // Not the first piece's before the preamble's end.
                let due = starts.len() * share;
                if line.starts_with("[[part]]") && here >= due && starts.len() < pieces {
                    starts.push(here);
                    before.push(count);
                }
                count += 1;
            }
        }
        if starts.len() < 2 {
            return None;
        }
        let mut lines: Vec<usize> = before.windows(2).map(|w| w[1] - w[0]).collect();
        lines.push(count - before[before.len() - 1]);
        // The preamble's header lines (indented ones): the pieces decline
        // a preamble with a part, so these must be none.
        (before[0] == 0).then_some(Cut {
            starts,
            before,
            lines,
        })
    }
}

/// The events of a piece lexed from its own text, their spans moved to
/// the file's (`feed`).
pub(super) struct Shift<'r, 'i>(pub(super) &'r mut Builder<'i>, pub(super) usize);

impl Shift<'_, '_> {
    fn at(&self, span: Span) -> Span {
        Span::new_unchecked(span.start() + self.1, span.end() + self.1)
    }
}

impl EventReceiver for Shift<'_, '_> {
    fn std_table_open(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.std_table_open(self.at(span), error);
    }
    fn std_table_close(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.std_table_close(self.at(span), error);
    }
    fn array_table_open(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.array_table_open(self.at(span), error);
    }
    fn array_table_close(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.array_table_close(self.at(span), error);
    }
    fn inline_table_open(&mut self, span: Span, error: &mut dyn ErrorSink) -> bool {
        self.0.inline_table_open(self.at(span), error)
    }
    fn inline_table_close(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.inline_table_close(self.at(span), error);
    }
    fn array_open(&mut self, span: Span, error: &mut dyn ErrorSink) -> bool {
        self.0.array_open(self.at(span), error)
    }
    fn array_close(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.array_close(self.at(span), error);
    }
    fn simple_key(&mut self, span: Span, kind: Option<Encoding>, error: &mut dyn ErrorSink) {
        self.0.simple_key(self.at(span), kind, error);
    }
    fn key_sep(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.key_sep(self.at(span), error);
    }
    fn key_val_sep(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.key_val_sep(self.at(span), error);
    }
    fn scalar(&mut self, span: Span, kind: Option<Encoding>, error: &mut dyn ErrorSink) {
        self.0.scalar(self.at(span), kind, error);
    }
    fn value_sep(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.value_sep(self.at(span), error);
    }
    fn whitespace(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.whitespace(self.at(span), error);
    }
    fn comment(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.comment(self.at(span), error);
    }
    fn newline(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.newline(self.at(span), error);
    }
    fn error(&mut self, span: Span, error: &mut dyn ErrorSink) {
        self.0.error(self.at(span), error);
    }
}
