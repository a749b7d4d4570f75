//! The axle loads' table (`[analysis] axles`): each axle's position in the
//! file's length unit, its load in N and in kg (load / g), and its share
//! of the weight in %.

use super::fit;
use crate::analysis::summary::Summary;
use crate::output::format::{DisplayUnits, fmt_num};
use crate::output::grid::write_rows;
use std::fmt::Write;

/// The table, after a line naming g; nothing without `axles`.
pub(super) fn write(out: &mut String, s: &Summary, u: &DisplayUnits, width: Option<usize>) {
    let Some(a) = &s.axle_loads else { return };
    let _ = writeln!(out, "axle loads (g = {} m/s²)", fmt_num(a.g));
    let header = [
        "",
        &format!("position ({})", u.length_label),
        "load (N)",
        "load (kg)",
        "share (%)",
    ]
    .map(String::from);
    let rows: Vec<Vec<String>> = [("front", &a.front), ("rear", &a.rear)]
        .iter()
        .map(|(name, axle)| {
            vec![
                name.to_string(),
                fmt_num(axle.position / u.length),
                fmt_num(axle.load),
                fmt_num(axle.load / a.g),
                fmt_num(100.0 * axle.share),
            ]
        })
        .collect();
    write_rows(
        out,
        &header,
        &rows,
        &[false, true, true, true, true],
        fit(width),
    );
}
