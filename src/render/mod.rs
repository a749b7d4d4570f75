//! The output layer: how every command's result is written, for people
//! (tables in the file's units) and for scripts (JSON in SI).
//!
//! - `format`: numbers, percentages, display units and labels — the one
//!   place a value's look is decided;
//! - `grid`: the one table writer;
//! - one module per command (`report`, `check`, `diff`, `materials`), each
//!   with a `table` and a `json` renderer that return strings.
//!
//! `Format` is matched in one place, `render`: a command hands over its
//! result as an `Output` and never looks at the format.

pub mod check;
pub mod diff;
pub mod format;
pub mod grid;
pub mod materials;
pub mod report;

use crate::analysis::check::FileResult;
use crate::analysis::diff::Diff;
use crate::analysis::summary::Summary;

/// Output format (`--format`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Format {
    /// Tables for people, in the file's units.
    #[default]
    Table,
    /// One JSON object in SI units (docs/json.md, docs/check.md,
    /// docs/diff.md).
    Json,
}

/// A command's result, ready to be written in either format.
pub enum Output<'a> {
    /// `report`: the summary, and the name of the file it came from.
    Report(&'a Summary, &'a str),
    Check(&'a [FileResult]),
    Diff(&'a Diff),
    Materials(&'a [materials::Listed]),
}

/// `output` in `format`: the one place formats are told apart.
pub fn render(output: &Output, format: Format) -> String {
    match (format, output) {
        (Format::Table, Output::Report(s, source)) => report::table(s, source),
        (Format::Json, Output::Report(s, _)) => report::json(s),
        (Format::Table, Output::Check(r)) => check::table(r),
        (Format::Json, Output::Check(r)) => check::json(r),
        (Format::Table, Output::Diff(d)) => diff::table(d),
        (Format::Json, Output::Diff(d)) => diff::json(d),
        (Format::Table, Output::Materials(l)) => materials::table(l),
        (Format::Json, Output::Materials(l)) => materials::json(l),
    }
}
