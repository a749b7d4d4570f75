//! The envelope's line in the report table (`[envelope]`): the centre of
//! mass's coordinate along the envelope's axis, in the file's length unit
//! and in % MAC when `mac` is given, the mass, and the margin.

use crate::analysis::envelope::Placed;
use crate::output::format::{DisplayUnits, fmt_num};
use std::fmt::Write;

/// The axis's name.
const AXES: [&str; 3] = ["x", "y", "z"];

/// One line; nothing without `[envelope]`.
pub(super) fn write(out: &mut String, p: Option<&Placed>, u: &DisplayUnits) {
    let Some(p) = p else { return };
    let _ = writeln!(out, "envelope: {}", line(p, u));
}

/// "x = 2.31 m (24.5 % MAC) at 1050 kg: margin 0.09 m, inside", as the
/// report and `report --cases` show it.
pub fn line(p: &Placed, u: &DisplayUnits) -> String {
    let mac = p
        .mac
        .map_or(String::new(), |m| format!(" ({} % MAC)", fmt_num(m)));
    format!(
        "{} = {} {}{mac} at {} {}: {}",
        AXES[p.axis],
        fmt_num(p.coordinate / u.length),
        u.length_label,
        fmt_num(p.mass / u.mass),
        u.mass_label,
        margin(p, u),
    )
}

/// The margin and its verdict, or why there is none.
pub fn margin(p: &Placed, u: &DisplayUnits) -> String {
    match p.margin {
        Some(d) => format!(
            "margin {} {}, {}",
            fmt_num(d / u.length),
            u.length_label,
            if p.inside() { "inside" } else { "outside" }
        ),
        None => "no margin: the mass is outside the envelope's range of masses".to_string(),
    }
}
