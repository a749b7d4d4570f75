//! The one table writer: comfy-table in massprop's style for every table,
//! and a hand-written writer for tables of a row per part (see
//! `write_table`), pinned byte for byte against comfy-table in the tests.

use comfy_table::{CellAlignment, Table, presets};
use std::ops::Range;

use unicode_width::UnicodeWidthStr;

mod blocks;
mod typed;
pub use blocks::with_threads;
pub use typed::{Cell, CellSink, stream_cells};

/// A table in the style every massprop table uses.
pub fn new_table() -> Table {
    let mut t = Table::new();
    t.load_style(presets::UTF8_FULL_CONDENSED);
    t
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

    /// Empty again, its memory kept.
    pub fn clear(&mut self) {
        self.text.clear();
        self.ends.clear();
    }

    fn append(&mut self, other: &Cells) {
        let base = self.text.len();
        self.text.push_str(&other.text);
        self.ends.extend(other.ends.iter().map(|e| e + base));
    }

    fn iter(&self) -> impl Iterator<Item = &str> {
        let starts = std::iter::once(0).chain(self.ends.iter().copied());
        starts.zip(&self.ends).map(|(a, b)| &self.text[a..*b])
    }
}

/// How wide a table may be. A table wider than `width` is split into
/// parts, each a table of its own with the rows' labels (its first `keys`
/// columns) and as many of the other columns, in order, as fit (at least
/// one; the columns of a group together where they fit), as R and pandas
/// print a wide data frame, and a note says so: a number is never cut and
/// no column is hidden. (A part may still be wider than `width` when its
/// labels and one column are.)
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Fit {
    /// The most columns a line of the table may take; none: no limit.
    pub width: Option<usize>,
    /// How many of the first columns every part repeats.
    pub keys: usize,
    /// Columns kept in one part where they fit (a vector's x, y and z):
    /// each group its first column and the column after its last, as a
    /// range is written (a one-element array of ranges reads as a mistake
    /// to clippy).
    pub groups: &'static [(usize, usize)],
}

impl Fit {
    /// No limit: the table whole, however wide.
    pub const WHOLE: Fit = Fit {
        width: None,
        keys: 0,
        groups: &[],
    };

    /// Within `width`, each part with the first `keys` columns.
    pub fn new(width: Option<usize>, keys: usize) -> Fit {
        Fit {
            width,
            keys,
            groups: &[],
        }
    }

    /// The columns of each part, given each column's width: all of them
    /// in one part when the table fits.
    fn parts(&self, widths: &[usize]) -> Vec<Vec<usize>> {
        let n = widths.len();
        // A line: a border, then for each column a space, the cell, a
        // space and a border.
        let span = |cols: Range<usize>| cols.map(|i| widths[i] + 3).sum::<usize>();
        let Some(limit) = self.width else {
            return vec![(0..n).collect()];
        };
        // The whole line, its first border with it, is 1 + span(0..n).
        if span(0..n) < limit {
            return vec![(0..n).collect()];
        }
        let keys = self.keys.min(n.saturating_sub(1));
        let labels = 1 + span(0..keys);
        // The columns after the keys in blocks: a group that fits in a part
        // beside the labels, or a single column.
        let mut blocks: Vec<Range<usize>> = Vec::new();
        let mut i = keys;
        while i < n {
            let group = self
                .groups
                .iter()
                .map(|&(start, end)| start..end)
                .find(|g| g.start == i && g.end <= n && labels + span(g.clone()) <= limit);
            let block = group.unwrap_or(i..i + 1);
            i = block.end;
            blocks.push(block);
        }
        let mut parts = Vec::new();
        let mut part: Vec<usize> = (0..keys).collect();
        let mut used = labels;
        for block in blocks {
            let more = span(block.clone());
            if part.len() > keys && used + more > limit {
                parts.push(std::mem::replace(&mut part, (0..keys).collect()));
                used = labels;
            }
            part.extend(block);
            used += more;
        }
        parts.push(part);
        parts
    }

    /// The line after a table split into `parts`.
    fn note(&self, parts: usize) -> String {
        let width = self.width.unwrap_or_default();
        format!(
            "note: table split into {parts} to fit {width} columns; --width 0 prints it whole\n"
        )
    }
}

/// Write a table exactly as comfy-table prints it in `new_table`'s style
/// (columns as wide as their widest cell, one space of padding, no row
/// separators; `right[i]` aligns column i right), then a newline; split
/// to `fit` if it is wider.
///
/// NOTE: the parts table has a row per part, 100,000 and more: through
/// comfy-table (a `String` and several `Vec`s per cell and per line) it
/// took 0.44 s for 100,000 parts, more than the rest of `report` after
/// parsing; written here, 0.1 s. Tables with a line break in a cell or in
/// the header (comfy-table splits those into lines) still go through
/// comfy-table. Columns wider than comfy-table can hold do not: it keeps a
/// column's width with its padding in a u16, which saturates at 65,535
/// (its borders come out shorter than its rows), and it wraps wider content
/// in time quadratic in its length (a 20 MB part name took 5.5 s); written
/// here such a column is as wide as its content, in linear time, and the
/// table keeps its shape. Widths are unicode-width's `str::width`, as comfy-table's are
/// (wide CJK characters 2, combining marks 0, an emoji ZWJ sequence or a
/// flag 2, a tab 1): the same function, so the same columns, whatever a
/// terminal makes of them.
pub fn write_table(out: &mut String, header: &[String], cells: &Cells, right: &[bool], fit: Fit) {
    let mut bytes = Vec::new();
    stream_table(&mut bytes, header, right, fit, &mut |row| row(cells))
        .expect("invariant: writing to memory does not fail");
    out.push_str(std::str::from_utf8(&bytes).expect("invariant: the table is UTF-8"));
}

/// `write_table` of a few rows, each a `Vec` of its cells.
pub fn write_rows(
    out: &mut String,
    header: &[String],
    rows: &[Vec<String>],
    right: &[bool],
    fit: Fit,
) {
    let mut cells = Cells::with_capacity(rows.len() * header.len());
    for cell in rows.iter().flatten() {
        cells.text.push_str(cell);
        cells.end();
    }
    write_table(out, header, &cells, right, fit);
}

/// Rows handed out by a table's source, one `Cells` at a time.
pub type RowSink<'a> = dyn FnMut(&Cells) + 'a;

/// `write_table` for a table too long to hold in memory (a row per part of
/// a body of 2²⁰ parts): `rows` is called once to measure the columns, then
/// once for each part of the table (once, unless it is split to `fit`),
/// and each time hands every row, in order, to the function it is given (a
/// `Cells` of whole rows, reused as it likes). The output is the same as
/// `write_table`'s.
pub fn stream_table(
    out: &mut dyn std::io::Write,
    header: &[String],
    right: &[bool],
    fit: Fit,
    rows: &mut dyn FnMut(&mut RowSink<'_>),
) -> std::io::Result<()> {
    assert!(
        !header.is_empty(),
        "invariant: every massprop table has a header (its cells are laid out by it)"
    );
    let n = header.len();
    let mut widths: Vec<usize> = header.iter().map(|h| h.width().max(1)).collect();
    // The widest line of each column's cells, where a cell has line breaks
    // (the width comfy-table lays it out in).
    let mut lines = vec![1; n];
    let mut multiline = false;
    let mut measure = |i: usize, c: &str| {
        let w = cell_width(c);
        widths[i] = widths[i].max(w);
        if !printable_ascii(c) && c.contains('\n') {
            multiline = true;
            lines[i] = lines[i].max(c.split('\n').map(str::width).max().unwrap_or(0));
        } else {
            lines[i] = lines[i].max(w);
        }
    };
    for (i, h) in header.iter().enumerate() {
        measure(i, h);
    }
    rows(&mut |cells| {
        debug_assert!(
            cells.ends.len().is_multiple_of(n),
            "invariant: whole rows of cells"
        );
        for (i, c) in cells.iter().enumerate() {
            measure(i % n, c);
        }
    });
    let parts = fit.parts(if multiline { &lines } else { &widths });
    if multiline {
        let mut all = Cells::with_capacity(0);
        rows(&mut |cells| all.append(cells));
        for cols in &parts {
            writeln!(out, "{}", comfy(header, &all, right, cols))?;
        }
    } else {
        for cols in &parts {
            write_part(out, header, right, &widths, cols, rows)?;
        }
    }
    if parts.len() > 1 {
        out.write_all(fit.note(parts.len()).as_bytes())?;
    }
    Ok(())
}

/// The columns `cols` of a table whose cells have no line breaks, columns
/// `widths` wide.
fn write_part(
    out: &mut dyn std::io::Write,
    header: &[String],
    right: &[bool],
    widths: &[usize],
    cols: &[usize],
    rows: &mut dyn FnMut(&mut RowSink<'_>),
) -> std::io::Result<()> {
    let n = header.len();
    let mut shown = vec![false; n];
    for &i in cols {
        shown[i] = true;
    }
    let last = *cols.last().expect("invariant: a part has a column");
    let rule = |out: &mut String, chars: [char; 4]| push_rule(out, widths, cols, chars);
    let row = |out: &mut String, row: &mut dyn Iterator<Item = &str>| {
        out.push('│');
        for (i, c) in row.enumerate() {
            if !shown[i] {
                continue;
            }
            let pad = widths[i] - cell_width(c);
            out.push(' ');
            if right[i] {
                push_spaces(out, pad);
                out.push_str(c);
            } else {
                out.push_str(c);
                push_spaces(out, pad);
            }
            out.push(' ');
            out.push(if i == last { '│' } else { '┆' });
        }
        out.push('\n');
    };
    // Written in pieces of about this many bytes.
    const PIECE: usize = 1 << 16;
    let mut buf = String::with_capacity(PIECE);
    rule(&mut buf, ['┌', '─', '┬', '┐']);
    row(&mut buf, &mut header.iter().map(String::as_str));
    rule(&mut buf, ['╞', '═', '╪', '╡']);
    let mut failed = Ok(());
    rows(&mut |cells| {
        let mut it = cells.iter();
        for _ in 0..cells.ends.len() / n {
            row(&mut buf, &mut it.by_ref().take(n));
        }
        if buf.len() >= PIECE && failed.is_ok() {
            failed = out.write_all(buf.as_bytes());
            buf.clear();
        }
    });
    failed?;
    rule(&mut buf, ['└', '─', '┴', '┘']);
    out.write_all(buf.as_bytes())
}

/// A rule of the columns `cols`, `widths` wide: its left end, its line,
/// the junctions between columns and its right end, then a newline.
fn push_rule(out: &mut String, widths: &[usize], cols: &[usize], chars: [char; 4]) {
    let [left, fill, junction, end] = chars;
    out.push(left);
    for (k, &i) in cols.iter().enumerate() {
        if k > 0 {
            out.push(junction);
        }
        out.extend(std::iter::repeat_n(fill, widths[i] + 2));
    }
    out.push(end);
    out.push('\n');
}

/// Whether `c` is printable ASCII alone: a column a character, no break.
fn printable_ascii(c: &str) -> bool {
    c.bytes().all(|b| (0x20..0x7f).contains(&b))
}

/// The columns `c` takes: `width()`, which is its length in bytes for
/// printable ASCII (what almost every cell of a row per part is: the
/// table of 2²⁰ parts measures and pads 22 million cells).
fn cell_width(c: &str) -> usize {
    if printable_ascii(c) {
        c.len()
    } else {
        c.width()
    }
}

/// `n` spaces after `out`, as `str`s rather than char by char.
fn push_spaces(out: &mut String, mut n: usize) {
    const SPACES: &str = "                                ";
    while n > 0 {
        let k = n.min(SPACES.len());
        out.push_str(&SPACES[..k]);
        n -= k;
    }
}

/// The columns `cols` of a table with a line break in a cell or in the
/// header, through comfy-table (which splits those into lines).
fn comfy(header: &[String], cells: &Cells, right: &[bool], cols: &[usize]) -> Table {
    let n = header.len();
    let mut t = new_table();
    t.set_header(cols.iter().map(|&i| header[i].as_str()));
    let all: Vec<&str> = cells.iter().collect();
    for row in all.chunks(n) {
        t.add_row(cols.iter().map(|&i| row[i]));
    }
    for (c, &i) in t.column_iter_mut().zip(cols) {
        if right[i] {
            c.set_cell_alignment(CellAlignment::Right);
        }
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

    /// The table as comfy-table prints it: `new_table()`'s style, the
    /// header, the rows, and `right[i]` aligning column i right; then the
    /// newline `write_table` ends with.
    fn comfy(header: &[&str], rows: &[Vec<&str>], right: &[bool]) -> String {
        let mut t = new_table();
        t.set_header(header.to_vec());
        for row in rows {
            t.add_row(row.clone());
        }
        for (column, r) in t.column_iter_mut().zip(right) {
            if *r {
                column.set_cell_alignment(CellAlignment::Right);
            }
        }
        format!("{t}\n")
    }

    /// The same table through `write_table`.
    fn written(header: &[&str], rows: &[Vec<&str>], right: &[bool]) -> String {
        let header: Vec<String> = header.iter().map(|h| h.to_string()).collect();
        let mut cells = Cells::with_capacity(rows.len() * header.len());
        for cell in rows.iter().flatten() {
            cells.text.push_str(cell);
            cells.end();
        }
        let mut out = String::new();
        write_table(&mut out, &header, &cells, right, Fit::WHOLE);
        out
    }

    /// `write_table` prints, byte for byte, what comfy-table prints.
    fn same_as_comfy_table(header: &[&str], rows: &[Vec<&str>], right: &[bool]) {
        let ours = written(header, rows, right);
        let theirs = comfy(header, rows, right);
        if ours == theirs {
            return;
        }
        let first = ours.lines().zip(theirs.lines()).position(|(a, b)| a != b);
        let short = |text: &str| text.chars().take(200).collect::<String>();
        let line = |text: &str| short(first.and_then(|i| text.lines().nth(i)).unwrap_or_default());
        panic!(
            "write_table differs from comfy-table for header {:?}, right {right:?}, {} rows \
             (widest cell {} columns); first differing line {first:?}:\n  write_table: {:?}\n  comfy-table: {:?}\n\
             write_table:\n{}\ncomfy-table:\n{}",
            header.iter().map(|h| short(h)).collect::<Vec<_>>(),
            rows.len(),
            rows.iter().flatten().map(|c| c.width()).max().unwrap_or(0),
            line(&ours),
            line(&theirs),
            short(&ours),
            short(&theirs),
        );
    }

    #[test]
    fn an_ascii_table_prints_as_comfy_table_prints_it() {
        same_as_comfy_table(
            &["part", "shape", "mass [kg]", "x [m]"],
            &[
                vec!["base plate", "plate", "1.25", "-0.5"],
                vec!["bolt", "rod", "0.012", "10"],
                vec!["a much longer part name", "box", "100", "0"],
            ],
            &[false, false, true, true],
        );
    }

    #[test]
    fn wide_cjk_characters_take_two_columns_as_in_comfy_table() {
        same_as_comfy_table(
            &["部品", "質量"],
            &[
                vec!["底板", "1.5"],
                vec!["ﾎﾞﾙﾄ", "２０"],
                vec!["a", "漢字漢字漢字"],
            ],
            &[false, true],
        );
    }

    #[test]
    fn combining_marks_take_no_column_as_in_comfy_table() {
        same_as_comfy_table(
            &["name", "n"],
            &[
                vec!["e\u{301}", "1"],
                vec!["cafe\u{301} cre\u{300}me", "2"],
                vec!["a\u{301}\u{302}\u{303}\u{304}", "3"],
                vec!["\u{301}", "4"],
            ],
            &[false, true],
        );
    }

    #[test]
    fn emoji_take_the_columns_comfy_table_gives_them() {
        // A crab; a ZWJ sequence (woman scientist) and a family; a flag
        // (two regional indicators) and a lone regional indicator; an emoji
        // with a skin-tone modifier; a heart with and without the emoji
        // variation selector; a keycap.
        let emoji = [
            "🦀",
            "👩\u{200d}🔬",
            "👨\u{200d}👩\u{200d}👧\u{200d}👦",
            "🇫🇷",
            "🇫",
            "👍🏽",
            "❤\u{fe0f}",
            "❤",
            "1\u{fe0f}\u{20e3}",
        ];
        let rows: Vec<Vec<&str>> = emoji.iter().map(|e| vec![*e, *e, "x"]).collect();
        same_as_comfy_table(&["left", "right", "x"], &rows, &[false, true, false]);
    }

    #[test]
    fn tabs_count_as_unicode_width_counts_them_as_in_comfy_table() {
        same_as_comfy_table(
            &["a\tb", "c"],
            &[vec!["\t", "x\ty"], vec!["1", "\t\t"]],
            &[false, true],
        );
    }

    #[test]
    fn empty_cells_and_headers_make_columns_one_wide_as_in_comfy_table() {
        same_as_comfy_table(
            &["", "b", ""],
            &[vec!["", "", ""], vec!["", "x", ""]],
            &[false, true, true],
        );
    }

    #[test]
    fn a_header_without_rows_prints_as_in_comfy_table() {
        same_as_comfy_table(&["part", "mass"], &[], &[false, true]);
    }

    #[test]
    fn a_single_column_prints_as_in_comfy_table() {
        same_as_comfy_table(&["only"], &[vec!["1"], vec!["22"], vec![""]], &[true]);
        same_as_comfy_table(&["only"], &[vec!["1"], vec!["22"]], &[false]);
    }

    #[test]
    fn a_multi_line_cell_goes_through_comfy_table() {
        same_as_comfy_table(
            &["part", "mass"],
            &[vec!["two\nlines", "1"], vec!["one", "2\n3\n4"]],
            &[false, true],
        );
    }

    #[test]
    fn control_and_zero_width_characters_print_as_in_comfy_table() {
        same_as_comfy_table(
            &["a", "b"],
            &[
                vec!["\r", "x\u{200b}y"],
                vec!["\u{1b}[1m", "\u{ad}"],
                vec!["\u{feff}", "\u{0}"],
            ],
            &[false, true],
        );
    }

    #[test]
    fn a_line_break_in_the_header_goes_through_comfy_table() {
        same_as_comfy_table(&["mass\n[kg]", "n"], &[vec!["1", "2"]], &[true, false]);
        same_as_comfy_table(&["mass\n[kg]", "n"], &[], &[true, false]);
    }

    #[test]
    fn columns_up_to_comfy_tables_u16_width_limit_print_as_in_comfy_table() {
        // comfy-table keeps a column's width with its padding in a u16:
        // 65,533 columns of content is the widest it holds.
        for width in [65_531, 65_532, 65_533] {
            let wide = "a".repeat(width);
            same_as_comfy_table(&["wide", "n"], &[vec![&wide, "1"]], &[false, true]);
        }
    }

    #[test]
    fn a_column_wider_than_comfy_table_holds_keeps_the_table_in_shape() {
        // Past comfy-table's u16 (which would shorten the borders and wrap
        // the cell), every line is as wide as the widest cell and its
        // padding, and the cell is printed whole, on one line.
        for width in [65_534, 65_536, 200_000] {
            let wide = "漢".repeat(width / 2) + "a";
            let out = written(
                &["wide", "n"],
                &[vec![&wide, "1"], vec!["b", "22"]],
                &[false, true],
            );
            let lines: Vec<&str> = out.lines().collect();
            assert_eq!(lines.len(), 6, "three rules, a header and two rows");
            let w = lines[0].width();
            assert_eq!(w, 1 + (wide.width() + 2) + 1 + (2 + 2) + 1);
            assert!(lines.iter().all(|l| l.width() == w));
            assert!(lines[3].contains(&wide));
            assert!(
                lines[4].ends_with(" 22 │"),
                "right-aligned: {:?}",
                &lines[4][lines[4].len() - 20..]
            );
        }
    }

    fn fitted(header: &[&str], rows: &[Vec<&str>], right: &[bool], fit: Fit) -> String {
        let header: Vec<String> = header.iter().map(|h| h.to_string()).collect();
        let rows: Vec<Vec<String>> = rows
            .iter()
            .map(|r| r.iter().map(|c| c.to_string()).collect())
            .collect();
        let mut out = String::new();
        write_rows(&mut out, &header, &rows, right, fit);
        out
    }

    const HEADER: [&str; 5] = ["", "x", "y", "z", "unit"];

    fn rows() -> Vec<Vec<&'static str>> {
        vec![
            vec!["centre of mass", "0.000654146", "-3.69021e-6", "1.5", "mm"],
            vec!["ω", "1", "2", "3", "rad/s"],
        ]
    }

    const RIGHT: [bool; 5] = [false, true, true, true, false];

    #[test]
    fn a_table_within_the_width_is_written_whole() {
        let whole = fitted(&HEADER, &rows(), &RIGHT, Fit::WHOLE);
        let w = whole.lines().map(str::width).max().unwrap();
        assert_eq!(w, 60);
        for width in [w, w + 1, 1000] {
            let fit = Fit::new(Some(width), 1);
            assert_eq!(fitted(&HEADER, &rows(), &RIGHT, fit), whole);
        }
    }

    #[test]
    fn a_wider_table_is_split_into_parts_that_repeat_the_labels() {
        let out = fitted(&HEADER, &rows(), &RIGHT, Fit::new(Some(50), 1));
        assert_eq!(
            out,
            "\
┌────────────────┬─────────────┬─────────────┐
│                ┆           x ┆           y │
╞════════════════╪═════════════╪═════════════╡
│ centre of mass ┆ 0.000654146 ┆ -3.69021e-6 │
│ ω              ┆           1 ┆           2 │
└────────────────┴─────────────┴─────────────┘
┌────────────────┬─────┬───────┐
│                ┆   z ┆ unit  │
╞════════════════╪═════╪═══════╡
│ centre of mass ┆ 1.5 ┆ mm    │
│ ω              ┆   3 ┆ rad/s │
└────────────────┴─────┴───────┘
note: table split into 2 to fit 50 columns; --width 0 prints it whole
"
        );
    }

    #[test]
    fn a_group_stays_in_one_part_where_it_fits() {
        // A label 10 wide, a column 8, and a group of three 5 wide: 49
        // columns in all, the label and the group 38.
        let widths = [10, 8, 5, 5, 5];
        let fit = |width| Fit {
            groups: &[(2, 5)],
            ..Fit::new(Some(width), 1)
        };
        assert_eq!(fit(40).parts(&widths), [vec![0, 1], vec![0, 2, 3, 4]]);
        // Without the group, as many as fit.
        let ungrouped = Fit::new(Some(40), 1);
        assert_eq!(ungrouped.parts(&widths), [vec![0, 1, 2], vec![0, 3, 4]]);
        // Too wide beside the label: its columns go one by one.
        assert_eq!(
            fit(30).parts(&widths),
            [vec![0, 1], vec![0, 2, 3], vec![0, 4]]
        );
    }

    #[test]
    fn a_part_has_a_column_beside_its_labels_however_narrow_the_width() {
        assert_eq!(
            Fit::new(Some(1), 2).parts(&[3, 5, 7, 9]),
            [vec![0, 1, 2], vec![0, 1, 3]]
        );
        // Labels that are all the columns but one: nothing to split.
        assert_eq!(Fit::new(Some(1), 5).parts(&[3, 5]), [vec![0, 1]]);
        assert_eq!(Fit::new(Some(1), 0).parts(&[3, 5]), [vec![0], vec![1]]);
    }

    #[test]
    fn a_table_with_line_breaks_splits_through_comfy_table() {
        let out = fitted(
            &["name", "mass\n(kg)", "x"],
            &[vec!["a", "1", "22"], vec!["b\nc", "333", "4"]],
            &[false, true, true],
            Fit::new(Some(15), 1),
        );
        let tables = out.matches('┌').count();
        assert_eq!(tables, 2, "{out}");
        assert!(
            out.ends_with(
                "note: table split into 2 to fit 15 columns; --width 0 prints it whole\n"
            )
        );
        for cell in ["(kg)", "333", "22", "b", "c"] {
            assert!(out.contains(cell), "{cell}: {out}");
        }
        assert!(
            out.lines()
                .all(|l| l.width() <= 15 || l.starts_with("note")),
            "{out}"
        );
    }

    #[test]
    fn widths_are_what_the_note_on_write_table_says() {
        assert_eq!("漢".width(), 2);
        assert_eq!("e\u{301}".width(), 1);
        assert_eq!("👩\u{200d}🔬".width(), 2);
        assert_eq!("🇫🇷".width(), 2);
        assert_eq!("\t".width(), 1);
    }

    /// Pieces of cells: ASCII, wide CJK, combining marks, emoji (ZWJ
    /// sequences, flags, modifiers, variation selectors), tabs, control
    /// and zero-width characters.
    const PIECES: &[&str] = &[
        "a",
        "mass",
        "1.25e-3",
        " ",
        "-",
        "漢",
        "字",
        "ﾎ",
        "Ｈ",
        "e\u{301}",
        "\u{301}",
        "\u{20e3}",
        "🦀",
        "👩\u{200d}🔬",
        "👨\u{200d}👩\u{200d}👧",
        "\u{200d}",
        "🇫🇷",
        "🇫",
        "👍🏽",
        "🏽",
        "❤\u{fe0f}",
        "❤",
        "\u{fe0f}",
        "\t",
        "\r",
        "\u{1b}",
        "\u{0}",
        "\u{200b}",
        "\u{ad}",
        "\u{feff}",
    ];

    /// A cell: a few pieces, sometimes any character at all, rarely a
    /// line break (which sends the table through comfy-table).
    fn cell() -> impl Strategy<Value = String> {
        let piece = prop_oneof![
            40 => prop::sample::select(PIECES).prop_map(str::to_string),
            4 => any::<char>().prop_map(String::from),
            1 => Just("\n".to_string()),
        ];
        prop::collection::vec(piece, 0..5).prop_map(|p| p.concat())
    }

    /// A header, rows of as many cells, and the right-aligned columns.
    fn table() -> impl Strategy<Value = (Vec<String>, Vec<Vec<String>>, Vec<bool>)> {
        (1..=4usize).prop_flat_map(|n| {
            (
                prop::collection::vec(cell(), n),
                prop::collection::vec(prop::collection::vec(cell(), n), 0..6),
                prop::collection::vec(any::<bool>(), n),
            )
        })
    }

    #[test]
    fn random_tables_print_as_comfy_table_prints_them() {
        let mut config = Config::with_cases(1000);
        config.failure_persistence = None;
        config.rng_algorithm = RngAlgorithm::ChaCha;
        let mut runner =
            TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha));
        let written_here = std::cell::Cell::new(0);
        runner
            .run(&table(), |(header, rows, right)| {
                let header: Vec<&str> = header.iter().map(String::as_str).collect();
                let rows: Vec<Vec<&str>> = rows
                    .iter()
                    .map(|r| r.iter().map(String::as_str).collect())
                    .collect();
                let lines = header.iter().chain(rows.iter().flatten());
                let one_line = !lines.clone().any(|c| c.contains('\n'));
                written_here.set(written_here.get() + usize::from(one_line));
                same_as_comfy_table(&header, &rows, &right);
                Ok(())
            })
            .unwrap();
        // Most tables must take the hand-written path, not the fallback.
        let written_here = written_here.get();
        println!("{written_here} of 1000 random tables written by write_table itself");
        assert!(
            written_here >= 500,
            "{written_here} of 1000 tables written here"
        );
    }
}
