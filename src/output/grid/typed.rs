//! Tables of a row per part from typed cells (`Cell`): a number's column
//! measured from its rounded digits without its text, a row written
//! straight into the output buffer, padded as it goes. The same bytes as
//! `stream_table` given the cells' text (held to it in the tests).
//!
//! NOTE: a table streamed from a walk is walked twice, its columns
//! measured, then its rows written (holding a million rows is memory
//! unbounded). Measured through their text, the `--full` table of a tree
//! of 2²⁰ instances formatted its 17 million numbers twice and copied
//! every row through a `Cells` (issue 33, item 3).

use super::blocks::{self, Block};
use super::{Cells, Fit, RowSink, cell_width, push_rule, push_spaces, stream_table};
use crate::output::format::{
    ascii_name, ascii_name_width, count_len, extend_ascii_name, extend_count, extend_percent,
    extend_sig, percent_is_ascii, percent_width, push_name, push_percent, push_sig, sig_width,
};
use std::io::Write;
use unicode_width::UnicodeWidthStr;

/// A cell of a streamed table, as its source hands it out.
#[derive(Debug, Clone, Copy)]
pub enum Cell<'a> {
    /// Text shown as it is.
    Text(&'a str),
    /// A name from input, shown as `push_name` shows it.
    Name(&'a str),
    /// A name from input after `n` indents of two spaces (a sub-assembly
    /// by its depth), as `push_name` shows it.
    Indented(usize, &'a str),
    /// A count, in decimal.
    Count(usize),
    /// A number to `digits` significant digits, as `push_sig` writes it.
    Sig(f64, usize),
    /// A fraction as a percentage, as `push_percent` writes it.
    Percent(Option<f64>),
}

/// A row's cells, handed to the table.
pub type CellSink<'a> = dyn FnMut(&[Cell<'_>]) + 'a;

impl Cell<'_> {
    /// Its text after `out`.
    fn push(&self, out: &mut String) {
        match *self {
            Cell::Text(t) => out.push_str(t),
            Cell::Name(t) => push_name(out, t),
            Cell::Indented(n, t) => {
                push_spaces(out, 2 * n);
                push_name(out, t);
            }
            Cell::Count(n) => push_count(out, n),
            Cell::Sig(x, digits) => push_sig(out, x, digits),
            Cell::Percent(f) => push_percent(out, f),
        }
    }

    /// Its text after bytes: numbers and names of printable ASCII written
    /// straight into `out`, anything else through `scratch`.
    fn extend(&self, out: &mut Vec<u8>, scratch: &mut String) {
        match *self {
            Cell::Text(t) => out.extend_from_slice(t.as_bytes()),
            Cell::Count(n) => extend_count(out, n),
            Cell::Sig(x, digits) => extend_sig(out, x, digits),
            Cell::Percent(f) => extend_percent(out, f),
            Cell::Name(t) | Cell::Indented(_, t) => match ascii_name(t) {
                Some(shown) => {
                    out.resize(out.len() + self.indent(), b' ');
                    extend_ascii_name(out, shown);
                }
                None => {
                    scratch.clear();
                    self.push(scratch);
                    out.extend_from_slice(scratch.as_bytes());
                }
            },
        }
    }

    /// The columns before a name: two spaces an indent.
    fn indent(&self) -> usize {
        match *self {
            Cell::Indented(n, _) => 2 * n,
            Cell::Text(_) | Cell::Name(_) | Cell::Count(_) | Cell::Sig(..) | Cell::Percent(_) => 0,
        }
    }

    /// The columns its text takes, as `cell_width` measures the text:
    /// numbers from their digits, a name of printable ASCII from its
    /// length, anything else from its text written into `scratch`.
    fn width(&self, scratch: &mut String) -> usize {
        match *self {
            Cell::Count(n) => count_len(n),
            Cell::Sig(x, digits) => sig_width(x, digits),
            Cell::Percent(f) => percent_width(f),
            Cell::Text(t) => cell_width(t),
            Cell::Name(t) | Cell::Indented(_, t) => match ascii_name(t) {
                Some(shown) => self.indent() + ascii_name_width(shown),
                None => {
                    scratch.clear();
                    self.push(scratch);
                    cell_width(scratch)
                }
            },
        }
    }

    /// Whether its text has a line break (which sends the table through
    /// comfy-table): only text shown as it is can (`push_name` shows a
    /// break as a picture).
    fn breaks(&self) -> bool {
        match *self {
            Cell::Text(t) => t.contains('\n'),
            Cell::Name(_)
            | Cell::Indented(..)
            | Cell::Count(_)
            | Cell::Sig(..)
            | Cell::Percent(_) => false,
        }
    }

    /// Its text after `out`, padded to `width` columns on the left
    /// (`right`) or on the right.
    fn extend_padded(&self, out: &mut Vec<u8>, width: usize, right: bool, scratch: &mut String) {
        let start = out.len();
        // A number's text is ASCII: as wide as it is long, measured once
        // written; anything else measured first.
        let w = match *self {
            Cell::Count(_) | Cell::Sig(..) => None,
            Cell::Percent(f) if percent_is_ascii(f) => None,
            Cell::Percent(_) | Cell::Text(_) | Cell::Name(_) | Cell::Indented(..) => {
                Some(self.width(scratch))
            }
        };
        self.extend(out, scratch);
        let pad = width - w.unwrap_or(out.len() - start);
        out.resize(out.len() + pad, b' ');
        if right {
            out[start..].rotate_right(pad);
        }
    }
}

/// `n` in decimal after `out`.
fn push_count(out: &mut String, n: usize) {
    let mut bytes = Vec::with_capacity(20);
    extend_count(&mut bytes, n);
    out.push_str(std::str::from_utf8(&bytes).expect("invariant: ASCII digits"));
}

/// `stream_table` for rows of typed cells: `rows` is called once to
/// measure the columns, then once for each part of the table (once,
/// unless it is split to `fit`), and each time hands every row, in order,
/// to the function it is given. The output is `stream_table`'s of the
/// cells' text; a table with a line break in its header or a cell goes
/// through it. On two cores the rows are measured and formatted on both
/// (`blocks`), the same bytes.
pub fn stream_cells(
    out: &mut dyn Write,
    header: &[String],
    right: &[bool],
    fit: Fit,
    rows: &mut dyn FnMut(&mut CellSink<'_>),
) -> std::io::Result<()> {
    let n = header.len();
    let two = blocks::threads() > 1;
    let mut scratch = String::new();
    let mut breaks = header.iter().any(|h| h.contains('\n'));
    // As `stream_table` measures: the header's width, at least one column.
    let mut widths: Vec<usize> = header.iter().map(|h| h.width().max(1)).collect();
    if !breaks && two {
        let work = |block: &Block| {
            let mut widths = vec![0; n];
            let mut breaks = false;
            let mut scratch = String::new();
            block.each(&mut |row| measure(row, &mut widths, &mut breaks, &mut scratch));
            (widths, breaks)
        };
        blocks::in_blocks(rows, &work, &mut |(w, b)| {
            for (all, w) in widths.iter_mut().zip(w) {
                *all = (*all).max(w);
            }
            breaks |= b;
            Ok(())
        })?;
    } else if !breaks {
        rows(&mut |row| measure(row, &mut widths, &mut breaks, &mut scratch));
    }
    if breaks {
        let mut cells = Cells::with_capacity(n);
        return stream_table(out, header, right, fit, &mut |sink: &mut RowSink<'_>| {
            rows(&mut |row| {
                cells.clear();
                for c in row {
                    c.push(&mut cells.text);
                    cells.end();
                }
                sink(&cells);
            });
        });
    }
    let parts = fit.parts(&widths);
    for cols in &parts {
        let part = Part {
            right,
            widths: &widths,
            cols,
        };
        part.write(out, header, rows, two, &mut scratch)?;
    }
    if parts.len() > 1 {
        out.write_all(fit.note(parts.len()).as_bytes())?;
    }
    Ok(())
}

/// A row's cells measured into `widths`; `breaks` if one has a line break.
fn measure(row: &[Cell<'_>], widths: &mut [usize], breaks: &mut bool, scratch: &mut String) {
    debug_assert_eq!(row.len(), widths.len(), "invariant: whole rows of cells");
    for (w, c) in widths.iter_mut().zip(row) {
        *w = (*w).max(c.width(scratch));
        *breaks |= c.breaks();
    }
}

/// The columns `cols` of the table, `widths` wide.
struct Part<'a> {
    right: &'a [bool],
    widths: &'a [usize],
    cols: &'a [usize],
}

impl Part<'_> {
    /// A row's line after `buf`.
    fn line(&self, buf: &mut Vec<u8>, row: &[Cell<'_>], scratch: &mut String) {
        let last = *self.cols.last().expect("invariant: a part has a column");
        buf.extend_from_slice("│".as_bytes());
        for &i in self.cols {
            buf.push(b' ');
            row[i].extend_padded(buf, self.widths[i], self.right[i], scratch);
            buf.extend_from_slice(if i == last { " │" } else { " ┆" }.as_bytes());
        }
        buf.push(b'\n');
    }

    /// A rule after `buf`.
    fn rule(&self, buf: &mut Vec<u8>, chars: [char; 4]) {
        let mut text = String::new();
        push_rule(&mut text, self.widths, self.cols, chars);
        buf.extend_from_slice(text.as_bytes());
    }

    /// The part, its rows formatted here or (`two`) on two threads.
    fn write(
        &self,
        out: &mut dyn Write,
        header: &[String],
        rows: &mut dyn FnMut(&mut CellSink<'_>),
        two: bool,
        scratch: &mut String,
    ) -> std::io::Result<()> {
        // Written in pieces of about this many bytes.
        const PIECE: usize = 1 << 16;
        let mut buf = Vec::with_capacity(PIECE + 1024);
        self.rule(&mut buf, ['┌', '─', '┬', '┐']);
        let titles: Vec<Cell<'_>> = header.iter().map(|h| Cell::Text(h)).collect();
        self.line(&mut buf, &titles, scratch);
        self.rule(&mut buf, ['╞', '═', '╪', '╡']);
        if two {
            out.write_all(&buf)?;
            buf.clear();
            // NOTE: a block's bytes (~250 kB) are kept for the next block
            // once written: a fresh buffer that size is a fresh mapping,
            // its pages faulted in again each time.
            let spare = std::sync::Mutex::new(Vec::<Vec<u8>>::new());
            let work = |block: &Block| {
                let mut bytes = spare
                    .lock()
                    .ok()
                    .and_then(|mut s| s.pop())
                    .unwrap_or_default();
                let mut scratch = String::new();
                block.each(&mut |row| self.line(&mut bytes, row, &mut scratch));
                bytes
            };
            blocks::in_blocks(rows, &work, &mut |mut bytes| {
                out.write_all(&bytes)?;
                bytes.clear();
                if let Ok(mut s) = spare.lock() {
                    s.push(bytes);
                }
                Ok(())
            })?;
        } else {
            let mut failed = Ok(());
            rows(&mut |row| {
                // NOTE: after a failed write (a closed pipe) nothing more is
                // made: the walk runs out without formatting the rows left.
                if failed.is_err() {
                    return;
                }
                self.line(&mut buf, row, scratch);
                if buf.len() >= PIECE {
                    failed = out.write_all(&buf);
                    buf.clear();
                }
            });
            failed?;
        }
        self.rule(&mut buf, ['└', '─', '┴', '┘']);
        out.write_all(&buf)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A few rows of every kind of cell, and the same rows as text.
    fn rows() -> Vec<Vec<Cell<'static>>> {
        vec![
            vec![
                Cell::Count(1),
                Cell::Name("base plate"),
                Cell::Text("box"),
                Cell::Sig(1.25, 6),
                Cell::Percent(Some(0.031_25)),
                Cell::Indented(2, "wheel #2"),
            ],
            vec![
                Cell::Count(12_345),
                Cell::Name("bolt\u{1b}[31m 漢字"),
                Cell::Text("cylinder"),
                Cell::Sig(-0.000_123_456_789, 6),
                Cell::Percent(None),
                Cell::Indented(0, "é"),
            ],
            vec![
                Cell::Count(0),
                Cell::Name(""),
                Cell::Text(""),
                Cell::Sig(0.0, 6),
                Cell::Percent(Some(f64::MAX)),
                Cell::Indented(1, "##[x]"),
            ],
        ]
    }

    fn header() -> Vec<String> {
        ["#", "name", "shape", "mass (kg)", "share", "sub-assembly"]
            .map(String::from)
            .to_vec()
    }

    const RIGHT: [bool; 6] = [true, false, false, true, true, false];

    fn through_cells(fit: Fit, right: &[bool]) -> String {
        let mut out = Vec::new();
        let rows = rows();
        stream_cells(&mut out, &header(), right, fit, &mut |sink| {
            for r in &rows {
                sink(r);
            }
        })
        .unwrap();
        String::from_utf8(out).unwrap()
    }

    fn through_text(fit: Fit, right: &[bool]) -> String {
        let mut out = Vec::new();
        let rows = rows();
        let mut cells = Cells::with_capacity(0);
        stream_table(&mut out, &header(), right, fit, &mut |sink| {
            for r in &rows {
                cells.clear();
                for c in r {
                    c.push(&mut cells.text);
                    cells.end();
                }
                sink(&cells);
            }
        })
        .unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn typed_cells_print_as_their_text_prints() {
        assert_eq!(
            through_cells(Fit::WHOLE, &RIGHT),
            through_text(Fit::WHOLE, &RIGHT)
        );
    }

    #[test]
    fn typed_cells_split_to_a_width_as_their_text_splits() {
        for width in [20, 40, 60] {
            let fit = Fit::new(Some(width), 2);
            assert_eq!(through_cells(fit, &RIGHT), through_text(fit, &RIGHT));
        }
    }

    #[test]
    fn text_aligned_right_is_padded_on_its_left() {
        let right = [true; 6];
        assert_eq!(
            through_cells(Fit::WHOLE, &right),
            through_text(Fit::WHOLE, &right)
        );
    }

    #[test]
    fn a_line_break_in_a_text_cell_goes_through_comfy_table_as_before() {
        let mut out = Vec::new();
        let header = ["a", "b"].map(String::from);
        stream_cells(&mut out, &header, &[false, true], Fit::WHOLE, &mut |sink| {
            sink(&[Cell::Text("two\nlines"), Cell::Sig(2.5, 6)]);
        })
        .unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.contains("│ two   ┆ 2.5 │"), "{text}");
        assert!(text.contains("│ lines ┆     │"), "{text}");
    }

    #[test]
    fn counts_are_written_and_measured_in_decimal() {
        for n in [0, 7, 10, 99, 100, 12_345, usize::MAX] {
            let mut s = String::new();
            push_count(&mut s, n);
            assert_eq!(s, n.to_string());
            assert_eq!(count_len(n), s.len());
        }
    }

    /// A random cell of every kind: names of any characters and of any
    /// length around the limit a name is cut at, numbers of any bits.
    fn any_cell() -> impl proptest::strategy::Strategy<Value = (u8, String, f64, usize)> {
        use proptest::prelude::*;
        let text = prop_oneof![
            "[ -~]{0,12}",
            ".{0,8}",
            "[a-z /#\\[]{90,110}",
            "(漢|e\u{301}|\u{1b}|##\\[|a){95,105}",
        ];
        let number = prop_oneof![
            any::<u64>().prop_map(f64::from_bits),
            (any::<i32>(), -8i32..8).prop_map(|(m, e)| f64::from(m) * 10f64.powi(e)),
            Just(0.0),
        ];
        (0u8..6, text, number, 0usize..4)
    }

    fn cell_of((kind, text, x, n): &(u8, String, f64, usize)) -> Cell<'_> {
        match kind {
            0 => Cell::Text(text),
            1 => Cell::Name(text),
            2 => Cell::Indented(*n, text),
            3 => Cell::Count(x.to_bits() as usize),
            4 => Cell::Sig(*x, 1 + n * 2),
            _ => Cell::Percent(Some(*x).filter(|_| *n > 0)),
        }
    }

    #[test]
    fn random_typed_rows_print_as_their_text_prints() {
        use proptest::prelude::*;
        use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
        let mut runner = TestRunner::new_with_rng(
            Config::with_cases(500),
            TestRng::deterministic_rng(RngAlgorithm::ChaCha),
        );
        let table = (1usize..5).prop_flat_map(|n| {
            (
                prop::collection::vec(prop::collection::vec(any_cell(), n), 0..5),
                prop::collection::vec(any::<bool>(), n),
                prop::option::of(10usize..80),
            )
        });
        runner
            .run(&table, |(rows, right, width)| {
                let n = right.len();
                let header: Vec<String> = (0..n).map(|i| format!("c{i}")).collect();
                let fit = Fit::new(width, 1);
                let typed: Vec<Vec<Cell<'_>>> = rows
                    .iter()
                    .map(|r| r.iter().map(cell_of).collect())
                    .collect();
                let mut ours = Vec::new();
                stream_cells(&mut ours, &header, &right, fit, &mut |sink| {
                    typed.iter().for_each(|r| sink(r));
                })
                .unwrap();
                let mut theirs = Vec::new();
                let mut cells = Cells::with_capacity(0);
                stream_table(&mut theirs, &header, &right, fit, &mut |sink| {
                    for r in &typed {
                        cells.clear();
                        for c in r {
                            c.push(&mut cells.text);
                            cells.end();
                        }
                        sink(&cells);
                    }
                })
                .unwrap();
                prop_assert_eq!(String::from_utf8(ours), String::from_utf8(theirs));
                Ok(())
            })
            .unwrap();
    }
}
