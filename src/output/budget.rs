//! `budget`'s weight statement: a table for people, masses and lengths in
//! the file's units (as `report`'s), and JSON in SI (docs/budget.md).

use super::format::{DisplayUnits, fmt_bounded, fmt_num, precision_label, push_name, push_percent};
use super::grid::{Cells, Fit, write_rows, write_table};
use super::report::{conventions, matrix_table, title};
use crate::analysis::budget::{LimitSource, Statement};
use std::fmt::Write;

/// The statement as one JSON object, SI.
pub fn json(s: &Statement) -> String {
    super::json_line(s)
}

/// What the parts with no group are called in the table (JSON: `path`
/// `[]`).
pub const NO_GROUP: &str = "(no group)";

/// The statement for people; tables wider than `width` split.
pub fn table(s: &Statement, width: Option<usize>) -> String {
    let u = DisplayUnits::of(s.file_units);
    let mut out = String::new();
    title(&mut out, &s.name, &s.sub_assembly, &s.source);
    conventions(&mut out, &u, "", s.products_convention, &s.axes);
    let _ = writeln!(
        out,
        "precision: basic body {}, predicted body {}; --rtol {:e}",
        precision_label(s.precision),
        precision_label(s.predicted_precision),
        s.rtol
    );

    let _ = writeln!(out, "\nweight statement ({})", u.mass_label);
    let header = [
        "group",
        "parts",
        "basic",
        "growth",
        "growth %",
        "predicted",
        "share",
    ]
    .map(String::from);
    let mut cells = Cells::with_capacity((s.groups.len() + 1) * header.len());
    let mut row = |label: &dyn Fn(&mut String),
                   parts: usize,
                   (basic, growth, fraction): (f64, f64, Option<f64>),
                   predicted: f64,
                   share: Option<f64>| {
        label(&mut cells.text);
        cells.end();
        let _ = write!(cells.text, "{parts}");
        cells.end();
        for m in [basic, growth] {
            cells.text.push_str(&fmt_num(m / u.mass));
            cells.end();
        }
        push_percent(&mut cells.text, fraction);
        cells.end();
        cells.text.push_str(&fmt_num(predicted / u.mass));
        cells.end();
        push_percent(&mut cells.text, share);
        cells.end();
    };
    for g in &s.groups {
        row(
            &|t: &mut String| match &g.name {
                None => t.push_str(NO_GROUP),
                Some(own) => {
                    t.push_str(&"  ".repeat(g.depth - 1));
                    push_name(t, own);
                }
            },
            g.parts,
            (g.basic_mass, g.growth_mass, g.growth_fraction),
            g.predicted_mass,
            g.share,
        );
    }
    let t = &s.total;
    row(
        &|c: &mut String| c.push_str("total"),
        t.parts,
        (t.basic_mass, t.growth_mass, t.growth_fraction),
        t.predicted_mass,
        Some(1.0),
    );
    let right: Vec<bool> = (0..header.len()).map(|i| i > 0).collect();
    write_table(&mut out, &header, &cells, &right, Fit::new(width, 1));
    let _ = writeln!(
        out,
        "growth: basic × the allowance of the part's maturity ([growth]); predicted = basic + growth"
    );
    if s.no_maturity.parts > 0 {
        let n = s.no_maturity.parts;
        let _ = writeln!(
            out,
            "no maturity: {n} part{} ({} {} basic) counted with zero growth",
            if n == 1 { "" } else { "s" },
            fmt_num(s.no_maturity.basic_mass / u.mass),
            u.mass_label
        );
    }
    match &s.limit {
        None if s.limit_with_only => {
            let _ = writeln!(
                out,
                "limit: not applied with --only (it is the whole body's)"
            );
        }
        None => {
            let _ = writeln!(out, "limit: none given ([budget] limit)");
        }
        Some(l) => {
            let from = match l.source {
                LimitSource::Budget => "[budget] limit",
                LimitSource::ExpectMassMax => "[expect] mass max",
            };
            let mut pct = String::new();
            push_percent(&mut pct, Some(l.margin_fraction));
            let _ = writeln!(
                out,
                "limit: {} {} ({from}); margin {} {} ({pct} of the limit): {}",
                fmt_num(l.limit / u.mass),
                u.mass_label,
                fmt_num(l.margin / u.mass),
                u.mass_label,
                if l.met { "met" } else { "NOT MET" }
            );
        }
    }

    let _ = writeln!(out, "\nbasic and predicted bodies");
    let header = [
        String::new(),
        format!("mass ({})", u.mass_label),
        format!("centre of mass x ({})", u.length_label),
        "y".to_string(),
        "z".to_string(),
    ];
    let mut rows = Vec::new();
    for (label, b) in [("basic", &s.basic), ("predicted", &s.predicted)] {
        let own = |v: f64, e: f64, scale: f64| fmt_bounded(v / scale, e / scale, (v / scale).abs());
        let mut cells = vec![label.to_string(), own(b.mass, b.error_bounds.mass, u.mass)];
        let top = b.center_of_mass.iter().fold(0.0f64, |a, x| a.max(x.abs())) / u.length;
        cells.extend(
            b.center_of_mass
                .iter()
                .zip(&b.error_bounds.center_of_mass)
                .map(|(x, e)| fmt_bounded(x / u.length, e / u.length, top)),
        );
        rows.push(cells);
    }
    let right: Vec<bool> = (0..header.len()).map(|i| i > 0).collect();
    write_rows(
        &mut out,
        &header,
        &rows,
        &right,
        Fit {
            groups: &[(2, 5)],
            ..Fit::new(width, 1)
        },
    );
    for (label, b) in [("basic", &s.basic), ("predicted", &s.predicted)] {
        let _ = writeln!(
            out,
            "\ninertia of the {label} body about its centre of mass ({})",
            u.inertia_label
        );
        matrix_table(
            &mut out,
            (&b.inertia_com, &b.error_bounds.inertia_com),
            u.inertia,
            width,
        );
    }
    out
}
