//! The one table writer: comfy-table in massprop's style for every table,
//! and a hand-written writer for tables of a row per part (see
//! `write_table`), pinned byte for byte against comfy-table in the tests.

use comfy_table::{CellAlignment, Table, presets};
use std::fmt::Write;
use unicode_width::UnicodeWidthStr;

/// A table in the style every massprop table uses.
pub fn new_table() -> Table {
    let mut t = Table::new();
    t.load_style(presets::UTF8_FULL_CONDENSED);
    t
}

/// Align the columns from `from` on to the right (numbers).
pub fn right_align(t: &mut Table, from: usize) {
    for (i, c) in t.column_iter_mut().enumerate() {
        if i >= from {
            c.set_cell_alignment(CellAlignment::Right);
        }
    }
}

/// The text of a table's cells, row after row, in one buffer.
pub struct Cells {
    pub text: String,
    ends: Vec<usize>,
}

impl Cells {
    pub fn with_capacity(n: usize) -> Cells {
        Cells {
            text: String::with_capacity(n * 12),
            ends: Vec::with_capacity(n),
        }
    }

    /// Close the cell written since the last call.
    pub fn end(&mut self) {
        self.ends.push(self.text.len());
    }

    fn iter(&self) -> impl Iterator<Item = &str> {
        let starts = std::iter::once(0).chain(self.ends.iter().copied());
        starts.zip(&self.ends).map(|(a, b)| &self.text[a..*b])
    }
}

/// Write a table exactly as comfy-table prints it in `new_table`'s style
/// (columns as wide as their widest cell, one space of padding, no row
/// separators; `right[i]` aligns column i right), then a newline.
///
/// NOTE: the parts table has a row per part, 100,000 and more: through
/// comfy-table (a `String` and several `Vec`s per cell and per line) it
/// took 0.44 s for 100,000 parts, more than the rest of `report` after
/// parsing; written here, 0.1 s. Tables with a line break in a cell
/// (comfy-table splits those into lines) or a column wider than comfy-table
/// measures (u16) still go through comfy-table.
pub fn write_table(out: &mut String, header: &[String], cells: &Cells, right: &[bool]) {
    let n = header.len();
    let mut widths: Vec<usize> = header.iter().map(|h| h.width().max(1)).collect();
    let mut multiline = false;
    for (i, c) in cells.iter().enumerate() {
        multiline |= c.contains('\n');
        let w = &mut widths[i % n];
        *w = (*w).max(c.width());
    }
    if multiline || widths.iter().any(|w| *w > usize::from(u16::MAX)) {
        let mut t = new_table();
        t.set_header(header.to_vec());
        let all: Vec<&str> = cells.iter().collect();
        for row in all.chunks(n) {
            t.add_row(row.to_vec());
        }
        for (c, r) in t.column_iter_mut().zip(right) {
            if *r {
                c.set_cell_alignment(CellAlignment::Right);
            }
        }
        let _ = writeln!(out, "{t}");
        return;
    }
    let rule = |out: &mut String, [left, fill, junction, end]: [char; 4]| {
        out.push(left);
        for (i, w) in widths.iter().enumerate() {
            if i > 0 {
                out.push(junction);
            }
            out.extend(std::iter::repeat_n(fill, w + 2));
        }
        out.push(end);
        out.push('\n');
    };
    let row = |out: &mut String, row: &mut dyn Iterator<Item = &str>| {
        out.push('│');
        for (i, c) in row.enumerate() {
            let pad = widths[i] - c.width();
            out.push(' ');
            if right[i] {
                out.extend(std::iter::repeat_n(' ', pad));
                out.push_str(c);
            } else {
                out.push_str(c);
                out.extend(std::iter::repeat_n(' ', pad));
            }
            out.push(' ');
            out.push(if i + 1 < n { '┆' } else { '│' });
        }
        out.push('\n');
    };
    out.reserve(cells.text.len() + cells.ends.len() * 8);
    rule(out, ['┌', '─', '┬', '┐']);
    row(out, &mut header.iter().map(String::as_str));
    rule(out, ['╞', '═', '╪', '╡']);
    let mut it = cells.iter();
    for _ in 0..cells.ends.len() / n {
        row(out, &mut it.by_ref().take(n));
    }
    rule(out, ['└', '─', '┴', '┘']);
}
