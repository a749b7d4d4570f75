//! `diff`'s table (in the new file's units) and JSON contract (SI,
//! docs/diff.md).

use super::format::{
    DisplayUnits, change_percent as percent, name, products_label, show_or_si as show,
};
use super::grid::{Fit, new_table, write_rows};
use crate::analysis::Products;
use crate::analysis::diff::{Change, Diff, FORMAT_VERSION, LinkDiff, PartView, QuantityDiff, Side};
use crate::analysis::summary::{BODY_UNITS, BodyUnits};
use crate::numeric::norm;
use serde::Serialize;
use std::fmt::Write;

#[derive(Serialize)]
struct JsonPartChange<'a> {
    name: &'a str,
    what: &'a [Change],
}

#[derive(Serialize)]
struct JsonParts<'a> {
    added: Vec<&'a str>,
    removed: Vec<&'a str>,
    changed: Vec<JsonPartChange<'a>>,
}

/// The JSON contract of docs/diff.md; field names are the keys.
#[derive(Serialize)]
struct JsonDiff<'a> {
    format_version: u32,
    massprop_version: &'static str,
    old: &'a str,
    new: &'a str,
    products_convention: Products,
    units: BodyUnits,
    tolerance: f64,
    /// The arithmetic each side was computed in (`--precision auto`
    /// chooses per file).
    precision: JsonPrecision,
    changed: bool,
    quantities: &'a [QuantityDiff],
    parts: JsonParts<'a>,
}

#[derive(Serialize)]
struct JsonPrecision {
    old: crate::compose::Precision,
    new: crate::compose::Precision,
}

/// The diff as one JSON object, SI.
pub fn json(d: &Diff) -> String {
    let (op, np) = (&d.old.parts, &d.new.parts);
    let json = JsonDiff {
        format_version: FORMAT_VERSION,
        massprop_version: crate::analysis::summary::MASSPROP_VERSION,
        old: &d.old.loaded.source.name,
        new: &d.new.loaded.source.name,
        products_convention: Products::Tensor,
        units: BODY_UNITS,
        tolerance: d.tol,
        precision: JsonPrecision {
            old: d.old.loaded.summary.precision,
            new: d.new.loaded.summary.precision,
        },
        changed: d.changed,
        quantities: &d.quantities,
        parts: JsonParts {
            added: d
                .parts
                .added
                .iter()
                .map(|l| np[l.index].name.as_str())
                .collect(),
            removed: d
                .parts
                .removed
                .iter()
                .map(|l| op[l.index].name.as_str())
                .collect(),
            changed: d
                .parts
                .changed
                .iter()
                .map(|c| JsonPartChange {
                    name: &op[c.old].name,
                    what: &c.what,
                })
                .collect(),
        },
    };
    super::json_line(&json)
}

/// A part file against a link, as one JSON object, SI: diff's contract
/// with `link` for `parts` (docs/diff.md).
pub fn link_json(d: &LinkDiff) -> String {
    #[derive(Serialize)]
    struct JsonLinkDiff<'a> {
        format_version: u32,
        massprop_version: &'static str,
        old: &'a str,
        new: &'a str,
        link: &'a str,
        products_convention: Products,
        units: BodyUnits,
        tolerance: f64,
        changed: bool,
        quantities: &'a [QuantityDiff],
    }
    super::json_line(&JsonLinkDiff {
        format_version: FORMAT_VERSION,
        massprop_version: crate::analysis::summary::MASSPROP_VERSION,
        old: &d.old,
        new: &d.new,
        link: &d.link,
        products_convention: Products::Tensor,
        units: BODY_UNITS,
        tolerance: d.tol,
        changed: d.changed,
        quantities: &d.quantities,
    })
}

/// A part file against a link, for people, in the part file's units.
pub fn link_table(d: &LinkDiff, width: Option<usize>) -> String {
    let u = DisplayUnits::of(d.file_units);
    let mut out = String::new();
    let _ = writeln!(out, "old: {}", name(&d.old));
    let _ = writeln!(out, "new: {}", name(&d.new));
    let _ = writeln!(
        out,
        "link: {} (the part file's body in its link frame: origin `about`, axes `axes`)",
        name(&d.link)
    );
    preamble(&mut out, &u, "the part file's", d.tol);
    quantities_table(&mut out, &d.quantities, &u, width);
    out
}

/// The lines before the table of quantities: its units (`whose`: which
/// file's), convention and relative-change rule, then a blank line.
fn preamble(out: &mut String, u: &DisplayUnits, whose: &str, tol: f64) {
    let _ = writeln!(
        out,
        "units ({whose}): mass {}, length {}, inertia {}",
        u.mass_label, u.length_label, u.inertia_label
    );
    let _ = writeln!(
        out,
        "Ixx … Iyz: inertia about the centre of mass, {}",
        products_label(Products::Tensor)
    );
    let _ = writeln!(
        out,
        "relative: change ÷ the scale of the whole quantity (docs/diff.md); tolerance {tol:e}"
    );
    out.push('\n');
}

/// The table of compared quantities.
fn quantities_table(
    out: &mut String,
    quantities: &[QuantityDiff],
    u: &DisplayUnits,
    width: Option<usize>,
) {
    let header = ["", "old", "new", "change", "relative", "unit", ""].map(String::from);
    let mut rows = Vec::new();
    for q in quantities {
        let (factor, unit) = u.of_dim(q.dim);
        rows.push(vec![
            q.label.clone(),
            show(q.old, factor),
            show(q.new, factor),
            show(q.abs_change, factor),
            percent(q.rel_change),
            unit.to_string(),
            if q.changed { "changed" } else { "" }.to_string(),
        ]);
    }
    // The numbers right; each part of a split table keeps the quantity.
    let right: Vec<bool> = (0..header.len()).map(|i| (1..=4).contains(&i)).collect();
    write_rows(out, &header, &rows, &right, Fit::new(width, 1));
}

/// How a file is named in the table: its path, and its `name` if it has one.
fn title(side: &Side) -> String {
    let shown = name(&side.loaded.source.name);
    match &side.loaded.model.name {
        Some(n) => format!("{shown} ({})", name(n)),
        None => shown,
    }
}

/// Each part's name as the table shows it, numbered where the name is not
/// unique in its file (`bolt (#2)`): counted once for all the parts, so a
/// diff of many parts of one name stays linear (counting for each row
/// was quadratic).
fn part_labels(parts: &[PartView]) -> Vec<String> {
    let mut total: std::collections::HashMap<&str, usize> = Default::default();
    for p in parts {
        *total.entry(&p.name).or_default() += 1;
    }
    let mut seen: std::collections::HashMap<&str, usize> = Default::default();
    parts
        .iter()
        .map(|p| {
            let shown = name(&p.name);
            if total[p.name.as_str()] > 1 {
                let k = seen.entry(&p.name).or_default();
                *k += 1;
                format!("{shown} (#{k})")
            } else {
                shown
            }
        })
        .collect()
}

fn describe_lone(p: &PartView, u: &DisplayUnits) -> String {
    let c = p.si.center.as_array();
    format!(
        "{}, {} {} at ({}, {}, {}) {}",
        p.shape.name(),
        show(p.si.mass, u.mass),
        u.mass_label,
        show(c[0], u.length),
        show(c[1], u.length),
        show(c[2], u.length),
        u.length_label
    )
}

fn describe_change(o: &PartView, n: &PartView, what: &[Change], u: &DisplayUnits) -> String {
    what.iter()
        .map(|w| match *w {
            Change::Shape => format!("shape {} → {}", o.shape.name(), n.shape.name()),
            Change::Mass => format!(
                "mass {} → {} {} ({})",
                show(o.si.mass, u.mass),
                show(n.si.mass, u.mass),
                u.mass_label,
                percent(Some((n.si.mass - o.si.mass) / o.si.mass))
            ),
            Change::Centroid => {
                let moved = norm(&(n.si.center - o.si.center).as_array());
                if moved < f64::MAX {
                    format!(
                        "centroid moved {} {}",
                        show(moved, u.length),
                        u.length_label
                    )
                } else {
                    "centroid moved".to_string()
                }
            }
            Change::SecondMoment => "second moment".to_string(),
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// The diff for people, in the new file's units; the table of quantities
/// split to fit `width` (`grid::Fit`).
pub fn table(d: &Diff, width: Option<usize>) -> String {
    let u = DisplayUnits::of(d.new.loaded.summary.file_units);
    let mut out = String::new();
    let _ = writeln!(out, "old: {}", title(&d.old));
    let _ = writeln!(out, "new: {}", title(&d.new));
    preamble(&mut out, &u, "the new file's", d.tol);
    quantities_table(&mut out, &d.quantities, &u, width);

    let (op, np) = (&d.old.parts, &d.new.parts);
    let p = &d.parts;
    if p.is_empty() {
        let _ = writeln!(out, "\nparts: none added, removed or changed");
    } else {
        let _ = writeln!(
            out,
            "\nparts: {} added, {} removed, {} changed (matched by name)",
            p.added.len(),
            p.removed.len(),
            p.changed.len()
        );
        let (old_labels, new_labels) = (part_labels(op), part_labels(np));
        let mut t = new_table();
        t.set_header(vec!["part", "", "what"]);
        for l in &p.removed {
            t.add_row(vec![
                old_labels[l.index].clone(),
                "removed".to_string(),
                describe_lone(&op[l.index], &u),
            ]);
        }
        for l in &p.added {
            t.add_row(vec![
                new_labels[l.index].clone(),
                "added".to_string(),
                describe_lone(&np[l.index], &u),
            ]);
        }
        for c in &p.changed {
            t.add_row(vec![
                old_labels[c.old].clone(),
                "changed".to_string(),
                describe_change(&op[c.old], &np[c.new], &c.what, &u),
            ]);
        }
        let _ = writeln!(out, "{t}");
    }
    let _ = writeln!(
        out,
        "\n{}",
        if d.changed {
            "result: changed beyond the tolerance"
        } else if p.is_empty() {
            "result: no change beyond the tolerance"
        } else {
            "result: no mass property changed beyond the tolerance (the parts differ: `--names` fails on that)"
        }
    );
    out
}
